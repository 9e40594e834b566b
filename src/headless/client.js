// The command line's and the harness's one client of the engine page's API (window.shaderEngine,
// src/player/hook/engine-hook.js): one method for each thing they ask the page, and the only module
// under src/ that runs code on a page (page.evaluate). Everything else (view.js, long-work.js,
// the session, render, sound, test) asks through it, so that what the page is asked, and what
// comes back, is written once and typed here.
//
// Work that takes longer than one question (a view being drawn, a converge, a recording) is
// started on the page into a slot of its own (window.__view, window.__longWork) and asked after
// with short questions: a wait on the page is bounded (watch.js), and a poll shows progress.
//
// What the page says beside the picture (its notes), the watchdog's message and the page's error
// come back as data from the hook (notes(), hang(), info()), not from its DOM: the page's ids and
// attributes are its own. The one exception is describePage(), which tells what a page that does
// not answer was doing, and so must read a page that may have no hook yet.

/**
 * The band the GPU is on (null: none): how long the page has seen it drawn, whether it is a
 * program's first draw, its serial number; `bands` of the frame drawn so far; and `hang`, the
 * message of the page's own watchdog when it has given up on the band (a hang the page shows; the
 * command line judges for itself: band-watch.js).
 * @typedef {{band: {seconds: number, compiling: boolean, serial: number} | null, bands: number, hang: string | null}} BandReport
 */

/**
 * How a view started on the page (startView) stands: drawn, failed (`compile` when the shader did
 * not compile), or still running (`rows` of `height` drawn of the pass under way, and its band).
 * @typedef {{state: 'drawn'} | {state: 'failed', error: string, compile: boolean}
 *   | ({state: 'running', rows: number, height: number} & BandReport)} ViewPoll
 */

/**
 * How long work started by startLong stands: `done` with its value, failed, or how far it has
 * got (`done` of `total`, and its band).
 * @typedef {{state: 'done', value: any} | {state: 'failed', error: string}
 *   | ({state: 'running', done: number, total: number} & BandReport)} LongPoll
 */

/** @typedef {'record' | 'frameAt' | 'converge'} LongMethod */

/** The engine page's hook: its type is the hook's class (src/player/hook/engine-hook.js). @typedef {import('../player/hook/engine-hook.js').EngineHook} EngineHook */
/** The window with the hook, as code run on the page reads it. @typedef {import('../player/hook/hook-window.js').HookedWindow} HookedWindow */

/** An image from the page: base64 data, rows top to bottom. @typedef {{width: number, height: number, data: string}} PageImage */

/**
 * A client for the engine page on `page`.
 * @param {import('puppeteer-core').Page} page
 */
