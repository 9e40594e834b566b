// The GPU time of each frame the render worker draws, for the page's frame-time readout
// (ui/toolbar/frame-readout.js), where the browser has EXT_disjoint_timer_query_webgl2: a TIME_ELAPSED
// query around each frame's draws, read back frames later (results are never ready in the frame
// that asked), discarded when the GPU says its timer was disjoint (a power-state change or a
// context switch makes the figure meaningless). The times travel to the page with each frame
// drawn (protocol.js: DrawnFrame.gpuTimes).

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
