// Line charts of curves that each have their own x values (uPlot), with optional bands
// (mean ± spread) drawn under their curve, and smoothing.
import uPlot from 'uplot';
import 'uplot/dist/uPlot.min.css';

export const palette = [
  '#1f77b4', '#d62728', '#2ca02c', '#ff7f0e', '#9467bd',
  '#8c564b', '#e377c2', '#17becf', '#7f7f7f', '#bcbd22',
];

function translucent(hex, alpha) {
  const value = parseInt(hex.slice(1), 16);
  return `rgba(${(value >> 16) & 255},${(value >> 8) & 255},${value & 255},${alpha})`;
}

// One number for a readout (legend, table): three significant digits, k and M for large ones.
export function formatNumber(value) {
  if (value === null || value === undefined || !Number.isFinite(value)) return '–';
  const magnitude = Math.abs(value);
  const trim = (text) => (text.includes('.') ? text.replace(/\.?0+$/, '') : text);
  if (magnitude >= 1e6) return `${trim((value / 1e6).toFixed(2))}M`;
  if (magnitude >= 1e3) return `${trim((value / 1e3).toFixed(magnitude >= 1e5 ? 0 : 1))}k`;
  if (magnitude >= 100 || value === 0) return value.toFixed(0);
  return String(Number(value.toPrecision(3)));
}

// A value in a table (the run list's returns): four significant digits below 100,000, so that
// −1,122.5 reads −1123 and not −1.1k.
export function formatReadout(value) {
  if (value === null || value === undefined || !Number.isFinite(value)) return '–';
  if (Math.abs(value) >= 1e5) return formatNumber(value);
  return String(Number(value.toPrecision(4)));
}

// The labels of an axis's ticks, `increment` apart: one unit (k, M) and as many decimals as the
// increment needs for all of them, so that neighbouring ticks never read the same (−1.10k,
// −1.12k, … where one decimal would print −1.1k twice).
export function formatTicks(ticks, increment) {
  const finite = ticks.filter(Number.isFinite);
  if (finite.length === 0) return ticks.map(() => '');
  const largest = Math.max(...finite.map(Math.abs));
  let step = Math.abs(increment);
  if (!Number.isFinite(step) || step === 0) {
    const gaps = finite.slice(1).map((v, i) => Math.abs(v - finite[i])).filter((g) => g > 0);
    step = gaps.length > 0 ? Math.min(...gaps) : largest || 1;
  }
  if (largest > 0 && largest < 1e-3) {  // tiny values (learning rates): powers of ten
    const digits = Math.min(6, Math.max(0, Math.ceil(Math.log10(largest / step) - 1e-9)));
    return ticks.map((v) => (Number.isFinite(v) ? (v === 0 ? '0' : v.toExponential(digits)) : ''));
  }
  const [unit, suffix] = largest >= 1e6 ? [1e6, 'M'] : largest >= 1e3 ? [1e3, 'k'] : [1, ''];
  const decimals = Math.min(10, Math.max(0, Math.ceil(-Math.log10(step / unit) - 1e-9)));
  return ticks.map((v) => {
    if (!Number.isFinite(v)) return '';
    const text = (v / unit).toFixed(decimals);
    return `${/^-0(\.0*)?$/.test(text) ? text.slice(1) : text}${suffix}`;
  });
}

// TensorBoard's smoothing: an exponential moving average with weight `weight` in [0, 1),
// debiased at the start (so the first points are not pulled towards zero); gaps are kept.
export function smooth(values, weight) {
  if (!(weight > 0)) return values.slice();
  let last = 0;
  let debias = 0;
  return values.map((v) => {
    if (!Number.isFinite(v)) return null;
    last = last * weight + (1 - weight) * v;
    debias = debias * weight + (1 - weight);
    return last / debias;
  });
}

