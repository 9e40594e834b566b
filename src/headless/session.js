// What every verb of the command line starts with: the built page served on a loopback port
// (src/headless/page-server.js), one headless Chromium (src/headless/browser.js: SwiftShader,
// llvmpipe or the machine's GPU, src/headless/renderers.js), and a page on it brought to each view
// through the same drawView as the render tests (src/headless/view.js). The watchdog counts the
// work of that browser's GPU process (src/headless/watchdog/gpu-time.js), not the wall clock. A shader that
// never finishes holds the GPU process for good (tests/browser/page-heavy.test.js): the session then
// kills that browser and starts another for whatever comes next.

import fs from 'node:fs';
import { rendererLabel } from './browser.js';
import { killBrowser } from './watch.js';
import { findChrome } from './chrome-path.js';
import { launchChromium, servePage } from './core.js';
import { drawView } from './view.js';
import { WALL_CLOCK, gpuClock } from './watchdog/gpu-time.js';
import { engineClient } from './client.js';
import { openPage } from './page-open.js';
import { CLOSE_TIMEOUT_MS, withTimeout } from './watch.js';
import { fromBase64 } from '../shared/pixels.js';
import { WATCHDOG_LIMITS, hungLine } from './watchdog/limits.js';
import { jsonSyntaxError } from '../shared/json-syntax.js';

/**
 * The one error of shaderproof, the command line's and the Node API's: what went wrong and what
 * to do, in one line, without a stack. exitCode: what the command line exits with.
 */
export class ShaderproofError extends Error {
  /** @param {string} message @param {number} [exitCode] */
  constructor(message, exitCode = 1) {
    super(message);
    this.exitCode = exitCode;
    /** the shader did not finish a frame (the watchdog) */
    this.hung = false;
    /** the shader did not compile */
    this.compile = false;
  }
}

/**
 * The page every view is drawn on: the engine page (src/player/engine.html), only what draws, not
 * the interactive page with its editor, panel and inspector, whose code it never loads.
 */
export const ENGINE_PAGE = '/engine.html';

/**
 * How long one question to the page may take that is no frame (a load, a read-back): a drawing
 * view is asked after every 0.1 s and bounded by the watchdog instead (view.js), so this bounds
 * only a page that stopped answering for some other reason.
 */
const WAIT_MS = 120_000;

/**
 * The view a new page starts at, before the first view: the engine page's own start shader (no
 * ?shader=: a black one, src/player/engine-main.js), 2×2. A page whose first load is a shader that
 * never finishes stops answering (its first draw holds the page's own thread on SwiftShader),
 * whereas one that has drawn once hears the watchdog and says so. So every view is brought in
 * by open(), on a page that has drawn this.
 */
const START_VIEW = `${ENGINE_PAGE}?size=2x2&time=0`;

/**
 * @param {{renderer?: import('./renderers.js').RendererName, hangMs?: number, compileHangMs?: number,
 *   loopLimit?: import('../api/loop-limit.js').LoopLimitMode,
 *   say?: (line: string) => void, verbose?: boolean,
 *   progress?: (state: import('./view.js').ViewProgress | null) => void}} [options]
 *   hangMs: a band of a frame that costs the GPU process this long in CPU time (the wall clock
 *   where that cannot be read) fails (the watchdog: watchdog.js); compileHangMs: the same for a
 *   program's first draw, which compiles it; loopLimit: what a loop cut by llvmpipe's limit does
 *   (loop-limit.js); progress: hears how far each view has got, every 0.1 s while it draws;
 *   verbose: `say` hears the page's build log too, when it is built (page-build.js)
 */
