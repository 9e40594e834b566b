// Everything the tests need from a browser, in one module.
//
// As vitest's globalSetup (tests/vitest.config.js), `setup` runs once in the main process: it finds a
// Chromium, launches it headless on SwiftShader (the CPU WebGL2 implementation, identical on
// every machine that runs the same Chromium build), checks that WebGL2 really is SwiftShader,
// serves the real page with Vite on a free loopback port, and hands the browser's endpoint and
// the page's URL to the test files (project.provide → inject('harness')). `teardown` stops both.
//
// In the test files (one worker at a time, fileParallelism: false), the other exports connect to
// that browser, open the page at a view, wait for a real frame, read its pixels, and compare them
// with a golden image (tests/golden/<name>.png; see tests/views.js for the tolerance).

import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import net from 'node:net';
import { fileURLToPath } from 'node:url';
import puppeteer from 'puppeteer-core';
import { PNG } from 'pngjs';
import pixelmatch from 'pixelmatch';
import { INCLUDE_AA, MAX_DIFF_FRACTION, PAGE_PARAMS, PIXEL_THRESHOLD, viewQuery, viewSize } from './views.js';

export const REPO_ROOT = fileURLToPath(new URL('..', import.meta.url));
export const GOLDEN_DIR = path.join(REPO_ROOT, 'tests', 'golden');
export const OUTPUT_DIR = path.join(REPO_ROOT, 'tests', 'output');
export const ENVIRONMENT_FILE = path.join(GOLDEN_DIR, 'ENVIRONMENT.json');
export const SHADER_FILE = path.join(REPO_ROOT, 'shaders', 'raytrace.glsl');
export const UPDATE_COMMAND = 'npm run test:update';
/** Goldens are written only when this is set (by `npm run test:update`). */
export const UPDATING = process.env.UPDATE_GOLDENS === '1';

const INJECTION_SOURCE = fs.readFileSync(new URL('./deterministic-injection.js', import.meta.url), 'utf8');

const CHROME_CANDIDATES = [
  '/usr/bin/chromium',
  '/usr/bin/chromium-browser',
  '/usr/bin/google-chrome',
  '/usr/bin/google-chrome-stable',
  '/usr/lib/chromium/chromium',
  '/snap/bin/chromium',
  '/opt/google/chrome/chrome',
  '/Applications/Google Chrome.app/Contents/MacOS/Google Chrome',
  '/Applications/Chromium.app/Contents/MacOS/Chromium',
];

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
export const GPU_CHROME_ARGS = (process.platform === 'linux'
  ? [['--use-angle=vulkan', '--enable-features=Vulkan', '--disable-vulkan-surface'], ['--use-angle=default']]
  : [['--use-angle=default']]
).map((backend) => [
  ...CHROME_ARGS.filter((arg) => !/swiftshader/i.test(arg)),
  '--enable-gpu',
  '--ignore-gpu-blocklist',
  ...backend,
]);

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

const PAGE_TIMEOUT_MS = 90_000;

// ------------------------------------------------------------------------------------------------
// Global setup (main process)
// ------------------------------------------------------------------------------------------------

/** The Chromium to test with: $CHROME_PATH, else the first usual system path that exists. */
export function findChrome(env = process.env, candidates = CHROME_CANDIDATES, exists = fs.existsSync) {
  const help =
    'Install one with `apt-get update && apt-get install -y chromium` (Debian/Ubuntu), or point ' +
    'CHROME_PATH at a Chrome or Chromium executable.';
  if (env.CHROME_PATH) {
    if (!exists(env.CHROME_PATH)) throw new Error(`CHROME_PATH is ${env.CHROME_PATH}, which does not exist. ${help}`);
    return env.CHROME_PATH;
  }
  const found = candidates.find((p) => exists(p));
  if (!found) throw new Error(`No Chrome or Chromium found (looked in ${candidates.join(', ')}). ${help}`);
  return found;
}

