"""Python overhead of tendril.make_vec(...).step: vector steps per second of 8 Elastica case-1
environments stepped from Python (through the extension, the Gymnasium vector interface and the
Stable-Baselines3 adapter) against the same VecEnv stepped from C++, measured in the same run.

    PYTHONPATH=build/python /usr/bin/python3 bench/python_vec_step_bench.py build/bench/vec_step_cpp

Prints one line per variant and its ratio to C++ (1.00 = no overhead)."""
import argparse
import json
import subprocess
import time

import numpy as np


def time_loop(step, batches, seconds):
    for i in range(256):
        step(batches[i % 64])
    steps, start = 0, time.perf_counter()
    elapsed = 0.0
    while elapsed < seconds:
        for i in range(256):
            step(batches[(steps + i) % 64])
        steps += 256
        elapsed = time.perf_counter() - start
    return steps / elapsed


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("cpp", help="path of the vec_step_cpp program (build/bench/vec_step_cpp)")
    parser.add_argument("--env", default="Elastica/Tracking3D-v0")
    parser.add_argument("--num-envs", type=int, default=8)
    parser.add_argument("--threads", type=int, default=1)
    parser.add_argument("--seconds", type=float, default=3.0)
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()

    import tendril

    rows = {"C++ VecEnv::step": [], "native step (views)": [], "make_vec().step (Gymnasium API)": []}
    try:
        import stable_baselines3  # noqa: F401

        rows["SB3 adapter step"] = []
    except ImportError:
        print("Stable-Baselines3 not importable: the adapter row is left out")
    for _ in range(args.repeats):  # interleaved, so machine load hits every variant alike
        done = subprocess.run([args.cpp, args.env, str(args.num_envs), str(args.threads),
                               str(args.seconds)], capture_output=True, text=True, check=True)
        rows["C++ VecEnv::step"].append(json.loads(done.stdout)["vec_steps_per_s"])
        venv = tendril.make_vec(args.env, args.num_envs, num_threads=args.threads)
        space = venv.single_action_space
        rng = np.random.default_rng(0)
        batches = [rng.uniform(space.low, space.high, (args.num_envs, space.shape[0]))
                   .astype(np.float32) for _ in range(64)]
        venv.reset(seed=0)
        rows["native step (views)"].append(time_loop(venv.native.step, batches, args.seconds))
        venv.reset(seed=0)
        rows["make_vec().step (Gymnasium API)"].append(time_loop(venv.step, batches, args.seconds))
        if "SB3 adapter step" in rows:
            sb3 = venv.to_sb3()
            sb3.reset()
            rows["SB3 adapter step"].append(time_loop(sb3.step, batches, args.seconds))

    baseline = np.median(rows["C++ VecEnv::step"])
    print(f"{args.env} x{args.num_envs}, {args.threads} thread(s), median of {args.repeats} "
          f"runs of {args.seconds} s")
    for name, values in rows.items():
        rate = np.median(values)
        per_step_us = 1e6 / rate
        overhead_us = per_step_us - 1e6 / baseline
        print(f"  {name:34s} {rate:10.0f} vec steps/s ({rate * args.num_envs:10.0f} env steps/s)"
              f"  {per_step_us:7.1f} us/step  overhead {overhead_us:6.1f} us  "
              f"ratio to C++ {rate / baseline:.3f}")


if __name__ == "__main__":
    main()
