// Work on a page that takes as long as it takes: a converge of thousands of samples, frame 99,999
// of a shader with buffers, a long recording. Such work cannot be one question to the page (a
// wait on the page is bounded, watch.js, and so is every call of the DevTools protocol, 180 s),
// so it is started on the page and then asked after, a short question at a time (client.js
// startLong, pollLong): the page's watchdog (a band of a frame unfinished for the watchdog's
// time) is its only limit, and each answer gives the progress a terminal shows.

/** How often the page is asked how far the work has got. */
const POLL_MS = 250;

/**
 * Runs `method` of window.shaderEngine with `request` on the page of `client` until it settles, and
 * returns its value. `progress` is called after each ask with the work's count so far
 * (window.shaderEngine's `progressOf` reading: 'recording' for record and frameAt, 'stillFrames'
 * for a converge). A converge sets the live `controls` it is given first (the raytracer's
 * sample-count overlay off: the caller knows its shader). Rejects with the page's error, or with
 * `hung` set when the watchdog gave up on the shader. With `limits` (the command line's watchdog, view.js), a page that leaves an ask unanswered for
 * longer than a program's first draw may take has hung too: its own thread is held, and its
 * watchdog cannot speak.
 * @param {import('./client.js').EngineClient} client
 * @param {{method: import('./client.js').LongMethod, request: any, total: number,
 *   controls?: Record<string, number>, progress?: (done: number, total: number) => void,
 *   limits?: import('./view.js').ProgressLimits | null}} work
 */
export async function runLong(client, { method, request, total, controls = {}, progress = () => {}, limits = null }) {
  await client.startLong(method, { request, total, controls });
  for (;;) {
    const asked = client.pollLong(method, total);
    asked.catch(() => {}); // an ask given up on below fails when the page is closed
    let timer;
    const poll = await (limits
      ? Promise.race([asked, new Promise((resolve) => (timer = setTimeout(resolve, limits.compileHangMs, null)))])
      : asked);
    clearTimeout(timer);
    if (poll === null) throw Object.assign(new Error('the page stopped answering while it drew'), { hung: true });
    if (poll.state === 'done') return poll.value;
    if (poll.state === 'failed') throw new Error(poll.error);
    if (poll.state === 'hung')
      throw Object.assign(new Error(`the watchdog gave up on the shader${poll.message ? ` ("${poll.message}")` : ''}`), { hung: true });
    if (poll.state === 'running') progress(poll.done, poll.total);
    await new Promise((resolve) => setTimeout(resolve, POLL_MS));
  }
}
