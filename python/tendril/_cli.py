"""The `tendril` command of an installed package: runs the command-line program installed
beside the package (tendril/bin/tendril), pointed at this interpreter for `tendril plot` and at
the installed dashboard page for `tendril serve`."""
import os
import sys


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    program = os.path.join(here, "bin", "tendril")
    if not os.access(program, os.X_OK):
        sys.exit(f"tendril: the command-line program is missing from the package ({program}); "
                 "reinstall it with `pip install .`")
    environment = dict(os.environ)
    # `tendril plot` runs `python -m tendril_plot` with this interpreter and this installation.
    environment.setdefault("TENDRIL_PYTHON", sys.executable)
    environment.setdefault("TENDRIL_PLOT_PATH", os.path.dirname(here))
    arguments = sys.argv[1:]
    pages = os.path.join(here, "dashboard")
    if arguments[:1] == ["serve"] and "--assets" not in arguments and os.path.isdir(pages):
        arguments += ["--assets", pages]
    os.execve(program, [program, *arguments], environment)


if __name__ == "__main__":
    main()
