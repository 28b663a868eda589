#!/usr/bin/env python3
"""Turns the JSON of one billiards_bench run into bench/RESULTS.md and bench/throughput.svg.

Usage: bench/report.py RESULTS_JSON [--command "how the JSON was made"] [--derive BIN] [--out-dir DIR]
                       [--pooltool POOLTOOL_JSON] [--fastfiz FASTFIZ_JSON [--breaks BREAKS_JSON]]...
                       [--edmd EDMD_TEXT]
                       [--python PYTHON_JSON]

POOLTOOL_JSON is what ../shared/peers/pooltool/bench_breaks.py printed in the same run (bench/run.sh runs
both): pooltool's breaks beside ours. FASTFIZ_JSON is what ../shared/peers/fastfiz's bench_break printed
in the same run: FastFiz's breaks beside ours. --fastfiz may be given once a round, each with --breaks
BREAKS_JSON, the billiards_bench run of our breaks just before it (rounds alternating on one core): the
ratio is then the median of the rounds'. EDMD_TEXT is what ../shared/peers/edmd/run.py printed in the same
run: the gas against Smallenburg's SingleEvent code.

Both files are written atomically (tools/atomic_write.py), into bench/ unless --out-dir names another
folder.

Every figure is a ratio of two benchmarks measured in the same run (the machines are shared and
noisy); absolute times are shown only beside them. With --benchmark_repetitions each figure is the
median of the repetitions.
"""
import argparse
import re
import json
import math
import os
import statistics
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, os.pardir, "tools"))
from atomic_write import write_atomically  # noqa: E402


def fail(argument, value, expected):
    """Exits with status 2 and one line naming the argument, its value and what was expected."""
    print(f"report.py: {argument} {value!r}: expected {expected}", file=sys.stderr)
    sys.exit(2)


TIME_UNITS = {"ns": 1, "us": 1e3, "ms": 1e6, "s": 1e9}


def load(path, argument="RESULTS_JSON"):
    expected = "the JSON of a billiards_bench run (--benchmark_format=json)"
    try:
        with open(path, encoding="utf-8") as f:
            data = json.load(f)
    except OSError as error:
        fail(argument, path, f"a readable file ({error.strerror})")
    except (UnicodeDecodeError, ValueError) as error:
        fail(argument, path, f"{expected}; not JSON ({error})")
    if not isinstance(data, dict) or not isinstance(data.get("context"), dict) or \
            not isinstance(data.get("benchmarks"), list):
        fail(argument, path, f"{expected}: an object with \"context\" and a \"benchmarks\" list")
    for b in data["benchmarks"]:
        if not isinstance(b, dict) or not isinstance(b.get("name"), str) or \
                not isinstance(b.get("real_time"), (int, float)) or b.get("time_unit") not in TIME_UNITS:
            fail(argument, path, f"{expected}: each benchmark with a name, a real_time and a time_unit "
                 f"({', '.join(TIME_UNITS)}); found {str(b)[:80]}")
    # One figure per benchmark: the median of its repetitions where the run repeated them
    # (--benchmark_repetitions), else its one measurement.
    # Every benchmark runs in real time (UseRealTime): Google Benchmark names it ".../real_time".
    def key(name):
        return name[: -len("/real_time")] if name.endswith("/real_time") else name

    runs, medians = {}, {}
    for b in data["benchmarks"]:
        if b.get("run_type", "iteration") == "iteration":
            runs.setdefault(key(b.get("run_name", b["name"])), b)
        elif b.get("aggregate_name") == "median":
            medians[key(b["run_name"])] = b
    runs.update(medians)
    return data["context"], runs


def per_item_ns(b):
    return b["real_time"] * TIME_UNITS[b["time_unit"]]


def single_call_table(runs):
    lines = ["| variant | double (ns) | against the paper's formula | float (ns) | against the paper's formula |",
             "|---|---:|---:|---:|---:|"]
    names = [("generated", "generated `collide` (the plain form in its mass range, else the mass-ratio form)"),
             ("paper_formula", "the paper's formula by hand, 2 m2/(m1 + m2)"),
             ("engine_formula", "an engine's form by hand, stored inverse masses: J = 2 s/(w1 + w2)"),
             ("eigen_expression", "a plain Eigen expression of the paper's formula"),
             ("ratio_formula", "the generated form typed by hand"),
             ("ratio_formula_without_select", "the ratio form by hand, without the small-mass select"),
             ("raw_derivation", "the raw derivation (quadratic formula with √D), emitted by derive")]
    for key, label in names:
        row = [label]
        for scalar in ("double", "float"):
            b = runs.get(f"collide/{key}/{scalar}")
            reference = runs.get(f"collide/paper_formula/{scalar}")
            if b is None or reference is None:
                row += ["–", "–"]
                continue
            row += [f"{per_item_ns(b):.2f}", f"{per_item_ns(b) / per_item_ns(reference):.2f}×"]
        lines.append("| " + " | ".join(row) + " |")
    return "\n".join(lines)


def ratio(runs, a, b):
    if a not in runs or b not in runs:
        return "–"
    return f"{per_item_ns(runs[a]) / per_item_ns(runs[b]):.2f}×"


