// What a test run reports, chosen by --reporter (repeatable, or a comma list; all three by
// default): `dot`, a line for each case on stdout as it comes (in the cases' order); `junit`,
// junit.xml (junit.js); `html`, index.html with its images (html-report.js). On a terminal the
// run also shows a progress line on stderr, kept below the case lines.

import { io } from '../../api/io.js';
import { UsageError } from '../../api/view-options.js';

const REPORTERS = /** @type {const} */ (['dot', 'junit', 'html']);

/** @typedef {typeof REPORTERS[number]} Reporter */

/**
 * The reporters --reporter names (each value a name or a comma list), or all of them.
 * @param {string[] | undefined} given
 * @returns {Set<Reporter>}
 */
export function readReporters(given) {
  if (!given?.length) return new Set(REPORTERS);
  const names = given.flatMap((value) => value.split(',')).map((name) => name.trim());
  const unknown = names.filter((name) => !(/** @type {readonly string[]} */ (REPORTERS).includes(name)));
  if (unknown.length)
    throw new UsageError(
      `--reporter ${unknown[0] || '""'}: expected ${REPORTERS.join(', ')} (repeat the flag or give a comma list, such as --reporter dot,html)`,
    );
  return new Set(/** @type {Reporter[]} */ (names));
}

/** A case's line: pass, FAIL or skip, its name, its time, what it said. @param {import('../case.js').CaseResult} result */
export function dotLine(result) {
  if (result.skipped) return `skip  ${result.name.padEnd(28)} ${'-'.padStart(6)}     ${result.notes.join('; ').replace(/^skipped: /, '')}`;
  const said = [...result.failures, ...result.notes].join('; ');
  return `${result.ok ? 'pass' : 'FAIL'}  ${result.name.padEnd(28)} ${String(result.ms).padStart(6)} ms  ${said}`.trimEnd();
}

/** "1:05" from milliseconds. @param {number} ms */
const clock = (ms) => `${Math.floor(ms / 60_000)}:${String(Math.floor((ms % 60_000) / 1000)).padStart(2, '0')}`;

/**
 * The progress line of a run of `total` cases, on a terminal only (a log or CI gets the case
 * lines and the summary): how many are done and failed, the time so far and an estimate of
 * what is left, redrawn every second and after each case. `line` prints a case line above it.
 * @param {number} total
 */
export function progressLine(total) {
  const started = Date.now();
  let done = 0;
  let failed = 0;
  let shown = '';
  const terminal = io.isTerminal();
  const draw = () => {
    if (!terminal) return;
    const spent = Date.now() - started;
    const left = done ? ` · about ${clock((spent / done) * (total - done))} left` : '';
    const width = 24;
    const filled = Math.round((done / Math.max(1, total)) * width);
    shown = `[${'#'.repeat(filled)}${'.'.repeat(width - filled)}] ${done}/${total} cases · ${failed} failed · ${clock(spent)}${left}`;
    process.stderr.write(`\r\x1b[2K${shown}`);
  };
  const clear = () => {
    if (terminal && shown) process.stderr.write('\r\x1b[2K');
  };
  const timer = terminal ? setInterval(draw, 1000) : null;
  timer?.unref();
  draw();
  return {
    /** A case finished (in any order). @param {import('../case.js').CaseResult} result */
    settled(result) {
      done++;
      if (!result.ok) failed++;
      draw();
    },
    /** Prints `text` on stdout above the progress line. @param {string} text */
    line(text) {
      clear();
      io.out(text);
      if (shown) draw();
    },
    end() {
      if (timer) clearInterval(timer);
      clear();
      shown = '';
    },
  };
}
