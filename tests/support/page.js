// Opening the page and rendering views, in the test workers (one at a time: fileParallelism is
// off). Every test file that renders connects to the browser setup.js started, opens pages with
// the deterministic injection, and calls `disconnect` from its afterAll. Every wait on a page
// has its own timeout and fails at once on a crash, saying what the page was doing (watch.js).

import fs from 'node:fs';
import puppeteer from 'puppeteer-core';
import { fromBase64 } from '../../src/shared/pixels.js';
import { CLOSE_TIMEOUT_MS, SCRIPT_WAIT_TIMEOUT_MS, WAIT_TIMEOUT_MS, closeBrowser, withTimeout } from '../../src/headless/watch.js';
import { PAGE_PARAMS, viewQuery, viewSize } from './tables/views.js';
import { drawView } from '../../src/headless/view.js';
import { engineClient } from '../../src/headless/client.js';
import { openPage as openEnginePage } from '../../src/headless/page-open.js';

const INJECTION_SOURCE = fs.readFileSync(new URL('./deterministic-injection.js', import.meta.url), 'utf8');

let connection;
let scriptContext;

/** For scripts outside vitest: use the context that startHarness() returned (see withHarness). */
export function useHarness(context) {
  scriptContext = context;
}

/** What globalSetup provided (or a script set with useHarness): { wsEndpoint, baseUrl, environment }. */
export async function harnessContext() {
  if (scriptContext) return scriptContext;
  const { inject } = await import('vitest');
  const context = inject('harness');
  if (!context) {
    throw new Error(
      'The harness did not start: tests/support/setup.js must be the globalSetup of tests/vitest.config.js (run the tests with npm test).',
    );
  }
  return context;
}

/**
 * The browser this worker talks to: the run's own (setup.js), or, once that one is gone (it
 * crashed), one launched here for the rest of this test file, so that the next test still gets
 * a fresh page.
 * @returns {Promise<{browser: import('puppeteer-core').Browser, context: any, own: boolean}>}
 */
async function connect() {
  if (connection) {
    const current = await connection.catch(() => null);
    if (current?.browser.connected) return current;
    connection = undefined;
  }
  const pending = (async () => {
    const context = await harnessContext();
    try {
      const browser = await withTimeout(
        `connecting to Chromium at ${context.wsEndpoint}`,
        puppeteer.connect({ browserWSEndpoint: context.wsEndpoint, defaultViewport: null }),
        WAIT_TIMEOUT_MS,
      );
      return { browser, context, own: false };
    } catch (error) {
      const { startBrowser } = await import('../../src/headless/browser.js');
      console.warn(`The test run's Chromium is gone (${error.message}); launching another for the rest of this test file.`);
      const started = await startBrowser({ renderer: context.environment.rendererName, probe: false });
      return { browser: started.browser, context, own: true, closeOwn: started.close };
    }
  })();
  connection = pending;
  return pending;
}

/** Call from afterAll in every test file that renders. */
export async function disconnect() {
  await closeViewPage();
  if (!connection) return;
  const pending = connection;
  connection = undefined;
  const { browser, own, closeOwn } = await pending.catch(() => ({ browser: undefined, own: false, closeOwn: undefined }));
  if (own) await (closeOwn ? closeOwn() : closeBrowser(browser));
  else if (browser?.connected) await withTimeout('disconnecting from Chromium', browser.disconnect(), CLOSE_TIMEOUT_MS).catch(() => {});
}

/**
 * A fresh page with the deterministic injection (unless `deterministic: false`), and the page's
 * `timeouts` (src/shared/timeouts.js) set as given (e.g. config.js's SHORT_TIMEOUTS), collecting
 * console errors and page errors. Every wait on it (evaluate, waitForFunction, goto, ...) ends
 * within `waitTimeoutMs` (WAIT_TIMEOUT_MS in tests, SCRIPT_WAIT_TIMEOUT_MS in scripts), and at
 * once when the page or the browser crashes, with what the page was doing in the message; its
 * close() gives up after a while (watch.js). `on` opens it on another browser than the run's (the
 * benchmarks time one renderer beside another: tests/bench/renderer-set.js).
 * @param {{deterministic?: boolean, waitTimeoutMs?: number, timeouts?: Partial<import('../../src/shared/timeouts.js').Timeouts>,
 *   on?: {browser: import('puppeteer-core').Browser, context: object}}} [options]
 * @returns {Promise<{page: import('puppeteer-core').Page, errors: string[], context: object}>}
 */
