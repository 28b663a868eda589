#!/usr/bin/env python3
"""The Python package's figures, for bench/run.sh (which runs it in the same run as billiards_bench and the
peers, pinned to the same core) and bench/report.py: printed as JSON.

- breaks from Python: the 9- and 8-ball breaks of billiards_bench's shot/break (the 7-ft table, the 64
  racks of 1e-3 R jitter, the cue at 8 m/s with b = 0.25 R), each a Shot, strike and play called from
  Python; µs per break, the median of --repetitions;
- random shots with play_shots: shot/random's kind (1–16 balls scattered on a 7-, 8- or 9-ft table, a cue
  of 0.1–12 m/s in any direction, elevation up to 0.3 rad, tip offsets within 0.7 R), drawn here from a
  seeded numpy generator, batched by table and ball count, on one thread and on every core;
- the Dask batch: the same breaks on a local cluster of one worker process a core, against the local
  batch on every core;
- the games: games.GameEnv's step for each game (a seeded random player: pool with any cue, snooker and
  three-cushion aiming at a ball it may meet first), against the same shots replayed from Python (Shot,
  strike, play from the layout each step struck), and the rules' decision alone on those shots.

  bench_python.py --build BUILD_DIR --part one-core|every-core [--shots 100000] [--repetitions 5]
                  [--dask-shots 20000]
"""
import argparse
import json
import os
import statistics
import sys
import time


def breaks(billiards, kind, repetitions, count=640):
    table = billiards.pool_table("7ft")
    physics = billiards.PoolPhysics()
    options = billiards.ShotOptions()
    racks = [billiards.rack(table, physics, kind, 1e-3, seed) for seed in range(64)]
    cue = billiards.Cue(8.0, up_offset=0.25)
    times, events = [], 0
    for _ in range(repetitions):
        begun = time.perf_counter()
        events = 0
        for k in range(count):
            shot = billiards.Shot(table, physics, racks[k % 64], options)
            shot.strike(0, cue)
            events += shot.play() + 1
        times.append((time.perf_counter() - begun) / count)
    return {"us_per_break": 1e6 * statistics.median(times), "events_per_break": events / count}


def random_batches(billiards, np, shots):
    """shot/random's kind of shots, grouped by table and ball count: [(table, layouts, cues)]."""
    rng = np.random.default_rng(2026)
    physics = billiards.PoolPhysics()
    tables = {name: billiards.pool_table(name) for name in ("7ft", "8ft", "9ft")}
    groups = {}
    for seed in range(shots):
        name = ("7ft", "8ft", "9ft")[seed % 3]
        count = 1 + int(rng.uniform() * 16) % 16
        r, angle = 0.7 * np.sqrt(rng.uniform()), 2 * np.pi * rng.uniform()
        cue = (0.1 + 11.9 * rng.uniform(), 2 * np.pi * rng.uniform(), 0.3 * rng.uniform(), r * np.cos(angle),
               r * np.sin(angle))
        layouts, cues = groups.setdefault((name, count), ([], []))
        layouts.append(billiards.scatter(tables[name], physics, count, seed))
        cues.append(cue)
    out = []
    for (name, count), (layouts, cues) in groups.items():
        c = np.array(cues)
        out.append((tables[name], np.stack(layouts),
                    billiards.cues(speed=c[:, 0], azimuth=c[:, 1], elevation=c[:, 2], side_offset=c[:, 3],
                                   up_offset=c[:, 4])))
    return out


def play_random(billiards, batches, threads, repetitions):
    rates, events = [], 0
    shots = sum(len(layouts) for _, layouts, _ in batches)
    for _ in range(repetitions):
        begun = time.perf_counter()
        events = 0
        for table, layouts, cues in batches:
            events += int(billiards.play_shots(table, None, layouts, cues, threads=threads).event_count.sum())
        rates.append(shots / (time.perf_counter() - begun))
    return {"shots_per_second": statistics.median(rates), "events_per_shot": events / shots, "threads": threads,
            "shots": shots}


