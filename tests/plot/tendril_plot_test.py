"""`tendril plot` on real runs: a finished run, a sweep over seeds, recorded episodes, CSV files.
Each figure must exist, be a valid PNG (or SVG/PDF) and not be blank; the Python episode reader
must find what the C++ reader finds.
    tendril_plot_test.py <tendril> <sample runs> <figure directory>"""
import csv
import os
import re
import shutil
import struct
import subprocess
import sys
import unittest
import zlib

TENDRIL, RUNS, OUT = sys.argv[1:4]
sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "python"))
# The build's tendril package (with its extension) before the sources', as `tendril plot` has it.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(TENDRIL))), "python"))

import numpy as np  # noqa: E402
import matplotlib.image  # noqa: E402

from tendril_plot.episode import EpisodeError, read_episode  # noqa: E402
from tendril_plot.runs import aggregate, natural_key, read_csv, seed_group  # noqa: E402
from tendril_plot.tables import distinct  # noqa: E402

RUN = os.path.join(RUNS, "sweep", "ppo_seed0")
EPISODES = os.path.join(RUN, "episodes")


def f32(text):
    """A number the C++ side printed from a float32, as that float32."""
    return float(np.float32(float(text)))


def plot(*args):
    return subprocess.run([TENDRIL, "plot", *args], capture_output=True, text=True, timeout=120)


class FigureTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        shutil.rmtree(OUT, ignore_errors=True)
        os.makedirs(OUT)

    def draw(self, name, *args):
        out = os.path.join(OUT, name)
        result = plot(*args, "--out", out)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertTrue(os.path.isfile(out), out)
        return out

    def assert_picture(self, path, min_ink=0.01):
        """A valid PNG (signature, IHDR with its CRC) whose pixels are not all one colour."""
        with open(path, "rb") as f:
            data = f.read()
        self.assertEqual(data[:8], b"\x89PNG\r\n\x1a\n", path)
        length, kind = struct.unpack(">I4s", data[8:16])
        self.assertEqual(kind, b"IHDR")
        width, height = struct.unpack(">II", data[16:24])
        (crc,) = struct.unpack(">I", data[16 + length:20 + length])
        self.assertEqual(zlib.crc32(data[12:16 + length]), crc, "IHDR checksum")
        self.assertGreater(width, 300)
        self.assertGreater(height, 200)
        pixels = matplotlib.image.imread(path)[..., :3]
        background = pixels[0, 0]
        ink = np.mean(np.abs(pixels - background).sum(axis=2) > 0.15)
        self.assertGreater(ink, min_ink, f"{path}: only {ink:.4f} of the pixels are drawn")
        self.assertLess(ink, 0.9, f"{path}: {ink:.4f} of the pixels differ from the background")

    def test_learning_curves_of_a_finished_run(self):
        self.assert_picture(self.draw("run.png", "curves", RUN))
        self.assert_picture(self.draw("run_eval.png", "curves", RUN, "--metric", "eval",
                                      "--title", "evaluations"))
        svg = self.draw("run.svg", "curves", RUN)
        with open(svg) as f:
            self.assertIn("<svg", f.read(2000))
        pdf = self.draw("run.pdf", "curves", RUN)
        with open(pdf, "rb") as f:
            self.assertEqual(f.read(5), b"%PDF-")

    def test_learning_curves_of_a_sweep_with_mean_and_spread(self):
        self.assert_picture(self.draw("sweep.png", "curves", os.path.join(RUNS, "sweep"),
                                      "--seeds", "--labels", "PPO on case 1"))
        self.assert_picture(self.draw("sweep_eval.png", "curves", os.path.join(RUNS, "sweep"),
                                      "--spread", "minmax", "--metric", "eval"))

    def test_sweeps_over_seeds_alone_are_one_curve_each(self):
        # Two sweeps whose runs are named by their seed alone: each sweep is one group.
        sweeps = [os.path.join(OUT, "seed_sweeps", name) for name in ("sweep_a", "sweep_b")]
        for k, sweep in enumerate(sweeps):
            for seed in (1, 2, 3):
                run = os.path.join(sweep, f"seed_{seed}")
                os.makedirs(run, exist_ok=True)
                with open(os.path.join(run, "progress.csv"), "w") as f:
                    f.write("time/total_timesteps,rollout/success_rate\n")
                    for step in range(1, 6):
                        f.write(f"{step * 1000},{min(1.0, 0.1 * step * (k + 1) + 0.01 * seed)}\n")
        self.assert_picture(self.draw("seed_sweeps.png", "curves", *sweeps, "--metric",
                                      "rollout/success_rate", "--labels", "A,B", "--seeds"))
        result = plot("curves", *sweeps, "--labels", "A,B,C", "--out",
                      os.path.join(OUT, "never_seed_sweeps.png"))
        self.assertEqual(result.returncode, 1)
        self.assertIn("there are 2: sweep_a, sweep_b", result.stderr)

    def test_episode_snapshots(self):
        recorded = sorted(f for f in os.listdir(EPISODES) if f.startswith("episode_"))
        self.assertEqual(len(recorded), 1)
        self.assert_picture(self.draw("episode.png", "episode", os.path.join(EPISODES, recorded[0])))
        self.assert_picture(self.draw("primitives.png", "episode",
                                      os.path.join(EPISODES, "all_primitives.tep"),
                                      "--snapshots", "4"))

    def test_columns_of_csv_files(self):
        files = [os.path.join(RUNS, "sweep", f"ppo_seed{s}", "progress.csv") for s in range(3)]
        self.assert_picture(self.draw("csv.png", "csv", *files, "--x", "time/total_timesteps",
                                      "--y", "train/entropy_loss,train/value_loss",
                                      "--kind", "scatter", "--logy", "symlog"))
        # A sweep summary's final evaluations with their spread as error bars.
        table = os.path.join(OUT, "configurations.csv")
        with open(table, "w") as f:
            f.write("configuration,algo.n_steps,final_eval_mean,final_eval_std\n"
                    "a,256,-10,4\nb,1024,5,2\nc,4096,8,1\n")
        self.assert_picture(self.draw("final.png", "csv", table, "--x", "algo.n_steps", "--y",
                                      "final_eval_mean", "--yerr", "final_eval_std",
                                      "--kind", "linepoints", "--logx"))
        result = plot("csv", table, "--x", "algo.n_steps", "--y", "final_eval_mean", "--yerr",
                      "final_eval_std,x", "--out", os.path.join(OUT, "never_yerr.png"))
        self.assertEqual(result.returncode, 1)
        self.assertIn("--yerr names 2 columns", result.stderr)

    def test_data_files_split_into_series_panels_paths_and_boxes(self):
        # A data file as tendril's collectors write them: a commented header, a column of names.
        table = os.path.join(OUT, "holds.csv")
        with open(table, "w") as f:
            f.write("# format: example v1\n# column coil: the coil held on\n"
                    "coil,pwm,time_s,angle_deg,lower,upper,goal_x,goal_y\n")
            for coil in ("pos_x", "neg_x"):
                for pwm in (10, 20, 30):
                    for t in range(20):
                        angle = (pwm - 10) * t / 4.0
                        f.write(f"{coil},{pwm},{t * 0.1:.1f},{angle},{int(pwm == 20)},"
                                f"{int(pwm == 30)},{t % 5},{-angle}\n")
        numbers, text = read_csv(table, with_text=True)
        self.assertEqual(len(numbers["pwm"]), 120)
        self.assertEqual(list(text["coil"][[0, 60]]), ["pos_x", "neg_x"])
        self.assertTrue(np.isnan(numbers["coil"]).all())
        self.assertEqual(numbers["angle_deg"][59], 20 * 19 / 4.0)
        self.assertEqual(distinct(np.array(["10", "9", "10", "30"])), ["9", "10", "30"])
        self.assertEqual(distinct(np.array(["S1", "S0", "S1"])), ["S1", "S0"])
        self.assert_picture(self.draw("split.png", "csv", table, "--x", "time_s", "--y",
                                      "angle_deg", "--split", "pwm", "--panels", "coil",
                                      "--colormap", "viridis", "--bold", "lower,upper"))
        self.assert_picture(self.draw("paths.png", "csv", table, "--x", "time_s,goal_x", "--y",
                                      "angle_deg,goal_y", "--styles", "solid,dashed", "--kind", "path",
                                      "--where", "pwm=30", "--panels", "coil", "--equal"))
        self.assert_picture(self.draw("panels_y.png", "csv", table, "--x", "time_s", "--y",
                                      "angle_deg,goal_y", "--panels", "y", "--split", "coil",
                                      "--where", "pwm!=10"))
        # Several files in panels by column: each file's series in its own colour, named.
        second = os.path.join(OUT, "holds_copy.csv")
        shutil.copy(table, second)
        self.assert_picture(self.draw("files_panels_y.png", "csv", table, second, "--x", "time_s",
                                      "--y", "angle_deg,goal_y", "--panels", "y",
                                      "--labels", "a,a,b,b", "--titles", "angle,goal"))
        self.assert_picture(self.draw("boxes.png", "csv", table, "--x", "coil", "--y",
                                      "angle_deg", "--kind", "box", "--split", "pwm"))
        for bad, message in ((["--where", "pwm"], "expected COLUMN=VALUE"),
                             (["--where", "nope=1"], "has no column 'nope'"),
                             (["--where", "pwm=99"], "no rows left"),
                             (["--split", "nope"], "has no column 'nope'"),
                             (["--x", "time_s,goal_x,pwm"], "--x names 3 columns"),
                             (["--titles", "one"], "--titles names 1 panels, there are 2")):
            out = os.path.join(OUT, "never_table.png")
            words = ["csv", table, "--x", "time_s", "--y", "angle_deg", "--panels", "coil", *bad]
            result = plot(*words, "--out", out)
            self.assertEqual(result.returncode, 1, bad)
            self.assertIn(message, result.stderr)
            self.assertFalse(os.path.exists(out))

    def test_csv_paths_keep_the_row_order(self):
        # A unit square walked round: joined in row order its x steps 0, 1, 1, 0, 0; sorted by x
        # (the default, for functions) 0, 0, 0, 1, 1.
        square = os.path.join(OUT, "square.csv")
        with open(square, "w") as f:
            f.write("x,y\n0,0\n1,0\n1,1\n0,1\n0,0\n")

        def five_point_line_xs(*options):
            svg = self.draw(f"square{len(options)}.svg", "csv", square, "--x", "x", "--y", "y",
                            *options)
            with open(svg) as f:
                text = f.read()
            paths = [re.findall(r"[ML] ([-0-9.e]+) [-0-9.e]+", d)
                     for d in re.findall(r'<path d="([^"]*)"', text)]
            lines = [[float(x) for x in p] for p in paths if len(p) == 5]
            self.assertEqual(len(lines), 1, "one drawn line of five points")
            return lines[0]

        xs = five_point_line_xs("--order", "rows", "--equal")
        self.assertEqual([xs[0] == xs[i] for i in range(5)], [True, False, False, True, True])
        self.assertAlmostEqual(xs[1], xs[2])
        xs = five_point_line_xs()
        self.assertEqual([xs[0] == xs[i] for i in range(5)], [True, True, True, False, False])
        self.assert_picture(self.draw("square.png", "csv", square, "--x", "x", "--y", "y",
                                      "--order", "rows", "--equal"))

    def test_csv_rectangles_and_marks(self):
        square = os.path.join(OUT, "square_marked.csv")
        with open(square, "w") as f:
            f.write("x,y\n0,0\n1,0\n1,1\n0,1\n0,0\n")

        def closed_quadrilaterals(name, *options):
            svg = self.draw(name, "csv", square, "--x", "x", "--y", "y", "--order", "rows",
                            *options)
            with open(svg) as f:
                text = f.read()
            ds = re.findall(r'<path d="([^"]*)"', text)
            return [d for d in ds if d.strip().endswith("z") and len(re.findall("[ML] ", d)) == 4]

        plain = closed_quadrilaterals("plain.svg")
        shaded = closed_quadrilaterals("shaded.svg", "--rect", "0.2,0.6,0.1,0.5", "--mark",
                                       "0.5,0.5:target")
        self.assertEqual(len(shaded), len(plain) + 1, "one rectangle more")
        self.assert_picture(self.draw("shaded.png", "csv", square, "--x", "x", "--y", "y",
                                      "--rect", "0.2,0.6,0.1,0.5:box", "--mark", "0.5,0.5"))
        out = os.path.join(OUT, "bad_rect.png")
        result = plot("csv", square, "--x", "x", "--y", "y", "--rect", "0,1,2", "--out", out)
        self.assertEqual(result.returncode, 2)
        self.assertIn("expected X0,X1,Y0,Y1[:LABEL], got '0,1,2'", result.stderr)
        self.assertFalse(os.path.exists(out))

    def test_value_map_with_contours_paths_and_circles(self):
        # A 21 × 11 grid in scrambled row order: V = 10 − x² − y², an indicator of x < 0.
        grid = os.path.join(OUT, "value_grid.csv")
        points = [(x / 10, y / 10) for y in range(-5, 6) for x in range(-10, 11)]
        points = points[1::2] + points[0::2]
        with open(grid, "w") as f:
            f.write("x,y,value,left\n")
            for x, y in points:
                f.write(f"{x},{y},{10 - x * x - y * y},{1 if x < 0 else 0}\n")
        path = os.path.join(OUT, "value_path.csv")
        with open(path, "w") as f:
            f.write("px,py\n-0.5,0\n0,0.3\n0.5,0\n")

        def count_curves(name, *options):
            svg = self.draw(name, "map", grid, "--x", "x", "--y", "y", "--z", "value", *options)
            with open(svg) as f:
                return len(re.findall(r'<path d="M', f.read()))

        plain = count_curves("map_plain.svg")
        drawn = count_curves("map_drawn.svg", "--contour", "left:0.5:x < 0", "--path",
                             path + ":px,py:trajectory", "--circle", "0,0,0.4:circle")
        self.assertGreaterEqual(drawn, plain + 3, "a contour, a path and a circle")
        self.assert_picture(self.draw("map.png", "map", grid, "--x", "x", "--y", "y", "--z",
                                      "value", "--contour", "value:6,9", "--equal"))
        with open(os.path.join(OUT, "holey.csv"), "w") as f:
            f.write("x,y,value\n0,0,1\n1,0,2\n0,1,3\n")
        out = os.path.join(OUT, "holey.png")
        result = plot("map", os.path.join(OUT, "holey.csv"), "--x", "x", "--y", "y", "--z",
                      "value", "--out", out)
        self.assertEqual(result.returncode, 1)
        self.assertIn("do not form a full grid", result.stderr)
        self.assertFalse(os.path.exists(out))

    def test_bad_input_is_named_and_writes_nothing(self):
        out = os.path.join(OUT, "never.png")
        result = plot("csv", os.path.join(RUN, "progress.csv"), "--x", "nope", "--y",
                      "rollout/ep_rew_mean", "--out", out)
        self.assertEqual(result.returncode, 1)
        self.assertIn("has no column 'nope'", result.stderr)
        result = plot("curves", RUN, "--metric", "eval:nope", "--out", out)
        self.assertEqual(result.returncode, 1)
        self.assertIn("eval.csv has no column 'nope'", result.stderr)
        result = plot("curves", os.path.join(RUNS, "missing"), "--out", out)
        self.assertEqual(result.returncode, 1)
        self.assertIn("neither a run directory", result.stderr)
        result = plot("curves", RUN, "--out", os.path.join(OUT, "figure.jpeg"))
        self.assertEqual(result.returncode, 1)
        self.assertIn(".png, .svg or .pdf", result.stderr)
        self.assertFalse(os.path.exists(out))


