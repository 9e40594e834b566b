// tests/scripts/test-times.js: the per-file table of docs/testing.md from vitest's JSON report.
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { describe, expect, test } from 'vitest';
import { REPO_ROOT } from '../support/config.js';
import { tableOf, timesOf } from '../scripts/test-times.js';

const file = (name, startTime, endTime, tests) => ({
  name: path.join(REPO_ROOT, 'tests', name),
  startTime,
  endTime,
  status: 'passed',
  assertionResults: Array.from({ length: tests }, () => ({ status: 'passed' })),
});

const REPORT = {
  startTime: 1_000,
  numTotalTests: 6,
  numPassedTests: 6,
  numFailedTests: 0,
  testResults: [file('quick.test.js', 5_000, 5_250, 4), file('slow.test.js', 5_250, 17_750, 2)],
};

describe('the suite time table', () => {
  test('files slowest first; the wall time runs from the run start (set-up included) to the last end', () => {
    const times = timesOf(REPORT);
    expect(times.files).toEqual([
      { file: 'tests/slow.test.js', tests: 2, seconds: 12.5 },
      { file: 'tests/quick.test.js', tests: 4, seconds: 0.25 },
    ]);
    expect(times.wall).toBe(16.75);
    expect(times.inFiles).toBe(12.75);
  });

  test("a report from another checkout (a worktree) links the repository's own paths", () => {
    const elsewhere = fs.mkdtempSync(path.join(os.tmpdir(), 'checkout-'));
    fs.writeFileSync(path.join(elsewhere, 'package.json'), '{}');
    const report = { ...REPORT, testResults: [{ ...REPORT.testResults[0], name: path.join(elsewhere, 'tests', 'bench', 'x.test.js') }] };
    expect(timesOf(report).files[0].file).toBe('tests/bench/x.test.js');
    fs.rmSync(elsewhere, { recursive: true });
  });

  test('the table names the machine, links each file, and says how it was written', () => {
    const table = tableOf(timesOf(REPORT), '2 cores (a CPU)');
    expect(table.split('\n')[0]).toBe(
      '6 tests in 2 files, 17 s of wall time (13 s in the files, the rest set-up: the build, Chromium), on 2 cores (a CPU); written by `npm run test:times`.',
    );
    expect(table).toContain('| [slow.test.js](tests/slow.test.js) | 2 | 12.5 |');
    expect(table).toContain('| [quick.test.js](tests/quick.test.js) | 4 | 0.3 |');
  });
});
