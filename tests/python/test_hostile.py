"""Hostile input: every public call raises ValueError or TypeError naming what is wrong, never crashes."""

import numpy as np
import pytest

import billiards

Z3 = np.zeros(3)
X3 = np.array([1.0, 0.0, 0.0])

CALLS = {
    "collide": lambda **k: billiards.collide(**{**dict(m1=1.0, v1=X3, m2=1.0, v2=Z3, n=X3), **k}),
    "time_of_impact": lambda **k: billiards.time_of_impact(**{**dict(p1=Z3, v1=X3, p2=3 * X3, v2=Z3, distance=1.0), **k}),
    "collide_with_friction": lambda **k: billiards.collide_with_friction(
        **{**dict(m1=1.0, radius1=0.03, v1=X3, w1=Z3, m2=1.0, radius2=0.03, v2=Z3, w2=Z3, n=X3, restitution=0.9,
                  friction=0.1), **k}),
    "strike": lambda **k: billiards.strike(**{**dict(mass=0.17, radius=0.028575, velocity=Z3, angular_velocity=Z3,
                                                     speed=2.0), **k}),
    "collide_with_cushion": lambda **k: billiards.collide_with_cushion(
        **{**dict(mass=0.17, radius=0.028575, velocity=X3, angular_velocity=Z3, normal=X3, height=0.03629), **k}),
    "evolve": lambda **k: billiards.evolve(**{**dict(position=[0.5, 0.5, 0.028575], velocity=X3, angular_velocity=Z3,
                                                     radius=0.028575, t=1.0), **k}),
}
VECTORS = {"collide": "v1", "time_of_impact": "p1", "collide_with_friction": "w1", "strike": "velocity",
           "collide_with_cushion": "angular_velocity", "evolve": "angular_velocity"}
SCALARS = {"collide": "m1", "time_of_impact": "distance", "collide_with_friction": "friction", "strike": "speed",
           "collide_with_cushion": "height", "evolve": "t"}


@pytest.mark.parametrize("name", CALLS)
def test_the_calls_run_on_good_input(name):
    CALLS[name]()


@pytest.mark.parametrize("name", CALLS)
@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_nan_and_infinity_are_named(name, bad):
    vector = np.array([bad, 0.0, 0.0])
    with pytest.raises(ValueError, match=rf"{name}: {VECTORS[name]} is"):
        CALLS[name](**{VECTORS[name]: vector})
    batch = np.zeros((5, 3))
    batch[3, 0] = bad
    with pytest.raises(ValueError, match=r"at flat index 3"):
        CALLS[name](**{VECTORS[name]: batch + (X3 if VECTORS[name] in ("p1", "v1", "velocity") else 0)})


@pytest.mark.parametrize("name", CALLS)
def test_wrong_shapes_are_named(name):
    with pytest.raises(ValueError, match=VECTORS[name]):
        CALLS[name](**{VECTORS[name]: np.zeros(4)})
    with pytest.raises(ValueError, match="broadcast"):
        CALLS[name](**{VECTORS[name]: np.zeros((4, 3)), SCALARS[name]: np.ones(5)})


@pytest.mark.parametrize("name", CALLS)
@pytest.mark.parametrize("dtype", [np.int64, np.complex128, np.float16, object, np.bool_])
def test_wrong_dtypes_are_type_errors(name, dtype):
    with pytest.raises(TypeError, match=VECTORS[name]):
        CALLS[name](**{VECTORS[name]: np.zeros(3, dtype=dtype)})


@pytest.mark.parametrize("name", CALLS)
def test_mixed_float_dtypes_are_refused(name):
    with pytest.raises(TypeError, match="dtypes differ"):
        CALLS[name](**{VECTORS[name]: np.zeros(3, np.float32)})


@pytest.mark.parametrize("name", CALLS)
def test_strings_and_none_are_type_errors(name):
    for value in ("1.0", None, {"x": 1}):
        with pytest.raises(TypeError):
            CALLS[name](**{SCALARS[name]: value})


@pytest.mark.parametrize("name", CALLS)
def test_empty_batches_give_empty_results(name):
    out = CALLS[name](**{VECTORS[name]: np.zeros((0, 3))})
    for a in out if isinstance(out, tuple) else (out,):
        assert a.shape[0] == 0


def test_huge_counts_fail_cleanly():
    # 2^59 cases broadcast from one vector: the copy the loop needs cannot be made.
    with pytest.raises((MemoryError, ValueError)):
        billiards.collide(1.0, np.broadcast_to(X3, (2**59, 3)), 1.0, Z3, X3)
    with pytest.raises(ValueError, match="samples"):
        table = billiards.pool_table("9ft")
        shot = billiards.Shot(table, None, billiards.rack(table))
        shot.trajectories(1e300, until=1.0)


def test_earliest_contact_refuses_bad_coefficients():
    with pytest.raises(ValueError, match=r"c\[1\]"):
        billiards.earliest_contact([1.0, np.nan, 1.0], 1.0)
    with pytest.raises(ValueError, match="horizon"):
        billiards.earliest_contact([1.0, 0.0, 1.0], -1.0)
    with pytest.raises(ValueError, match="coefficients"):
        billiards.earliest_contact([1.0, 0.0, 1.0, 2.0], 1.0)


