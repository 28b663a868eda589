#!/usr/bin/env python3
"""A polydisperse snapshot through billiards-gas as a user runs it: a binary mixture written here as
extended XYZ (species A and B, radii 0.5 and 0.3, masses 1 and 0.216) is read, run, written, and read
again by the program (to .sph and back). Checked here, by hand, on the files: every ball keeps its species,
radius and mass in the order it was read; no pair overlaps at the end (all pairs, nearest images); the
kinetic energy and the momentum are those of the start; the frames written every --snapshot-every come at
its multiples; the time series has a row a block; the JSON's packing fraction is the mixture's.

usage: gas_polydisperse_round_trip.py --program BILLIARDS_GAS --work FOLDER
"""
import argparse, json, math, os, random, shutil, subprocess, sys

failures = []


def check(condition, what):
    if not condition:
        failures.append(what)


def run(program, *args):
    p = subprocess.run([program, *args], capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"billiards-gas {' '.join(args)} exited with {p.returncode}:\n{p.stdout}{p.stderr}")


def read_frames(path):
    """Every frame of an extended XYZ file: (time, box side, [(species, position, velocity, radius, mass)])."""
    lines = open(path).read().split("\n")
    frames, k = [], 0
    while k < len(lines) and lines[k].strip():
        n = int(lines[k])
        header = lines[k + 1]
        check("Properties=species:S:1:pos:R:3:velo:R:3:radius:R:1:mass:R:1" in header, f"{path}: header {header}")
        side = float(header.split('Lattice="')[1].split()[0])
        time = float(header.split("Time=")[1].split()[0])
        balls = []
        for line in lines[k + 2:k + 2 + n]:
            w = line.split()
            balls.append((w[0], [float(x) for x in w[1:4]], [float(x) for x in w[4:7]], float(w[7]), float(w[8])))
        frames.append((time, side, balls))
        k += n + 2
    return frames


def energy_and_momentum(balls):
    e = sum(0.5 * b[4] * sum(v * v for v in b[2]) for b in balls)
    p = [sum(b[4] * b[2][a] for b in balls) for a in range(3)]
    return e, p


