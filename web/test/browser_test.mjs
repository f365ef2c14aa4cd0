// The dashboard in a real browser: starts `tendril serve` on a directory of runs, opens every
// view in Debian's headless Chromium (driven by playwright-core; no browser is downloaded),
// checks that the charts and the 3D replay draw, that nothing logs an error, and writes one
// screenshot per view.
//   node browser_test.mjs --tendril build/apps/tendril --root RUNS --out SCREENSHOT_DIR
//        [--run PATH] [--compare PATH,PATH,...] [--episode PATH] [--primitives PATH|none]
//        [--external PATH] [--fit PATH]
import { spawn } from 'node:child_process';
import { mkdirSync, statSync } from 'node:fs';
import { join } from 'node:path';
import { chromium } from 'playwright-core';

const options = {
  run: 'sweep/ppo_seed0',
  external: 'external/sb3_pendulum',
  fit: 'fits/sma_stiff_lstm',
  compare: 'sweep/ppo_seed0,sweep/ppo_seed1,sweep/ppo_seed2',
  episode: 'sweep/ppo_seed0/episodes/episode_0000.tep',
  primitives: 'sweep/ppo_seed0/episodes/all_primitives.tep',
  width: '1280',
};
for (let i = 2; i < process.argv.length; i += 2) options[process.argv[i].replace(/^--/, '')] = process.argv[i + 1];
for (const required of ['tendril', 'root', 'out']) {
  if (!options[required]) throw new Error(`--${required} is required`);
}
mkdirSync(options.out, { recursive: true });

let failures = 0;
let passes = 0;
function check(condition, what) {
  if (condition) passes++;
  else failures++;
  console.log(`${condition ? 'ok  ' : 'FAIL'} ${what}`);
}

