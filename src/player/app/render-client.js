// The page's side of the render worker (gpu/render-worker.js): transport only. It asks the
// worker (requests, answered once) and tells it (commands), as gpu/protocol.js types them, and
// passes on what the worker reports unprompted: a band finished ('band'), the context lost or
// restored ('context'). What it keeps is what transport needs: the requests in flight, whether
// the context is lost, the GPU's largest side and name (from the worker's start), and the
// watchdog. Everything the page draws with (the shader, the channels, the size) has its owner
// in the app.
//
// The watchdog: the worker says when it hands a band to the GPU and when the GPU has finished
// it. A band still unfinished after TIMEOUTS.hangMs means the shader may never finish (an
// endless loop, or far too much work for one band): 'hang' is emitted with the seconds, and
// with null once the band ends after all. A program's first draw is where SwiftShader compiles
// it (render-worker.js draws one quad of it as a band of its own, marked compiling): that band is
// reported as compiling (a large shader takes seconds), and as a hang only after
// TIMEOUTS.compileHangMs. (The compile request itself, which links, is not watched: it is the
// worker's own work, and one waiting for the GPU waits behind a band, which is.)

import { Emitter } from './events.js';
import { fromWire, transferables } from '../gpu/protocol.js';
import { WebGL2UnavailableError } from '../gpu/errors.js';
import { TIMEOUTS } from '../../shared/timeouts.js';

/** @typedef {import('../gpu/protocol.js').Requests} Requests */
/** @typedef {import('../gpu/protocol.js').Commands} Commands */
/** @typedef {import('../gpu/protocol.js').Events} Events */
/** @typedef {import('../gpu/protocol.js').Message} Message */

/**
 * What the client reports.
 * @typedef {object} ClientEvents
 * @property {[band: Events['band']]} band the GPU finished a band (with a bitmap now and then)
 * @property {[lost: boolean]} context the worker's context was lost (true) or restored (false)
 * @property {[seconds: number | null, phase?: HangPhase]} hang a band has gone that long
 *   unfinished; null when bands come again
 */

/**
 * What a band that has gone long unfinished is doing: 'compiling' (a program's first draw, not
 * yet past TIMEOUTS.compileHangMs) or 'drawing' (it may never finish).
 * @typedef {'compiling' | 'drawing'} HangPhase
 */
/** How often the watchdog looks. */
const WATCH_EVERY_MS = 250;

/** @extends {Emitter<ClientEvents>} */
export class RenderClient extends Emitter {
  /**
   * Starts a render worker; resolves once it has a WebGL2 context. Rejects with
   * WebGL2UnavailableError when there is none.
   * @returns {Promise<RenderClient>}
   */
  static async start() {
    const client = new RenderClient();
    await client._spawn();
    return client;
  }

  constructor() {
    super();
    /** @type {Worker | null} */
    this.worker = null;
    /** The largest drawing-buffer side the GPU takes (0 while unknown). */
    this.maxSize = 0;
    /** @type {Record<string, string>} */
    this._info = {};
    this.contextLost = false;
    this._serial = 0;
    /** Requests in flight, by id. @type {Map<number, {resolve: (value: any) => void, reject: (error: Error) => void}>} */
    this._pending = new Map();
    /** performance.now() when the band the GPU is drawing was handed to it; null when none is. @type {number | null} */
    this._bandSince = null;
    /** Whether the band the GPU is drawing is a program's first draw (it compiles). */
    this._bandCompiling = false;
    /** Bands handed to the GPU since the page started: which band it is on, for a watchdog outside the page. */
    this._bandSerial = 0;
    /** What the last 'hang' said (null: no band has gone long unfinished). @type {HangPhase | null} */
    this._hung = null;
    this._watch = 0;
    /** Settles the worker's start. @type {{resolve: () => void, reject: (error: Error) => void} | null} */
    this._started = null;
    /** ImageBitmaps received from this worker, in all (its 'settled' command counts them). */
    this._bitmaps = 0;
    /** What the loop guard does with a cut (protocol.js 'loopGuard'): told to every worker started. */
    this._loopGuard = { stopOnCut: false, guard: true };
  }

  /**
   * Whether a frame in which llvmpipe's loop limit cut a loop stops there (the command line
   * draws it again with SwiftShader) or is drawn whole; kept for the workers started after.
   * @param {{stopOnCut: boolean, guard: boolean}} setting
   */
  setLoopGuard(setting) {
    this._loopGuard = { ...setting };
    this.tell('loopGuard', this._loopGuard);
  }

  async _spawn() {
    const worker = new Worker(new URL('../gpu/render-worker.js', import.meta.url), { type: 'module' });
    this.worker = worker;
    this._bitmaps = 0;
    /** @type {Promise<void>} */
    const started = new Promise((resolve, reject) => {
      this._started = { resolve, reject };
    });
    worker.onmessage = ({ data }) => this._receive(data);
    worker.onerror = (event) => {
      event.preventDefault();
      this._started?.reject(new Error(`the render worker failed: ${event.message}`));
    };
    this.tell('init', {});
    this.tell('loopGuard', this._loopGuard);
    const timer = window.setTimeout(
      () => this._started?.reject(new Error(`the render worker did not start within ${TIMEOUTS.workerStartMs / 1000} s`)),
      TIMEOUTS.workerStartMs,
    );
    try {
      await started;
    } finally {
      window.clearTimeout(timer);
    }
    window.clearInterval(this._watch);
    this._watch = window.setInterval(() => this._checkHang(), WATCH_EVERY_MS);
  }

