// The headless core: the built page served on a loopback port and one Chromium checked to draw
// with the renderer asked for. Everything that draws headless starts here: a session of the
// command line and of the Node API (session.js: the server at once, the browser when the first
// view needs it, again after a hang), and the test harness (tests/support/setup.js: both at once,
// through startHeadless, with its own routes or the dev server).

import { startBrowser } from './browser.js';
import { findChrome } from './chrome-path.js';
import { builtPage, startPageServer } from './page-server.js';
import { CLOSE_TIMEOUT_MS, withTimeout } from './watch.js';

/**
 * The built page (built now where a clone's is stale: page-server.js builtPage) on a free
 * loopback port, with `routes` answered first.
 * @param {{routes?: import('./page-server.js').Routes, say?: (line: string) => void, verbose?: boolean}} [options]
 */
export async function servePage({ routes, say, verbose = false } = {}) {
  const root = await builtPage({ say, verbose });
  return startPageServer({ root, routes });
}

/**
 * Chromium, launched and checked to draw with `renderer` (browser.js startBrowser). With
 * `probe: false` the caller checks its first page's WebGL2 through verify().
 * @param {{renderer: import('./renderers.js').RendererName, executablePath?: string, probe?: boolean}} options
 */
export function launchChromium({ renderer, executablePath = findChrome(), probe = true }) {
  return startBrowser({ renderer, executablePath, probe });
}

/**
 * Chromium and a page server together, for whoever connects pages of its own to them (the test
 * harness): Chromium first, so that a machine without it is told before anything is built.
 * `serve` starts another server in place of the built page's (the harness's dev server).
 * @param {{renderer: import('./renderers.js').RendererName, routes?: import('./page-server.js').Routes,
 *   serve?: () => Promise<{baseUrl: string, close: () => Promise<void>}>, say?: (line: string) => void}} options
 */
export async function startHeadless({ renderer, routes, serve = () => servePage({ routes, say }), say }) {
  const chromium = await launchChromium({ renderer });
  let server;
  try {
    server = await serve();
  } catch (error) {
    await chromium.close().catch(() => {});
    throw error;
  }
  const opened = server;
  return {
    chromium,
    server: opened,
    /** Stops the server, then Chromium; the first failure is thrown after both were tried. */
    async close() {
      const results = await Promise.allSettled([
        withTimeout('closing the page server', opened.close(), CLOSE_TIMEOUT_MS),
        chromium.close(),
      ]);
      const failed = results.find((r) => r.status === 'rejected');
      if (failed) throw /** @type {PromiseRejectedResult} */ (failed).reason;
    },
  };
}
