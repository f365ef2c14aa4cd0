// Small helpers for building the page's elements.
export function h(tag, attributes = {}, ...children) {
  const element = document.createElement(tag);
  for (const [key, value] of Object.entries(attributes)) {
    if (value === undefined || value === null || value === false) continue;
    if (key.startsWith('on')) element.addEventListener(key.slice(2), value);
    else if (key === 'class') element.className = value;
    else element.setAttribute(key, value === true ? '' : value);
  }
  for (const child of children.flat()) {
    if (child === null || child === undefined || child === false) continue;
    element.append(child instanceof Node ? child : document.createTextNode(String(child)));
  }
  return element;
}

export function link(hash, text) {
  return h('a', { href: hash }, text);
}

export function runHash(path) {
  return `#/run?path=${encodeURIComponent(path)}`;
}

export function episodeHash(path) {
  return `#/episode?path=${encodeURIComponent(path)}`;
}

export function summaryHash(path) {
  return `#/summary?path=${encodeURIComponent(path)}`;
}

// 1st, 2nd, 3rd, 4th, …, 11th, 12th, 13th, 21st.
export function ordinal(n) {
  const tens = n % 100;
  const suffix = tens >= 11 && tens <= 13 ? 'th' : { 1: 'st', 2: 'nd', 3: 'rd' }[n % 10] || 'th';
  return `${n}${suffix}`;
}

export function compareHash(paths, options = {}) {
  const query = new URLSearchParams({ runs: paths.join('|') });
  if (options.group) query.set('group', '1');
  if (options.metric) query.set('metric', options.metric);
  return `#/compare?${query}`;
}

export function setStatus(text, isError = false) {
  const status = document.getElementById('status');
  status.textContent = text;
  status.className = isError ? 'error' : '';
}

export function ago(seconds) {
  const age = Date.now() / 1000 - seconds;
  if (!Number.isFinite(age) || seconds <= 0) return '';
  if (age < 60) return `${Math.max(0, Math.round(age))} s ago`;
  if (age < 3600) return `${Math.round(age / 60)} min ago`;
  if (age < 86400) return `${Math.round(age / 3600)} h ago`;
  return new Date(seconds * 1000).toISOString().slice(0, 10);
}
