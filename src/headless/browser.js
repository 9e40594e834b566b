// The headless Chromium that draws every picture this project makes: the test harness's
// (tests/support/setup.js), the scripts' (bench, accuracy, picture) and the command line's
// (src/cli/). One launch, one check of who WebGL2 really is: SwiftShader by default (the CPU
// implementation, identical on every machine that runs the same Chromium build, so its pictures
// can be goldens), Mesa's llvmpipe, or the machine's own GPU (renderers.js says what each is),
// never another renderer in the place of the one asked for.

import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import puppeteer from 'puppeteer-core';
import { findChrome } from './chrome-path.js';
import { BASE_ARGS, LLVMPIPE_ARGS, SWIFTSHADER_ARGS, MESA_PACKAGES, drawnBy, findMesa, llvmpipeEnv, mesaMissingLine } from './renderers.js';
import { closeBrowser } from './watch.js';
import { webglIdentity } from './client.js';

/** SwiftShader's flags: what the goldens are drawn with, and the default of launchBrowser. */
export const CHROME_ARGS = [...SWIFTSHADER_ARGS];

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
).map((backend) => [...BASE_ARGS, '--enable-gpu', '--ignore-gpu-blocklist', ...backend]);

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
    return await webglIdentity(page);
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
 * Launches headless Chromium with the harness's flags (CHROME_ARGS unless `args`), in UTC, with
 * `env` added to its environment. Used by startBrowser, and by page.js when the run's browser is
 * gone (crashed) and a test file needs another. Without `userDataDir`, puppeteer makes a
 * temporary profile and removes it on close.
 * @param {{args?: readonly string[], env?: Record<string, string>, userDataDir?: string, executablePath?: string}} [options]
 */
export function launchBrowser({ args = CHROME_ARGS, env = {}, userDataDir, executablePath = findChrome() } = {}) {
  return puppeteer.launch({
    executablePath,
    headless: true,
    userDataDir,
    args: [...args], // a copy: puppeteer moves --enable-features out of the array it is given
    // iDate uses local time; UTC makes the frozen date the same everywhere.
    env: { ...process.env, ...env, TZ: 'UTC' },
    defaultViewport: null,
  });
}

/**
 * Throws unless `webgl` (what WebGL2 says it is, or null for no WebGL2) is the renderer asked
 * for: never another in its place, so a reference is never drawn, nor a figure measured, by
 * something else than its label says.
 * @param {{renderer: string, version: string} | null} webgl
 * @param {{renderer: import('./renderers.js').RendererName, chromium: string, executablePath: string}} where
 */
function checkWebGL(webgl, { renderer, chromium, executablePath }) {
  if (renderer === 'llvmpipe') {
    if (webgl && drawnBy('llvmpipe', webgl.renderer)) return;
    const got = webgl ? `WebGL2 is "${webgl.renderer}"` : 'there is no WebGL2';
    throw new Error(
      `llvmpipe was asked for, but ${got} in ${chromium}: ANGLE could not draw with Mesa's EGL here; ` +
        `check Debian's ${MESA_PACKAGES.join(' ')}, or use --renderer swiftshader`,
    );
  }
  if (!webgl) {
    throw new Error(
      `${chromium} (${executablePath}) has no WebGL2 with flags ${CHROME_ARGS.join(' ')}. ` +
        'Every picture here needs SwiftShader WebGL2; without it a render would be blank.',
    );
  }
  if (renderer === 'gpu' && rendererKind(webgl.renderer) !== 'hardware')
    throw new Error(`WebGL2 renderer is "${webgl.renderer}", not a hardware GPU.`);
  if (renderer === 'swiftshader' && !drawnBy('swiftshader', webgl.renderer)) {
    throw new Error(
      `WebGL2 renderer is "${webgl.renderer}", not SwiftShader. The goldens are SwiftShader renders; ` +
        'a GPU renders different pixels. Check that --use-angle=swiftshader is honoured by this Chromium.',
    );
  }
}

