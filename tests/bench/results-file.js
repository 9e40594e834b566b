// The benchmark's results file (tests/bench/results.json): each renderer's last run, keyed by
// renderer, so that a run on one renderer (`npm run bench -- --renderer llvmpipe`) replaces that
// renderer's figures and keeps the other's, and the report shows both side by side.
//
//   { "swiftshader": { "run": Run, "results": [Entry, ...] }, "llvmpipe": { ... } }
//
// A file from before renderers were keyed (a bare list of entries) is SwiftShader's.

import fs from 'node:fs';

/**
 * One variant at one size on one renderer, as run.js writes it.
 * @typedef {{name: string, group: string, width: number, height: number, samplesPerPixel: number,
 *   medianMs: number, minMs: number, maxMs: number, frames: number, rmse: number, over2: number,
 *   extraSampleFraction?: number, chromium: string, renderer: string}} Entry
 */

/**
 * When and beside what a renderer's figures were measured: `renderers` are those interleaved in
 * that run (one run, one `started`), `loadAverage` the machine's 1-minute load at its start and
 * end, `cores` its processor count.
 * @typedef {{started: string, renderers: string[], cores: number, cpu: string, loadAverage: number[],
 *   copies: number, frames: number, warmup: number}} Run
 */

/** @typedef {Record<string, {run: Run | null, results: Entry[]}>} ResultsByRenderer */

/**
 * The results file's contents by renderer (an empty object when there is no file).
 * @param {string} file
 * @returns {ResultsByRenderer}
 */
export function readResults(file) {
  if (!fs.existsSync(file)) return {};
  return byRenderer(JSON.parse(fs.readFileSync(file, 'utf8')));
}

/**
 * A parsed results file by renderer; a bare list (the file before renderers were keyed) is
 * SwiftShader's, with no record of its run.
 * @param {unknown} parsed
 * @returns {ResultsByRenderer}
 */
export function byRenderer(parsed) {
  if (Array.isArray(parsed)) return { swiftshader: { run: null, results: parsed } };
  if (parsed && typeof parsed === 'object') return /** @type {ResultsByRenderer} */ (parsed);
  throw new Error('benchmark results: expected an object keyed by renderer, or a list of results');
}

/**
 * `old` with the renderers of `measured` replaced by theirs, the others kept.
 * @param {ResultsByRenderer} old
 * @param {ResultsByRenderer} measured
 * @returns {ResultsByRenderer}
 */
export function mergeResults(old, measured) {
  return { ...old, ...measured };
}
