"""The file formats of the io library: a shot's events as JSON (docs/events.schema.json), its SVG and
animated HTML page, its trajectories as CSV, shot setup files, and gas snapshots (.sph, extended XYZ).
Every file is written atomically: a reader sees the old file or the new one, never a part."""

from __future__ import annotations

import os
from dataclasses import dataclass

import numpy as np

from . import _billiards
from ._shot import TABLES, PoolPhysics, PoolTable, Shot, _from_columns, check_layout, table_preset
from ._table_gas import Gas


def _path(function: str, path) -> str:
    if not isinstance(path, (str, os.PathLike)):
        raise TypeError(f"{function}: path is {type(path).__name__}, expected a file's path")
    return os.fspath(path)


def write_text(path, text: str) -> None:
    """Writes ``text`` to ``path`` atomically (OSError naming the path and the reason on failure)."""
    path = _path("write_text", path)
    try:
        _billiards.write_file_atomically(path, text)
    except RuntimeError as error:
        raise OSError(str(error)) from None


def table_name(table: PoolTable) -> str:
    """The preset a table is ("9ft", "8ft", "7ft", "snooker", "carom"), or "custom"."""
    for name in ("9ft", "8ft", "7ft", "snooker", "carom"):
        if table_preset(name) == table:
            return name
    return "custom"


def _rate(function: str, rate) -> float:
    if not (isinstance(rate, (int, float, np.integer, np.floating)) and 0 < rate <= 10**4):
        raise ValueError(f"{function}: rate is {rate!r}, expected samples a second in (0, 10000]")
    return float(rate)


def shot_json(shot: Shot) -> str:
    """The shot as JSON: the table, the physics, the balls at the start, every event, the balls at rest."""
    return _billiards.shot_json(shot._shot, table_name(shot._table))


def shot_svg(shot: Shot, title: str = "billiards") -> str:
    """The shot as SVG: the table, each ball's path, where it started and where it is now."""
    return _billiards.shot_svg(shot._shot, str(title))


def shot_html(shot: Shot, title: str = "billiards", rate: float = 60.0) -> str:
    """A self-contained page that animates the shot, sampled ``rate`` times a second."""
    return _billiards.shot_html(shot._shot, str(title), _rate("shot_html", rate))


def trajectories_csv(shot: Shot, rate: float = 100.0) -> str:
    """The centres sampled ``rate`` times a second as CSV."""
    return _billiards.trajectories_csv(shot._shot, _rate("trajectories_csv", rate))


def read_shot_setup(path, physics: PoolPhysics | None = None):
    """A shot setup file (``table 9ft`` and ``ball x y [vx vy [wx wy wz]]`` lines, docs/io.md): returns
    (the table it names or None, the layout as an array of ball_dtype). ValueError names the file, the
    line and what was expected."""
    physics = PoolPhysics() if physics is None else physics
    name, columns = _billiards.read_shot_setup(_path("read_shot_setup", path), physics.radius)
    return (table_preset(name) if name else None), _from_columns(columns)


def write_shot_setup(path, layout, table: str | None = None) -> None:
    """Writes a layout (ball_dtype, none pocketed) as a shot setup file that read_shot_setup reads back
    exactly, with ``table`` ("7ft", "8ft", "9ft", "snooker", "carom") where given."""
    layout = check_layout("write_shot_setup", layout)
    if layout.ndim != 1 or np.any(layout["pocketed"]):
        raise ValueError("write_shot_setup: layout must be one-dimensional with no ball pocketed")
    if table is not None and table not in TABLES:
        raise ValueError(f"write_shot_setup: table is {table!r}, expected one of {TABLES}")
    lines = [f"table {table}"] if table else []
    for ball in layout:
        numbers = [*ball["position"][:2], *ball["velocity"][:2], *ball["angular_velocity"]]
        lines.append("ball " + " ".join(repr(float(x)) for x in numbers))
    write_text(path, "\n".join(lines) + "\n")


@dataclass
class Snapshot:
    """A gas's configuration in a periodic box, as a snapshot file holds it."""

    dimension: int
    box: tuple
    time: float
    species: list
    position: np.ndarray
    velocity: np.ndarray
    radius: np.ndarray
    mass: np.ndarray


def read_snapshot(path) -> Snapshot:
    """Reads a snapshot file: .sph (Smallenburg's format) or .xyz/.extxyz (extended XYZ)."""
    return Snapshot(*_billiards.read_snapshot(_path("read_snapshot", path)))


def write_snapshot(path, snapshot: Snapshot) -> None:
    """Writes a snapshot file atomically, its format by its name (.sph: 3-D only)."""
    n = len(snapshot.species)
    rows = [np.ascontiguousarray(np.asarray(a, dtype=np.float64).reshape(n, 3)) for a in
            (snapshot.position, snapshot.velocity)]
    flat = [np.ascontiguousarray(np.asarray(a, dtype=np.float64).reshape(n)) for a in (snapshot.radius, snapshot.mass)]
    try:
        _billiards.write_snapshot(_path("write_snapshot", path), int(snapshot.dimension),
                                  np.asarray(snapshot.box, dtype=np.float64), float(snapshot.time),
                                  [str(s) for s in snapshot.species], *rows, *flat)
    except RuntimeError as error:
        raise OSError(str(error)) from None


def gas_snapshot(gas: Gas) -> Snapshot:
    """The gas now as a snapshot (species "a"; 2-D vectors padded with z = 0, a box of thickness 1)."""
    d = gas.positions.shape[1]
    pad = lambda a: np.pad(a, ((0, 0), (0, 3 - d)))
    side = gas.side
    return Snapshot(d, (side, side, side if d == 3 else 1.0), gas.time, ["a"] * len(gas.positions),
                    pad(gas.positions), pad(gas.velocities), gas.radii, gas.masses)


def gas_from_snapshot(snapshot: Snapshot) -> Gas:
    """A gas from a snapshot of a cubic (square) box."""
    d = snapshot.dimension
    side = snapshot.box[0]
    if any(snapshot.box[k] != side for k in range(d)):
        raise ValueError(f"gas_from_snapshot: the box is {snapshot.box}, expected equal sides")
    return Gas(snapshot.position[:, :d], snapshot.velocity[:, :d], side, radii=snapshot.radius,
               masses=snapshot.mass)
