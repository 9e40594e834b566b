// What every verb shares besides its session: where it prints (stdout for results, stderr for
// progress and errors), its one SHADER argument, and the watchdog's flag.

import { UsageError, readNumber } from './view-options.js';

export const io = {
  /** @param {string} line */
  out: (line) => process.stdout.write(line + '\n'),
  /** @param {string} line */
  err: (line) => process.stderr.write(line + '\n'),
  isTerminal: () => Boolean(process.stderr.isTTY),
};

/**
 * The page's watchdog from --watchdog S: without it, the page's own (5 s for a band of a frame,
 * 30 s for a program's first draw, in which SwiftShader compiles it); with it, S for both.
 * @param {string | undefined} text
 * @returns {{hangMs: number, compileHangMs: number}}
 */
export function watchdog(text) {
  if (text === undefined) return { hangMs: 5_000, compileHangMs: 30_000 };
  const ms = readNumber(text, '--watchdog', { min: 0.1 }) * 1000;
  return { hangMs: ms, compileHangMs: ms };
}

/** The one SHADER argument of a verb. @param {string[]} positionals @param {string} verb */
export function oneShader(positionals, verb) {
  if (positionals.length !== 1)
    throw new UsageError(`${verb}: expected one SHADER file, got ${positionals.length ? positionals.join(' ') : 'none'}`);
  return positionals[0];
}
