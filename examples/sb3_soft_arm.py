"""Stable-Baselines3's PPO on a tendril soft arm: the Elastica case-1 arm (a Cosserat rod
tracking a moving target) as a vector environment stepped in C++, then the trained arm drawn
with matplotlib.

    python3 examples/sb3_soft_arm.py [STEPS]     # default 200000, about 2 minutes on 2 cores
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from stable_baselines3 import PPO  # noqa: E402

import tendril  # noqa: E402

steps = int(sys.argv[1]) if len(sys.argv) > 1 else 200_000
venv = tendril.make_vec("Elastica/Tracking3D-v0", 8, num_threads=2).to_sb3()
model = PPO("MlpPolicy", venv, seed=0, device="cpu")
model.learn(total_timesteps=steps)

env = tendril.make("Elastica/Tracking3D-v0")
observation, _ = env.reset(seed=1)
rewards = []
for _ in range(500):
    action, _ = model.predict(observation, deterministic=True)
    observation, reward, terminated, truncated, info = env.step(action)
    rewards.append(reward)
    if terminated or truncated:
        break
print(f"after {steps} steps of PPO: mean reward per step {np.mean(rewards):.3f} "
      f"over {len(rewards)} steps")

scene = env.scene()
arm = next(rod for rod in scene["rods"] if rod["role"] == "arm")["centreline"]
target = next(sphere for sphere in scene["spheres"] if sphere["role"] == "target")["centre"]
axes = plt.figure().add_subplot(projection="3d")
axes.plot(arm[:, 0], arm[:, 1], arm[:, 2], lw=3, label="arm")
axes.scatter(*target, color="red", label="target")
axes.set_xlabel("x (m)")
axes.set_ylabel("y (m)")
axes.set_zlabel("z (m)")
axes.legend()
plt.savefig("sb3_arm.png")
print("wrote sb3_arm.png")
