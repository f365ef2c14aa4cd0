"""Train with tendril's own PPO (C++, one call), then use the policy from Python: evaluate it
on seeded episodes and write a video of one.

    python3 examples/train_then_python.py [STEPS]   # default 2000000, about half a minute
"""
import sys

import numpy as np

import tendril

steps = int(sys.argv[1]) if len(sys.argv) > 1 else 2_000_000
run = tendril.train("configs/elastica/tracking3d_ppo_quick.yaml", out="runs/example_arm",
                    n_timesteps=steps, quiet=True)
policy = tendril.load(run)

env = tendril.make("Elastica/Tracking3D-v0")
returns = []
for episode in range(3):
    observation, _ = env.reset(seed=episode)  # episode k resets with seed k, as `tendril run`
    total, done = 0.0, False
    while not done:
        observation, reward, terminated, truncated, _ = env.step(policy.act(observation))
        total += reward
        done = terminated or truncated
    returns.append(total)
print(f"{run}: return {np.mean(returns):.2f} +/- {np.std(returns):.2f} over {len(returns)} episodes")

tendril.record_video("Elastica/Tracking3D-v0", policy, "example_arm.mp4", size=(320, 240),
                     max_steps=1000)  # the first 1.4 s of an episode
print("wrote example_arm.mp4")
