// What the frame-time readout shows, measured honestly:
//
// - GPU time, from EXT_disjoint_timer_query_webgl2 where the browser has it: a TIME_ELAPSED
//   query around each frame's draw, read back frames later (results are never ready in the
//   frame that asked), discarded when the GPU says its timer was disjoint (a power-state
//   change or a context switch makes the figure meaningless).
// - The frame rate actually reached: frames drawn per second of the page's own clock
//   (performance.now() when each frame was drawn, not the animation frame's timestamp, which is
//   when the frame was due: on a slow GPU those timestamps run ahead of the drawing), over the
//   last two seconds. A frame rate is never computed from the GPU time: the page cannot draw
//   faster than its frames actually come.

const RATE_WINDOW_MS = 2000;
const MAX_PENDING_QUERIES = 8;

export class GpuTimer {
  /** @param {WebGL2RenderingContext} gl */
  constructor(gl) {
    this.gl = gl;
    this.ext = gl.getExtension('EXT_disjoint_timer_query_webgl2');
    /** @type {WebGLQuery | null} */
    this._active = null;
    /** @type {WebGLQuery[]} */
    this._pending = [];
  }

  /** Whether the browser measures GPU time here. */
  get available() {
    return Boolean(this.ext);
  }

  /** Before a frame's draw calls. */
  begin() {
    if (!this.ext || this._active || this._pending.length >= MAX_PENDING_QUERIES || this.gl.isContextLost()) return;
    const query = this.gl.createQuery();
    if (!query) return;
    this.gl.beginQuery(this.ext.TIME_ELAPSED_EXT, query);
    this._active = query;
  }

  /** After a frame's draw calls. */
  end() {
    if (!this._active) return;
    this.gl.endQuery(this.ext.TIME_ELAPSED_EXT);
    this._pending.push(this._active);
    this._active = null;
  }

  /**
   * The GPU times (ms) of the frames whose results have come in since the last call, oldest first.
   * @returns {number[]}
   */
  poll() {
    const gl = this.gl;
    if (!this.ext || gl.isContextLost()) {
      this._pending.length = 0;
      this._active = null;
      return [];
    }
    const disjoint = gl.getParameter(this.ext.GPU_DISJOINT_EXT);
    /** @type {number[]} */
    const times = [];
    while (this._pending.length && gl.getQueryParameter(this._pending[0], gl.QUERY_RESULT_AVAILABLE)) {
      const query = /** @type {WebGLQuery} */ (this._pending.shift());
      const ns = gl.getQueryParameter(query, gl.QUERY_RESULT);
      gl.deleteQuery(query);
      if (!disjoint) times.push(ns / 1e6);
    }
    return times;
  }
}

/** Frames drawn per second of the page's clock, over the last RATE_WINDOW_MS. */
export class FrameRate {
  constructor() {
    /** @type {number[]} */
    this._times = [];
  }

  /** @param {number} now performance.now() when a frame was drawn */
  add(now) {
    this._times.push(now);
    while (this._times.length > 2 && now - this._times[0] > RATE_WINDOW_MS) this._times.shift();
  }

  reset() {
    this._times.length = 0;
  }

  /** Frames per second, or null until two frames are in. */
  get fps() {
    const t = this._times;
    return t.length < 2 ? null : ((t.length - 1) * 1000) / (t[t.length - 1] - t[0]);
  }
}
