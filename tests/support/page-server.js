// The page's server for a test run (setup.js starts it once; scripts through withHarness).
//
// By default the page the tests load is the production build (`vite build` into dist/ when it is
// older than its sources, ~2 s), served by the command line's own server (one page server for
// both: src/headless/page-server.js): one bundle, a worker chunk and
// the styles instead of the dev server's ~100 modules transformed one by one. A page load then
// takes ~0.5 s to its first frame where the dev server took ~1.3 s (measured: 5 loads of
// examples/pattern.glsl at 32x18 each way), and ~220 loads a run add up. It is also the page a
// person deploys. The dev server stays for what only it does: a server that watches the files and
// hot-updates the page (startWatchingServer, tests/browser/page-lifecycle.test.js), and, with
// SHADERPROOF_TEST_SERVER=dev, for a whole run (to debug with unbundled modules).
//
// Either way the harness's own routes (routes.js: a request that hangs, a redirect, files the
// tests write into public/ served at once) are plugged in.

import fs from 'node:fs';
import net from 'node:net';
import path from 'node:path';
import { REPO_ROOT } from './config.js';
import { harnessMiddleware, harnessRoutes } from './routes.js';
import { servePage } from '../../src/headless/core.js';

const CONFIG_FILE = path.join(REPO_ROOT, 'vite.config.js');

function freePort() {
  return new Promise((resolve, reject) => {
    const server = net.createServer();
    server.unref();
    server.on('error', reject);
    server.listen(0, '127.0.0.1', () => {
      const { port } = /** @type {import('node:net').AddressInfo} */ (server.address());
      server.close(() => resolve(port));
    });
  });
}

function configFile() {
  if (!fs.existsSync(CONFIG_FILE)) throw new Error(`${CONFIG_FILE} is missing; the page cannot be served.`);
  return CONFIG_FILE;
}

/**
 * The dev server (`npm run dev`'s), on a free loopback port. `watch: true` watches the files and
 * hot-updates the page; the shared one of a run does not watch.
 * @returns {Promise<{baseUrl: string, close: () => Promise<void>}>}
 */
async function startDevServer({ watch = false } = {}) {
  const { createServer } = await import('vite');
  const port = await freePort();
  const server = await createServer({
    configFile: configFile(),
    logLevel: 'warn',
    clearScreen: false,
    server: { host: '127.0.0.1', port, strictPort: true, open: false, ...(watch ? {} : { watch: null }) },
    plugins: [harnessRoutes()],
  });
  const close = () => server.close();
  try {
    await server.listen();
  } catch (error) {
    await close();
    throw error;
  }
  return { baseUrl: `http://127.0.0.1:${port}`, close };
}

/**
 * The production build in dist/ (built now when it is missing or older than its sources: as
 * `npm run build` makes it, so tests/browser/cli.test.js packs it without building it again), served by
 * the command line's own server (src/headless/core.js servePage) on a free loopback port, with the
 * harness's routes first; close() stops it.
 * @returns {Promise<{baseUrl: string, close: () => Promise<void>}>}
 */
async function startBuiltServer() {
  try {
    return await servePage({ routes: harnessMiddleware(path.join(REPO_ROOT, 'public')) });
  } catch (error) {
    throw new Error(`The page did not build (vite build, as npm run build does): ${error.message}`, { cause: error });
  }
}

/** The page server of a test run: the build (or the dev server with SHADERPROOF_TEST_SERVER=dev). */
export function startPageServer(env = process.env) {
  const chosen = env.SHADERPROOF_TEST_SERVER ?? 'build';
  if (chosen === 'dev') return startDevServer();
  if (chosen === 'build') return startBuiltServer();
  throw new Error(`SHADERPROOF_TEST_SERVER=${chosen}: expected "build" (the default) or "dev".`);
}

/** Another page server, in the test worker, with file watching and hot updates on. Close it after. */
export function startWatchingServer() {
  return startDevServer({ watch: true });
}
