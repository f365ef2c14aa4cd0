// A sweep's summary (summary/summary.md, written by `tendril sweep`): its headings, paragraphs,
// lists, tables and figures, drawn from the Markdown the sweep writes.
import { api } from '../api.js';
import { h } from '../dom.js';

// Inline Markdown of the summary: `code`, **bold**, [text](link); everything else as text.
function inline(text, base) {
  const parts = [];
  const pattern = /`([^`]+)`|\*\*([^*]+)\*\*|\[([^\]]+)\]\(([^)\s]+)\)/g;
  let last = 0;
  for (const match of text.matchAll(pattern)) {
    if (match.index > last) parts.push(text.slice(last, match.index));
    if (match[1] !== undefined) parts.push(h('code', {}, match[1]));
    else if (match[2] !== undefined) parts.push(h('strong', {}, match[2]));
    else parts.push(h('a', { href: resolve(match[4], base), target: '_blank' }, match[3]));
    last = match.index + match[0].length;
  }
  if (last < text.length) parts.push(text.slice(last));
  return parts;
}

// A link or image of the summary, relative to its directory, as a URL of the server's files.
function resolve(target, base) {
  if (/^[a-z]+:/i.test(target) || target.startsWith('#')) return target;
  const parts = [...base.split('/').filter(Boolean)];
  for (const part of target.split('/')) {
    if (part === '..') parts.pop();
    else if (part !== '.' && part !== '') parts.push(part);
  }
  return `files/${parts.map(encodeURIComponent).join('/')}`;
}

function cells(line) {
  return line.trim().replace(/^\|/, '').replace(/\|$/, '').split('|').map((c) => c.trim());
}

// Block Markdown: # headings, | tables |, - lists, ![images](file), paragraphs.
export function renderMarkdown(text, base) {
  const blocks = [];
  const lines = text.split('\n');
  let i = 0;
  while (i < lines.length) {
    const line = lines[i];
    if (line.trim() === '') {
      i++;
      continue;
    }
    const heading = line.match(/^(#{1,4})\s+(.*)$/);
    const image = line.trim().match(/^!\[([^\]]*)\]\(([^)\s]+)\)$/);
    if (heading) {
      blocks.push(h(`h${Math.min(heading[1].length + 1, 5)}`, {}, ...inline(heading[2], base)));
      i++;
    } else if (image) {
      blocks.push(h('figure', {}, h('img', { src: resolve(image[2], base), alt: image[1] }),
        h('figcaption', {}, image[1])));
      i++;
    } else if (line.trim().startsWith('|')) {
      const rows = [];
      while (i < lines.length && lines[i].trim().startsWith('|')) rows.push(lines[i++]);
      const header = cells(rows[0]);
      const body = rows.slice(1).filter((r) => !/^\s*\|?\s*:?-{2,}/.test(r));
      blocks.push(h('table', { class: 'summary-table' },
        h('thead', {}, h('tr', {}, ...header.map((c) => h('th', {}, ...inline(c, base))))),
        h('tbody', {}, ...body.map((r) => h('tr', {}, ...cells(r).map((c) => h('td', {}, ...inline(c, base))))))));
    } else if (/^\s*[-*]\s+/.test(line)) {
      const items = [];
      while (i < lines.length && /^\s*[-*]\s+/.test(lines[i])) {
        items.push(h('li', {}, ...inline(lines[i++].replace(/^\s*[-*]\s+/, ''), base)));
      }
      blocks.push(h('ul', {}, ...items));
    } else {
      const paragraph = [lines[i++].trim()];  // at least this line, whatever it starts with
      while (i < lines.length && lines[i].trim() !== '' && !/^(#|\||!\[|\s*[-*]\s)/.test(lines[i])) {
        paragraph.push(lines[i++].trim());
      }
      blocks.push(h('p', {}, ...inline(paragraph.join(' '), base)));
    }
  }
  return blocks;
}

export async function showSummary(container, query) {
  const path = query.get('path') || '';
  const text = await api.text(path);
  const base = path.split('/').slice(0, -1).join('/');
  container.append(h('p', { class: 'summary' }, h('a', { href: `files/${path.split('/').map(encodeURIComponent).join('/')}`, target: '_blank' }, path)),
    h('article', { class: 'markdown' }, ...renderMarkdown(text, base)));
  return {};
}