def other_calls_table(runs):
    lines = ["| call | plain form by hand | double: generated / plain (ns) | ratio | float: generated / plain (ns) | "
             "ratio | goal |", "|---|---|---:|---:|---:|---:|---:|"]
    calls = [("restitution", "`collide(m1, v1, m2, v2, n, e)`", "(1 + e) m2/(m1 + m2)", "≤ 1.2×"),
             ("direction", "`collide_along_direction(..., d, e)`", "s = (v2 − v1)·d/(d·d), then as above", "≤ 1.2×"),
             ("friction", "`collide_with_friction`", "J_n, k = (7/2)(1/m1 + 1/m2), j = min(μ J_n, |u_t|/k), J/m",
              "measured"),
             ("evolve", "`evolve` (half a slide on the cloth)", "v0 − μ_s g t û, ω and p by the sliding closed form",
              "measured"),
             ("time_of_impact", "`time_of_impact(p1, v1, p2, v2, r)`",
              "a = w·w, b = p·w, c = p·p − r², (−b − √(b² − a c))/a", "measured")]
    for key, call, plain, goal in calls:
        row = [call, plain]
        for scalar in ("double", "float"):
            g, h = runs.get(f"collide/{key}/{scalar}"), runs.get(f"collide/{key}_formula/{scalar}")
            if g is None or h is None:
                row += ["–", "–"]
                continue
            row += [f"{per_item_ns(g):.2f} / {per_item_ns(h):.2f}", f"{per_item_ns(g) / per_item_ns(h):.2f}×"]
        lines.append("| " + " | ".join(row + [goal]) + " |")
    return "\n".join(lines)


def promise_steps(runs):
    """Per call, the library's call with its promises taken away (Dropped in bench_collide.cpp),
    beside the plain form by hand: each form's time and, in brackets, its ratio to the plain form."""
    steps = {"restitution": ["restitution", None, "restitution_without_promises", "restitution_formula"],
             "direction": ["direction", "direction_unscaled", "direction_without_promises", "direction_formula"]}
    lines = ["| call | type | the library's call | d unscaled | no promise kept | the plain form by hand |",
             "|---|---|---:|---:|---:|---:|"]
    found = False
    for call, names in steps.items():
        for scalar in ("double", "float"):
            row = [runs.get(f"collide/{name}/{scalar}") if name else None for name in names]
            plain = row[-1]
            if plain is None or row[0] is None:
                continue
            found = True
            cells = [f"`{call}`", scalar]
            for b in row[:-1]:
                cells.append("–" if b is None else f"{per_item_ns(b):.2f} ({per_item_ns(b) / per_item_ns(plain):.2f}×)")
            cells.append(f"{per_item_ns(plain):.2f}")
            lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines) if found else "(not in this run)"


def pairs_per_second(b):
    # Real time throughout: items over the real time of an iteration.
    return b["items_per_second"]


def ceiling(runs, scalar, pairs):
    # The fastest loop with the batch's access pattern: the multiply-add loop by the hardware prefetcher
    # alone (bandwidth/*) and in the batch's blocks with its software prefetch (bandwidth_prefetched/*),
    # and the plain formula's loop (plain_batch/*), which reads and writes the same arrays too: out of
    # cache it has measured faster than both multiply-add loops in some runs, and a ceiling that a loop
    # of the same pattern beats is no ceiling.
    loops = [runs.get(f"{name}/{scalar}/{pairs}") for name in ("bandwidth", "bandwidth_prefetched", "plain_batch")]
    loops = [b for b in loops if b]
    return max(loops, key=lambda b: b["bytes_per_second"]) if loops else None


def batch_rows(runs, scalar):
    rows = []
    for name, b in runs.items():
        if not name.startswith(f"batch/{scalar}/"):
            continue
        pairs = int(name.split("/")[-1])
        rows.append((pairs, b, runs.get(f"plain_batch/{scalar}/{pairs}"), ceiling(runs, scalar, pairs),
                     runs.get(f"divisions/{scalar}/{pairs}")))
    return sorted(rows, key=lambda r: r[0])


def batch_table(runs):
    lines = ["| type | pairs | collisions/s | GB/s | plain formula's loop, pairs/s | time over the plain loop | "
             "ceiling GB/s | fraction of the ceiling | division limit, pairs/s | time over the division limit |",
             "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for scalar in ("double", "float"):
        for pairs, b, plain, ceiling, divisions in batch_rows(runs, scalar):
            items = pairs_per_second(b)
            cells = [scalar, f"{pairs:,}", f"{items / 1e6:.1f} M", f"{b['bytes_per_second'] / 1e9:.1f}"]
            cells += [f"{pairs_per_second(plain) / 1e6:.1f} M", f"{pairs_per_second(plain) / items:.2f}×"] if plain else ["–", "–"]
            cells += [f"{ceiling['bytes_per_second'] / 1e9:.1f}", f"{b['bytes_per_second'] / ceiling['bytes_per_second']:.2f}"] \
                if ceiling else ["–", "–"]
            cells += [f"{pairs_per_second(divisions) / 1e6:.0f} M", f"{pairs_per_second(divisions) / items:.2f}×"] \
                if divisions else ["–", "–"]
            lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines)


def batch_goals(runs):
    out = []
    for scalar in ("double", "float"):
        rows = {r[0]: r for r in batch_rows(runs, scalar)}
        cache = [f"{p:,}: {pairs_per_second(rows[p][2]) / pairs_per_second(rows[p][1]):.2f}×"
                 for p in (1000, 10000) if p in rows and rows[p][2]]
        memory = [f"{p:,}: {rows[p][1]['bytes_per_second'] / rows[p][3]['bytes_per_second']:.2f}"
                  for p in (1000000, 10000000) if p in rows and rows[p][3]]
        out.append(f"- {scalar}: in cache, time over the plain formula's loop {', '.join(cache) or '(not in this run)'} "
                   f"(goal ≤ 1.2×); out of cache, fraction of the bandwidth ceiling {', '.join(memory) or '(not in this run)'} "
                   f"(goal ≥ 0.9)")
    return "\n".join(out)



