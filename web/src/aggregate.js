// Curves of several runs on one axis: seeds grouped, their mean and spread on a common grid.

// A run's name without its seed token and the separators left at its ends ("n_steps_256-seed_3"
// → "n_steps_256", "ppo_case1_seed0" → "ppo_case1", "seed_3-tau_0.01" → "tau_0.01", "seed_42" →
// the name of the directory holding "seed_42"; a trailing time stamp goes too, "ppo-seed1-20261128-
// 093000" → "ppo"): runs that differ only by seed share a group, as in
// `tendril sweep` and `tendril plot`.
export function seedGroup(name, parent = '') {
  const stripped = name.replace(/(^|[-_])seed_?\d+/i, '')
    .replace(/[-_]\d{8}-\d{6}$/, '')
    .replace(/^[-_]+|[-_]+$/g, '');
  return stripped.length > 0 ? stripped : parent || 'seeds';
}

// The points of a curve with both coordinates finite, sorted by x.
export function cleanCurve(xs, ys) {
  const points = [];
  for (let i = 0; i < xs.length; i++) {
    if (Number.isFinite(xs[i]) && Number.isFinite(ys[i])) points.push([xs[i], ys[i]]);
  }
  points.sort((a, b) => a[0] - b[0]);
  return { x: points.map((p) => p[0]), y: points.map((p) => p[1]) };
}

// The curve's value at x by linear interpolation; null outside its range.
export function interpolate(curve, x) {
  const { x: xs, y: ys } = curve;
  if (xs.length === 0 || x < xs[0] || x > xs[xs.length - 1]) return null;
  let lo = 0;
  let hi = xs.length - 1;
  while (hi - lo > 1) {
    const mid = (lo + hi) >> 1;
    if (xs[mid] <= x) lo = mid;
    else hi = mid;
  }
  if (xs[hi] === xs[lo]) return ys[lo];
  const t = (x - xs[lo]) / (xs[hi] - xs[lo]);
  return ys[lo] + t * (ys[hi] - ys[lo]);
}

// Mean ± one standard deviation (population) of `curves` on `points` evenly spaced x values
// spanning all of them; at each x only the curves that reach it count (`n` says how many), so a
// run still training shortens nothing.
export function aggregate(curves, points = 200) {
  const usable = curves.filter((c) => c.x.length > 0);
  const result = { x: [], mean: [], lo: [], hi: [], n: [] };
  if (usable.length === 0) return result;
  const start = Math.min(...usable.map((c) => c.x[0]));
  const end = Math.max(...usable.map((c) => c.x[c.x.length - 1]));
  const count = end > start ? points : 1;
  for (let i = 0; i < count; i++) {
    const x = count === 1 ? start : start + ((end - start) * i) / (count - 1);
    const values = usable.map((c) => interpolate(c, x)).filter((v) => v !== null);
    result.x.push(x);
    result.n.push(values.length);
    if (values.length === 0) {
      result.mean.push(null);
      result.lo.push(null);
      result.hi.push(null);
      continue;
    }
    const mean = values.reduce((a, b) => a + b, 0) / values.length;
    const variance = values.reduce((a, b) => a + (b - mean) ** 2, 0) / values.length;
    const std = Math.sqrt(variance);
    result.mean.push(mean);
    result.lo.push(mean - std);
    result.hi.push(mean + std);
  }
  return result;
}
