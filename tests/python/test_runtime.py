"""The runtime's calls on arrays: bit for bit the C++ checked calls, and against independent formulas."""

import numpy as np
import pytest

import billiards


def unit(rng, shape, d):
    n = rng.normal(size=shape + (d,))
    return n / np.linalg.norm(n, axis=-1, keepdims=True)


def bits(a):
    return np.ascontiguousarray(a).view(np.uint8 if a.dtype == np.float64 else np.uint8)


@pytest.mark.parametrize("d", [2, 3])
@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_collide_equals_the_cpp_call_bit_for_bit(runtime_reference, rng, d, dtype):
    count = 300
    m1, m2 = rng.uniform(0.1, 5, count).astype(dtype), rng.uniform(0.1, 5, count).astype(dtype)
    m2[:10] = m1[:10]  # equal masses: the exact exchange
    v1, v2 = rng.normal(size=(count, d)).astype(dtype), rng.normal(size=(count, d)).astype(dtype)
    n = unit(rng, (count,), d).astype(dtype)
    e = rng.uniform(0, 1, count).astype(dtype)
    e[:20] = 1
    x1, x2 = billiards.collide(m1, v1, m2, v2, n, e)
    assert x1.dtype == dtype and x1.shape == (count, d)
    cases = np.column_stack([m1, v1, m2, v2, n, e]).astype(np.float64)
    expected = runtime_reference(f"collide{d}", cases, "float" if dtype == np.float32 else "double")
    got = np.column_stack([x1, x2]).astype(np.float64)
    assert np.array_equal(got.view(np.uint64), np.asarray(expected).view(np.uint64))


def test_collide_is_the_papers_formula(rng):
    count = 1000
    m1, m2 = rng.uniform(0.1, 5, count), rng.uniform(0.1, 5, count)
    v1, v2, n = rng.normal(size=(count, 3)), rng.normal(size=(count, 3)), unit(rng, (count,), 3)
    x1, x2 = billiards.collide(m1, v1, m2, v2, n)
    along = np.sum((v2 - v1) * n, axis=-1)
    paper1 = v1 + (2 * m2 / (m1 + m2) * along)[:, None] * n
    paper2 = v2 - (2 * m1 / (m1 + m2) * along)[:, None] * n
    assert np.allclose(x1, paper1, rtol=1e-13, atol=1e-13) and np.allclose(x2, paper2, rtol=1e-13, atol=1e-13)
    # Momentum and energy conserved.
    assert np.allclose(m1[:, None] * x1 + m2[:, None] * x2, m1[:, None] * v1 + m2[:, None] * v2, atol=1e-12)
    energy = lambda a, b: m1 * np.sum(a * a, -1) + m2 * np.sum(b * b, -1)
    assert np.allclose(energy(x1, x2), energy(v1, v2), rtol=1e-12)


def test_collide_broadcasts_and_keeps_one_case_a_vector():
    x1, x2 = billiards.collide(1.0, [1.0, 0.0], 1.0, [0.0, 0.0], [1.0, 0.0])
    assert x1.shape == (2,) and x1.tolist() == [0.0, 0.0] and x2.tolist() == [1.0, 0.0]
    v1 = np.zeros((4, 5, 3))
    v1[..., 0] = 1
    x1, x2 = billiards.collide(np.ones(5), v1, 1.0, [0.0, 0.0, 0.0], [1.0, 0.0, 0.0])
    assert x1.shape == (4, 5, 3) and np.all(x2[..., 0] == 1)


def test_the_wall_limit_reflects(rng):
    v = rng.normal(size=(50, 3))
    n = unit(rng, (50,), 3)
    x1, x2 = billiards.collide(1.0, v, np.inf, np.zeros(3), n)
    assert np.allclose(x1, v - 2 * np.sum(v * n, -1)[:, None] * n, atol=1e-14)
    assert np.all(x2 == 0)


