// The app's frame loop (app.frames): when to draw, and what a drawn frame changes. The app asks
// the render worker for one frame at a time, and asks for the next only when that one is done, so
// frames never queue up behind a heavy one; while playing it asks again at the next animation
// frame, while paused only on demand (a control change, a resize, the mouse), and while
// converging (converge.js) as long as the view is still. The frames the worker draws come back
// as bitmaps, shown on the app's canvas, with their GPU times; a capture (a screenshot) draws
// the last frame again, at another size.
//
// It owns what drawing knows: the frame under way and how far it has got, the last frame drawn
// (its inputs and size), the counters, the last shader a frame was finished with, and the
// canvas's bitmap renderer that shows the frames.

import { fitGpu } from './canvas-size.js';

/** @typedef {import('./app.js').ShaderVersion} ShaderVersion */
/** @typedef {import('../gpu/protocol.js').FrameInputs} FrameInputs */
/** @typedef {import('./events.js').DrawnEvent} DrawnEvent */

/**
 * What the frame loop uses of the app (app.js builds it): the parts a frame is made from, what
 * it reads of the shader and the other parts at each frame, and the 'drawn' event it tells.
 * @typedef {object} FrameHost
 * @property {import('./render-client.js').RenderClient} gpu the render worker (on, contextLost, ask, maxSize)
 * @property {HTMLCanvasElement} canvas where the frames are shown (sized to them here)
 * @property {import('./shadertoy-inputs.js').ShadertoyInputs} inputs the clock and the mouse
 * @property {import('./canvas-size.js').CanvasSize} canvasSize the drawing buffer's size
 * @property {import('../../shadertoy/keyboard.js').KeyboardState} keyboard Shadertoy's keyboard texture
 * @property {() => boolean} readsKeyboard whether some pass reads the keyboard (ShaderApp.readsKeyboard)
 * @property {(frame: FrameInputs, running: boolean | null) => FrameInputs | Promise<FrameInputs>} withMedia a
 *   frame's inputs with its moving channels' textures at its iTime (Channels.withMedia)
 * @property {() => boolean} isMultipass whether the shader has a Common tab or a buffer
 * @property {() => boolean} hasProgram whether a shader runs (CompileJob.hasProgram)
 * @property {(serial: number) => ShaderVersion | null} versionOf the shader a frame was drawn with (CompileJob.versionOf)
 * @property {() => ShaderVersion | null} onScreen the shader that runs now (CompileJob.running)
 * @property {(stillFrames: number) => boolean} wantsFrame whether converging wants another frame (Converge.wantsFrame)
 * @property {(frame: DrawnEvent) => void} emitDrawn the app's 'drawn' event
 */

export class FrameLoop {
  /** @param {FrameHost} host */
  constructor(host) {
    this._host = host;
    /** Shows the frames the worker draws. */
    this._screen = /** @type {ImageBitmapRenderingContext} */ (host.canvas.getContext('bitmaprenderer'));
    this._raf = 0;
    /** The frame the worker is drawing. @type {Promise<unknown> | null} */
    this._drawing = null;
    /** Something changed since the frame under way was asked for: another one is due. */
    this._dirty = false;
    /** performance.now() when the last frame of a run of frames was drawn (for its interval). @type {number | null} */
    this._lastDrawnAt = null;
    /** Frames drawn since the page started. */
    this.count = 0;
    /** Frames drawn since the last change (a converging shader adds one sample per frame). */
    this.stillFrames = 0;
    /** The inputs of the last frame drawn (a screenshot draws it again; its size is the canvas's). @type {FrameInputs | null} */
    this.last = null;
    /** How far the frame under way has got: rows done of its height, bands drawn (null: none under way). @type {{y: number, height: number, bands: number} | null} */
    this.progress = null;
    /** Whether the next frame the page draws by itself is read back (the 'drawn' event's pixels). */
    this._readBackNext = false;
    /** The last shader a frame was finished with (the watchdog goes back to it). @type {ShaderVersion | null} */
    this.lastFinished = null;
    /** The last whole frame on the canvas: its shader's load (ShaderVersion.load) and its size. @type {{load: number | undefined, width: number, height: number} | null} */
    this._whole = null;
    /** The size of the frame under way, or else of the last one asked for. @type {{width: number, height: number} | null} */
    this._asked = null;

    host.gpu.on('band', (_, band) => {
      if (band.kind !== 'frame') return;
      this.progress = { y: band.y, height: band.height, bands: (this.progress?.bands ?? 0) + 1 };
      if (band.bitmap) this.show(band.bitmap);
    });
  }

