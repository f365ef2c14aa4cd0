// The runs and sweeps under the served directory; pick runs to compare.
import { api } from '../api.js';
import { ago, compareHash, h, link, runHash, setStatus } from '../dom.js';
import { seedGroup } from '../aggregate.js';

const LIVE_SECONDS = 30;

function runRow(run, selected) {
  const live = Date.now() / 1000 - run.modified < LIVE_SECONDS;
  const box = h('input', { type: 'checkbox', 'data-path': run.path });
  box.checked = selected.has(run.path);
  box.addEventListener('change', () => {
    if (box.checked) selected.add(run.path);
    else selected.delete(run.path);
  });
  return h(
    'tr',
    {},
    h('td', {}, box),
    h('td', {}, link(runHash(run.path), run.path || run.name), live ? h('span', { class: 'live' }, 'live') : null),
    h('td', {}, run.algorithm),
    h('td', {}, run.env_id),
    h('td', {}, [run.has_progress ? 'progress' : null, run.has_eval ? 'eval' : null].filter(Boolean).join(', ')),
    h('td', { class: 'number' }, run.episodes || ''),
    h('td', {}, ago(run.modified)),
    h('td', { class: 'problem' }, run.problem),
  );
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
      h('h2', {}, 'Sweeps'),
      sweeps),
    h('section', {},
      h('h2', {}, 'Runs'),
      h('div', { class: 'toolbar' }, compare,
        h('label', { for: 'group-seeds' }, groupBox, ' mean ± std over seeds')),
      h('table', { class: 'runs' },
        h('thead', {}, h('tr', {}, ...['', 'run', 'algorithm', 'environment', 'curves', 'episodes', 'updated', ''].map((t) => h('th', {}, t)))),
        table)),
  );

  async function refresh() {
    const index = await api.index();
    document.getElementById('root-name').textContent = index.root;
    table.replaceChildren(...index.runs.map((run) => runRow(run, selected)));
    if (index.runs.length === 0) {
      table.append(h('tr', {}, h('td', { colspan: 8 }, 'No runs here yet: a run directory holds config.yaml, progress.csv or eval.csv.')));
    }
    sweeps.replaceChildren(
      ...index.sweeps.map((sweep) => {
        const groups = new Set(sweep.runs.map((p) => seedGroup(p.split('/').pop(), p.split('/').slice(-2, -1)[0])));
        return h('div', { class: 'sweep' },
          h('strong', {}, sweep.path || sweep.name),
          ` — ${sweep.runs.length} runs in ${groups.size} group${groups.size === 1 ? '' : 's'} `,
          link(compareHash(sweep.runs, { group: true }), 'curves, mean ± std over seeds'),
          ' · ',
          link(compareHash(sweep.runs), 'every run'));
      }),
    );
    if (index.sweeps.length === 0) sweeps.append(h('p', { class: 'muted' }, 'No directory here holds two runs or more.'));
  }

  await refresh();
  const timer = setInterval(() => refresh().catch((e) => setStatus(e.message, true)), 5000);
  return { dispose: () => clearInterval(timer) };
}
