"""The heat case in closed form (Carslaw and Jaeger): the square [0, L]^2
initially at T0, its four sides held at 0 from t = 0 on, as heat_scene.yaml
and dolfinx_heat.py set it: T = T0 X(x, t) X(y, t) with
X(x, t) = sum over odd n of 4 / (n pi) sin(n pi x / L) exp(-n^2 pi^2 kappa t / L^2)."""
import math

L, CONDUCTIVITY, HEAT_CAPACITY, T0 = 1.0, 3.0, 2.4e6, 100.0
KAPPA = CONDUCTIVITY / HEAT_CAPACITY  # m^2/s


def one_side(x, t, terms=2001):
    """X(x, t) for t > 0 (the series converges like exp(-n^2) then)."""
    total = 0.0
    for n in range(1, terms + 1, 2):
        total += (4 / (n * math.pi) * math.sin(n * math.pi * x / L)
                  * math.exp(-n * n * math.pi ** 2 * KAPPA * t / L ** 2))
    return total


def temperature(x, y, t):
    return T0 * one_side(x, t) * one_side(y, t)