  /** The size of the last frame drawn (0 × 0 before the first). */
  get size() {
    return { width: this.last?.width ?? 0, height: this.last?.height ?? 0 };
  }

  /** Whether a frame is under way. */
  get busy() {
    return this._drawing !== null;
  }

  /** Resolves once no frame is under way (whatever its outcome). */
  async idle() {
    while (this._drawing) await this._drawing.catch(() => {});
  }

  /** Draws at the next animation frame (once, however often it is asked, and never while a frame is under way). */
  request() {
    this._dirty = true;
    this.stillFrames = 0;
    this._schedule();
  }

  /**
   * The canvas's target size may have changed (CanvasSize.watch): a frame is due unless the one
   * under way, or the last one, has that size. A resize observer reports a new fixed size only
   * after the frame at that size has started; a frame asked for then would be one more frame
   * than the view was given, and a render read back after it would show the next iFrame.
   */
  resized() {
    const { width, height } = this._host.canvasSize.target();
    if (this._asked?.width !== width || this._asked?.height !== height) this.request();
  }

  /** The next frame starts a new run: its interval is not measured from the last one (after a pause). */
  restartInterval() {
    this._lastDrawnAt = null;
  }

  /** The worker went away with the frame it was drawing (a new worker after a hang). */
  forgetDrawing() {
    this._drawing = null;
    this.progress = null;
  }

  _schedule() {
    if (!this._raf && !this._drawing) this._raf = requestAnimationFrame((now) => this._tick(now));
  }

  /**
   * Whether frames follow one another by themselves: playing (at a speed above 0: at 0× the
   * clock stands still, and every frame would be the last one again), or converging a still view.
   */
  get running() {
    const { playing, speed } = this._host.inputs;
    return (playing && speed > 0) || this._host.wantsFrame(this.stillFrames);
  }

  /** @param {number} now */
  _tick(now) {
    this._raf = 0;
    if (this._drawing || !(this._dirty || this.running)) return;
    const readBack = this._readBackNext;
    this._readBackNext = false;
    this.draw(now, readBack).catch(() => {}); // a lost context: the page says so
  }

  /** The next frame the page draws by itself is read back: its 'drawn' event has its pixels. */
  readBackNextFrame() {
    this._readBackNext = true;
  }

  /**
   * Draws one frame (after the one under way, if any), and resolves once it is on the canvas:
   * with its pixels (RGBA8, rows top to bottom) when `readBack`, null when no shader runs or the
   * context is lost.
   * @param {number} [now] timestamp in ms (performance.now() or a rAF time)
   * @param {boolean} [readBack]
   * @returns {Promise<DrawnEvent | null>}
   */
  async draw(now = performance.now(), readBack = false) {
    const host = this._host;
    while (this._drawing) await this._drawing.catch(() => {});
    if (host.gpu.contextLost || !host.hasProgram()) return null;
    const { width, height } = host.canvasSize.target();
    this._asked = { width, height };
    this._dirty = false;
    const continued = this.running && this._lastDrawnAt !== null;
    const run = host.inputs.run;
    const timed = host.inputs.beginFrame(width, height, now);
    const { playing, speed } = host.inputs;
    /** @type {FrameInputs} */
    let frame = timed;
    // the keyboard texture goes to the worker (and is uploaded) only for a shader that reads it
    const keyboard = host.readsKeyboard() ? host.keyboard.data.slice() : null;
    this.progress = { y: 0, height, bands: 0 };
    const progressive = this._buildsUp(width, height);
    const send = (/** @type {FrameInputs} */ withMedia) => {
      frame = withMedia;
      return host.gpu.ask('frame', { inputs: keyboard ? { ...frame, keyboard } : frame, readBack, progressive });
    };
    // a moving channel's texture at this frame's iTime first (Channels.withMedia), inside the
    // drawing this loop waits on, so that no other frame starts meanwhile; without one, the frame
    // is asked for at once, as before there were moving channels
    const withMedia = host.withMedia(timed, playing && speed === 1);
    const drawing = withMedia instanceof Promise ? withMedia.then(send) : send(withMedia);
    this._drawing = drawing;
    let drawn;
    try {
      drawn = await drawing;
    } finally {
      if (this._drawing === drawing) {
        this._drawing = null;
        this.progress = null;
      }
    }
    if (run !== host.inputs.run) {
      // The clock was restarted while this frame was drawn (Restart, a new shader): its iFrame
      // and iTime are the run before's, and a buffer cleared meanwhile was drawn half over. It is
      // not shown; the new run's iFrame 0 is drawn in its place.
      drawn.bitmap.close();
      return this.draw(performance.now(), readBack);
    }
    this.show(drawn.bitmap);
    this.last = frame;
    host.inputs.endFrame(run);
    // "pressed this frame" is over: a shader that reads it is drawn once more without it
    if (host.keyboard.endFrame() && host.readsKeyboard()) this.request();
    this.count++;
    // the shader the worker drew it with: a compile that landed while it was drawn started the
    // frame again with the new program (gpu/protocol.js)
    this.lastFinished = host.versionOf(drawn.program) ?? this.lastFinished;
    this._whole = { load: this.lastFinished?.load, width, height };
    // the clock when the frame was drawn, not when it was due: on a slow GPU the animation
    // frames' timestamps run ahead of the drawing
    const drawnAt = performance.now();
    const interval = continued ? drawnAt - /** @type {number} */ (this._lastDrawnAt) : null;
    this._lastDrawnAt = this.running ? drawnAt : null;
    /** @type {DrawnEvent} */
    const result = { pixels: drawn.pixels, width, height, frame: frame.frame, interval, gpuTimes: drawn.gpuTimes };
    host.emitDrawn(result);
    this.stillFrames++;
    if (this.running || this._dirty) this._schedule();
    return result;
  }