export async function openPage({
  deterministic = true,
  waitTimeoutMs = scriptContext ? SCRIPT_WAIT_TIMEOUT_MS : WAIT_TIMEOUT_MS,
  timeouts = undefined,
  on = undefined,
} = {}) {
  const { browser, context } = on ?? (await connect());
  // the HTTP cache stays on: the build's files are revalidated (ETag; page-server.js), and what
  // the tests write into public/ is served with no-store (routes.js)
  const { page, errors } = await openEnginePage(browser, { waitTimeoutMs, timeouts, scripts: deterministic ? [INJECTION_SOURCE] : [] });
  return { page, errors, context };
}

/** The RGBA bytes of a base64 string from a page, checked to be width x height pixels. */
export function decodeRgba(base64, width, height, what) {
  const bytes = fromBase64(base64);
  if (bytes.length !== width * height * 4) {
    throw new Error(`${what}: ${bytes.length} bytes of pixels for ${width}x${height} (expected ${width * height * 4})`);
  }
  return Buffer.from(bytes.buffer, bytes.byteOffset, bytes.byteLength);
}

/**
 * The page renderView draws on, kept for the rest of the test file: loaded at the first view's
 * URL, then brought to each next view by window.shaderEngine.open() (src/player/open-view.js), which
 * gives what a fresh load of that URL gives (tests/browser/page-open.test.js) without loading the page
 * again. Closed by disconnect(), and after a view that failed (the next one gets a fresh page).
 * @type {{page: import('puppeteer-core').Page, errors: string[], context: any} | null}
 */
let viewSession = null;

async function closeViewPage() {
  const session = viewSession;
  viewSession = null;
  await session?.page.close().catch(() => {});
}

/**
 * Brings the page to a view (tests/support/tables/views.js: a fresh load for the first view of a test file,
 * window.shaderEngine.open() after), waits until its first frame, and reads one
 * rendered frame. Throws if the page reports a WebGL/compile error, logs a console error or
 * throws, renders a frame of the wrong size, or does not report the view's controls and time as
 * its current values (window.shaderEngine.info()).
 * @returns {Promise<{width:number, height:number, data:Buffer, url:string, frame:number, info:object}>}
 */
export async function renderView(view) {
  const reused = viewSession !== null && !viewSession.page.isClosed();
  if (!reused) viewSession = await openPage();
  const { page, context, errors: logged } = /** @type {NonNullable<typeof viewSession>} */ (viewSession);
  const seen = logged.length;
  /** What the page logged while it drew this view. */
  const errorsNow = () => logged.slice(seen);
  const query = viewQuery(view);
  const url = context.baseUrl + query;
  const [width, height] = viewSize(view);
  let navigations = 0;
  const onNavigated = (frame) => {
    if (frame === page.mainFrame()) navigations++;
  };
  page.on('framenavigated', onNavigated);
  let ok = false;
  const fail = (message) => {
    const errors = errorsNow();
    const said = errors.length ? `\nThe page logged:\n  ${errors.join('\n  ')}` : '';
    return new Error(`${view.name} (${url}): ${message}${said}`);
  };
  try {
    const drawn = await drawView(engineClient(page), { baseUrl: context.baseUrl, query, fresh: !reused }).catch((error) => {
      throw fail(`${error.message}${navigations > 1 ? ` (the page navigated ${navigations} times)` : ''}`);
    });
    if (drawn.error !== undefined) throw fail(drawn.error);
    const result = /** @type {Extract<import('../../src/headless/view.js').DrawnView, {pixels: object}>} */ (drawn);
    if (result.pageError) throw fail(`the page reports an error: ${result.pageError}`);
    if (!(result.frame >= 1)) throw fail(`no rendered frame: canvas data-frame is ${result.frame}`);
    const { pixels, info } = result;
    if (pixels.width !== width || pixels.height !== height) {
      throw fail(`readPixels returned ${pixels.width}x${pixels.height}, the view asks for ${width}x${height}`);
    }
    const ignored = Object.entries(view.params)
      .filter(([name]) => !PAGE_PARAMS.has(name))
      .filter(([name, value]) => JSON.stringify(info?.controls?.[name]) !== JSON.stringify(value))
      .map(([name, value]) => `${name}: asked ${JSON.stringify(value)}, page uses ${JSON.stringify(info?.controls?.[name])}`);
    if (ignored.length) throw fail(`the page did not apply the view's controls:\n  ${ignored.join('\n  ')}`);
    if ('time' in view.params && (info?.time !== view.params.time || info?.playing !== false)) {
      throw fail(`asked for time=${view.params.time} paused, page reports time=${info?.time} playing=${info?.playing}`);
    }
    const data = decodeRgba(pixels.data, width, height, view.name);
    if (errorsNow().length) throw fail('console errors or page errors while rendering');
    ok = true;
    return { width, height, data, url, frame: result.frame, info };
  } finally {
    page.off('framenavigated', onNavigated);
    if (!ok) await closeViewPage();
  }
}
