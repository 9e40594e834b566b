// Browser and server set-up: one headless Chromium and one page server for a whole test run.
//
// As vitest's globalSetup (tests/vitest.config.js), `setup` runs once in the main process: it finds a
// Chromium (chrome-path.js), launches it headless on SwiftShader (the CPU WebGL2 implementation,
// identical on every machine that runs the same Chromium build), checks that WebGL2 really is
// SwiftShader, builds the page and serves the build on a free loopback port (page-server.js), and hands the browser's
// endpoint and the page's URL to the test files (project.provide → inject('harness'), read by
// page.js). The function it returns stops both. Scripts (the benchmark, the accuracy report,
// the README picture) do the same through withHarness.

import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import puppeteer from 'puppeteer-core';
import { ENVIRONMENT_FILE, GOLDEN_DIR, UPDATING } from './config.js';
import { findChrome } from './chrome-path.js';
import { disconnect, useHarness } from './page.js';
import { startPageServer } from './page-server.js';
import { CLOSE_TIMEOUT_MS, WAIT_TIMEOUT_MS, closeBrowser, watchPage, withTimeout } from './watch.js';

export const CHROME_ARGS = [
  '--no-sandbox',
  '--use-angle=swiftshader',
  '--enable-unsafe-swiftshader',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
  '--no-first-run',
  '--disable-default-apps',
  '--disable-extensions',
  '--mute-audio',
  '--lang=en-US',
];

/**
 * For startHarness({ gpu: true }): CHROME_ARGS without SwiftShader, plus what headless Chromium
 * needs to use the machine's own GPU, one set per ANGLE back end to try, in order. On Linux that
 * is Vulkan first (Chrome's recipe for GPUs in headless mode:
 * https://developer.chrome.com/blog/supercharge-web-ai-testing), then Chromium's default back
 * end; elsewhere the default (Metal on macOS, Direct3D 11 on Windows).
 */
export const GPU_CHROME_ARGS = (
  process.platform === 'linux'
    ? [['--use-angle=vulkan', '--enable-features=Vulkan', '--disable-vulkan-surface'], ['--use-angle=default']]
    : [['--use-angle=default']]
).map((backend) => [...CHROME_ARGS.filter((arg) => !/swiftshader/i.test(arg)), '--enable-gpu', '--ignore-gpu-blocklist', ...backend]);

const SOFTWARE_RENDERERS = /swiftshader|llvmpipe|lavapipe|softpipe|software|basic render|mesa offscreen/i;

/**
 * What draws a WebGL renderer string: 'software' (SwiftShader, Mesa llvmpipe/lavapipe/softpipe,
 * Microsoft Basic Render Driver, any "Software" renderer), 'unknown' (no string, or the masked
 * "WebKit WebGL" that names no device), else 'hardware'.
 */
export function rendererKind(renderer) {
  if (!renderer || !String(renderer).trim() || /^webkit webgl$/i.test(String(renderer).trim())) return 'unknown';
  return SOFTWARE_RENDERERS.test(renderer) ? 'software' : 'hardware';
}

/** A renderer string for reports, without its device id ("... (0x0000C0DE)"). */
export function rendererLabel(renderer) {
  return renderer.replace(/\s*\(0x[0-9A-F]+\)/i, '');
}

/** Opens a blank page and asks WebGL2 who it is. */
async function probeWebGL(browser) {
  const page = await browser.newPage();
  try {
    return await page.evaluate(() => {
      const gl = document.createElement('canvas').getContext('webgl2');
      if (!gl) return null;
      const debug = gl.getExtension('WEBGL_debug_renderer_info');
      return {
        renderer: debug ? gl.getParameter(debug.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER),
        vendor: debug ? gl.getParameter(debug.UNMASKED_VENDOR_WEBGL) : gl.getParameter(gl.VENDOR),
        version: gl.getParameter(gl.VERSION),
      };
    });
  } finally {
    await page.close();
  }
}

/**
 * Loads the page once before any test. On the dev server (RAYTRACER_TEST_SERVER=dev) Vite then
 * has transformed every module and pre-bundled every dependency (one it discovers during a test's
 * page load makes it reload that page mid-test); on either, the built-in shader has compiled once.
 * Best effort: a page that fails here fails, with a message, in the tests.
 */
async function warmUp(browser, baseUrl) {
  const page = await withTimeout('opening a page', browser.newPage(), WAIT_TIMEOUT_MS);
  watchPage(page, browser); // each wait below ends (a `ready` that never settles hung the run here)
  try {
    await page.goto(`${baseUrl}/?size=32x18&time=0`, { waitUntil: 'load' });
    await page.waitForFunction(() => window.raytracer || document.documentElement.dataset.error);
    await page.evaluate(() => window.raytracer?.ready.catch(() => {}));
  } catch (error) {
    // the tests report it for themselves; this says why they may start slowly
    console.warn(`harness warm-up: ${error.message.split('\n')[0]}`);
  } finally {
    await page.close();
  }
}

/**
 * Launches Chromium with each of GPU_CHROME_ARGS in turn and keeps the first whose WebGL2 is a
 * hardware renderer (rendererKind). Never settles for a software one: if none is hardware, it
 * throws an error with code 'NO_HARDWARE_GPU' that lists what each attempt got.
 */
