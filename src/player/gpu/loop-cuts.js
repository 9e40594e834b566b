// What llvmpipe's loop limit cut short, pass by pass (src/shadertoy/loop-guard.js says why and
// how a pass is guarded). On llvmpipe each pass with loops is drawn in its guarded form, which
// writes a second output beside its colour: red where a loop of the pixel was stopped by the
// limit. That output goes into one texture of this module's (RGBA8, as large as the largest
// target drawn), attached to whatever target the pass draws into, for that draw alone. The
// texture is all zero between draws: after each band the rows it drew are read back (the band's
// fence has passed, so nothing waits), and cleared again where a cut was found. What was found
// is kept as a log until the page asks for it (the command line, after each view).
//
// The GL calls made here behind three.js's back leave its state as they found it: the bindings
// they change (a texture, the read framebuffer, the draw buffers of the target bound) are put
// back, so three.js's cache of that state stays true.

/**
 * What the limit cut in one pass: in how many pixel draws in all (a pixel of every frame it was
 * cut in counts), in how many frames, and the first: its frame (iFrame; for the Sound tab the
 * block), its pixel (x, y from the bottom left of the pass's target, or of a Cube A face), and
 * for the Sound tab its sample.
 * @typedef {{pass: string, pixels: number, frames: number, first: {frame: number, x: number, y: number, sample?: number}}} LoopCut
 */

/**
 * A pass that could not be checked: it has loops, and its guarded form could not be made or
 * did not compile (`reason`), so it is drawn as it is and llvmpipe may cut it unseen.
 * @typedef {{pass: string, reason: string}} UncheckedPass
 */

/**
 * The region of the last guarded draw, not yet read; `samples`: a Sound block's first sample
 * (its pixels are samples, row by row).
 * @typedef {{x: number, y: number, width: number, height: number, pass: string, frame: number, samples?: number}} Pending
 */

import { LLVMPIPE_LOOP_LIMIT } from '../../shadertoy/loop-guard.js';

export class LoopCuts {
  /** @param {WebGL2RenderingContext} gl */
  constructor(gl) {
    this.gl = gl;
    /** Whether this is llvmpipe, the only renderer with the limit. */
    this.onLlvmpipe = /llvmpipe/i.test(rendererName(gl));
    /** Whether passes compiled from now on are guarded: on llvmpipe (off only to time the guard). */
    this.enabled = this.onLlvmpipe;
    /** Whether a frame stops at its first band with a cut (its picture is not kept then). */
    this.stopOnCut = false;
    /** @type {WebGLTexture | null} */
    this.texture = null;
    /** @type {WebGLFramebuffer | null} */
    this.framebuffer = null;
    this.width = 0;
    this.height = 0;
    /** @type {Pending | null} */
    this.pending = null;
    /** @type {Map<string, LoopCut & {frameSet: Set<number>}>} */
    this.cuts = new Map();
    /** @type {Map<string, UncheckedPass>} */
    this.unchecked = new Map();
  }

