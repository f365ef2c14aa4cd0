"""`tendril plot` (python -m tendril_plot): figures from runs, sweeps, episodes and CSV files."""
import argparse
import sys

from .episode import EpisodeError
from .runs import PlotError


def size(text):
    try:
        width, height = (float(v) for v in text.split(","))
    except ValueError:
        raise argparse.ArgumentTypeError("expected WIDTH,HEIGHT in inches, e.g. 6.4,4")
    return (width, height)


def resolution(text):
    try:
        width, height = (int(v) for v in text.lower().split("x"))
    except ValueError:
        raise argparse.ArgumentTypeError("expected WIDTHxHEIGHT in pixels, e.g. 960x540")
    if width <= 0 or height <= 0 or width % 2 or height % 2:
        raise argparse.ArgumentTypeError("a video's width and height must be positive and even")
    return (width, height)


def numbers_with_label(text, count, form):
    values, _, label = text.partition(":")
    try:
        numbers = [float(v) for v in values.split(",")]
    except ValueError:
        numbers = []
    if len(numbers) != count:
        raise argparse.ArgumentTypeError(f"expected {form}, got '{text}'")
    return numbers, label or None


def rectangle(text):
    return numbers_with_label(text, 4, "X0,X1,Y0,Y1[:LABEL]")


def mark(text):
    return numbers_with_label(text, 2, "X,Y[:LABEL]")


def circle(text):
    return numbers_with_label(text, 3, "X,Y,R[:LABEL]")


def common(parser, default_size):
    parser.add_argument("-o", "--output", "--out", dest="out", required=True,
                        help="the figure's file: .png, .svg or .pdf (a video: .mp4)")
    parser.add_argument("--title")
    parser.add_argument("--xlabel")
    parser.add_argument("--ylabel")
    parser.add_argument("--size", type=size, default=default_size, help="inches, WIDTH,HEIGHT")
    parser.add_argument("--dpi", type=int, default=150)


