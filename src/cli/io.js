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
 * The page's notes on a view, one warning line each on stderr: what the shader went without
 * (the note's title, "NAME runs without…", is the line's `warning: FILE:` here), and values
 * that were not used as given (a control clamped into range), as the page shows them. One input
 * missing from several passes is one line naming them (mergeMissingLines). With `strict`, a view
 * that went without an input or a pass is an error instead (nothing is written): a render never
 * claims what did not happen, nor, then, what it drew in its place.
 * @param {string} file
 * @param {import('../engine/view.js').PageNote[]} notes
 * @param {{strict?: boolean}} [options]
 */
export function sayNotes(file, notes, { strict = false } = {}) {
  const missing = mergeMissingLines(notes.filter((note) => note.kind === 'missing').flatMap((note) => note.lines));
  if (strict && missing.length) {
    const what = missing[0].replace(/; the channel is black.*$/, '');
    throw new CliError(
      `${file}: --strict: nothing written, as it goes without ${missing.length === 1 ? what : `${missing.length} of what it asks for, the first: ${what}`}`,
    );
  }
  for (const line of missing) io.err(`warning: ${file}: ${line}`);
  for (const { title, lines } of notes.filter((note) => note.kind !== 'missing'))
    for (const line of lines) io.err(`warning: ${file}: ${title}: ${line}`);
}

/**
 * Lines of the "went without" note, each said once: "PASS, iChannelN: WHAT" lines that differ
 * in where they are (one texture three passes read) become one: "iChannel0 of A, B and C: WHAT",
 * "Image, iChannel0 and iChannel1: WHAT", or "A iChannel0, B iChannel2: WHAT"; the first one's
 * place is kept.
 * @param {string[]} lines
 */
export function mergeMissingLines(lines) {
  /** @type {Map<string, Array<{pass: string, channel: string}>>} what → where, in order */
  const groups = new Map();
  /** @type {Array<string | {what: string}>} */
  const order = [];
  for (const line of lines) {
    const match = /^([^,:]+), (iChannel\d): (.*)$/.exec(line);
    if (!match) {
      if (!order.includes(line)) order.push(line);
      continue;
    }
    const [, pass, channel, what] = match;
    if (!groups.has(what)) {
      groups.set(what, []);
      order.push({ what });
    }
    const places = /** @type {Array<{pass: string, channel: string}>} */ (groups.get(what));
    if (!places.some((p) => p.pass === pass && p.channel === channel)) places.push({ pass, channel });
  }
  const list = (/** @type {string[]} */ items) =>
    items.length < 2 ? items.join('') : `${items.slice(0, -1).join(', ')} and ${items.at(-1)}`;
  return order.map((entry) => {
    if (typeof entry === 'string') return entry;
    const places = /** @type {Array<{pass: string, channel: string}>} */ (groups.get(entry.what));
    if (places.length === 1) return `${places[0].pass}, ${places[0].channel}: ${entry.what}`;
    const channels = new Set(places.map((p) => p.channel));
    const passes = new Set(places.map((p) => p.pass));
    const where =
      passes.size === 1
        ? `${places[0].pass}, ${list(places.map((p) => p.channel))}`
        : channels.size === 1
          ? `${places[0].channel} of ${list(places.map((p) => p.pass))}`
          : places.map((p) => `${p.pass} ${p.channel}`).join(', ');
    return `${where}: ${entry.what}`;
  });
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

/** The one SHADER argument of a verb (the line that says otherwise is the verb's already). @param {string[]} positionals */
export function oneShader(positionals) {
  if (positionals.length !== 1)
    throw new UsageError(`expected one SHADER file, got ${positionals.length ? positionals.join(' ') : 'none'}`);
  return positionals[0];
}
