"""Observation and action spaces: Gymnasium's Box and Discrete when Gymnasium is installed,
otherwise small stand-ins with the same attributes and methods (shape, dtype, low, high, n,
sample, contains, seed)."""
import numpy as np

try:
    from gymnasium.spaces import Box, Discrete

    HAVE_GYMNASIUM = True
except ImportError:  # the package works without Gymnasium, with these stand-ins
    HAVE_GYMNASIUM = False

    class _Space:
        def __init__(self, shape, dtype, seed=None):
            self.shape = shape
            self.dtype = np.dtype(dtype)
            self.np_random = np.random.default_rng(seed)

        def seed(self, seed=None):
            self.np_random = np.random.default_rng(seed)
            return [seed]

        def __contains__(self, x):
            return self.contains(x)

    class Box(_Space):
        """Per-component bounds (possibly infinite), float32, as gymnasium.spaces.Box."""

        def __init__(self, low, high, dtype=np.float32, seed=None):
            super().__init__(np.shape(low), dtype, seed)
            self.low = np.asarray(low, dtype=self.dtype)
            self.high = np.asarray(high, dtype=self.dtype)

        def sample(self):
            # Uniform where bounded, standard normal where unbounded (Gymnasium's rule).
            bounded = np.isfinite(self.low) & np.isfinite(self.high)
            out = self.np_random.normal(size=self.shape)
            out[bounded] = self.np_random.uniform(self.low[bounded], self.high[bounded])
            return out.astype(self.dtype)

        def contains(self, x):
            x = np.asarray(x)
            return bool(x.shape == self.shape and np.all(x >= self.low) and np.all(x <= self.high))

        def __repr__(self):
            return f"Box({self.low.min()}, {self.high.max()}, {self.shape}, {self.dtype})"

    class Discrete(_Space):
        """Integers 0 … n−1, as gymnasium.spaces.Discrete."""

        def __init__(self, n, seed=None):
            super().__init__((), np.int64, seed)
            self.n = np.int64(n)
            self.start = np.int64(0)

        def sample(self):
            return np.int64(self.np_random.integers(self.n))

        def contains(self, x):
            x = np.asarray(x)
            return bool(x.shape == () and x.dtype.kind in "iu" and 0 <= int(x) < self.n)

        def __repr__(self):
            return f"Discrete({self.n})"


def from_native(space):
    """The space described by the extension's {"kind": ...} dictionary."""
    if space["kind"] == "discrete":
        return Discrete(int(space["n"]))
    return Box(space["low"], space["high"], dtype=np.float32)
