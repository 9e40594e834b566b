// Every wait on a page ends, and says why: the pages the test harness (tests/support/page.js) and
// the command line (src/cli/) open have waits (evaluate, waitForFunction, goto, ...) that each
// have a timeout shorter than the test's or the command's, and fail at once when the page or the browser crashes, with what the page was doing (its frame count, the
// error it reports, the message it shows, what window.shaderEngine.info() says) in the message.
// Without this a hung `shaderEngine.ready` ran into vitest's 120 s test timeout with no word about
// the page, and a wait on a crashed page never ended (puppeteer settles it only when the page is
// closed).

import { describePage } from './client.js';

/**
 * One wait on a page in a test (a load, `ready`, a frame, a read-back): SwiftShader compiles on
 * the CPU, and a test has 120 s (tests/vitest.config.js), so a hang fails the wait first.
 */
export const WAIT_TIMEOUT_MS = 90_000;
/**
 * One wait in a script (bench, accuracy, picture): puppeteer's own protocol timeout, 180 s, which
 * bounded them before; the benchmark compiles all its shaders in one call.
 */
export const SCRIPT_WAIT_TIMEOUT_MS = 180_000;
/**
 * Closing a page: the browser closes a tab in milliseconds, even one whose script is stuck in an
 * endless loop (measured: 0.1 s); a close that takes 10 s means the browser no longer answers.
 */
export const CLOSE_TIMEOUT_MS = 10_000;
/**
 * Asking a page what it was doing, after a failed wait: a page that answers at all does so in
 * milliseconds; after 2 s its script is taken to be stuck.
 */
const DESCRIBE_TIMEOUT_MS = 2_000;

/** The page's methods that wait on it, each given the timeout and the crash watch. */
const WAITS = ['evaluate', 'evaluateHandle', 'waitForFunction', 'waitForSelector', 'goto', 'reload', '$eval', '$$eval'];

/** How long a wait rejected with "Target closed" waits to hear that the browser is gone. */
const CRASH_NOTICE_MS = 500;

const TIMED_OUT = Symbol('timed out');

/** Resolves with TIMED_OUT after `ms` (unless cancelled); never with an infinite `ms`. */
function timer(ms) {
  let id;
  const promise = new Promise((resolve) => {
    if (Number.isFinite(ms)) id = setTimeout(() => resolve(TIMED_OUT), ms);
  });
  return { promise, cancel: () => clearTimeout(id) };
}

/**
 * The timeout a caller gave a wait in its own options, in ms (0: none, the caller bounds it),
 * or undefined: waitForFunction(fn, options), waitForSelector(selector, options), goto(url,
 * options) and reload(options) take one; evaluate does not.
 * @param {string} name
 * @param {unknown[]} args
 * @returns {number | undefined}
 */
function callersTimeout(name, args) {
  const at = { waitForFunction: 1, waitForSelector: 1, goto: 1, reload: 0 }[name];
  const options = at === undefined ? undefined : /** @type {{timeout?: unknown} | undefined} */ (args[at]);
  return options && typeof options === 'object' && typeof options.timeout === 'number' ? options.timeout : undefined;
}

/** Seconds for messages: "2 s", "0.5 s". */
const seconds = (ms) => `${ms / 1000} s`;

/**
 * Watches `page` of `browser`: its waiting methods (WAITS) time out after `waitTimeoutMs` (or
 * after the timeout the caller gave one in its options: 0 for none) and fail
 * at once on a crash; `close()` gives up after CLOSE_TIMEOUT_MS. Changes the page object in place.
 * @param {import('puppeteer-core').Page} page
 * @param {import('puppeteer-core').Browser} browser
 * @param {{waitTimeoutMs?: number}} [options]
 * @returns {{crashed: () => string | null, describe: () => Promise<string>}}
 */
