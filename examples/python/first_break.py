import numpy as np
import billiards

table = billiards.pool_table("9ft")
shot = billiards.Shot(table, billiards.PoolPhysics(), billiards.rack(table, kind="9ball", jitter=1e-3, seed=1))
shot.strike(0, billiards.Cue(speed=8.0))  # m/s, the cue along +x
print(f"{shot.play()} events, at rest after {shot.time:.2f} s")
cues = billiards.cues(speed=np.random.default_rng(0).uniform(2, 8, 1000))
results = billiards.play_shots(table, None, shot.placed, cues)  # 1000 breaks on every core
print(f"object balls pocketed per break: {results.pocketed[:, 1:].sum(axis=1).mean():.2f}")
