"""The shot engine from Python: the same events as the C++ program bit for bit, and the engine's laws."""

import json
import subprocess

import numpy as np
import pytest

import billiards


def play_program(shot_program, tmp_path, *args):
    out = tmp_path / "events.json"
    subprocess.run([shot_program, *args, "--json", str(out)], check=True, capture_output=True)
    return json.loads(out.read_text())


@pytest.mark.parametrize("rack,seed,speed,offset", [("9ball", 3, 6.0, (0.0, 0.0)), ("8ball", 11, 8.0, (0.2, -0.3))])
def test_a_break_equals_billiards_shot_bit_for_bit(shot_program, tmp_path, rack, seed, speed, offset):
    expected = play_program(shot_program, tmp_path, "--table", "9ft", "--rack", rack, "--jitter", "0.001", "--seed",
                            str(seed), "--speed", str(speed), "--offset", f"{offset[0]},{offset[1]}")
    table = billiards.pool_table("9ft")
    shot = billiards.Shot(table, billiards.PoolPhysics(), billiards.rack(table, None, rack, 0.001, seed))
    shot.strike(0, billiards.Cue(speed, side_offset=offset[0], up_offset=offset[1]))
    shot.play()
    events = shot.events
    assert len(events) == len(expected["events"])
    for got, want in zip(events, expected["events"]):
        assert got["time"] == want["time"] and got["kind"] == want["kind"]
        assert got["from"] == want["from"] and got["to"] == want["to"]
        assert got["first"] == want["balls"][0]
        state = want["states"][0]
        assert got["first_after"]["position"][:2].tolist() == state["position"]
        assert got["first_after"]["velocity"][:2].tolist() == state["velocity"]
        assert got["first_after"]["angular_velocity"].tolist() == state["angular_velocity"]
    final = shot.balls
    for want in expected["final"]:
        assert final[want["ball"]]["position"][:2].tolist() == want["position"]
    assert shot.time == expected["time"]
    assert sorted(np.flatnonzero(final["pocketed"]).tolist()) == sorted(expected["pocketed"])


def test_a_shot_keeps_the_engines_invariants():
    table = billiards.pool_table("7ft")
    physics = billiards.PoolPhysics()
    shot = billiards.Shot(table, physics, billiards.rack(table, physics, "8ball", 0.001, 5),
                          billiards.ShotOptions(check_invariants=True))
    shot.strike(0, billiards.Cue(7.0, azimuth=0.01))
    energies = [shot.energy]
    while (event := shot.step()) is not None:
        assert event.dtype == billiards.event_dtype
        energies.append(shot.energy)
    assert np.all(np.diff(energies) <= 1e-12 * max(energies))
    assert shot.energy == 0
    balls = shot.balls
    live = balls[~balls["pocketed"]]["position"][:, :2]
    gaps = np.linalg.norm(live[:, None] - live[None], axis=-1) + np.eye(len(live)) * 1
    assert gaps.min() >= 2 * physics.radius * (1 - 1e-9)
    assert np.all((live[:, 0] >= physics.radius * (1 - 1e-9)) & (live[:, 0] <= table.length - physics.radius * (1 - 1e-9)))


def test_run_until_and_trajectories_follow_the_shot():
    table = billiards.pool_table("9ft")
    shot = billiards.Shot(table, None, billiards.rack(table, None, "9ball", 0.001, 1))
    shot.strike(0, billiards.Cue(5.0))
    ran = shot.run_until(0.5)
    assert shot.time == 0.5 and ran == shot.event_count - 1
    early = shot.balls
    shot.play()
    assert np.array_equal(shot.balls_at(0.5)["position"], early["position"])
    times, positions = shot.trajectories(50)
    assert positions.shape == (len(times), 10, 3) and times[0] == 0 and times[-1] <= shot.time
    assert np.array_equal(positions[0], shot.placed["position"])
    assert np.array_equal(positions[25], shot.balls_at(times[25])["position"])
    with pytest.raises(ValueError, match="until"):
        shot.run_until(0.1)


def test_the_cue_maps_from_pooltools():
    cue = billiards.Cue.from_pooltool(V0=2.0, phi=90.0, theta=10.0, a=0.1, b=-0.2)
    assert cue.speed == 2.0 and cue.azimuth == pytest.approx(np.pi / 2) and cue.elevation == pytest.approx(np.pi / 18)
    assert (cue.side_offset, cue.up_offset, cue.mass) == (0.1, -0.2, 0.567)


def test_balls_from_arrays_make_a_layout():
    layout = billiards.balls([[0.5, 0.5], [1.0, 0.5]], velocity=[[1.0, 0, 0], [0, 0, 0]])
    shot = billiards.Shot(billiards.pool_table("9ft"), None, layout)
    shot.play()
    assert shot.event_count > 1 and shot.balls["position"][0, 2] == billiards.PoolPhysics().radius
