#!/usr/bin/env python3
"""The cue strike and the cushion, side by side with pooltool's on the same inputs.

pooltool's cue_strike (the instantaneous point model, TP A-30, through InstantaneousPoint3D with squirt off)
and its han2005 cushion model are called on seeded random inputs where the models are the same (a ball at
rest, e_tip = 1; a ball on the cloth moving into the cushion), and so is shot_physics_probe (the runtime's
checked strike and collide_with_cushion). Prints, per call, the largest difference of velocity and of spin
relative to the speeds involved, and the cases where a regime differs. Needs pooltool importable (set up
by ../shared/peers/pooltool/setup.sh and env.sh); exits 77 where it is not.

  compare_pooltool.py --probe build/tests/peers/shot_physics_probe [--cases 2000] [--seed 1] [--tolerance 1e-12]
"""
import argparse
import math
import random
import subprocess
import sys

try:
    import attrs
    import numpy as np
    import pooltool as pt
    from pooltool.objects.cue.datatypes import CueSpecs
    from pooltool.objects.ball.datatypes import Ball, BallState
    from pooltool.physics.resolve.ball_cushion.han_2005.model import han2005
    from pooltool.physics.resolve.stick_ball.instantaneous_point import InstantaneousPoint3D
except ImportError as error:
    print(f"compare_pooltool: pooltool is not importable here ({error}); skipped", file=sys.stderr)
    sys.exit(77)


def pooltool_strike(m, R, M, V, azimuth, elevation, a, b):
    ball = Ball.create("cue", xy=(0.5, 0.5), m=m, R=R)
    specs = attrs.evolve(CueSpecs.default(), M=M)
    cue = pt.Cue(V0=V, phi=math.degrees(azimuth), theta=math.degrees(elevation), a=-a, b=b, specs=specs)  # its a: left positive
    _, ball = InstantaneousPoint3D(squirt_throttle=0.0).solve(cue, ball)
    return list(ball.state.rvw[1]) + list(ball.state.rvw[2])


def pooltool_cushion(m, R, v, w, n, h, e, mu):
    rvw = np.array([[0.5, 0.5, R], [v[0], v[1], 0.0], list(w)], dtype=float)
    out = han2005(rvw=rvw, xy_normal=np.array([n[0], n[1], 0.0]), R=R, m=m, h=h, e_c=e, f_c=mu)
    return list(out[1]) + list(out[2])


def draw_cases(count, seed):
    rng = random.Random(seed)
    cases = []
    for _ in range(count):
        m, R = 0.17 * math.exp(rng.uniform(-0.5, 0.5)), 0.028575 * math.exp(rng.uniform(-0.3, 0.3))
        # The strike: TP A-30's ball at rest, e_tip = 1, any azimuth, elevation to 60°, the tip on the ball.
        radius, angle = 0.9 * math.sqrt(rng.random()), rng.uniform(-math.pi, math.pi)
        a, b = radius * math.cos(angle), radius * math.sin(angle)
        cases.append(("strike", (m, R, 0.54 * math.exp(rng.uniform(-0.5, 0.5)), rng.uniform(0.1, 12),
                                 rng.uniform(-math.pi, math.pi), rng.uniform(0, math.pi / 3), a, b)))
        # The cushion: a ball on the cloth moving into it at any angle, any spin, the nose in [R, 1.6 R].
        psi = rng.uniform(-math.pi, math.pi)
        n = (math.cos(psi), math.sin(psi))
        speed, heading = rng.uniform(0.05, 10), psi + rng.uniform(-1.5, 1.5)
        v = (speed * math.cos(heading), speed * math.sin(heading))
        w = tuple(rng.uniform(-1, 1) * 2 * speed / R for _ in range(3))
        cases.append(("cushion", (m, R, v, w, n, R * rng.uniform(1, 1.6), rng.uniform(0.5, 1), rng.uniform(0, 1))))
    return cases


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--probe", required=True, help="the shot_physics_probe program")
    parser.add_argument("--cases", type=int, default=2000, help="random cases of each call (default 2000)")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--tolerance", type=float, default=1e-12,
                        help="the largest relative difference that passes (default 1e-12)")
    args = parser.parse_args()
    if not 1 <= args.cases <= 10**6:
        parser.error(f"--cases is {args.cases}; expected 1 to 10^6")
    cases = draw_cases(args.cases, args.seed)
    lines = []
    for call, p in cases:
        if call == "strike":
            lines.append("strike " + " ".join(repr(x) for x in p[:8]) + " 1")
        else:
            m, R, v, w, n, h, e, mu = p
            lines.append("cushion " + " ".join(repr(x) for x in (m, R, *v, *w, *n, h, e, mu)))
    run = subprocess.run([args.probe], input="\n".join(lines) + "\n", capture_output=True, text=True, check=True)
    ours = [[float(x) for x in line.split()] for line in run.stdout.splitlines()]
    worst = {"strike": [0.0, 0.0], "cushion": [0.0, 0.0]}
    for (call, p), mine in zip(cases, ours):
        if call == "strike":
            m, R, M, V, azimuth, elevation, a, b = p
            theirs = pooltool_strike(m, R, M, V, azimuth, elevation, a, b)
            scale = V
        else:
            m, R, v, w, n, h, e, mu = p
            if v[0] * n[0] + v[1] * n[1] <= 0:
                continue
            theirs = pooltool_cushion(m, R, v, w, n, h, e, mu)
            scale = math.hypot(*v) + R * math.sqrt(sum(x * x for x in w))
        dv = math.dist(mine[:3], theirs[:3]) / scale
        dw = math.dist(mine[3:], theirs[3:]) * p[1] / scale
        worst[call] = [max(worst[call][0], dv), max(worst[call][1], dw)]
    print(f"pooltool {pt.__version__}, {args.cases} cases of each call, seed {args.seed}")
    print("| call | pooltool's | largest difference of v / speeds | of R ω / speeds |")
    print("|---|---|---:|---:|")
    print(f"| strike (ball at rest, e_tip = 1) | cue_strike via InstantaneousPoint3D, squirt off | "
          f"{worst['strike'][0]:.3g} | {worst['strike'][1]:.3g} |")
    print(f"| collide_with_cushion | han2005 | {worst['cushion'][0]:.3g} | {worst['cushion'][1]:.3g} |")
    bad = [call for call, w in worst.items() if max(w) > args.tolerance]
    if bad:
        print(f"compare_pooltool: more than {args.tolerance:g} from pooltool: {', '.join(bad)}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
