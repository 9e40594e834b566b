// The page's side of the render worker (render-worker.js): the same questions the app asked its
// renderer, answered by messages. What the page needs to know at once (whether a shader runs,
// the drawing size, the GPU's limits, each channel's size) is kept here as the worker reports it,
// so asking never waits for the worker.
//
// It is also the page's watchdog: the worker says when it hands a band to the GPU and when the
// GPU has finished it. A band still unfinished after HANG_AFTER_MS means the shader may never
// finish (an endless loop, or far too much work for one band): `onHang(seconds)` is called, and
// `onHang(null)` once the band ends after all. (A compile is not watched: it is the worker's own
// work, and one waiting for the GPU waits behind a band, which is.)

import { ShaderCompileError, WebGL2UnavailableError } from './renderer-errors.js';

/** A band unfinished for this long: the shader may never finish. A band is sized to take ~0.1 s
 * (band-planner.js); only a shader far heavier than its first band, or one that never ends,
 * holds the GPU this long. */
export const HANG_AFTER_MS = 5000;
/** A worker that has not said whether it has a context by then has failed to start (a script
 * that did not load, a browser that cannot run module workers). */
const START_TIMEOUT_MS = 20000;
/** How often the watchdog looks. */
const WATCH_EVERY_MS = 250;

/** @typedef {import('./shadertoy-inputs.js').FrameInputs} FrameInputs */
/** @typedef {{bitmap: ImageBitmap, pixels: Uint8Array | null, gpuTimes: number[]}} DrawnFrame */

export class RenderClient {
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
    /** @type {Worker | null} */
    this.worker = null;
    this.maxSize = 0;
    /** @type {Record<string, string>} */
    this._info = {};
    /** True once some shader has compiled (the worker draws nothing before). */
    this.hasProgram = false;
    this.contextLost = false;
    /** The size of the last frame drawn. */
    this.width = 0;
    this.height = 0;
    /** [width, height] of the image in each channel. @type {number[][]} */
    this._channelSizes = [
      [0, 0],
      [0, 0],
      [0, 0],
      [0, 0],
    ];
    /** How far the frame under way has got: rows done of its height, bands drawn (null: none under way). @type {{y: number, height: number, bands: number} | null} */
    this.progress = null;
    /** GPU times of frames drawn since the last poll (frame-timer.js's GpuTimer, in the worker). @type {number[]} */
    this._gpuTimes = [];
    this.gpuTimer = { poll: () => this._gpuTimes.splice(0) };

    /** Called with a bitmap to show: each finished frame, and unfinished ones now and then. */
    this.onPicture = (/** @type {ImageBitmap} */ bitmap) => bitmap.close();
    /** Called on a lost (true) and a restored (false) context. */
    this.onContext = (/** @type {boolean} */ _lost) => {};
    /** Called with the seconds a frame has gone without a band, or null when bands come again. */
    this.onHang = (/** @type {number | null} */ _seconds) => {};

