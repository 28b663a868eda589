"""The games from Python: the rules' verdicts on shots the engine plays, and the environment played to the
end by a random player (every game ends, every state valid, every shot within the engine's invariants)."""

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
            state, verdict = env._state, info["verdict"]
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
