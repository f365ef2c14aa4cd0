// The dashboard's page: a hash router over four views.
import './style.css';
import { api } from './api.js';
import { setStatus } from './dom.js';
import { showRuns } from './views/runs.js';
import { showRun } from './views/run.js';
import { showCompare } from './views/compare.js';
import { showReplay } from './views/replay.js';
import { showSummary } from './views/summary.js';

const views = {
  '': showRuns, run: showRun, compare: showCompare, episode: showReplay, summary: showSummary,
};
let current = null;  // { dispose } of the view on screen

async function route() {
  const hash = location.hash.replace(/^#\/?/, '');
  const [name, query = ''] = hash.split('?');
  const show = views[name] || showRuns;
  if (current && current.dispose) current.dispose();
  current = null;
  const container = document.getElementById('view');
  container.replaceChildren();
  setStatus('');
  try {
    current = await show(container, new URLSearchParams(query));
  } catch (error) {
    setStatus(error.message, true);
    console.warn(error);
  }
}

// The served directory's name in the header, once.
api.index().then((index) => {
  document.getElementById('root-name').textContent = `${index.root}/`;
}).catch(() => {});

window.addEventListener('hashchange', route);
route();
