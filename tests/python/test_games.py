"""The games from Python: the rules' verdicts on shots the engine plays, and the environment played to the
end by a random player (every game ends, every state valid, every shot within the engine's invariants)."""

import json
import math

import numpy as np
import pytest

import billiards
import billiards.games as games

R = billiards.PoolPhysics().radius


def played(layout, cue, table=None):
    table = table or billiards.pool_table("9ft")
    shot = billiards.Shot(table, None, layout)
    shot.strike(0, cue)
    shot.play()
    return shot


def test_a_scratch_and_a_pot_decided_on_the_engines_shots():
    table = billiards.pool_table("9ft")
    layout = billiards.balls([[0.5, 0.3]] + [[0.4 + 0.1 * b, 1.0] for b in range(1, 10)])
    layout["pocketed"][2:] = True
    layout["position"][1, :2] = [2.0, 1.0]
    state = games.NineBallState(on_table=[True, True] + [False] * 8, breaking=False)
    verdict, after = games.nine_ball(state, played(layout, billiards.Cue(3.0, azimuth=math.atan2(-0.3, -0.5))))
    assert verdict.fouls == ["no contact", "scratch"] and not verdict.legal
    assert verdict.ball_in_hand == "anywhere" and after.player == 1 and after.fouls_in_a_row == (1, 0)
    corner = np.array([table.length, table.width])
    diagonal = np.array([1.0, 1.0]) / math.sqrt(2)
    layout["position"][1, :2] = corner - 0.2 * diagonal
    layout["position"][0, :2] = corner - 0.7 * diagonal
    verdict, after = games.nine_ball(state, played(layout, billiards.Cue(2.0, azimuth=math.pi / 4, up_offset=-0.4)))
    assert verdict.legal and verdict.potted == [1] and verdict.next_player == 0
    assert not after.on_table[1]


def test_the_rules_refuse_bad_states():
    shot = played(billiards.rack(billiards.pool_table("9ft")), billiards.Cue(8.0))
    with pytest.raises(TypeError, match="state"):
        games.nine_ball(games.EightBallState(), shot)
    with pytest.raises(ValueError, match="the game is over"):
        games.nine_ball(games.NineBallState(over=True), shot)
    with pytest.raises(ValueError, match="player is 3"):
        games.nine_ball(games.NineBallState(player=3), shot)
    with pytest.raises(ValueError, match="on_table has 16 balls, expected 10"):
        games.nine_ball(games.NineBallState(on_table=[True] * 16), shot)


@pytest.mark.parametrize("game,count", [("9ball", 1000), ("8ball", 1000)])
def test_a_random_player_finishes_every_game(game, count):
    env = games.PoolEnv(game, max_shots=400, options=billiards.ShotOptions(check_invariants=True))
    rng = np.random.default_rng(2026)
    balls = 10 if game == "9ball" else 16
    for g in range(count):
        observation, _ = env.reset(seed=g)
        for shots in range(1, 401):
            action = [rng.uniform(0.3, 9), rng.uniform(-np.pi, np.pi), rng.uniform(-0.4, 0.4), rng.uniform(-0.4, 0.4),
                      rng.uniform(0, env.table.length), rng.uniform(0, env.table.width)]
            observation, reward, terminated, truncated, info = env.step(action)
            state, verdict = env.state, info["verdict"]
            # Every object ball is either on the table or down, in the rules and on the cloth alike.
            assert observation["on_table"].shape == (balls,)
            assert list(observation["on_table"][1:]) == list(state.on_table[1:])
            assert np.all(np.isnan(observation["positions"][~observation["on_table"]]))
            assert set(verdict.potted).isdisjoint(b for b in range(balls) if state.on_table[b]) or verdict.respotted
            assert reward in (-1.0, 0.0, 1.0) and (reward != 0) == terminated
            if terminated or truncated:
                break
        assert terminated, f"game {g} did not end in 400 shots"
        assert state.over and state.winner in (0, 1)


