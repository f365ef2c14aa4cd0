"""Figures of tendril runs without a browser: learning curves of runs and sweeps, snapshots of
recorded episodes, columns of any CSV file. Used through `tendril plot` (docs/plotting.md);
needs only NumPy and matplotlib (Debian's python3-numpy, python3-matplotlib)."""