export class CurveChart {
  // options: { title, xLabel, yLabel, height, logY, compact } — compact: no legend and no axis
  // labels (the small charts of a grid, titled by their metric).
  constructor(container, options = {}) {
    this.container = container;
    this.options = options;
    this.plot = null;
    this.signature = '';
    this.resizer = new ResizeObserver(() => {
      if (this.plot) this.plot.setSize(this.size());
    });
    this.resizer.observe(container);
  }

  size() {
    return {
      width: Math.max(this.container.clientWidth, 240),
      height: this.options.height || 300,
    };
  }

  // curves: [{ label, x, y, color, lo?, hi?, smoothing? }]; x ascending. A curve with
  // smoothing > 0 is drawn smoothed over its raw values, which stay faint behind it.
  setCurves(curves) {
    const tables = [];
    const series = [{ label: this.options.xLabel || 'x', value: (u, v) => formatNumber(v) }];
    const bands = [];
    const hidden = [];  // the bands' bounds and the raw curves under smoothed ones
    curves.forEach((curve, i) => {
      const color = curve.color || palette[i % palette.length];
      const x = Float64Array.from(curve.x);
      const raw = curve.y.map((v) => (Number.isFinite(v) ? v : null));
      if (curve.smoothing > 0) {
        hidden.push(series.length);
        tables.push([x, raw]);
        series.push({
          label: `${curve.label} (raw)`,
          stroke: translucent(color, 0.25),
          width: 1,
          spanGaps: true,
          points: { show: false },
          value: (u, v) => formatNumber(v),
        });
      }
      tables.push([x, curve.smoothing > 0 ? smooth(raw, curve.smoothing) : raw]);
      series.push({
        label: curve.label,
        stroke: color,
        width: curve.width || 2,
        dash: curve.dash,
        spanGaps: true,
        points: { show: curve.x.length < 40, size: 4 },
        value: (u, v) => formatNumber(v),
      });
      if (curve.lo && curve.hi) {
        const index = series.length;
        hidden.push(index, index + 1);
        for (const [bound, values] of [['+σ', curve.hi], ['−σ', curve.lo]]) {
          tables.push([x, values.map((v) => (Number.isFinite(v) ? v : null))]);
          series.push({
            label: `${curve.label} ${bound}`,
            stroke: translucent(color, 0.35),
            width: 1,
            spanGaps: true,
            points: { show: false },
            value: (u, v) => formatNumber(v),
          });
        }
        bands.push({ series: [index, index + 1], fill: translucent(color, 0.18) });
      }
    });
    const data = tables.length > 0 ? uPlot.join(tables) : [[]];
    const signature = [this.options.yLabel, this.options.xLabel, this.options.logY,
      ...series.map((s) => s.label)].join('\n');
    if (this.plot && signature === this.signature) {
      this.plot.setData(data);
      return;
    }
    if (this.plot) this.plot.destroy();
    this.signature = signature;
    const container = this.container;
    this.plot = new uPlot(
      {
        ...this.size(),
        title: this.options.title,
        series,
        bands,
        scales: { x: { time: false }, y: this.options.logY ? { distr: 3 } : {} },
        axes: [
          {
            label: this.options.compact ? undefined : this.options.xLabel,
            values: (u, ticks, axis, space, increment) => formatTicks(ticks, increment),
          },
          {
            label: this.options.compact ? undefined : this.options.yLabel,
            size: 64,
            values: (u, ticks, axis, space, increment) => {
              const labels = formatTicks(ticks, increment);
              container.dataset.yTicks = JSON.stringify(labels);  // what the axis shows
              return labels;
            },
          },
        ],
        legend: { live: true, show: !this.options.compact },
      },
      data,
      this.container,
    );
    const rows = this.plot.root.querySelectorAll('.u-legend .u-series');
    for (const i of hidden) if (rows[i]) rows[i].style.display = 'none';
  }

  destroy() {
    this.resizer.disconnect();
    if (this.plot) this.plot.destroy();
    this.plot = null;
  }
}