export async function startSession({
  renderer = 'swiftshader',
  loopLimit = 'fail',
  hangMs = WATCHDOG_LIMITS[renderer].hangMs,
  compileHangMs = WATCHDOG_LIMITS[renderer].compileHangMs,
  say = () => {},
  verbose = false,
  progress = () => {},
} = {}) {
  const limits = { hangMs, compileHangMs };
  mark('node started, modules loaded');
  let executablePath;
  try {
    executablePath = findChrome();
  } catch (error) {
    throw new ShaderproofError(error.message);
  }
  const server = await servePage({ say, verbose }).catch((error) => {
    throw new ShaderproofError(error.message);
  });
  mark('server');
  /** @type {Awaited<ReturnType<typeof launchChromium>> | null} */
  let chromium = null;
  /** The page the views are drawn on, through its client. @type {import('./client.js').EngineClient | null} */
  let page = null;
  /** What the current page logged as errors (page-open.js). @type {string[]} */
  let pageErrors = [];
  /** Set by kill(): this session starts no browser again. */
  let killed = false;
  /** How many browsers this session started (another after each hang). */
  let launches = 0;
  /**
   * The watchdog's clock: the work of the current browser's GPU process (its CPU time on a CPU
   * renderer; on a hardware GPU, whose work is not the CPU's, the wall clock).
   * @type {import('./watchdog/gpu-time.js').WorkClock}
   */
  let clock = WALL_CLOCK;

  async function browser() {
    if (chromium) return chromium;
    if (killed) throw new ShaderproofError('this session was given up: its browser stopped answering');
    const launched = await launchChromium({ renderer, executablePath, probe: false }).catch((error) => {
      throw new ShaderproofError(error.message);
    });
    launches++;
    if (killed) {
      killBrowser(launched.browser); // killed while it launched
      await launched.close().catch(() => {});
      throw new ShaderproofError('this session was given up: its browser stopped answering');
    }
    chromium = launched;
    clock = renderer === 'gpu' ? WALL_CLOCK : gpuClock(launched.browser.process()?.pid);
    mark('chromium launched');
    return chromium;
  }

  async function freshPage() {
    const { browser: b } = await browser();
    const { page: opened, errors } = await openPage(b, { waitTimeoutMs: WAIT_MS, timeouts: { hangMs, compileHangMs } });
    pageErrors = errors;
    const client = engineClient(opened);
    const started = await drawView(client, {
      baseUrl: server.baseUrl,
      query: START_VIEW,
      fresh: true,
      limits,
      clock,
    });
    if (started.error !== undefined) throw new ShaderproofError(`the page did not start: ${started.error}`);
    try {
      const { renderer, version } = /** @type {Extract<import('./view.js').DrawnView, {pixels: unknown}>} */ (started).info;
      (await browser()).verify(renderer ? { renderer, version } : null);
    } catch (error) {
      throw new ShaderproofError(error.message);
    }
    // a frame stops at its first cut (its picture is not the shader's, and an endless loop costs
    // the limit's trips in every pixel); SHADERPROOF_LOOP_GUARD=off: no pass guarded, so no cut
    // seen (the benchmark's, to time the guard)
    await client.setLoopGuard({ stopOnCut: true, guard: process.env.SHADERPROOF_LOOP_GUARD !== 'off' });
    mark('page loaded, first frame, WebGL2 checked');
    return client;
  }

  /** Drops the browser (after a hang: its GPU process is stuck); the next view starts another. */
  async function dropBrowser() {
    const old = chromium;
    chromium = null;
    page = null;
    if (!old) return;
    killBrowser(old.browser);
    await old.close().catch(() => {});
  }

  return {
    server,
    /** The watchdog's limits this session runs with. */
    limits,
    /** What a loop cut by llvmpipe's limit does (loop-limit.js). */
    loopLimit,
    /**
     * What llvmpipe's loop limit cut short since the last view began, pass by pass (the render
     * worker's log: src/player/gpu/loop-cuts.js); null when no page is open.
     */
    async loopReport() {
      return page && !page.isClosed() ? page.loopCuts() : null;
    },
    /** How many browsers this session started: one, and another after each hang. */
    launches: () => launches,
    /** The watchdog's clock (the current browser's, or the last one's): what the limits are counted on. */
    clock: () => clock,
    /**
     * What draws: Chromium's version, the renderer's name (`rendererName`) and its WebGL2 string
     * (`label`: without its device id).
     */
    async environment() {
      if (!page) page = await freshPage(); // the renderer is known once a page has drawn
      const { environment } = await browser();
      return { ...environment, label: rendererLabel(environment.renderer) };
    },
    /**
     * Draws the view `query` and reads its frame: { width, height, data (RGBA8 rows top to
     * bottom), info }. Throws ShaderproofError with the page's words: a compile error, a shader that
     * did not finish (the watchdog), a page error.
     * @param {string} query
     */
    async draw(query) {
      if (!page || page.isClosed()) page = await freshPage();
      const current = /** @type {import('./client.js').EngineClient} */ (page);
      let result;
      try {
        result = await drawView(current, { baseUrl: server.baseUrl, query, fresh: false, limits, clock, progress });
        progress(null);
      } catch (error) {
        progress(null);
        await current.close().catch(() => {});
        page = null;
        throw new ShaderproofError(error.message.split('\n')[0]);
      }
      if (result.error !== undefined) {
        // (the tests' type check runs without null checks, where `error?: undefined` does not narrow)
        const failed = /** @type {Extract<import('./view.js').DrawnView, {hung?: boolean}>} */ (result);
        if (failed.hung) await dropBrowser();
        else {
          await current.close().catch(() => {});
          page = null;
        }
        const error = new ShaderproofError(failed.hung ? hungLine(limits, clock.measure) : failed.error);
        Object.assign(error, { hung: Boolean(failed.hung), compile: Boolean(failed.compile) });
        throw error;
      }
      const { pixels, info, notes } = /** @type {Extract<import('./view.js').DrawnView, {pixels: unknown}>} */ (result);
      mark('view drawn');
      return { width: pixels.width, height: pixels.height, data: fromBase64(pixels.data), info, notes };
    },
    /**
     * The last view's frame again in RGBA32F, as the shader wrote its colours (unclamped, NaN
     * and infinity kept): { width, height, data: Float32Array, rows top to bottom }.
     */
    async drawFloat() {
      if (!page) throw new Error('drawFloat: no view has been drawn');
      const { width, height, data } = await page.captureFloat();
      const bytes = fromBase64(data);
      return { width, height, data: new Float32Array(bytes.buffer, bytes.byteOffset, bytes.byteLength / 4) };
    },
    /**
     * The client of the page the last view was drawn on (for what only it can do: record, frame
     * steps, sound, a tile), or null when there is none.
     */
    client: () => page,
    /** Console errors and page errors the current page logged since the last call. */
    takeLogged: () => pageErrors.splice(0),
    /** Kills the browser at once (it stopped answering: src/runner/guard.js), for good. */
    async kill() {
      killed = true;
      await dropBrowser();
    },
    async close() {
      mark('output written');
      if (page && !page.isClosed()) await withTimeout('closing the page', page.close(), CLOSE_TIMEOUT_MS).catch(() => {});
      if (chromium) await chromium.close().catch(() => {});
      await server.close();
      mark('closed');
      if (process.env.SHADERPROOF_TIMINGS) say(`timings: ${JSON.stringify(marks)}`);
    },
  };
}

