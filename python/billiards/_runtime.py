"""The runtime's calls over arrays: every argument broadcast against the others, the loop in C++.

Each result equals, bit for bit, what the C++ call billiards::checked::<name> returns for that case,
and every case is validated as that call validates it: a case out of its domain raises ValueError
naming the argument, its value and what was expected (and, in a batch, the case's flat index).
Lengths are in metres, times in seconds, masses in kilograms, velocities in m/s, angular velocities in
rad/s (any consistent units work: the formulas are homogeneous).
"""

from __future__ import annotations

import numpy as np

from . import _billiards
from ._arrays import as_array, broadcast, call_dtype


def _vectors_alike(function: str, rows: dict) -> int:
    sizes = {name: a.shape[-1] for name, a in rows.items()}
    if len(set(sizes.values())) > 1:
        listed = ", ".join(f"{name} {size}" for name, size in sizes.items())
        raise ValueError(f"{function}: the vectors' lengths differ ({listed}); expected all 2 or all 3")
    return next(iter(sizes.values()))


def _shaped(shape: tuple, *results):
    out = tuple(r.reshape(shape + r.shape[1:]) for r in results)
    return out if len(out) > 1 else out[0]


def collide(m1, v1, m2, v2, n, restitution=1.0):
    """Two balls meeting with unit contact normal ``n`` (the paper's collision; with restitution e).

    x1 = v1 + (1 + e)/(1 + m1/m2) ((v2 − v1)·n) n and x2 = v2 − (1 + e)/(1 + m2/m1) ((v2 − v1)·n) n:
    momentum conserved, Newton's law (x2 − x1)·n = −e (v2 − v1)·n; e = 1 (the default) is the paper's
    elastic collision, bit for bit.

    Parameters
    ----------
    m1, m2 : array_like
        The masses (kg): positive, one of them may be ``inf`` (an immovable body), not both.
    v1, v2 : array_like, shape (..., 2) or (..., 3)
        The velocities before (m/s), components finite.
    n : array_like, shape (..., 2) or (..., 3)
        The unit contact normal (either direction).
    restitution : array_like
        e in [0, 1] (dimensionless).

    Returns
    -------
    (x1, x2) : the velocities after (m/s), of the broadcast shape, in the arguments' dtype.
    """
    function = "collide"
    args = dict(m1=m1, v1=v1, m2=m2, v2=v2, n=n, restitution=restitution)
    dtype = call_dtype(function, args)
    scalars = {k: as_array(function, k, args[k], dtype) for k in ("m1", "m2", "restitution")}
    vectors = {k: as_array(function, k, args[k], dtype, (2, 3)) for k in ("v1", "v2", "n")}
    size = _vectors_alike(function, vectors)
    shape, flat, rows = broadcast(function, scalars, vectors)
    call = _billiards.collide2 if size == 2 else _billiards.collide3
    x1, x2 = call(flat["m1"], rows["v1"], flat["m2"], rows["v2"], rows["n"], flat["restitution"], shape != ())
    return _shaped(shape, x1, x2)


def time_of_impact(p1, v1, p2, v2, distance):
    """When two spheres moving at constant velocities first come within ``distance`` of each other.

    Parameters
    ----------
    p1, p2 : array_like, shape (..., 2) or (..., 3)
        The centres now (m).
    v1, v2 : array_like, shape (..., 2) or (..., 3)
        The velocities (m/s).
    distance : array_like
        The contact distance (m), the sum of the radii: positive.

    Returns
    -------
    The time from now (s) of the broadcast shape: 0 for spheres already within ``distance`` and
    approaching, ``inf`` where they never touch.
    """
    function = "time_of_impact"
    args = dict(p1=p1, v1=v1, p2=p2, v2=v2, distance=distance)
    dtype = call_dtype(function, args)
    scalars = {"distance": as_array(function, "distance", distance, dtype)}
    vectors = {k: as_array(function, k, args[k], dtype, (2, 3)) for k in ("p1", "v1", "p2", "v2")}
    size = _vectors_alike(function, vectors)
    shape, flat, rows = broadcast(function, scalars, vectors)
    call = _billiards.time_of_impact2 if size == 2 else _billiards.time_of_impact3
    times = call(rows["p1"], rows["v1"], rows["p2"], rows["v2"], flat["distance"], shape != ())
    return _shaped(shape, times)


