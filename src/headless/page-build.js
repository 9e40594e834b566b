// The page built for the command line (vite build), quietly. A first run in a clone builds it
// before its render, and Vite's log is none of the person's business then: its banner, the files
// it wrote and rolldown's plugin-timings table ([PLUGIN_TIMINGS], a warning) are kept, not
// printed. They are said with --verbose, and follow the one line that says why when the build
// fails. Vite's own reporter writes the files it wrote straight to stdout at log level info:
// at 'warn' it writes nothing, and what Vite logs goes to the logger given here.

import { stripVTControlCharacters } from 'node:util';

/** The header rolldown puts before its errors, no reason in itself. */
const FAILED_HEADER = /^Build failed with \d+ errors?:$/;

/**
 * Builds the page with the Vite config `configFile`. `say` hears the build's log line by line
 * with `verbose`, else nothing. Rejects, when the build fails, with one line that says why and
 * where, then the build's log.
 * @param {{configFile: string, verbose?: boolean, say?: (line: string) => void}} options
 * @returns {Promise<void>}
 */
export async function buildPage({ configFile, verbose = false, say = () => {} }) {
  const { build } = await import('vite');
  /** @type {string[]} */
  const log = [];
  const keep = (/** @type {unknown} */ message) => {
    const text = stripVTControlCharacters(String(message));
    log.push(text);
    if (verbose) say(text);
  };
  /** @type {import('vite').Logger} */
  const logger = {
    info: keep,
    warn: keep,
    warnOnce: keep,
    error: keep,
    clearScreen: () => {},
    hasErrorLogged: () => false,
    hasWarned: false,
  };
  try {
    await build({ configFile, logLevel: 'warn', customLogger: logger });
  } catch (error) {
    const said = stripVTControlCharacters(String(error?.message ?? error));
    const lines = said.split('\n').map((line) => line.trim());
    const why = lines.find((line) => line && !FAILED_HEADER.test(line)) ?? 'no reason given';
    const where = /\[\s*([^\s\]]+:\d+:\d+)\s*\]/.exec(said)?.[1];
    throw new Error(
      [
        `could not build the page (vite build): ${why}${where ? ` at ${where}` : ''}; fix that and run again (the build's log follows)`,
        ...[...log, ...said.split('\n')].filter((line) => line.trim()).map((line) => `  ${line}`),
      ].join('\n'),
      { cause: error },
    );
  }
}