def dask_batch(billiards, np, shots):
    try:
        import distributed
    except ImportError:
        return None
    import billiards.distributed as bd
    table = billiards.pool_table("7ft")
    physics = billiards.PoolPhysics()
    racks = np.stack([billiards.rack(table, physics, "9ball", 1e-3, seed % 64) for seed in range(shots)])
    cues = billiards.cues(speed=np.linspace(2, 8, shots), up_offset=0.25)
    cores = billiards.available_cores()
    begun = time.perf_counter()
    billiards.play_shots(table, physics, racks, cues, threads=cores)
    local = shots / (time.perf_counter() - begun)
    chunk = max(1, shots // (8 * cores))
    with distributed.LocalCluster(n_workers=cores, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, distributed.Client(cluster) as client:
        bd.play_shots(client, table, physics, racks[:cores], cues[:cores], chunk_size=1)  # warm the workers
        begun = time.perf_counter()
        bd.play_shots(client, table, physics, racks, cues, chunk_size=chunk, threads=1)
        remote = shots / (time.perf_counter() - begun)
    tasks = -(-shots // chunk)
    return {"shots": shots, "workers": cores, "chunk_size": chunk, "tasks": tasks, "local_shots_per_second": local,
            "dask_shots_per_second": remote,
            "overhead_ms_per_task": 1e3 * max(0.0, (shots / remote - shots / local)) * cores / tasks}


def game_steps(billiards, np, game, steps, repetitions):
    """µs per GameEnv.step, per the same shot replayed from Python, and per rules' decision alone."""
    import billiards.games as games
    decide = {"9ball": games.nine_ball, "8ball": games.eight_ball, "snooker": games.snooker,
              "3cushion": games.three_cushion}[game]
    env_times, shot_times, rule_times = [], [], []
    for _ in range(repetitions):
        env = games.GameEnv(game, max_shots=10**9)
        rng = np.random.default_rng(2026)
        observation, _ = env.reset(seed=0)
        played, spent = [], 0.0
        for k in range(steps):
            action = env.sample_action(rng, aim=game in ("snooker", "3cushion"))
            state = env.state
            begun = time.perf_counter()
            observation, reward, terminated, truncated, info = env.step(action)
            spent += time.perf_counter() - begun
            cue = billiards.Cue(speed=action[0], azimuth=action[1], side_offset=action[2], up_offset=action[3])
            shot = env.last_shot()
            played.append((shot.placed, info["shooter"] if game == "3cushion" else 0, cue, state, shot))
            if terminated or truncated:
                observation, _ = env.reset(seed=k + 1)
        env_times.append(spent / steps)
        begun = time.perf_counter()
        for layout, striker, cue, _, _ in played:
            shot = billiards.Shot(env.table, env.physics, layout)
            shot.strike(striker, cue)
            shot.play()
        shot_times.append((time.perf_counter() - begun) / steps)
        begun = time.perf_counter()
        for _, _, _, state, shot in played:
            decide(state, shot)
        rule_times.append((time.perf_counter() - begun) / steps)
    return {"steps": steps, "us_per_step": 1e6 * statistics.median(env_times),
            "us_per_shot": 1e6 * statistics.median(shot_times), "us_per_decision": 1e6 * statistics.median(rule_times)}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--build", required=True, help="the build folder whose python/ holds the package")
    parser.add_argument("--shots", type=int, default=100000)
    parser.add_argument("--repetitions", type=int, default=5)
    parser.add_argument("--dask-shots", type=int, default=20000)
    parser.add_argument("--part", choices=("one-core", "every-core"), required=True,
                        help="one-core: the breaks and play_shots on one thread (run it pinned); every-core: "
                             "play_shots on every core and the Dask batch (unpinned)")
    args = parser.parse_args()
    sys.path.insert(0, os.path.join(args.build, "python"))
    import numpy as np

    import billiards
    result = {"python": sys.version.split()[0], "numpy": np.__version__, "billiards": billiards.__version__}
    batches = random_batches(billiards, np, args.shots)
    if args.part == "one-core":
        for kind in ("9ball", "8ball"):
            result[f"break_{kind}"] = breaks(billiards, kind, args.repetitions)
        result["random_one_thread"] = play_random(billiards, batches, 1, max(1, args.repetitions // 2))
        for game in ("9ball", "8ball", "snooker", "3cushion"):
            result[f"game_{game}"] = game_steps(billiards, np, game, 2000, max(1, args.repetitions // 2))
    else:
        result["random_every_core"] = play_random(billiards, batches, billiards.available_cores(),
                                                  max(1, args.repetitions // 2))
        result["dask"] = dask_batch(billiards, np, args.dask_shots)
    json.dump(result, sys.stdout, indent=1)
    print()


if __name__ == "__main__":
    main()
