"""pooltool interop, where pooltool is importable (../shared/peers/pooltool/setup.sh and env.sh): its
System converted into ours plays the same shot as pooltool's own engine set to our models, within what
docs/shot.md documents (the first collisions' kinds and balls the same, their times within 2 %)."""

import math

import numpy as np
import pytest

pt = pytest.importorskip("pooltool")

import attrs  # noqa: E402  (pooltool's dependency)
from pooltool.events.datatypes import EventType  # noqa: E402
from pooltool.objects.table.specs import PocketTableSpecs  # noqa: E402

import billiards  # noqa: E402
import billiards.pooltool as interop  # noqa: E402

L, W, R = 1.9812, 0.9906, 0.028575
SPECS = attrs.evolve(PocketTableSpecs(), l=L, w=W, cushion_height=0.03629, corner_pocket_width=0.1159,
                     side_pocket_width=0.1286)


def system(balls, speed, phi, a=0.0, b=0.0):
    """A pooltool System: `balls` in pooltool's frame (x across, y along), the first the cue ball."""
    ids = ["cue"] + [str(i) for i in range(1, len(balls))]
    pt_balls = {bid: pt.Ball.create(bid, xy=xy, m=0.170, R=R, u_b=0.06) for bid, xy in zip(ids, balls)}
    s = pt.System(cue=pt.Cue(cue_ball_id="cue"), table=pt.Table.from_table_specs(SPECS), balls=pt_balls)
    s.strike(V0=speed, phi=phi, theta=0.0, a=a, b=b)
    return s


SHOTS = [
    ("straight with follow", [(0.5, 0.5), (0.5, 1.5)], 2.0, 90.0, 0.0, 0.4),
    ("half-ball cut", [(0.54, 0.6), (0.54 - R, 1.3)], 2.5, 90.0, 0.0, 0.3),
    ("a combination", [(0.5, 0.5), (0.5, 1.0), (0.48, 1.3)], 3.0, 90.0, 0.0, 0.0),
    ("into the side cushion with side spin", [(0.5, 0.6)], 1.5, 45.0, 0.2, 0.0),
]


def collisions(kinds_and_balls):
    return [(k, b) for k, b, _ in kinds_and_balls]


@pytest.mark.parametrize("name,balls,speed,phi,a,b", SHOTS)
def test_a_converted_system_plays_pooltools_shot(name, balls, speed, phi, a, b):
    theirs = system(balls, speed, phi, a, b)
    table, physics, layout, cue, struck, ids = interop.from_system(theirs, SPECS)
    assert ids[0] == "cue" and table.length == L and table.width == W and physics.ball_friction == 0.06
    for k, (x, y) in enumerate(balls):  # ours (x, y) is pooltool's (y, w − x)
        assert layout[k]["position"][:2].tolist() == [y, W - x]
    assert cue.azimuth == pytest.approx(math.radians(phi - 90.0)) and cue.side_offset == -a

    shot = billiards.Shot(table, physics, layout)
    shot.strike(struck, cue)
    shot.play()
    pt.simulate(theirs, engine=interop.matched_engine(), inplace=True)

    kinds = {EventType.BALL_BALL: "ball", EventType.BALL_LINEAR_CUSHION: "cushion",
             EventType.BALL_CIRCULAR_CUSHION: "jaw", EventType.BALL_POCKET: "pocket"}
    index = {bid: k for k, bid in enumerate(ids)}
    other = [(kinds[e.event_type], tuple(sorted(index[i] for i in e.ids if i in index)), float(e.time))
             for e in theirs.events if e.event_type in kinds][:4]
    ours = [(str(e["kind"]), tuple(sorted({int(e["first"]), int(e["second"])} if e["kind"] == "ball"
                                          else {int(e["first"])})), float(e["time"]))
            for e in shot.events if e["kind"] in ("ball", "cushion", "jaw", "pocket")][:4]
    assert collisions(ours) == collisions(other)
    for mine, its in zip(ours, other):
        assert mine[2] == pytest.approx(its[2], rel=0.02)

    events = interop.to_events(shot, ids)
    assert events[0].event_type == EventType.STICK_BALL and events[0].agents[1].id == "cue"
    first_ball = next(e for e in events if e.event_type == EventType.BALL_BALL) if len(balls) > 1 else None
    if first_ball is not None:
        ours_first = next(e for e in shot.events if e["kind"] == "ball")
        r = first_ball.agents[0].final.state.rvw[0]
        assert [r[1], W - r[0]] == pytest.approx(ours_first["first_after"]["position"][:2].tolist(), abs=1e-15)
        assert first_ball.time == ours_first["time"]
