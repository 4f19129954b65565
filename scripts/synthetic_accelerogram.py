#!/usr/bin/env python3
"""A deterministic recorded-like accelerogram, written as a csv record
(t, ax[, ay]) that `mechanics.ground_motion` reads (docs/dda.md section 10).

White noise (Python's Mersenne Twister with the seed; Box-Muller normals)
through the Kanai-Tajimi ground filter (f_g, zeta_g) and the Clough-Penzien
high-pass (f_f, zeta_f) that keeps the velocity from drifting, times the
Saragoni-Hart envelope of Boore (2003, "Simulation of ground motion using
the stochastic method", Pure Appl. Geophys. 160), tapered to 0 over the
last 5 %, scaled to the peak ground acceleration. The vertical component,
when asked for, is an independent record scaled to `--vertical` times the
horizontal peak. Plain Python: the same seed gives the same file.
The verification tests draw theirs in C++ (synthetic_accelerogram in
tests/support/newmark_sliding_block.h): the same recipe with a low pass at
f_max and another noise generator, so not the same samples.

    scripts/synthetic_accelerogram.py OUT.csv --duration 20 --pga 0.4 --seed 3
"""
import argparse
import math
import random


def filtered_noise(n, dt, rng, fg, zg, ff, zf):
    """Kanai-Tajimi then Clough-Penzien filtered white noise (unit scale)."""
    wg, wf = 2 * math.pi * fg, 2 * math.pi * ff
    xg = vg = xf = vf = 0.0
    out = []
    for _ in range(n):
        # Box-Muller: one normal per sample.
        u1, u2 = 1.0 - rng.random(), rng.random()
        w = math.sqrt(-2 * math.log(u1)) * math.cos(2 * math.pi * u2) / math.sqrt(dt)
        # Ground filter: x'' + 2 zg wg x' + wg^2 x = -w; its absolute acceleration.
        ag = -(2 * zg * wg * vg + wg * wg * xg)
        vg += dt * (-w - 2 * zg * wg * vg - wg * wg * xg)
        xg += dt * vg
        # High-pass: y'' + 2 zf wf y' + wf^2 y = ag, output y''.
        af = ag - 2 * zf * wf * vf - wf * wf * xf
        vf += dt * af
        xf += dt * vf
        out.append(af)
    return out


def envelope(t, duration, peak=0.2, end_level=0.05):
    """Saragoni-Hart: (t/tn)^b exp(-c t/tn), its maximum 1 at peak * tn."""
    eta, eps = end_level, peak
    b = -eps * math.log(eta) / (1 + eps * (math.log(eps) - 1))
    c = b / eps
    a = (math.e / eps) ** b
    x = t / duration
    w = a * x ** b * math.exp(-c * x) if x > 0 else 0.0
    taper = min(1.0, (duration - t) / (0.05 * duration))
    return w * max(taper, 0.0)


def record(duration, dt, pga, rng, fg, zg, ff, zf):
    n = int(round(duration / dt)) + 1
    noise = filtered_noise(n, dt, rng, fg, zg, ff, zf)
    a = [noise[k] * envelope(k * dt, duration) for k in range(n)]
    a[0] = a[-1] = 0.0
    peak = max(abs(v) for v in a)
    return [pga * v / peak for v in a]


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("out")
    p.add_argument("--duration", type=float, default=20.0, help="s")
    p.add_argument("--dt", type=float, default=0.005, help="s")
    p.add_argument("--pga", type=float, default=0.3, help="peak horizontal acceleration, g")
    p.add_argument("--vertical", type=float, default=0.0, help="vertical peak / horizontal peak")
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--ground-frequency", type=float, default=2.5, help="f_g, Hz")
    p.add_argument("--ground-damping", type=float, default=0.6)
    p.add_argument("--high-pass", type=float, default=0.25, help="f_f, Hz")
    args = p.parse_args()
    rng = random.Random(args.seed)
    g = 9.80665
    ax = record(args.duration, args.dt, args.pga * g, rng, args.ground_frequency,
                args.ground_damping, args.high_pass, 0.6)
    ay = (record(args.duration, args.dt, args.vertical * args.pga * g, rng, 2 * args.ground_frequency,
                 args.ground_damping, args.high_pass, 0.6) if args.vertical > 0 else None)
    with open(args.out, "w") as f:
        f.write(f"# synthetic_accelerogram.py --duration {args.duration:g} --dt {args.dt:g} "
                f"--pga {args.pga:g} --vertical {args.vertical:g} --seed {args.seed}\n")
        f.write("t,ax,ay\n" if ay else "t,ax\n")
        for k, v in enumerate(ax):
            f.write(f"{k * args.dt:.4f},{v:.6f}" + (f",{ay[k]:.6f}\n" if ay else "\n"))


if __name__ == "__main__":
    main()
