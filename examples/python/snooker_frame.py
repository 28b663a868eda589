"""A frame of snooker between two random players on the WPBSA table, through the game environment:
each shot aimed at a ball the player may meet first, the rules deciding fouls, points and respots."""
import numpy as np
import billiards.games as games

env = games.GameEnv("snooker", max_shots=5000)
observation, info = env.reset(seed=1)
rng = np.random.default_rng(1)
shots = 0
while True:
    observation, reward, terminated, truncated, info = env.step(env.sample_action(rng))
    shots += 1
    if terminated or truncated:
        break
scores = observation["scores"]
print(f"{shots} shots, {scores[0]}–{scores[1]}, won by player {env.state.winner}")
