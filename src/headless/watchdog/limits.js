// The command line's watchdog: how much work a shader may cost without finishing a band of a
// frame before it is taken never to finish, per renderer, and what a person reads when it gives
// up. The work is the CPU time of the browser's GPU process (src/headless/watchdog/gpu-time.js: where it
// cannot be read, and on a hardware GPU, the wall clock), counted from the band's start
// (src/headless/watchdog/band-watch.js): a busy machine, a stopped process or a suspended laptop does not
// count. A band is sized to take about 0.1 s (src/player/gpu/bands/band-planner.js), so a frame
// that is still making progress finishes a band every fraction of a second and is never
// stopped, however long the whole frame takes; only a band that does not end is. A program's
// first draw is where it is compiled, and gets longer. SwiftShader and llvmpipe draw on every
// core, so an endless band reaches its limit sooner than its seconds on the wall clock (on 2
// cores, in half of them); a compile runs on one.

import { PRODUCTION_TIMEOUTS } from '../../shared/timeouts.js';

/**
 * Per renderer: `hangMs` for a band, `compileHangMs` for a band with a program's first draw.
 * SwiftShader and a GPU keep the page's own limits (src/shared/timeouts.js: the heaviest
 * scene of the studio's built-in shader compiles in 3.5 s on SwiftShader here, a large public
 * shader in ~15 s). LLVM compiles more slowly than SwiftShader's Subzero (that shader's first
 * draw: docs/renderers.md), so llvmpipe gets twice SwiftShader's limit for a first draw.
 * @type {Record<import('../renderers.js').RendererName, {hangMs: number, compileHangMs: number}>}
 */
export const WATCHDOG_LIMITS = Object.freeze({
  swiftshader: { hangMs: PRODUCTION_TIMEOUTS.hangMs, compileHangMs: PRODUCTION_TIMEOUTS.compileHangMs },
  llvmpipe: { hangMs: PRODUCTION_TIMEOUTS.hangMs, compileHangMs: 2 * PRODUCTION_TIMEOUTS.compileHangMs },
  gpu: { hangMs: PRODUCTION_TIMEOUTS.hangMs, compileHangMs: PRODUCTION_TIMEOUTS.compileHangMs },
});

/**
 * The limits a session runs with: `seconds` (--watchdog S, of the GPU process's CPU time) for
 * every band, else the renderer's.
 * @param {import('../renderers.js').RendererName} renderer
 * @param {number | null} seconds
 */
export function watchdogFor(renderer, seconds) {
  if (seconds === null) return { ...WATCHDOG_LIMITS[renderer] };
  return { hangMs: seconds * 1000, compileHangMs: seconds * 1000 };
}

/**
 * The one line said when the watchdog gives up on a shader: `measure`, what its limits were
 * counted on (the GPU process's CPU time, or the wall clock: gpu-time.js).
 * @param {{hangMs: number, compileHangMs: number}} limits
 * @param {import('./gpu-time.js').ClockMeasure} measure
 */
export function hungLine({ hangMs, compileHangMs }, measure) {
  const s = (/** @type {number} */ ms) => `${ms / 1000} s`;
  const cpu = measure === 'cpu' ? " of the GPU process's CPU time" : '';
  const compile = hangMs === compileHangMs ? '' : ` (${s(compileHangMs)} for a program's first draw, which compiles it)`;
  const cost = measure === 'cpu' ? 'used more than' : 'took longer than';
  return (
    `did not finish drawing a frame: one band of it ${cost} the watchdog's ${s(hangMs)}${cpu}${compile}; ` +
    `it may never finish (an endless loop, or far too much work per pixel): --watchdog S gives each band S seconds${cpu ? ' of CPU time' : ''}`
  );
}
