"""The event-driven table and the hard-sphere gas, in the engines' vocabulary.

Both take their balls as arrays and report their events as structured arrays (``table_event_dtype``,
``gas_event_dtype``) where asked: ``run_events(count, events=True)`` and ``run_until(time,
events=True)`` return ``(count, events)``; without ``events`` they return the count.
"""

from __future__ import annotations

import math

import numpy as np

from . import _billiards
from ._shot import _describe

#: An event of the table: its time (s), what the ball met ("ball" or "cushion"), the ball, the other
#: ball or the cushion (0 left, 1 right, 2 bottom, 3 top), and whether velocities changed.
table_event_dtype = np.dtype([("time", "<f8"), ("kind", "U7"), ("first", "<i8"), ("second", "<i8"),
                              ("resolved", "?")])
#: An event of the gas: two balls meeting at a time.
gas_event_dtype = np.dtype([("time", "<f8"), ("kind", "U4"), ("first", "<i8"), ("second", "<i8")])


def _rows(function: str, name: str, value, dimension: int, count: int | None = None) -> np.ndarray:
    if isinstance(value, np.ndarray) and value.dtype != np.float64:
        raise TypeError(f"{function}: {name} has dtype {value.dtype}, expected float64")
    array = np.ascontiguousarray(value, dtype=np.float64)
    if array.ndim != 2 or array.shape[1] != dimension or (count is not None and array.shape[0] != count):
        rows = "N" if count is None else str(count)
        raise ValueError(f"{function}: {name} has shape {array.shape}, expected ({rows}, {dimension})")
    return array


def _count(function: str, count) -> int:
    if isinstance(count, bool) or not isinstance(count, (int, np.integer)) or count < 0:
        raise ValueError(f"{function}: count is {count!r}, expected a whole number >= 0")
    return min(int(count), 2**64 - 1)


def _until(function: str, until) -> float:
    try:
        until = float(until)
    except (TypeError, ValueError):
        raise TypeError(f"{function}: until is {_describe(until)}, expected a time (s)") from None
    if not math.isfinite(until):
        raise ValueError(f"{function}: until is {until}, expected a finite time")
    return until


def _events(columns, dtype, kinds) -> np.ndarray:
    time, kind, first, second, resolved = columns
    out = np.empty(len(time), dtype)
    out["time"], out["first"], out["second"] = time, first, second
    out["kind"] = np.asarray(kinds)[kind]
    if "resolved" in dtype.names:
        out["resolved"] = resolved.astype(bool)
    return out


class _Engine:
    _dtype: np.dtype
    _kinds: tuple

    def _run(self, function: str, count: int, until: float, events: bool):
        try:
            done, columns = self._engine.run(count, until, bool(events))
        except ValueError as error:
            raise ValueError(f"{function}: {error}") from None
        return (done, _events(columns, self._dtype, self._kinds)) if events else done

    def run_events(self, count: int, events: bool = False):
        """Runs at most ``count`` events; returns how many ran (and their events, with ``events``)."""
        return self._run("run_events", _count("run_events", count), math.inf, events)

    def run_until(self, until: float, events: bool = False):
        """Runs every event up to the time ``until``, which becomes the time now; returns how many ran
        (and their events, with ``events``)."""
        return self._run("run_until", 2**64 - 1, _until("run_until", until), events)

    def step(self):
        """Runs the next event and returns it (a record); None where no event is left."""
        done, events = self.run_events(1, events=True)
        return events[0] if done else None

    @property
    def time(self) -> float:
        """The time now (s)."""
        return self._engine.time()

    @property
    def energy(self) -> float:
        """The kinetic energy Σ ½ m v² (J)."""
        return self._engine.energy()