def batch_steps(runs):
    """In cache, the plain formula's loop turned into collide_batch one promise at a time (PlainStep in
    bench_collide.cpp): each step's time a pair and its ratio to the step before, and the product,
    collide_batch over the plain loop."""
    steps = ["plain_batch", "plain_batch_keeping_zero_signs", "plain_batch_generated_form", "batch"]
    lines = ["| type | pairs | 1. plain loop, ns a pair | 2. keeping −0 | 3. generated plain kernel | "
             "4. mass-range test: collide_batch | collide_batch over the plain loop |",
             "|---|---:|---:|---:|---:|---:|---:|"]
    found = False
    for scalar in ("double", "float"):
        for pairs in (100, 1000, 10000):
            row = [runs.get(f"{name}/{scalar}/{pairs}") for name in steps]
            if not all(row):
                continue
            found = True
            ns = [1e9 / pairs_per_second(b) for b in row]
            cells = [scalar, f"{pairs:,}", f"{ns[0]:.3f}"]
            cells += [f"{ns[k]:.3f} ({ns[k] / ns[k - 1]:.2f}×)" for k in range(1, len(ns))]
            cells.append(f"{ns[-1] / ns[0]:.2f}×")
            lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines) if found else "(not in this run)"


def table_events(runs):
    rows = sorted((int(name.split("/")[-1]), b) for name, b in runs.items() if name.startswith("table/events/"))
    if not rows:
        return "(not in this run)"
    lines = ["| balls | events/s | ns per event | ns per event and ball | cost per event against 16 balls |",
             "|---:|---:|---:|---:|---:|"]
    base = per_item_ns(rows[0][1])
    for balls, b in rows:
        ns = per_item_ns(b)
        lines.append(f"| {balls} | {b['items_per_second'] / 1e3:,.0f} k | {ns:,.0f} | {ns / balls:.1f} | {ns / base:.1f}× |")
    return "\n".join(lines)


def cpu_ns(b):
    """The benchmark's CPU time per iteration (its real time where the JSON has none)."""
    return b.get("cpu_time", b["real_time"]) * TIME_UNITS[b["time_unit"]]


def fastfiz_ratios(fastfiz, game, us):
    """FastFiz's mean CPU time per break over ours (CPU time too, like for like, and a mean: the
    benchmark's CPU time over the breaks it played), a round at a time: ours from the round's own run of
    our breaks where it has one, else `us` (the main run's, µs)."""
    ratios = []
    for peer, breaks in fastfiz:
        ours = cpu_ns(breaks[f"shot/break/{game}"]) / 1e3 if breaks is not None else us
        ratios.append(peer[game]["cpu_time_per_shot_us"]["mean"] / ours)
    return ratios


