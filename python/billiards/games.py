"""The games: the rules of 9-ball and 8-ball (WPA) and of three-cushion (UMB) decided from a shot's
events, and a game environment with the ``reset()`` / ``step(action)`` conventions of Gymnasium (without
depending on it).

Which rules are in and which are left out: docs/games.md. Ball 0 is the cue ball, the object balls are
numbered as in the game (9-ball: 1 to 9; 8-ball: 1 to 15, the solids 1–7, the stripes 9–15).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np

from . import _billiards
from ._shot import Cue, PoolPhysics, PoolTable, Shot, ShotOptions, pool_table, rack

#: Where the next player may place the cue ball: "none", "anywhere", "behind_head_string".
BALL_IN_HAND = ("none", "anywhere", "behind_head_string")
#: An 8-ball player's group: "open" (not chosen yet), "solids" (1–7), "stripes" (9–15).
GROUPS = ("open", "solids", "stripes")


@dataclass
class Verdict:
    """What the rules decide about a shot."""

    fouls: list            #: the fouls committed: "scratch", "no contact", "wrong ball first", "no rail", "illegal break"
    potted: list           #: the object balls pocketed, in the order they dropped
    respotted: list        #: the balls to put back on their spot
    next_player: int       #: who shoots next (0 or 1)
    ball_in_hand: str      #: where the next player may place the cue ball (BALL_IN_HAND)
    game_over: bool        #: the game has ended
    winner: int | None     #: who won it
    reason: str            #: the rule applied, in words
    points: int = 0        #: the points the shot scored for its shooter

    @property
    def legal(self) -> bool:
        """Whether the shot was legal."""
        return not self.fouls


@dataclass
class NineBallState:
    """A game of 9-ball: the balls on the table by number (0 the cue ball), whose turn, the break, each
    player's fouls in a row, where the player to shoot may place the cue ball, the end."""

    on_table: list = field(default_factory=lambda: [True] * 10)
    player: int = 0
    breaking: bool = True
    fouls_in_a_row: tuple = (0, 0)
    ball_in_hand: str = "none"
    over: bool = False
    winner: int | None = None


@dataclass
class EightBallState:
    """A game of 8-ball: the balls on the table by number, whose turn, the break, each player's group,
    where the player to shoot may place the cue ball, the end."""

    on_table: list = field(default_factory=lambda: [True] * 16)
    player: int = 0
    breaking: bool = True
    groups: tuple = ("open", "open")
    ball_in_hand: str = "none"
    over: bool = False
    winner: int | None = None


@dataclass
class ThreeCushionState:
    """A game of three-cushion: ball 0 is player 0's cue ball (white), ball 1 player 1's (yellow), ball 2
    the red; each player's points, whose turn, the points that win, the end."""

    scores: tuple = (0, 0)
    player: int = 0
    target: int = 40
    over: bool = False
    winner: int | None = None


def _verdict(d: dict) -> Verdict:
    return Verdict(list(d["fouls"]), list(d["potted"]), list(d["respotted"]), d["next_player"],
                   BALL_IN_HAND[d["ball_in_hand"]], d["game_over"], d["winner"], d["reason"], d["points"])


def _check(function: str, state, kind, shot):
    if not isinstance(state, kind):
        raise TypeError(f"{function}: state is {type(state).__name__}, expected a billiards.games.{kind.__name__}")
    if not isinstance(shot, Shot):
        raise TypeError(f"{function}: shot is {type(shot).__name__}, expected a billiards.Shot that was played")
    if getattr(state, "ball_in_hand", "none") not in BALL_IN_HAND:
        raise ValueError(f"{function}: ball_in_hand is {state.ball_in_hand!r}, expected one of {BALL_IN_HAND}")


def nine_ball(state: NineBallState, shot: Shot):
    """The rules' decision on ``shot`` (its events, from its strike of ball 0) in the game ``state``:
    returns (Verdict, the NineBallState after it). ValueError for a game over, a player other than 0 or 1,
    a shot that is not one strike of the cue ball, or a pocketed ball that was not on the table."""
    _check("nine_ball", state, NineBallState, shot)
    if state.over:
        _over("nine_ball")
    verdict, after = _billiards.nine_ball([bool(b) for b in state.on_table], int(state.player), bool(state.breaking),
                                          list(state.fouls_in_a_row), BALL_IN_HAND.index(state.ball_in_hand),
                                          shot._shot)
    return _verdict(verdict), NineBallState(list(after["on_table"]), after["player"], after["breaking"],
                                            tuple(after["fouls_in_a_row"]), BALL_IN_HAND[after["ball_in_hand"]],
                                            after["over"], after["winner"])


