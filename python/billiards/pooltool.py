"""Interop with pooltool (github ekiefl/pooltool), where it is importable.

``from_system(system)`` converts a pooltool ``System`` — its table, balls and cue — into ours: a
``PoolTable``, ``PoolPhysics``, a layout, a ``Cue`` and the struck ball's index, with the ball ids in our
index order. ``to_events(shot, ids)`` turns a shot's events into pooltool ``Event`` objects. The frames:
pooltool's x runs across the table and y along it; ours is x along the length, y across: our (x, y) is
pooltool's (y, w − x), a rotation, so spins turn with the vectors and keep their sense (ω_z the same).
pooltool's cue azimuth ``phi`` (degrees, from its +x) is ours + 90°; its side offset ``a`` is positive to
the left, ours to the right.

What stays pooltool's own where the two are compared (docs/shot.md, "Against pooltool"): its default
models differ from ours (Stronge's compliant cushion, a speed-dependent ball–ball friction, squirt in the
strike); ``matched_engine()`` builds its engine with ours where it has them.
"""

from __future__ import annotations

import math

import numpy as np

from ._shot import Cloth, Cue, PoolPhysics, PoolTable, Shot, ball_dtype

try:
    import pooltool as _pt
except ImportError as error:  # pragma: no cover - depends on the machine
    raise ImportError(f"billiards.pooltool needs pooltool importable ({error})") from None

from pooltool.events.datatypes import Agent, AgentType, Event, EventType


def _to_ours(xy, w):
    return np.array([xy[1], w - xy[0]])


def _vector_to_ours(v):
    return np.array([v[1], -v[0], v[2]])


def _vector_to_theirs(v):
    return np.array([-v[1], v[0], v[2]])


def table_from(system, specs=None) -> PoolTable:
    """Our table for pooltool's: its length and width, its cushions' height, no pockets where it has none
    (a carom table), and the pocket mouths of ``specs`` (a pooltool ``PocketTableSpecs``) where given,
    else ours (the WPA's)."""
    table = system.table
    linear = next(iter(table.cushion_segments.linear.values()))
    fields = dict(length=float(table.l), width=float(table.w), nose_height=float(linear.height),
                  has_pockets=bool(table.pockets))
    if specs is not None:
        fields.update(corner_mouth=float(specs.corner_pocket_width), side_mouth=float(specs.side_pocket_width),
                      corner_jaw_radius=float(specs.corner_jaw_radius), side_jaw_radius=float(specs.side_jaw_radius),
                      corner_pocket_radius=float(specs.corner_pocket_radius),
                      corner_pocket_depth=float(specs.corner_pocket_depth),
                      side_pocket_radius=float(specs.side_pocket_radius),
                      side_pocket_depth=float(specs.side_pocket_depth))
    return PoolTable(**fields)


def physics_from(system) -> PoolPhysics:
    """Our physics for pooltool's balls' parameters (the cue ball's): R, m, μ_s, μ_r, μ_sp, g, e_b, its
    ball–ball friction u_b as our constant μ, e_c and f_c."""
    p = system.balls[system.cue.cue_ball_id].params
    cloth = Cloth(float(p.u_s), float(p.u_r), float(p.u_sp), float(p.g))
    return PoolPhysics(radius=float(p.R), mass=float(p.m), cloth=cloth, ball_restitution=float(p.e_b),
                       ball_friction=float(p.u_b), cushion_restitution=float(p.e_c), cushion_friction=float(p.f_c))


def from_system(system, specs=None):
    """pooltool's ``System`` as ours: (table, physics, layout, cue, struck, ids). ``ids`` lists its ball ids
    in our index order, the cue ball first; ``struck`` is the cue ball's index (0)."""
    cue_id = system.cue.cue_ball_id
    ids = [cue_id] + sorted(b for b in system.balls if b != cue_id)
    w = float(system.table.w)
    layout = np.zeros(len(ids), ball_dtype)
    for k, bid in enumerate(ids):
        state = system.balls[bid].state
        r, v, spin = (np.asarray(x, dtype=np.float64) for x in state.rvw)
        layout[k]["position"][:2] = _to_ours(r, w)
        layout[k]["velocity"] = _vector_to_ours(v)
        layout[k]["angular_velocity"] = _vector_to_ours(spin)
        layout[k]["pocketed"] = int(state.s) == 4
    c = system.cue
    cue = Cue(speed=float(c.V0), azimuth=math.radians(float(c.phi) - 90.0), elevation=math.radians(float(c.theta)),
              side_offset=-float(c.a), up_offset=float(c.b), mass=float(c.specs.M))
    return table_from(system, specs), physics_from(system), layout, cue, 0, ids