def closest(balls, side):
    worst = math.inf
    for i in range(len(balls)):
        for j in range(i + 1, len(balls)):
            d = 0.0
            for a in range(3):
                x = balls[j][1][a] - balls[i][1][a]
                x -= side * round(x / side)
                d += x * x
            worst = min(worst, math.sqrt(d) / (balls[i][3] + balls[j][3]))
    return worst


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--program", required=True)
    ap.add_argument("--work", required=True)
    a = ap.parse_args()
    shutil.rmtree(a.work, ignore_errors=True)
    os.makedirs(a.work)
    # 256 balls on an FCC lattice (4 x 4 x 4 cells), A and B alternating, η = 0.3.
    random.seed(11)
    n_cells, basis = 4, [(0.25, 0.25, 0.25), (0.75, 0.75, 0.25), (0.75, 0.25, 0.75), (0.25, 0.75, 0.75)]
    kinds = [("A", 0.5, 1.0), ("B", 0.3, 0.216)]
    volume = 128 * 4 / 3 * math.pi * (0.5 ** 3 + 0.3 ** 3)
    side = (volume / 0.3) ** (1 / 3)
    spacing = side / n_cells
    balls = []
    for i in range(n_cells):
        for j in range(n_cells):
            for k in range(n_cells):
                for b in basis:
                    species, radius, mass = kinds[len(balls) % 2]
                    position = [(i + b[0]) * spacing, (j + b[1]) * spacing, (k + b[2]) * spacing]
                    velocity = [random.gauss(0, 1 / math.sqrt(mass)) for _ in range(3)]
                    balls.append((species, position, velocity, radius, mass))
    start = os.path.join(a.work, "mixture.xyz")
    with open(start, "w") as f:
        f.write(f"{len(balls)}\n")
        f.write(f'Lattice="{side!r} 0 0 0 {side!r} 0 0 0 {side!r}" '
                'Properties=species:S:1:pos:R:3:velo:R:3:radius:R:1:mass:R:1 Time=0 pbc="T T T"\n')
        for s, p, v, r, m in balls:
            f.write(" ".join([s] + [repr(x) for x in p + v] + [repr(r), repr(m)]) + "\n")
    e0, p0 = energy_and_momentum(balls)

    out, frames_file, series, report = (os.path.join(a.work, name) for name in ("end.xyz", "frames.xyz", "series.csv", "end.json"))
    run(a.program, "--read", start, "--events", "20000", "--equilibrate", "2000", "--blocks", "8", "--write", out,
        "--snapshots", frames_file, "--snapshot-every", "0.5", "--series", series, "--json", report)
    ((time, end_side, end),) = read_frames(out)
    check(end_side == side, f"the box's side {end_side}, expected {side}")
    check(len(end) == len(balls), f"{len(end)} balls written, expected {len(balls)}")
    check(all(e[0] == b[0] and e[3] == b[3] and e[4] == b[4] for e, b in zip(end, balls)),
          "a ball's species, radius or mass changed, or the order did")
    check(all(0 <= x < side for e in end for x in e[1]), "a position outside [0, side)")
    check(end[0][1] != balls[0][1], "ball 0 did not move")
    e1, p1 = energy_and_momentum(end)
    check(abs(e1 - e0) <= 1e-12 * e0, f"kinetic energy {e1}, expected {e0}")
    check(all(abs(x - y) <= 1e-11 for x, y in zip(p1, p0)), f"momentum {p1}, expected {p0}")
    c = closest(end, side)
    check(c > 1 - 1e-9, f"the closest pair is {c} of its contact distance apart")
    r = json.load(open(report))
    eta = sum(4 / 3 * math.pi * b[3] ** 3 for b in balls) / side ** 3
    check(r["balls"] == 256 and abs(r["packing_fraction"] - eta) < 1e-12, f"JSON balls {r['balls']}, η {r['packing_fraction']}")
    check(r["collisions"] == 20000 and r["largest_overlap"] < 1e-9, "JSON collisions or overlap")
    check(r["equation_of_state"] is not None and 3 < r["equation_of_state"] < 4, f"BMCSL {r['equation_of_state']}")
    rows = open(series).read().split("\n")
    check(rows[0].startswith("time,collisions,compressibility_factor,pressure,temperature,mean_squared_displacement"),
          f"series header {rows[0]}")
    check(len([x for x in rows[1:] if x]) == 8, "series: expected 8 rows")
    frames = read_frames(frames_file)
    check(len(frames) == math.floor(r["time"] / 0.5) + 1, f"{len(frames)} frames over a span of {r['time']}")
    check(all(abs(f[0] - frames[0][0] - 0.5 * k) < 1e-9 for k, f in enumerate(frames)), "frames not 0.5 apart")
    check(all(len(f[2]) == 256 and [b[0] for b in f[2]] == [b[0] for b in balls] for f in frames), "a frame's balls")
    check(abs(frames[0][0] - (time - r["time"])) < 1e-9, f"the first frame at {frames[0][0]}, expected the span's start")

    # Read again, run on, written as .sph (type, position, radius) and read back once more.
    sph = os.path.join(a.work, "again.sph")
    run(a.program, "--read", out, "--events", "5000", "--equilibrate", "0", "--write", sph)
    lines = open(sph).read().split("\n")
    check(lines[0] == "256", f".sph count {lines[0]}")
    typed = [line.split() for line in lines[2:258]]
    check([t[0] for t in typed] == [b[0] for b in balls], ".sph types differ from the species read")
    check([float(t[4]) for t in typed] == [b[3] for b in balls], ".sph radii differ from those read")
    run(a.program, "--read", sph, "--events", "5000", "--equilibrate", "0", "--write", os.path.join(a.work, "last.xyz"))
    ((_, _, last),) = read_frames(os.path.join(a.work, "last.xyz"))
    check([b[3] for b in last] == [b[3] for b in balls], "radii after the .sph round trip")
    check(closest(last, side) > 1 - 1e-9, "an overlap after the .sph round trip")
    if failures:
        print("\n".join(failures))
        sys.exit(1)
    print(f"{len(balls)} balls: read, run, written and read again (.xyz, .sph, .xyz); {len(frames)} frames")


if __name__ == "__main__":
    main()
