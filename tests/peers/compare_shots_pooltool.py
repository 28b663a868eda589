#!/usr/bin/env python3
"""Whole shots side by side with pooltool's: the same balls, cue and table played by billiards-shot and by
pooltool's event-based engine, configured where it can be to the same models.

pooltool is set to our physics: Han (2005) at straight cushions and jaws (its default is Stronge's
compliant model), the instantaneous point strike with squirt off, its FrictionalInelastic ball-ball
model with a constant μ = 0.06 (its default is Alciatore's speed-dependent fit), m = 0.170 kg, and our
7-ft table's mouths (corner 0.1159 m, side 0.1286 m) and nose height (0.03629 m). What stays pooltool's:
the walls of its pockets behind the jaws, the friction bound of its ball-ball contact (μ e |Δv_n|
where ours is μ (1 + e)/2 |Δv_n|), and where it places balls after a contact.

For each shot, prints the first collisions of each (ball–ball, cushion, jaw, pocket: which balls, the
times) and where they part, and, for shots short enough not to be chaotic, where the balls stop. Exit
status 0 when every compared shot's first collisions agree in kind and balls and within --time-tolerance
in time, 1 otherwise, 77 (ctest's skip) where pooltool is not importable.

  compare_shots_pooltool.py --program build/programs/billiards-shot [--time-tolerance 0.02]
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile

try:
    import attrs
    import pooltool as pt
    from pooltool.events.datatypes import EventType
    from pooltool.objects.table.specs import PocketTableSpecs
    from pooltool.physics.resolve.ball_ball.friction import AverageBallBallFriction
    from pooltool.physics.resolve.ball_ball.frictional_inelastic import FrictionalInelastic
    from pooltool.physics.resolve.ball_cushion.han_2005.model import Han2005Circular, Han2005Linear
    from pooltool.physics.resolve.ball_pocket import CanonicalBallPocket
    from pooltool.physics.resolve.ball_table import FrictionalInelasticTable
    from pooltool.physics.resolve.resolver import Resolver
    from pooltool.physics.resolve.stick_ball.instantaneous_point import InstantaneousPoint2D
    from pooltool.physics.resolve.transition import CanonicalTransition
except ImportError as error:
    print(f"compare_shots_pooltool: pooltool is not importable here ({error}); skipped", file=sys.stderr)
    sys.exit(77)

L, W, R = 1.9812, 0.9906, 0.028575

# Each shot: a name, balls (ours: x along the length, y across; ball 0 the cue ball), the cue (speed,
# azimuth in degrees from +x, elevation in degrees, side offset a, up offset b), and whether it is short
# enough for its final positions to be compared.
SHOTS = [
    ("straight: the cue ball rolls into the 1 head on", [(0.5, 0.5), (1.5, 0.5)], (2.0, 0.0, 0.0, 0.0, 0.4), True),
    ("stun: sliding at contact, the cue ball stops", [(1.2, 0.5), (1.5, 0.5)], (3.0, 0.0, 0.0, 0.0, -0.1), True),
    ("draw: the cue ball comes back", [(1.0, 0.5), (1.4, 0.5)], (3.0, 0.0, 0.0, 0.0, -0.5), True),
    ("half-ball cut with follow", [(0.6, 0.45), (1.3, 0.45 + R)], (2.5, 0.0, 0.0, 0.0, 0.3), True),
    ("into the side cushion at 45 degrees", [(0.6, 0.5)], (1.5, -45.0, 0.0, 0.0, 0.0), True),
    ("along the length into the foot cushion and back", [(0.4, 0.3)], (2.0, 0.0, 0.0, 0.0, 0.2), True),
    ("a cut towards the corner pocket", [(1.2, 0.6), (1.7, 0.25)], (2.0, math.degrees(math.atan2(0.25 - 0.6, 1.7 - 1.2)) - 4.0, 0.0, 0.0, 0.0), True),
    ("9-ball break, the rack spread by 1e-3 R, 8 m/s at b = 0.25", [(0.25 * L, W / 2)] + [
        (0.75 * L + row * 2 * R * 1.001 * math.sqrt(3) / 2, W / 2 + 2 * R * 1.001 * (j - (count - 1) / 2))
        for row, count in enumerate((1, 2, 3, 2, 1)) for j in range(count)], (8.0, 0.0, 0.0, 0.0, 0.25), False),
    ("three balls: a combination", [(0.5, 0.5), (1.0, 0.5), (1.3, 0.52)], (3.0, 0.0, 0.0, 0.0, 0.0), False),
]


def ours(program, balls, cue, work):
    setup = os.path.join(work, "shot.setup")
    with open(setup, "w") as f:
        f.write("table 7ft\n")
        for x, y in balls:
            f.write(f"ball {x!r} {y!r}\n")
    out = os.path.join(work, "shot.json")
    speed, azimuth, elevation, a, b = cue
    subprocess.run([program, "--setup", setup, "--speed", repr(speed), "--azimuth", repr(azimuth), "--elevation",
                    repr(elevation), "--offset", f"{a!r},{b!r}", "--json", out], check=True, capture_output=True)
    shot = json.load(open(out))
    events = []
    for e in shot["events"]:
        if e["kind"] in ("ball", "cushion", "jaw", "pocket"):
            events.append((e["kind"], tuple(sorted(e["balls"])), e["time"]))
    final = [tuple(s["position"]) if not s["pocketed"] else None for s in shot["final"]]
    return events, final


def engine():
    return pt.evolution.SimulationEngine(resolver=Resolver(
        ball_ball=FrictionalInelastic(friction=AverageBallBallFriction()),
        ball_linear_cushion=Han2005Linear(),
        ball_circular_cushion=Han2005Circular(),
        ball_pocket=CanonicalBallPocket(),
        stick_ball=InstantaneousPoint2D(english_throttle=1.0, squirt_throttle=0.0),
        ball_table=FrictionalInelasticTable(min_bounce_height=0.005),
        transition=CanonicalTransition()))


def theirs(balls, cue):
    specs = attrs.evolve(PocketTableSpecs(), l=L, w=W, cushion_height=0.03629, corner_pocket_width=0.1159,
                         side_pocket_width=0.1286)
    table = pt.Table.from_table_specs(specs)
    ids = ["cue"] + [str(i) for i in range(1, len(balls))]
    # Ours (x, y) is pooltool's (W − y, x): its x across the table, its y along it.
    pt_balls = {bid: pt.Ball.create(bid, xy=(W - y, x), m=0.170, R=R, u_b=0.06) for bid, (x, y) in zip(ids, balls)}
    system = pt.System(cue=pt.Cue(cue_ball_id="cue"), table=table, balls=pt_balls)
    speed, azimuth, elevation, a, b = cue
    system.strike(V0=speed, phi=azimuth + 90.0, theta=elevation, a=-a, b=b)  # its a: left positive
    pt.simulate(system, engine=engine(), inplace=True)
    index = {bid: k for k, bid in enumerate(ids)}
    kinds = {EventType.BALL_BALL: "ball", EventType.BALL_LINEAR_CUSHION: "cushion",
             EventType.BALL_CIRCULAR_CUSHION: "jaw", EventType.BALL_POCKET: "pocket"}
    events = []
    for e in system.events:
        if e.event_type in kinds:
            events.append((kinds[e.event_type], tuple(sorted(index[i] for i in e.ids if i in index)), float(e.time)))
    final = []
    for bid in ids:
        ball = system.balls[bid]
        if int(ball.state.s) == 4:  # pocketed
            final.append(None)
        else:
            x, y = ball.state.rvw[0][0], ball.state.rvw[0][1]
            final.append((float(y), float(W - x)))
    return events, final


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--program", required=True)
    parser.add_argument("--first", type=int, default=4, help="the first collisions compared (default 4)")
    parser.add_argument("--time-tolerance", type=float, default=0.02,
                        help="the largest difference of a collision's time, relative to it (default 0.02)")
    args = parser.parse_args()
    failures = 0
    print("| shot | first collisions (ours) | same kinds and balls | largest time difference | final positions: largest distance |")
    print("|---|---|---|---:|---:|")
    with tempfile.TemporaryDirectory() as work:
        for name, balls, cue, short in SHOTS:
            mine, my_final = ours(args.program, balls, cue, work)
            try:
                other, other_final = theirs(balls, cue)
            except (ValueError, ArithmeticError) as error:
                # pooltool's own failure (e.g. its quartic solver on a degenerate quartic): said, not ours.
                print(f"| {name} | {len(mine)} collisions | pooltool failed: {str(error)[:90]} | | |")
                continue
            first_mine, first_other = mine[:args.first], other[:args.first]
            same = [(a[0], a[1]) for a in first_mine] == [(b[0], b[1]) for b in first_other]
            worst = max((abs(a[2] - b[2]) / max(b[2], 1e-9) for a, b in zip(first_mine, first_other)), default=0.0)
            if short:
                distances = [math.dist(a, b) if a and b else (0.0 if a == b else math.inf)
                             for a, b in zip(my_final, other_final)]
                final_text = f"{max(distances) * 1000:.1f} mm"
            else:
                final_text = "(chaotic: not compared)"
            sequence = ", ".join(f"{k} {'-'.join(map(str, b))} at {t:.4f} s" for k, b, t in first_mine)
            print(f"| {name} | {sequence} | {'yes' if same else 'no: ' + str([(b[0], b[1]) for b in first_other])} | "
                  f"{100 * worst:.2f} % | {final_text} |")
            if not same or worst > args.time_tolerance:
                failures += 1
    print(f"\n{failures} shot(s) whose first collisions differ beyond the tolerance")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
