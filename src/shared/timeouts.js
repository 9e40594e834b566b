// How long the page waits before it says that something is wrong, in one place. A test harness
// shortens them (it must not wait out a production timeout) by defining
// window.__shaderEngineTimeouts before the page's scripts run (tests/support/page.js); the page
// never reads them from its URL, so a link cannot change them. tests/unit/timeouts.test.js holds the
// production values.

/**
 * @typedef {object} Timeouts
 * @property {number} loadMs a shader or image fetched from the page's server gets this long to
 *   arrive (io/shader-loader.js). A file of the page's own server arrives in well under a
 *   second; 15 s leaves room for a slow network or a server waking up, and ends what would
 *   otherwise be a black page, with no message, for as long as the server keeps the request open
 * @property {number} hangMs a band of a frame unfinished for this long: the shader may never
 *   finish (app/render-client.js). A band is sized to take ~0.1 s (gpu/bands/band-planner.js).
 *   The page's watchdog counts the wall clock; the command line's counts the same limits in the
 *   GPU process's CPU time (src/headless/watchdog/band-watch.js), and does not fail on the page's word
 * @property {number} compileHangMs a program's first draw, in which SwiftShader compiles it,
 *   unfinished for this long: it may never finish (the raytracer's heaviest scene compiles in
 *   3.5 s; a large shader from Shadertoy took ~15 s on this machine)
 * @property {number} workerStartMs a render worker that has not said whether it has a context
 *   by then has failed to start (after a hang: the GPU is still held)
 */

/** @type {Readonly<Timeouts>} */
export const PRODUCTION_TIMEOUTS = Object.freeze({ loadMs: 15_000, hangMs: 5_000, compileHangMs: 30_000, workerStartMs: 20_000 });

/**
 * The timeouts in force: the production ones, with what a harness set before the page loaded.
 * @param {Partial<Timeouts> | undefined} [overrides]
 * @returns {Readonly<Timeouts>}
 */
export function timeoutsWith(overrides) {
  const chosen = { ...PRODUCTION_TIMEOUTS };
  for (const [name, value] of Object.entries(overrides ?? {}))
    if (name in chosen && Number.isFinite(value) && value > 0) chosen[/** @type {keyof Timeouts} */ (name)] = value;
  return Object.freeze(chosen);
}

/** @type {Readonly<Timeouts>} */
export const TIMEOUTS = timeoutsWith(/** @type {any} */ (globalThis).__shaderEngineTimeouts);
