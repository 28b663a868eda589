"""The shot engine: tables, physics, layouts, the cue and the Shot, with numpy structured arrays.

Units: metres, seconds, kilograms, radians; velocities in m/s, angular velocities in rad/s. The table's
frame: x along its length (0 at the head cushion's nose), y across (0 and ``width`` at the side
cushions' noses), z up with the cloth at z = 0, so a ball's centre is at z = R.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from . import _billiards

Cloth = _billiards.Cloth
PoolPhysics = _billiards.PoolPhysics
PoolTable = _billiards.PoolTable
ShotOptions = _billiards.ShotOptions
EventLimitReached = _billiards.EventLimitReached
EventLimitReached.__doc__ = "A run stopped at the engine's limit on events (ShotOptions.event_limit for a shot)."
BrokenInvariant = _billiards.BrokenInvariant
BrokenInvariant.__doc__ = ("An invariant broken at an event (two balls overlapping, a ball off the table, kinetic "
                           "energy gained): a defect of the engine, reported with the time, the event and the balls.")

#: A ball of a layout or of an event: its centre (m), velocity (m/s), angular velocity (rad/s) and
#: whether it is out of play.
ball_dtype = np.dtype([("position", "<f8", (3,)), ("velocity", "<f8", (3,)), ("angular_velocity", "<f8", (3,)),
                       ("pocketed", "?")])

#: The kinds of events, in the order in which events at the same time are resolved.
EVENT_KINDS = ("strike", "ball", "cushion", "jaw", "pocket", "transition")
#: The phases of a ball's motion on the cloth.
MOTIONS = ("sliding", "rolling", "spinning", "stationary")

#: An event of a shot: its time (s), kind (EVENT_KINDS), the ball (``first``), the other body
#: (``second``: a ball, cushion, jaw or pocket index, else ``first``), the first ball's phase before
#: and after, and the states after of the first ball and of the second (a ball–ball event; else the
#: first's again).
event_dtype = np.dtype([("time", "<f8"), ("kind", "U10"), ("first", "<i8"), ("second", "<i8"),
                        ("from", "U10"), ("to", "U10"), ("first_after", ball_dtype), ("second_after", ball_dtype)])

#: A cue's parameters, as Cue's fields.
cue_dtype = np.dtype([("mass", "<f8"), ("speed", "<f8"), ("azimuth", "<f8"), ("elevation", "<f8"),
                      ("side_offset", "<f8"), ("up_offset", "<f8"), ("tip_restitution", "<f8")])


@dataclass(frozen=True)
class Cue:
    """A cue at the moment it strikes.

    Attributes
    ----------
    speed : float
        Its speed along its axis (m/s), ≥ 0. pooltool's ``V0``.
    azimuth : float
        Its direction in the table's plane (radians), from +x towards +y: the direction the ball is
        driven. pooltool's ``phi`` is the same angle in degrees.
    elevation : float
        Its elevation above the table (radians), in [0, π/2). pooltool's ``theta`` in degrees.
    side_offset : float
        Where the tip meets the ball, to the right of its centre as the player sees it, in units of
        the radius (a; right positive: right-hand side spin). pooltool's ``a``.
    up_offset : float
        Where the tip meets the ball, above its centre, in units of the radius (b; up positive:
        follow, negative: draw); a² + b² < 1. pooltool's ``b``.
    mass : float
        The cue's mass (kg), 0.567 by default (pooltool's ``M``).
    tip_restitution : float
        The tip's restitution in [0, 1], 1 by default (Alciatore's TP A-30).
    """

    speed: float
    azimuth: float = 0.0
    elevation: float = 0.0
    side_offset: float = 0.0
    up_offset: float = 0.0
    mass: float = 0.567
    tip_restitution: float = 1.0

    def as_array(self) -> np.ndarray:
        """The cue as a one-element array of ``cue_dtype``."""
        return cues(self.speed, self.azimuth, self.elevation, self.side_offset, self.up_offset, self.mass,
                    self.tip_restitution).reshape(1)

    @classmethod
    def from_pooltool(cls, V0: float, phi: float, theta: float = 0.0, a: float = 0.0, b: float = 0.0,
                      M: float = 0.567) -> "Cue":
        """The cue pooltool's ``Cue(V0, phi, theta, a, b)`` describes (its angles in degrees)."""
        return cls(speed=V0, azimuth=math.radians(phi), elevation=math.radians(theta), side_offset=a, up_offset=b,
                   mass=M)