def test_time_of_impact_equals_the_cpp_call_and_the_quadratic(runtime_reference, rng):
    count = 200
    p1, p2 = rng.normal(size=(count, 3)), rng.normal(size=(count, 3)) + 3
    # Ball 2 heading back towards ball 1, give or take: some meet, some pass.
    v1, v2 = rng.normal(size=(count, 3)), (p1 - p2) + rng.normal(size=(count, 3)) * 2
    d = rng.uniform(0.1, 1, count)
    t = billiards.time_of_impact(p1, v1, p2, v2, d)
    expected = runtime_reference("time_of_impact3", np.column_stack([p1, v1, p2, v2, d]))
    assert np.array_equal(t.view(np.uint64), np.asarray(expected)[:, 0].view(np.uint64))
    # Where finite, the centres are d apart then; the quadratic's earlier root.
    hit = np.isfinite(t)
    assert hit.any() and (~hit).any()
    gap = np.linalg.norm((p2 - p1) + t[:, None] * (v2 - v1), axis=-1)
    assert np.allclose(gap[hit], d[hit], rtol=1e-9)


def test_collide_with_friction_equals_the_cpp_call_and_conserves_momentum(runtime_reference, rng):
    count = 200
    m1, m2, r1, r2 = (rng.uniform(0.1, 1, count) for _ in range(4))
    v1, v2, w1, w2 = (rng.normal(size=(count, 3)) for _ in range(4))
    n = unit(rng, (count,), 3)
    e, mu = rng.uniform(0, 1, count), rng.uniform(0, 0.5, count)
    out = billiards.collide_with_friction(m1, r1, v1, w1, m2, r2, v2, w2, n, e, mu)
    cases = np.column_stack([m1, r1, v1, w1, m2, r2, v2, w2, n, e, mu])
    expected = np.asarray(runtime_reference("collide_with_friction", cases))
    assert np.array_equal(np.column_stack(out).view(np.uint64), expected.view(np.uint64))
    a1, b1, a2, b2 = out
    assert np.allclose(m1[:, None] * a1 + m2[:, None] * a2, m1[:, None] * v1 + m2[:, None] * v2, atol=1e-12)


def test_strike_equals_the_cpp_call_and_the_impulse_equations(runtime_reference, rng):
    count = 200
    mass, radius = np.full(count, 0.17), np.full(count, 0.028575)
    speed = rng.uniform(0.5, 8, count)
    azimuth = rng.uniform(-np.pi, np.pi, count)
    a, b = rng.uniform(-0.5, 0.5, count), rng.uniform(-0.5, 0.5, count)
    zeros = np.zeros((count, 3))
    v, w = billiards.strike(mass, radius, zeros, zeros, speed, azimuth, 0.0, a, b)
    cases = np.column_stack([mass, radius, zeros, zeros, np.full(count, 0.567), speed, azimuth, np.zeros(count), a, b,
                             np.ones(count)])
    expected = np.asarray(runtime_reference("strike", cases))
    assert np.array_equal(np.column_stack([v, w]).view(np.uint64), expected.view(np.uint64))
    # TP A-30, level cue, ball at rest: |v| = 2V / (1 + m/M + 5 (a² + b²)/2), along the cue.
    speed_after = 2 * speed / (1 + 0.17 / 0.567 + 2.5 * (a * a + b * b))
    assert np.allclose(np.linalg.norm(v, axis=-1), speed_after, rtol=1e-12)
    assert np.allclose(v[:, 0], speed_after * np.cos(azimuth), atol=1e-12)


def test_collide_with_cushion_equals_the_cpp_call(runtime_reference, rng):
    count = 200
    mass, radius = np.full(count, 0.17), np.full(count, 0.028575)
    v = rng.normal(size=(count, 3))
    v[:, 2] = 0
    w = rng.normal(size=(count, 3)) * 20
    normal = np.zeros((count, 3))
    normal[:, 0] = 1
    out = billiards.collide_with_cushion(mass, radius, v, w, normal, 0.03629, 0.85, 0.2)
    cases = np.column_stack([mass, radius, v, w, normal, np.full(count, 0.03629), np.full(count, 0.85),
                             np.full(count, 0.2)])
    expected = np.asarray(runtime_reference("collide_with_cushion", cases))
    assert np.array_equal(np.column_stack(out).view(np.uint64), expected.view(np.uint64))
    away = v[:, 0] <= 0  # not moving into the cushion: unchanged
    assert np.array_equal(out[0][away], v[away]) and np.array_equal(out[1][away], w[away])