def test_the_environment_refuses_bad_actions():
    env = games.PoolEnv("9ball")
    with pytest.raises(RuntimeError, match="reset"):
        env.step([1.0, 0.0, 0.0, 0.0])
    env.reset(seed=1)
    with pytest.raises(ValueError, match="action"):
        env.step([1.0, np.nan, 0.0, 0.0])
    with pytest.raises(ValueError, match="action"):
        env.step([1.0, 0.0])
    with pytest.raises(ValueError, match="up_offset"):
        env.step([1.0, 0.0, 0.0, 1.5])
    with pytest.raises(ValueError, match="game"):
        games.PoolEnv("snooker")


def test_three_cushion_scores_a_bank_into_both_balls():
    # The white banked off three cushions into the red and then the yellow, on a table without a pocket
    # in its way: the rules count the cushions before the second ball.
    table = billiards.pool_table("9ft")
    layout = billiards.balls([[1.0, 0.3], [1.9, 0.9], [1.7, 0.95]])
    state = games.ThreeCushionState(target=1)
    for azimuth in np.linspace(0.2, 1.4, 25):
        shot = played(layout, billiards.Cue(4.0, azimuth=azimuth), table)
        if any(shot.events["kind"] == "pocket"):
            continue
        verdict, after = games.three_cushion(state, shot)
        assert verdict.points in (0, 1) and verdict.legal
        assert after.over == (verdict.points == 1)
        kinds = [(str(e["kind"]), int(e["first"]), int(e["second"])) for e in shot.events]
        hits, cushions, scored = set(), 0, False
        for kind, first, second in kinds:
            if kind in ("cushion", "jaw") and first == 0:
                cushions += 1
            if kind == "ball" and 0 in (first, second):
                hits.add(first + second)
                if len(hits) == 2:
                    scored = cushions >= 3
                    break
        assert scored == (verdict.points == 1)
    with pytest.raises(ValueError, match="the strike of ball 1"):
        games.three_cushion(games.ThreeCushionState(player=1), played(layout, billiards.Cue(1.0)))


def test_a_random_player_finishes_every_snooker_frame():
    env = games.GameEnv("snooker", max_shots=5000, options=billiards.ShotOptions(check_invariants=True))
    rng = np.random.default_rng(2026)
    for g in range(1000):
        observation, _ = env.reset(seed=g)
        scored, black_respots = [0, 0], 0
        for _ in range(5000):
            before = env.state
            observation, reward, terminated, truncated, info = env.step(env.sample_action(rng))
            state, verdict = env.state, info["verdict"]
            shooter = info["shooter"]
            # The scores follow the verdicts: points to the shooter, a foul's penalty to the opponent.
            expected = list(before.scores)
            expected[shooter] += verdict.points
            expected[1 - shooter] += verdict.penalty
            assert list(state.scores) == expected
            assert reward == verdict.points - verdict.penalty
            assert verdict.penalty in (0, 4, 5, 6, 7) and (verdict.penalty > 0) == (not verdict.legal)
            scored[shooter] += verdict.points
            black_respots += int(21 in verdict.respotted and before.on == "sequence" and not before.on_table[20])
            # No ball both potted and on the table, in the rules and on the cloth alike.
            assert list(observation["on_table"][1:]) == list(state.on_table[1:])
            assert all(not state.on_table[b] for b in verdict.potted if b not in verdict.respotted)
            if terminated or truncated:
                break
        assert terminated, f"frame {g} did not end in 5000 shots"
        assert state.over and state.winner in (0, 1) and state.scores[state.winner] > state.scores[1 - state.winner]
        # The 147 ceiling: the pots of both players together, and 7 for each re-spotted black.
        assert sum(scored) <= 147 + 7 * black_respots


def test_a_random_player_finishes_every_three_cushion_game():
    env = games.GameEnv("3cushion", max_shots=3000, target=2, options=billiards.ShotOptions(check_invariants=True))
    rng = np.random.default_rng(2026)
    for g in range(1000):
        observation, _ = env.reset(seed=g)
        for _ in range(3000):
            observation, reward, terminated, truncated, info = env.step(env.sample_action(rng))
            assert reward == info["verdict"].points and observation["on_table"].all()
            assert observation["player"] == (info["shooter"] if reward else 1 - info["shooter"]) or terminated
            if terminated or truncated:
                break
        assert terminated, f"game {g} did not end in 3000 shots"
        assert env.state.scores[env.state.winner] == 2