  /**
   * Stops the worker, whatever it is doing, and starts a new one (no shader, no channels: the
   * app gives it those again). After a hang: on a real GPU the browser resets the GPU, and a new
   * context draws again; on SwiftShader the endless draw goes on, and so does the wait.
   */
  async respawn() {
    this.worker?.terminate();
    for (const { reject } of this._pending.values()) reject(new Error('the render worker was restarted'));
    this._pending.clear();
    this._bandSince = null;
    await this._spawn(); // rejects when the GPU does not answer a new worker either: still hung
    this._recover();
  }

  /** @param {Message} message */
  _receive(message) {
    this._bitmaps += transferables(message.kind === 'reply' ? message.result : message.params).filter(
      (item) => item instanceof ImageBitmap,
    ).length;
    this._dispatch(message);
  }

  /**
   * The worker holds a new program's first draws until the page has painted the bitmaps it was
   * sent (gpu/bands/paint-gate.js: painting a bitmap waits for the GPU process, which an endless draw
   * holds for good), and waits as long as it takes: the page always answers. What the page has
   * received by now has been given to the canvas (shown, or closed); at the second animation
   * frame from now it has been painted. A hidden page paints nothing and gets no animation
   * frames (a background tab): it answers at once, or as soon as it is hidden.
   */
  _settleAfterPaint() {
    const worker = this.worker;
    const count = this._bitmaps;
    let answered = false;
    const answer = () => {
      if (answered) return;
      answered = true;
      document.removeEventListener('visibilitychange', answerIfHidden);
      if (this.worker === worker) this.tell('settled', { bitmaps: count });
    };
    const answerIfHidden = () => {
      if (document.visibilityState === 'hidden') answer();
    };
    answerIfHidden();
    if (answered) return;
    document.addEventListener('visibilitychange', answerIfHidden);
    requestAnimationFrame(() => requestAnimationFrame(answer));
  }

  /** @param {Message} message */
  _dispatch(message) {
    if (message.kind === 'reply') {
      const pending = this._pending.get(message.id);
      if (!pending) return;
      this._pending.delete(message.id);
      if (message.error) pending.reject(fromWire(message.error));
      else pending.resolve(message.result);
      return;
    }
    if (message.kind !== 'event') throw new Error(`render client: a ${message.kind} message from the worker`);
    const { type, params } = message;
    if (type === 'ready') {
      this.maxSize = params.maxSize;
      this._info = params.info;
      this._started?.resolve();
    } else if (type === 'failed') {
      this._started?.reject(params.name === 'WebGL2UnavailableError' ? new WebGL2UnavailableError() : new Error(params.message));
    } else if (type === 'context') {
      this.contextLost = params.lost;
      this._bandEnded();
      this.emit('context', params.lost);
    } else if (type === 'awaitingPaint') {
      this._settleAfterPaint();
    } else if (type === 'bandStarted') {
      this._bandSince = performance.now();
      this._bandCompiling = params.compiling;
      this._bandSerial++;
    } else if (type === 'band') {
      this._bandEnded();
      this.emit('band', params);
    }
  }

  /**
   * Asks the worker; resolves with its reply's result, rejects with its error.
   * @template {keyof Requests} K
   * @param {K} type
   * @param {Requests[K][0]} params
   * @returns {Promise<Requests[K][1]>}
   */
  ask(type, params) {
    const id = ++this._serial;
    return new Promise((resolve, reject) => {
      this._pending.set(id, { resolve, reject });
      this._spawned().postMessage({ kind: 'request', id, type, params }, transferables(params));
    });
  }

  /**
   * Tells the worker, no answer.
   * @template {keyof Commands} K
   * @param {K} type
   * @param {Commands[K]} params
   */
  tell(type, params) {
    this._spawned().postMessage({ kind: 'command', type, params }, transferables(params));
  }

  /** The worker: start() spawns it before anything is asked or told. */
  _spawned() {
    if (!this.worker) throw new Error('the render worker has not started');
    return this.worker;
  }

  // ---- the watchdog ----------------------------------------------------------------------------

  /** A band has ended (or the context went with it). */
  _bandEnded() {
    this._bandSince = null;
    this._recover();
  }

  _recover() {
    if (!this._hung) return;
    this._hung = null;
    this.emit('hang', null);
  }

  _checkHang() {
    if (this._bandSince === null || this.contextLost) return;
    const quiet = performance.now() - this._bandSince;
    if (quiet < TIMEOUTS.hangMs) return;
    /** @type {HangPhase} */
    const phase = this._bandCompiling && quiet < TIMEOUTS.compileHangMs ? 'compiling' : 'drawing';
    this._hung = phase;
    this.emit('hang', quiet / 1000, phase);
  }

  /**
   * The band the GPU is on now: how long it has been on it, whether it is a program's first draw
   * (a compile), and its serial number (the command line's watchdog counts the GPU process's work
   * from the moment it changes: src/headless/watchdog/band-watch.js); null when it is on none, or the context
   * is lost.
   * @returns {{seconds: number, compiling: boolean, serial: number} | null}
   */
  get band() {
    if (this._bandSince === null || this.contextLost) return null;
    return { seconds: (performance.now() - this._bandSince) / 1000, compiling: this._bandCompiling, serial: this._bandSerial };
  }

  /** Whether a band has gone TIMEOUTS.hangMs unfinished, and what it is doing then (null: none has). */
  get hung() {
    return this._hung;
  }

  /** What GPU and driver we run on. */
  info() {
    return { ...this._info };
  }
}
