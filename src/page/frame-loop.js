// The app's frame loop (app.js: requestRender, drawFrame): when to draw and what a drawn frame
// changes. The app asks the render worker for one frame at a time, and asks for the next only
// when that one is done, so frames never queue up behind a heavy one; while playing it asks again
// at the next animation frame, while paused only on demand (a control change, a resize, the
// mouse), and while converging (converge.js) as long as the view is still, up to the app's
// convergeFrames. The frames the worker draws come back as bitmaps, shown on the app's canvas; a
// capture (a screenshot) draws the last frame again, at another size.

import { fitGpu } from './canvas-size.js';

/** @typedef {import('./app.js').RaytracerApp} RaytracerApp */

export class FrameLoop {
  /** @param {RaytracerApp} app */
  constructor(app) {
    this.app = app;
    this.raf = 0;
    /** When the last frame was drawn while playing (for the 'frame' event's frame time). @type {number | null} */
    this.lastFrameAt = null;
    /** The frame the worker is drawing. @type {Promise<unknown> | null} */
    this.drawing = null;
    /** Something changed since the frame under way was asked for: another one is due. */
    this.dirty = false;
  }

  /** Draws at the next animation frame (once, however often it is asked, and never while a frame is under way). */
  request() {
    this.dirty = true;
    this.app.stillFrames = 0;
    this.schedule();
  }

  schedule() {
    if (!this.raf && !this.drawing) this.raf = requestAnimationFrame((now) => this._tick(now));
  }

  /** Whether converging asks for another frame: while the view is still, up to convergeFrames. */
  get converging() {
    return this.app.converging && this.app.stillFrames < this.app.convergeFrames;
  }

  /** @param {number} now */
  _tick(now) {
    const app = this.app;
    this.raf = 0;
    if (this.drawing || !(this.dirty || app.inputs.playing || this.converging)) return;
    const readBack = app.readBackNext;
    app.readBackNext = false;
    this.draw(now, readBack).catch(() => {}); // a lost context: the page says so
  }

  /**
   * Draws one frame (after the one under way, if any), and resolves once it is on the canvas:
   * with its pixels (RGBA8, rows top to bottom) when `readBack`, null when no shader runs or the
   * context is lost.
   * @param {number} [now] timestamp in ms (performance.now() or a rAF time)
   * @param {boolean} [readBack]
   * @returns {Promise<{pixels: Uint8Array | null, width: number, height: number, frame: number} | null>}
   */
  async draw(now = performance.now(), readBack = false) {
    const app = this.app;
    while (this.drawing) await this.drawing.catch(() => {});
    if (app.renderer.contextLost || !app.renderer.hasProgram) return null;
    const { width, height } = app.canvasSize.target();
    this.dirty = false;
    const frame = app.inputs.beginFrame(width, height, now);
    // the keyboard texture goes to the worker (and is uploaded) only for a shader that reads it
    const inputs = app.readsKeyboard ? { ...frame, keyboard: app.keyboard.data.slice() } : frame;
    const running = app._running;
    const drawing = app.renderer.drawFrame(inputs, readBack);
    this.drawing = drawing;
    let drawn;
    try {
      drawn = await drawing;
    } finally {
      if (this.drawing === drawing) this.drawing = null;
    }
    app.inputs.endFrame();
    // "pressed this frame" is over: a shader that reads it is drawn once more without it
    if (app.keyboard.endFrame() && app.readsKeyboard) app.requestRender();
    app.framesRendered++;
    app.lastFinished = running;
    if (app.inputs.playing) {
      // the clock when the frame was drawn, not when it was due: on a slow GPU the animation
      // frames' timestamps run ahead of the drawing (frame-timer.js)
      const drawnAt = performance.now();
      if (this.lastFrameAt !== null) app.emit('frame', drawnAt - this.lastFrameAt);
      this.lastFrameAt = drawnAt;
    } else {
      this.lastFrameAt = null;
    }
    const result = { pixels: drawn.pixels, width, height, frame: inputs.frame };
    app.emit('drawn', result);
    app.stillFrames++;
    if (app.inputs.playing || this.dirty || this.converging) this.schedule();
    return result;
  }

  /**
   * The last drawn frame drawn again at width × height (default: its own size), with the same
   * iTime, iFrame, iDate, and iMouse scaled to the new size. Rows top to bottom.
   * @param {{width: number, height: number} | null} [size]
   * @returns {Promise<{width:number, height:number, data:Uint8Array}>}
   */
  async capture(size = null) {
    const app = this.app;
    if (!app.renderer.hasProgram || app.renderer.contextLost) throw new Error('nothing to capture: no shader is running');
    if (!app.inputs.last) await app.drawFrame();
    const last = /** @type {import('./shadertoy-inputs.js').FrameInputs} */ (app.inputs.last);
    // a multipass shader's buffers are the canvas's size: its Image pass is drawn again over them
    // as they are, which only means the same picture at the same size
    const wanted = size && !app.isMultipass ? size : { width: last.width, height: last.height };
    const rounded = { width: Math.max(1, Math.round(wanted.width)), height: Math.max(1, Math.round(wanted.height)) };
    const { width, height } = fitGpu(rounded, app.renderer.maxSize, 'screenshot size');
    return { width, height, data: await app.renderer.redraw(last, width, height) };
  }

  /** Puts a bitmap from the worker on the canvas (sized to it: the mouse maps through that size). @param {ImageBitmap} bitmap */
  show(bitmap) {
    const canvas = this.app.canvas;
    if (canvas.width !== bitmap.width || canvas.height !== bitmap.height) {
      canvas.width = bitmap.width;
      canvas.height = bitmap.height;
    }
    this.app.screen.transferFromImageBitmap(bitmap);
  }
}
