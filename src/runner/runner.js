// The cases of a test run on `jobs` workers, each its own session (its own Chromium: SwiftShader
// draws a browser's pages on one GPU thread, and a shader that never finishes holds that
// browser's GPU process, so pages of one browser would wait on each other). Each worker takes the
// next case not yet taken; the results come back in the cases' order whatever order they finish
// in, so that every report is the same as one worker's.
//
// One case never takes the run down: each runs guarded (guard.js). A case whose browser stopped
// answering, or whose run threw (a bug), fails with one line, its session is replaced (killed,
// and another started for the next case), and the run goes on.

import { ShaderproofError } from '../headless/session.js';
import { caseResult, runCase } from './case.js';
import { guarded } from './guard.js';

/** How long the run's end waits for given-up sessions to close (each is killed already). */
const CLOSING_MS = 10_000;

/**
 * @param {import('./manifest.js').TestCase[]} cases
 * @param {{jobs: number, start: () => Promise<import('../headless/session.js').Session>, silenceMs: number,
 *   run: {update: boolean, out: string, thumbnails: boolean}, verbose?: boolean,
 *   say?: (line: string) => void,
 *   onEnvironment?: (environment: {label: string, renderer: string, chromium: string, rendererName: import('../headless/renderers.js').RendererName}) => void,
 *   onSettled?: (result: import('./case.js').CaseResult) => void,
 *   onResult?: (result: import('./case.js').CaseResult) => void}} options
 *   start: a new session; silenceMs: guard.js's limit; onSettled: a case finished (any order);
 *   onResult: the next case in order has its result
 * @returns {Promise<{results: import('./case.js').CaseResult[], environment: {label: string, renderer: string, chromium: string, rendererName: import('../headless/renderers.js').RendererName}}>}
 */
export async function runCases(cases, { jobs, start, silenceMs, run, verbose = false, say = () => {}, ...hooks }) {
  const { onEnvironment = () => {}, onSettled = () => {}, onResult = () => {} } = hooks;
  /** @type {Promise<unknown>[]} sessions being closed */
  const closing = [];
  /** @type {(import('../headless/session.js').Session | null)[]} each worker's session */
  const sessions = [];
  const retire = (/** @type {number} */ worker) => {
    const old = sessions[worker];
    sessions[worker] = null;
    if (old)
      closing.push(
        old
          .kill()
          .then(() => old.close())
          .catch(() => {}),
      );
  };

  const first = await start();
  sessions[0] = first;
  let environment;
  try {
    environment = await guarded(first, (s) => s.environment(), { silenceMs });
  } catch (error) {
    retire(0);
    await settle(closing);
    if (error instanceof ShaderproofError) throw error;
    throw new ShaderproofError(`the browser did not start: ${String(error?.message ?? error).split('\n')[0]}`);
  }
  onEnvironment(environment);
  /** Each case is compared at the tolerance of the renderer that draws it (manifest.js). */
  const caseRun = { ...run, renderer: environment.rendererName };

  /** @type {import('./case.js').CaseResult[]} */
  const results = [];
  let next = 0;
  let reported = 0;
  const report = () => {
    for (; reported < cases.length && results[reported]; reported++) onResult(results[reported]);
  };

  /** One case on worker `worker`'s session: its result, whatever happens. */
  async function runOne(/** @type {number} */ worker, /** @type {import('./manifest.js').TestCase} */ testCase) {
    if (testCase.skip !== null) return caseResult(testCase, { ok: true, skipped: true, notes: [`skipped: ${testCase.skip}`] });
    const started = Date.now();
    try {
      const session = (sessions[worker] ??= await start());
      const result = await guarded(session, (s) => runCase(s, testCase, caseRun), { silenceMs });
      if (result.replace) retire(worker);
      return result;
    } catch (error) {
      retire(worker);
      const ms = Date.now() - started;
      if (error instanceof ShaderproofError) return caseResult(testCase, { failures: [error.message], ms });
      if (verbose) say(String(error?.stack ?? error));
      const why = String(error?.message ?? error).split('\n')[0];
      // a wait of the session's own that ran out (watch.js): the browser's silence, not a bug
      if (/: no answer within /.test(why))
        return caseResult(testCase, { failures: [`the browser stopped answering (${why}); it was replaced and the run went on`], ms });
      return caseResult(testCase, {
        failures: [`internal error: ${why} (run again with --verbose for its stack, and report it); the browser was replaced`],
        ms,
      });
    }
  }

  async function worker(/** @type {number} */ id) {
    while (next < cases.length) {
      const index = next++;
      const result = await runOne(id, cases[index]);
      results[index] = result;
      onSettled(result);
      report();
    }
  }

  const count = Math.max(1, Math.min(jobs, cases.filter((c) => c.skip === null).length));
  try {
    await Promise.all(Array.from({ length: count }, (_, id) => worker(id)));
  } finally {
    for (const session of sessions.splice(0)) if (session) closing.push(session.close().catch(() => {}));
    await settle(closing);
  }
  return { results, environment };
}

/** Waits for `promises`, at most CLOSING_MS. @param {Promise<unknown>[]} promises */
async function settle(promises) {
  let id;
  await Promise.race([Promise.allSettled(promises), new Promise((resolve) => (id = setTimeout(resolve, CLOSING_MS)))]);
  clearTimeout(id);
}
