// The renderers a benchmark measures, and a browser for each. Without a choice a benchmark
// measures both CPU renderers, SwiftShader and llvmpipe (src/headless/renderers.js), side by side:
// one Chromium each on one page server, so that a script can time the same shaders on both,
// interleaved round by round (timer.js), and a machine that slows down moves both alike.
//
//   --renderer NAME   that renderer alone (swiftshader, llvmpipe or gpu)
//   $SHADERPROOF_RENDERER, where no --renderer is given: the same

import { startBrowser } from '../../src/headless/browser.js';
import { RENDERER_ENV } from '../../src/headless/renderers.js';
import { startPageServer } from '../support/page-server.js';
import { CLOSE_TIMEOUT_MS, withTimeout } from '../../src/headless/watch.js';

/** @typedef {import('../../src/headless/renderers.js').RendererName} RendererName */

/** What a benchmark measures when it is not told: the two CPU renderers, side by side. */
export const CPU_RENDERERS = /** @type {readonly RendererName[]} */ (Object.freeze(['swiftshader', 'llvmpipe']));
const NAMES = /** @type {readonly RendererName[]} */ (Object.freeze([...CPU_RENDERERS, 'gpu']));

/** How a report names a renderer. */
export const RENDERER_TITLES = Object.freeze({ swiftshader: 'SwiftShader', llvmpipe: 'llvmpipe', gpu: 'GPU' });

/**
 * The renderers a benchmark's command line asks for: `--renderer NAME` (or `--gpu`, the same as
 * `--renderer gpu`), else $SHADERPROOF_RENDERER, else both CPU renderers. Throws an Error whose
 * message is the one line to print for a name that is not a renderer or a --renderer without one.
 * @param {string[]} argv the script's arguments (process.argv.slice(2))
 * @param {Record<string, string | undefined>} [env]
 * @returns {RendererName[]}
 */
export function renderersAsked(argv, env = process.env) {
  const at = argv.indexOf('--renderer');
  const named = at >= 0 ? argv[at + 1] : undefined;
  if (at >= 0 && (!named || named.startsWith('--')))
    throw new Error(`--renderer: name one of ${NAMES.join(', ')} (without it, both ${CPU_RENDERERS.join(' and ')} are measured)`);
  if (argv.includes('--gpu') && named !== undefined && named !== 'gpu') throw new Error(`--gpu and --renderer ${named} disagree: give one`);
  const asked = argv.includes('--gpu') ? 'gpu' : (named ?? env[RENDERER_ENV]);
  if (!asked) return [...CPU_RENDERERS];
  if (!NAMES.includes(/** @type {RendererName} */ (asked))) {
    const where = named === undefined && !argv.includes('--gpu') ? `${RENDERER_ENV}=${asked}` : `--renderer ${asked}`;
    throw new Error(`${where}: not a renderer; one of ${NAMES.join(', ')}`);
  }
  return [/** @type {RendererName} */ (asked)];
}

/**
 * One renderer of a run: its name, what draws (startBrowser's environment: the WebGL2 string, the
 * Chromium) and `on`, for page.js openPage and raw-webgl.js, which open their pages on it.
 * @typedef {{name: RendererName, environment: {chromium: string, renderer: string, webglVersion: string, rendererName: string},
 *   on: {browser: import('puppeteer-core').Browser, context: {baseUrl: string, wsEndpoint: string, environment: object}}}} BenchRenderer
 */

/**
 * Starts the page server and one Chromium per renderer (each checked to draw with it: a GPU run
 * with no hardware GPU throws with code NO_HARDWARE_GPU), runs `body` with them in the order
 * given, and closes everything however it ends. Nothing global changes: a page is opened on one
 * of them by naming it (`on`).
 * @template T
 * @param {RendererName[]} names
 * @param {(renderers: BenchRenderer[]) => Promise<T>} body
 * @returns {Promise<T>}
 */
export async function withRenderers(names, body) {
  /** @type {Array<() => Promise<unknown>>} */
  const cleanups = [];
  try {
    const server = await startPageServer();
    cleanups.push(() => withTimeout('closing the page server', server.close(), CLOSE_TIMEOUT_MS));
    /** @type {BenchRenderer[]} */
    const renderers = [];
    for (const name of names) {
      const { browser, environment, close } = await startBrowser({ renderer: name });
      cleanups.push(close);
      const context = { baseUrl: server.baseUrl, wsEndpoint: browser.wsEndpoint(), environment };
      renderers.push({ name, environment, on: { browser, context } });
    }
    return await body(renderers);
  } finally {
    for (const cleanup of cleanups.reverse()) {
      try {
        await cleanup();
      } catch (error) {
        console.warn(`benchmark teardown: ${error.message}`);
      }
    }
  }
}
