// Work on a page that takes as long as it takes: a converge of thousands of samples, frame 99,999
// of a shader with buffers, a long recording. Such work cannot be one page.evaluate (a wait on
// the page is bounded, watch.js, and so is every call of the DevTools protocol, 180 s), so it is
// started on the page and then asked after, a short evaluate at a time: the page's watchdog (a
// band of a frame unfinished for the watchdog's time: data-hung) is its only limit, and each
// answer gives the progress a terminal shows.

/** How often the page is asked how far the work has got. */
const POLL_MS = 250;

/**
 * What one ask returns: `done` with the work's value or error, or how far it has got, or that
 * the page's watchdog gave up on the shader (`hung`, with the message the page shows).
 * @typedef {{state: 'done', value: any} | {state: 'failed', error: string}
 *   | {state: 'hung', message: string} | {state: 'running', done: number, total: number}} Poll
 */

/**
 * Runs `method` of window.raytracer with `request` on `page` until it settles, and returns its
 * value. `progress` is called after each ask with the work's count so far (window.raytracer's
 * `progressOf` reading: 'recording' for record and frameAt, 'stillFrames' for a converge).
 * Rejects with the page's error, or with `hung` set when the watchdog gave up on the shader.
 * @param {import('puppeteer-core').Page} page
 * With `limits` (the command line's watchdog, view.js), a page that leaves an ask unanswered for
 * longer than a program's first draw may take has hung too: its own thread is held, and its
 * watchdog cannot speak.
 * @param {{method: 'record' | 'frameAt' | 'converge', request: any, total: number,
 *   progress?: (done: number, total: number) => void, limits?: import('./view.js').ProgressLimits | null}} work
 */
export async function runLong(page, { method, request, total, progress = () => {}, limits = null }) {
  await page.evaluate(
    (m, r, t) => {
      const hook = /** @type {any} */ (window.raytracer);
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
              .setConverging(true, { frames: t })
              .then(() => hook.setControls({ SHOW_SAMPLE_COUNT: 0 }))
              .then(constants)
              .then(() => hook.restart())
          : hook[m](r);
      started.then(
        (value) => (slot.settled = m === 'converge' ? { state: 'started' } : { state: 'done', value }),
        (error) => (slot.settled = { state: 'failed', error: String(error?.message ?? error) }),
      );
    },
    method,
    request,
    total,
  );
  for (;;) {
    /** @type {Promise<Poll | {state: 'started'}>} */
    const asked = page.evaluate(
      (m, t) => {
        const hook = /** @type {any} */ (window.raytracer);
        const settled = /** @type {any} */ (window).__longWork.settled;
        if (document.documentElement.dataset.hung === 'true') {
          const alert = document.querySelector('[role="alert"]')?.textContent?.trim().replace(/\s+/g, ' ') ?? '';
          return { state: 'hung', message: alert };
        }
        if (m === 'converge') {
          if (settled?.state === 'failed') return settled;
          const { stillFrames } = hook.info();
          if (settled && stillFrames >= t) return { state: 'done', value: null };
          return { state: 'running', done: settled ? Math.min(stillFrames, t) : 0, total: t };
        }
        if (settled) return settled;
        const { done, total } = hook.recording();
        return { state: 'running', done, total: total || t };
      },
      method,
      total,
    );
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
