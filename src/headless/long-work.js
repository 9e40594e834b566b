// Work on a page that takes as long as it takes: a converge of thousands of samples, frame 99,999
// of a shader with buffers, a long recording. Such work cannot be one question to the page (a
// wait on the page is bounded, watch.js, and so is every call of the DevTools protocol, 180 s),
// so it is started on the page and then asked after, a short question at a time (client.js
// startLong, pollLong): the watchdog (band-watch.js: a band of a frame that costs the GPU process
// more than the limit) is its only limit, and each answer gives the progress a terminal shows.

import { BandWatch, answerUnlessOverdue } from './watchdog/band-watch.js';
import { WALL_CLOCK } from './watchdog/gpu-time.js';

/** How often the page is asked how far the work has got. */
const POLL_MS = 250;

/**
 * Runs `method` of window.shaderEngine with `request` on the page of `client` until it settles, and
 * returns its value. `progress` is called after each ask with the work's count so far
 * (window.shaderEngine's `progressOf` reading: 'recording' for record and frameAt, 'stillFrames'
 * for a converge). A converge is of the picture alone (its form's on-screen overlays off).
 * Rejects with the page's error, or with `hung` set when the watchdog gave up on the shader:
 * with `limits` (the command line's watchdog), a band that costs more than they allow on `clock`
 * (view.js drawView), whether or not the page still answers; without, the page's own watchdog.
 * @param {import('./client.js').EngineClient} client
 * @param {{method: import('./client.js').LongMethod, request: any, total: number,
 *   progress?: (done: number, total: number) => void,
 *   limits?: import('./view.js').ProgressLimits | null, clock?: import('./watchdog/gpu-time.js').WorkClock}} work
 */
export async function runLong(client, { method, request, total, progress = () => {}, limits = null, clock = WALL_CLOCK }) {
  await client.startLong(method, { request, total });
  const watch = limits ? new BandWatch(limits, clock) : null;
  const hung = (/** @type {string} */ said) =>
    Object.assign(new Error(`the watchdog gave up on the shader${said ? ` ("${said}")` : ''}`), { hung: true });
  for (;;) {
    const asked = client.pollLong(method, total);
    asked.catch(() => {}); // an ask given up on below fails when the page is closed
    const poll = watch ? await answerUnlessOverdue(asked, watch, POLL_MS) : await asked;
    if (poll === null) throw hung('');
    if (poll.state === 'done') return poll.value;
    if (poll.state === 'failed') throw new Error(poll.error);
    if (watch) {
      watch.heard(poll);
      if (watch.overdue()) throw hung('');
    } else if (poll.hang !== null) throw hung(poll.hang);
    progress(poll.done, poll.total);
    await new Promise((resolve) => setTimeout(resolve, POLL_MS));
  }
}