def test_the_snooker_and_carom_tables_and_their_starting_positions():
    snooker = billiards.table_preset("snooker")
    assert (snooker.length, snooker.width) == (3.569, 1.778) and snooker.has_pockets
    assert snooker == billiards.snooker_table()
    carom = billiards.carom_table()
    assert (carom.length, carom.width, carom.has_pockets) == (2.84, 1.42, False)
    assert billiards.physics_preset("carom").radius == pytest.approx(0.03075)
    with pytest.raises(ValueError, match="expected 7ft, 8ft, 9ft, snooker or carom"):
        billiards.table_preset("billiard")
    layout = billiards.rack(snooker, kind="snooker")
    assert len(layout) == 22
    radius = billiards.physics_preset("snooker").radius
    assert layout["position"][0, 0] <= 0.737 and np.allclose(layout["position"][21, :2], [3.569 - 0.324, 0.889])
    opening = billiards.rack(carom, kind="3cushion")
    assert np.allclose(opening["position"][:, :2], [[0.71, 0.71 + 0.182], [0.71, 0.71], [2.13, 0.71]])
    # The white in hand in the D, wanted on the brown: placed at the nearest free point in the D.
    games.place_cue_ball(layout, layout["position"][18, :2], "in_d", snooker, radius)
    x, y = layout["position"][0, :2]
    assert x <= 0.737 and math.hypot(x - 0.737, y - 0.889) <= 0.292
    assert not games.place(layout, 0, (1.0, 0.9), snooker, radius, "in_d")
    # The pink potted and its spot covered: respotted on the highest free spot (the black's is taken).
    layout["pocketed"][[19, 20]] = True
    assert games.place(layout, 0, layout["position"][20, :2] + [0, 1.5 * radius], snooker, radius)
    games.respot(layout, 20, snooker, radius, "snooker")
    assert np.allclose(layout["position"][20, :2], [3.569 / 2, 0.889]) and not layout["pocketed"][20]
    with pytest.raises(ValueError, match="ball 3 is not a colour, expected 16 to 21"):
        games.respot(layout, 3, snooker, radius, "snooker")


def test_the_snooker_and_carom_tables_in_the_files(tmp_path):
    for name, kind in (("snooker", "snooker"), ("carom", "3cushion")):
        table, physics = billiards.table_preset(name), billiards.physics_preset(name)
        layout = billiards.rack(table, physics, kind)
        billiards.write_shot_setup(tmp_path / f"{name}.setup", layout, name)
        named, read = billiards.read_shot_setup(tmp_path / f"{name}.setup", physics)
        assert named == table and np.array_equal(read["position"], layout["position"])
        shot = billiards.Shot(table, physics, read)
        shot.strike(0, billiards.Cue(3.0, azimuth=0.1))
        shot.play()
        assert json.loads(billiards.shot_json(shot))["table"]["size"] == name
        # The balls in their game's colours: 15 reds and the six colours; the carom's yellow and red.
        svg = billiards.shot_svg(shot)
        finals = [line for line in svg.splitlines() if 'stroke-width="1.5"' in line and "<circle" in line]
        colours = [line.split('fill="')[1][:7] for line in finals]
        assert colours == (["#ffffff"] + ["#d62828"] * 15 + ["#f4d03f", "#1e8449", "#7b4a1e", "#1f4fa3", "#f48fb1",
                                                             "#111111"] if name == "snooker"
                           else ["#ffffff", "#f4d03f", "#d62828"])