/**
 * Removes a profile folder startBrowser made, with the folder Chromium keeps its singleton socket
 * in (a temporary folder of its own, which the profile's SingletonSocket link names): Chromium
 * removes that one on a clean exit, and a browser killed by the watchdog left one behind each
 * time (129 of them in /tmp after a day of test runs here). The GPU fallback's profiles
 * (launchOnGpu) lie inside the folder.
 * @param {string} userDataDir
 */
function removeChromiumProfile(userDataDir) {
  const profiles = [userDataDir, ...readdirOrNone(userDataDir).map((name) => path.join(userDataDir, name))];
  for (const profile of profiles) {
    let socket;
    try {
      socket = fs.readlinkSync(path.join(profile, 'SingletonSocket'));
    } catch {
      continue; // not a profile, or Chromium made no socket
    }
    const owner = path.dirname(socket);
    // only Chromium's own temporary folder, never what a link elsewhere might name
    if (path.dirname(owner) === os.tmpdir() && path.basename(owner).startsWith('org.chromium.'))
      fs.rmSync(owner, { recursive: true, force: true });
  }
  fs.rmSync(userDataDir, { recursive: true, force: true });
}

/** @param {string} folder */
function readdirOrNone(folder) {
  try {
    return fs.readdirSync(folder);
  } catch {
    return [];
  }
}

/**
 * Launches Chromium, checked to draw with `renderer`: SwiftShader (the default, the goldens'),
 * Mesa's llvmpipe, or the machine's GPU (for the benchmark and a person's renders, never for
 * goldens); `gpu: true` is the same as `renderer: 'gpu'`. It runs in a profile of its own that
 * close() removes. `environment` says what draws: the Chromium version, the renderer's name and
 * its WebGL2 string, as every output of the command line and the references' drawn-by.json name
 * them. With `probe: false` (SwiftShader or llvmpipe) WebGL2 is not asked on a page of its own
 * (0.45 s here): the caller asks its own first page and hands the answer to verify(), which
 * checks it and fills in `environment`.
 * `mesa` finds Mesa for llvmpipe (renderers.js findMesa; a test gives it another machine's).
 * @param {{renderer?: import('./renderers.js').RendererName, gpu?: boolean, executablePath?: string, probe?: boolean,
 *   mesa?: typeof findMesa}} [options]
 */
export async function startBrowser({
  renderer: asked,
  gpu = false,
  executablePath = findChrome(),
  probe = true,
  mesa: findIt = findMesa,
} = {}) {
  const renderer = gpu ? 'gpu' : (asked ?? 'swiftshader');
  const mesa = renderer === 'llvmpipe' ? findIt() : null;
  if (mesa && mesa.missing.length) throw new Error(mesaMissingLine(mesa.missing));
  const userDataDir = fs.mkdtempSync(path.join(os.tmpdir(), 'shaderproof-chromium-'));
  const removeProfile = () => removeChromiumProfile(userDataDir);
  let browser;
  try {
    const launch = (args, dataDir, env) => launchBrowser({ args, env, userDataDir: dataDir, executablePath });
    if (renderer === 'gpu') browser = await launchOnGpu(launch, executablePath, userDataDir);
    else if (renderer === 'llvmpipe') browser = await launch(LLVMPIPE_ARGS, userDataDir, llvmpipeEnv(mesa?.vendorFile));
    else browser = await launch(CHROME_ARGS, userDataDir);
    const chromium = await browser.version();
    const environment = { chromium, renderer: '', webglVersion: '', rendererName: renderer, gpu: renderer === 'gpu' };
    /** @param {{renderer: string, version: string} | null} webgl */
    const verify = (webgl) => {
      checkWebGL(webgl, { renderer, chromium, executablePath });
      Object.assign(environment, { renderer: webgl?.renderer, webglVersion: webgl?.version });
    };
    if (probe || renderer === 'gpu') verify(await probeWebGL(browser));
    const opened = browser;
    const close = async () => {
      try {
        await closeBrowser(opened); // closed, or killed if it does not answer
      } finally {
        removeProfile();
      }
    };
    return { browser, environment, close, verify };
  } catch (error) {
    if (browser) await closeBrowser(browser).catch(() => {});
    removeProfile();
    throw error;
  }
}