def cues(speed, azimuth=0.0, elevation=0.0, side_offset=0.0, up_offset=0.0, mass=0.567, tip_restitution=1.0):
    """Many cues at once: the arguments (Cue's fields, in its units) broadcast to an array of cue_dtype."""
    fields = dict(mass=mass, speed=speed, azimuth=azimuth, elevation=elevation, side_offset=side_offset,
                  up_offset=up_offset, tip_restitution=tip_restitution)
    arrays = {}
    for name, value in fields.items():
        array = np.asarray(value)
        if array.dtype.kind not in "fiu":
            raise TypeError(f"cues: {name} has dtype {array.dtype}, expected numbers")
        arrays[name] = array
    try:
        shape = np.broadcast_shapes(*(a.shape for a in arrays.values()))
    except ValueError:
        listed = ", ".join(f"{k} {a.shape}" for k, a in arrays.items())
        raise ValueError(f"cues: the arguments' shapes do not broadcast together ({listed})") from None
    out = np.empty(shape, cue_dtype)
    for name, array in arrays.items():
        out[name] = array
    return out


def balls(position, velocity=None, angular_velocity=None, pocketed=None) -> np.ndarray:
    """A layout of N balls from arrays: an array of ball_dtype.

    Parameters
    ----------
    position : array_like, shape (N, 2) or (N, 3)
        The centres (m) on the table; z is set to the radius when the shot is made.
    velocity, angular_velocity : array_like, shape (N, 3), optional
        m/s and rad/s; at rest where omitted.
    pocketed : array_like of bool, shape (N,), optional
        Out of play; none where omitted.
    """
    position = np.asarray(position, dtype=np.float64)
    if position.ndim != 2 or position.shape[1] not in (2, 3):
        raise ValueError(f"balls: position has shape {position.shape}, expected (N, 2) or (N, 3)")
    n = position.shape[0]
    out = np.zeros(n, ball_dtype)
    out["position"][:, : position.shape[1]] = position
    for name, value in (("velocity", velocity), ("angular_velocity", angular_velocity)):
        if value is not None:
            value = np.asarray(value, dtype=np.float64)
            if value.shape != (n, 3):
                raise ValueError(f"balls: {name} has shape {value.shape}, expected ({n}, 3)")
            out[name] = value
    if pocketed is not None:
        pocketed = np.asarray(pocketed)
        if pocketed.shape != (n,) or pocketed.dtype != np.bool_:
            raise ValueError(f"balls: pocketed is {pocketed.dtype} of shape {pocketed.shape}, expected bool ({n},)")
        out["pocketed"] = pocketed
    return out


def _from_columns(columns) -> np.ndarray:
    position, velocity, angular_velocity, pocketed = columns
    out = np.empty(len(pocketed), ball_dtype)
    out["position"], out["velocity"] = position, velocity
    out["angular_velocity"], out["pocketed"] = angular_velocity, pocketed
    return out


def _events_from_columns(columns) -> np.ndarray:
    time, kind, first, second, before, after, first_after, second_after = columns
    out = np.empty(len(time), event_dtype)
    out["time"], out["first"], out["second"] = time, first, second
    out["kind"] = np.asarray(EVENT_KINDS)[kind]
    out["from"] = np.asarray(MOTIONS)[before]
    out["to"] = np.asarray(MOTIONS)[after]
    out["first_after"] = _from_columns(first_after)
    out["second_after"] = _from_columns(second_after)
    return out