function freePort() {
  return new Promise((resolve, reject) => {
    const server = net.createServer();
    server.unref();
    server.on('error', reject);
    server.listen(0, '127.0.0.1', () => {
      const { port } = server.address();
      server.close(() => resolve(port));
    });
  });
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
 * Loads the page once before any test, so Vite has transformed every module and pre-bundled
 * every dependency: a dependency Vite discovers during a test's page load makes it reload that
 * page mid-test. Best effort: a page that fails here fails, with a message, in the tests.
 */
async function warmUp(browser, baseUrl) {
  const page = await browser.newPage();
  try {
    await page.goto(`${baseUrl}/?size=32x18&time=0`, { waitUntil: 'load', timeout: PAGE_TIMEOUT_MS });
    await page.waitForFunction(() => window.raytracer || document.documentElement.dataset.error, { timeout: PAGE_TIMEOUT_MS });
    await page.evaluate(() => window.raytracer?.ready.catch(() => {}));
  } catch {
    // reported by the tests themselves
  } finally {
    await page.close().catch(() => {});
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
  const error = new Error(
    `No hardware GPU found: headless Chromium (${executablePath}) has no WebGL2 on a hardware GPU. Tried:\n  ` +
      `${tried.join('\n  ')}\nA software renderer (SwiftShader, llvmpipe, ...) is never used in its place.`,
  );
  error.code = 'NO_HARDWARE_GPU';
  throw error;
}

/**
 * Starts Chromium (checked to be SwiftShader WebGL2) and the page server. Used once per run by
 * vitest's globalSetup below, and directly by scripts (the benchmark, the accuracy report).
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
    const launch = (args, dataDir) =>
      puppeteer.launch({
        executablePath,
        headless: true,
        userDataDir: dataDir,
        args: [...args], // a copy: puppeteer moves --enable-features out of the array it is given
        // iDate uses local time; UTC makes the frozen date the same everywhere.
        env: { ...process.env, TZ: 'UTC' },
        defaultViewport: null,
      });
    const browser = gpu ? await launchOnGpu(launch, executablePath, userDataDir) : await launch(CHROME_ARGS, userDataDir);
    cleanups.push(() => browser.close());

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

    const configFile = path.join(REPO_ROOT, 'vite.config.js');
    if (!fs.existsSync(configFile)) throw new Error(`${configFile} is missing; the page cannot be served.`);
    const { createServer } = await import('vite');
    const port = await freePort();
    const server = await createServer({
      configFile,
      logLevel: 'warn',
      clearScreen: false,
      server: { host: '127.0.0.1', port, strictPort: true, watch: null, open: false },
    });
    cleanups.push(() => server.close());
    await server.listen();
    const baseUrl = `http://127.0.0.1:${port}`;
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
  if (UPDATING) {
    fs.mkdirSync(GOLDEN_DIR, { recursive: true });
    fs.writeFileSync(ENVIRONMENT_FILE, JSON.stringify(context.environment, null, 2) + '\n');
  }
  project.provide('harness', context);
  return close;
}

// ------------------------------------------------------------------------------------------------
// In the test workers
// ------------------------------------------------------------------------------------------------

let connection;
let scriptContext;

/** For scripts outside vitest: use the context that startHarness() returned. */
export function useHarness(context) {
  scriptContext = context;
}

/** What globalSetup provided (or a script set with useHarness): { wsEndpoint, baseUrl, environment }. */
export async function harnessContext() {
  if (scriptContext) return scriptContext;
  const { inject } = await import('vitest');
  const context = inject('harness');
  if (!context) throw new Error('The harness did not start: tests/harness.js must be the globalSetup of tests/vitest.config.js (run the tests with npm test).');
  return context;
}

async function connect() {
  if (!connection) {
    connection = (async () => {
      const context = await harnessContext();
      const browser = await puppeteer.connect({ browserWSEndpoint: context.wsEndpoint, defaultViewport: null });
      return { browser, context };
    })();
  }
  return connection;
}

/** Call from afterAll in every test file that renders. */
export async function disconnect() {
  if (!connection) return;
  const pending = connection;
  connection = undefined;
  const { browser } = await pending.catch(() => ({}));
  if (browser?.connected) await browser.disconnect();
}

/**
 * A fresh page with the deterministic injection, collecting console errors and page errors.
 * @returns {Promise<{page: import('puppeteer-core').Page, errors: string[], context: object}>}
 */
export async function openPage({ deterministic = true } = {}) {
  const { browser, context } = await connect();
  const page = await browser.newPage();
  const errors = [];
  page.on('console', (message) => {
    if (message.type() !== 'error') return;
    const { url, lineNumber } = message.location() ?? {};
    errors.push(`console.error: ${message.text()}${url ? ` (${url}${lineNumber !== undefined ? `:${lineNumber + 1}` : ''})` : ''}`);
  });
  page.on('pageerror', (error) => errors.push(`page error: ${error?.message ?? error}`));
  page.on('error', (error) => errors.push(`page crashed: ${error?.message ?? error}`));
  page.setDefaultTimeout(PAGE_TIMEOUT_MS);
  await page.setViewport({ width: 800, height: 600, deviceScaleFactor: 1 });
  // Every page loads fresh from the server: no 304s, nothing left over from an earlier test.
  await page.setCacheEnabled(false);
  if (deterministic) await page.evaluateOnNewDocument(INJECTION_SOURCE);
  return { page, errors, context };
}

function decodeRgba(base64, width, height, what) {
  const data = Buffer.from(base64, 'base64');
  if (data.length !== width * height * 4) {
    throw new Error(`${what}: ${data.length} bytes of pixels for ${width}x${height} (expected ${width * height * 4})`);
  }
  return data;
}

/**
 * Opens the page at a view (tests/views.js), waits until `window.raytracer.ready`, and reads one
 * rendered frame. Throws if the page reports a WebGL/compile error, logs a console error or
 * throws, renders a frame of the wrong size, or does not report the view's controls and time as
 * its current values (window.raytracer.info()).
 * @returns {Promise<{width:number, height:number, data:Buffer, url:string, frame:number, info:object}>}
 */
export async function renderView(view) {
  try {
    return await renderViewOnce(view);
  } catch (error) {
    // Vite reloads a page when it discovers a dependency to pre-bundle during the load. That is
    // the dev server, not the page: try once more, and say so.
    if (!error.selfNavigated) throw error;
    console.warn(`${view.name}: the page reloaded itself during the test (${error.message.split('\n')[0]}); retrying once`);
    return await renderViewOnce(view);
  }
}

async function renderViewOnce(view) {
  const { page, errors, context } = await openPage();
  const url = context.baseUrl + viewQuery(view);
  const [width, height] = viewSize(view);
  let navigations = 0;
  page.on('framenavigated', (frame) => {
    if (frame === page.mainFrame()) navigations++;
  });
  const fail = (message) => {
    const logged = errors.length ? `\nThe page logged:\n  ${errors.join('\n  ')}` : '';
    const error = new Error(`${view.name} (${url}): ${message}${logged}`);
    error.selfNavigated = navigations > 1;
    return error;
  };
  try {
    const response = await page.goto(url, { waitUntil: 'load' });
    if (!response || (!response.ok() && response.status() !== 304)) throw fail(`the page answered HTTP ${response?.status()}`);
    await page
      .waitForFunction(() => window.raytracer || document.documentElement.dataset.error, { polling: 100 })
      .catch(() => {
        throw fail('window.raytracer never appeared');
      });
    const result = await page
      .evaluate(async () => {
        const datasetError = () => document.documentElement.dataset.error;
        if (!window.raytracer) return { error: `page error: ${datasetError()}` };
        try {
          await window.raytracer.ready;
        } catch (error) {
          return { error: `raytracer.ready rejected: ${error?.message ?? error}; data-error: ${datasetError() ?? '(none)'}` };
        }
        const pixels = await window.raytracer.readPixels();
        const canvas = document.querySelector('canvas[data-frame]');
        const frame = canvas ? Number(canvas.dataset.frame) : NaN;
        const info = window.raytracer.info();
        return { pixels, frame, info: JSON.parse(JSON.stringify(info)), datasetError: datasetError() };
      })
      .catch((error) => {
        throw fail(`${error.message}${navigations > 1 ? ` (the page navigated ${navigations} times)` : ''}`);
      });
    if (result.error) throw fail(result.error);
    if (result.datasetError) throw fail(`the page reports an error: ${result.datasetError}`);
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
    if (errors.length) throw fail('console errors or page errors while rendering');
    return { width, height, data, url, frame: result.frame, info };
  } finally {
    await page.close().catch(() => {});
  }
}

/**
 * Installed in the raw WebGL2 pages below (renderRawShader, evaluateFloatShader, timeShaders):
 * what they share, in the page's own context. `program` compiles a fullscreen-triangle vertex
 * shader and `fragment`, links them and returns { program } or { stage, log } on failure;
 * `toBase64` turns GL's bottom-up RGBA8 rows into top-down base64.
 */
function installRawWebGL() {
  const vertex = `#version 300 es
void main() {
    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
`;
  window.__rawWebGL = {
    program(gl, fragment) {
      const compile = (type, text) => {
        const shader = gl.createShader(type);
        gl.shaderSource(shader, text);
        gl.compileShader(shader);
        return shader;
      };
      const vs = compile(gl.VERTEX_SHADER, vertex);
      if (!gl.getShaderParameter(vs, gl.COMPILE_STATUS)) return { stage: 'vertex', log: gl.getShaderInfoLog(vs) };
      const fs = compile(gl.FRAGMENT_SHADER, fragment);
      if (!gl.getShaderParameter(fs, gl.COMPILE_STATUS)) return { stage: 'compile', log: gl.getShaderInfoLog(fs) };
      const program = gl.createProgram();
      gl.attachShader(program, vs);
      gl.attachShader(program, fs);
      gl.linkProgram(program);
      if (!gl.getProgramParameter(program, gl.LINK_STATUS)) return { stage: 'link', log: gl.getProgramInfoLog(program) };
      gl.useProgram(program);
      return { program };
    },
    toBase64(pixels, w, h) {
      const flipped = new Uint8Array(pixels.length);
      const row = w * 4;
      for (let y = 0; y < h; y++) flipped.set(pixels.subarray((h - 1 - y) * row, (h - y) * row), y * row);
      let binary = '';
      for (let i = 0; i < flipped.length; i += 0x8000) binary += String.fromCharCode.apply(null, flipped.subarray(i, i + 0x8000));
      return btoa(binary);
    },
  };
}

/** A blank page with the raw WebGL2 helpers; `deterministic: false` keeps the real clock. */
async function openRawPage(title, options) {
  const opened = await openPage(options);
  await opened.page.goto(`data:text/html,<!doctype html><title>${title}</title><body></body>`);
  await opened.page.evaluate(installRawWebGL);
  return opened;
}

/**
 * Compiles a complete fragment shader (e.g. composeImageShader(source).code) in a plain WebGL2
 * context, no three.js, no page code, and draws one fullscreen triangle with Shadertoy's uniforms
 * at their first-frame values: iResolution = (width, height, 1), iTime 0, iFrame 0, iMouse 0,
 * iDate from the (frozen) clock. `uniforms` overrides any of them, e.g.
 * { iTime: 1.5, iFrame: 3, iMouse: [40, 59, 40, -59] } (ints for iFrame, arrays for vectors).
 * @returns {Promise<{stage:'compile'|'link', log:string} | {width, height, data:Buffer, glError:number, renderer:string}>}
 */
export async function renderRawShader(code, { width, height, uniforms = {} }) {
  const { page, errors } = await openRawPage('raw WebGL2');
  try {
    const result = await page.evaluate(
      (fragment, w, h, overrides) => {
        if (!window.__deterministic) return { stage: 'setup', log: 'the deterministic injection did not run' };
        const canvas = document.createElement('canvas');
        canvas.width = w;
        canvas.height = h;
        document.body.appendChild(canvas);
        const gl = canvas.getContext('webgl2', { antialias: false, depth: false, stencil: false, premultipliedAlpha: false, preserveDrawingBuffer: true });
        if (!gl) return { stage: 'setup', log: 'no WebGL2 context' };
        const built = window.__rawWebGL.program(gl, fragment);
        if (built.stage) return built;
        const { program } = built;
        const at = (name) => gl.getUniformLocation(program, name);
        const now = new Date();
        gl.uniform3f(at('iResolution'), w, h, 1);
        gl.uniform1f(at('iTime'), 0);
        gl.uniform1f(at('iTimeDelta'), 1 / 60);
        gl.uniform1f(at('iFrameRate'), 60);
        gl.uniform1i(at('iFrame'), 0);
        gl.uniform4f(at('iMouse'), 0, 0, 0, 0);
        gl.uniform4f(
          at('iDate'),
          now.getFullYear(),
          now.getMonth(),
          now.getDate(),
          now.getHours() * 3600 + now.getMinutes() * 60 + now.getSeconds() + now.getMilliseconds() / 1000,
        );
        gl.uniform1f(at('iSampleRate'), 44100);
        gl.uniform1fv(at('iChannelTime'), new Float32Array(4));
        gl.uniform3fv(at('iChannelResolution'), new Float32Array(12));
        for (let i = 0; i < 4; i++) gl.uniform1i(at(`iChannel${i}`), i);
        // per-call values (iTime, iMouse, iFrame, ...): floats and vectors as numbers or arrays
        for (const [name, value] of Object.entries(overrides)) {
          const location = at(name);
          if (name === 'iFrame') gl.uniform1i(location, value);
          else if (Array.isArray(value)) gl[`uniform${value.length}fv`](location, new Float32Array(value));
          else gl.uniform1f(location, value);
        }
        gl.viewport(0, 0, w, h);
        gl.drawArrays(gl.TRIANGLES, 0, 3);
        const pixels = new Uint8Array(w * h * 4);
        gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
        const glError = gl.getError();
        const debug = gl.getExtension('WEBGL_debug_renderer_info');
        return {
          data: window.__rawWebGL.toBase64(pixels, w, h),
          glError,
          renderer: debug ? gl.getParameter(debug.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER),
        };
      },
      code,
      width,
      height,
      uniforms,
    );
    if (errors.length) throw new Error(`raw WebGL2 page logged errors:\n  ${errors.join('\n  ')}`);
    if (result.stage) return result;
    return { width, height, data: decodeRgba(result.data, width, height, 'raw render'), glError: result.glError, renderer: result.renderer };
  } finally {
    await page.close().catch(() => {});
  }
}

// ------------------------------------------------------------------------------------------------
// Images (plain Node; no browser)
// ------------------------------------------------------------------------------------------------

/**
 * Rewrites a GLSL compiler log ("ERROR: 0:123: ...") in terms of the user's file: line 123 of the
 * composed shader is line 123 - firstSourceLine + 1 of the file, shown with its text.
 */
export function mapShaderLog(log, { firstSourceLine, source, fileName = 'shaders/raytrace.glsl' }) {
  const lines = source.split('\n');
  return String(log ?? '')
    .split('\n')
    .filter((l) => l.trim() !== '')
    .map((entry) => {
      const match = entry.match(/^(\s*\w+:\s*)\d+:(\d+):(.*)$/);
      if (!match) return entry;
      const composedLine = Number(match[2]);
      const line = composedLine - firstSourceLine + 1;
      if (line < 1) return `${match[1]}(Shadertoy header, line ${composedLine}):${match[3]}`;
      if (line > lines.length) return `${match[1]}(Shadertoy main wrapper, line ${composedLine}):${match[3]}`;
      return `${match[1]}${fileName}:${line}:${match[3]}\n    ${line} | ${lines[line - 1].trim()}`;
    })
    .join('\n');
}

export function readPng(file) {
  const png = PNG.sync.read(fs.readFileSync(file));
  return { width: png.width, height: png.height, data: png.data };
}

export function writePng(file, { width, height, data }) {
  fs.mkdirSync(path.dirname(file), { recursive: true });
  const png = new PNG({ width, height });
  Buffer.from(data.buffer, data.byteOffset, data.byteLength).copy(png.data);
  fs.writeFileSync(file, PNG.sync.write(png, { colorType: 6 }));
}

/**
 * Why an image is not a render, or null if it could be one: the tests reject uniform images
 * (nothing drawn), all-white ones (Shadertoy's colour when mainImage writes nothing) and
 * all-black ones (a dead context or an unlit scene).
 */
export function blankReason({ width, height, data }) {
  const n = width * height;
  if (n === 0) return 'the image is empty (0 pixels)';
  const colours = new Set();
  let white = 0;
  let black = 0;
  let transparent = 0;
  for (let i = 0; i < n; i++) {
    const r = data[i * 4];
    const g = data[i * 4 + 1];
    const b = data[i * 4 + 2];
    if (data[i * 4 + 3] !== 255) transparent++;
    if (r >= 250 && g >= 250 && b >= 250) white++;
    if (r <= 5 && g <= 5 && b <= 5) black++;
    if (colours.size < 64) colours.add((r << 16) | (g << 8) | b);
  }
  if (colours.size === 1) return `the image is a single colour (rgb ${[...colours][0].toString(16).padStart(6, '0')})`;
  if (white / n > 0.98) return `the image is white (${((100 * white) / n).toFixed(1)}% of pixels)`;
  if (black / n > 0.98) return `the image is black (${((100 * black) / n).toFixed(1)}% of pixels)`;
  if (colours.size < 16) return `the image has only ${colours.size} colours`;
  if (transparent) return `${transparent} pixels are not opaque (Shadertoy forces alpha to 1)`;
  return null;
}

export function assertNotBlank(image, what) {
  const reason = blankReason(image);
  if (reason) throw new Error(`${what}: not a rendered scene: ${reason}`);
}

/** pixelmatch with the suite's tolerance: { diffPixels, fraction, diff (RGBA diff image) }. */
export function compareImages(actual, expected, { threshold = PIXEL_THRESHOLD, includeAA = INCLUDE_AA } = {}) {
  if (actual.width !== expected.width || actual.height !== expected.height) {
    throw new Error(`cannot compare ${actual.width}x${actual.height} with ${expected.width}x${expected.height}`);
  }
  const { width, height } = actual;
  const diff = Buffer.alloc(width * height * 4);
  const diffPixels = pixelmatch(actual.data, expected.data, diff, width, height, { threshold, includeAA });
  return { diffPixels, fraction: diffPixels / (width * height), diff: { width, height, data: diff } };
}

export function allowedDiffPixels(width, height) {
  return Math.floor(width * height * MAX_DIFF_FRACTION);
}

/** A sentence about the environment, if it is not the one the goldens were made in. */
export function environmentNote(current) {
  if (!current || !fs.existsSync(ENVIRONMENT_FILE)) return '';
  let recorded;
  try {
    recorded = JSON.parse(fs.readFileSync(ENVIRONMENT_FILE, 'utf8'));
  } catch {
    return `\nNote: ${path.relative(REPO_ROOT, ENVIRONMENT_FILE)} cannot be read.`;
  }
  const changes = ['chromium', 'renderer']
    .filter((key) => recorded[key] !== current[key])
    .map((key) => `${key}: goldens made with "${recorded[key]}", this run uses "${current[key]}"`);
  if (!changes.length) return '';
  return (
    `\nNote: this environment differs from the one the goldens were made in (${changes.join('; ')}). ` +
    `If the diff shows only that, regenerate the goldens with \`${UPDATE_COMMAND}\` in the new environment.`
  );
}

function outputPaths(name) {
  return {
    actual: path.join(OUTPUT_DIR, `${name}-actual.png`),
    expected: path.join(OUTPUT_DIR, `${name}-expected.png`),
    diff: path.join(OUTPUT_DIR, `${name}-diff.png`),
  };
}

const rel = (file) => path.relative(REPO_ROOT, file);

/**
 * Compares a render with tests/golden/<name>.png. With UPDATE_GOLDENS=1 it (re)writes the golden
 * when it is missing or its pixels differ at all; otherwise a missing golden fails, and a render
 * outside the tolerance fails with actual/expected/diff PNGs written to tests/output/.
 * @returns {Promise<{status:'match'|'written'|'unchanged', diffPixels?:number}>}
 */
export async function expectMatchesGolden(name, image) {
  const golden = path.join(GOLDEN_DIR, `${name}.png`);
  const out = outputPaths(name);
  for (const file of Object.values(out)) fs.rmSync(file, { force: true });

  const exists = fs.existsSync(golden);
  if (UPDATING) {
    if (exists) {
      const old = readPng(golden);
      if (old.width === image.width && old.height === image.height && Buffer.compare(old.data, Buffer.from(image.data)) === 0) {
        return { status: 'unchanged' };
      }
    }
    writePng(golden, image);
    console.log(`${exists ? 'updated' : 'created'} ${rel(golden)}`);
    return { status: 'written' };
  }

  const { environment } = await harnessContext().catch(() => ({}));
  const note = environmentNote(environment);
  if (!exists) {
    writePng(out.actual, image);
    throw new Error(
      `No golden image ${rel(golden)} for view "${name}". Run \`${UPDATE_COMMAND}\` to create it, look at it, ` +
        `and commit it. This run's render is in ${rel(out.actual)}.`,
    );
  }
  const expected = readPng(golden);
  if (expected.width !== image.width || expected.height !== image.height) {
    writePng(out.actual, image);
    throw new Error(
      `${name}: rendered ${image.width}x${image.height} but ${rel(golden)} is ${expected.width}x${expected.height}. ` +
        `Actual: ${rel(out.actual)}. If the view's size changed on purpose, run \`${UPDATE_COMMAND}\`.${note}`,
    );
  }
  const { diffPixels, fraction, diff } = compareImages(image, expected);
  const allowed = allowedDiffPixels(image.width, image.height);
  if (diffPixels > allowed) {
    writePng(out.actual, image);
    writePng(out.expected, expected);
    writePng(out.diff, diff);
    throw new Error(
      `${name}: ${diffPixels} pixels (${(100 * fraction).toFixed(2)}%) differ from ${rel(golden)} by more than ` +
        `threshold ${PIXEL_THRESHOLD}; at most ${allowed} (${(100 * MAX_DIFF_FRACTION).toFixed(2)}%) may.\n` +
        `  actual:   ${rel(out.actual)}\n  expected: ${rel(out.expected)}\n  diff:     ${rel(out.diff)}\n` +
        `If the change is intended, run \`${UPDATE_COMMAND}\` and review the new goldens.${note}`,
    );
  }
  return { status: 'match', diffPixels };
}

/**
 * Runs a complete fragment shader over a table of inputs and reads its RGBA32F output back as
 * floats: the way the intersector tests run GLSL functions on chosen rays. The table is an
 * RGBA32F texture `tableUniform` of width x tableHeight texels; output is width x height.
 * @returns {Promise<Float32Array>} RGBA floats, row 0 first (GL order)
 */
export async function evaluateFloatShader(code, { width, height, table, tableHeight, tableUniform }) {
  const { page, errors } = await openRawPage('float WebGL2');
  try {
    const result = await page.evaluate(
      (fragment, w, h, tableData, th, uniformName) => {
        const canvas = document.createElement('canvas');
        const gl = canvas.getContext('webgl2');
        if (!gl) return { error: 'no WebGL2 context' };
        if (!gl.getExtension('EXT_color_buffer_float')) return { error: 'EXT_color_buffer_float is not supported' };
        const built = window.__rawWebGL.program(gl, fragment);
        if (built.stage) return { error: `${built.stage}: ${built.log}` };
        const { program } = built;
        const input = gl.createTexture();
        gl.activeTexture(gl.TEXTURE0);
        gl.bindTexture(gl.TEXTURE_2D, input);
        gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, w, th, 0, gl.RGBA, gl.FLOAT, new Float32Array(tableData));
        gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
        gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
        gl.uniform1i(gl.getUniformLocation(program, uniformName), 0);
        const target = gl.createTexture();
        gl.bindTexture(gl.TEXTURE_2D, target);
        gl.texStorage2D(gl.TEXTURE_2D, 1, gl.RGBA32F, w, h);
        const framebuffer = gl.createFramebuffer();
        gl.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
        gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, target, 0);
        gl.bindTexture(gl.TEXTURE_2D, input);
        gl.viewport(0, 0, w, h);
        gl.drawArrays(gl.TRIANGLES, 0, 3);
        const out = new Float32Array(w * h * 4);
        gl.readPixels(0, 0, w, h, gl.RGBA, gl.FLOAT, out);
        const glError = gl.getError();
        if (glError) return { error: `GL error ${glError}` };
        return { data: Array.from(out) };
      },
      code,
      width,
      height,
      Array.from(table),
      tableHeight,
      tableUniform,
    );
    if (errors.length) throw new Error(`float WebGL2 page logged errors:\n  ${errors.join('\n  ')}`);
    if (result.error) throw new Error(`evaluateFloatShader: ${result.error}`);
    return new Float32Array(result.data);
  } finally {
    await page.close().catch(() => {});
  }
}