def test_snooker_decided_on_the_engines_shots():
    table, physics = billiards.snooker_table(), billiards.physics_preset("snooker")
    layout = billiards.rack(table, physics, "snooker")
    layout["pocketed"][2:16] = True
    corner, diagonal = np.array([table.length, table.width]), np.array([1.0, 1.0]) / math.sqrt(2)
    layout["position"][1, :2] = corner - 0.25 * diagonal
    layout["position"][0, :2] = corner - 0.6 * diagonal
    state = games.SnookerState(on_table=[True, True] + [False] * 14 + [True] * 6, ball_in_hand="none")

    def stroke(cue):
        shot = billiards.Shot(table, physics, layout)
        shot.strike(0, cue)
        shot.play()
        return games.snooker(state, shot)

    verdict, after = stroke(billiards.Cue(2.0, azimuth=math.pi / 4, up_offset=-0.3))
    assert verdict.legal and verdict.points == 1 and after.on == "colour" and after.player == 0
    verdict, after = stroke(billiards.Cue(2.5, azimuth=math.pi / 4, up_offset=0.6))
    assert verdict.fouls == ["scratch"] and verdict.penalty == 4 and after.ball_in_hand == "in_d"
    assert after.scores == (0, 4) and after.player == 1


def test_the_environment_exposes_its_state_layout_and_last_shot():
    env = games.GameEnv("snooker")
    assert env.last_shot() is None
    observation, _ = env.reset(seed=3)
    assert observation["on"] == games.SNOOKER_ON.index("red") and list(observation["scores"]) == [0, 0]
    assert env.state == games.SnookerState()
    # Placed in the D where it is wanted there: the white starts the shot from that point.
    observation, reward, terminated, truncated, info = env.step([3.0, 0.02, 0.0, 0.0, 0.6, 0.8])
    shot = env.last_shot()
    assert np.allclose(shot.placed["position"][0, :2], [0.6, 0.8])
    assert info["events"] == shot.event_count
    verdict, after = games.snooker(games.SnookerState(), shot)
    assert verdict == info["verdict"] and after == env.state
    layout = env.layout
    assert np.array_equal(~layout["pocketed"], observation["on_table"])
    with pytest.raises(ValueError, match="action is 'fast'"):
        env.step("fast")
    with pytest.raises(ValueError, match="target"):
        games.GameEnv("3cushion", target=0)
    with pytest.raises(ValueError, match="game is 'pool'"):
        games.GameEnv("pool")
    with pytest.raises(ValueError, match="expected a carom table"):
        games.GameEnv("3cushion", table="9ft")
    with pytest.raises(ValueError, match="too short"):
        games.GameEnv("snooker", table="7ft")
    with pytest.raises(TypeError, match="table"):
        games.GameEnv("snooker", table=3)
    with pytest.raises(IndexError, match="ball is 99"):
        games.place(layout, 99, (1.0, 1.0), billiards.snooker_table(), 0.02625)
    with pytest.raises(ValueError, match="region"):
        games.place(layout, 0, (1.0, 1.0), billiards.snooker_table(), 0.02625, "the D")


def test_the_random_player_aims_at_a_ball_it_may_meet_first():
    env = games.GameEnv("9ball")
    env.reset(seed=5)
    rng = np.random.default_rng(5)
    for _ in range(50):
        speed, azimuth, side, up, x, y = env.sample_action(rng)
        assert 0.3 <= speed <= 7 and abs(side) <= 0.4 and abs(up) <= 0.4 and x <= env.table.length / 4
        one = env.layout["position"][1, :2]
        towards = math.atan2(one[1] - y, one[0] - x)
        assert abs(math.remainder(azimuth - towards, 2 * math.pi)) < 0.5
    # Snooker's opening stroke: at a red, from the D.
    env = games.GameEnv("snooker")
    env.reset(seed=5)
    for _ in range(50):
        speed, azimuth, side, up, x, y = env.sample_action(rng)
        assert 0.737 - 0.292 <= x <= 0.737
        reds = env.layout["position"][1:16, :2]
        towards = np.arctan2(reds[:, 1] - y, reds[:, 0] - x)
        assert np.min(np.abs(np.remainder(azimuth - towards + np.pi, 2 * np.pi) - np.pi)) < 0.5


def test_every_public_name_of_the_games_is_documented():
    for name in games.__all__:
        value = getattr(games, name)
        assert name.isupper() or value.__doc__, name
    assert {n for n in dir(games) if not n.startswith("_") and callable(getattr(games, n))
            and getattr(getattr(games, n), "__module__", "") == "billiards.games"} <= set(games.__all__)