def eight_ball(state: EightBallState, shot: Shot):
    """The rules' decision on ``shot`` in the game ``state``: returns (Verdict, the EightBallState after
    it). Errors as for nine_ball."""
    _check("eight_ball", state, EightBallState, shot)
    if state.over:
        _over("eight_ball")
    groups = [GROUPS.index(g) for g in state.groups]
    verdict, after = _billiards.eight_ball([bool(b) for b in state.on_table], int(state.player), bool(state.breaking),
                                           groups, BALL_IN_HAND.index(state.ball_in_hand), shot._shot)
    return _verdict(verdict), EightBallState(list(after["on_table"]), after["player"], after["breaking"],
                                             tuple(GROUPS[g] for g in after["groups"]),
                                             BALL_IN_HAND[after["ball_in_hand"]], after["over"], after["winner"])


def three_cushion(state: ThreeCushionState, shot: Shot):
    """The rules' decision on ``shot`` (its events, from its strike of the shooter's cue ball, ball
    ``state.player``) in the game ``state``: a point when that ball meets both others and at least three
    cushions before the second. Returns (Verdict, the ThreeCushionState after it)."""
    _check("three_cushion", state, ThreeCushionState, shot)
    if state.over:
        _over("three_cushion")
    verdict, after = _billiards.three_cushion(list(state.scores), int(state.player), int(state.target), shot._shot)
    return _verdict(verdict), ThreeCushionState(tuple(after["scores"]), after["player"], after["target"],
                                                after["over"], after["winner"])


def _over(function: str):
    raise ValueError(f"{function}: the game is over, expected a game in play")


def _free(layout: np.ndarray, xy, radius: float, ignore: int) -> bool:
    live = ~layout["pocketed"]
    live[ignore] = False
    centres = layout["position"][live, :2]
    return bool(np.all(np.hypot(centres[:, 0] - xy[0], centres[:, 1] - xy[1]) >= 2 * radius * (1 + 1e-9)))


def place(layout: np.ndarray, ball: int, xy, table: PoolTable, radius: float, region: str = "anywhere") -> bool:
    """Puts ``ball`` of ``layout`` (in place) at ``xy`` if it lies on the cloth (a radius inside the
    noses), in ``region`` ("anywhere", or "behind_head_string": x at most a quarter of the length) and
    overlaps no ball; returns whether it did."""
    x, y = float(xy[0]), float(xy[1])
    if not (math.isfinite(x) and math.isfinite(y)):
        return False
    inside = radius <= x <= table.length - radius and radius <= y <= table.width - radius
    if region == "behind_head_string":
        inside = inside and x <= 0.25 * table.length
    if not inside or not _free(layout, (x, y), radius, ball):
        return False
    layout[ball]["position"] = (x, y, radius)
    layout[ball]["velocity"] = 0.0
    layout[ball]["angular_velocity"] = 0.0
    layout[ball]["pocketed"] = False
    return True


def respot(layout: np.ndarray, ball: int, table: PoolTable, radius: float) -> None:
    """Puts ``ball`` back on the foot spot, or where that is covered, on the long string behind it as
    near the spot as it fits (then in front of it), as the WPA's rules spot a ball."""
    fx, fy = table.foot_spot()
    step = radius / 8
    for k in range(int(table.length / step)):
        for x in (fx + k * step, fx - k * step):
            if place(layout, ball, (x, fy), table, radius):
                return
    raise RuntimeError(f"respot: no free place on the long string for ball {ball}")


def place_cue_ball(layout: np.ndarray, xy, region: str, table: PoolTable, radius: float) -> None:
    """The cue ball in hand: at ``xy`` where that is legal, else on the head spot, else the nearest free
    point to it in ``region``."""
    if xy is not None and place(layout, 0, xy, table, radius, region):
        return
    hx, hy = table.head_spot()
    for k in range(200):
        for angle in np.linspace(0, 2 * np.pi, 8 * k + 1, endpoint=False):
            if place(layout, 0, (hx + k * radius / 2 * np.cos(angle), hy + k * radius / 2 * np.sin(angle)), table,
                     radius, region):
                return
    raise RuntimeError("place_cue_ball: no free place for the cue ball")