  /**
   * Draws with `draw()` into the target bound now, the guard attached when `material` is a
   * guarded pass (material.userData.loopGuard, set by pass-compiler.js): the rows [y, y + height)
   * and columns [x, x + width) of `pass`'s target, for frame `frame`.
   * @param {{userData: Record<string, any>}} material
   * @param {Pending & {targetWidth: number, targetHeight: number}} region
   * @param {() => void} draw
   */
  around(material, region, draw) {
    if (!material.userData.loopGuard) {
      draw();
      return;
    }
    // a draw whose band was never waited for (the benchmark's frames) is read now: the texture
    // must be zero again before the next
    if (this.pending) this.collect();
    const gl = this.gl;
    this._fit(region.targetWidth, region.targetHeight);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT1, gl.TEXTURE_2D, this.texture, 0);
    gl.drawBuffers([gl.COLOR_ATTACHMENT0, gl.COLOR_ATTACHMENT1]);
    try {
      draw();
    } finally {
      gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT1, gl.TEXTURE_2D, null, 0);
      gl.drawBuffers([gl.COLOR_ATTACHMENT0]);
    }
    // a draw of no pixel (a program's first, which compiles it) is guarded too: llvmpipe compiles
    // a program for the targets it draws into, and the bands after it draw into two
    const { x, y, width, height, pass, frame, samples } = region;
    if (width > 0 && height > 0) this.pending = { x, y, width, height, pass, frame, samples };
  }

  /**
   * Reads what the last guarded draw found (call it once its band's fence has passed): whether a
   * loop was cut in it. Adds it to the log.
   */
  collect() {
    const pending = this.pending;
    this.pending = null;
    if (!pending || !this.framebuffer) return false;
    const gl = this.gl;
    const { x, y, width, height, pass, frame, samples } = pending;
    const pixels = new Uint8Array(width * height * 4);
    const bound = gl.getParameter(gl.READ_FRAMEBUFFER_BINDING);
    gl.bindFramebuffer(gl.READ_FRAMEBUFFER, this.framebuffer);
    gl.readPixels(x, y, width, height, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
    gl.bindFramebuffer(gl.READ_FRAMEBUFFER, bound);
    let count = 0;
    let first = -1;
    for (let i = 0; i < pixels.length; i += 4)
      if (pixels[i] !== 0) {
        count++;
        if (first < 0) first = i / 4;
      }
    if (count === 0) return false;
    this._clear();
    /** @type {LoopCut['first']} */
    const at = { frame, x: x + (first % width), y: y + Math.floor(first / width) };
    if (samples !== undefined) at.sample = samples + at.y * width + at.x;
    const cut = this.cuts.get(pass) ?? { pass, pixels: 0, frames: 0, frameSet: new Set(), first: at };
    cut.pixels += count;
    cut.frameSet.add(frame);
    cut.frames = cut.frameSet.size;
    this.cuts.set(pass, cut);
    return true;
  }

  /** A pass with loops drawn unguarded, and why. @param {string} pass @param {string} reason */
  uncheckable(pass, reason) {
    this.unchecked.set(pass, { pass, reason });
  }

  /** A pass compiled guarded again: it is checked now. @param {string} pass */
  checkable(pass) {
    this.unchecked.delete(pass);
  }

  /**
   * The log: what was cut since the last reset, and the passes drawn unchecked (of the shader
   * compiled last).
   * @param {boolean} reset start a new log (the cuts; the unchecked passes stay with their shader)
   * @returns {import('./protocol.js').LoopReport}
   */
  report(reset) {
    const cuts = [...this.cuts.values()].map(({ frameSet, ...cut }) => ({ ...cut, first: { ...cut.first } }));
    if (reset) this.cuts.clear();
    return { enabled: this.enabled, limit: LLVMPIPE_LOOP_LIMIT, cuts, unchecked: [...this.unchecked.values()] };
  }

  /** The context was lost: its texture and framebuffer with it. */
  forget() {
    this.texture = null;
    this.framebuffer = null;
    this.width = 0;
    this.height = 0;
    this.pending = null;
  }

  /** Makes the texture at least width × height (zero throughout when made). */
  _fit(width, height) {
    if (this.texture && width <= this.width && height <= this.height) return;
    const gl = this.gl;
    const w = Math.max(width, this.width);
    const h = Math.max(height, this.height);
    if (this.texture) gl.deleteTexture(this.texture);
    if (this.framebuffer) gl.deleteFramebuffer(this.framebuffer);
    const texture = gl.createTexture();
    const unbound = gl.getParameter(gl.TEXTURE_BINDING_2D);
    gl.bindTexture(gl.TEXTURE_2D, texture);
    gl.texStorage2D(gl.TEXTURE_2D, 1, gl.RGBA8, w, h);
    gl.bindTexture(gl.TEXTURE_2D, unbound);
    this.texture = texture;
    this.framebuffer = gl.createFramebuffer();
    this.width = w;
    this.height = h;
    const bound = gl.getParameter(gl.READ_FRAMEBUFFER_BINDING);
    gl.bindFramebuffer(gl.READ_FRAMEBUFFER, this.framebuffer);
    gl.framebufferTexture2D(gl.READ_FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, texture, 0);
    gl.bindFramebuffer(gl.READ_FRAMEBUFFER, bound);
    this._clear();
  }

  /** Zero throughout, whatever the scissor. */
  _clear() {
    const gl = this.gl;
    const drawBound = gl.getParameter(gl.DRAW_FRAMEBUFFER_BINDING);
    const scissored = gl.isEnabled(gl.SCISSOR_TEST);
    gl.bindFramebuffer(gl.DRAW_FRAMEBUFFER, this.framebuffer);
    if (scissored) gl.disable(gl.SCISSOR_TEST);
    gl.clearBufferfv(gl.COLOR, 0, [0, 0, 0, 0]);
    if (scissored) gl.enable(gl.SCISSOR_TEST);
    gl.bindFramebuffer(gl.DRAW_FRAMEBUFFER, drawBound);
  }
}

/** The driver's renderer string (llvmpipe names itself there, through ANGLE too). @param {WebGL2RenderingContext} gl */
function rendererName(gl) {
  const debug = gl.getExtension('WEBGL_debug_renderer_info');
  return String(gl.getParameter(debug ? debug.UNMASKED_RENDERER_WEBGL : gl.RENDERER));
}
