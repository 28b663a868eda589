#!/usr/bin/env python3
"""Runs billiards-shot with every output and checks them against each other and their formats.

- The JSON: every event's fields (time non-decreasing, a known kind, the balls, the cushion, jaw or
  pocket where the kind has one, the states after), the balls at rest matching the last states, and
  "pocketed" listing exactly the balls whose final state is pocketed.
- The CSV: a row per ball per sample at the rate asked, its columns, and at each event's time the
  sampled positions where the JSON's states after the event put them.
- The SVG: well-formed XML with a path per ball.
- The HTML page: self-contained (no src or href to anything but a fragment), and, in headless
  Chromium (where it is installed), each ball drawn where the CSV puts it at the time named in the
  address (#t=SECONDS), the slider set to that sample.

Usage: shot_outputs.py --program PATH --work DIR [--chromium PATH] [billiards-shot arguments...]
Exit status 0 when everything holds, 1 when something does not.
"""

import argparse
import csv
import json
import os
import re
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ElementTree

KINDS = {"strike", "ball", "cushion", "jaw", "pocket", "transition"}
PHASES = {"sliding", "rolling", "spinning", "stationary"}


def fail(message):
    print(f"shot_outputs: {message}")
    sys.exit(1)


def check_json(shot):
    events = shot["events"]
    if not events or events[0]["kind"] != "strike":
        fail("the events do not start with the strike")
    last_time = 0.0
    count = len(shot["start"])
    for k, event in enumerate(events):
        where = f"event {k}"
        if event["kind"] not in KINDS:
            fail(f"{where}: unknown kind {event['kind']!r}")
        if event["time"] < last_time:
            fail(f"{where}: time {event['time']} before {last_time}")
        last_time = event["time"]
        if event["from"] not in PHASES or event["to"] not in PHASES:
            fail(f"{where}: phases {event['from']!r} -> {event['to']!r}")
        expected_balls = 2 if event["kind"] == "ball" else 1
        if len(event["balls"]) != expected_balls or not all(0 <= b < count for b in event["balls"]):
            fail(f"{where}: balls {event['balls']}")
        if event["kind"] in ("cushion", "jaw", "pocket") and event["kind"] not in event:
            fail(f"{where}: a {event['kind']} event without its index")
        if [s["ball"] for s in event["states"]] != event["balls"]:
            fail(f"{where}: states of {[s['ball'] for s in event['states']]}, expected {event['balls']}")
        if event["kind"] == "pocket" and not event["states"][0]["pocketed"]:
            fail(f"{where}: a pocketed ball not marked pocketed")
        if event["kind"] == "transition" and event["from"] == event["to"]:
            fail(f"{where}: a transition from {event['from']} to itself")
    final = shot["final"]
    pocketed = [s["ball"] for s in final if s["pocketed"]]
    if pocketed != shot["pocketed"]:
        fail(f"pocketed {shot['pocketed']}, final states say {pocketed}")
    for state in final:
        if not state["pocketed"] and any(v != 0 for v in state["velocity"]):
            fail(f"ball {state['ball']} is not at rest at the end: {state['velocity']}")
    # Each ball's last state in the events is where it ended.
    last_state = {s["ball"]: s for s in shot["start"]}
    for event in events:
        for state in event["states"]:
            last_state[state["ball"]] = state
    for state in final:
        if last_state[state["ball"]]["position"] != state["position"] and not state["pocketed"]:
            fail(f"ball {state['ball']} ended at {state['position']}, its last event left it at "
                 f"{last_state[state['ball']]['position']}")
    return events


