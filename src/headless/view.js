// One view of the page drawn and read back: the step that every picture of this project goes
// through, the page tests' (tests/support/page.js renderView), the scripts' and the command
// line's (src/api/render.js, which draws the goldens too: tests/support/goldens.js). A view is a query of the page's URL contract
// (src/shared/url-params.js: ?shader=…&size=…&time=…&NAME=value); a fresh page loads it, a page
// that is already loaded is brought to it by window.shaderEngine.open(), which gives what a fresh
// load gives (tests/browser/page-open.test.js).

/**
 * What drawView found: the frame's pixels (base64 RGBA8, rows top to bottom) and their iFrame (0:
 * a still is the view's first frame), what the page said of itself and its notes (PageNote), or `error` (why there is no frame) with `hung` when the
 * watchdog gave up on the shader (it may never finish) and `compile` when it did not compile.
 * @typedef {{pixels: {width: number, height: number, data: string}, iFrame: number, frame: number, info: any,
 *   notes: {kind: 'missing' | 'values', title: string, lines: string[]}[], pageError: string | undefined, error?: undefined}
 *   | {error: string, hung?: boolean, compile?: boolean}} DrawnView
 */

/**
 * A note the page shows beside the picture, a title and its lines: what a shader went without
 * (kind 'missing', the page's load-notes: media, passes), or values not used as given ('values':
 * a control clamped into range), which a person sees on the page and the command line prints.
 * @typedef {{kind: 'missing' | 'values', title: string, lines: string[]}} PageNote
 */

/**
 * The command line's watchdog (src/headless/watchdog/limits.js), judged here (band-watch.js): a band that has
 * cost the GPU process more than the limit in work (`compileHangMs` for a program's first draw,
 * `hangMs` else) without ending has hung, whether or not the page still answers. A page whose
 * own thread is held by the GPU (a canvas waiting on a GPU process stuck in an endless draw) can
 * no longer run its own watchdog, nor answer; this one counts on.
 * @typedef {import('./watchdog/band-watch.js').ProgressLimits} ProgressLimits
 */

import { BandWatch, answerUnlessOverdue } from './watchdog/band-watch.js';
import { WALL_CLOCK } from './watchdog/gpu-time.js';

/** How often the page is asked how far the view has got. */
const POLL_MS = 100;

/**
 * How far a view has got: `rows` of `height` drawn of the pass under way, `bands` so far, and the
 * band the GPU is on (its `seconds`, and whether it is a program's first draw: `compiling`).
 * @typedef {{rows: number, height: number, bands: number, band: {seconds: number, compiling: boolean, serial?: number} | null}} ViewProgress
 */

/**
 * Brings the page of `client` to the view `query` and reads one frame. `fresh`: the page is
 * loaded at baseUrl + query (else it is a loaded page, and open() brings it there). The page is
 * asked how far it has got every POLL_MS. With `limits`, a band that costs more than they allow
 * on `clock` (the GPU process's work: gpu-time.js; the wall clock by default) is a hang (`hung`),
 * whether or not the page still answers, and the page's own watchdog is not heeded; without,
 * the page's is. `progress` hears each answer.
 * @param {import('./client.js').EngineClient} client
 * @param {{baseUrl: string, query: string, fresh: boolean, limits?: ProgressLimits | null,
 *   clock?: import('./watchdog/gpu-time.js').WorkClock, progress?: (state: ViewProgress) => void}} view
 * @returns {Promise<DrawnView>}
 */
export async function drawView(client, { baseUrl, query, fresh, limits = null, clock = WALL_CLOCK, progress = () => {} }) {
  if (fresh) {
    const failed = await client.load(baseUrl + query);
    if (failed !== null) return { error: failed };
  }
  const started = await client.startView(fresh ? null : query);
  if (started !== null) return { error: started };
  const outcome = await waitForView(client, limits ? new BandWatch(limits, clock) : null, progress);
  if (outcome.state === 'failed') return { error: outcome.error, compile: outcome.compile };
  if (outcome.state === 'hung') return { error: outcome.error, hung: true };
  return client.readView();
}

/**
 * Asks the page after the view drawView started until it is drawn, failed, or hung: with a
 * `watch`, its band cost more than the limit (answered or not); without, the page's own watchdog
 * gave up on it.
 * @param {import('./client.js').EngineClient} client
 * @param {BandWatch | null} watch
 * @param {(state: ViewProgress) => void} progress
 * @returns {Promise<{state: 'drawn'} | {state: 'failed', error: string, compile: boolean} | {state: 'hung', error: string}>}
 */
async function waitForView(client, watch, progress) {
  const hung = (/** @type {string} */ said) => ({
    state: /** @type {const} */ ('hung'),
    error: `the shader did not finish drawing a frame: the watchdog gave up on it${said ? ` ("${said}")` : ''}`,
  });
  for (;;) {
    const asked = client.pollView();
    asked.catch(() => {}); // a question given up on below fails when the page is closed
    const answer = watch ? await answerUnlessOverdue(asked, watch, POLL_MS) : await asked;
    if (answer === null) return hung('');
    if (answer.state === 'drawn' || answer.state === 'failed') return answer;
    if (watch) {
      watch.heard(answer);
      if (watch.overdue()) return hung('');
    } else if (answer.hang !== null) return hung(answer.hang);
    progress({ rows: answer.rows, height: answer.height, bands: answer.bands, band: answer.band });
    await new Promise((resolve) => setTimeout(resolve, POLL_MS));
  }
}