async function launchOnGpu(launch, executablePath, userDataDir) {
  const tried = [];
  for (const [i, args] of GPU_CHROME_ARGS.entries()) {
    const browser = await launch(args, path.join(userDataDir, `gpu-${i}`));
    const webgl = await probeWebGL(browser).catch(() => null);
    const kind = rendererKind(webgl?.renderer);
    if (webgl && kind === 'hardware') return browser;
    await browser.close();
    const flags = args.filter((arg) => !CHROME_ARGS.includes(arg)).join(' ');
    tried.push(`${flags}: ${webgl ? `WebGL2 renderer "${webgl.renderer}" (${kind})` : 'no WebGL2'}`);
  }
  /** @type {Error & {code?: string}} */
  const error = new Error(
    `No hardware GPU found: headless Chromium (${executablePath}) has no WebGL2 on a hardware GPU. Tried:\n  ` +
      `${tried.join('\n  ')}\nA software renderer (SwiftShader, llvmpipe, ...) is never used in its place.`,
  );
  error.code = 'NO_HARDWARE_GPU';
  throw error;
}

/**
 * Launches headless Chromium with the harness's flags (CHROME_ARGS unless `args`), in UTC. Used
 * by startHarness, and by page.js when the run's browser is gone (crashed) and a test file needs
 * another. Without `userDataDir`, puppeteer makes a temporary profile and removes it on close.
 * @param {{args?: string[], userDataDir?: string, executablePath?: string}} [options]
 */
export function launchBrowser({ args = CHROME_ARGS, userDataDir, executablePath = findChrome() } = {}) {
  return puppeteer.launch({
    executablePath,
    headless: true,
    userDataDir,
    args: [...args], // a copy: puppeteer moves --enable-features out of the array it is given
    // iDate uses local time; UTC makes the frozen date the same everywhere.
    env: { ...process.env, TZ: 'UTC' },
    defaultViewport: null,
  });
}

/**
 * Starts Chromium (checked to be SwiftShader WebGL2) and the page server. Used once per run by
 * vitest's globalSetup below, and by scripts through withHarness.
 * With { gpu: true }, Chromium runs on the machine's own GPU instead (launchOnGpu: checked to be
 * a hardware renderer, else it throws): for `npm run bench -- --gpu` only, never for the goldens.
 * @returns {Promise<{context: {wsEndpoint, baseUrl, environment}, close: () => Promise<void>}>}
 */
export async function startHarness({ gpu = false } = {}) {
  const executablePath = findChrome();
  const userDataDir = fs.mkdtempSync(path.join(os.tmpdir(), 'raytracer-chromium-'));
  const cleanups = [() => fs.rmSync(userDataDir, { recursive: true, force: true })];
  const close = async () => {
    for (const cleanup of cleanups.reverse()) {
      try {
        await cleanup();
      } catch (error) {
        console.warn(`harness teardown: ${error.message}`);
      }
    }
  };
  try {
    const launch = (args, dataDir) => launchBrowser({ args, userDataDir: dataDir, executablePath });
    const browser = gpu ? await launchOnGpu(launch, executablePath, userDataDir) : await launch(CHROME_ARGS, userDataDir);
    // closed, or killed if it does not answer: a hung browser must not keep the run alive
    cleanups.push(() => closeBrowser(browser));

    const chromium = await browser.version();
    const webgl = await probeWebGL(browser);
    if (!webgl) {
      throw new Error(
        `${chromium} (${executablePath}) has no WebGL2 with flags ${CHROME_ARGS.join(' ')}. ` +
          'The render tests need SwiftShader WebGL2; without it they would pass while rendering nothing.',
      );
    }
    if (gpu && rendererKind(webgl.renderer) !== 'hardware') throw new Error(`WebGL2 renderer is "${webgl.renderer}", not a hardware GPU.`);
    if (!gpu && !/swiftshader/i.test(webgl.renderer)) {
      throw new Error(
        `WebGL2 renderer is "${webgl.renderer}", not SwiftShader. The goldens are SwiftShader renders; ` +
          'a GPU renders different pixels. Check that --use-angle=swiftshader is honoured by this Chromium.',
      );
    }
    const environment = { chromium, renderer: webgl.renderer, webglVersion: webgl.version };

    const server = await startPageServer();
    cleanups.push(() => withTimeout('closing the page server', server.close(), CLOSE_TIMEOUT_MS));
    await warmUp(browser, server.baseUrl);
    return { context: { wsEndpoint: browser.wsEndpoint(), baseUrl: server.baseUrl, environment }, close };
  } catch (error) {
    await close();
    throw error;
  }
}

/** vitest globalSetup: start Chromium and the page server once for the whole run. */
export async function setup(project) {
  const { context, close } = await startHarness();
  if (UPDATING) {
    fs.mkdirSync(GOLDEN_DIR, { recursive: true });
    fs.writeFileSync(ENVIRONMENT_FILE, JSON.stringify(context.environment, null, 2) + '\n');
  }
  project.provide('harness', context);
  return close;
}

/**
 * For scripts outside vitest (npm run accuracy, picture, bench): starts the harness, runs
 * `body(context)` with page.js connected to it, and stops everything however the body ends.
 * @template T
 * @param {(context: {wsEndpoint, baseUrl, environment}) => Promise<T>} body
 * @param {{gpu?: boolean}} [options] as for startHarness
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
