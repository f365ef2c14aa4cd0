// One run: its learning curves (following the files while it trains), config and episodes.
import { api, LiveCsv } from '../api.js';
import { CurveChart, formatNumber, palette } from '../chart.js';
import { episodeHash, h, link, setStatus } from '../dom.js';

const X = 'time/total_timesteps';

function withSpread(eval_) {
  const x = eval_.column('timesteps') || [];
  const mean = eval_.column('mean_return') || [];
  const std = eval_.column('std_return') || x.map(() => 0);
  return {
    label: 'evaluation mean return ± std',
    x,
    y: mean,
    lo: mean.map((m, i) => m - std[i]),
    hi: mean.map((m, i) => m + std[i]),
    color: palette[1],
  };
}

export async function showRun(container, query) {
  const path = query.get('path') || '';
  const run = await api.run(path);
  const progress = new LiveCsv(`${path ? `${path}/` : ''}progress.csv`);
  const evaluation = new LiveCsv(`${path ? `${path}/` : ''}eval.csv`);
  const metricSelect = h('select', { 'aria-label': 'metric' });
  const curves = h('div', { class: 'chart' });
  const other = h('div', { class: 'chart' });
  const problems = h('ul', { class: 'problems' });
  const summary = h('p', { class: 'summary' });
  container.append(
    h('h2', {}, run.path || run.name),
    summary,
    h('section', {}, h('h3', {}, 'Return'), curves),
    h('section', {}, h('h3', {}, 'Any logged value ', metricSelect), other),
    problems,
    h('section', { class: 'columns' },
      h('div', {}, h('h3', {}, 'Recorded episodes'), episodeList(run)),
      h('div', {}, h('h3', {}, 'config.yaml'), h('pre', { class: 'config' }, run.config ?? '(none)'))),
  );
  const returnChart = new CurveChart(curves, { xLabel: 'environment steps', yLabel: 'episode return' });
  const metricChart = new CurveChart(other, { xLabel: 'environment steps', height: 240 });
  metricSelect.addEventListener('change', () => draw());

  function draw() {
    const x = progress.column(X) || [];
    const series = [];
    const training = progress.column('rollout/ep_rew_mean');
    if (training) series.push({ label: 'training mean return (last 100 episodes)', x, y: training, color: palette[0] });
    if (evaluation.rows.length > 0) series.push(withSpread(evaluation));
    returnChart.setCurves(series);

    const choices = progress.columns.filter((c) => c !== X);
    if (metricSelect.options.length !== choices.length) {
      const keep = metricSelect.value || (choices.includes('train/loss') ? 'train/loss' : choices[0]);
      metricSelect.replaceChildren(...choices.map((c) => h('option', { value: c }, c)));
      if (keep) metricSelect.value = keep;
    }
    const metric = metricSelect.value;
    if (metric) metricChart.setCurves([{ label: metric, x, y: progress.column(metric) || [], color: palette[2] }]);

    const last = progress.rows.length > 0 ? progress.rows[progress.rows.length - 1] : null;
    summary.textContent = [
      last ? `${formatNumber(last[progress.columns.indexOf(X)])} steps` : 'no progress.csv rows yet',
      training && training.length ? `training mean return ${formatNumber(training[training.length - 1])}` : null,
      evaluation.rows.length ? `last evaluation ${formatNumber(evaluation.column('mean_return').at(-1))}` : null,
      progress.partial ? 'a row is being written' : null,
    ].filter(Boolean).join(' · ');
    problems.replaceChildren(
      ...[...progress.problems.map((p) => `progress.csv ${p}`), ...evaluation.problems.map((p) => `eval.csv ${p}`)]
        .map((p) => h('li', {}, p)));
  }

  async function poll() {
    const changed = (await Promise.all([progress.poll(), evaluation.poll()])).some(Boolean);
    if (changed) draw();
  }
  await poll();
  draw();
  const timer = setInterval(() => poll().catch((e) => setStatus(e.message, true)), 2000);
  return {
    dispose() {
      clearInterval(timer);
      returnChart.destroy();
      metricChart.destroy();
    },
  };
}

function episodeList(run) {
  if (run.episodes.length === 0) {
    return h('p', { class: 'muted' }, 'None. ', h('code', {}, `tendril run ${run.path || '.'} --record ${run.path || '.'}/episodes`), ' records some.');
  }
  return h('table', { class: 'episodes' },
    h('thead', {}, h('tr', {}, h('th', {}, 'file'), h('th', {}, 'frames'), h('th', {}, 'return'), h('th', {}, ''))),
    h('tbody', {}, ...run.episodes.map((e) => h('tr', {},
      h('td', {}, e.frames > 0 ? link(episodeHash(e.path), e.name) : e.name),
      h('td', { class: 'number' }, e.frames),
      h('td', { class: 'number' }, formatNumber(e.return)),
      h('td', { class: 'problem' }, e.problem)))));
}