class Table(_Engine):
    """An event-driven billiards table: N equal balls on a rectangle with cushions, no friction, from
    contact to contact (no time stepping).

    Parameters
    ----------
    position, velocity : array_like, shape (N, 2)
        The centres (m; on the table, at least a radius inside) and velocities (m/s).
    width, height : float
        The table's sides (m): its cushions are x = 0, x = width, y = 0, y = height.
    radius, mass : float
        Every ball's radius (m) and mass (kg).
    check_every_pair : bool
        After each event check every pair for overlap (O(N²)), not only the event's balls.
    """

    _dtype, _kinds = table_event_dtype, ("ball", "cushion")

    def __init__(self, position, velocity=None, width: float = 2.54, height: float = 1.27, radius: float = 0.028575,
                 mass: float = 0.17, check_every_pair: bool = True):
        position = _rows("Table", "position", position, 2)
        velocity = np.zeros_like(position) if velocity is None else _rows("Table", "velocity", velocity, 2,
                                                                           len(position))
        self._engine = _billiards.Table(position, velocity, float(width), float(height), float(radius), float(mass),
                                        bool(check_every_pair))

    @property
    def event_count(self) -> int:
        """Events so far."""
        return self._engine.event_count()

    @property
    def balls(self):
        """(positions (N, 2), velocities (N, 2)) now."""
        return self._engine.balls()


class Gas(_Engine):
    """A hard-sphere gas (disks in 2-D, spheres in 3-D) in a periodic box, event by event.

    Parameters
    ----------
    position, velocity : array_like, shape (N, 2) or (N, 3)
        The centres (anywhere: taken into the box) and velocities, in any consistent units.
    side : float
        The box's side.
    radius, mass : float
        Every ball's radius and mass, where ``radii`` and ``masses`` are not given.
    radii, masses : array_like, shape (N,), optional
        Each ball's own.
    max_events_without_collision : int
        The engine's own events (cell crossings, list rebuilds) allowed in a row without a collision
        before EventLimitReached (0: the engine's default).
    """

    _dtype, _kinds = gas_event_dtype, ("ball",)

    def __init__(self, position, velocity, side: float, radius: float = 0.5, mass: float = 1.0, radii=None,
                 masses=None, max_events_without_collision: int = 0):
        position = np.asarray(position)
        if position.ndim != 2 or position.shape[1] not in (2, 3):
            raise ValueError(f"Gas: position has shape {position.shape}, expected (N, 2) or (N, 3)")
        dimension = position.shape[1]
        position = _rows("Gas", "position", position, dimension)
        velocity = _rows("Gas", "velocity", velocity, dimension, len(position))
        engine = _billiards.Gas2 if dimension == 2 else _billiards.Gas3
        self._engine = engine(position, velocity, float(side), float(radius), float(mass),
                              [] if radii is None else np.asarray(radii, dtype=np.float64),
                              [] if masses is None else np.asarray(masses, dtype=np.float64),
                              int(max_events_without_collision))

    @classmethod
    def lattice(cls, dimension: int = 3, balls: int = 1000, packing_fraction: float = 0.3, seed: int = 1) -> "Gas":
        """``balls`` balls of diameter 1 and mass 1 on a square (2-D) or FCC (3-D) lattice filling the box
        at ``packing_fraction``, with Gaussian velocities of zero total momentum at kT = 1."""
        if dimension not in (2, 3):
            raise ValueError(f"Gas.lattice: dimension is {dimension!r}, expected 2 or 3")
        gas = cls.__new__(cls)
        engine = _billiards.Gas2 if dimension == 2 else _billiards.Gas3
        gas._engine = engine.lattice(int(balls), float(packing_fraction), int(seed))
        return gas

    @property
    def collisions(self) -> int:
        """Collisions since the start."""
        return self._engine.collisions()

    @property
    def temperature(self) -> float:
        """kT = Σ m v²/(d N)."""
        return self._engine.temperature()

    @property
    def side(self) -> float:
        return self._engine.side()

    @property
    def positions(self) -> np.ndarray:
        """The centres now, in the box."""
        return self._engine.positions()

    @property
    def unwrapped_positions(self) -> np.ndarray:
        """The centres now, followed across the periodic boundaries since the start."""
        return self._engine.unwrapped_positions()

    @property
    def velocities(self) -> np.ndarray:
        return self._engine.velocities()

    @property
    def radii(self) -> np.ndarray:
        return np.asarray(self._engine.radii())

    @property
    def masses(self) -> np.ndarray:
        return np.asarray(self._engine.masses())

    def reset_measurements(self) -> None:
        """Starts a new span of measurement now."""
        self._engine.reset_measurements()

    def measured(self) -> dict:
        """What was measured since the start or the last reset: time, collisions, virial, temperature
        (kT at the span's start), compressibility_factor (Z = PV/NkT from the collision virial),
        compressibility_factor_from_collision_rate, mean_free_time."""
        return self._engine.measured()