class SeedGroupTest(unittest.TestCase):
    def test_the_rule_of_the_sweep_summary(self):
        # The cases of tests/core/run_curves_test.cpp (SeedGroup): the figures group by that code.
        cases = {("n_steps_256-seed_3", ""): "n_steps_256", ("ppo_case1_seed0", ""): "ppo_case1",
                 ("seed_3-tau_0.01", ""): "tau_0.01",
                 ("n_steps_64-seed_12-gamma_0.9", ""): "n_steps_64-gamma_0.9",
                 ("PPO_Seed7", ""): "PPO", ("seed_42", "ur5_ppo_base"): "ur5_ppo_base",
                 ("seed_42", ""): "seeds", ("tau_0.01", ""): "tau_0.01",
                 ("ppo_pendulum-seed1-20261128-093000", ""): "ppo_pendulum",
                 ("ppo_pendulum-seed2-20261128-093512", ""): "ppo_pendulum",
                 ("lr_0.001-20261128-093000", ""): "lr_0.001"}
        for (name, parent), group in cases.items():
            self.assertEqual(seed_group(name, parent), group, name)

    def test_curves_are_aggregated_over_the_range_every_seed_covers(self):
        # y = x on [0, 10] and y = 3 x on [5, 20]: on the common range [5, 10] the mean is 2 x
        # and the population std x (core/run_curves, as the sweep summaries compute it).
        stats = aggregate([{"x": np.array([0.0, 10.0]), "y": np.array([0.0, 10.0])},
                           {"x": np.array([5.0, 20.0]), "y": np.array([15.0, 60.0])}], points=6)
        np.testing.assert_allclose(stats["x"], [5, 6, 7, 8, 9, 10])
        np.testing.assert_allclose(stats["mean"], 2 * stats["x"])
        np.testing.assert_allclose(stats["std"], stats["x"])
        self.assertEqual(stats["n"], 2)

    def test_runs_are_ordered_by_the_numbers_in_their_names(self):
        # A sweep's directory lists batch sizes as text ("1024" < "256"); curves, their
        # --labels and legends follow the values.
        names = ["n_steps_1024-seed_0", "n_steps_16384-seed_0", "n_steps_256-seed_1",
                 "n_steps_256-seed_0", "n_steps_4096-seed_0", "tau_0.005", "tau_0.01"]
        self.assertEqual(sorted(names, key=natural_key),
                         ["n_steps_256-seed_0", "n_steps_256-seed_1", "n_steps_1024-seed_0",
                          "n_steps_4096-seed_0", "n_steps_16384-seed_0", "tau_0.005", "tau_0.01"])


class EpisodeReaderTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        os.makedirs(OUT, exist_ok=True)

    def test_reads_what_the_cpp_reader_reads(self):
        episode = read_episode(os.path.join(EPISODES, "all_primitives.tep"))
        with open(os.path.join(EPISODES, "all_primitives.csv")) as f:
            expected = list(csv.DictReader(f))
        self.assertEqual(len(episode.frames), len(expected))
        self.assertEqual(episode.metadata["env"], "every Scene primitive")
        for frame, row in zip(episode.frames, expected):
            self.assertEqual(frame["step"], int(row["step"]))
            self.assertEqual(frame["time"], float(row["time"]))
            self.assertEqual(frame["reward"], float(row["reward"]))
            self.assertEqual(list(frame["rods"][0]["points"][-1]),
                             [f32(row["tip_x"]), f32(row["tip_y"]), f32(row["tip_z"])])
            self.assertEqual(frame["boxes"][0]["orientation"][0], f32(row["box_w"]))
            self.assertEqual(frame["lattices"][0]["nodes"][0, 0], f32(row["lattice_x0"]))
            self.assertEqual(frame["values"]["distance"], f32(row["distance"]))
            for kind, count in (("rods", 1), ("spheres", 1), ("cylinders", 2), ("boxes", 1),
                                ("planes", 1), ("lattices", 1), ("paths", 1)):
                self.assertEqual(len(frame[kind]), count, kind)
        self.assertTrue(episode.frames[0]["cylinders"][0]["capped"])
        self.assertEqual(episode.frames[0]["lattices"][0]["springs"].shape, (13, 2))
        self.assertAlmostEqual(episode.summary["episode_return"],
                               sum(float(r["reward"]) for r in expected), places=9)

    def test_damage_and_truncation_are_named(self):
        with open(os.path.join(EPISODES, "all_primitives.tep"), "rb") as f:
            data = bytearray(f.read())
        cut = os.path.join(OUT, "cut.tep")
        with open(cut, "wb") as f:
            f.write(data[:len(data) // 2])
        with self.assertRaisesRegex(EpisodeError, "ends inside a record"):
            read_episode(cut)
        partial = read_episode(cut, partial=True)
        self.assertTrue(partial.truncated)
        self.assertGreater(len(partial.frames), 10)
        data[len(data) // 2] ^= 0x20
        flipped = os.path.join(OUT, "flipped.tep")
        with open(flipped, "wb") as f:
            f.write(data)
        with self.assertRaisesRegex(EpisodeError, "checksum mismatch"):
            read_episode(flipped)


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1], verbosity=2)
