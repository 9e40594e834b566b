// The command line's watchdog: how long a shader may go without finishing a band of a frame
// before it is taken never to finish, per renderer, and what a person reads when it gives up.
// A band is sized to take about 0.1 s (src/page/gpu/bands/band-planner.js), so a frame that is still
// making progress finishes a band every fraction of a second and is never stopped, however long
// the whole frame takes; only a band that does not end is. A program's first draw is where it is
// compiled, and gets longer.

import { PRODUCTION_TIMEOUTS } from '../shared/timeouts.js';

/**
 * Per renderer: `hangMs` for a band, `compileHangMs` for a band with a program's first draw.
 * SwiftShader and a GPU keep the page's own limits (src/shared/timeouts.js: the heaviest
 * scene of the raytracer compiles in 3.5 s on SwiftShader here, a large public shader in ~15 s).
 * LLVM compiles more slowly than SwiftShader's Subzero (the raytracer's first draw: docs/renderers.md),
 * so llvmpipe gets twice SwiftShader's limit for a first draw.
 * @type {Record<import('../engine/renderers.js').RendererName, {hangMs: number, compileHangMs: number}>}
 */
export const WATCHDOG_LIMITS = Object.freeze({
  swiftshader: { hangMs: PRODUCTION_TIMEOUTS.hangMs, compileHangMs: PRODUCTION_TIMEOUTS.compileHangMs },
  llvmpipe: { hangMs: PRODUCTION_TIMEOUTS.hangMs, compileHangMs: 2 * PRODUCTION_TIMEOUTS.compileHangMs },
  gpu: { hangMs: PRODUCTION_TIMEOUTS.hangMs, compileHangMs: PRODUCTION_TIMEOUTS.compileHangMs },
});

/**
 * The limits a session runs with: `seconds` (--watchdog S) for every band, else the renderer's.
 * @param {import('../engine/renderers.js').RendererName} renderer
 * @param {number | null} seconds
 */
export function watchdogFor(renderer, seconds) {
  if (seconds === null) return { ...WATCHDOG_LIMITS[renderer] };
  return { hangMs: seconds * 1000, compileHangMs: seconds * 1000 };
}

/**
 * The one line said when the watchdog gives up on a shader.
 * @param {{hangMs: number, compileHangMs: number}} limits
 */
export function hungLine({ hangMs, compileHangMs }) {
  const s = (/** @type {number} */ ms) => `${ms / 1000} s`;
  const limits = hangMs === compileHangMs ? s(hangMs) : `${s(hangMs)} (${s(compileHangMs)} for a program's first draw, which compiles it)`;
  return (
    `did not finish drawing a frame: one band of it took longer than the watchdog's ${limits}; ` +
    `it may never finish (an endless loop, or far too much work per pixel): --watchdog S gives each band S seconds`
  );
}
