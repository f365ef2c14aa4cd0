// Bundles the dashboard's page into the directory given as the first argument: index.html,
// app.js (the page with three.js and uPlot) and app.css. Offline: only node_modules is read.
import * as esbuild from 'esbuild';
import { copyFileSync, mkdirSync } from 'node:fs';
import { join } from 'node:path';

const out = process.argv[2];
if (!out) {
  console.error('usage: node build.mjs <output directory>');
  process.exit(2);
}
mkdirSync(out, { recursive: true });
await esbuild.build({
  entryPoints: { app: 'src/main.js' },
  bundle: true,
  minify: true,
  format: 'esm',
  target: ['es2020'],
  outdir: out,
  logLevel: 'warning',
  legalComments: 'linked',
});
copyFileSync('src/index.html', join(out, 'index.html'));