def check_csv(path, shot, rate):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows or list(rows[0].keys()) != ["time", "ball", "x", "y", "vx", "vy", "pocketed"]:
        fail(f"{path}: columns {list(rows[0].keys()) if rows else []}")
    count = len(shot["start"])
    times = sorted({float(r["time"]) for r in rows})
    if len(rows) != count * len(times):
        fail(f"{path}: {len(rows)} rows for {count} balls and {len(times)} samples")
    end = shot["time"]
    expected = [k / rate for k in range(int(end * rate) + 1)]
    if expected[-1] < end:
        expected.append(end)
    if len(times) != len(expected) or any(abs(a - b) > 1e-12 for a, b in zip(times, expected)):
        fail(f"{path}: sample times {times[:3]}..., expected every 1/{rate} s to {end}")
    at = {(float(r["time"]), int(r["ball"])): r for r in rows}
    # At the last sample (the last event's time) every ball is where the JSON's final states put it.
    for state in shot["final"]:
        row = at[(times[-1], state["ball"])]
        if [float(row["x"]), float(row["y"])] != state["position"] or (row["pocketed"] == "1") != state["pocketed"]:
            fail(f"{path}: ball {state['ball']} at the end is {row}, the JSON says {state}")
    return at, times


def check_svg(path, count):
    tree = ElementTree.parse(path)
    lines = tree.getroot().findall("{http://www.w3.org/2000/svg}polyline")
    if len(lines) != count:
        fail(f"{path}: {len(lines)} paths for {count} balls")


def check_html(path, chromium, work, at, times, count):
    text = open(path, encoding="utf-8").read()
    for reference in re.findall(r"""(?:src|href)\s*=\s*["']([^"']*)""", text):
        if not reference.startswith("#"):
            fail(f"{path}: loads {reference!r}, expected a self-contained page")
    if re.search(r"@import|url\(", text):
        fail(f"{path}: a style loads something")
    if chromium is None:
        print("shot_outputs: Chromium not found; the page's rendering not checked")
        return
    for sample in (times[len(times) // 3], times[-1]):
        url = "file://" + os.path.abspath(path) + f"#t={sample!r}"
        result = subprocess.run([chromium, "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run",
                                 f"--user-data-dir={os.path.join(work, 'profile')}",
                                 "--virtual-time-budget=5000", "--dump-dom", url],
                                capture_output=True, timeout=180, check=False, text=True)
        dom = result.stdout
        shown = re.search(r'<body[^>]*data-time="([^"]+)"', dom)
        if not shown or float(shown.group(1)) != sample:
            fail(f"{path}#t={sample}: the page shows time {shown.group(1) if shown else None}")
        for i in range(count):
            circle = re.search(r'<circle id="ball-%d"[^>]*>' % i, dom)
            if not circle:
                fail(f"{path}: no circle for ball {i}")
            x = re.search(r'data-x="([^"]+)"', circle.group(0))
            y = re.search(r'data-y="([^"]+)"', circle.group(0))
            row = at[(sample, i)]
            if not x or not y or float(x.group(1)) != float(row["x"]) or float(y.group(1)) != float(row["y"]):
                fail(f"{path}#t={sample}: ball {i} drawn at {circle.group(0)}, the CSV says ({row['x']}, {row['y']})")
            hidden = 'visibility="hidden"' in circle.group(0)
            if hidden != (row["pocketed"] == "1"):
                fail(f"{path}#t={sample}: ball {i} hidden={hidden}, pocketed={row['pocketed']}")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--program", required=True)
    parser.add_argument("--work", required=True)
    parser.add_argument("--chromium", default="chromium")
    args, rest = parser.parse_known_args()
    os.makedirs(args.work, exist_ok=True)
    files = {k: os.path.join(args.work, f"shot.{k}") for k in ("json", "svg", "html", "csv")}
    rate = 100
    command = [args.program, *rest, "--json", files["json"], "--svg", files["svg"], "--html", files["html"],
               "--trajectories", files["csv"], "--rate", str(rate)]
    run = subprocess.run(command, capture_output=True, text=True, timeout=300, check=False)
    if run.returncode != 0:
        fail(f"{' '.join(command)} exited {run.returncode}: {run.stderr.strip()}")
    shot = json.load(open(files["json"]))
    check_json(shot)
    at, times = check_csv(files["csv"], shot, rate)
    check_svg(files["svg"], len(shot["start"]))
    check_html(files["html"], shutil.which(args.chromium), args.work, at, times, len(shot["start"]))
    print(f"shot_outputs: {len(shot['events'])} events, {len(times)} samples: every output agrees")


if __name__ == "__main__":
    main()