export function engineClient(page) {
  return {
    /** The Puppeteer page, for the tests that drive the browser itself (src/ asks through the methods below). */
    get page() {
      return page;
    },
    isClosed: () => page.isClosed(),
    close: () => page.close(),

    /**
     * Loads `url` and waits for the hook (or the page's start-up error): null, or why not.
     * @param {string} url
     */
    async load(url) {
      const response = await page.goto(url, { waitUntil: 'load' });
      if (!response || (!response.ok() && response.status() !== 304)) return `the page answered HTTP ${response?.status()}`;
      // a page that could not start has a hook too (hook/failed-hook.js)
      await page.waitForFunction(() => Boolean(/** @type {HookedWindow} */ (window).shaderEngine), { polling: 100 });
      return null;
    },

    /**
     * Starts bringing the page to the view `query` (null: the view it loaded at) and reading its
     * frame back: null, or the page's start-up error. The still is the view's frame 0, as it was
     * drawn (readFrame draws nothing), so that an iFrame-reading shader renders as Shadertoy
     * draws its first frame.
     * @param {string | null} query
     * @returns {Promise<string | null>}
     */
    startView(query) {
      return page.evaluate((opening) => {
        if (!(/** @type {HookedWindow} */ (window).shaderEngine)) return 'page error: the page has no engine hook (window.shaderEngine)';
        const hook = /** @type {HookedWindow} */ (window).shaderEngine;
        const slot = { settled: /** @type {any} */ (null), view: /** @type {any} */ (null) };
        /** @type {any} */ (window).__view = slot;
        // what the loop guard found is said of this view alone (loopCuts)
        const opened = hook
          .loopCuts(true)
          .catch(() => null)
          .then(() => (opening === null ? hook.ready : hook.open(opening)));
        opened
          .then(async () => {
            const { iFrame, ...pixels } = await hook.readFrame();
            const info = JSON.parse(JSON.stringify(hook.info()));
            slot.view = { pixels, frame: info.frame, iFrame, info, notes: hook.notes(), pageError: info.error ?? undefined };
            slot.settled = { state: 'drawn' };
          })
          .catch(
            (error) =>
              (slot.settled = {
                state: 'failed',
                error: error?.report ?? error?.message ?? String(error),
                compile: Boolean(error?.report),
              }),
          );
        return null;
      }, query);
    },

    /** How the view startView started stands. @returns {Promise<ViewPoll>} */
    pollView() {
      return page.evaluate(() => {
        const settled = /** @type {any} */ (window).__view?.settled;
        if (settled) return settled;
        const said = /** @type {HookedWindow} */ (window).shaderEngine.hang();
        const hang = said?.phase === 'drawing' ? said.message : null;
        const { progress, band } = /** @type {HookedWindow} */ (window).shaderEngine.info();
        return { state: 'running', rows: progress?.y ?? 0, height: progress?.height ?? 0, bands: progress?.bands ?? 0, band, hang };
      });
    },

    /**
     * The view startView drew (once pollView says it is drawn): its pixels and their iFrame, the
     * frames drawn so far, what the page says of itself (info), its notes, and its start-up error
     * if any.
     * @returns {Promise<{pixels: PageImage, iFrame: number, frame: number, info: any,
     *   notes: import('./view.js').PageNote[], pageError: string | undefined}>}
     */
    readView() {
      return page.evaluate(() => {
        const slot = /** @type {any} */ (window).__view;
        const view = slot.view;
        slot.view = null; // its pixels are given once
        return view;
      });
    },

    /** What the page says of itself (hook/engine-state.js info()). */
    info: () => page.evaluate(() => JSON.parse(JSON.stringify(/** @type {HookedWindow} */ (window).shaderEngine.info()))),
    /** The last frame drawn again (RGBA8). @returns {Promise<PageImage>} */
    capture: () => page.evaluate(() => /** @type {HookedWindow} */ (window).shaderEngine.capture()),
    /** The last frame's Image pass in RGBA32F. @returns {Promise<PageImage>} */
    captureFloat: () => page.evaluate(() => /** @type {HookedWindow} */ (window).shaderEngine.captureFloat()),
    /**
     * A tile of the last frame drawn at the full size.
     * @param {{x: number, y: number, width: number, height: number, fullWidth: number, fullHeight: number}} tile
     * @returns {Promise<PageImage>}
     */
    captureTile: (tile) => page.evaluate((t) => /** @type {HookedWindow} */ (window).shaderEngine.captureTile(t), tile),
    /** `n` whole frames drawn back to back: their median time in ms. @param {number} n */
    renderFrames: (n) => page.evaluate((count) => /** @type {HookedWindow} */ (window).shaderEngine.renderFrames(count), n),
    /**
     * The Sound tab's samples over [time, time + duration): base64 interleaved 16-bit PCM.
     * @param {{time: number, duration: number}} range
     * @returns {Promise<{data: string, sampleRate: number}>}
     */
    renderSound: (range) => page.evaluate((r) => /** @type {HookedWindow} */ (window).shaderEngine.renderSound(r), range),
    /**
     * What llvmpipe's loop limit cut short since the view began (or the last reset), pass by
     * pass, and the passes it could not check (src/player/gpu/loop-cuts.js).
     * @param {boolean} [reset]
     * @returns {Promise<import('../player/gpu/protocol.js').LoopReport>}
     */
    loopCuts: (reset = false) => page.evaluate((r) => /** @type {HookedWindow} */ (window).shaderEngine.loopCuts(r), reset),
    /**
     * Whether a frame with a loop cut stops at that band (the default renderer then draws the
     * shader with SwiftShader) rather than being drawn whole; `guard` false: passes are not
     * guarded at all (the benchmark's, to time the guard).
     * @param {{stopOnCut: boolean, guard: boolean}} setting
     */
    setLoopGuard: (setting) => page.evaluate((s) => /** @type {HookedWindow} */ (window).shaderEngine.setLoopGuard(s), setting),
    /** Answers at once if the page's thread is free: a heartbeat. */
    ping: () => page.evaluate(() => 0),

    /**
     * Starts long work on the page: `record` or `frameAt` with `request`, or a converge of `total`
     * still frames, the picture alone (its progressive form's on-screen overlays off).
     * @param {LongMethod} method
     * @param {{request: any, total: number}} work
     */
    startLong(method, { request, total }) {
      return page.evaluate(
        (m, r, t) => {
          const hook = /** @type {any} */ (/** @type {HookedWindow} */ (window).shaderEngine);
          const slot = { settled: /** @type {any} */ (null) };
          /** @type {any} */ (window).__longWork = slot;
          // a converge is "Converge when still" of t samples, done when t still frames are drawn: its
          // live controls settle into constants first (a compile), then a restart clears the sum
          const constants = () =>
            new Promise((resolve) => {
              const id = setInterval(() => hook.info().liveControls === 'constants' && (clearInterval(id), resolve(null)), 50);
            });
          const started =
            m === 'converge'
              ? hook
                  .setConverging(true, { frames: t, overlays: false })
                  .then(constants)
                  .then(() => hook.restart())
              : hook[m](r);
          started.then(
            (/** @type {any} */ value) => (slot.settled = m === 'converge' ? { state: 'started' } : { state: 'done', value }),
            (/** @type {any} */ error) => (slot.settled = { state: 'failed', error: String(error?.message ?? error) }),
          );
        },
        method,
        request,
        total,
      );
    },

    /**
     * How the long work startLong started stands.
     * @param {LongMethod} method
     * @param {number} total
     * @returns {Promise<LongPoll>}
     */
    pollLong(method, total) {
      return page.evaluate(
        (m, t) => {
          const hook = /** @type {HookedWindow} */ (window).shaderEngine;
          const settled = /** @type {any} */ (window).__longWork.settled;
          const said = hook.hang();
          const { progress, band, stillFrames } = hook.info();
          const report = { band, bands: progress?.bands ?? 0, hang: said?.phase === 'drawing' ? said.message : null };
          if (m === 'converge') {
            if (settled?.state === 'failed') return settled;
            if (settled && stillFrames >= t) return { state: 'done', value: null };
            return { state: 'running', done: settled ? Math.min(stillFrames, t) : 0, total: t, ...report };
          }
          if (settled) return settled;
          const { done, total: all } = hook.recording();
          return { state: 'running', done, total: all || t, ...report };
        },
        method,
        total,
      );
    },
  };
}