def check_layout(function: str, layout) -> np.ndarray:
    """`layout` as an array of ball_dtype (C-contiguous), or TypeError / ValueError naming it."""
    if not isinstance(layout, np.ndarray) or layout.dtype != ball_dtype:
        raise TypeError(f"{function}: balls is {_describe(layout)}, expected an array of billiards.ball_dtype "
                        f"(billiards.balls(...), billiards.rack(...))")
    return np.ascontiguousarray(layout)


def _describe(value) -> str:
    if isinstance(value, np.ndarray):
        return f"an array of shape {value.shape} and dtype {value.dtype}"
    return type(value).__name__


def pool_table(size: str = "9ft") -> PoolTable:
    """A pool table preset: "9ft" (WPA, 2.54 × 1.27 m), "8ft" (WPA, 2.3368 × 1.1684 m) or "7ft" (1.9812 ×
    0.9906 m), each with the WPA's pocket mouths and nose height."""
    if not isinstance(size, str):
        raise TypeError(f"pool_table: size is {_describe(size)}, expected '7ft', '8ft' or '9ft'")
    return _billiards.pool_table(size)


TABLES = ("7ft", "8ft", "9ft", "snooker", "carom")


def table_preset(name: str = "9ft") -> PoolTable:
    """A table by name: "7ft", "8ft", "9ft" (pool_table), "snooker" (the WPBSA's 12-ft table, 3.569 ×
    1.778 m, pockets with curved facings) or "carom" (the UMB's 2.84 × 1.42 m, no pockets); the sources
    of every dimension are in docs/games.md."""
    if not isinstance(name, str):
        raise TypeError(f"table_preset: name is {_describe(name)}, expected one of {TABLES}")
    return _billiards.table_preset(name)


def physics_preset(name: str = "9ft") -> PoolPhysics:
    """The balls' and the cloth's physics of table_preset(name): the pool physics on the pool tables,
    52.5 mm balls of 0.140 kg on the snooker table, 61.5 mm balls of 0.210 kg on the carom table's faster
    heated cloth."""
    if not isinstance(name, str):
        raise TypeError(f"physics_preset: name is {_describe(name)}, expected one of {TABLES}")
    return _billiards.physics_preset(name)


def snooker_table() -> PoolTable:
    """The snooker table: table_preset("snooker")."""
    return table_preset("snooker")


def carom_table() -> PoolTable:
    """The carom table: table_preset("carom")."""
    return table_preset("carom")


def rack(table: PoolTable, physics: PoolPhysics | None = None, kind: str = "9ball", jitter: float = 0.0,
         seed: int = 0) -> np.ndarray:
    """The balls of a game's start. "9ball" (a diamond of 9) or "8ball" (a triangle of 15): the cue ball
    (index 0) on the head spot, the object balls racked on the foot spot; "snooker": the snooker set-up
    (0 the white in the D, 1–15 the reds behind the pink, 16–21 yellow, green, brown, blue, pink, black on
    their spots); "3cushion": the UMB's opening position (0 the white on the head string 182 mm beside
    the head spot — on the side +y for an even ``seed``, −y for an odd —, 1 the yellow on the head spot,
    2 the red on the foot spot). ``jitter`` in [0, 1] spreads a rack by 1 + jitter and moves each ball by
    up to jitter/2 of a radius, drawn from ``seed`` (every gap ≥ jitter R). ``physics`` defaults to the
    game's (physics_preset). Returns an array of ball_dtype."""
    if not isinstance(kind, str):
        raise TypeError(f"rack: kind is {_describe(kind)}, expected '9ball', '8ball', 'snooker' or '3cushion'")
    if physics is None:
        physics = physics_preset({"snooker": "snooker", "3cushion": "carom"}.get(kind, "9ft"))
    if not (0 <= jitter <= 1):
        raise ValueError(f"rack: jitter is {jitter!r}, expected a number in [0, 1]")
    return _from_columns(_billiards.rack(table, physics, kind, float(jitter), _seed("rack", seed)))