def test_earliest_contact_equals_the_cpp_call_and_the_roots(runtime_reference, rng):
    count = 300
    # (t − r1)(t − r2)(t² + 1): roots r1 < r2 placed at random, some beyond the horizon.
    r1, r2 = rng.uniform(0.1, 3, count), rng.uniform(3, 6, count)
    c = np.column_stack([r1 * r2, -(r1 + r2), r1 * r2 + 1, -(r1 + r2), np.ones(count)])
    horizon = rng.uniform(0, 4, count)
    t = billiards.earliest_contact(c, horizon)
    expected = runtime_reference("earliest_contact5", np.column_stack([c, horizon]))
    assert np.array_equal(t.view(np.uint64), np.asarray(expected)[:, 0].view(np.uint64))
    inside = r1 < horizon * (1 - 1e-9)
    assert np.allclose(t[inside], r1[inside], rtol=1e-12)
    assert np.all(np.isinf(t[r1 > horizon * (1 + 1e-9)]))


def test_evolve_equals_the_cpp_call_and_the_closed_forms(runtime_reference, rng):
    count, R = 300, 0.028575
    position = np.column_stack([rng.uniform(0, 2, count), rng.uniform(0, 1, count), np.full(count, R)])
    velocity = np.column_stack([rng.normal(size=(count, 2)), np.zeros(count)])
    spin = rng.normal(size=(count, 3)) * 30
    t = rng.uniform(0, 20, count)
    cloth = billiards.Cloth()
    p, v, w = billiards.evolve(position, velocity, spin, R, t)
    cases = np.column_stack([position, velocity, spin, np.full(count, R), t,
                             np.tile([cloth.sliding_friction, cloth.rolling_friction, cloth.spinning_friction,
                                      cloth.gravity], (count, 1))])
    expected = np.asarray(runtime_reference("evolve", cases))
    assert np.array_equal(np.column_stack([p, v, w]).view(np.uint64), expected.view(np.uint64))
    # A ball without spin slides for 2|v|/(7 μ_s g), decelerating at μ_s g, then rolls at 5/7 of its speed.
    speed = np.linalg.norm(velocity, axis=-1)
    slide = 2 * speed / (7 * cloth.sliding_friction * cloth.gravity)
    zeros = np.zeros((count, 3))
    assert np.allclose(billiards.transition_time(position, velocity, zeros, R), slide, rtol=1e-14)
    assert set(billiards.motion(position, velocity, zeros, R).tolist()) == {"sliding"}
    half = slide / 2
    p, v, _ = billiards.evolve(position, velocity, zeros, R, half)
    direction = velocity / speed[:, None]
    travelled = speed * half - 0.5 * cloth.sliding_friction * cloth.gravity * half**2
    assert np.allclose(p, position + travelled[:, None] * direction, rtol=1e-13, atol=1e-15)
    _, v, _ = billiards.evolve(position, velocity, zeros, R, slide)
    assert np.allclose(np.linalg.norm(v, axis=-1), 5 / 7 * speed, rtol=1e-13)
    assert billiards.motion(position[0], [0.0, 0, 0], [0.0, 0, 1.0], R) == "spinning"


def test_version_is_the_projects():
    import pathlib
    import re
    text = (pathlib.Path(__file__).resolve().parents[2] / "CMakeLists.txt").read_text()
    assert billiards.__version__ == re.search(r"project\(\s*billiards\s+VERSION ([0-9.]+)", text).group(1)


def test_the_stubs_name_every_public_name():
    import ast
    import pathlib
    stubs = pathlib.Path(billiards.__file__).with_name("__init__.pyi")
    tree = ast.parse(stubs.read_text())
    named = set()
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            named.add(node.name)
        elif isinstance(node, ast.AnnAssign):
            named.add(node.target.id)
    public = set(billiards.__all__)
    assert public - named == set()
    assert {n for n in named if not n.startswith("_")} - public <= {"ArrayLike", "FloatArray"}
    for name in public:
        assert getattr(billiards, name).__doc__ or name.isupper() or name.endswith("dtype") or name == "__version__"
