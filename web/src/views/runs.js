// The runs and sweeps under the served directory: what each run is doing, how far it got and
// what it returns; pick runs to compare.
import { api } from '../api.js';
import { formatNumber, formatReadout } from '../chart.js';
import { ago, compareHash, h, link, runHash, setStatus, summaryHash } from '../dom.js';

// The status column: what the run's files say it is doing (the server reads them: a process
// holding the run's lock, model.policy, checkpoints).
export function statusBadge(run) {
  const s = run.status;
  if (!s) return h('span', { class: 'status muted' }, '–');
  const text = s === 'paused' && run.checkpoint >= 0
    ? `paused at ${formatNumber(run.checkpoint)}`
    : s;
  const title = {
    running: `a process (PID ${run.pid}) is writing it now`,
    finished: run.kind === 'fit' ? 'the fit ended and evaluated its model' : 'training ended: model.policy is written',
    paused: 'stopped at a checkpoint: tendril resume continues it',
    stopped: 'stopped without a checkpoint to resume from',
  }[s];
  return h('span', { class: `status status-${s}`, title }, text);
}

// Steps so far against the budget ("1.02M / 2M"); a fit's epochs.
export function progressText(run) {
  if (!Number.isFinite(run.steps)) return '';
  const unit = run.kind === 'fit' ? ' epochs' : '';
  const total = Number.isFinite(run.total) ? ` / ${formatNumber(run.total)}` : '';
  return `${formatNumber(run.steps)}${total}${unit}`;
}

function progressCell(run) {
  const text = progressText(run);
  if (!text) return h('td', { class: 'number steps' }, '');
  const share = Number.isFinite(run.total) && run.total > 0 ? Math.min(1, run.steps / run.total) : null;
  return h('td', { class: 'number steps' }, text,
    share !== null ? h('div', { class: 'bar' }, h('div', { style: `width:${(100 * share).toFixed(1)}%` })) : null);
}

function runRow(run, selected) {
  const box = h('input', { type: 'checkbox', 'data-path': run.path, 'aria-label': `select ${run.path || run.name}` });
  box.checked = selected.has(run.path);
  box.addEventListener('change', () => {
    if (box.checked) selected.add(run.path);
    else selected.delete(run.path);
  });
  const fit = run.kind === 'fit';
  return h(
    'tr',
    { 'data-path': run.path },
    h('td', {}, box),
    h('td', {}, link(runHash(run.path), run.path || run.name)),
    h('td', { class: 'status-cell' }, statusBadge(run)),
    h('td', {}, fit ? 'model fit' : run.algorithm),
    h('td', {}, run.env_id),
    progressCell(run),
    h('td', { class: 'number return' }, fit ? (Number.isFinite(run.last_loss) ? `loss ${formatReadout(run.last_loss)}` : '') : formatReadout(run.last_return)),
    h('td', { class: 'number eval' }, fit ? '' : formatReadout(run.last_eval)),
    h('td', { class: 'number' }, run.episodes || ''),
    h('td', {}, ago(run.modified)),
    h('td', { class: 'problem' }, run.problem),
  );
}

const COLUMNS = [
  ['', ''],
  ['run', ''],
  ['status', 'running, finished, paused at a checkpoint (resumable), or stopped'],
  ['algorithm', ''],
  ['environment', ''],
  ['steps', 'environment steps so far / the budget (a fit: epochs)'],
  ['return', 'mean training return of the last 100 episodes (a fit: its last validation loss)'],
  ['evaluation', 'mean return of the latest evaluation (eval.csv)'],
  ['episodes', 'recorded episodes'],
  ['updated', ''],
  ['', ''],
];

function sweepRow(sweep) {
  const parts = [
    h('strong', {}, sweep.path || sweep.name),
    ` — ${sweep.runs.length} run${sweep.runs.length === 1 ? '' : 's'} in ${sweep.groups} group${sweep.groups === 1 ? '' : 's'}: `,
    link(compareHash(sweep.runs, { group: true }), 'curves, mean ± std over seeds'),
    ' · ',
    link(compareHash(sweep.runs), 'every run'),
  ];
  if (sweep.summary) parts.push(' · ', h('a', { href: summaryHash(sweep.summary), class: 'summary-link' }, 'summary'));
  for (const figure of sweep.figures || []) {
    parts.push(' · ', h('a', { href: `files/${figure.split('/').map(encodeURIComponent).join('/')}`, target: '_blank', class: 'figure-link' }, figure.split('/').pop()));
  }
  return h('div', { class: 'sweep', 'data-path': sweep.path }, ...parts);
}

export async function showRuns(container) {
  const selected = new Set();
  const table = h('tbody');
  const sweeps = h('div', { class: 'sweeps' });
  const compare = h('button', {
    onclick: () => {
      if (selected.size > 0) location.hash = compareHash([...selected], { group: groupBox.checked });
    },
  }, 'compare selected');
  const groupBox = h('input', { type: 'checkbox', id: 'group-seeds' });
  groupBox.checked = true;
  container.append(
    h('section', {},
      h('h2', {}, 'Runs'),
      h('div', { class: 'toolbar' }, compare,
        h('label', { for: 'group-seeds' }, groupBox, ' mean ± std over seeds')),
      h('table', { class: 'runs' },
        h('thead', {}, h('tr', {}, ...COLUMNS.map(([t, title]) => h('th', { title: title || undefined }, t)))),
        table)),
    h('section', {},
      h('h2', {}, 'Sweeps'),
      sweeps),
  );

  async function refresh() {
    const index = await api.index();
    table.replaceChildren(...index.runs.map((run) => runRow(run, selected)));
    if (index.runs.length === 0) {
      table.append(h('tr', {}, h('td', { colspan: COLUMNS.length }, 'No runs here yet: a run directory holds config.yaml, progress.csv or eval.csv.')));
    }
    sweeps.replaceChildren(...index.sweeps.map(sweepRow));
    if (index.sweeps.length === 0) {
      sweeps.append(h('p', { class: 'muted' }, 'No directory below this one holds two runs or more.'));
    }
  }

  await refresh();
  const timer = setInterval(() => refresh().catch((e) => setStatus(e.message, true)), 5000);
  return { dispose: () => clearInterval(timer) };
}
