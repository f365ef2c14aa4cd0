"""Stable-Baselines3 PPO (default hyper-parameters, one environment, one torch thread) training on
tendril's Elastica case-1 arm through tendril.make_vec and the SB3 adapter, against SB3 PPO on the
same arm written with PyElastica, steps per second measured in the same run: what a user who
switches from PyElastica to tendril without leaving SB3 sees.

The PyElastica side is a Gymnasium env of case 1 (20 elements, 7 rod steps per action, 44
observations, 12 actions) run by an external script given by path, which prints a JSON line with
"steps_per_s" (e.g. ../shared/anchors/bench/bench_sb3_arm.py with --mode ppo):

    V=../shared/vendor
    PYTHONPATH=build/python:$V/gymnasium-0.29.1:$V/stable-baselines3-2.3.2 /usr/bin/python3 \\
        bench/python_sb3_arm_bench.py --steps 20480 \\
        --pyelastica-script ../shared/anchors/bench/bench_sb3_arm.py \\
        --pyelastica-path $V/pyelastica-0.3.1.post1

PyElastica needs Numba (Debian: python3-numba)."""
import argparse
import json
import os
import subprocess
import sys
import time


def tendril_ppo(steps, seed):
    import torch
    from stable_baselines3 import PPO

    import tendril

    torch.set_num_threads(1)
    venv = tendril.make_vec("Elastica/Tracking3D-v0", 1).to_sb3()
    model = PPO("MlpPolicy", venv, seed=seed, device="cpu", verbose=0)
    start = time.perf_counter()
    model.learn(total_timesteps=steps)
    seconds = time.perf_counter() - start
    return model.num_timesteps / seconds, seconds


def pyelastica_ppo(script, extra_path, steps, seed):
    paths = [os.path.dirname(os.path.abspath(script)), *extra_path, *sys.path]
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(p for p in paths if p)}
    done = subprocess.run([sys.executable, script, "--mode", "ppo", "--steps", str(steps),
                           "--threads", "1", "--seed", str(seed)],
                          capture_output=True, text=True, env=env, check=True)
    result = json.loads(done.stdout.strip().splitlines()[-1])
    return result["steps_per_s"], result["wall_s"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, default=20480)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--pyelastica-script", required=True)
    parser.add_argument("--pyelastica-path", action="append", default=[],
                        help="folder to put on the baseline's PYTHONPATH (repeatable)")
    args = parser.parse_args()
    ours, our_seconds = tendril_ppo(args.steps, args.seed)
    theirs, their_seconds = pyelastica_ppo(args.pyelastica_script, args.pyelastica_path,
                                           args.steps, args.seed)
    print(f"SB3 PPO (defaults), Elastica case 1, {args.steps} steps, one torch thread")
    print(f"  tendril (make_vec + SB3 adapter) {ours:8.0f} steps/s  ({our_seconds:.1f} s)")
    print(f"  PyElastica env                   {theirs:8.0f} steps/s  ({their_seconds:.1f} s)")
    print(f"  ratio tendril / PyElastica       {ours / theirs:8.2f}")


if __name__ == "__main__":
    main()
