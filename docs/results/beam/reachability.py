"""The beam's reachability floor (seed 003, tasks 1–2): how close the tip can be held to each arc
point with constant torques.

For every point r·(sin φ, cos φ) of the arcs (the base at the origin, the beam along +y; radius
r over [0.2, 0.6] m, φ over ±80°, as `src/tendril/envs/beam/arc_path.cpp` draws them) it finds
the five constant torques in [−1, 1] × torque_scale whose settled tip lies closest: first the
nearest of a set of random torque vectors' settled tips, then Nelder–Mead from the three
nearest (scipy). A torque vector is held for `--settle` seconds from rest and the tip averaged
over its last second. A tip that follows a moving target cannot hold it closer than this on
average where the target moves slowly (the arcs' 0.1–0.5 rad/s), so the table is a floor for the
policies' distance errors, per radius and angle.

  PYTHONPATH=build/python /usr/bin/python3 docs/results/beam/reachability.py \
      --out docs/results/beam/reachability.csv

Writes one row per arc point (radius, angle, floor distance, the torques, the settled tip) and
prints the floor's mean over the arcs' distribution (radius and angle uniform).
"""
import argparse
import csv
import math
import sys

import numpy as np
from scipy.optimize import minimize

import tendril

STEP_S = 0.05  # the environment's control period (Beam/* control_period)


def settled_tip(env, action, settle_s):
    env.reset(seed=0)
    steps = int(round(settle_s / STEP_S))
    tail = int(round(1.0 / STEP_S))
    tips = []
    held = np.asarray(np.clip(action, -1.0, 1.0), dtype=np.float32)
    for k in range(steps):
        obs, _, terminated, _, _ = env.step(held)
        if terminated or not np.all(np.isfinite(obs)):
            return None
        if k >= steps - tail:
            tips.append(obs[10:12].astype(float))
    return np.mean(tips, axis=0)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", required=True)
    parser.add_argument("--samples", type=int, default=3000)
    parser.add_argument("--settle", type=float, default=4.0)
    parser.add_argument("--radii", default="0.2,0.3,0.4,0.5,0.6")
    parser.add_argument("--angles", default="-80,-60,-40,-20,0,20,40,60,80")
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args()

    env = tendril.make("Beam/TrajectoryFollow-v0")
    rng = np.random.default_rng(args.seed)
    actions = rng.uniform(-1.0, 1.0, size=(args.samples, 5))
    tips = []
    kept = []
    for a in actions:
        tip = settled_tip(env, a, args.settle)
        if tip is not None:
            tips.append(tip)
            kept.append(a)
    tips = np.array(tips)
    kept = np.array(kept)
    print(f"{len(kept)} of {args.samples} random torque vectors settle", file=sys.stderr)

    rows = []
    for r in [float(x) for x in args.radii.split(",")]:
        for phi_deg in [float(x) for x in args.angles.split(",")]:
            phi = math.radians(phi_deg)
            target = np.array([r * math.sin(phi), r * math.cos(phi)])
            distances = np.linalg.norm(tips - target, axis=1)
            best_d, best_a = float(distances.min()), kept[int(distances.argmin())]
            for start in np.argsort(distances)[:3]:

                def cost(a):
                    tip = settled_tip(env, a, args.settle)
                    penalty = float(np.sum(np.maximum(np.abs(a) - 1.0, 0.0)))
                    return 10.0 if tip is None else float(np.linalg.norm(tip - target)) + penalty

                result = minimize(cost, kept[start], method="Nelder-Mead",
                                  options={"xatol": 1e-3, "fatol": 1e-4, "maxfev": 250})
                if result.fun < best_d:
                    best_d, best_a = float(result.fun), np.clip(result.x, -1.0, 1.0)
            tip = settled_tip(env, best_a, args.settle)
            best_d = float(np.linalg.norm(tip - target))
            rows.append([r, phi_deg, best_d, *best_a.round(4), *tip.round(4)])
            print(f"r {r:.2f} m  angle {phi_deg:+4.0f}°  floor {best_d:.4f} m", file=sys.stderr)

    with open(args.out, "w", newline="") as out:
        writer = csv.writer(out)
        writer.writerow(["radius_m", "angle_deg", "floor_m", "a1", "a2", "a3", "a4", "a5",
                         "tip_x_m", "tip_y_m"])
        for row in rows:
            writer.writerow([f"{v:.4f}" if isinstance(v, float) else v for v in row])
    floors = np.array([row[2] for row in rows])
    print(f"mean floor over the arcs: {floors.mean():.4f} m "
          f"(max {floors.max():.4f} m, {len(rows)} points)")
    by_radius = {}
    for row in rows:
        by_radius.setdefault(row[0], []).append(row[2])
    for r, values in sorted(by_radius.items()):
        print(f"  radius {r:.2f} m: mean floor {np.mean(values):.4f} m")


if __name__ == "__main__":
    main()