  /**
   * Whether the next frame, width × height, is shown as it builds up (the worker sends a picture
   * of it as far as it got, four times a second). A still frame is, and so is the first frame of
   * a newly loaded shader or of a new size while playing: there is nothing newer to show. Frames
   * that follow one another (playing, converging) are shown only whole: one shown as it builds
   * up lies half over the frame before it, a torn picture (issue 45).
   * @param {number} width
   * @param {number} height
   */
  _buildsUp(width, height) {
    const whole = this._whole;
    const shown = whole !== null && whole.width === width && whole.height === height && whole.load === this._host.onScreen()?.load;
    return !this.running || !shown;
  }

  /**
   * The last frame drawn, read back as it was drawn (nothing is drawn: a still's frame 0 stays
   * frame 0), once no frame is under way; rows top to bottom.
   * @returns {Promise<{width: number, height: number, data: Uint8Array, frame: number}>}
   */
  async readLast() {
    await this.idle();
    const last = this.last;
    if (!last || this._host.gpu.contextLost)
      throw new Error(this._host.gpu.contextLost ? 'the GPU context is lost' : 'no frame has been drawn');
    return { width: last.width, height: last.height, data: await this._host.gpu.ask('readFrame', {}), frame: last.frame };
  }

  /**
   * The last drawn frame drawn again at width × height (default: its own size), with the same
   * iTime, iFrame, iDate, and iMouse scaled to the new size. Rows top to bottom; `time` is its iTime.
   * @param {{width: number, height: number} | null} [size]
   * @returns {Promise<{width:number, height:number, data:Uint8Array, time: number}>}
   */
  async capture(size = null) {
    const host = this._host;
    if (!host.hasProgram() || host.gpu.contextLost) throw new Error('nothing to capture: no shader is running');
    if (!this.last) await this.draw();
    const last = this.last;
    if (!last) throw new Error('nothing to capture: the GPU context is lost');
    // a multipass shader's buffers are the canvas's size: its Image pass is drawn again over them
    // as they are, which only means the same picture at the same size
    const wanted = size && !host.isMultipass() ? size : { width: last.width, height: last.height };
    const rounded = { width: Math.max(1, Math.round(wanted.width)), height: Math.max(1, Math.round(wanted.height)) };
    const { width, height } = fitGpu(rounded, host.gpu.maxSize, 'screenshot size');
    return { width, height, data: await host.gpu.ask('capture', { inputs: last, width, height, allPasses: false }), time: last.time };
  }

  /** Puts a bitmap from the worker on the canvas (sized to it: the mouse maps through that size). @param {ImageBitmap} bitmap */
  show(bitmap) {
    const canvas = this._host.canvas;
    if (canvas.width !== bitmap.width || canvas.height !== bitmap.height) {
      canvas.width = bitmap.width;
      canvas.height = bitmap.height;
    }
    this._screen.transferFromImageBitmap(bitmap);
  }
}
