// What the command line does about llvmpipe's loop limit (src/shadertoy/loop-guard.js): it ends
// every pixel's loops after 65,535 trips in all, so a long loop, and every loop that never ends,
// draws a picture that is not the shader's. The render worker draws each pass with loops in a
// guarded form on llvmpipe and logs what was cut (src/page/gpu/loop-cuts.js); after a verb has
// drawn, it reads the log here, and:
//   'fallback'  (llvmpipe by default) each frame stops at its first cut, and the verb is run
//               again with SwiftShader, which has no limit, saying so in one line;
//   'warn'      (--renderer llvmpipe, asked for) the frames are drawn whole and written, with a
//               warning line for each pass cut (--strict: an error, nothing written);
//   'fail'      (`test`) each frame stops at its first cut, and the case fails, its reference
//               unwritten.
// A pass whose guarded form could not be made is unchecked, and treated as cut.

import { CliError } from './session.js';

/** @typedef {'fallback' | 'warn' | 'fail'} LoopLimitMode */

/** What the limit is (the worker's report says its number), in the words of every line that names it. */
const limitWords = (/** @type {number} */ trips) => `each pixel's loops after ${trips.toLocaleString('en-US')} trips in all`;

/** The verb drew with llvmpipe by default, and a loop was cut: it is run again with SwiftShader. */
export class LoopLimitFallback extends CliError {
  /** @param {string} file @param {string[]} what each pass cut or unchecked, in a few words @param {number} limit */
  constructor(file, what, limit) {
    super(`${file}: ${what.join('; ')} (it ends ${limitWords(limit)}): drawn with SwiftShader instead`);
  }
}

/**
 * The lines that say what the limit cut (or could not check) in `report`, one a pass; none when
 * nothing was.
 * @param {import('../page/gpu/protocol.js').LoopReport | null} report
 * @returns {{short: string[], lines: string[]}} short: a few words a pass; lines: the whole
 *   lines, with what to do
 */
function loopLines(report) {
  if (!report?.enabled) return { short: [], lines: [] };
  const LIMIT = limitWords(report.limit);
  const count = (/** @type {number} */ n, /** @type {string} */ unit) => `${n.toLocaleString('en-US')} ${unit}${n === 1 ? '' : 's'}`;
  /** @type {string[]} */
  const short = [];
  /** @type {string[]} */
  const lines = [];
  for (const { pass, pixels, frames, first } of report.cuts) {
    short.push(`llvmpipe would cut a loop of its ${pass} pass short`);
    const sound = pass === 'Sound';
    const where = sound ? `sample ${first.sample}` : `x ${first.x}, y ${first.y} of frame ${first.frame}`;
    const what = sound ? count(pixels, 'sample') : `${count(pixels, 'pixel')}${frames > 1 ? ` of ${count(frames, 'frame')}` : ''}`;
    lines.push(
      `llvmpipe cut a loop of the ${pass} pass short in ${what} (the first at ${where}): llvmpipe ends ${LIMIT}, ` +
        `so this is not the shader's ${sound ? 'sound' : 'picture'}; --renderer swiftshader draws it whole`,
    );
  }
  for (const { pass, reason } of report.unchecked) {
    short.push(`its ${pass} pass could not be checked for llvmpipe's loop limit (${reason})`);
    lines.push(
      `the ${pass} pass could not be checked for llvmpipe's loop limit (${reason}): llvmpipe ends ${LIMIT}, ` +
        'so its loops may be cut short unseen; --renderer swiftshader draws it without that limit',
    );
  }
  return { short, lines };
}

/**
 * After a verb has drawn (and before it writes anything): what the limit cut, dealt with as
 * `mode` says. 'fallback' throws LoopLimitFallback; 'warn' prints a warning a pass, or with
 * `strict` throws; 'fail' returns the lines (the test case fails with them).
 * @param {import('./session.js').Session} session
 * @param {string} file
 * @param {{mode: LoopLimitMode, strict?: boolean, warn?: (line: string) => void}} how
 * @returns {Promise<string[]>}
 */
export async function judgeLoops(session, file, { mode, strict = false, warn = () => {} }) {
  const report = await session.loopReport();
  const { short, lines } = loopLines(report);
  if (lines.length === 0 || mode === 'fail') return lines;
  if (mode === 'fallback') throw new LoopLimitFallback(file, short, report?.limit ?? 0);
  if (strict) throw new CliError(`${file}: --strict: nothing written, as ${lines[0]}`);
  for (const line of lines) warn(`warning: ${file}: ${line}`);
  return lines;
}
