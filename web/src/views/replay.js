// A recorded episode replayed in 3D: play, pause, scrub, speed, orbit camera; the step's reward,
// info and values beside it, and the reward over the episode below with the current time marked.
import uPlot from 'uplot';
import { api } from '../api.js';
import { formatNumber } from '../chart.js';
import { h, ordinal, runHash, setStatus } from '../dom.js';
import { SceneView } from '../scene3d.js';

function runOf(path) {
  const parts = path.split('/');
  const at = parts.lastIndexOf('episodes');
  return at > 0 ? parts.slice(0, at).join('/') : null;
}

export async function showReplay(container, query) {
  const path = query.get('path') || '';
  const episode = await api.episode(path);
  const frames = episode.frames;
  if (frames.length === 0) throw new Error(`${path}: no frames (${episode.problem || 'empty'})`);

  const run = runOf(path);
  const viewport = h('div', { class: 'viewport' });
  const play = h('button', { class: 'play' }, 'play');
  const slider = h('input', { type: 'range', min: 0, max: frames.length - 1, value: 0, 'aria-label': 'frame' });
  const speed = h('select', { 'aria-label': 'speed' },
    ...[0.1, 0.25, 0.5, 1, 2, 4, 10].map((s) => h('option', { value: s, selected: s === 1 }, `${s}×`)));
  const up = h('select', { 'aria-label': 'up axis' },
    h('option', { value: 'z' }, 'z up'), h('option', { value: 'y' }, 'y up'));
  const resetCamera = h('button', {}, 'reset camera');
  const clock = h('span', { class: 'clock' });
  const readout = h('table', { class: 'readout' });
  const rewardBox = h('div', { class: 'chart' });
  const meta = Object.entries(episode.metadata).map(([k, v]) => `${k}: ${v}`).join(' · ');
  container.append(...[
    h('h2', {}, path.split('/').pop(), run !== null ? h('small', {}, ' of ', h('a', { href: runHash(run) }, run || '(root)')) : null),
    h('p', { class: 'summary' }, meta,
      episode.summary ? ` · return ${formatNumber(episode.summary.return)} over ${episode.summary.steps} steps` : '',
      episode.stride > 1 ? ` · every ${ordinal(episode.stride)} of ${episode.frame_count} frames` : ''),
    episode.problem ? h('p', { class: 'problem' }, `Incomplete recording: ${episode.problem}. Showing the ${episode.frame_count} whole frames before it.`) : null,
    h('div', { class: 'replay' },
      viewport,
      h('aside', {}, readout)),
    h('div', { class: 'controls' }, play, slider, clock, speed, up, resetCamera),
    rewardBox,
  ].filter(Boolean));

  const view = new SceneView(viewport, episode);
  up.value = view.up;
  let index = 0;
  let playing = false;
  let time = frames[0].time;
  let last = null;
  const endTime = frames[frames.length - 1].time;

  const times = frames.map((f) => f.time);
  const rewardPlot = new uPlot({
    width: Math.max(rewardBox.clientWidth, 300),
    height: 160,
    scales: { x: { time: false } },
    series: [
      { label: 'time (s)' },
      { label: 'reward', stroke: '#1f77b4', width: 1.5, spanGaps: true },
      { label: 'return so far', stroke: '#2ca02c', width: 1.5, scale: 'return', spanGaps: true },
    ],
    axes: [{}, { label: 'reward' }, { side: 1, scale: 'return', label: 'return', grid: { show: false } }],
    hooks: {
      draw: [(u) => {
        const x = u.valToPos(frames[index].time, 'x', true);
        const { ctx } = u;
        ctx.save();
        ctx.strokeStyle = '#d62728';
        ctx.lineWidth = 2;
        ctx.beginPath();
        ctx.moveTo(x, u.bbox.top);
        ctx.lineTo(x, u.bbox.top + u.bbox.height);
        ctx.stroke();
        ctx.restore();
      }],
    },
  }, [times, frames.map((f) => (f.step === 0 ? null : f.reward)), frames.map((f) => f.return)], rewardBox);
  const resizer = new ResizeObserver(() => rewardPlot.setSize({ width: Math.max(rewardBox.clientWidth, 300), height: 160 }));
  resizer.observe(rewardBox);

  function show(i) {
    index = Math.max(0, Math.min(frames.length - 1, i));
    const frame = frames[index];
    view.show(index);
    slider.value = index;
    clock.textContent = `t = ${frame.time.toFixed(3)} s · step ${frame.step}`;
    const rows = [
      ['reward', frame.reward],
      ['return so far', frame.return],
      ...Object.entries(frame.values),
      ...Object.entries(frame.info).filter(([k]) => !(k in frame.values)),
    ];
    if (frame.terminated) rows.push(['terminated', 'yes']);
    if (frame.truncated) rows.push(['truncated', 'yes']);
    if (frame.action.length > 0) rows.push(['action', frame.action.map((a) => a.toFixed(2)).join(' ')]);
    readout.replaceChildren(...rows.map(([k, v]) => h('tr', {}, h('th', {}, k), h('td', {}, typeof v === 'number' ? formatNumber(v) : v))));
    rewardPlot.redraw(false);
  }

  function tick(now) {
    if (!playing) return;
    if (last !== null) {
      time += ((now - last) / 1000) * Number(speed.value);
      if (time >= endTime) {
        time = endTime;
        playing = false;
        play.textContent = 'play';
      }
      let i = index;
      while (i + 1 < frames.length && frames[i + 1].time <= time) i++;
      if (i !== index) show(i);
    }
    last = now;
    if (playing) requestAnimationFrame(tick);
  }

  play.addEventListener('click', () => {
    playing = !playing;
    play.textContent = playing ? 'pause' : 'play';
    if (playing) {
      if (index >= frames.length - 1) show(0);
      time = frames[index].time;
      last = null;
      requestAnimationFrame(tick);
    }
  });
  slider.addEventListener('input', () => {
    show(Number(slider.value));
    time = frames[index].time;
  });
  up.addEventListener('change', () => view.setUp(up.value));
  resetCamera.addEventListener('click', () => view.resetCamera());
  show(0);
  setStatus(episode.complete ? '' : 'incomplete recording', !episode.complete);

  return {
    dispose() {
      playing = false;
      resizer.disconnect();
      rewardPlot.destroy();
      view.dispose();
    },
  };
}