def test_the_engine_refuses_bad_layouts():
    table = billiards.pool_table("9ft")
    physics = billiards.PoolPhysics()
    good = billiards.rack(table, physics)
    with pytest.raises(TypeError, match="ball_dtype"):
        billiards.Shot(table, physics, np.zeros((10, 3)))
    overlapping = good.copy()
    overlapping[1]["position"] = overlapping[2]["position"]
    with pytest.raises(ValueError, match="ball"):
        billiards.Shot(table, physics, overlapping)
    off = good.copy()
    off[3]["position"][0] = -1.0
    with pytest.raises(ValueError, match="ball 3"):
        billiards.Shot(table, physics, off)
    fast = good.copy()
    fast[5]["velocity"][0] = 1e300
    with pytest.raises(ValueError, match="ball 5"):
        billiards.Shot(table, physics, fast)
    nan = good.copy()
    nan[2]["angular_velocity"][1] = np.nan
    with pytest.raises(ValueError, match="ball 2"):
        billiards.Shot(table, physics, nan)
    with pytest.raises(TypeError, match="table"):
        billiards.Shot("9ft", physics, good)


def test_the_engine_refuses_bad_arguments():
    table = billiards.pool_table("9ft")
    shot = billiards.Shot(table, None, billiards.rack(table))
    with pytest.raises(ValueError, match="ball is 10"):
        shot.strike(10, billiards.Cue(1.0))
    with pytest.raises(TypeError, match="cue"):
        shot.strike(0, 3.0)
    with pytest.raises(ValueError, match="speed"):
        shot.strike(0, billiards.Cue(np.nan))
    with pytest.raises(ValueError, match="up_offset"):
        shot.strike(0, billiards.Cue(1.0, up_offset=1.0))
    with pytest.raises(ValueError, match="until"):
        shot.run_until(np.inf)
    with pytest.raises(ValueError, match="count"):
        shot.run_events(-1)
    with pytest.raises(ValueError, match="rate"):
        shot.trajectories(0)
    with pytest.raises(ValueError, match="7ft, 8ft or 9ft"):
        billiards.pool_table("10ft")
    with pytest.raises(ValueError, match="kind"):
        billiards.rack(table, None, "10ball")
    with pytest.raises(ValueError, match="too short"):
        billiards.rack(billiards.pool_table("7ft"), None, "snooker")
    with pytest.raises(ValueError, match="expected 7ft, 8ft, 9ft, snooker or carom"):
        billiards.table_preset("billiard")
    with pytest.raises(TypeError, match="name"):
        billiards.physics_preset(9)
    with pytest.raises(ValueError, match="jitter"):
        billiards.rack(table, None, "9ball", jitter=np.nan)
    with pytest.raises(ValueError, match="count"):
        billiards.scatter(table, None, 17)
    with pytest.raises(ValueError, match="seed"):
        billiards.rack(table, None, "9ball", 0.1, -1)


def test_the_batch_refuses_bad_arguments():
    table = billiards.pool_table("9ft")
    layouts = np.stack([billiards.rack(table)] * 3)
    with pytest.raises(ValueError, match="counts differ"):
        billiards.play_shots(table, None, layouts, billiards.cues(speed=np.ones(4)))
    with pytest.raises(ValueError, match="threads"):
        billiards.play_shots(table, None, layouts, billiards.Cue(1.0), threads=0)
    with pytest.raises(ValueError, match="struck"):
        billiards.play_shots(table, None, layouts, billiards.Cue(1.0), struck=10)
    with pytest.raises(TypeError, match="cues"):
        billiards.play_shots(table, None, layouts, [1.0, 2.0, 3.0])
    empty = billiards.play_shots(table, None, layouts[:0], billiards.cues(speed=np.ones(0)))
    assert empty.balls.shape == (0, 10)


def test_the_table_and_the_gas_refuse_bad_balls():
    with pytest.raises(ValueError, match="ball 1"):
        billiards.Table([[0.5, 0.5], [np.nan, 0.5]], [[0.0, 0.0], [0.0, 0.0]])
    with pytest.raises(ValueError, match="expected \\(N, 2\\)"):
        billiards.Table(np.zeros((3, 3)))
    with pytest.raises(TypeError, match="float64"):
        billiards.Table(np.zeros((2, 2), np.float32))
    with pytest.raises(ValueError, match="velocity"):
        billiards.Gas(np.zeros((4, 3)), np.zeros((5, 3)), side=10.0)
    with pytest.raises(ValueError):
        billiards.Gas([[0.0, 0.0, 0.0], [0.1, 0.0, 0.0]], np.zeros((2, 3)), side=10.0)  # overlapping
    with pytest.raises(ValueError, match="dimension"):
        billiards.Gas.lattice(4)
    gas = billiards.Gas.lattice(2, 64, 0.2)
    with pytest.raises(ValueError, match="until"):
        gas.run_until(np.nan)
    with pytest.raises(ValueError, match="count"):
        gas.run_events(-5)


def test_the_files_refuse_bad_paths_and_contents(tmp_path):
    with pytest.raises(ValueError, match="cannot open"):
        billiards.read_shot_setup(tmp_path / "missing.setup")
    with pytest.raises(TypeError, match="path"):
        billiards.read_snapshot(42)
    (tmp_path / "truncated.sph").write_text("3\n10 10 10\na 1 1 1 0.5\n")
    with pytest.raises(ValueError, match="truncated.sph"):
        billiards.read_snapshot(tmp_path / "truncated.sph")
    with pytest.raises(OSError):
        billiards.write_text(tmp_path, "a folder")


def test_evolve_names_a_ball_off_the_table():
    with pytest.raises(ValueError, match="evolve: position is .*on the table"):
        billiards.evolve([0.5, 0.5, 1.0], X3, Z3, 0.028575, 1.0)
    with pytest.raises(ValueError, match="evolve: t is"):
        billiards.evolve([0.5, 0.5, 0.028575], X3, Z3, 0.028575, -1.0)
    with pytest.raises(TypeError, match="cloth"):
        billiards.evolve([0.5, 0.5, 0.028575], X3, Z3, 0.028575, 1.0, cloth=0.2)
