// The one way a page is opened on the engine's browser, for the command line (src/headless/session.js)
// and the test harness (tests/support/page.js) alike: a new tab whose every wait ends (watch.js),
// at the viewport the goldens were drawn at, with scripts injected before the page's own (the
// page's timeouts; the tests' deterministic clock), collecting what the page logs as errors.

import { beforeEachLoad } from './client.js';
import { watchPage, withTimeout } from './watch.js';

/** The viewport every page opens at: the size its fixed-size views are drawn in. */
const VIEWPORT = { width: 800, height: 600, deviceScaleFactor: 1 };

/**
 * Opens a page on `browser`. `errors` fills with one line for each console error
 * ("console.error: text (url:line)"), page error and crash. The browser's own line for a
 * request that answered 404 ("Failed to load resource") is not the page's error: a shader or an
 * image that is not there is the page's to say, on the page, and the tests ask for such files.
 * @param {import('puppeteer-core').Browser} browser
 * @param {{waitTimeoutMs: number, timeouts?: Partial<import('../shared/timeouts.js').Timeouts>, scripts?: string[]}} options
 *   timeouts: the page's (src/shared/timeouts.js), set before it loads; scripts: sources run
 *   before the page's own
 * @returns {Promise<{page: import('puppeteer-core').Page, errors: string[]}>}
 */
export async function openPage(browser, { waitTimeoutMs, timeouts, scripts = [] }) {
  const page = await withTimeout('opening a page', browser.newPage(), waitTimeoutMs);
  watchPage(page, browser, { waitTimeoutMs });
  /** @type {string[]} */
  const errors = [];
  page.on('console', (message) => {
    if (message.type() !== 'error' || /^Failed to load resource: the server responded with a status of 404\b/.test(message.text())) return;
    const { url, lineNumber } = message.location() ?? {};
    errors.push(`console.error: ${message.text()}${url ? ` (${url}${lineNumber !== undefined ? `:${lineNumber + 1}` : ''})` : ''}`);
  });
  page.on('pageerror', (error) => errors.push(`page error: ${/** @type {Error} */ (error)?.message ?? error}`));
  page.on('error', (error) => errors.push(`page crashed: ${error?.message ?? error}`));
  await page.setViewport(VIEWPORT);
  await beforeEachLoad(page, scripts, timeouts);
  return { page, errors };
}