// ------------------------------------------------------------------------------------------------
// A second page server, with file watching (the shared one runs with watch: null)
// ------------------------------------------------------------------------------------------------

/**
 * Starts another Vite dev server for the page, in the test worker, with file watching and hot
 * updates on: for tests of what `npm run dev` does when a shader file changes. Close it after.
 * @returns {Promise<{baseUrl: string, close: () => Promise<void>}>}
 */
export async function startWatchingServer() {
  const { createServer } = await import('vite');
  const port = await freePort();
  const server = await createServer({
    configFile: path.join(REPO_ROOT, 'vite.config.js'),
    logLevel: 'warn',
    clearScreen: false,
    server: { host: '127.0.0.1', port, strictPort: true, open: false },
  });
  await server.listen();
  return { baseUrl: `http://127.0.0.1:${port}`, close: () => server.close() };
}

/**
 * Times complete fragment shaders in one plain WebGL2 canvas (no page code), interleaved: each
 * round draws every shader once, so that a machine that speeds up or slows down during the run
 * moves all of them alike. `warmup` untimed rounds (the first compiles SwiftShader's code), then
 * `frames` timed rounds; a frame is a draw plus a 1-pixel readPixels, so that what is timed is
 * the rendering. Then each shader's last frame is read back. Each frame is its own call into the
 * page (no protocol timeout however slow), and `onRound(i)` can show progress.
 * `shaders` is a list of { code, uniforms } where uniforms are { name, type, value } (float,
 * int, vecN) besides Shadertoy's own at their first-frame values (iTime 0, iMouse 0).
 * @returns {Promise<Array<{times: number[], width, height, data: Buffer} | {error: string}>>}
 */
