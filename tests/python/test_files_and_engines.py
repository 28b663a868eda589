"""The table, the gas and the file formats from Python: hand-computed event times, conservation laws,
the JSON Schema and the C++ program's files byte for byte, and exact round trips."""

import json
import subprocess
from pathlib import Path

import numpy as np
import pytest

import billiards

SOURCE = Path(__file__).resolve().parents[2]


def test_the_tables_event_times_are_the_hand_computed_ones():
    R = 0.028575
    table = billiards.Table([[0.6, 0.635], [1.9, 0.635]], [[2.0, 0.0], [0.0, 0.0]], radius=R)
    count, events = table.run_until(3.0, events=True)
    # Equal masses head on: ball 0 stops, ball 1 leaves at 2 m/s for the right cushion (x = 2.54 − R),
    # comes back and meets ball 0 again.
    meet = (1.9 - 0.6 - 2 * R) / 2
    cushion = meet + (2.54 - R - (1.9 - 0.0)) / 2
    assert count == len(events) >= 2
    assert events[0]["kind"] == "ball" and events[0]["time"] == pytest.approx(meet, rel=1e-12)
    assert events[1]["kind"] == "cushion" and events[1]["second"] == 1
    assert events[1]["time"] == pytest.approx(cushion, rel=1e-12)
    assert table.energy == pytest.approx(0.5 * 0.17 * 4.0, rel=1e-12) and table.time == 3.0


def test_the_gas_conserves_energy_and_momentum_and_meets_carnahan_starling():
    gas = billiards.Gas.lattice(3, 500, 0.3, seed=3)
    energy = gas.energy
    momentum = (gas.masses[:, None] * gas.velocities).sum(axis=0)
    gas.run_events(20000)
    gas.reset_measurements()
    done, events = gas.run_events(40000, events=True)
    assert done == 40000 and np.all(np.diff(events["time"]) >= 0) and np.all(events["first"] != events["second"])
    assert gas.energy == pytest.approx(energy, rel=1e-10)
    assert np.allclose((gas.masses[:, None] * gas.velocities).sum(axis=0), momentum, atol=1e-9)
    eta = 0.3
    carnahan_starling = (1 + eta + eta**2 - eta**3) / (1 - eta) ** 3
    assert gas.measured()["compressibility_factor"] == pytest.approx(carnahan_starling, rel=0.03)


@pytest.mark.parametrize("dimension,balls", [(3, 500), (2, 400)])
def test_the_gas_is_billiards_gas_bit_for_bit(gas_program, tmp_path, dimension, balls):
    out = tmp_path / "end.xyz"
    subprocess.run([gas_program, "--dimension", str(dimension), "--balls", str(balls), "--packing-fraction", "0.3",
                    "--seed", "3", "--equilibrate", "0", "--events", "5000", "--write", str(out), "--json",
                    str(tmp_path / "gas.json")], check=True, capture_output=True)
    gas = billiards.Gas.lattice(dimension, balls, 0.3, seed=3)
    gas.run_events(5000)
    end = billiards.read_snapshot(out)
    assert end.time == gas.time
    assert np.array_equal(end.position[:, :dimension], gas.positions)
    assert np.array_equal(end.velocity[:, :dimension], gas.velocities)


def test_a_gas_of_your_own_in_two_dimensions():
    rng = np.random.default_rng(1)
    grid = np.stack(np.meshgrid(np.arange(10), np.arange(10)), -1).reshape(-1, 2) * 2.0 + 1.0
    gas = billiards.Gas(grid, rng.normal(size=(100, 2)), side=20.0, radii=np.full(100, 0.5), masses=np.ones(100))
    assert gas.step()["kind"] == "ball" and gas.collisions == 1


def test_the_events_json_is_the_programs_byte_for_byte_and_meets_its_schema(shot_program, tmp_path):
    jsonschema = pytest.importorskip("jsonschema")
    program_file = tmp_path / "program.json"
    subprocess.run([shot_program, "--table", "9ft", "--rack", "9ball", "--jitter", "0.001", "--seed", "3", "--speed",
                    "6", "--json", str(program_file)], check=True, capture_output=True)
    table = billiards.pool_table("9ft")
    shot = billiards.Shot(table, None, billiards.rack(table, None, "9ball", 0.001, 3))
    shot.strike(0, billiards.Cue(6.0))
    shot.play()
    ours = tmp_path / "python.json"
    shot.write_json(ours)
    assert ours.read_bytes() == program_file.read_bytes()
    jsonschema.validate(json.loads(ours.read_text()), json.loads((SOURCE / "docs" / "events.schema.json").read_text()))


def test_the_pictures_and_the_trajectories(tmp_path):
    table = billiards.pool_table("7ft")
    shot = billiards.Shot(table, None, billiards.rack(table, None, "8ball", 0.001, 2))
    shot.strike(0, billiards.Cue(7.0))
    shot.play()
    shot.write_svg(tmp_path / "shot.svg", title="a <break> & more")
    svg = (tmp_path / "shot.svg").read_text()
    assert "<svg" in svg and "a &lt;break" in svg and "&amp; more" in svg and "<break" not in svg
    shot.write_html(tmp_path / "shot.html")
    assert 'id="ball-15"' in (tmp_path / "shot.html").read_text()
    shot.write_trajectories(tmp_path / "t.csv", rate=20)
    lines = (tmp_path / "t.csv").read_text().splitlines()
    times, positions = shot.trajectories(20)
    assert len(lines) == 1 + len(times) * 16 and times[-1] == shot.time
    row = lines[1 + 16 * 7 + 5].split(",")  # the eighth sample, ball 5
    assert float(row[0]) == times[7] and [float(row[2]), float(row[3])] == positions[7, 5, :2].tolist()
    with pytest.raises(OSError, match="nowhere"):
        shot.write_json(tmp_path / "nowhere" / "x.json")


def test_setup_files_round_trip_exactly(tmp_path):
    table = billiards.pool_table("8ft")
    layout = billiards.scatter(table, None, 12, seed=9)
    layout["velocity"][3, :2] = [0.1, -1 / 3]
    layout["angular_velocity"][4] = [1e-300, 2.5, -7 / 3]
    path = tmp_path / "layout.setup"
    billiards.write_shot_setup(path, layout, "8ft")
    named, read = billiards.read_shot_setup(path)
    assert named == table and np.array_equal(read.view(np.uint8), layout.view(np.uint8))
    (tmp_path / "bad.setup").write_text("table 8ft\nball 1.0\n")
    with pytest.raises(ValueError, match=r"bad.setup:2: ball"):
        billiards.read_shot_setup(tmp_path / "bad.setup")


def test_snapshots_round_trip_exactly(tmp_path):
    gas = billiards.Gas.lattice(3, 108, 0.2, seed=4)
    gas.run_events(500)
    snapshot = billiards.gas_snapshot(gas)
    for name in ("gas.sph", "gas.xyz"):
        billiards.write_snapshot(tmp_path / name, snapshot)
        back = billiards.read_snapshot(tmp_path / name)
        assert np.array_equal(back.position, snapshot.position) and back.dimension == 3
    again = billiards.gas_from_snapshot(billiards.read_snapshot(tmp_path / "gas.xyz"))
    assert np.array_equal(again.velocities, gas.velocities) and np.array_equal(again.positions, gas.positions)
    flat = billiards.gas_snapshot(billiards.Gas.lattice(2, 100, 0.3))
    with pytest.raises(ValueError, match="extended XYZ"):
        billiards.write_snapshot(tmp_path / "disks.sph", flat)