def collide_with_friction(m1, radius1, v1, w1, m2, radius2, v2, w2, n, restitution, friction):
    """Two spinning solid spheres meeting with Coulomb friction at the contact.

    The normal impulse is restitution's (as ``collide``); the tangential impulse opposes the slip of the
    contact points, at most ``friction`` times the normal one (sticking where that suffices).

    Parameters
    ----------
    m1, m2 : array_like
        The masses (kg), positive and finite.
    radius1, radius2 : array_like
        The radii (m), positive and finite.
    v1, v2 : array_like, shape (..., 3)
        The velocities before (m/s).
    w1, w2 : array_like, shape (..., 3)
        The angular velocities before (rad/s).
    n : array_like, shape (..., 3)
        The unit normal from ball 1's centre to ball 2's.
    restitution : array_like
        e in [0, 1].
    friction : array_like
        μ ≥ 0 between the balls.

    Returns
    -------
    (v1, w1, v2, w2) after the contact; a pair that does not approach is returned unchanged.
    """
    function = "collide_with_friction"
    args = dict(m1=m1, radius1=radius1, v1=v1, w1=w1, m2=m2, radius2=radius2, v2=v2, w2=w2, n=n,
                restitution=restitution, friction=friction)
    dtype = call_dtype(function, args)
    scalars = {k: as_array(function, k, args[k], dtype) for k in ("m1", "radius1", "m2", "radius2", "restitution",
                                                                   "friction")}
    vectors = {k: as_array(function, k, args[k], dtype, 3) for k in ("v1", "w1", "v2", "w2", "n")}
    shape, f, r = broadcast(function, scalars, vectors)
    out = _billiards.collide_with_friction(f["m1"], f["radius1"], r["v1"], r["w1"], f["m2"], f["radius2"], r["v2"],
                                           r["w2"], r["n"], f["restitution"], f["friction"], shape != ())
    return _shaped(shape, *out)


def strike(mass, radius, velocity, angular_velocity, speed, azimuth=0.0, elevation=0.0, side_offset=0.0,
           up_offset=0.0, cue_mass=0.567, tip_restitution=1.0):
    """A ball struck by a cue (Alciatore's instantaneous point model, TP A-30, with the tip's restitution).

    Parameters
    ----------
    mass, radius : array_like
        The ball's mass (kg) and radius (m).
    velocity, angular_velocity : array_like, shape (..., 3)
        The ball's state before the strike (m/s, rad/s).
    speed : array_like
        The cue's speed along its axis (m/s), ≥ 0.
    azimuth : array_like
        The cue's direction in the table's plane (radians, from +x towards +y).
    elevation : array_like
        The cue's elevation above the table (radians), in [0, π/2).
    side_offset, up_offset : array_like
        Where the tip meets the ball, right and up of the centre in units of the radius (a² + b² < 1),
        in the plane perpendicular to the cue.
    cue_mass : array_like
        The cue's mass (kg); 0.567 by default.
    tip_restitution : array_like
        The tip's restitution in [0, 1]; 1 by default.

    Returns
    -------
    (velocity, angular_velocity) after the strike.
    """
    function = "strike"
    args = dict(mass=mass, radius=radius, velocity=velocity, angular_velocity=angular_velocity, speed=speed,
                azimuth=azimuth, elevation=elevation, side_offset=side_offset, up_offset=up_offset,
                cue_mass=cue_mass, tip_restitution=tip_restitution)
    dtype = call_dtype(function, args)
    cue_fields = ("cue_mass", "speed", "azimuth", "elevation", "side_offset", "up_offset", "tip_restitution")
    scalars = {k: as_array(function, k, args[k], dtype) for k in ("mass", "radius") + cue_fields}
    vectors = {k: as_array(function, k, args[k], dtype, 3) for k in ("velocity", "angular_velocity")}
    shape, f, r = broadcast(function, scalars, vectors)
    cue = np.ascontiguousarray(np.stack([f[k] for k in cue_fields], axis=-1))
    out = _billiards.strike(f["mass"], f["radius"], r["velocity"], r["angular_velocity"], cue, shape != ())
    return _shaped(shape, *out)


def collide_with_cushion(mass, radius, velocity, angular_velocity, normal, height, restitution=0.85,
                         friction=0.2):
    """A spinning ball meeting a cushion's nose (the immovable limit of the frictional contact, Han 2005).

    Parameters
    ----------
    mass, radius : array_like
        The ball's mass (kg) and radius (m).
    velocity, angular_velocity : array_like, shape (..., 3)
        The ball's state (m/s, rad/s), on the cloth: velocity's z component 0.
    normal : array_like, shape (..., 3)
        The cushion's unit normal from the ball into the cushion, horizontal.
    height : array_like
        The nose's height above the cloth (m), R ≤ h < 2R.
    restitution, friction : array_like
        The cushion's e in [0, 1] and μ ≥ 0.

    Returns
    -------
    (velocity, angular_velocity) after the contact; a ball not moving into the cushion is unchanged.
    """
    function = "collide_with_cushion"
    args = dict(mass=mass, radius=radius, velocity=velocity, angular_velocity=angular_velocity, normal=normal,
                height=height, restitution=restitution, friction=friction)
    dtype = call_dtype(function, args)
    scalars = {k: as_array(function, k, args[k], dtype) for k in ("mass", "radius", "height", "restitution",
                                                                   "friction")}
    vectors = {k: as_array(function, k, args[k], dtype, 3) for k in ("velocity", "angular_velocity", "normal")}
    shape, f, r = broadcast(function, scalars, vectors)
    cushion = np.ascontiguousarray(np.stack([f["height"], f["restitution"], f["friction"]], axis=-1))
    out = _billiards.collide_with_cushion(f["mass"], f["radius"], r["velocity"], r["angular_velocity"], r["normal"],
                                          cushion, shape != ())
    return _shaped(shape, *out)


