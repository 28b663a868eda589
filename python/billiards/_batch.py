"""Many shots at once, on every core: play_shots."""

from __future__ import annotations

import os
from dataclasses import dataclass, field

import numpy as np

from . import _billiards
from ._shot import (Cue, PoolPhysics, PoolTable, ShotOptions, ball_dtype, check_layout, cue_dtype, _describe,
                    _events_from_columns)


@dataclass
class ShotResults:
    """What ``play_shots`` returns, one row a shot (S shots of N balls).

    Attributes
    ----------
    balls : array of ball_dtype, shape (S, N)
        Each shot's balls at rest (or pocketed) at its end.
    time : float64 array, shape (S,)
        Each shot's last event's time (s).
    event_count : uint64 array, shape (S,)
        Each shot's events, the strike included.
    events : list of S arrays of event_dtype, or None
        Each shot's events, where asked for (``events=True``).
    """

    balls: np.ndarray
    time: np.ndarray
    event_count: np.ndarray
    events: list | None = field(default=None)

    @property
    def position(self) -> np.ndarray:
        """The final centres (m), shape (S, N, 3)."""
        return self.balls["position"]

    @property
    def pocketed(self) -> np.ndarray:
        """Which balls each shot pocketed (or found pocketed), bool (S, N)."""
        return self.balls["pocketed"]


def available_cores() -> int:
    """The cores this process may run on."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # not on Linux
        return os.cpu_count() or 1


def _cue_array(cues) -> np.ndarray:
    if isinstance(cues, Cue):
        return cues.as_array().reshape(())
    if isinstance(cues, (list, tuple)) and all(isinstance(c, Cue) for c in cues):
        return np.concatenate([c.as_array() for c in cues]) if cues else np.empty(0, cue_dtype)
    if isinstance(cues, (np.ndarray, np.void)) and cues.dtype == cue_dtype:
        return np.asarray(cues)
    raise TypeError(f"play_shots: cues is {_describe(cues)}, expected a billiards.Cue, a list of them or an array "
                    f"of billiards.cue_dtype (billiards.cues(...))")


def broadcast_batch(function: str, layouts, cues, struck):
    """A batch's layouts, cues and struck balls checked and broadcast to one count S of shots: returns
    (S, layouts (S, N), cues (S,) of cue_dtype, struck (S,) int64), each C-contiguous."""
    layouts = check_layout(function, layouts)
    if layouts.ndim not in (1, 2):
        raise ValueError(f"{function}: layouts has shape {layouts.shape}, expected (S, N) or (N,)")
    cue = _cue_array(cues)
    if cue.ndim > 1:
        raise ValueError(f"{function}: cues has shape {cue.shape}, expected (S,) or one cue")
    struck = np.asarray(struck)
    if struck.dtype.kind not in "iu" or struck.ndim > 1:
        raise TypeError(f"{function}: struck is {_describe(struck)}, expected a ball's index or one a shot")
    shots_of = {"layouts": layouts.shape[0] if layouts.ndim == 2 else None,
                "cues": cue.shape[0] if cue.ndim == 1 else None,
                "struck": struck.shape[0] if struck.ndim == 1 else None}
    counts = {k: v for k, v in shots_of.items() if v is not None}
    if len(set(counts.values())) > 1:
        raise ValueError(f"{function}: the shots' counts differ ({counts}); expected one count S for all")
    shots = next(iter(counts.values()), 1)
    return (shots, np.ascontiguousarray(np.broadcast_to(layouts, (shots, layouts.shape[-1]))),
            np.ascontiguousarray(np.broadcast_to(cue, (shots,))),
            np.ascontiguousarray(np.broadcast_to(struck, (shots,)), dtype=np.int64))


def play_shots(table: PoolTable, physics: PoolPhysics | None, layouts, cues, *, struck=0,
               options: ShotOptions | None = None, threads: int | None = None, events: bool = False) -> ShotResults:
    """Plays a batch of shots, each its own layout and cue, on ``threads`` threads (every core this
    process may use by default) with the GIL released.

    Each shot is played exactly as ``Shot(table, physics, layout, options)``, ``strike(struck, cue)``,
    ``play()`` plays it: the same inputs give the same bits, whatever the number of threads.

    Parameters
    ----------
    table, physics, options :
        As for Shot (the same for every shot).
    layouts : array of ball_dtype, shape (S, N) or (N,)
        The shots' layouts (one layout: the same for every shot).
    cues : Cue, list of Cue, or array of cue_dtype, shape (S,) or ()
        The shots' cues (one cue: the same for every shot).
    struck : int or int array of shape (S,)
        The ball each shot strikes (its index); the cue ball, 0, by default.
    threads : int, optional
        How many threads play the batch, at least 1.
    events : bool
        Keep each shot's events (``ShotResults.events``).

    Raises
    ------
    ValueError naming the first shot whose input is out of its domain; EventLimitReached naming the
    first shot that reached the event limit.
    """
    function = "play_shots"
    if not isinstance(table, PoolTable):
        raise TypeError(f"{function}: table is {_describe(table)}, expected a billiards.PoolTable")
    physics = PoolPhysics() if physics is None else physics
    options = ShotOptions() if options is None else options
    if not isinstance(physics, PoolPhysics) or not isinstance(options, ShotOptions):
        raise TypeError(f"{function}: physics and options must be a billiards.PoolPhysics and a billiards.ShotOptions")
    shots, layouts, cue_rows, struck = broadcast_batch(function, layouts, cues, struck)
    balls = layouts.shape[-1]
    cue_numbers = np.ascontiguousarray(np.stack([cue_rows[name].astype(np.float64) for name in cue_dtype.names],
                                                axis=-1).reshape(shots, 7))
    if np.any(struck >= balls):
        bad = int(np.argmax(struck >= balls))
        raise ValueError(f"{function}: struck[{bad}] is {struck[bad]}, expected a ball's index below {balls}")
    threads = available_cores() if threads is None else threads
    if isinstance(threads, bool) or not isinstance(threads, (int, np.integer)) or threads < 1:
        raise ValueError(f"{function}: threads is {threads!r}, expected a whole number >= 1")
    out = _billiards.play_shots(table, physics, options,
                                np.ascontiguousarray(layouts["position"]).reshape(-1, 3),
                                np.ascontiguousarray(layouts["velocity"]).reshape(-1, 3),
                                np.ascontiguousarray(layouts["angular_velocity"]).reshape(-1, 3),
                                np.ascontiguousarray(layouts["pocketed"]), cue_numbers, struck, int(threads),
                                bool(events))
    final = np.empty((shots, balls), ball_dtype)
    for name in ("position", "velocity", "angular_velocity", "pocketed"):
        final[name] = out[name]
    kept = [_events_from_columns(e) for e in out["events"]] if events else None
    return ShotResults(final, out["time"], out["event_count"], kept)