class PoolEnv:
    """A game of 9-ball or 8-ball as an environment, with Gymnasium's conventions (``reset(seed)`` →
    ``(observation, info)``; ``step(action)`` → ``(observation, reward, terminated, truncated, info)``),
    without depending on Gymnasium. One agent plays both sides; the observation says whose turn it is.

    Parameters
    ----------
    game : "9ball" or "8ball"
    table : str or PoolTable
        A preset ("7ft", "8ft", "9ft") or a table of your own.
    physics : PoolPhysics, optional
    jitter : float
        The rack's spread and jitter, as ``billiards.rack`` takes it.
    max_shots : int
        Shots after which an unfinished game is truncated.
    options : ShotOptions, optional
        How each shot plays (``check_invariants=True`` checks the engine's invariants at every event).

    Observation (a dict of arrays): ``positions`` (N, 2) — the centres (m), NaN for a ball off the table;
    ``on_table`` (N,) bool (the cue ball in hand after a scratch: False until it is placed); ``player`` — who shoots (0 or 1); ``ball_in_hand`` — an index into
    BALL_IN_HAND; ``breaking``; for 8-ball ``groups`` — each player's, an index into GROUPS.

    Action: ``(speed, azimuth, side_offset, up_offset)`` or ``(speed, azimuth, side_offset, up_offset, x,
    y)`` — the cue's speed (m/s), its direction in the table's plane (radians from +x), the tip's offsets in
    units of the radius (as ``Cue``), and where to place the cue ball when it is in hand (m; an illegal or
    missing place puts it on the head spot, or the nearest free point). A level cue of 0.567 kg.

    Reward: +1 when the shot wins the game for the player who took it, −1 when it loses it, 0 otherwise.
    ``info``: the shot's ``verdict`` (Verdict), its ``shooter``, its ``events`` count.
    """

    def __init__(self, game: str = "9ball", table="7ft", physics: PoolPhysics | None = None, jitter: float = 1e-3,
                 max_shots: int = 200, options: ShotOptions | None = None):
        if game not in ("9ball", "8ball"):
            raise ValueError(f"PoolEnv: game is {game!r}, expected '9ball' or '8ball'")
        self.game = game
        self.table = pool_table(table) if isinstance(table, str) else table
        if not isinstance(self.table, PoolTable):
            raise TypeError(f"PoolEnv: table is {type(table).__name__}, expected a preset's name or a PoolTable")
        self.physics = PoolPhysics() if physics is None else physics
        if not (isinstance(max_shots, int) and max_shots >= 1):
            raise ValueError(f"PoolEnv: max_shots is {max_shots!r}, expected a whole number >= 1")
        self.jitter, self.max_shots = float(jitter), max_shots
        self._options = ShotOptions() if options is None else options
        self._rng = np.random.default_rng()
        self._layout = None

    def reset(self, seed: int | None = None, options: dict | None = None):
        """A new game: the rack (its jitter drawn from ``seed``), the break to play."""
        if seed is not None:
            self._rng = np.random.default_rng(seed)
        self._layout = rack(self.table, self.physics, self.game, self.jitter, int(self._rng.integers(2**63)))
        state = NineBallState() if self.game == "9ball" else EightBallState()
        self._state = replace(state, ball_in_hand="behind_head_string")
        self._shots = 0
        return self._observation(), {}

    def _observation(self) -> dict:
        positions = self._layout["position"][:, :2].copy()
        on_table = ~self._layout["pocketed"]
        positions[~on_table] = np.nan
        obs = {"positions": positions, "on_table": on_table, "player": self._state.player,
               "ball_in_hand": BALL_IN_HAND.index(self._state.ball_in_hand), "breaking": self._state.breaking}
        if self.game == "8ball":
            obs["groups"] = np.array([GROUPS.index(g) for g in self._state.groups])
        return obs

    def step(self, action):
        """Plays one shot: returns (observation, reward, terminated, truncated, info)."""
        if self._layout is None:
            raise RuntimeError("PoolEnv.step: call reset() first")
        if self._state.over:
            raise RuntimeError("PoolEnv.step: the game is over; call reset()")
        numbers = np.asarray(action, dtype=np.float64).reshape(-1)
        if numbers.size not in (4, 6) or not np.all(np.isfinite(numbers[:4])):
            raise ValueError(f"PoolEnv.step: action is {action!r}, expected 4 finite numbers (speed, azimuth, "
                             f"side_offset, up_offset) and optionally the cue ball's place x, y")
        if self._state.ball_in_hand != "none":
            where = numbers[4:6] if numbers.size == 6 else None
            place_cue_ball(self._layout, where, self._state.ball_in_hand, self.table, self.physics.radius)
        shooter = self._state.player
        shot = Shot(self.table, self.physics, self._layout, self._options)
        shot.strike(0, Cue(speed=numbers[0], azimuth=numbers[1], side_offset=numbers[2], up_offset=numbers[3]))
        shot.play()
        decide = nine_ball if self.game == "9ball" else eight_ball
        verdict, self._state = decide(self._state, shot)
        self._layout = shot.balls
        for ball in verdict.respotted:
            respot(self._layout, ball, self.table, self.physics.radius)
        self._shots += 1
        reward = 0.0
        if verdict.game_over:
            reward = 1.0 if verdict.winner == shooter else -1.0
        truncated = not verdict.game_over and self._shots >= self.max_shots
        info = {"verdict": verdict, "shooter": shooter, "events": shot.event_count}
        return self._observation(), reward, verdict.game_over, truncated, info
