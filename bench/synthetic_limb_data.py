"""Writes a prepared data set (tendril's prepared CSV) of a known nonlinear system shaped like
seed 001's SMA limb, for timing and checking `tendril model fit` before the twin's data exist.

The system is the one of tests/dynamics/synthetic_limb.hpp: two bending angles θ (deg) driven by
two integer throttles u ∈ [−10, 10] (held for 10 samples) through a first-order heat lag
(τ_h = 0.8 s), a stiffening spring and cross-coupling,
    ḣ = (u − h) / τ_h,   θ̈ = −6 θ (1 + θ² / 7200) − 2.5 θ̇ + 40 h + 0.5 (θ_other − θ),
integrated with 10 semi-implicit Euler substeps per sample, sampled every 70 ms ± 10 %; the last
20 % of the rows are the test split.

    /usr/bin/python3 bench/synthetic_limb_data.py ROWS OUT.csv [SEED]
"""
import os
import random
import sys


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    rows, out = int(sys.argv[1]), sys.argv[2]
    seed = int(sys.argv[3]) if len(sys.argv) == 4 else 1
    if os.path.exists(out):
        sys.exit(f"{out}: exists; nothing is overwritten")
    rng = random.Random(seed)
    theta, omega, heat, throttle = [0.0, 0.0], [0.0, 0.0], [0.0, 0.0], [0, 0]
    time = 0.0
    test_begin = round(0.8 * rows)
    with open(out + ".part", "w") as f:
        f.write("time_s,theta_x,theta_y,omega_x,omega_y,u_x,u_y,split\n")
        for row in range(rows):
            if row % 10 == 0:
                throttle = [rng.randint(-10, 10) for _ in range(2)]
            split = "train" if row < test_begin else "test"
            f.write(f"{time!r},{theta[0]!r},{theta[1]!r},{omega[0]!r},{omega[1]!r},"
                    f"{throttle[0]},{throttle[1]},{split}\n")
            dt = 0.07 * rng.uniform(0.9, 1.1)
            h = dt / 10
            for _ in range(10):
                acceleration = [0.0, 0.0]
                for a in range(2):
                    heat[a] += h * (throttle[a] - heat[a]) / 0.8
                    acceleration[a] = (-6 * theta[a] * (1 + theta[a] ** 2 / 7200) - 2.5 * omega[a]
                                       + 40 * heat[a] + 0.5 * (theta[1 - a] - theta[a]))
                for a in range(2):
                    omega[a] += h * acceleration[a]
                    theta[a] += h * omega[a]
            time += dt
    os.rename(out + ".part", out)


if __name__ == "__main__":
    main()