def shot_section(runs, pooltool, fastfiz=None):
    """Shots played to rest (billiards::simulation::Shot): breaks against pooltool's and FastFiz's, random shots."""
    lines = ["| break (7-ft table, 8 m/s at the apex, b = 0.25 R, 1e-3 R jitter) | ours: µs per break | events | µs per event | pooltool: ms per break (median, seeds 1–20) | events | pooltool / ours | goal | FastFiz: µs per break (mean CPU time) | events (mean) | µs per event | FastFiz / ours (CPU time) |",
             "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    found = False
    for game, name in (("9ball", "9-ball"), ("8ball", "8-ball")):
        b = runs.get(f"shot/break/{game}")
        if b is None:
            continue
        found = True
        us = per_item_ns(b) / 1e3
        events = b.get("events_per_break", float("nan"))
        ours = f"| {name} | {us:,.0f} | {events:.0f} | {us / events:.2f} |"
        if pooltool is not None:
            peer = pooltool[f"{game}_seeds1to20"]
            ms = 1e3 * peer["time_s"]["median"]
            row = f"{ours} {ms:,.1f} | {peer['events']['median']:.0f} | {1e3 * ms / us:,.0f}× | ≥ 300× |"
        else:
            row = f"{ours} (pooltool not set up) | | | ≥ 300× |"
        if fastfiz:
            peer_us = statistics.median([peer[game]["cpu_time_per_shot_us"]["mean"] for peer, _ in fastfiz])
            peer_events = statistics.median([peer[game]["events_per_shot"]["mean"] for peer, _ in fastfiz])
            ratio = statistics.median(fastfiz_ratios(fastfiz, game, cpu_ns(b) / 1e3))
            row += f" {peer_us:,.0f} | {peer_events:.0f} | {peer_us / peer_events:.2f} | {ratio:.2f}× |"
        else:
            row += " (FastFiz not set up) | | | |"
        lines.append(row)
    if not found:
        return "(not in this run)"
    random = runs.get("shot/random")
    threads = sorted((int(name.split(":")[-1]), b) for name, b in runs.items()
                     if name.startswith("shot/random/") and "threads:" in name)
    lines.append("")
    if random is not None:
        lines.append(f"- Random shots (1–16 balls scattered, some frozen to a ball or a cushion; 0.1–12 m/s, any "
                     f"direction, tip offsets within 0.7 R), one core: {random['items_per_second']:,.0f} shots/s, "
                     f"{random.get('events_per_shot', float('nan')):.1f} events a shot.")
    for count, b in threads:
        per_core = b["items_per_second"] / count
        ratio_text = f", {per_core / random['items_per_second']:.2f}× one core's rate per core" if random else ""
        lines.append(f"- One shot per thread on {count} threads: {b['items_per_second']:,.0f} shots/s{ratio_text}.")
    if pooltool is not None:
        lines.append(f"- pooltool on the same machine in the same run: Python "
                     f"{pooltool.get('python', '?')}, numba {pooltool.get('numba', '?')}; its seed-0 break repeated "
                     f"20 times: {1e3 * pooltool['9ball_fixed_seed0']['time_s']['median']:.1f} ms (9-ball), "
                     f"{1e3 * pooltool['8ball_fixed_seed0']['time_s']['median']:.1f} ms (8-ball); other processes' "
                     f"load meanwhile {pooltool['9ball_seeds1to20'].get('other_processes_cpu_cores', float('nan')):.2f} cores.")
    if fastfiz:
        first = fastfiz[0][0]
        reps = first.get("settings", {}).get("reps", "?")
        medians = ", ".join(
            f"{name} {statistics.median([p[game]['cpu_time_per_shot_us']['median'] for p, _ in fastfiz]):,.0f} µs "
            f"({statistics.median([p[game]['events_per_shot']['median'] for p, _ in fastfiz]):.0f} events)"
            for game, name in (("9ball", "9-ball"), ("8ball", "8-ball")))
        lines.append(f"- FastFiz on the same core in the same run: {first.get('engine', 'FastFiz')}, {reps} "
                     f"breaks a game after a warm-up, its thread's CPU time per break (executeShot and its "
                     f"deletion); its events count its cue strike, ball–ball, ball–rail, pocket and state-change "
                     f"events. Its mean is set against ours, which is a mean (our benchmark's CPU time over the "
                     f"breaks it played, the 64 racks in turn); its median break: {medians}.")
        if fastfiz[0][1] is not None:
            rounds = "; ".join(
                f"{name}: " + ", ".join(f"{r:.2f}×" for r in fastfiz_ratios(fastfiz, game, None))
                for game, name in (("9ball", "9-ball"), ("8ball", "8-ball")))
            lines.append(f"- FastFiz / ours is the median of {len(fastfiz)} rounds on that core, each our break "
                         f"benchmark (the median of 3 repetitions) then FastFiz's, back to back, so that both meet "
                         f"the machine as it was within seconds: {rounds}.")
    return "\n".join(lines)


GAMES = (("9ball", "9-ball"), ("8ball", "8-ball"), ("snooker", "snooker"), ("3cushion", "three-cushion"))


def games_section(runs, python):
    """The rules' decision against the shot it decides (C++), and GameEnv's step against the same shot
    played from Python, from the same run."""
    lines = ["| game | a shot, C++ | the rules' decision, C++ | rules / shot | GameEnv.step, Python | "
             "the shot from Python | step / shot | goal |", "|---|---:|---:|---:|---:|---:|---:|---:|"]
    for game, name in GAMES:
        play, rules = runs.get(f"games/play/{game}"), runs.get(f"games/rules/{game}")
        if play is None or rules is None:
            continue
        play_us, rules_us = per_item_ns(play) / 1e3, per_item_ns(rules) / 1e3
        step = (python or {}).get(f"game_{game}")
        env = ("| | | |" if step is None else
               f"| {step['us_per_step']:,.1f} µs | {step['us_per_shot']:,.1f} µs | "
               f"{step['us_per_step'] / step['us_per_shot']:.2f}× | ≤ 1.2× |")
        lines.append(f"| {name} | {play_us:,.2f} µs | {rules_us * 1e3:,.0f} ns | {100 * rules_us / play_us:.2f} % {env}")
    if len(lines) == 2:
        return "(not in this run)"
    return "\n".join(lines)


def python_section(runs, python, pooltool):
    """The Python package beside the C++ calls and pooltool, from bench_python.py's JSON of the same run."""
    if python is None:
        return "(the Python package was not built for this run: BILLIARDS_BUILD_PYTHON)"
    lines = ["| what | Python | C++ (the same run) | Python / C++ | goal | pooltool / Python | goal |",
             "|---|---:|---:|---:|---:|---:|---:|"]
    for game, name in (("9ball", "9-ball"), ("8ball", "8-ball")):
        ours = python.get(f"break_{game}")
        cpp = runs.get(f"shot/break/{game}")
        if ours is None or cpp is None:
            continue
        cpp_us = per_item_ns(cpp) / 1e3
        peer = ""
        if pooltool is not None:
            ms = 1e3 * pooltool[f"{game}_seeds1to20"]["time_s"]["median"]
            peer = f"{1e3 * ms / ours['us_per_break']:,.0f}×"
        lines.append(f"| {'an' if name[0] == '8' else 'a'} {name} break: Shot, strike, play from Python | {ours['us_per_break']:,.1f} µs "
                     f"({ours['events_per_break']:.0f} events) | {cpp_us:,.1f} µs | "
                     f"{ours['us_per_break'] / cpp_us:.2f}× | ≤ 1.2× | {peer or '(pooltool not set up)'} | ≥ 300× |")
    one, random = python.get("random_one_thread"), runs.get("shot/random")
    if one is not None and random is not None:
        lines.append(f"| random shots with `play_shots`, one thread | {one['shots_per_second']:,.0f} shots/s "
                     f"({one['events_per_shot']:.1f} events a shot) | {random['items_per_second']:,.0f} shots/s "
                     f"({random.get('events_per_shot', float('nan')):.1f}) | "
                     f"{one['shots_per_second'] / random['items_per_second']:.2f}× the rate | ≥ 0.8× | | |")
    every = python.get("random_every_core")
    if every is not None and one is not None:
        lines.append(f"| random shots with `play_shots`, {every['threads']} threads | "
                     f"{every['shots_per_second']:,.0f} shots/s | | "
                     f"{every['shots_per_second'] / one['shots_per_second'] / every['threads']:.2f}× one thread's "
                     f"rate a thread | | | |")
    lines.append("")
    lines.append(f"Python {python.get('python', '?')}, numpy {python.get('numpy', '?')}; {one['shots'] if one else '?'} "
                 f"random shots, the kind of `shot/random` drawn from a seeded numpy generator and batched by "
                 f"table and ball count.")
    dask = python.get("dask")
    if dask:
        lines.append(f"The Dask batch (`billiards.distributed.play_shots`) on a local cluster of {dask['workers']} "
                     f"worker processes, {dask['shots']:,} breaks in {dask['tasks']} tasks of {dask['chunk_size']}: "
                     f"{dask['dask_shots_per_second']:,.0f} shots/s against {dask['local_shots_per_second']:,.0f} "
                     f"for `play_shots` on every core in this process "
                     f"({dask['dask_shots_per_second'] / dask['local_shots_per_second']:.2f}×): about "
                     f"{dask['overhead_ms_per_task']:.1f} ms of overhead a task (scheduling, pickling the layouts "
                     f"and the results).")
    return "\n".join(lines)


def gas_events(runs):
    """The hard-sphere gas (billiards::simulation::Gas): collisions per second against N, beside the table."""
    sizes = sorted({int(name.split("/")[-1]) for name in runs if name.startswith("gas/events/")})
    if not sizes:
        return "(not in this run)"
    def rate(dimension, balls):
        b = runs.get(f"gas/events/{dimension}/{balls}")
        return b["items_per_second"] if b else None
    lines = ["| balls | 2-D events/s | 2-D cost per event against the smallest | 3-D events/s | "
             "3-D cost per event against the smallest | the all-pairs table, events/s |",
             "|---:|---:|---:|---:|---:|---:|"]
    base = {d: rate(d, sizes[0]) for d in ("2d", "3d")}
    notes = []
    for balls in sizes:
        cells = [f"{balls:,}"]
        for d in ("2d", "3d"):
            r = rate(d, balls)
            cells.append(f"{r / 1e3:,.0f} k" if r else "–")
            cells.append(f"{base[d] / r:.2f}×" if r and base[d] else "–")
        table = runs.get(f"table/events/{balls}")
        cells.append(f"{table['items_per_second'] / 1e3:,.1f} k" if table else "–")
        lines.append("| " + " | ".join(cells) + " |")
    largest = sizes[-1]
    for d in ("2d", "3d"):
        r = rate(d, largest)
        if r and base[d]:
            goal = ("goal ≤ 2× at 10^6 against 10^3" if d == "2d" else
                    "the spheres' goal is the comparison with SingleEvent below; the small gas here runs on "
                    "neighbour lists, faster than cells, and the large one on cells")
            notes.append(f"{d[0]}-D: the cost per event at {largest:,} balls is {base[d] / r:.2f}× that at "
                         f"{sizes[0]:,} ({goal})")
    return "\n".join(lines) + "\n\n" + "\n".join(f"- {n}" for n in notes)


def edmd_section(path):
    """The gas against Smallenburg's SingleEvent code: the lines ../shared/peers/edmd/run.py printed."""
    if path is None:
        return "(Smallenburg's SingleEvent code is not in this run: ../shared/peers/edmd/run.py was not found)"
    rows = []
    pattern = re.compile(r"N=(\d+) eta=([0-9.]+): billiards-gas (\d+) k/s, Smallenburg SingleEvent (\d+) k/s, "
                         r"ours/peer ([0-9.]+) \(runs: ours \[([0-9, ]*)\], peer \[([0-9, ]*)\]\)")
    with open(path, encoding="utf-8") as f:
        for line in f:
            m = pattern.match(line.strip())
            if m:
                rows.append(m.groups())
    if not rows:
        fail("--edmd", path, "the lines of ../shared/peers/edmd/run.py (N=… eta=…: billiards-gas … k/s, …)")
    lines = ["| N | η | billiards-gas | SingleEvent | ours / theirs | goal | runs: ours | runs: theirs |",
             "|---:|---:|---:|---:|---:|---:|---|---|"]
    for n, eta, ours, peer, ratio_text, ours_runs, peer_runs in rows:
        ratio_value = float(ratio_text)
        mark = "" if ratio_value >= 1.0 else " (below the goal)"
        lines.append(f"| {int(n):,} | {eta} | {int(ours):,} k/s | {int(peer):,} k/s | **{ratio_value:.2f}**{mark} | ≥ 1.0 | "
                     f"{ours_runs} | {peer_runs} |")
    worst = min(float(r[4]) for r in rows)
    return "\n".join(lines) + f"\n\n- The smallest ratio: {worst:.2f} (goal ≥ 1.0 in every row)."


def svg(runs):
    """The throughput figure's SVG text, or None where the run has no batch benchmarks."""
    width, height, left, bottom, top, right = 720, 420, 70, 50, 20, 150
    series = []
    for scalar, colour in (("double", "#1f77b4"), ("float", "#2ca02c")):
        rows = batch_rows(runs, scalar)
        series.append((f"batch {scalar}", colour, [(r[0], r[1]["bytes_per_second"]) for r in rows], ""))
        series.append((f"ceiling ({scalar})", colour, [(r[0], r[3]["bytes_per_second"]) for r in rows if r[3]], "6,4"))
    points = [pt for _, _, pts, _ in series for pt in pts]
    if not points:
        return None
    xs = [math.log10(p) for p, _ in points]
    ys = [v / 1e9 for _, v in points]
    x0, x1 = min(xs), max(xs)
    y1 = max(ys) * 1.1

    def sx(p):
        return left + (math.log10(p) - x0) / max(x1 - x0, 1e-9) * (width - left - right)

    def sy(v):
        return height - bottom - (v / 1e9) / y1 * (height - bottom - top)

    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" font-family="sans-serif" font-size="12">',
           f'<rect width="{width}" height="{height}" fill="white"/>',
           f'<line x1="{left}" y1="{height - bottom}" x2="{width - right}" y2="{height - bottom}" stroke="black"/>',
           f'<line x1="{left}" y1="{top}" x2="{left}" y2="{height - bottom}" stroke="black"/>']
    for e in range(int(math.floor(x0)), int(math.ceil(x1)) + 1):
        x = sx(10 ** e)
        out.append(f'<text x="{x:.1f}" y="{height - bottom + 18}" text-anchor="middle">10^{e}</text>')
    for k in range(6):
        v = y1 * k / 5
        y = height - bottom - v / y1 * (height - bottom - top)
        out.append(f'<text x="{left - 8}" y="{y + 4:.1f}" text-anchor="end">{v:.0f}</text>')
    out.append(f'<text x="{(left + width - right) / 2}" y="{height - 10}" text-anchor="middle">pairs (N)</text>')
    out.append(f'<text x="16" y="{(top + height - bottom) / 2}" transform="rotate(-90 16 {(top + height - bottom) / 2})" text-anchor="middle">GB/s (read + written)</text>')
    for i, (label, colour, pts, dash) in enumerate(series):
        if not pts:
            continue
        path_d = " ".join(f"{'M' if j == 0 else 'L'}{sx(p):.1f},{sy(v):.1f}" for j, (p, v) in enumerate(pts))
        dash_attr = f' stroke-dasharray="{dash}"' if dash else ""
        out.append(f'<path d="{path_d}" fill="none" stroke="{colour}" stroke-width="2"{dash_attr}/>')
        ly = top + 16 * (i + 1)
        out.append(f'<line x1="{width - right + 10}" y1="{ly - 4}" x2="{width - right + 30}" y2="{ly - 4}" stroke="{colour}" stroke-width="2"{dash_attr}/>')
        out.append(f'<text x="{width - right + 35}" y="{ly}">{label}</text>')
    out.append("</svg>")
    return "\n".join(out) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("json")
    parser.add_argument("--command", default="BILLIARDS_BENCH_MAX_PAIRS=10000000 build/bench/billiards_bench "
                        "--benchmark_format=json --benchmark_out=bench.json")
    parser.add_argument("--derive", help="billiards-derive to time (five runs, the median is reported)")
    parser.add_argument("--clean-build", help="what a clean build cost, measured by the caller (text)")
    parser.add_argument("--pooltool", help="the JSON pooltool's bench_breaks.py printed in the same run")
    parser.add_argument("--edmd", help="what ../shared/peers/edmd/run.py printed in the same run")
    parser.add_argument("--fastfiz", action="append", default=[],
                        help="the JSON ../shared/peers/fastfiz's bench_break printed in the same run (once a round)")
    parser.add_argument("--breaks", action="append", default=[],
                        help="the billiards_bench JSON of our breaks run just before each --fastfiz")
    parser.add_argument("--python", help="the JSON bench/bench_python.py printed in the same run")
    parser.add_argument("--out-dir", default=HERE, help="where RESULTS.md and throughput.svg go (default: bench/)")
    args = parser.parse_args()
    if not os.path.isdir(args.out_dir):
        fail("--out-dir", args.out_dir, "an existing folder")
    if args.breaks and len(args.breaks) != len(args.fastfiz):
        fail("--breaks", args.breaks, f"one for each --fastfiz ({len(args.fastfiz)}), or none")
    context, runs = load(args.json)
    pooltool = None
    if args.pooltool:
        try:
            with open(args.pooltool, encoding="utf-8") as f:
                pooltool = json.load(f)
            for game in ("9ball", "8ball"):
                float(pooltool[f"{game}_seeds1to20"]["time_s"]["median"])
        except OSError as error:
            fail("--pooltool", args.pooltool, f"a readable file ({error.strerror})")
        except (UnicodeDecodeError, ValueError, KeyError, TypeError) as error:
            fail("--pooltool", args.pooltool, f"the JSON of pooltool's bench_breaks.py ({error!r})")
    args.pooltool_runs = pooltool
    fastfiz = []
    for k, path in enumerate(args.fastfiz):
        try:
            with open(path, encoding="utf-8") as f:
                peer = json.load(f)
            for game in ("9ball", "8ball"):
                for statistic in ("mean", "median"):
                    float(peer[game]["cpu_time_per_shot_us"][statistic]) / float(peer[game]["events_per_shot"][statistic])
        except OSError as error:
            fail("--fastfiz", path, f"a readable file ({error.strerror})")
        except (UnicodeDecodeError, ValueError, KeyError, TypeError, ZeroDivisionError) as error:
            fail("--fastfiz", path, f"the JSON of FastFiz's bench_break ({error!r})")
        breaks = None
        if args.breaks:
            breaks = load(args.breaks[k], "--breaks")[1]
            if not all(f"shot/break/{game}" in breaks for game in ("9ball", "8ball")):
                fail("--breaks", args.breaks[k], "a billiards_bench run of shot/break/9ball and shot/break/8ball")
        fastfiz.append((peer, breaks))
    args.fastfiz_runs = fastfiz
    python = None
    if args.python:
        try:
            with open(args.python, encoding="utf-8") as f:
                python = json.load(f)
            float(python["break_9ball"]["us_per_break"])
        except OSError as error:
            fail("--python", args.python, f"a readable file ({error.strerror})")
        except (ValueError, KeyError, TypeError) as error:
            fail("--python", args.python, f"the JSON of bench/bench_python.py ({error!r})")
    args.python_runs = python
    try:
        figure, text = report(args, context, runs)
    except (KeyError, TypeError, ValueError, ZeroDivisionError) as error:
        fail("RESULTS_JSON", args.json, f"the JSON of a billiards_bench run; it lacks or garbles {error!r}")
    # Both files are composed before either is written, and each is written atomically.
    try:
        if figure is not None:
            write_atomically(os.path.join(args.out_dir, "throughput.svg"), figure)
        write_atomically(os.path.join(args.out_dir, "RESULTS.md"), text)
    except OSError as error:
        fail("--out-dir", args.out_dir, f"a folder this user can write ({error.strerror})")
    return 0


