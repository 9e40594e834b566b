// The command line's watchdog, judged here, on the Node side: a band of a frame that has cost the
// browser's GPU process the limit in work (gpu-time.js: its CPU time, on a CPU renderer) without
// ending is taken never to end. The page is asked how far it has got (view.js every 0.1 s,
// long-work.js every 0.25 s); each answer names the band the GPU is on (render-client.js's serial
// number), and the count starts again whenever that changes. A page that does not answer (its
// own thread held by a GPU process stuck in a draw) is judged all the same: the GPU process's
// work goes on being counted from the last band heard of.
//
// Why not the wall clock: a busy machine (other browsers, a build) gave a shader that finishes a
// fraction of the CPU, and a band of it took 5 s of the wall clock; a stopped or suspended
// process took any time at all. The page's own watchdog (render-client.js) still times its
// bands on the wall clock, and still shows its note in the studio; a headless run does not fail
// on its word, only on this one's.

/**
 * How long a band may go without ending, in the clock's ms: `hangMs` for a band, `compileHangMs`
 * for a program's first draw, which compiles it (src/headless/watchdog/limits.js has them per renderer).
 * @typedef {{hangMs: number, compileHangMs: number}} ProgressLimits
 */

/**
 * What an answer of the page says of the band the GPU is on: the band (null: none), and the
 * bands of the frame drawn so far.
 * @typedef {{band: {compiling: boolean, serial?: number} | null, bands: number}} BandState
 */

export class BandWatch {
  /**
   * @param {ProgressLimits} limits
   * @param {import('./gpu-time.js').WorkClock} clock
   */
  constructor(limits, clock) {
    this.limits = limits;
    this.clock = clock;
    /** The band last heard of (its serial; null: none). @type {number | null | undefined} */
    this._band = undefined;
    /** The clock when it was first heard of. */
    this._since = clock.now();
    /** Whether it is, or the next may be, a program's first draw (none heard of yet: it may). */
    this._compiling = true;
  }

  /**
   * The page answered with `state`: a band other than the last one starts the count again.
   * @param {BandState} state
   */
  heard({ band, bands }) {
    const serial = band ? (band.serial ?? -1) : null;
    // with no band in flight, the next one of a frame that has drawn none may be a compile
    this._compiling = band ? band.compiling : bands === 0;
    if (serial === this._band) return;
    this._band = serial;
    this._since = this.clock.now();
  }

  /** The limit of the band last heard of, in the clock's ms. */
  get limit() {
    return this._compiling ? this.limits.compileHangMs : this.limits.hangMs;
  }

  /** Whether the band last heard of has cost more than its limit. */
  overdue() {
    return this.clock.now() - this._since > this.limit;
  }
}

/**
 * `asked` (a question to the page), or null as soon as `watch` finds the band overdue before the
 * answer comes (looked at every `everyMs`).
 * @template T
 * @param {Promise<T>} asked
 * @param {BandWatch} watch
 * @param {number} everyMs
 * @returns {Promise<T | null>}
 */
export async function answerUnlessOverdue(asked, watch, everyMs) {
  let timer;
  const overdue = new Promise((resolve) => {
    const look = () => (watch.overdue() ? resolve(null) : (timer = setTimeout(look, everyMs)));
    timer = setTimeout(look, everyMs);
  });
  try {
    return await Promise.race([asked, /** @type {Promise<null>} */ (overdue)]);
  } finally {
    clearTimeout(timer);
  }
}
