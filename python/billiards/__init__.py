"""billiards: billiard-ball physics derived and checked with a computer algebra system, and event-driven
engines on it, from Python.

- The runtime's calls on numpy arrays (``collide``, ``collide_with_friction``, ``strike``,
  ``collide_with_cushion``, ``earliest_contact``, ``time_of_impact``): one case or a batch, broadcast,
  in float64 or float32, each case the C++ call's result bit for bit.
- The shot engine: ``pool_table``, ``table_preset`` (pool, snooker and carom tables), ``physics_preset``,
  ``PoolPhysics``, ``rack`` (the pool racks, the snooker set-up, the three-cushion opening position),
  ``scatter``, ``balls``, ``Cue``, ``Shot``;
  layouts and events as numpy structured arrays (``ball_dtype``, ``event_dtype``).
- ``play_shots``: a batch of shots on every core; ``billiards.distributed``: the same on a Dask cluster.
- ``Table`` and ``Gas``: the event-driven table and the hard-sphere gas, in the same vocabulary.
- The file formats: events JSON, SVG, the animated page, CSV, shot setup files, gas snapshots.

Units: metres, seconds, kilograms, radians.
"""

from ._billiards import __version__
from ._batch import ShotResults, available_cores, play_shots
from ._runtime import (collide, collide_with_cushion, collide_with_friction, earliest_contact, evolve, motion, strike,
                       time_of_impact, transition_time)
from ._files import (Snapshot, gas_from_snapshot, gas_snapshot, read_shot_setup, read_snapshot, shot_html,
                     shot_json, shot_svg, trajectories_csv, write_shot_setup, write_snapshot, write_text)
from ._table_gas import Gas, Table, gas_event_dtype, table_event_dtype
from ._shot import (EVENT_KINDS, MOTIONS, BrokenInvariant, Cloth, Cue, EventLimitReached, PoolPhysics, PoolTable,
                    TABLES, Shot, ShotOptions, ball_dtype, balls, carom_table, cue_dtype, cues, event_dtype,
                    physics_preset, pool_table, rack, scatter, snooker_table, table_preset)

__all__ = [
    "__version__", "collide", "collide_with_friction", "strike", "collide_with_cushion", "earliest_contact",
    "time_of_impact", "evolve", "transition_time", "motion", "Cloth", "PoolPhysics", "PoolTable", "ShotOptions", "pool_table", "table_preset",
    "physics_preset", "snooker_table", "carom_table", "TABLES", "rack", "scatter", "balls",
    "Cue", "cues", "Shot", "ShotResults", "play_shots", "available_cores", "ball_dtype", "event_dtype", "cue_dtype",
    "EVENT_KINDS", "MOTIONS", "EventLimitReached", "BrokenInvariant", "Table", "Gas", "table_event_dtype",
    "gas_event_dtype", "Snapshot", "read_snapshot", "write_snapshot", "gas_snapshot", "gas_from_snapshot",
    "read_shot_setup", "write_shot_setup", "shot_json", "shot_svg", "shot_html", "trajectories_csv", "write_text",
]
