// Several runs on one chart: each run its own curve, or the seeds of each group as their mean
// with a ± one-standard-deviation band.
import { api, LiveCsv } from '../api.js';
import { aggregate, cleanCurve, seedGroup } from '../aggregate.js';
import { CurveChart, palette, smooth } from '../chart.js';
import { compareHash, h, link, runHash, setStatus } from '../dom.js';

const EVAL = 'eval/mean_return';

export async function showCompare(container, query) {
  const paths = (query.get('runs') || '').split('|').filter((p) => p.length > 0);
  if (paths.length === 0) throw new Error('no runs to compare');
  const grouped = query.get('group') === '1';
  let metric = query.get('metric') || 'rollout/ep_rew_mean';
  const described = await Promise.all(paths.map((path) => api.run(path)));
  const runs = paths.map((path, i) => ({
    path,
    name: path.split('/').pop() || path,
    files: described[i].files,
    progress: new LiveCsv(`${path ? `${path}/` : ''}progress.csv`),
    evaluation: new LiveCsv(`${path ? `${path}/` : ''}eval.csv`),
  }));
  const metricSelect = h('select', { 'aria-label': 'metric' });
  const groupBox = h('input', { type: 'checkbox', id: 'group' });
  groupBox.checked = grouped;
  groupBox.addEventListener('change', () => {
    location.hash = compareHash(paths, { group: groupBox.checked, metric });
  });
  metricSelect.addEventListener('change', () => {
    metric = metricSelect.value;
    draw();
  });
  const smoothing = h('input', {
    type: 'range', min: 0, max: 0.99, step: 0.01, 'aria-label': 'smoothing',
    value: localStorage.getItem('tendril.smoothing') ?? 0.6,
  });
  smoothing.addEventListener('input', () => {
    localStorage.setItem('tendril.smoothing', smoothing.value);
    draw();
  });
  const chartBox = h('div', { class: 'chart' });
  const legend = h('ul', { class: 'groups' });
  container.append(
    h('h2', {}, `${runs.length} runs`),
    h('div', { class: 'toolbar' }, metricSelect,
      h('label', { for: 'group' }, groupBox, ' mean ± std over seeds'),
      h('label', {}, 'smoothing ', smoothing)),
    chartBox,
    legend,
  );
  const chart = new CurveChart(chartBox, { xLabel: 'environment steps', yLabel: metric, height: 380 });

  // A run's curve of the metric, smoothed (each run before any mean over seeds); evaluations are
  // few and are not smoothed.
  function curveOf(run) {
    if (metric === EVAL) {
      return cleanCurve(run.evaluation.column('timesteps') || [], run.evaluation.column('mean_return') || []);
    }
    const curve = cleanCurve(run.progress.column('time/total_timesteps') || [], run.progress.column(metric) || []);
    return { x: curve.x, y: smooth(curve.y, Number(smoothing.value)) };
  }

  function draw() {
    const columns = new Set([EVAL]);
    runs.forEach((r) => r.progress.columns.forEach((c) => c !== 'time/total_timesteps' && columns.add(c)));
    if (metricSelect.options.length !== columns.size) {
      metricSelect.replaceChildren(...[...columns].sort().map((c) => h('option', { value: c }, c)));
    }
    metricSelect.value = metric;
    chart.options.yLabel = metric;

    const series = [];
    const rows = [];
    if (groupBox.checked) {
      const groups = new Map();
      for (const run of runs) {
        const key = seedGroup(run.name, run.path.split('/').slice(-2, -1)[0]);
        if (!groups.has(key)) groups.set(key, []);
        groups.get(key).push(run);
      }
      [...groups.entries()].forEach(([key, members], i) => {
        const stats = aggregate(members.map(curveOf));
        const color = palette[i % palette.length];
        const label = `${key} (${members.length} seed${members.length === 1 ? '' : 's'})`;
        series.push({ label, x: stats.x, y: stats.mean, lo: stats.lo, hi: stats.hi, color });
        rows.push(h('li', {}, h('span', { class: 'swatch', style: `background:${color}` }), label, ': ',
          ...members.flatMap((m, k) => [k ? ', ' : '', link(runHash(m.path), m.name)])));
      });
    } else {
      runs.forEach((run, i) => {
        const color = palette[i % palette.length];
        const curve = curveOf(run);
        series.push({ label: run.name, x: curve.x, y: curve.y, color });
        rows.push(h('li', {}, h('span', { class: 'swatch', style: `background:${color}` }), link(runHash(run.path), run.path)));
      });
    }
    chart.setCurves(series);
    legend.replaceChildren(...rows);
  }

  async function poll() {
    // Only the files each run has (a missing one would be a 404 in the browser's console).
    const results = await Promise.all(runs.flatMap((r) => [
      r.files.includes('progress.csv') ? r.progress.poll() : false,
      r.files.includes('eval.csv') ? r.evaluation.poll() : false,
    ]));
    if (results.some(Boolean)) draw();
  }
  await poll();
  draw();
  const timer = setInterval(() => poll().catch((e) => setStatus(e.message, true)), 3000);
  return {
    dispose() {
      clearInterval(timer);
      chart.destroy();
    },
  };
}
