"""The games: the rules of 9-ball and 8-ball (WPA), snooker (WPBSA) and three-cushion (UMB) decided
from a shot's events, placing balls by hand (the cue ball in hand, respotting), and a game environment
with the ``reset()`` / ``step(action)`` conventions of Gymnasium (without depending on it).

Which rules are in and which are left out: a page per game, from docs/games.md. Ball 0 is the cue ball,
the object balls are numbered as in the game (9-ball: 1 to 9; 8-ball: 1 to 15, the solids 1–7, the
stripes 9–15; snooker: 1–15 the reds, 16–21 yellow, green, brown, blue, pink, black; three-cushion: 0
the white, 1 the yellow, 2 the red).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from . import _billiards
from ._shot import PoolPhysics, PoolTable, Shot, ShotOptions, _from_columns, physics_preset, table_preset

__all__ = ["BALL_IN_HAND", "GROUPS", "SNOOKER_ON", "GAMES", "Verdict", "NineBallState",
           "EightBallState", "SnookerState", "ThreeCushionState", "nine_ball", "eight_ball", "snooker",
           "three_cushion", "place", "place_cue_ball", "respot", "GameEnv", "PoolEnv"]

#: Where the next player may place the cue ball: "none", "anywhere", "behind_head_string", "in_d" (the
#: snooker D).
BALL_IN_HAND = ("none", "anywhere", "behind_head_string", "in_d")
#: What a snooker player is on: "red", "colour" (any, after a red), "sequence" (the lowest colour left).
SNOOKER_ON = ("red", "colour", "sequence")
#: An 8-ball player's group: "open" (not chosen yet), "solids" (1–7), "stripes" (9–15).
GROUPS = ("open", "solids", "stripes")


@dataclass
class Verdict:
    """What the rules decide about a shot."""

    fouls: list            #: the fouls committed: "scratch", "no contact", "wrong ball first", "no rail",
    #: "illegal break", "wrong ball potted"
    potted: list           #: the object balls pocketed, in the order they dropped
    respotted: list        #: the balls to put back on their spot
    next_player: int       #: who shoots next (0 or 1)
    ball_in_hand: str      #: where the next player may place the cue ball (BALL_IN_HAND)
    game_over: bool        #: the game has ended
    winner: int | None     #: who won it
    reason: str            #: the rule applied, in words
    points: int = 0        #: the points the shot scored for its shooter
    penalty: int = 0       #: the points a foul gave the opponent (snooker)

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
class SnookerState:
    """A frame of snooker: the balls on the table by index (0 the white, 1–15 the reds, 16–21 the
    colours), whose turn, the scores, what the player to shoot is on (SNOOKER_ON), where they may place
    the white (in the D for the opening stroke), the end."""

    on_table: list = field(default_factory=lambda: [True] * 22)
    player: int = 0
    scores: tuple = (0, 0)
    on: str = "red"
    ball_in_hand: str = "in_d"
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
    return Verdict(*verdict), _state_from("9ball", after)


def eight_ball(state: EightBallState, shot: Shot):
    """The rules' decision on ``shot`` in the game ``state``: returns (Verdict, the EightBallState after
    it). Errors as for nine_ball."""
    _check("eight_ball", state, EightBallState, shot)
    if state.over:
        _over("eight_ball")
    groups = [GROUPS.index(g) for g in state.groups]
    verdict, after = _billiards.eight_ball([bool(b) for b in state.on_table], int(state.player), bool(state.breaking),
                                           groups, BALL_IN_HAND.index(state.ball_in_hand), shot._shot)
    return Verdict(*verdict), _state_from("8ball", after)


def snooker(state: SnookerState, shot: Shot):
    """The rules' decision on ``shot`` (its events, from its strike of the white, ball 0) in the frame
    ``state``: a red then a colour while reds remain (the first colour the white meets is the nominated
    one; colours respotted), then the colours in order; a foul gives the opponent the highest value
    involved, at least 4. Returns (Verdict, the SnookerState after it). Errors as for nine_ball."""
    _check("snooker", state, SnookerState, shot)
    if state.over:
        raise ValueError("snooker: the frame is over, expected a frame in play")
    if state.on not in SNOOKER_ON:
        raise ValueError(f"snooker: on is {state.on!r}, expected one of {SNOOKER_ON}")
    verdict, after = _billiards.snooker([bool(b) for b in state.on_table], int(state.player), list(state.scores),
                                        SNOOKER_ON.index(state.on), BALL_IN_HAND.index(state.ball_in_hand),
                                        shot._shot)
    return Verdict(*verdict), _state_from("snooker", after)


def three_cushion(state: ThreeCushionState, shot: Shot):
    """The rules' decision on ``shot`` (its events, from its strike of the shooter's cue ball, ball
    ``state.player``) in the game ``state``: a point when that ball meets both others and at least three
    cushions before the second. Returns (Verdict, the ThreeCushionState after it)."""
    _check("three_cushion", state, ThreeCushionState, shot)
    if state.over:
        _over("three_cushion")
    verdict, after = _billiards.three_cushion(list(state.scores), int(state.player), int(state.target), shot._shot)
    return Verdict(*verdict), _state_from("3cushion", after)


def _over(function: str):
    raise ValueError(f"{function}: the game is over, expected a game in play")


def _physics(radius: float) -> PoolPhysics:
    return PoolPhysics(radius=float(radius))


def _region(function: str, region: str) -> int:
    if region not in BALL_IN_HAND[1:]:
        raise ValueError(f"{function}: region is {region!r}, expected one of {BALL_IN_HAND[1:]}")
    return BALL_IN_HAND.index(region) - 1


def place(layout: np.ndarray, ball: int, xy, table: PoolTable, radius: float, region: str = "anywhere") -> bool:
    """Puts ``ball`` of ``layout`` (in place) at rest at ``xy`` if it lies on the cloth (a radius inside the
    noses), in ``region`` ("anywhere"; "behind_head_string": x at most a quarter of the length; "in_d":
    in the snooker D) and overlaps no ball; returns whether it did."""
    x, y = float(xy[0]), float(xy[1])
    placed, columns = _billiards.place_ball(table, _physics(radius), layout, int(ball), x, y,
                                            _region("place", region))
    if placed:
        layout[ball] = _from_columns(columns)[ball]
    return bool(placed)


def respot(layout: np.ndarray, ball: int, table: PoolTable, radius: float, game: str = "pool") -> None:
    """Puts ``ball`` back on the table (in place). Pool (``game`` "pool"): on the foot spot, or where that
    is covered, on the long string behind it as near the spot as it fits (then in front of it), as the
    WPA's rules spot a ball. Snooker (``game`` "snooker", ``ball`` a colour 16–21): on its own spot, else
    the highest valued free spot, else as near its own spot as it fits towards the top cushion (then
    towards the baulk cushion; ValueError for a ball that is not a colour). RuntimeError where no place is
    free."""
    if game not in ("pool", "snooker"):
        raise ValueError(f"respot: game is {game!r}, expected 'pool' or 'snooker'")
    layout[:] = _from_columns(_billiards.respot(table, _physics(radius), layout, int(ball), game == "snooker"))


def place_cue_ball(layout: np.ndarray, xy, region: str, table: PoolTable, radius: float) -> None:
    """The cue ball in hand (in place): at ``xy`` where that is legal, else the nearest free point in
    ``region`` to its own point (the head spot; the middle of the D for "in_d")."""
    where = None if xy is None else (float(xy[0]), float(xy[1]))
    layout[:] = _from_columns(_billiards.place_cue_ball(table, _physics(radius), layout, where,
                                                        _region("place_cue_ball", region)))


GAMES = ("9ball", "8ball", "snooker", "3cushion")
_DEFAULT_TABLES = {"9ball": "7ft", "8ball": "7ft", "snooker": "snooker", "3cushion": "carom"}


class GameEnv:
    """A game of 9-ball, 8-ball, snooker or three-cushion as an environment, with Gymnasium's conventions
    (``reset(seed)`` → ``(observation, info)``; ``step(action)`` → ``(observation, reward, terminated,
    truncated, info)``), without depending on Gymnasium. One agent plays both sides; the observation says
    whose turn it is.

    Parameters
    ----------
    game : "9ball", "8ball", "snooker" or "3cushion"
    table : str or PoolTable
        A preset (table_preset's names) or a table of your own; by default "7ft" for pool, "snooker" and
        "carom".
    physics : PoolPhysics, optional
        By default the table preset's (physics_preset), the pool physics for a table of your own.
    jitter : float
        The rack's spread and jitter, as ``billiards.rack`` takes it (no effect in three-cushion).
    max_shots : int
        Shots after which an unfinished game is truncated.
    target : int
        Three-cushion: the points that win (40 by default).
    options : ShotOptions, optional
        How each shot plays (``check_invariants=True`` checks the engine's invariants at every event).

    Observation (a dict of arrays): ``positions`` (N, 2) — the centres (m), NaN for a ball off the table;
    ``on_table`` (N,) bool (the cue ball in hand after it was pocketed: False until it is placed);
    ``player`` — who shoots (0 or 1); ``ball_in_hand`` — an index into BALL_IN_HAND; pool: ``breaking``,
    and for 8-ball ``groups`` — each player's, an index into GROUPS; snooker and three-cushion:
    ``scores`` (2,); snooker: ``on`` — an index into SNOOKER_ON.

    Action: ``(speed, azimuth, side_offset, up_offset)`` or ``(speed, azimuth, side_offset, up_offset, x,
    y)`` — the cue's speed (m/s), its direction in the table's plane (radians from +x), the tip's offsets in
    units of the radius (as ``Cue``), and where to place the cue ball when it is in hand (m; an illegal or
    missing place puts it on the nearest free point to the head spot, or to the D's middle). A level cue
    of 0.567 kg, on ball 0 — in three-cushion on the shooter's own ball (``player``).

    Reward, for the player who took the shot: pool: +1 when it wins the game, −1 when it loses it, 0
    otherwise; snooker: the points it scored less the points a foul gave away; three-cushion: the point
    it scored (0 or 1). ``info``: the shot's ``verdict`` (Verdict), its ``shooter``, its ``events`` count;
    ``last_shot()`` gives the Shot itself (its events and trajectories). ``state`` is the game's state
    (NineBallState, EightBallState, SnookerState or ThreeCushionState), ``layout`` the balls where they
    lie (ball_dtype). The game is played in C++ (games::Game): a step costs little beyond its shot.
    """

    def __init__(self, game: str = "9ball", table=None, physics: PoolPhysics | None = None, jitter: float = 1e-3,
                 max_shots: int = 200, options: ShotOptions | None = None, target: int = 40):
        if game not in GAMES:
            raise ValueError(f"{type(self).__name__}: game is {game!r}, expected one of {GAMES}")
        self.game = game
        name = _DEFAULT_TABLES[game] if table is None else table
        self.table = table_preset(name) if isinstance(name, str) else name
        if not isinstance(self.table, PoolTable):
            raise TypeError(f"{type(self).__name__}: table is {type(table).__name__}, expected a preset's name or "
                            f"a PoolTable")
        if physics is None:
            physics = physics_preset(name) if isinstance(name, str) else PoolPhysics()
        if not isinstance(physics, PoolPhysics):
            raise TypeError(f"{type(self).__name__}: physics is {type(physics).__name__}, expected a PoolPhysics")
        self.physics = physics
        if isinstance(max_shots, bool) or not (isinstance(max_shots, int) and max_shots >= 1):
            raise ValueError(f"{type(self).__name__}: max_shots is {max_shots!r}, expected a whole number >= 1")
        if isinstance(target, bool) or not (isinstance(target, int) and target >= 1):
            raise ValueError(f"{type(self).__name__}: target is {target!r}, expected a whole number >= 1")
        if not (0 <= jitter <= 1):
            raise ValueError(f"{type(self).__name__}: jitter is {jitter!r}, expected a number in [0, 1]")
        self.jitter, self.max_shots, self.target = float(jitter), max_shots, target
        options = ShotOptions() if options is None else options
        self._game = _billiards.Game(game, self.table, self.physics, options, target)
        self._rng = np.random.default_rng()
        self._started = False

    @property
    def state(self):
        """The game's state now (a NineBallState, EightBallState, SnookerState or ThreeCushionState)."""
        return _state_from(self.game, self._game.state())

    @property
    def layout(self) -> np.ndarray:
        """The balls where they lie (ball_dtype); the cue ball in hand is placed by the next step."""
        return _from_columns(self._game.balls())

    def last_shot(self):
        """The last shot played (a billiards.Shot; None before the first step)."""
        native = self._game.last_shot()
        return None if native is None else Shot._played(native, self.table, self.physics, len(self.layout))

    def sample_action(self, rng: np.random.Generator | None = None, aim: bool = True) -> list:
        """A random player's action: a speed of 0.3 to 7 m/s, tip offsets within ±0.4 of the radius, the cue
        ball's place drawn where it may be placed in hand, and, with ``aim``, the cue aimed at a ball it may
        meet first (the lowest in 9-ball, its group's or the 8 in 8-ball, a ball on in snooker, either other
        ball in three-cushion) with a random cut of about 0.08 rad; without, in any direction. ``rng``: a
        numpy Generator (the environment's own, seeded by ``reset``, where omitted)."""
        rng = self._rng if rng is None else rng
        balls, state = self._game.balls(), self.state
        position, pocketed = balls[0], balls[3]
        length, width, radius = self.table.length, self.table.width, self.physics.radius
        hand = getattr(state, "ball_in_hand", "none")
        if hand == "in_d":
            place = [rng.uniform(0.737 - 0.292, 0.737), rng.uniform(width / 2 - 0.292, width / 2 + 0.292)]
        else:
            place = [rng.uniform(radius, length / 4 if hand == "behind_head_string" else length - radius),
                     rng.uniform(radius, width - radius)]
        striker = state.player if self.game == "3cushion" else 0
        cue = np.asarray(place) if hand != "none" else position[striker, :2]
        targets = [b for b in range(len(pocketed)) if not pocketed[b] and self._game.may_meet_first(b)]
        if aim and targets:
            target = position[targets[rng.integers(len(targets))], :2]
            azimuth = math.atan2(target[1] - cue[1], target[0] - cue[0]) + rng.normal(0, 0.08)
        else:
            azimuth = rng.uniform(-math.pi, math.pi)
        return [rng.uniform(0.3, 7), azimuth, rng.uniform(-0.4, 0.4), rng.uniform(-0.4, 0.4)] + place

    def reset(self, seed: int | None = None, options: dict | None = None):
        """A new game: the game's starting position (the rack's jitter, or three-cushion's side, drawn from
        ``seed``), the break to play."""
        if seed is not None:
            self._rng = np.random.default_rng(seed)
        self._game.reset(self.jitter, int(self._rng.integers(2**63)))
        self._shots, self._started = 0, True
        return self._game.observation(), {}

    def step(self, action):
        """Plays one shot: returns (observation, reward, terminated, truncated, info)."""
        if not self._started:
            raise RuntimeError(f"{type(self).__name__}.step: call reset() first")
        if self._game.over():
            raise RuntimeError(f"{type(self).__name__}.step: the game is over; call reset()")
        verdict, shooter, reward, events, observation = self._game.step(action, f"{type(self).__name__}.step")
        verdict = Verdict(*verdict)
        self._shots += 1
        truncated = not verdict.game_over and self._shots >= self.max_shots
        return observation, reward, verdict.game_over, truncated, {"verdict": verdict, "shooter": shooter,
                                                                     "events": events}


def _state_from(game: str, d: dict):
    """A game's state from the compiled module's dict."""
    if game == "3cushion":
        return ThreeCushionState(tuple(d["scores"]), d["player"], d["target"], d["over"], d["winner"])
    hand = BALL_IN_HAND[d["ball_in_hand"]]
    if game == "snooker":
        return SnookerState(list(d["on_table"]), d["player"], tuple(d["scores"]), SNOOKER_ON[d["on"]], hand,
                            d["over"], d["winner"])
    if game == "9ball":
        return NineBallState(list(d["on_table"]), d["player"], d["breaking"], tuple(d["fouls_in_a_row"]), hand,
                             d["over"], d["winner"])
    return EightBallState(list(d["on_table"]), d["player"], d["breaking"], tuple(GROUPS[g] for g in d["groups"]),
                          hand, d["over"], d["winner"])


class PoolEnv(GameEnv):
    """GameEnv for 9-ball and 8-ball (its defaults: 9-ball on the 7-ft table)."""

    def __init__(self, game: str = "9ball", table="7ft", physics: PoolPhysics | None = None, jitter: float = 1e-3,
                 max_shots: int = 200, options: ShotOptions | None = None):
        if game not in ("9ball", "8ball"):
            raise ValueError(f"PoolEnv: game is {game!r}, expected '9ball' or '8ball' (GameEnv plays the others)")
        super().__init__(game, table, physics, jitter, max_shots, options)