def earliest_contact(coefficients, horizon):
    """The earliest time in [0, horizon] at which an event polynomial reaches 0, decided exactly.

    Parameters
    ----------
    coefficients : array_like, shape (..., 3) or (..., 5)
        c0, c1, … of p(t) = Σ c_k t^k: a cushion's (3) or a contact's (5) event polynomial, p > 0 apart.
    horizon : array_like
        The last time looked at (s), finite and ≥ 0.

    Returns
    -------
    The time (s), of the broadcast shape, ``inf`` where p stays above 0 up to the horizon.
    """
    function = "earliest_contact"
    dtype = call_dtype(function, dict(coefficients=coefficients, horizon=horizon))
    vectors = {"coefficients": as_array(function, "coefficients", coefficients, dtype, (3, 5))}
    scalars = {"horizon": as_array(function, "horizon", horizon, dtype)}
    shape, f, r = broadcast(function, scalars, vectors)
    call = _billiards.earliest_contact3 if r["coefficients"].shape[1] == 3 else _billiards.earliest_contact5
    return _shaped(shape, call(r["coefficients"], f["horizon"], shape != ()))


def _cloth_rows(function: str, cloth, dtype):
    from ._shot import Cloth
    cloth = Cloth() if cloth is None else cloth
    if not isinstance(cloth, Cloth):
        raise TypeError(f"{function}: cloth is {type(cloth).__name__}, expected a billiards.Cloth")
    return np.array([cloth.sliding_friction, cloth.rolling_friction, cloth.spinning_friction, cloth.gravity],
                    dtype=dtype)


def _ball_on_cloth(function: str, args: dict, dtype, extra_scalars=()):
    scalars = {k: as_array(function, k, args[k], dtype) for k in ("radius",) + tuple(extra_scalars)}
    vectors = {k: as_array(function, k, args[k], dtype, 3) for k in ("position", "velocity", "angular_velocity")}
    vectors["cloth"] = _cloth_rows(function, args["cloth"], dtype)
    return broadcast(function, scalars, vectors)


def evolve(position, velocity, angular_velocity, radius, t, cloth=None):
    """Balls on the cloth after ``t`` seconds, across as many phases as ``t`` spans (sliding, rolling,
    spinning, at rest), each by its derived closed form.

    Parameters
    ----------
    position, velocity, angular_velocity : array_like, shape (..., 3)
        The centre (m; z equal to the radius: on the table), the velocity (m/s, horizontal) and the spin
        (rad/s).
    radius : array_like
        The balls' radius (m).
    t : array_like
        The time (s), ≥ 0.
    cloth : Cloth, optional
        μ_s, μ_r, μ_sp and g; pooltool's defaults where omitted.

    Returns
    -------
    (position, velocity, angular_velocity) after ``t``.
    """
    function = "evolve"
    args = dict(position=position, velocity=velocity, angular_velocity=angular_velocity, radius=radius, t=t,
                cloth=cloth)
    dtype = call_dtype(function, {k: v for k, v in args.items() if k != "cloth"})
    shape, f, r = _ball_on_cloth(function, args, dtype, ("t",))
    out = _billiards.evolve(r["position"], r["velocity"], r["angular_velocity"], f["radius"], f["t"], r["cloth"],
                            shape != ())
    return _shaped(shape, *out)


def _phase(function: str, position, velocity, angular_velocity, radius, cloth):
    args = dict(position=position, velocity=velocity, angular_velocity=angular_velocity, radius=radius, cloth=cloth)
    dtype = call_dtype(function, {k: v for k, v in args.items() if k != "cloth"})
    shape, f, r = _ball_on_cloth(function, args, dtype)
    phases, duration = _billiards.phase(r["position"], r["velocity"], r["angular_velocity"], f["radius"],
                                        r["cloth"], shape != ())
    return shape, phases, duration


def transition_time(position, velocity, angular_velocity, radius, cloth=None):
    """How long each ball's phase on the cloth lasts (s): the slide, the roll or the spin; ``inf`` at rest.
    Arguments as for ``evolve``."""
    shape, _, duration = _phase("transition_time", position, velocity, angular_velocity, radius, cloth)
    return _shaped(shape, duration)


def motion(position, velocity, angular_velocity, radius, cloth=None):
    """Each ball's phase on the cloth: "sliding", "rolling", "spinning" or "stationary" (a str array).
    Arguments as for ``evolve``."""
    shape, phases, _ = _phase("motion", position, velocity, angular_velocity, radius, cloth)
    return _shaped(shape, np.asarray(("sliding", "rolling", "spinning", "stationary"))[phases])
