// What every verb shares besides its session: where it prints (stdout for results, stderr for
// progress and errors), its one SHADER argument, and the watchdog's flag.

import { PRODUCTION_TIMEOUTS } from '../shared/timeouts.js';
import { CliError } from './session.js';
import { UsageError, readNumber } from './view-options.js';

export const io = {
  /** @param {string} line */
  out: (line) => process.stdout.write(line + '\n'),
  /** @param {string} line */
  err: (line) => process.stderr.write(line + '\n'),
  isTerminal: () => Boolean(process.stderr.isTTY),
};

/**
 * The page's notes on a view, one warning line each on stderr: what the shader went without,
 * and values that were not used as given (a control clamped into range), as the page shows them.
 * With `strict`, a view that went without an input or a pass is an error instead (nothing is
 * written): a render never claims what did not happen.
 * @param {string} file
 * @param {import('../engine/view.js').PageNote[]} notes
 * @param {{strict?: boolean}} [options]
 */
export function sayNotes(file, notes, { strict = false } = {}) {
  const missing = notes.filter((note) => note.kind === 'missing').flatMap((note) => note.lines);
  if (strict && missing.length)
    throw new CliError(
      `${file}: --strict: it went without ${missing.length === 1 ? 'this' : `${missing.length} things, the first`}: ${missing[0]}`,
    );
  for (const { title, lines } of notes) for (const line of lines) io.err(`warning: ${file}: ${title}: ${line}`);
}

/**
 * Whether a line of the page's "went without" note is one a test case allows: an entry of its
 * manifest's allowMissing names the pass ("Sound", "Cube A"), the channel ("iChannel2", in any
 * pass) or both ("Image/iChannel2"). A line reads "PASS, iChannelN: …" or "PASS: …".
 * @param {string} line
 * @param {string[]} allowed
 */
export function allowedMissing(line, allowed) {
  const match = /^([^,:]+?)(?:, (iChannel\d))?:/.exec(line);
  if (!match) return false;
  const [, pass, channel] = match;
  return allowed.some((entry) => entry === pass || (channel !== undefined && (entry === channel || entry === `${pass}/${channel}`)));
}

/**
 * A progress bar on stderr, on a terminal only (a log or CI gets the one result line): `update`
 * after each step, `end` once, whatever the outcome.
 * @param {string} unit what is counted ("frames", "samples")
 */
export function progressBar(unit) {
  let shown = '';
  const line = (done, total) => {
    const width = 30;
    const filled = total ? Math.round((Math.min(done, total) / total) * width) : 0;
    return `[${'#'.repeat(filled)}${'.'.repeat(width - filled)}] ${done}/${total} ${unit}`;
  };
  return {
    /** @param {number} done @param {number} total */
    update(done, total) {
      const next = line(done, total);
      if (io.isTerminal() && next !== shown) process.stderr.write(`\r${next}`);
      shown = next;
    },
    end() {
      if (io.isTerminal() && shown) process.stderr.write('\n');
    },
  };
}

/**
 * The page's watchdog from --watchdog S: without it, the page's own (5 s for a band of a frame,
 * 30 s for a program's first draw, in which SwiftShader compiles it); with it, S for both.
 * @param {string | undefined} text
 * @returns {{hangMs: number, compileHangMs: number}}
 */
export function watchdog(text) {
  if (text === undefined) return { hangMs: PRODUCTION_TIMEOUTS.hangMs, compileHangMs: PRODUCTION_TIMEOUTS.compileHangMs };
  const ms = readNumber(text, '--watchdog', { min: 0.1 }) * 1000;
  return { hangMs: ms, compileHangMs: ms };
}

/** The one SHADER argument of a verb. @param {string[]} positionals @param {string} verb */
export function oneShader(positionals, verb) {
  if (positionals.length !== 1)
    throw new UsageError(`${verb}: expected one SHADER file, got ${positionals.length ? positionals.join(' ') : 'none'}`);
  return positionals[0];
}
