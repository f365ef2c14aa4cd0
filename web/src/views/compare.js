// Several runs on one chart: each run its own curve, or the seeds of each group as their mean
// with a ± one-standard-deviation band. The groups and their statistics come from the server
// (/api/curves: core/run_curves, as `tendril plot curves` and the sweep summaries compute them);
// the page smooths and draws them.
import { api, LiveCsv } from '../api.js';
import { cleanCurve } from '../curves.js';
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
  const redraw = () => draw().catch((e) => setStatus(e.message, true));
  metricSelect.addEventListener('change', () => {
    metric = metricSelect.value;
    redraw();
  });
  const smoothing = h('input', {
    type: 'range', min: 0, max: 0.99, step: 0.01, 'aria-label': 'smoothing',
    value: localStorage.getItem('tendril.smoothing') ?? 0.6,
  });
  smoothing.addEventListener('input', () => {
    localStorage.setItem('tendril.smoothing', smoothing.value);
    redraw();
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

  // A run's own curve of the metric, smoothed; evaluations are few and are not smoothed.
  function curveOf(run) {
    if (metric === EVAL) {
      return cleanCurve(run.evaluation.column('timesteps') || [], run.evaluation.column('mean_return') || []);
    }
    const curve = cleanCurve(run.progress.column('time/total_timesteps') || [], run.progress.column(metric) || []);
    return { x: curve.x, y: smooth(curve.y, Number(smoothing.value)) };
  }

  let drawn = 0;  // the latest draw: an older answer from the server arrives too late to show

  async function draw() {
    const columns = new Set([EVAL]);
    runs.forEach((r) => r.progress.columns.forEach((c) => c !== 'time/total_timesteps' && columns.add(c)));
    if (metricSelect.options.length !== columns.size) {
      metricSelect.replaceChildren(...[...columns].sort().map((c) => h('option', { value: c }, c)));
    }
    metricSelect.value = metric;
    chart.options.yLabel = metric;
    const ticket = ++drawn;
    const series = [];
    const rows = [];
    if (groupBox.checked) {
      const answer = await api.curves(paths, metric === EVAL ? 'eval' : metric);
      if (ticket !== drawn) return;
      const weight = Number(smoothing.value);
      const byPath = new Map(runs.map((r) => [r.path, r]));
      answer.groups.forEach((group, i) => {
        const color = palette[i % palette.length];
        const seeds = group.runs.length;
        const label = `${group.name} (${seeds} seed${seeds === 1 ? '' : 's'})`;
        const band = (sign) => group.mean.map((m, k) => (m === null ? null : m + sign * group.std[k]));
        series.push({
          label, x: group.x, y: smooth(group.mean, weight), lo: smooth(band(-1), weight), hi: smooth(band(1), weight), color,
        });
        const members = group.runs.map((path) => byPath.get(path) || { path, name: path.split('/').pop() });
        rows.push(h('li', {}, h('span', { class: 'swatch', style: `background:${color}` }), label, ': ',
          ...members.flatMap((m, k) => [k ? ', ' : '', link(runHash(m.path), m.name)]),
          ...group.problems.map((p) => h('div', { class: 'problem' }, p))));
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
    if (results.some(Boolean)) await draw();
  }
  await poll();
  await draw();
  const timer = setInterval(() => poll().catch((e) => setStatus(e.message, true)), 3000);
  return {
    dispose() {
      clearInterval(timer);
      chart.destroy();
    },
  };
}
