"""A beam policy's tip distance by the target's radius and angle on the arcs (seed 003, tasks 1–2),
from `tendril run … --trace` files (Python's standard library only).

The target of a step is observation 14–15 (x, y; m) and the tip after it next_observation 10–11
(Beam/TrajectoryFollow-v0's observation, docs/envs.md); the arc point is r·(sin φ, cos φ) about
the beam's base. Prints, and writes as CSV, the mean distance per radius band (0.1 m wide from
0.2 m) and per angle band (40° wide from −80°) over every step of the traces given (the
reachability floor of the same points is docs/results/beam/reachability.csv).

  build/apps/tendril run RUN --steps 3000 --seed 1000 --trace trace.csv
  /usr/bin/python3 docs/results/beam/error_by_arc.py --out error_by_arc.csv LABEL=trace.csv ...
"""
import argparse
import csv
import math


def bands(value, start, width, count):
    index = int((value - start) // width)
    return min(max(index, 0), count - 1)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", required=True)
    parser.add_argument("traces", nargs="+", help="LABEL=trace.csv")
    args = parser.parse_args()
    rows = []
    for item in args.traces:
        label, path = item.split("=", 1)
        radius_sums = [[0.0, 0] for _ in range(4)]
        angle_sums = [[0.0, 0] for _ in range(4)]
        with open(path, newline="") as trace:
            for step in csv.DictReader(trace):
                tx, ty = float(step["observation_14"]), float(step["observation_15"])
                px, py = float(step["next_observation_10"]), float(step["next_observation_11"])
                distance = math.hypot(px - tx, py - ty)
                radius = math.hypot(tx, ty)
                angle = math.degrees(math.atan2(tx, ty))
                r = radius_sums[bands(radius, 0.2, 0.1, 4)]
                a = angle_sums[bands(angle, -80.0, 40.0, 4)]
                r[0] += distance; r[1] += 1
                a[0] += distance; a[1] += 1
        for k, (total, count) in enumerate(radius_sums):
            low = 0.2 + 0.1 * k
            rows.append([label, "radius_m", f"{low:.1f}-{low + 0.1:.1f}", count,
                         f"{total / count:.4f}" if count else ""])
        for k, (total, count) in enumerate(angle_sums):
            low = -80 + 40 * k
            rows.append([label, "angle_deg", f"{low}-{low + 40}", count,
                         f"{total / count:.4f}" if count else ""])
    with open(args.out, "w", newline="") as out:
        writer = csv.writer(out)
        writer.writerow(["policy", "band_of", "band", "steps", "mean_distance_m"])
        writer.writerows(rows)
    for row in rows:
        print(",".join(str(v) for v in row))


if __name__ == "__main__":
    main()
