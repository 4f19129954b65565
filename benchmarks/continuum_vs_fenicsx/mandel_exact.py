"""Mandel's problem in closed form (docs/verification.md (k)): the pressure
on the plates' mid-plane, for the benchmark's error column. The parameters
of configs/continuum_mandel.yaml: a = 1 m, E = 1 GPa, nu = 0.2, alpha = 1,
M = 2 GPa, k / mu = 1e-10 m^2/(Pa s), F = 1 MN/m on the quarter."""
import math

A, E, NU, BIOT, M, MOBILITY, FORCE = 1.0, 1e9, 0.2, 1.0, 2e9, 1e-10, 1e6
K = E / (3 * (1 - 2 * NU))
G = E / (2 * (1 + NU))
K_U = K + BIOT * BIOT * M
NU_U = (3 * K_U - 2 * G) / (2 * (3 * K_U + G))
SKEMPTON = BIOT * M / K_U
C = MOBILITY / (1 / M + BIOT * BIOT / (K + 4 * G / 3))
P0 = FORCE * SKEMPTON * (1 + NU_U) / (3 * A)


def roots(n):
    """The first n roots of tan x = (1 - nu) / (nu_u - nu) x, by bisection of
    sin x - s x cos x on ((i - 1) pi, (i - 1/2) pi)."""
    s = (1 - NU) / (NU_U - NU)
    out = []
    for i in range(1, n + 1):
        sign = 1 if i % 2 == 1 else -1
        lo, hi = (i - 1) * math.pi, (i - 0.5) * math.pi
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if mid <= lo or mid >= hi:
                break
            g = sign * (math.sin(mid) - s * mid * math.cos(mid))
            if g < 0:
                lo = mid
            else:
                hi = mid
        out.append(0.5 * (lo + hi))
    return out


def pressure(x, t):
    """p(x, t) in Pa; p0 inside at t = 0."""
    if t <= 0:
        return P0 if x < A else 0.0
    tv = C * t / (A * A)
    n = max(400, int(math.sqrt(45 / tv) / math.pi) + 2)
    total = 0.0
    for alpha in roots(n):
        e = alpha * alpha * tv
        if e > 45:
            break
        s, c = math.sin(alpha), math.cos(alpha)
        total += s / (alpha - s * c) * (math.cos(alpha * x / A) - c) * math.exp(-e)
    return 2 * P0 * total


if __name__ == "__main__":
    print(f"p0 = {P0:.10g} Pa, c = {C:.6g} m^2/s")
    for t in (0.1, 1.0, 7.0):
        print(f"t = {t}: p(0) = {pressure(0, t):.10g}, p(0.5) = {pressure(0.5, t):.10g}")