_KINDS = {"strike": EventType.STICK_BALL, "ball": EventType.BALL_BALL, "cushion": EventType.BALL_LINEAR_CUSHION,
          "jaw": EventType.BALL_CIRCULAR_CUSHION, "pocket": EventType.BALL_POCKET}
_TRANSITIONS = {("sliding", "rolling"): EventType.SLIDING_ROLLING,
                ("rolling", "stationary"): EventType.ROLLING_STATIONARY,
                ("rolling", "spinning"): EventType.ROLLING_SPINNING,
                ("spinning", "stationary"): EventType.SPINNING_STATIONARY}
_STATES = {"stationary": 0, "spinning": 1, "sliding": 2, "rolling": 3}
_OTHERS = {"cushion": AgentType.LINEAR_CUSHION_SEGMENT, "jaw": AgentType.CIRCULAR_CUSHION_SEGMENT,
           "pocket": AgentType.POCKET}


def _ball(bid: str, after, motion: str, w: float, physics: PoolPhysics):
    ball = _pt.Ball.create(bid, xy=(0.0, 0.0), R=physics.radius, m=physics.mass)
    r = np.array([w - after["position"][1], after["position"][0], physics.radius])
    ball.state.rvw = np.array([r, _vector_to_theirs(after["velocity"]), _vector_to_theirs(after["angular_velocity"])])
    ball.state.s = 4 if after["pocketed"] else _STATES[motion]
    return ball


def to_events(shot: Shot, ids) -> list:
    """The shot's events as pooltool ``Event`` objects: each kind as its ``EventType`` (a pooltool-less
    phase change, such as a pressed pair's, is left out), the balls as agents carrying their states
    after it in pooltool's frame, a cushion, jaw or pocket as an agent named ``cushion3``, ``jaw7`` or
    ``pocket2`` by our index (pooltool names its own segments otherwise)."""
    w = shot._table.width
    physics = shot._physics
    out = []
    for e in shot.events:
        kind = str(e["kind"])
        first = ids[int(e["first"])]
        if kind == "transition":
            event_type = _TRANSITIONS.get((str(e["from"]), str(e["to"])))
            if event_type is None:
                continue
            agents = [Agent(first, AgentType.BALL, None, _ball(first, e["first_after"], str(e["to"]), w, physics))]
        elif kind == "strike":
            event_type = _KINDS[kind]
            agents = [Agent("cue_stick", AgentType.CUE),
                      Agent(first, AgentType.BALL, None, _ball(first, e["first_after"], str(e["to"]), w, physics))]
        else:
            event_type = _KINDS[kind]
            agents = [Agent(first, AgentType.BALL, None, _ball(first, e["first_after"], str(e["to"]), w, physics))]
            if kind == "ball":
                second = ids[int(e["second"])]
                agents.append(Agent(second, AgentType.BALL, None,
                                    _ball(second, e["second_after"], "sliding", w, physics)))
            else:
                agents.append(Agent(f"{kind}{int(e['second'])}", _OTHERS[kind]))
        out.append(Event(event_type=event_type, agents=tuple(agents), time=float(e["time"])))
    return out


def matched_engine():
    """pooltool's event-based engine set to our models where it has them: Han (2005) at straight cushions
    and jaws, the instantaneous point strike without squirt, its frictional inelastic ball–ball contact
    with a constant μ (each ball's u_b)."""
    from pooltool.physics.resolve.ball_ball.friction import AverageBallBallFriction
    from pooltool.physics.resolve.ball_ball.frictional_inelastic import FrictionalInelastic
    from pooltool.physics.resolve.ball_cushion.han_2005.model import Han2005Circular, Han2005Linear
    from pooltool.physics.resolve.ball_pocket import CanonicalBallPocket
    from pooltool.physics.resolve.ball_table import FrictionalInelasticTable
    from pooltool.physics.resolve.resolver import Resolver
    from pooltool.physics.resolve.stick_ball.instantaneous_point import InstantaneousPoint2D
    from pooltool.physics.resolve.transition import CanonicalTransition
    return _pt.evolution.SimulationEngine(resolver=Resolver(
        ball_ball=FrictionalInelastic(friction=AverageBallBallFriction()),
        ball_linear_cushion=Han2005Linear(), ball_circular_cushion=Han2005Circular(),
        ball_pocket=CanonicalBallPocket(),
        stick_ball=InstantaneousPoint2D(english_throttle=1.0, squirt_throttle=0.0),
        ball_table=FrictionalInelasticTable(min_bounce_height=0.005), transition=CanonicalTransition()))