def scatter(table: PoolTable, physics: PoolPhysics | None = None, count: int = 16, seed: int = 0) -> np.ndarray:
    """``count`` balls (1 to 16) at rest placed at random from ``seed`` on the cloth, about a quarter of
    them frozen to another ball and a quarter to a cushion. Returns an array of ball_dtype."""
    physics = PoolPhysics() if physics is None else physics
    if isinstance(count, bool) or not isinstance(count, (int, np.integer)) or not (1 <= count <= 16):
        raise ValueError(f"scatter: count is {count!r}, expected a whole number from 1 to 16")
    return _from_columns(_billiards.scatter(table, physics, int(count), _seed("scatter", seed)))


def _seed(function: str, seed) -> int:
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or not (0 <= seed < 2**64):
        raise ValueError(f"{function}: seed is {seed!r}, expected a whole number in [0, 2**64)")
    return int(seed)


def cue_numbers(function: str, cue) -> tuple:
    """A Cue (or a cue_dtype record) as its seven numbers in the compiled module's order."""
    if isinstance(cue, Cue):
        return (float(cue.mass), float(cue.speed), float(cue.azimuth), float(cue.elevation), float(cue.side_offset),
                float(cue.up_offset), float(cue.tip_restitution))
    if not (isinstance(cue, (np.void, np.ndarray)) and cue.dtype == cue_dtype and np.ndim(cue) == 0):
        raise TypeError(f"{function}: cue is {_describe(cue)}, expected a billiards.Cue")
    return tuple(float(cue[name]) for name in cue_dtype.names)