def report(args, context, runs):
    """The throughput figure (SVG text or None) and RESULTS.md's text."""
    derive_text = "(not measured in this run)"
    if args.derive:
        import os, subprocess, tempfile, time

        def timed_runs(count, cache):
            """The median of `count` runs, with the proof cache folder `cache` (None: no cache)."""
            env = {k: v for k, v in os.environ.items() if k != "BILLIARDS_PROOF_CACHE"}
            if cache:
                env["BILLIARDS_PROOF_CACHE"] = cache
            times = []
            for _ in range(count):
                with tempfile.TemporaryDirectory() as out:
                    start = time.perf_counter()
                    try:
                        subprocess.run([args.derive, "--out", out], check=True, stdout=subprocess.DEVNULL, env=env)
                    except (OSError, subprocess.CalledProcessError) as error:
                        fail("--derive", args.derive, f"billiards-derive, a program that runs ({error})")
                    times.append(time.perf_counter() - start)
            return sorted(times)[count // 2]

        cold = timed_runs(3, None)
        with tempfile.TemporaryDirectory() as cache:
            timed_runs(1, cache)  # fills it
            warm = timed_runs(5, cache)
        derive_text = (f"{cold:.3f} s proving every kernel afresh (median of 3 runs of `billiards-derive --out DIR`, "
                       f"no proof cache), {warm:.3f} s with every Gappa proof in the proof cache "
                       f"(`BILLIARDS_PROOF_CACHE`, median of 5; goal: well under 2 s)")
    figure = svg(runs)
    caches = ", ".join(f"L{c['level']} {c['type']} {c['size'] // 1024} KiB" for c in context.get("caches", [])) \
        or "not reported by this machine"
    text = f"""# Benchmark results

Generated by `bench/report.py` from one run of `billiards_bench`: every ratio compares two benchmarks
of that same run, and every figure is real (wall-clock) time — each benchmark runs with UseRealTime,
so the times and the per-second counters share one basis.

- Machine: {context.get('cpu_model', 'CPU model not recorded')}; {context.get('num_cpus')} CPUs at {context.get('mhz_per_cpu')} MHz; caches: {caches}
- Load average at the start: {', '.join(f'{x:.2f}' for x in context.get('load_avg', []))}
- Command: `{args.command}`
- Library build: {context.get('library_build_type')} (Debian's libbenchmark); billiards_bench itself at -O3 -march=native with NDEBUG

## One collision per call (3-D, 4096 random cases)

One call per iteration, cycling through the cases; the loop's index wraps by a comparison, so nothing
but the call lies on its dependency chain.

{single_call_table(runs)}

- What the overflow safety costs, generated against the paper's plain formula:
  {ratio(runs, "collide/generated/double", "collide/paper_formula/double")} (double), {ratio(runs, "collide/generated/float", "collide/paper_formula/float")} (float). Goal: ≤ 1.2×.
- Generated against an engine's form with stored inverse masses:
  {ratio(runs, "collide/generated/double", "collide/engine_formula/double")} (double), {ratio(runs, "collide/generated/float", "collide/engine_formula/float")} (float). Goal: ≤ 1.2×.
- Generated against the same form typed by hand: {ratio(runs, "collide/generated/double", "collide/ratio_formula/double")} (double),
  {ratio(runs, "collide/generated/float", "collide/ratio_formula/float")} (float); of the form's cost, the small-mass select alone:
  {ratio(runs, "collide/ratio_formula/double", "collide/ratio_formula_without_select/double")} (double), {ratio(runs, "collide/ratio_formula/float", "collide/ratio_formula_without_select/float")} (float).
- The raw derivation against the generated kernel: {ratio(runs, "collide/raw_derivation/double", "collide/generated/double")} (double),
  {ratio(runs, "collide/raw_derivation/float", "collide/generated/float")} (float).

## The other calls against their plain forms (one per call, the same cases)

{other_calls_table(runs)}

### What the promises cost a call

The restitution and direction calls' goals (≤ 1.2× their plain forms) are not met. Here each is rebuilt
from the same generated kernels with its promises taken away, each form's time in ns and, in brackets,
its ratio to the plain form by hand (none of these forms is offered to users):

- d unscaled (`collide_along_direction` only): d taken as given, not scaled by a power of two first,
  which keeps a heavy ball's subnormal change to its last digits and gives every 2^k d the same bits;
- no promise kept: also the plain kernel straight away, without the mass-range test (wrong, even ∞ or
  NaN, for a mass outside [plain_mass_low, plain_mass_high], an immovable +∞ included), and the
  update as v + c n, one multiply-add, which turns an unchanged −0 into +0. What is left
  against the plain form is the generated kernel's own form (two divisions by one sum, which give
  equal masses their exact (1 + e)/2) and the code the compiler makes of it.

{promise_steps(runs)}

## The batch path against the plain formula's loop, a bandwidth ceiling and the division limit

Bytes per pair: 17 scalars (11 read, 6 written). The plain formula's loop (`plain_batch/*`) is the paper's
formula over the same arrays, the loop a user would write instead. The bandwidth ceiling
is the fastest loop with the batch's own access pattern — each reads the same arrays, every component
once a pair, and writes v1 and v2 in place: a multiply-add per component in one pass left to the
hardware prefetcher (`bandwidth/*`) or in blocks of 1024 pairs, each asking memory for the next
block's arrays first (`bandwidth_prefetched/*`), or the plain formula's loop itself,
which out of cache has measured faster than both in some runs; memcpy is no ceiling (below glibc's
non-temporal threshold it uses cached stores). The division limit is the ratio form's five divisions per pair alone
(the batch takes that form only for blocks with a mass outside the plain range), vectorised over arrays
of the same length (`divisions/*`): where the data sit in cache it, not the bandwidth, bounds the batch.

{batch_table(runs)}

{batch_goals(runs)}

### Where the batch's time goes in cache

The plain formula's loop turned into collide_batch one promise at a time, over the same arrays; each
step's time a pair, and in brackets its ratio to the step before:

1. `plain_batch/*`: the paper's formula, one division by m1 + m2 and a multiply-add a component;
2. `plain_batch_keeping_zero_signs/*`: the update v − (0 − c n), which leaves an unchanged velocity's
   bits alone, −0 included;
3. `plain_batch_generated_form/*`: the generated plain kernel, 2 m2/(m1 + m2) and 2 m1/(m1 + m2), two
   divisions by one sum, which give equal masses their exact exchange: collide_batch's pass;
4. `batch/*`: collide_batch itself, which also tests the masses' range before each block of 4096 pairs
   to pick the plain kernel or the full one for it.

{batch_steps(runs)}

{"![throughput against N](throughput.svg)" if figure is not None else ""}

## The derivation

- `billiards-derive`: {derive_text}
- A clean build: {args.clean_build or "(not measured in this run)"}

## The event-driven table (billiards::simulation::Table), events per second as the balls grow

At a constant density (the area per ball of 16 balls on a 9-ft table); each event re-predicts the one
or two balls it changed against every other ball (naive all-pairs prediction), so the cost per event
grows as O(N): the last column should grow about as the number of balls.

{table_events(runs)}

## The hard-sphere gas (billiards::simulation::Gas), events per second as the balls grow

At packing fraction 0.3, equilibrated for max(N, 20 000) collisions first; each event predicts only
against the balls of its neighbour list or of the neighbouring cells, and its next event is filed in a
calendar queue (O(1)), so the cost per event should not grow with N (the caches aside). The engine is
the automatic choice (docs/simulations.md): disks on cells at every N here; spheres on neighbour lists
up to 10^5 balls and on cells at 10^6. One core; the all-pairs table beside it where it ran the same N.

{gas_events(runs)}

## The hard-sphere gas against Smallenburg's SingleEvent code

Collisions per second of wall time, 3-D, an FCC start, σ = m = kT = 1, both microcanonical (SingleEvent's
thermostat off), as `../shared/peers/edmd/run.py` measures them: both programs as separate processes
pinned to the same core, alternating, three pairs a row, the median of each side; SingleEvent's rate
from its own printed collision counts over the last two thirds of its run, ours from `billiards-gas
--json` over its measured span (after 3 N collisions of equilibration); SingleEvent built from its
unmodified source with `gcc -O3 -ffast-math -funroll-loops -march=native`, ours as built here. The
ratio is ours over theirs.

{edmd_section(args.edmd)}

## Shots to rest (billiards::simulation::Shot) against pooltool and FastFiz

A break played to rest event by event, invariant checks off as in a release build; each iteration a new
rack of 64 seeded ones. pooltool plays the same break (`../shared/peers/pooltool/bench_breaks.py`: its
default 7-ft table and physics, the cue ball struck at 8 m/s at the apex with b = 0.25, its 1e-3 R
jitter; its own racks and cue ball spot) on the same machine in the same run of `bench/run.sh`; its
time is the median over seeds 1–20 after its JIT is warm. FastFiz, the C++ engine of the computational
pool tournaments, plays it too (`../shared/peers/fastfiz/bench_break`: its own default table, the cue
stick at 8 m/s at the apex with b = 0.25 R, racks with 1e-3 R jitter) on the same core in the same run,
in rounds alternating with ours.
The models differ (docs/shot.md), so the event counts differ too.

{shot_section(runs, args.pooltool_runs, getattr(args, "fastfiz_runs", None))}

## Python

The package `billiards` (docs/python.md) as built in the build tree, on Debian's Python: the breaks above
called from Python (`Shot`, `strike`, `play`, pinned to the same core as the C++ benchmark), random shots
through `play_shots`, and pooltool's breaks of the same run against the Python ones.

{python_section(runs, getattr(args, "python_runs", None), args.pooltool_runs)}

## The games: the rules against the shot, the environment against the shot

256 shots of each game a seeded random player plays (`games::Game`: any cue in pool; in snooker and
three-cushion a cue aimed with a random cut at a ball it may meet first), replayed from where each
started (`games/play/*`) against the rules' decision alone on the same events (`games/rules/*`); and,
from Python, 2000 steps of `billiards.games.GameEnv` with the same kind of player against the same
shots played from Python (`Shot`, `strike`, `play` from the layout each step struck; `bench_python.py`).

{games_section(runs, getattr(args, "python_runs", None))}
"""
    return figure, text


if __name__ == "__main__":
    sys.exit(main())