export function watchPage(page, browser, { waitTimeoutMs = WAIT_TIMEOUT_MS } = {}) {
  /** @type {string | null} why the page is gone: set once, never cleared */
  let crash = null;
  /** @type {(why: string) => void} */
  let onCrash = () => {};
  const crashed = new Promise((resolve) => (onCrash = resolve));
  const setCrash = (/** @type {string} */ why) => {
    crash ??= why;
    onCrash(crash);
  };
  page.on('error', (error) => setCrash(`the page crashed (${error?.message ?? error})`));
  const onDisconnect = () => setCrash('the browser crashed or was closed (it disconnected)');
  browser.on('disconnected', onDisconnect);
  page.once('close', () => browser.off('disconnected', onDisconnect));

  const original = Object.fromEntries(WAITS.map((name) => [name, page[name].bind(page)]));
  const close = page.close.bind(page);

  /** What the page was doing, in one line, or why it cannot say. */
  async function describe() {
    if (crash) return `${crash}.`;
    const asked = timer(DESCRIBE_TIMEOUT_MS);
    const state = await Promise.race([
      describePage(original.evaluate).catch((error) => ({ failed: String(error?.message ?? error) })),
      asked.promise,
      crashed,
    ]);
    asked.cancel();
    if (crash) return `${crash}.`;
    if (state === TIMED_OUT)
      return `The page does not answer either (its script has been busy for over ${seconds(DESCRIBE_TIMEOUT_MS)}: an endless loop?).`;
    if ('failed' in state) return `The page could not be asked what it was doing (${state.failed}).`;
    return (
      `The page (${state.url.length > 120 ? `${state.url.slice(0, 117)}...` : state.url}): frames drawn ${state.frame ?? '(none)'}; error ${state.error ?? '(none)'}; ` +
      `message shown ${state.status ? JSON.stringify(state.status.slice(0, 500)) : '(none)'}; ` +
      `window.shaderEngine ${state.shaderEngine ? `info() ${JSON.stringify(state.info)}` : '(none)'}.`
    );
  }

  /** Runs one wait: its result, or an Error saying what was awaited, why it ended and what the page was doing. */
  async function within(what, run, ms) {
    if (crash) throw new Error(`${what}: ${crash}.`);
    const limit = timer(ms);
    /** @type {Promise<unknown>} */
    const work = run();
    const outcome = await Promise.race([
      work.then(
        (value) => ({ value }),
        (error) => ({ error }),
      ),
      limit.promise,
      crashed,
    ]);
    limit.cancel();
    if (outcome === TIMED_OUT) {
      work.catch(() => {}); // settles (rejected) when the page closes
      throw new Error(`${what}: no answer within ${seconds(ms)}. ${await describe()}`);
    }
    if (typeof outcome === 'string' || crash) {
      work.catch(() => {});
      throw new Error(`${what}: ${crash}.`);
    }
    if ('error' in outcome) {
      const error = outcome.error;
      // a browser that dies rejects the waits ("Target closed") a moment before it says so
      if (/closed/i.test(error?.message ?? '') && !crash) await Promise.race([crashed, timer(CRASH_NOTICE_MS).promise]);
      if (crash) throw new Error(`${what}: ${crash}.`, { cause: error });
      if (error?.name === 'TimeoutError') throw new Error(`${what}: ${error.message}. ${await describe()}`, { cause: error });
      throw error;
    }
    return outcome.value;
  }

  const target = /** @type {Record<string, Function>} */ (/** @type {unknown} */ (page));
  for (const name of WAITS) {
    target[name] = (...args) => {
      const subject = (typeof args[0] === 'function' ? args[0].toString() : String(args[0])).replace(/\s+/g, ' ');
      const what = `page.${name}(${subject.length > 80 ? `${subject.slice(0, 77)}...` : subject})`;
      // a caller's own timeout stands, and its 0 means no limit but a crash (a converge of many
      // samples, a long recording: their own loops watch the page's watchdog)
      const own = callersTimeout(name, args);
      return within(what, () => original[name](...args), own === undefined ? waitTimeoutMs : own === 0 ? Infinity : own);
    };
  }
  page.setDefaultTimeout(waitTimeoutMs);
  target.close = async (options) => {
    const limit = timer(CLOSE_TIMEOUT_MS);
    const outcome = await Promise.race([close(options).catch(() => undefined), limit.promise]);
    limit.cancel();
    if (outcome === TIMED_OUT)
      console.warn(`page.close() got no answer within ${seconds(CLOSE_TIMEOUT_MS)}; the browser is left to close it`);
  };
  return { crashed: () => crash, describe };
}

/**
 * Closes a browser this process launched, and kills it if the close gets no answer within
 * CLOSE_TIMEOUT_MS: a hung browser must not keep the test run alive after its summary.
 * @param {import('puppeteer-core').Browser} browser
 * @returns {Promise<'closed' | 'killed'>}
 */
export async function closeBrowser(browser) {
  const limit = timer(CLOSE_TIMEOUT_MS);
  const outcome = await Promise.race([browser.close().catch(() => undefined), limit.promise]);
  limit.cancel();
  if (outcome !== TIMED_OUT) return 'closed';
  killBrowser(browser);
  return 'killed';
}

/**
 * Kills a browser this process launched, with every process it started. Its GPU process, stuck in
 * a draw that never ends, does not die with the browser's main process: it goes on holding a
 * core, and the next browser on a 2-core machine crawls. Puppeteer starts Chromium as the leader
 * of a process group of its own (detached, on POSIX), so the group is killed whole.
 * @param {import('puppeteer-core').Browser} browser
 */
export function killBrowser(browser) {
  const child = browser.process();
  if (!child?.pid) return;
  try {
    process.kill(process.platform === 'win32' ? child.pid : -child.pid, 'SIGKILL');
  } catch {
    child.kill('SIGKILL');
  }
}

/**
 * `promise`, or a rejection saying `what` got no answer within `ms`.
 * @template T
 * @param {string} what
 * @param {Promise<T>} promise
 * @param {number} ms
 * @returns {Promise<T>}
 */
export async function withTimeout(what, promise, ms) {
  const limit = timer(ms);
  try {
    const outcome = await Promise.race([promise, limit.promise]);
    if (outcome === TIMED_OUT) {
      promise.catch(() => {});
      throw new Error(`${what}: no answer within ${seconds(ms)}`);
    }
    return /** @type {T} */ (outcome);
  } finally {
    limit.cancel();
  }
}
