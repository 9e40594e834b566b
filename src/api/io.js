// What every verb shares besides its session: where it prints (stdout for results, stderr for
// progress and errors), its one SHADER argument, and the watchdog's flag.

import { RENDERER_ENV, chooseRenderer } from '../headless/renderers.js';
import { sayOnce } from '../shared/said-once.js';
import { ShaderproofError } from '../headless/session.js';
import { watchdogFor } from '../headless/watchdog/limits.js';
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
 * missing from several passes is one line naming them (sayOnce, src/shared/said-once.js). With `strict`, a view
 * that went without an input or a pass is an error instead (nothing is written): a render never
 * claims what did not happen, nor, then, what it drew in its place.
 * @param {string} file
 * @param {import('../headless/view.js').PageNote[]} notes
 * @param {{strict?: boolean, say?: (line: string) => void}} [options] say: where the warnings go
 */
export function sayNotes(file, notes, { strict = false, say = io.err } = {}) {
  const missing = sayOnce(notes.filter((note) => note.kind === 'missing').flatMap((note) => note.lines));
  if (strict && missing.length) {
    // nothing was drawn, so nothing was drawn black ("the channel is", "both channels are", ...)
    const what = missing[0].replace(/; (the channel is|both channels are|all \d+ channels are) black.*$/, '');
    throw new ShaderproofError(
      `${file}: --strict: nothing written, as it goes without ${missing.length === 1 ? what : `${missing.length} of what it asks for, the first: ${what}`}`,
    );
  }
  for (const line of missing) say(`warning: ${file}: ${line}`);
  for (const { title, lines } of notes.filter((note) => note.kind !== 'missing'))
    for (const line of lines) say(`warning: ${file}: ${title}: ${line}`);
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
 * What a verb's session draws with and how long it waits: the renderer (--renderer, --gpu, else
 * `fallback`: 'auto' is llvmpipe where Mesa is installed, else SwiftShader) and the watchdog
 * (--watchdog S for every band, else the renderer's own limits: watchdog.js), and whether a build
 * of the page says its log (--verbose).
 * @param {{renderer?: string, gpu?: boolean, watchdog?: string, verbose?: boolean}} values
 * @param {import('../headless/renderers.js').RendererName | 'auto'} fallback
 */
export function sessionOptions(values, fallback) {
  let renderer;
  try {
    // $SHADERPROOF_RENDERER is as if --renderer were given, unless a flag says otherwise
    const fromEnv = values.gpu ? undefined : process.env[RENDERER_ENV] || undefined;
    renderer = chooseRenderer({ ...values, renderer: values.renderer ?? fromEnv }, fallback);
  } catch (error) {
    throw new UsageError(error.message);
  }
  const seconds = values.watchdog === undefined ? null : readNumber(values.watchdog, '--watchdog', { min: 0.1 });
  // llvmpipe by default gives way to SwiftShader where its loop limit would cut a loop; asked
  // for, it fails there (loop-limit.js)
  const asked = Boolean(values.gpu || values.renderer || process.env[RENDERER_ENV]) || fallback !== 'auto';
  /** @type {import('./loop-limit.js').LoopLimitMode} */
  const loopLimit = asked ? 'fail' : 'fallback';
  return { renderer, loopLimit, verbose: Boolean(values.verbose), ...watchdogFor(renderer, seconds) };
}

/** A frame slower than this gets a progress line on a terminal. */
const SLOW_FRAME_MS = 1_000;

/**
 * A session's `progress`: on a terminal, one line that says how far a slow frame has got (the
 * rows of the pass under way, and how long the GPU has been on its band), rewritten in place and
 * cleared when the view is done (null); nothing on a log or CI.
 */
export function frameProgress() {
  let since = 0;
  let shown = false;
  /** @param {import('../headless/view.js').ViewProgress | null} state */
  return (state) => {
    if (!io.isTerminal()) return;
    if (state === null) {
      if (shown) process.stderr.write('\r\x1b[2K');
      since = 0;
      shown = false;
      return;
    }
    const now = Date.now();
    if (since === 0) since = now;
    if (now - since < SLOW_FRAME_MS) return;
    const band = state.band ? `, ${state.band.compiling ? 'compiling' : 'on a band'} for ${state.band.seconds.toFixed(1)} s` : '';
    const rows = state.height ? `${state.rows}/${state.height} rows` : 'starting';
    process.stderr.write(`\r\x1b[2Kdrawing a frame: ${rows}, ${state.bands} bands${band}`);
    shown = true;
  };
}

/** The one SHADER argument of a verb (the line that says otherwise is the verb's already). @param {string[]} positionals */
export function oneShader(positionals) {
  if (positionals.length !== 1)
    throw new UsageError(`expected one SHADER file, got ${positionals.length ? positionals.join(' ') : 'none'}`);
  return positionals[0];
}
