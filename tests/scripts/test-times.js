// The suite's time, file by file, in docs/testing.md (between the test-times markers).
//
//   npm run test:times                  runs `npm test` with vitest's JSON reporter beside its own,
//                                       then writes the table
//   npm run test:times -- --from FILE   writes the table from a report a run already left (for
//                                       example CI's: vitest run --reporter=json --outputFile=FILE)
//
// Vitest's JSON report gives each file its start and end (ms since the epoch) and each test its
// duration. Files run one at a time (fileParallelism is off), so a file's time is its end less its
// start, and the run's wall time is the last end less the first start, set-up included.

import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { OUTPUT_DIR, REPO_ROOT } from '../support/config.js';
import { replaceMarkedSection } from './readme-section.js';

const TIMES_DOC = path.join(REPO_ROOT, 'docs', 'testing.md');
const DEFAULT_REPORT = path.join(OUTPUT_DIR, 'test-times.json');

/**
 * @typedef {{name: string, startTime: number, endTime: number, status: string, assertionResults: {status: string}[]}} FileResult
 * @typedef {{startTime: number, numTotalTests: number, numPassedTests: number, numFailedTests: number, testResults: FileResult[]}} Report
 */

/**
 * The checkout a test file belongs to: the nearest folder above it with a package.json (a run in
 * another worktree names its own files, whose links must still be the repository's own paths).
 * @param {string} file
 */
function checkoutOf(file) {
  for (let dir = path.dirname(file); dir !== path.dirname(dir); dir = path.dirname(dir))
    if (fs.existsSync(path.join(dir, 'package.json'))) return dir;
  return REPO_ROOT;
}

/**
 * The table's rows, slowest first, and the run's figures.
 * @param {Report} report
 */
export function timesOf(report) {
  const files = report.testResults.map((file) => ({
    file: path.relative(checkoutOf(file.name), file.name).split(path.sep).join('/'),
    tests: file.assertionResults.length,
    seconds: Math.max(0, file.endTime - file.startTime) / 1000,
  }));
  files.sort((a, b) => b.seconds - a.seconds || a.file.localeCompare(b.file));
  const ends = report.testResults.map((f) => f.endTime);
  const wall = ends.length ? (Math.max(...ends) - report.startTime) / 1000 : 0;
  const inFiles = files.reduce((sum, f) => sum + f.seconds, 0);
  return { files, wall, inFiles, tests: report.numTotalTests, failed: report.numFailedTests };
}

/**
 * The table, its links relative to `linkFrom` (the folder of the document it goes in).
 * @param {ReturnType<typeof timesOf>} times @param {string} machine @param {string} [linkFrom]
 */
export function tableOf({ files, wall, inFiles, tests, failed }, machine, linkFrom = '') {
  const lines = [
    `${tests} tests in ${files.length} files, ${wall.toFixed(0)} s of wall time (${inFiles.toFixed(0)} s in the files, the rest set-up: the build, Chromium)${failed ? `, ${failed} failed` : ''}, on ${machine}; written by \`npm run test:times\`.`,
    '',
    '| file | tests | s |',
    '|---|---:|---:|',
    ...files.map((f) => `| [${path.basename(f.file)}](${linkFrom}${f.file}) | ${f.tests} | ${f.seconds.toFixed(1)} |`),
  ];
  return lines.join('\n');
}

function machineName() {
  const cpus = os.cpus();
  return `${cpus.length} cores (${cpus[0]?.model.trim() ?? 'unknown CPU'})`;
}

function main(argv) {
  const from = argv.indexOf('--from');
  let reportFile = DEFAULT_REPORT;
  if (from >= 0) {
    reportFile = path.resolve(argv[from + 1] ?? '');
    if (!argv[from + 1] || !fs.existsSync(reportFile)) {
      console.error(`test-times: --from needs a vitest JSON report; ${argv[from + 1] ?? '(none given)'} is not there.`);
      return 2;
    }
  } else {
    fs.mkdirSync(OUTPUT_DIR, { recursive: true });
    const run = spawnSync(
      'npx',
      ['vitest', 'run', '--config', 'tests/vitest.config.js', '--reporter=default', '--reporter=json', `--outputFile.json=${reportFile}`],
      { cwd: REPO_ROOT, stdio: 'inherit' },
    );
    if (run.status !== 0) {
      console.error(`test-times: the suite failed (exit ${run.status}); docs/testing.md is left as it was.`);
      return run.status ?? 1;
    }
  }
  /** @type {Report} */
  const report = JSON.parse(fs.readFileSync(reportFile, 'utf8'));
  const times = timesOf(report);
  if (times.failed) {
    console.error(`test-times: ${times.failed} tests failed in ${reportFile}; docs/testing.md is left as it was.`);
    return 1;
  }
  replaceMarkedSection(TIMES_DOC, 'test-times', tableOf(times, machineName(), '../'));
  console.log(`docs/testing.md: ${times.tests} tests, ${times.wall.toFixed(0)} s of wall time, ${times.files.length} files.`);
  return 0;
}

if (process.argv[1] && path.resolve(process.argv[1]) === path.resolve(new URL(import.meta.url).pathname)) {
  process.exitCode = main(process.argv.slice(2));
}
