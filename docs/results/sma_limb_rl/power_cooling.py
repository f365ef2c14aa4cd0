"""Seed 001's Fig. A.4: the power proxy's cool-down from p0 = 1600 with the throttles off, for
cooling rates k of 0.05-1 1/s at the thesis' step dt = 0.075 s. Algorithm 2 multiplies each coil's
value by (1 - k dt) per step, so the curves are p0 (1 - k dt)^n; tendril's PowerProxy follows this
closed form to 1e-9 (tests/envs/sma_limb/power_proxy_test.cpp, CoolsAsTheClosedFormOfFigA4).

  /usr/bin/python3 docs/results/sma_limb_rl/power_cooling.py docs/results/sma_limb_rl/power_cooling.png

Prints, per k, the fraction left after 10, 30 and 40 s.
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

P0, DT, SECONDS = 1600.0, 0.075, 40.0
RATES = (0.05, 0.1, 0.2, 0.5, 1.0)


def curve(k):
    steps = int(round(SECONDS / DT))
    return [n * DT for n in range(steps + 1)], [P0 * (1.0 - k * DT) ** n for n in range(steps + 1)]


def main():
    figure, axes = plt.subplots(figsize=(6.5, 4.0), dpi=90)
    print("k [1/s], left after 10 s, 30 s, 40 s")
    for k in RATES:
        times, power = curve(k)
        axes.plot(times, power, label=f"k = {k}", linewidth=2.5 if k == 0.2 else 1.2)
        left = [P0 * (1.0 - k * DT) ** round(t / DT) / P0 for t in (10.0, 30.0, 40.0)]
        print(f"{k}, " + ", ".join(f"{100 * f:.3g} %" for f in left))
    axes.axvline(30.0, color="grey", linestyle=":", linewidth=1)
    axes.set_xlabel("time with the throttles off [s]")
    axes.set_ylabel("power proxy p")
    axes.set_title("Fig. A.4: cool-down of the power proxy (Δt = 0.075 s)")
    axes.legend()
    figure.tight_layout()
    figure.savefig(sys.argv[1])


if __name__ == "__main__":
    main()