class Shot:
    """A shot on a pool table, played event by event from the cue to rest (no time stepping).

    Parameters
    ----------
    table : PoolTable
    physics : PoolPhysics, optional
        The balls, the cloth and the contacts; the documented defaults where omitted.
    balls : numpy array of ball_dtype, shape (N,)
        The layout: every centre on the cloth at least a radius inside the cushions' noses, no two
        overlapping, every velocity and spin finite (ValueError naming the ball otherwise).
    options : ShotOptions, optional
        The event limit, the pressing tolerance and whether the invariants are checked at every event.

    The engines' vocabulary: ``strike``, ``play``, ``step``, ``run_events``, ``run_until``, ``time``,
    ``energy``, ``balls``, ``events``.
    """

    def __init__(self, table: PoolTable, physics: PoolPhysics | None = None, balls=None,
                 options: ShotOptions | None = None):
        if not isinstance(table, PoolTable):
            raise TypeError(f"Shot: table is {_describe(table)}, expected a billiards.PoolTable")
        physics = PoolPhysics() if physics is None else physics
        if not isinstance(physics, PoolPhysics):
            raise TypeError(f"Shot: physics is {_describe(physics)}, expected a billiards.PoolPhysics")
        options = ShotOptions() if options is None else options
        if not isinstance(options, ShotOptions):
            raise TypeError(f"Shot: options is {_describe(options)}, expected a billiards.ShotOptions")
        layout = check_layout("Shot", balls)
        if layout.ndim != 1:
            raise ValueError(f"Shot: balls has shape {layout.shape}, expected (N,)")
        self._shot = _billiards.Shot(table, physics, layout, options)
        self._count = len(layout)
        self._table, self._physics = table, physics

    @classmethod
    def _played(cls, native, table: PoolTable, physics: PoolPhysics, count: int) -> "Shot":
        """A Shot around the compiled module's shot ``native`` (a game's last shot)."""
        shot = cls.__new__(cls)
        shot._shot, shot._count, shot._table, shot._physics = native, count, table, physics
        return shot

    def strike(self, ball: int, cue: Cue) -> None:
        """Strikes ball ``ball`` (its index) with ``cue`` now; the strike is the shot's next event."""
        if isinstance(ball, bool) or not isinstance(ball, (int, np.integer)):
            raise TypeError(f"strike: ball is {_describe(ball)}, expected a ball's index")
        if not (0 <= ball < self._count):
            raise ValueError(f"strike: ball is {ball}, expected an index from 0 to {self._count - 1}")
        try:
            numbers = cue_numbers("strike", cue)
        except (TypeError, ValueError) as error:  # a field that is no number
            raise TypeError(f"strike: cue is {_describe(cue)}, expected a billiards.Cue ({error})") from None
        self._shot.strike(int(ball), *numbers)

    def play(self) -> int:
        """Plays every event until every ball is at rest or pocketed; returns how many ran."""
        return self._shot.play()

    def step(self):
        """Runs the next event and returns it (a record of event_dtype); None when all is at rest."""
        if not self._shot.step():
            return None
        return _events_from_columns(self._shot.events(self._shot.event_count() - 1))[0]

    def run_events(self, count: int) -> int:
        """Runs at most ``count`` events; returns how many ran."""
        if isinstance(count, bool) or not isinstance(count, (int, np.integer)) or count < 0:
            raise ValueError(f"run_events: count is {count!r}, expected a whole number >= 0")
        return self._shot.run_events(min(int(count), 2**64 - 1))

    def run_until(self, time: float) -> int:
        """Runs every event up to the shot's time ``time`` (s), which becomes its time now; returns how
        many ran. ``time`` must be finite and not before ``self.time``."""
        try:
            return self._shot.run_until(float(time))
        except ValueError as error:
            raise ValueError(str(error).replace("billiards::simulation::Shot::run_until", "run_until")) from None

    @property
    def time(self) -> float:
        """The shot's time now (s)."""
        return self._shot.time()

    @property
    def energy(self) -> float:
        """The kinetic energy of the balls in play now (J), translation and rotation."""
        return self._shot.energy()

    @property
    def event_count(self) -> int:
        """How many events so far, the strike included."""
        return self._shot.event_count()

    @property
    def balls(self) -> np.ndarray:
        """The balls now: an array of ball_dtype."""
        return _from_columns(self._shot.balls())

    @property
    def placed(self) -> np.ndarray:
        """The balls as placed, before any event."""
        return _from_columns(self._shot.placed())

    @property
    def events(self) -> np.ndarray:
        """Every event so far, in order: an array of event_dtype."""
        return _events_from_columns(self._shot.events(0))

    def balls_at(self, t: float) -> np.ndarray:
        """The balls at the shot's time ``t`` ≥ 0 (s), on beyond the last event by their phases."""
        return _from_columns(self._shot.balls_at(float(t)))

    def write_json(self, path) -> None:
        """Writes the events as JSON (docs/events.schema.json), atomically."""
        from ._files import shot_json, write_text
        write_text(path, shot_json(self))

    def write_svg(self, path, title: str = "billiards") -> None:
        """Writes the shot as SVG (each ball's path), atomically."""
        from ._files import shot_svg, write_text
        write_text(path, shot_svg(self, title))

    def write_html(self, path, title: str = "billiards", rate: float = 60.0) -> None:
        """Writes a self-contained page that animates the shot, atomically."""
        from ._files import shot_html, write_text
        write_text(path, shot_html(self, title, rate))

    def write_trajectories(self, path, rate: float = 100.0) -> None:
        """Writes the centres sampled ``rate`` times a second as CSV, atomically."""
        from ._files import trajectories_csv, write_text
        write_text(path, trajectories_csv(self, rate))

    def trajectories(self, rate: float, until: float | None = None):
        """The centres sampled ``rate`` times a second (Hz): at 0, 1/rate, … up to ``until`` (the shot's
        time now by default) and at ``until`` itself, the samples of ``trajectories_csv``. Returns
        (times (T,), positions (T, N, 3))."""
        if not (isinstance(rate, (int, float, np.floating, np.integer)) and 0 < rate < math.inf):
            raise ValueError(f"trajectories: rate is {rate!r}, expected a positive finite number of samples a second")
        end = self.time if until is None else float(until)
        if not (0 <= end < math.inf):
            raise ValueError(f"trajectories: until is {until!r}, expected a finite time >= 0 (s)")
        samples = math.floor(end * rate) + 1
        if samples > 10**8:
            raise ValueError(f"trajectories: {samples} samples asked (rate {rate} Hz over {end} s), expected at "
                             f"most 10**8")
        times = np.arange(samples, dtype=np.float64) / float(rate)
        if times[-1] < end:
            times = np.append(times, end)
        return times, self._shot.positions_at(times)
