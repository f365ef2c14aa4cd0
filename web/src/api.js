// The server's JSON API (src/tendril/dashboard/server.hpp). Every call rejects with the
// server's own message when it answers with an error.
async function getJson(url) {
  const response = await fetch(url, { cache: 'no-store' });
  let body;
  try {
    body = await response.json();
  } catch {
    throw new Error(`${url}: ${response.status} ${response.statusText}`);
  }
  if (!response.ok) throw new Error(body.error || `${url}: ${response.status}`);
  return body;
}

const q = encodeURIComponent;

// A file under the served directory as text (GET /files/PATH).
async function getText(path) {
  const response = await fetch(`files/${path.split('/').map(encodeURIComponent).join('/')}`, { cache: 'no-store' });
  if (!response.ok) {
    let message = `${path}: ${response.status}`;
    try {
      message = (await response.json()).error || message;
    } catch {
      // not JSON: keep the status
    }
    throw new Error(message);
  }
  return response.text();
}

export const api = {
  text: getText,
  index: () => getJson('api/index'),
  run: (path) => getJson(`api/run?path=${q(path)}`),
  csv: (path, offset = 0) => getJson(`api/csv?path=${q(path)}&offset=${offset}`),
  // Runs grouped by seed with each group's mean, std and run count per point of `metric`
  // ("eval", "eval:<column>" or a progress.csv column).
  curves: (paths, metric, points = 200) =>
    getJson(`api/curves?runs=${q(paths.join('|'))}&metric=${q(metric)}&points=${points}`),
  episode: (path, maxFrames = 2000) =>
    getJson(`api/episode?path=${q(path)}&max_frames=${maxFrames}`),
};

// A CSV file followed while it grows: poll() fetches the rows past the last offset and returns
// true when something changed. A file rewritten with other columns is read again from the start.
export class LiveCsv {
  constructor(path) {
    this.path = path;
    this.columns = [];
    this.rows = [];
    this.offset = 0;
    this.problems = [];
    this.missing = false;
  }

  async poll() {
    let slice;
    try {
      slice = await api.csv(this.path, this.offset);
    } catch (error) {
      this.missing = true;
      this.error = error.message;
      return false;
    }
    this.missing = false;
    const sameColumns =
      slice.columns.length === this.columns.length &&
      slice.columns.every((c, i) => c === this.columns[i]);
    if (slice.restarted || !sameColumns) {
      if (this.offset > 0 && !slice.restarted) {
        this.offset = 0;  // the header changed under us: read everything again
        return this.poll();
      }
      this.columns = slice.columns;
      this.rows = [];
      this.problems = [];
    }
    this.rows.push(...slice.rows);
    this.problems.push(...slice.problems);
    this.partial = slice.partial_line;
    const changed = slice.rows.length > 0 || slice.restarted || !sameColumns;
    this.offset = slice.next_offset;
    // A long file comes in pages (a bounded number of lines per answer).
    if (slice.more) return (await this.poll()) || changed;
    return changed;
  }

  column(name) {
    const index = this.columns.indexOf(name);
    return index < 0 ? null : this.rows.map((row) => row[index]);
  }
}