function startServer() {
  return new Promise((resolve, reject) => {
    const server = spawn(options.tendril, ['serve', options.root, '--port', '0'], { stdio: ['ignore', 'pipe', 'inherit'] });
    let output = '';
    server.stdout.on('data', (chunk) => {
      output += chunk;
      const found = output.match(/http:\/\/127\.0\.0\.1:(\d+)\//);
      if (found) resolve({ server, url: found[0] });
    });
    server.on('exit', (code) => reject(new Error(`tendril serve exited (${code}): ${output}`)));
    setTimeout(() => reject(new Error('tendril serve did not start')), 10000);
  });
}

// The fraction of a page's canvases' pixels (the largest of them) that differ from the
// canvas's corner colour: 0 for a blank chart or scene.
async function ink(page, selector) {
  return page.evaluate((sel) => {
    let best = 0;
    for (const canvas of document.querySelectorAll(sel)) {
      if (canvas.width === 0 || canvas.height === 0) continue;
      const probe = document.createElement('canvas');
      probe.width = canvas.width;
      probe.height = canvas.height;
      const context = probe.getContext('2d');
      context.fillStyle = '#ffffff';
      context.fillRect(0, 0, probe.width, probe.height);
      context.drawImage(canvas, 0, 0);
      const data = context.getImageData(0, 0, probe.width, probe.height).data;
      const [r, g, b] = [data[0], data[1], data[2]];
      let differing = 0;
      for (let i = 0; i < data.length; i += 4) {
        if (Math.abs(data[i] - r) + Math.abs(data[i + 1] - g) + Math.abs(data[i + 2] - b) > 40) differing++;
      }
      best = Math.max(best, differing / (data.length / 4));
    }
    return best;
  }, selector);
}

async function screenshot(page, name) {
  const file = join(options.out, `${name}.png`);
  await page.screenshot({ path: file });
  check(statSync(file).size > 15000, `${name}.png is a picture (${statSync(file).size} bytes)`);
}

// Every chart's y-axis labels (what the axis formatter returned for the drawn ticks): none may
// repeat within a chart.
async function ticksAreDistinct(page, view) {
  const axes = await page.$$eval('.chart[data-y-ticks]', (boxes) => boxes.map((b) => JSON.parse(b.dataset.yTicks)));
  const repeated = axes.filter((labels) => new Set(labels.filter((l) => l !== '')).size !== labels.filter((l) => l !== '').length);
  check(axes.length > 0 && repeated.length === 0,
    `${view}: y-axis labels differ in each of ${axes.length} charts${repeated.length ? ` (repeated: ${JSON.stringify(repeated[0])})` : ''}`);
  return axes;
}

async function statusIsClean(page, view) {
  const status = await page.$eval('#status', (el) => ({ text: el.textContent, error: el.classList.contains('error') }));
  check(!status.error, `${view}: no error shown${status.error ? ` (${status.text})` : ''}`);
}

const { server, url } = await startServer();
const browser = await chromium.launch({
  executablePath: '/usr/bin/chromium',
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking',
    '--disable-component-update', '--disable-sync', '--no-first-run', '--enable-unsafe-swiftshader'],
});
const errors = [];
try {
  const page = await browser.newPage({ viewport: { width: Number(options.width), height: 860 } });
  page.on('console', (message) => {
    if (message.type() === 'error') errors.push(message.text());
  });
  page.on('pageerror', (error) => errors.push(error.message));
  page.on('requestfailed', (request) => errors.push(`request failed: ${request.url()}`));
  page.on('response', (response) => {
    if (response.status() >= 400) errors.push(`${response.status()} for ${response.url()}`);
  });
  page.on('request', (request) => {
    if (!request.url().startsWith(url) && !request.url().startsWith('data:')) errors.push(`request outside the server: ${request.url()}`);
  });

  // Runs and sweeps.
  await page.goto(url);
  await page.waitForSelector('table.runs tbody tr td a');
  const listed = await page.$$eval('table.runs tbody tr', (rows) => rows.length);
  check(listed >= 5, `runs view lists the runs (${listed})`);
  const headers = await page.$$eval('table.runs thead th', (cells) => cells.map((c) => c.textContent));
  for (const column of ['status', 'steps', 'return', 'evaluation']) {
    check(headers.includes(column), `runs view has a ${column} column (${headers.join(', ')})`);
  }
  // The columns of each kind of run, by column name.
  const row = (path) => page.$eval(`table.runs tbody tr[data-path="${path}"]`, (tr, names) => {
    const cells = [...tr.children].map((c) => c.textContent.trim());
    return Object.fromEntries(names.map((n, i) => [n, cells[i]]));
  }, headers);
  const trained = await row(options.run);
  check(trained.status === 'finished', `a finished training run says so (${trained.status})`);
  check(/^[\d.]+k? \/ [\d.]+k?$/.test(trained.steps), `its steps are shown against the budget (${trained.steps})`);
  check(/^-?[\d.]+$/.test(trained.return) && /^-?[\d.]+$/.test(trained.evaluation),
    `its last training return and evaluation are shown (${trained.return}, ${trained.evaluation})`);
  const fitted = await row(options.fit);
  check(fitted.status === 'finished' && fitted.algorithm === 'model fit' && /epochs$/.test(fitted.steps) && /^loss /.test(fitted.return),
    `a model fit is listed as one (${JSON.stringify(fitted)})`);
  const external = await row(options.external);
  check(external.status === '–' && /^-11\d\d$/.test(external.return), `logs from elsewhere: no status, their last return to four digits (${external.status}, ${external.return})`);
  check(!(await page.$$eval('.status', (badges) => badges.some((b) => b.textContent === 'live'))), 'nothing is called live');
  const sweeps = await page.$$eval('.sweep', (rows) => rows.map((r) => r.dataset.path));
  check(sweeps.length >= 1 && !sweeps.includes(''), `the sweep is listed, the served directory is not (${JSON.stringify(sweeps)})`);
  const sweepText = await page.$eval('.sweep[data-path="sweep"]', (el) => el.textContent);
  check(/\b3 runs in 1 group\b/.test(sweepText), `the sweep's three seeds are one group, as the server groups them (${sweepText.slice(0, 80)})`);
  const header = await page.$eval('header', (el) => el.textContent.replace(/\s+/g, ' ').trim());
  check(!/\bruns runs\b/.test(header) && header.includes('/'), `the header names the served directory once (${header})`);
  await statusIsClean(page, 'runs');
  await screenshot(page, 'runs');

  // A sweep's summary: its Markdown tables and figures.
  await page.click('.sweep a.summary-link');
  await page.waitForSelector('article.markdown table');
  await page.waitForFunction(() => [...document.querySelectorAll('article.markdown img')].every((i) => i.complete));
  const figures = await page.$$eval('article.markdown img', (images) => images.map((i) => i.naturalWidth));
  check(figures.length >= 1 && figures.every((w) => w > 0), `the sweep summary shows its figures (${figures})`);
  await statusIsClean(page, 'summary');
  await screenshot(page, 'summary');

  // One run: curves, any logged value, config, episodes.
  await page.goto(`${url}#/run?path=${encodeURIComponent(options.run)}`);
  await page.waitForSelector('.uplot canvas');
  await page.waitForTimeout(500);
  const runInk = await ink(page, '.chart .uplot canvas');
  check(runInk > 0.002, `run view draws its curves (${(100 * runInk).toFixed(2)}% of pixels)`);
  const config = await page.$eval('pre.config', (el) => el.textContent);
  check(config.includes('algorithm:'), 'run view shows config.yaml');
  const metrics = await page.$$eval('.metric-grid .metric', (cells) => cells.map((c) => c.dataset.metric));
  check(metrics.length >= 8 && metrics.includes('train/approx_kl') && metrics.includes('rollout/ep_len_mean'),
    `run view draws every logged value as a grid (${metrics.length}: ${metrics.slice(0, 4).join(', ')}, …)`);
  check((await page.$$('.metric-grid .uplot')).length === metrics.length, 'each logged value has its chart');
  await ticksAreDistinct(page, 'run');
  await page.$eval('input[aria-label=smoothing]', (el) => { el.value = '0.9'; el.dispatchEvent(new Event('input')); });
  await page.waitForTimeout(300);
  check(await page.$$eval('.u-legend .u-series', (rows) => rows.some((r) => r.textContent.includes('(raw)'))),
    'smoothing keeps the raw curve behind the smoothed one');
  await statusIsClean(page, 'run');
  await screenshot(page, 'run');
  await page.$eval('.metric-grid', (el) => el.scrollIntoView());
  await page.waitForTimeout(200);
  await screenshot(page, 'run_metrics');

  // Logs from elsewhere whose returns span −1,190 … −1,120: distinct labels on every axis.
  await page.goto(`${url}#/run?path=${encodeURIComponent(options.external)}`);
  await page.waitForSelector('.metric-grid .uplot canvas');
  await page.waitForTimeout(300);
  const externalTicks = await ticksAreDistinct(page, 'external run');
  check(externalTicks.some((labels) => labels.some((l) => /^-1\.1\d+k$/.test(l))),
    `the narrow range of large returns reads to the needed digit (${JSON.stringify(externalTicks[0])})`);
  await statusIsClean(page, 'external run');

  // A model fit: its loss against epochs, its evaluation, no episodes to record.
  await page.goto(`${url}#/run?path=${encodeURIComponent(options.fit)}`);
  await page.waitForSelector('table.evaluation tbody tr');
  await page.waitForTimeout(500);
  const fitInk = await ink(page, '.headline .uplot canvas');
  check(fitInk > 0.002, `fit view draws its loss (${(100 * fitInk).toFixed(2)}% of pixels)`);
  const fitPage = await page.$eval('main', (el) => ({
    text: el.textContent,
    x: document.querySelector('select[aria-label="x axis"]').value,
    heading: document.querySelector('.headline h3').textContent,
    rows: document.querySelectorAll('table.evaluation tbody tr').length,
  }));
  check(fitPage.heading === 'Loss' && fitPage.x === 'time/epochs', `fit view plots loss against epochs (${fitPage.heading}, ${fitPage.x})`);
  check(fitPage.rows === 4, `fit view shows evaluation.csv (${fitPage.rows} rows)`);
  check(!fitPage.text.includes('tendril record'), 'fit view does not offer to record episodes');
  await ticksAreDistinct(page, 'fit');
  await statusIsClean(page, 'fit');
  await screenshot(page, 'run_fit');

  // Several runs: mean and spread over seeds.
  const compare = options.compare.split(',');
  await page.goto(`${url}#/compare?runs=${encodeURIComponent(compare.join('|'))}&group=1`);
  await page.waitForSelector('.uplot canvas');
  await page.waitForTimeout(500);
  const compareInk = await ink(page, '.chart .uplot canvas');
  check(compareInk > 0.002, `compare view draws mean and band (${(100 * compareInk).toFixed(2)}% of pixels)`);
  const legend = await page.$eval('ul.groups', (el) => el.textContent);
  check(legend.includes(`${compare.length} seeds`), `compare view groups the seeds (${legend.slice(0, 80)})`);
  await ticksAreDistinct(page, 'compare');
  await statusIsClean(page, 'compare');
  await screenshot(page, 'compare');

  // Tendril's runs beside logs from elsewhere: still distinct labels.
  await page.goto(`${url}#/compare?runs=${encodeURIComponent([options.external, compare[0]].join('|'))}`);
  await page.waitForSelector('.uplot canvas');
  await page.waitForTimeout(300);
  await ticksAreDistinct(page, 'compare with logs from elsewhere');

  // The 3D replay: draws, plays, scrubs.
  for (const [name, path] of [['replay', options.episode], ['replay_primitives', options.primitives]]) {
    if (!path || path === 'none') continue;
    await page.goto(`${url}#/episode?path=${encodeURIComponent(path)}`);
    await page.waitForSelector('.viewport canvas');
    await page.waitForTimeout(800);
    const sceneInk = await ink(page, '.viewport canvas');
    check(sceneInk > 0.01, `${name}: the 3D view draws the scene (${(100 * sceneInk).toFixed(2)}% of pixels)`);
    const clockTime = () => page.$eval('.clock', (el) => Number((el.textContent.match(/t = (\d+\.\d+) s/) || [])[1]));
    const before = await page.$eval('input[type=range]', (el) => Number(el.value));
    const beforeTime = await clockTime();
    await page.selectOption('select[aria-label=speed]', '0.1');
    const started = Date.now();
    await page.click('button.play');
    await page.waitForTimeout(1200);
    const played = await page.$eval('input[type=range]', (el) => Number(el.value));
    const replayed = (await clockTime()) - beforeTime;
    const wall = (Date.now() - started) / 1000;
    check(played > before, `${name}: play advances the frames (${before} → ${played})`);
    // The episode's clock runs at a tenth of the wall clock's (a frame of slack); on a loaded
    // machine a short episode may already have ended.
    check(replayed <= 0.1 * wall + 0.05,
      `${name}: plays at 0.1× (${replayed.toFixed(3)} s of the episode in ${wall.toFixed(2)} s)`);
    // Pause in one step inside the page: on a loaded machine the replay may have reached its end
    // (and stopped) since the check above, and a click would then start it again.
    const paused = await page.$eval('button.play', (el) => {
      if (el.textContent === 'pause') el.click();
      return el.textContent === 'play';
    });
    check(paused, `${name}: pause stops the replay`);
    const target = await page.$eval('input[type=range]', (el) => {
      el.value = String(Math.round(Number(el.max) * 0.6));
      el.dispatchEvent(new Event('input'));
      return Number(el.value);
    });
    const clock = await page.$eval('.clock', (el) => el.textContent);
    const step = Number((clock.match(/step (\d+)/) || [])[1]);
    check(/t = \d+\.\d+ s/.test(clock) && step > 0 && (await page.$eval('input[type=range]', (el) => Number(el.value))) === target,
      `${name}: scrubbing to frame ${target} shows its time and step (${clock})`);
    await page.selectOption('select[aria-label=speed]', '2');
    const box = await page.$eval('.viewport canvas', (el) => { const r = el.getBoundingClientRect(); return [r.x + r.width / 2, r.y + r.height / 2]; });
    await page.mouse.move(box[0], box[1]);
    await page.mouse.down();
    await page.mouse.move(box[0] + 60, box[1] + 10, { steps: 5 });
    await page.mouse.up();
    await page.waitForTimeout(300);
    const orbitInk = await ink(page, '.viewport canvas');
    check(orbitInk > 0.01, `${name}: the scene still draws after orbiting the camera`);
    await statusIsClean(page, name);
    await screenshot(page, name);
  }
} finally {
  await browser.close();
  server.kill();
}
check(errors.length === 0, `no console errors${errors.length ? `: ${errors.join(' | ')}` : ''}`);
console.log(`${passes} passed, ${failures} failed`);
process.exit(failures === 0 ? 0 : 1);
