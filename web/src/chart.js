// Line charts of curves that each have their own x values (uPlot), with optional bands
// (mean ± spread) drawn under their curve.
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

export function formatNumber(value) {
  if (value === null || value === undefined || !Number.isFinite(value)) return '–';
  const magnitude = Math.abs(value);
  const trim = (text) => (text.includes('.') ? text.replace(/\.?0+$/, '') : text);
  if (magnitude >= 1e6) return `${trim((value / 1e6).toFixed(2))}M`;
  if (magnitude >= 1e3) return `${trim((value / 1e3).toFixed(magnitude >= 1e5 ? 0 : 1))}k`;
  if (magnitude >= 100 || value === 0) return value.toFixed(0);
  return String(Number(value.toPrecision(3)));
}

export class CurveChart {
  // options: { title, xLabel, yLabel, height }
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
      width: Math.max(this.container.clientWidth, 300),
      height: this.options.height || 300,
    };
  }

  // curves: [{ label, x, y, color, lo?, hi? }]; x ascending.
  setCurves(curves) {
    const tables = [];
    const series = [{ label: this.options.xLabel || 'x', value: (u, v) => formatNumber(v) }];
    const bands = [];
    const hidden = [];  // the bands' bounds, left out of the legend
    curves.forEach((curve, i) => {
      const color = curve.color || palette[i % palette.length];
      const x = Float64Array.from(curve.x);
      tables.push([x, curve.y.map((v) => (Number.isFinite(v) ? v : null))]);
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
    const signature = [this.options.yLabel, ...series.map((s) => s.label)].join('\n');
    if (this.plot && signature === this.signature) {
      this.plot.setData(data);
      return;
    }
    if (this.plot) this.plot.destroy();
    this.signature = signature;
    this.plot = new uPlot(
      {
        ...this.size(),
        title: this.options.title,
        series,
        bands,
        scales: { x: { time: false } },
        axes: [
          { label: this.options.xLabel, values: (u, ticks) => ticks.map(formatNumber) },
          { label: this.options.yLabel, values: (u, ticks) => ticks.map(formatNumber), size: 60 },
        ],
        legend: { live: true },
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