/** Where the time of a command goes (SHADERPROOF_TIMINGS=1 prints it; the benchmark reads it). */
const marks = /** @type {Record<string, number>} */ ({});
/** Milliseconds since the process started, at `what` (the first time it happens). @param {string} what */
function mark(what) {
  if (!(what in marks)) marks[what] = Math.round(process.uptime() * 1000);
}

/** @typedef {Awaited<ReturnType<typeof startSession>>} Session */

/**
 * What a file holds, for the error a person sees when it is not a shader: 'glsl' (has a
 * mainImage), 'json' (Shadertoy's export, checked by the page), or throws ShaderproofError.
 * @param {string} file
 */
export function shaderKind(file) {
  let text;
  try {
    text = fs.readFileSync(file, 'utf8');
  } catch (error) {
    /** @type {Record<string, string>} */
    const why = {
      ENOENT: 'no such file',
      EISDIR: 'a folder, not a shader file (shaderproof test DIR runs every shader in a folder)',
      EACCES: 'cannot be read: permission denied',
    };
    throw new ShaderproofError(`${file}: ${why[error.code] ?? `cannot be read (${error.code ?? error.message})`}`);
  }
  if (/\.json$/i.test(file) || /^\s*[[{]/.test(text)) {
    try {
      JSON.parse(text);
    } catch (error) {
      const where = jsonSyntaxError(text) ?? String(error.message).replace(/\s*\n\s*/g, ' ');
      throw new ShaderproofError(`${file}: not a shader: a Shadertoy export is JSON, and this is not (${where})`);
    }
    return 'json';
  }
  if (text.includes('\u0000')) throw new ShaderproofError(`${file}: not a shader: a binary file`);
  if (!/\bmainImage\s*\(/.test(text))
    throw new ShaderproofError(`${file}: not a shader: no mainImage() in it (a Shadertoy Image tab defines one)`);
  return 'glsl';
}
