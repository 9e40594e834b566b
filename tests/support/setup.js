// Browser and server set-up: one headless Chromium and one page server for a whole test run.
//
// As vitest's globalSetup (tests/vitest.config.js), `setup` runs once in the main process: it finds a
// Chromium and launches it headless on SwiftShader, checked to be SwiftShader
// (src/headless/core.js startHeadless, the command line's own core), builds the page and serves
// the build on a free loopback port (page-server.js), and hands the browser's
// endpoint and the page's URL to the test files (project.provide → inject('harness'), read by
// page.js). The function it returns stops both. Scripts (the benchmark, the accuracy report,
// the README picture) do the same through withHarness.

import { UPDATING } from './config.js';
import { startHeadless } from '../../src/headless/core.js';
import { RENDERER_ENV, suiteRenderer } from '../../src/headless/renderers.js';
import { disconnect, useHarness } from './page.js';
import { startPageServer } from './page-server.js';
import { WAIT_TIMEOUT_MS } from '../../src/headless/watch.js';
import { openPage } from '../../src/headless/page-open.js';

/**
 * Loads the page once before any test. On the dev server (SHADERPROOF_TEST_SERVER=dev) Vite then
 * has transformed every module and pre-bundled every dependency (one it discovers during a test's
 * page load makes it reload that page mid-test); on either, the built-in shader has compiled once.
 * Best effort: a page that fails here fails, with a message, in the tests.
 */
async function warmUp(browser, baseUrl) {
  // each wait on it ends (a `ready` that never settled hung the run here)
  const { page } = await openPage(browser, { waitTimeoutMs: WAIT_TIMEOUT_MS });
  try {
    await page.goto(`${baseUrl}/?size=32x18&time=0`, { waitUntil: 'load' });
    await page.waitForFunction(() => window.shaderEngine || document.documentElement.dataset.error);
    await page.evaluate(() => window.shaderEngine?.ready.catch(() => {}));
  } catch (error) {
    // the tests report it for themselves; this says why they may start slowly
    console.warn(`harness warm-up: ${error.message.split('\n')[0]}`);
  } finally {
    await page.close();
  }
}

/**
 * Starts Chromium (checked to draw with the suite's renderer: SwiftShader, the goldens' own,
 * unless $SHADERPROOF_RENDERER names another) and the page server. Used once per run by vitest's
 * globalSetup below, and by scripts through withHarness. With { gpu: true }, or { renderer },
 * that renderer instead (the GPU is checked to be a hardware one, else it throws): for the
 * benchmark, never for writing goldens.
 * @param {{gpu?: boolean, renderer?: import('../../src/headless/renderers.js').RendererName}} [options]
 * @returns {Promise<{context: {wsEndpoint, baseUrl, environment}, close: () => Promise<void>}>}
 */
export async function startHarness({ gpu = false, renderer = gpu ? 'gpu' : suiteRenderer() } = {}) {
  // the command line's own core (src/headless/core.js): Chromium checked to be `renderer`, then
  // the page server (page-server.js: the build with the harness's routes, or the dev server)
  const headless = await startHeadless({ renderer, serve: () => startPageServer() });
  const close = async () => {
    try {
      await headless.close();
    } catch (error) {
      console.warn(`harness teardown: ${error.message}`);
    }
  };
  const { browser, environment } = headless.chromium;
  const { baseUrl } = headless.server;
  try {
    await warmUp(browser, baseUrl);
    return { context: { wsEndpoint: browser.wsEndpoint(), baseUrl, environment }, close };
  } catch (error) {
    await close();
    throw error;
  }
}

/** vitest globalSetup: start Chromium and the page server once for the whole run. */
export async function setup(project) {
  const { context, close } = await startHarness();
  if (UPDATING && context.environment.rendererName !== 'swiftshader') {
    await close();
    throw new Error(
      `The goldens are SwiftShader's: npm run test:update with ${RENDERER_ENV}=${context.environment.rendererName} would overwrite them with another renderer's pictures.`,
    );
  }
  project.provide('harness', context);
  return close;
}

/**
 * For scripts outside vitest (npm run accuracy, picture, bench): starts the harness, runs
 * `body(context)` with page.js connected to it, and stops everything however the body ends.
 * @template T
 * @param {(context: {wsEndpoint, baseUrl, environment}) => Promise<T>} body
 * @param {{gpu?: boolean, renderer?: import('../../src/headless/renderers.js').RendererName}} [options] as for startHarness
 * @returns {Promise<T>}
 */
export async function withHarness(body, options) {
  const { context, close } = await startHarness(options);
  useHarness(context);
  try {
    return await body(context);
  } finally {
    await disconnect();
    await close();
  }
}