/** @typedef {ReturnType<typeof engineClient>} EngineClient */

/**
 * What a page that does not answer in time was doing (watch.js says it beside the timeout): its
 * address, its marks (frames drawn, its start-up or compile error, the line it shows: page-marks.js
 * window.pageMarks, data the page keeps from its first script on, since its hook may not be there
 * yet, or not whole) and what its hook says, asked with `evaluate` (the page's own, unbounded: the
 * caller races it).
 * @param {import('puppeteer-core').Page['evaluate']} evaluate
 * @returns {Promise<{url: string, frame: number | null, error: string | null, status: string | null, shaderEngine: boolean, info: object | null}>}
 */
export function describePage(evaluate) {
  return evaluate(() => {
    const marks = /** @type {Partial<import('../player/page-marks.js').PageMarks>} */ (
      /** @type {{pageMarks?: import('../player/page-marks.js').PageMarks}} */ (/** @type {unknown} */ (window)).pageMarks ?? {}
    );
    /** @type {object | null} */
    let info;
    /** @type {string | null} */
    let hang = null;
    // the hook may not be there yet, or not whole: this page is being asked why it is stuck
    const hook = /** @type {Partial<EngineHook> | undefined} */ (/** @type {Partial<HookedWindow>} */ (window).shaderEngine);
    try {
      const { fileName, origin, time, playing, width, height } = hook?.info?.() ?? {};
      info = hook?.info ? { fileName, origin, time, playing, width, height } : null;
      hang = hook?.hang?.()?.message ?? null;
    } catch (error) {
      info = { error: String(error?.message ?? error) };
    }
    return {
      url: location.href,
      frame: marks.frame ?? null,
      error: marks.error ?? null,
      status: marks.status ?? hang,
      shaderEngine: Boolean(/** @type {HookedWindow} */ (window).shaderEngine),
      info,
    };
  });
}

/**
 * Who WebGL2 is on the blank page `page`: its renderer, vendor and version strings, or null when
 * it has no WebGL2 (browser.js checks the renderer it launched).
 * @param {import('puppeteer-core').Page} page
 * @returns {Promise<{renderer: string, vendor: string, version: string} | null>}
 */
export function webglIdentity(page) {
  return page.evaluate(() => {
    const gl = document.createElement('canvas').getContext('webgl2');
    if (!gl) return null;
    const debug = gl.getExtension('WEBGL_debug_renderer_info');
    return {
      renderer: debug ? gl.getParameter(debug.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER),
      vendor: debug ? gl.getParameter(debug.UNMASKED_VENDOR_WEBGL) : gl.getParameter(gl.VENDOR),
      version: gl.getParameter(gl.VERSION),
    };
  });
}

/**
 * Runs `scripts` (sources) before the page's own on every load of `page`, and gives the page its
 * `timeouts` (src/shared/timeouts.js) before it starts.
 * @param {import('puppeteer-core').Page} page
 * @param {string[]} scripts
 * @param {Partial<import('../shared/timeouts.js').Timeouts> | undefined} timeouts
 */
export async function beforeEachLoad(page, scripts, timeouts) {
  for (const script of scripts) await page.evaluateOnNewDocument(script);
  if (timeouts)
    await page.evaluateOnNewDocument((chosen) => {
      /** @type {any} */ (window).__shaderEngineTimeouts = chosen;
    }, /** @type {any} */ (timeouts));
}
