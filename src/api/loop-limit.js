// What the command line does about llvmpipe's loop limit (src/shadertoy/loop-guard.js): it ends
// every pixel's loops after 65,535 trips in all, so a long loop, and every loop that never ends,
// draws a picture that is not the shader's. The render worker draws each pass with loops in a
// guarded form on llvmpipe, stops a frame at its first band with a cut, and logs what was cut
// (src/player/gpu/loop-cuts.js); after a verb has drawn, it reads the log here, and:
//   'fallback'  (llvmpipe by default) the verb is run again with SwiftShader, which has no limit,
//               saying so in one line;
//   'fail'      (--renderer llvmpipe, asked for; and `test`) the verb fails with a line that says
//               what was cut and what draws it whole, writing nothing: a picture that is not the
//               shader's, written with exit 0, is the one failure a script cannot see. A case
//               of `test` fails so, its reference unwritten.
// A pass whose guarded form could not be made is unchecked, and treated as cut.

import { ShaderproofError } from '../headless/session.js';

/** @typedef {'fallback' | 'fail'} LoopLimitMode */

/** What the limit is (the worker's report says its number), in the words of every line that names it. */
const limitWords = (/** @type {number} */ trips) => `each pixel's loops after ${trips.toLocaleString('en-US')} trips in all`;

/** The verb drew with llvmpipe by default, and a loop was cut: it is run again with SwiftShader. */
export class LoopLimitFallback extends ShaderproofError {
  /** @param {string} file @param {string[]} what each pass cut or unchecked, in a few words @param {number} limit */
  constructor(file, what, limit) {
    super(`${file}: ${what.join('; ')} (it ends ${limitWords(limit)}): drawn with SwiftShader instead`);
  }
}

/**
 * What the limit cut (or could not check) in `report`, a pass at a time: `short`, a few words
 * each; `lines`, whole lines with what to do. None when nothing was.
 * @param {import('../player/gpu/protocol.js').LoopReport | null} report
 * @returns {{short: string[], lines: string[]}}
 */
function loopLines(report) {
  if (!report?.enabled) return { short: [], lines: [] };
  const limit = limitWords(report.limit);
  /** @type {string[]} */
  const short = [];
  /** @type {string[]} */
  const lines = [];
  for (const { pass, first } of report.cuts) {
    short.push(`llvmpipe would cut a loop of its ${pass} pass short`);
    const where = pass === 'Sound' ? `sample ${first.sample}` : `x ${first.x}, y ${first.y} of frame ${first.frame}`;
    lines.push(
      `llvmpipe cut a loop of the ${pass} pass short (the first pixel at ${where}): it ends ${limit}, ` +
        'so it cannot draw this shader; --renderer swiftshader draws it whole',
    );
  }
  for (const { pass, reason } of report.unchecked) {
    short.push(`its ${pass} pass could not be checked for llvmpipe's loop limit (${reason})`);
    lines.push(
      `the ${pass} pass could not be checked for llvmpipe's loop limit (${reason}): it ends ${limit}, ` +
        'so its loops may be cut short unseen; --renderer swiftshader draws it without that limit',
    );
  }
  return { short, lines };
}

/**
 * After a verb has drawn, before it writes anything: what the limit cut, as `mode` says.
 * 'fallback' throws LoopLimitFallback; 'fail' returns the lines (a case fails with them; a
 * verb throws failLine's ShaderproofError).
 * @param {import('../headless/session.js').Session} session
 * @param {string} file
 * @param {LoopLimitMode} mode
 * @returns {Promise<string[]>}
 */
export async function judgeLoops(session, file, mode) {
  const report = await session.loopReport();
  const { short, lines } = loopLines(report);
  if (lines.length && mode === 'fallback') throw new LoopLimitFallback(file, short, report?.limit ?? 0);
  return lines;
}

/**
 * For render and record: nothing written where the limit cut a loop (or could not check one),
 * else the verb falls back to SwiftShader (judgeLoops).
 * @param {import('../headless/session.js').Session} session
 * @param {string} file
 */
export async function refuseCutLoops(session, file) {
  const [line] = await judgeLoops(session, file, session.loopLimit);
  if (line) throw new ShaderproofError(`${file}: ${line}; nothing written`);
}