def main(argv):
    parser = argparse.ArgumentParser(prog="tendril plot", description=__doc__)
    kinds = parser.add_subparsers(dest="figure", required=True)

    c = kinds.add_parser("curves", help="learning curves of runs and sweeps",
                         description="Learning curves of runs; directories of runs (sweeps) "
                         "add every run inside. Runs whose names differ only by seed "
                         "(seed_3, _seed3) are drawn as their mean with a band.")
    c.add_argument("runs", nargs="+", help="run directories or directories of runs")
    c.add_argument("--metric", default="rollout/ep_rew_mean",
                   help="a progress.csv column, 'eval' for eval.csv's mean return, or "
                        "'eval:<column>' for another eval.csv column (eval:success_rate)")
    c.add_argument("--x", default="time/total_timesteps", help="progress.csv column on the x axis")
    c.add_argument("--group", choices=["seeds", "none"], default="seeds")
    c.add_argument("--spread", choices=["std", "minmax", "none"], default="std")
    c.add_argument("--seeds", action="store_true", help="also draw each seed thinly")
    c.add_argument("--labels", help="comma-separated names of the curves, in order")
    c.add_argument("--logx", action="store_true")
    c.add_argument("--logy", nargs="?", const="log", choices=["log", "symlog"])
    common(c, (6.4, 4.0))

    e = kinds.add_parser("episode", help="snapshots of a recorded episode",
                         description="The arm's shape at evenly spaced times in 3D and seen "
                         "from above, the target's path, obstacles, and reward and distance "
                         "over time.")
    e.add_argument("episode", help="a recorded episode (.tep)")
    e.add_argument("--snapshots", type=int, default=6)
    e.add_argument("--up", choices=["auto", "x", "y", "z"], default="auto",
                   help="the lab axis drawn upwards (auto: the first rod's direction)")
    e.add_argument("--colormap", default="Oranges")
    e.add_argument("--video", action="store_true",
                   help="write a video of the episode instead (--out FILE.mp4, .webm or .gif): "
                        "the scene in 3D from one view, the tip's and targets' paths growing")
    e.add_argument("--speed", type=float, default=0.0,
                   help="video: episode seconds per second of video (default 0: every step a "
                        "frame, at the recording's rate up to 30 per second)")
    e.add_argument("--fps", type=float, default=0.0, help="video: frames per second")
    e.add_argument("--resolution", type=resolution, default=(960, 540),
                   help="video: WIDTHxHEIGHT in pixels, both even (default 960x540)")
    common(e, (10.0, 5.6))

    v = kinds.add_parser("csv", help="columns of CSV files",
                         description="Any columns of one or more CSV files against one column "
                         "(lines starting with '#' are skipped), split into series and panels "
                         "by the values of other columns.")
    v.add_argument("files", nargs="+")
    v.add_argument("--x", required=True, help="the column on the x axis, or one per --y column "
                   "(paths: --x theta_x,goal_x --y theta_y,goal_y)")
    v.add_argument("--y", required=True, help="comma-separated columns on the y axis")
    v.add_argument("--kind", choices=["line", "linepoints", "scatter", "path", "box"], default="line",
                   help="line: sorted by x; path: in the rows' order (a trajectory in the plane); "
                   "box: box plots of y at each distinct value of x")
    v.add_argument("--yerr", help="comma-separated columns, one per --y column: each point's ± "
                   "error, drawn as error bars (e.g. final_eval_std of a sweep's summary)")
    v.add_argument("--order", choices=["x", "rows"], default="x",
                   help="join the points sorted by x (a function) or in the file's row order "
                   "(a path, e.g. a trajectory; the same as --kind path)")
    v.add_argument("--rect", action="append", type=rectangle, default=[],
                   help="X0,X1,Y0,Y1[:LABEL]: a shaded rectangle in data units (an obstacle, a "
                   "region); repeatable")
    v.add_argument("--mark", action="append", type=mark, default=[],
                   help="X,Y[:LABEL]: a marked point in data units (a target); repeatable")
    v.add_argument("--labels", help="comma-separated names, one per file and column")
    v.add_argument("--where", action="append", metavar="COLUMN=VALUE",
                   help="keep only the rows whose COLUMN is (=) or is not (!=) VALUE; repeatable")
    v.add_argument("--split", metavar="COLUMN", help="one series per distinct value of COLUMN")
    v.add_argument("--panels", metavar="COLUMN",
                   help="one panel per distinct value of COLUMN, or 'y': one per --y column")
    v.add_argument("--columns", type=int, help="panels per row (default: up to 3)")
    v.add_argument("--titles", help="comma-separated titles of the panels, in order")
    v.add_argument("--colormap", help="colour the --split series along this matplotlib colormap, "
                   "with a colour bar (e.g. viridis for a sweep of PWM values)")
    v.add_argument("--bold", metavar="COLUMNS", help="comma-separated 0/1 columns: series with a 1 "
                   "in one of them are drawn thick, in their own colour, and named in the legend")
    v.add_argument("--styles", help="comma-separated line styles, one per --y column: solid, dashed, dotted, dashdot")
    v.add_argument("--equal", action="store_true", help="equal scales on x and y (paths, planes)")
    v.add_argument("--marker-size", type=float, default=12, help="scatter dots' area, points²")
    v.add_argument("--logx", action="store_true")
    v.add_argument("--logy", nargs="?", const="log", choices=["log", "symlog"])
    common(v, (6.4, 4.0))

    m = kinds.add_parser("map", help="a value over a plane: heat map, contours, paths",
                         description="A column of a CSV grid (e.g. `tendril safety map`'s) as a "
                         "heat map over two others, with contour lines at given levels of it or "
                         "of other columns, and paths and circles drawn over it.")
    m.add_argument("file")
    m.add_argument("--x", required=True, help="the column on the x axis")
    m.add_argument("--y", required=True, help="the column on the y axis")
    m.add_argument("--z", required=True, help="the column drawn as colour")
    m.add_argument("--zlabel", help="the colour bar's label (default: the column)")
    m.add_argument("--vmin", type=float)
    m.add_argument("--vmax", type=float)
    m.add_argument("--colormap", default="viridis")
    m.add_argument("--contour", action="append", metavar="COLUMN:LEVEL[,LEVEL...][:LABEL]",
                   help="contour lines of a column at the levels; repeatable (solid, dashed, "
                   "dotted, ... in turn)")
    m.add_argument("--level-labels", action="store_true", help="write the level on single contours")
    m.add_argument("--path", action="append", metavar="FILE:XCOLUMN,YCOLUMN[:LABEL]",
                   help="a path from another CSV file's columns, in row order; repeatable")
    m.add_argument("--circle", action="append", type=circle, metavar="X,Y,R[:LABEL]",
                   help="a circle in data units (a constraint boundary); repeatable")
    m.add_argument("--equal", action="store_true", help="equal scales on x and y")
    common(m, (6.4, 5.0))

    args = parser.parse_args(argv)
    if args.figure == "episode" and args.video:
        from .video import episode_video  # tendril's extension draws the frames, not matplotlib

        try:
            episode_video(args)
        except EpisodeError as error:
            print(f"tendril plot: error: {error}", file=sys.stderr)
            return 1
        return 0
    from . import figures, maps, tables  # matplotlib loads only when a figure is drawn

    try:
        {"curves": figures.curves, "episode": figures.episode, "csv": tables.csv_columns,
         "map": maps.value_map}[args.figure](args)
    except (PlotError, EpisodeError) as error:
        print(f"tendril plot: error: {error}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