    this._serial = 0;
    /** @type {Map<number, {resolve: (value: any) => void, reject: (error: Error) => void}>} */
    this._pending = new Map();
    /** performance.now() when the band the GPU is drawing was handed to it; null when none is. @type {number | null} */
    this._bandSince = null;
    this._hung = false;
    this._watch = 0;
  }

  async _spawn() {
    const worker = new Worker(new URL('./render-worker.js', import.meta.url), { type: 'module' });
    this.worker = worker;
    const started = new Promise((resolve, reject) => {
      this._started = { resolve, reject };
    });
    worker.onmessage = ({ data }) => this._receive(data);
    worker.onerror = (event) => {
      event.preventDefault();
      this._started?.reject(new Error(`the render worker failed: ${event.message}`));
    };
    worker.postMessage({ type: 'init' });
    const timer = window.setTimeout(
      () => this._started?.reject(new Error(`the render worker did not start within ${START_TIMEOUT_MS / 1000} s`)),
      START_TIMEOUT_MS,
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
    this.hasProgram = false;
    this._bandSince = null;
    await this._spawn(); // rejects when the GPU does not answer a new worker either: still hung
    if (this._hung) this.onHang(null);
    this._hung = false;
  }

  _receive(data) {
    switch (data.type) {
      case 'ready':
        this.maxSize = data.maxSize;
        this._info = data.info;
        this._started.resolve();
        return;
      case 'failed':
        this._started.reject(data.name === 'WebGL2UnavailableError' ? new WebGL2UnavailableError() : new Error(data.message));
        return;
      case 'context':
        this.contextLost = data.lost;
        if (!data.lost) this.hasProgram = false; // programs died with the context: compiled again
        this._bandEnded();
        this.onContext(data.lost);
        return;
      case 'bandStarted':
        this._bandSince = performance.now();
        return;
      case 'band':
        this._bandEnded();
        this.progress = { y: data.y, height: data.height, bands: (this.progress?.bands ?? 0) + 1 };
        if (data.bitmap) this.onPicture(data.bitmap);
        return;
      case 'drawn':
        this.progress = null;
        this._bandEnded();
        this.width = data.bitmap.width;
        this.height = data.bitmap.height;
        this._gpuTimes.push(...data.gpuTimes);
        this.onPicture(data.bitmap);
        this._settle(data.id, { pixels: data.pixels });
        return;
      case 'captured':
        this._bandEnded();
        this._settle(data.id, data.pixels);
        return;
      case 'compiled':
        if (data.error) {
          const error = data.error.messages
            ? new ShaderCompileError(data.error.report, data.error.messages)
            : new Error(data.error.message);
          this._settle(data.id, null, error);
        } else {
          this.hasProgram = true;
          this._settle(data.id, null);
        }
        return;
      case 'benched':
        this._settle(data.id, data.times);
        return;
      case 'jobFailed':
        this._bandEnded();
        this._settle(data.id, null, new Error(data.message));
        return;
      default:
        throw new Error(`render client: no message ${data.type}`);
    }
  }

  _settle(id, value, error = null) {
    const pending = this._pending.get(id);
    if (!pending) return;
    this._pending.delete(id);
    if (error) pending.reject(error);
    else pending.resolve(value);
  }

  /** Posts a request and resolves with the worker's answer to it. */
  _ask(message, transfer = []) {
    const id = ++this._serial;
    return new Promise((resolve, reject) => {
      this._pending.set(id, { resolve, reject });
      this.worker.postMessage({ ...message, id }, transfer);
    });
  }

  // ---- the watchdog ----------------------------------------------------------------------------

  /** A band has ended (or the context went with it). */
  _bandEnded() {
    this._bandSince = null;
    this._recover();
  }

  _recover() {
    if (!this._hung) return;
    this._hung = false;
    this.onHang(null);
  }

  _checkHang() {
    if (this._bandSince === null || this.contextLost) return;
    const quiet = performance.now() - this._bandSince;
    if (quiet < HANG_AFTER_MS) return;
    this._hung = true;
    this.onHang(quiet / 1000);
  }

  /** Whether a band has been drawing for HANG_AFTER_MS. */
  get hung() {
    return this._hung;
  }

  // ---- what the app asks -----------------------------------------------------------------------

  /**
   * Compiles every pass of a shader with `hostBlock` after the header. Resolves when it runs;
   * rejects with a ShaderCompileError (the last shader that compiled keeps running).
   * @param {import('../shadertoy/multipass.js').MultipassShader} project
   * @param {string} hostBlock
   * @param {string} fileName
   */
  compile(project, hostBlock, fileName) {
    return this._ask({ type: 'compile', project, hostBlock, fileName });
  }

  /** Clears every buffer of a multipass shader (Shadertoy's rewind). */
  clearBuffers() {
    this.worker.postMessage({ type: 'clearBuffers' });
  }

  setControlUniforms(controls, values) {
    this.worker.postMessage({ type: 'controlUniforms', controls, values });
  }

  setControlUniform(name, value) {
    this.worker.postMessage({ type: 'controlUniform', name, value });
  }

  /**
   * Puts an image into iChannel0..3 (null: black): a bitmap as shader-loader.js decodes it (rows
   * flipped, alpha not premultiplied). The worker gets a copy; the page keeps the original, to
   * give a new worker.
   * @param {number} index
   * @param {ImageBitmap | null} image
   */
  async setChannel(index, image) {
    const copy = image ? await createImageBitmap(image, { premultiplyAlpha: 'none', colorSpaceConversion: 'none' }) : null;
    this.worker.postMessage({ type: 'channel', index, image: copy }, copy ? [copy] : []);
    this._channelSizes[index] = image ? [image.width, image.height] : [0, 0];
  }

  /** Whether iChannel `index` holds an image (not the black default). @param {number} index */
  channelInUse(index) {
    return this._channelSizes[index][0] > 0;
  }

  /** [width, height] of the image in each channel (0, 0 when empty). */
  channelSizes() {
    return this._channelSizes.map((size) => size.slice());
  }

  /**
   * Draws a frame for the page (band by band: see render-worker.js). Resolves when it is done
   * and shown, with its pixels (rows top to bottom) when `readBack`.
   * @param {FrameInputs} inputs
   * @param {boolean} [readBack]
   * @returns {Promise<{pixels: Uint8Array | null}>}
   */
  drawFrame(inputs, readBack = false) {
    this.progress = { y: 0, height: inputs.height, bands: 0 };
    return this._ask({ type: 'frame', inputs, readBack });
  }

  /**
   * A frame drawn again off screen at width × height (iMouse scaled with it). RGBA8, rows top to
   * bottom, alpha 1.
   * @param {FrameInputs} inputs
   * @param {number} width
   * @param {number} height
   * @param {{allPasses?: boolean}} [options] allPasses: a whole frame of a multipass shader, its
   *   buffers drawn too (they move on, as in a played frame; width × height must be theirs)
   * @returns {Promise<Uint8Array>}
   */
  redraw(inputs, width, height, { allPasses = false } = {}) {
    return this._ask({ type: 'capture', inputs, width, height, allPasses });
  }

  /**
   * n whole frames, each a single draw waited for (the benchmark's measure). Resolves with their times in ms.
   * @param {FrameInputs} inputs
   * @param {number} n
   * @returns {Promise<number[]>}
   */
  bench(inputs, n) {
    return this._ask({ type: 'bench', inputs, n });
  }

  /** Loses (true) or restores (false) the worker's context through WEBGL_lose_context, for tests. */
  simulateContextLoss(lose) {
    this.worker.postMessage({ type: lose ? 'loseContext' : 'restoreContext' });
  }

  /** What GPU and driver we run on. */
  info() {
    return { ...this._info };
  }
}
