// One case never takes a test run down: each case runs on a guarded session, which asks the
// page every second whether it still answers (a trivial evaluate). A page answering is left to
// its own watchdog (the shader's limits) and to the session's waits. A case that goes without a
// sign of life for longer than silenceLimitMs (a browser that cannot open a page, a page whose
// script no longer answers) is given up: its browser is killed (session.kill), the case fails
// with one line, and the runner starts another session for the next case (runner.js). Calls an
// abandoned case makes afterwards are refused, so that it can start nothing.

import { PRODUCTION_TIMEOUTS } from '../shared/timeouts.js';
import { ShaderproofError } from '../headless/session.js';

/** How often a running case's page is asked whether it answers. */
const HEARTBEAT_MS = 1_000;

/**
 * The longest a case may go without a sign of life: a new page's start (its render worker's own
 * limit, workerStartMs, covers a browser's launch and a page's load on a busy machine: the page
 * cannot be asked while it starts), then a first frame's compile and one band, each as long as
 * the watchdog allows (compileHangMs, hangMs). Past that, the page's own watchdog would have
 * spoken, had the page been able to.
 * @param {{hangMs: number, compileHangMs: number}} watchdog
 */
export function silenceLimitMs({ hangMs, compileHangMs }) {
  return PRODUCTION_TIMEOUTS.workerStartMs + compileHangMs + hangMs;
}

/** The error a case's own work gets once the runner has given it up (it is not reported). */
class Abandoned extends Error {}

/**
 * Runs `work` on a guarded view of `session`. Resolves with the work's value, or rejects: with
 * the work's own error, or with a ShaderproofError saying that the browser stopped answering, after
 * `silenceMs` without a sign of life (then the session is killed: the caller must start another).
 * @template T
 * @param {import('../headless/session.js').Session} session
 * @param {(guarded: import('../headless/session.js').Session) => Promise<T>} work
 * @param {{silenceMs: number}} limits
 * @returns {Promise<T>}
 */
export function guarded(session, work, { silenceMs }) {
  let lastAlive = Date.now();
  let given = false;
  let asking = false;
  const alive = () => (lastAlive = Date.now());
  /** @type {(error: Error) => void} */
  let giveUp = () => {};
  const gaveUp = new Promise((_, reject) => (giveUp = reject));

  /** @type {any} */
  const view = {
    ...session,
    client: () => (given ? null : session.client()),
    kill: session.kill,
  };
  for (const name of /** @type {const} */ (['draw', 'drawFloat', 'environment'])) {
    view[name] = async (/** @type {any[]} */ ...args) => {
      if (given) throw new Abandoned('the runner gave this case up');
      alive();
      try {
        return await /** @type {Function} */ (session[name])(...args);
      } finally {
        alive();
      }
    };
  }

  const ask = () => {
    const client = session.client();
    if (asking || !client || client.isClosed()) return;
    asking = true;
    client
      .ping()
      .then(alive, () => {})
      .finally(() => (asking = false));
  };
  const beat = setInterval(
    () => {
      if (Date.now() - lastAlive <= silenceMs) return ask();
      given = true;
      clearInterval(beat);
      const seconds = Number((silenceMs / 1000).toFixed(1));
      giveUp(new ShaderproofError(`the browser stopped answering: no word from it for ${seconds} s; it was replaced and the run went on`));
    },
    Math.min(HEARTBEAT_MS, silenceMs / 4),
  );

  const done = Promise.resolve()
    .then(() => work(view))
    .finally(() => clearInterval(beat));
  done.catch(() => {}); // once given up, its own end is not waited for
  return Promise.race([done, gaveUp]).catch(async (error) => {
    if (given) await session.kill().catch(() => {});
    throw error;
  });
}
