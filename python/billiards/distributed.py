"""A batch of shots across machines, on a Dask cluster (Dask's ``distributed``).

``play_shots(client, ...)`` splits the batch into chunks of consecutive shots, plays each chunk on a
worker with ``billiards.play_shots`` (every core the worker may use) and gathers the chunks in order:
the results equal the local batch's bit for bit. The workers need the billiards package importable.
"""

from __future__ import annotations

import numpy as np

from ._batch import ShotResults, broadcast_batch
from ._batch import play_shots as _play_locally
from ._shot import PoolPhysics, PoolTable, ShotOptions


def _play_chunk(table, physics, options, layouts, cues, struck, threads, events):
    return _play_locally(table, physics, layouts, cues, struck=struck, options=options, threads=threads,
                         events=events)


def play_shots(client, table: PoolTable, physics: PoolPhysics | None, layouts, cues, *, struck=0,
               options: ShotOptions | None = None, chunk_size: int = 1000, threads: int | None = None,
               events: bool = False) -> ShotResults:
    """``billiards.play_shots`` on the workers of ``client`` (a ``distributed.Client``).

    Parameters are play_shots's, and:

    chunk_size : int
        The most shots a task plays (≥ 1); a batch of S shots becomes ceil(S / chunk_size) tasks.
    threads : int, optional
        The threads each task plays on (every core of its worker by default).
    """
    function = "distributed.play_shots"
    if isinstance(chunk_size, bool) or not isinstance(chunk_size, (int, np.integer)) or chunk_size < 1:
        raise ValueError(f"{function}: chunk_size is {chunk_size!r}, expected a whole number >= 1")
    physics = PoolPhysics() if physics is None else physics
    options = ShotOptions() if options is None else options
    shots, layouts, cue, struck = broadcast_batch(function, layouts, cues, struck)
    futures = []
    for begin in range(0, shots, int(chunk_size)):
        end = min(begin + int(chunk_size), shots)
        futures.append(client.submit(_play_chunk, table, physics, options, layouts[begin:end],
                                     cue[begin:end], struck[begin:end],
                                     threads, events, pure=False))
    parts = client.gather(futures)
    if not parts:
        return _play_locally(table, physics, layouts, cue, struck=struck, options=options, threads=1, events=events)
    return ShotResults(np.concatenate([p.balls for p in parts]), np.concatenate([p.time for p in parts]),
                       np.concatenate([p.event_count for p in parts]),
                       [e for p in parts for e in p.events] if events else None)
