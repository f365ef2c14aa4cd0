// One run: its return (training runs) or loss (model fits), every logged metric as a grid of
// charts (following the files while it runs), smoothing, its config, and its episodes or its
// fit's evaluation.
import { api, LiveCsv } from '../api.js';
import { CurveChart, formatNumber, palette } from '../chart.js';
import { episodeHash, h, link, setStatus } from '../dom.js';
import { progressText, statusBadge } from './runs.js';

const STEPS = 'time/total_timesteps';
const WALL = 'time/time_elapsed';
const EPOCHS = 'time/epochs';
const SMOOTHING_KEY = 'tendril.smoothing';

function withSpread(eval_, xColumn) {
  const x = eval_.column(xColumn) || [];
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

// Rows of a small CSV file with text cells (evaluation.csv), as objects.
function parseCsv(text) {
  const lines = text.split('\n').filter((l) => l.trim().length > 0);
  if (lines.length === 0) return { columns: [], rows: [] };
  const columns = lines[0].split(',').map((c) => c.trim());
  const rows = lines.slice(1).map((line) => {
    const cells = line.split(',');
    return Object.fromEntries(columns.map((c, i) => [c, (cells[i] ?? '').trim()]));
  });
  return { columns, rows };
}

function metricGroup(column) {
  const slash = column.indexOf('/');
  return slash > 0 ? column.slice(0, slash) : 'other';
}

export async function showRun(container, query) {
  const path = query.get('path') || '';
  const run = await api.run(path);
  const prefix = path ? `${path}/` : '';
  const fit = run.kind === 'fit';
  const progress = new LiveCsv(`${prefix}progress.csv`);
  const evaluation = new LiveCsv(`${prefix}eval.csv`);

  const stored = Number(localStorage.getItem(SMOOTHING_KEY));
  const smoothing = h('input', {
    type: 'range', min: 0, max: 0.99, step: 0.01, value: Number.isFinite(stored) && localStorage.getItem(SMOOTHING_KEY) !== null ? stored : 0.6,
    'aria-label': 'smoothing',
  });
  const smoothingValue = h('span', { class: 'smoothing-value' });
  const xSelect = h('select', { 'aria-label': 'x axis' },
    ...(fit ? [[EPOCHS, 'epochs']] : [[STEPS, 'environment steps'], [WALL, 'wall time (s)']])
      .map(([value, text]) => h('option', { value }, text)));
  const headline = h('section', { class: 'headline' });
  const grid = h('div', { class: 'metric-grid' });
  const problems = h('ul', { class: 'problems' });
  const summary = h('p', { class: 'summary' });
  const fitTable = h('div', { class: 'fit-evaluation' });
  container.append(
    h('h2', {}, run.path || run.name, ' ', statusBadge(run)),
    summary,
    h('div', { class: 'toolbar' },
      h('label', {}, 'smoothing ', smoothing, smoothingValue),
      h('label', {}, 'x axis ', xSelect)),
    headline,
    h('section', {}, h('h3', {}, 'Every logged value ', h('small', { class: 'muted x-note' })), grid),
    problems,
    h('section', { class: 'columns' },
      fit
        ? h('div', {}, h('h3', {}, 'Evaluation of the fitted model (evaluation.csv)'), fitTable)
        : h('div', {}, h('h3', {}, 'Recorded episodes'), episodeList(run)),
      h('div', {}, h('h3', {}, 'config.yaml'), h('pre', { class: 'config' }, run.config ?? '(none)'))),
  );

  const xLabel = () => xSelect.options[xSelect.selectedIndex].textContent;
  const mainChart = new CurveChart(h('div', { class: 'chart' }), {
    xLabel: xLabel(), yLabel: fit ? 'loss' : 'episode return',
  });
  headline.append(h('h3', {}, fit ? 'Loss' : 'Return'), mainChart.container);
  const charts = new Map();  // column → CurveChart of the grid

  function weight() {
    return Number(smoothing.value);
  }

  function draw() {
    localStorage.setItem(SMOOTHING_KEY, smoothing.value);
    smoothingValue.textContent = ` ${weight().toFixed(2)}`;
    const xColumn = xSelect.value;
    const x = progress.column(xColumn) || [];
    for (const chart of [mainChart, ...charts.values()]) chart.options.xLabel = xLabel();
    container.querySelector('.x-note').textContent = `against ${xLabel()}`;

    const series = [];
    if (fit) {
      const loss = progress.column('train/loss');
      const validation = progress.column('train/val_loss');
      if (loss) series.push({ label: 'training loss', x, y: loss, color: palette[0], smoothing: weight() });
      if (validation) series.push({ label: 'validation loss', x, y: validation, color: palette[1], smoothing: weight() });
    } else {
      const training = progress.column('rollout/ep_rew_mean');
      if (training) series.push({ label: 'training mean return (last 100 episodes)', x, y: training, color: palette[0], smoothing: weight() });
      // Evaluations are at steps; on the wall-time axis they are placed by the progress row
      // of their step.
      if (evaluation.rows.length > 0 && xColumn === STEPS) series.push(withSpread(evaluation, 'timesteps'));
    }
    mainChart.setCurves(series);

    const columns = progress.columns.filter((c) => c !== xColumn);
    let section = null;
    for (const column of columns) {
      if (!charts.has(column)) {
        const group = metricGroup(column);
        section = grid.querySelector(`[data-group="${group}"]`);
        if (!section) {
          section = h('div', { class: 'metric-group', 'data-group': group }, h('h4', {}, group));
          grid.append(section);
        }
        const cell = h('div', { class: 'metric', 'data-metric': column }, h('div', { class: 'metric-name' }, column));
        const box = h('div', { class: 'chart' });
        cell.append(box);
        section.append(cell);
        charts.set(column, new CurveChart(box, { xLabel: xLabel(), height: 150, compact: true }));
      }
      charts.get(column).setCurves([{ label: column, x, y: progress.column(column) || [], color: palette[2], smoothing: weight() }]);
    }

    const text = [
      run.algorithm ? `${run.algorithm}` : (fit ? 'model fit' : null),
      run.env_id || null,
      progressText(run) ? `${progressText(run)}${fit ? '' : ' steps'}` : null,
      fit && Number.isFinite(run.last_loss) ? `validation loss ${formatNumber(run.last_loss)}` : null,
      !fit && Number.isFinite(run.last_return) ? `training mean return ${formatNumber(run.last_return)}` : null,
      !fit && evaluation.rows.length ? `last evaluation ${formatNumber(evaluation.column('mean_return').at(-1))}` : null,
      progress.rows.length === 0 ? 'no progress.csv rows yet' : null,
      progress.partial ? 'a row is being written' : null,
    ];
    summary.textContent = text.filter(Boolean).join(' · ');
    problems.replaceChildren(
      ...[...progress.problems.map((p) => `progress.csv ${p}`), ...evaluation.problems.map((p) => `eval.csv ${p}`)]
        .map((p) => h('li', {}, p)));
  }

  async function showFitEvaluation() {
    if (!fit || !run.files.includes('evaluation.csv')) {
      fitTable.replaceChildren(h('p', { class: 'muted' }, 'None yet: a fit evaluates its model on the test split when it ends.'));
      return;
    }
    const table = parseCsv(await api.text(`${prefix}evaluation.csv`));
    fitTable.replaceChildren(h('table', { class: 'evaluation' },
      h('thead', {}, h('tr', {}, ...table.columns.map((c) => h('th', {}, c)))),
      h('tbody', {}, ...table.rows.map((row) => h('tr', {}, ...table.columns.map((c) => {
        const value = Number(row[c]);
        return h('td', { class: Number.isFinite(value) && row[c] !== '' ? 'number' : '' },
          Number.isFinite(value) && row[c] !== '' && c === 'rmse' ? value.toPrecision(4) : row[c]);
      }))))));
  }

  async function poll() {
    // Files the run does not have are not asked for (a 404 in the browser's console).
    const evaluates = !fit && run.files.includes('eval.csv');
    const changed = (await Promise.all([progress.poll(), evaluates ? evaluation.poll() : false])).some(Boolean);
    if (changed) draw();
  }
  smoothing.addEventListener('input', draw);
  xSelect.addEventListener('change', draw);
  await poll();
  draw();
  await showFitEvaluation();
  const timer = setInterval(() => poll().catch((e) => setStatus(e.message, true)), 2000);
  return {
    dispose() {
      clearInterval(timer);
      mainChart.destroy();
      for (const chart of charts.values()) chart.destroy();
    },
  };
}

function episodeList(run) {
  if (run.episodes.length === 0) {
    if (run.kind !== 'training') return h('p', { class: 'muted' }, 'None.');
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