export async function timeShaders(shaders, { width, height, frames = 15, warmup = 3, onRound = () => {} }) {
  // The benchmark needs the real clock: no deterministic injection here.
  const { page, errors } = await openRawPage('benchmark', { deterministic: false });
  try {
    const setups = await page.evaluate(
      (list, w, h) => {
        const canvas = document.createElement('canvas');
        canvas.width = w;
        canvas.height = h;
        const gl = canvas.getContext('webgl2', { antialias: false, depth: false, stencil: false });
        if (!gl) return list.map(() => ({ error: 'no WebGL2 context' }));
        gl.viewport(0, 0, w, h);
        const one = new Uint8Array(4);
        const programs = list.map(({ code, uniforms }) => {
          const built = window.__rawWebGL.program(gl, code);
          if (built.stage) return { error: `${built.stage}: ${built.log}` };
          const at = (name) => gl.getUniformLocation(built.program, name);
          gl.uniform3f(at('iResolution'), w, h, 1);
          for (const { name, type, value } of uniforms) {
            const v = Array.isArray(value) ? value : [Number(value)];
            if (type === 'int' || type === 'bool') gl.uniform1i(at(name), v[0]);
            else gl[`uniform${v.length}fv`](at(name), new Float32Array(v));
          }
          return { program: built.program };
        });
        window.__benchmark = {
          frame(i) {
            gl.useProgram(programs[i].program);
            const start = performance.now();
            gl.drawArrays(gl.TRIANGLES, 0, 3);
            gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, one);
            return performance.now() - start;
          },
          pixels(i) {
            gl.useProgram(programs[i].program);
            gl.drawArrays(gl.TRIANGLES, 0, 3);
            const pixels = new Uint8Array(w * h * 4);
            gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
            return window.__rawWebGL.toBase64(pixels, w, h);
          },
        };
        return programs.map((p) => (p.error ? { error: p.error } : {}));
      },
      shaders.map(({ code, uniforms = [] }) => ({ code, uniforms })),
      width,
      height,
    );
    const live = setups.map((s, i) => (s.error ? null : i)).filter((i) => i !== null);
    const times = shaders.map(() => []);
    for (let round = 0; round < warmup + frames; round++) {
      for (const i of live) {
        const ms = await page.evaluate((k) => window.__benchmark.frame(k), i);
        if (round >= warmup) times[i].push(ms);
      }
      onRound(round);
    }
    const results = [];
    for (const [i, setup] of setups.entries()) {
      if (setup.error) {
        results.push(setup);
        continue;
      }
      const data = await page.evaluate((k) => window.__benchmark.pixels(k), i);
      results.push({ times: times[i], width, height, data: decodeRgba(data, width, height, 'benchmark frame') });
    }
    if (errors.length) throw new Error(`benchmark page logged errors:\n  ${errors.join('\n  ')}`);
    return results;
  } finally {
    await page.close().catch(() => {});
  }
}
