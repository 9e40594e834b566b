// The page's state and frame loop: one shader source, its control values, the Shadertoy inputs,
// the canvas size, and when to draw. The drawing itself is done by the render worker
// (render-client.js, render-worker.js): the app asks for one frame at a time, and asks for the
// next only when that one is done, so frames never queue up behind a heavy one; while playing it
// asks again at the next animation frame, while paused only on demand (a control change, a
// resize, the mouse). A change made while a frame is being drawn reaches the worker at once and
// applies from its next band.
//
// The app touches no part of the page but its canvas: what it has to tell (a change of state, a
// compile's outcome, a lost context, each frame drawn) it emits as events (events.js), and the
// page shows it (main.js: the overlay and the data-* attributes; ui.js: the widgets). The
// canvas's size is canvas-size.js's business.

import { parseControls } from '../shadertoy/controls.js';
import { hostControlBlock } from '../shadertoy/header.js';
import { RenderClient } from './render-client.js';
import { ShadertoyInputs } from './shadertoy-inputs.js';
import { CanvasSize, fitGpu } from './canvas-size.js';
import { carriedOverValues, changedValues, readControlChanges } from './control-values.js';
import { Emitter } from './events.js';
import { LiveControlForm } from './live-controls.js';
import { loadImage } from './shader-loader.js';
import { KeyboardState, keyCodeOf } from '../shadertoy/keyboard.js';
import { frameSchedule, singlePass } from '../shadertoy/multipass.js';
import { MAX_SAMPLES, progressiveTabs } from '../shadertoy/progressive.js';

/** @typedef {import('../shadertoy/controls.js').Control} Control */
/** @typedef {import('./events.js').AppEvents} AppEvents */
/** @typedef {import('../shadertoy/multipass.js').MultipassShader} MultipassShader */
/**
 * A shader as it ran: its tabs, where it came from, and its control values.
 * @typedef {{project: MultipassShader, info: object | null, name: string, origin: RaytracerApp['origin'], url: string | null, values?: Record<string, any>}} ShaderVersion
 */

/** @extends {Emitter<AppEvents>} */
export class RaytracerApp extends Emitter {
  /**
   * Use RaytracerApp.start (the render worker starts first).
   * @param {object} options
   * @param {RenderClient} options.renderer a started render worker
   * @param {HTMLCanvasElement} options.canvas
   * @param {string} options.fileName the shader's name in error messages
   * @param {{width:number, height:number} | null} [options.size] fixed drawing-buffer size (device px)
   * @param {number} [options.scale] resolution scale of the device pixels (without a fixed size)
   * @param {number} [options.cap] cap on the drawing buffer's longer side (device px; 0: none)
   * @param {boolean} [options.playing]
   */
  constructor({ renderer, canvas, fileName, size = null, scale = 1, cap = 0, playing = true }) {
    super();
    this.canvas = canvas;
    /** Shows the frames the worker draws. */
    this.screen = /** @type {ImageBitmapRenderingContext} */ (canvas.getContext('bitmaprenderer'));
    /** The shader's name in messages and downloads. */
    this.fileName = fileName;
    this.renderer = renderer;
    renderer.onPicture = (bitmap) => this._show(bitmap);
    renderer.onHang = (seconds) => this.emit('hang', seconds);
    this.inputs = new ShadertoyInputs();
    this.inputs.playing = playing;
    this.inputs.attach(canvas);
    this.inputs.onMouseChange = () => this.requestRender();
    /** The drawing buffer's size: fixed, or the layout's with scale and cap. */
    this.canvasSize = new CanvasSize(canvas, { maxSide: () => this.renderer.maxSize, fixed: size, scale, cap });

    /** The shader: its tabs (a plain file is one Image tab). @type {MultipassShader} */
    this.project = singlePass('');
    /** The JSON `info` the shader came with (kept for an export), null for a plain file. @type {object | null} */
    this.projectInfo = null;
    /** What the page cannot give the shader (media a JSON names: black channels). @type {string[]} */
    this.notes = [];
    /** Shadertoy's keyboard texture, for the passes that read it. */
    this.keyboard = new KeyboardState();
    /** "Converge when still": the shader runs as its progressive form (setConverging). */
    this.converging = false;
    /** Frames drawn since the last change (a converging shader adds one sample per frame). */
    this.stillFrames = 0;
    /** Frames a converging shader is drawn while the view is still: then its buffer sums no more. */
    this.convergeFrames = MAX_SAMPLES;
    /** What to run instead of a shader that hung (hang-guard.js), once the page has one. @type {import('./hang-guard.js').HangGuard | null} */
    this.hangGuard = null;
    /** The single-pass shader that converges (setConverging(false) goes back to it). @type {ShaderVersion | null} */
    this._beforeConverging = null;
    /** Where the source came from. @type {'builtin' | 'url' | 'editor' | 'file'} */
    this.origin = 'builtin';
    /** The shader's URL as the page was given it, when it came from one (for a shared link). @type {string | null} */
    this.shaderUrl = null;
    /** The URL of the image in each channel, when it came from one. @type {Array<string | null>} */
    this.channelUrls = [null, null, null, null];
    /** @type {Control[]} */
    this.controls = [];
    /** The controls' current values, by name. @type {Record<string, any>} */
    this.values = {};
    /** Why the control block could not be read (the shader then runs with its own defaults). @type {string | null} */
    this.notice = null;
    /** The first source on its way (set by the page while it fetches it). @type {Promise<void> | null} */
    this.loading = null;
    this.framesRendered = 0;
    this.compiled = 0; // successful compiles
    /** The messages of the last failed compile, [] after a success. @type {Array<{line: number | null, message: string}>} */
    this.compileErrors = [];
    /** Whether the next compile takes the live controls as constants or as uniforms. */
    this.liveForm = new LiveControlForm(() => this.compile().catch(() => {})); // failures are shown on the page

    /** @type {Promise<void> | null} */
    this._latestCompile = null;
    this._raf = 0;
    /** @type {number | null} */
    this._lastFrameAt = null;
    /** The frame the worker is drawing. @type {Promise<unknown> | null} */
    this._drawing = null;
    /** Something changed since the frame under way was asked for: another one is due. */
    this._dirty = false;
    /** Whether the next frame the page draws by itself is read back (the 'drawn' event's pixels). */
    this.readBackNext = false;
    /** The images in iChannel0..3, as loaded (a new worker gets them again). @type {Array<ImageBitmap | null>} */
    this.channelImages = [null, null, null, null];
    /** The shader on screen, once it has compiled. @type {ShaderVersion | null} */
    this._running = null;
    /** The last shader a frame was finished with (the watchdog goes back to it). @type {ShaderVersion | null} */
    this.lastFinished = null;

    /** Resolves after the first frame is drawn; rejects if the first compile fails. @type {Promise<void>} */
    this.ready = new Promise((resolve, reject) => {
      this.once('drawn', () => resolve());
      this.on('compile', (_, error) => {
        if (error && !this.renderer.hasProgram) reject(error);
      });
    });
    this.ready.catch(() => {}); // a failure is reported on the page; callers may still await it

    this.canvasSize.watch(() => this.requestRender());
    this._watchContext();
    this._watchKeyboard();
  }

  /**
   * Keys into Shadertoy's keyboard texture (keyboard.js), for shaders that read it: keys typed into
   * the editor or a field of the panel are the page's, not the shader's.
   */
  _watchKeyboard() {
    const typing = (/** @type {KeyboardEvent} */ event) => {
      const target = /** @type {HTMLElement | null} */ (event.target instanceof HTMLElement ? event.target : null);
      return Boolean(target?.closest('input, textarea, select, [contenteditable="true"], .cm-editor'));
    };
    window.addEventListener('keydown', (event) => {
      if (!typing(event) && this.keyboard.keyDown(keyCodeOf(event))) this.requestRender();
    });
    window.addEventListener('keyup', (event) => {
      if (this.keyboard.keyUp(keyCodeOf(event))) this.requestRender();
    });
    window.addEventListener('blur', () => {
      // keys released in another window never come back up here; toggles stay
      for (let key = 0; key < 256; key++) this.keyboard.keyUp(key);
      this.requestRender();
    });
  }

  /**
   * Starts the render worker, then the app. Rejects with WebGL2UnavailableError when there is no
   * WebGL2.
   * @param {Omit<ConstructorParameters<typeof RaytracerApp>[0], 'renderer'>} options
   */
  static async start(options) {
    return new RaytracerApp({ ...options, renderer: await RenderClient.start() });
  }

  // ---- source and controls ---------------------------------------------------------------------

  /** The Image tab's text (the whole shader, for a plain file). */
  get source() {
    return this.project.passes.find((pass) => pass.kind === 'image')?.code ?? '';
  }

  /** Whether the shader has a Common tab or a buffer. */
  get isMultipass() {
    return this.project.common !== null || this.project.passes.length > 1;
  }

  /**
   * Takes a new shader source (one Image tab): see loadProject.
   * @param {string} source
   * @param {{name?: string, origin?: RaytracerApp['origin'], url?: string|null}} [from] where it came from
   */
  loadSource(source, from = {}) {
    this.loadProject(singlePass(source), from);
  }

  /**
   * Takes a new shader: reads its control blocks (one per tab at most; keeping current values of
   * controls that survive); the page rebuilds its panel on the 'source' event. Call compile() after.
   * @param {MultipassShader} project
   * @param {{name?: string, origin?: RaytracerApp['origin'], url?: string|null, info?: object | null, converging?: boolean}} [from]
   *   where it came from (converging: the progressive form setConverging makes)
   */
  loadProject(project, from = {}) {
    /** @type {Control[]} */
    const controls = [];
    this.notice = null;
    try {
      for (const text of [project.common ?? '', ...project.passes.map((pass) => pass.code)])
        for (const control of parseControls(text)) if (!controls.some((c) => c.name === control.name)) controls.push(control);
    } catch (error) {
      this.notice = `${error.message}\nThe shader runs with its own defaults and no panel controls.`;
    }
    const values = carriedOverValues(controls, this.controls, this.values);
    this.project = project;
    this.projectInfo = from.info ?? null;
    this.notes = frameSchedule(project).flatMap((step) => step.bindings.flatMap((binding) => (binding.note ? [binding.note] : [])));
    this.liveForm.reset();
    if (!from.converging) this.converging = false;
    if (from.name) this.fileName = from.name;
    if (from.origin) {
      this.origin = from.origin;
      this.shaderUrl = from.origin === 'url' ? from.url : from.origin === 'editor' ? this.shaderUrl : null;
    }
    this.controls = controls;
    this.values = values;
    this.renderer.setControlUniforms(controls, values);
    this.emit('source');
  }

  /**
   * loadSource + compile: resolves on success, rejects with the compile error.
   * @param {string} source
   * @param {{name?: string, origin?: RaytracerApp['origin'], url?: string|null}} [from]
   */
  setSource(source, from = {}) {
    this.loadSource(source, from);
    return this.compile();
  }

  /**
   * "Converge when still": runs a single-pass shader (the built-in raytracer) as its progressive
   * multipass form (progressive.js: Buffer A adds one jittered sample per pixel per frame while
   * nothing changes; Image shows the mean and the sample count), pausing the clock so that the
   * view is still; off, the shader as it was. Frames keep coming while the view is still, up to
   * `frames` (MAX_SAMPLES by default), and start again from one sample after any change.
   * @param {boolean} on
   * @param {{frames?: number}} [options]
   */
  async setConverging(on, { frames = MAX_SAMPLES } = {}) {
    this.convergeFrames = Math.max(1, Math.min(MAX_SAMPLES, Math.round(frames)));
    if (on === this.converging) return this.requestRender();
    if (!on) {
      const back = /** @type {ShaderVersion} */ (this._beforeConverging);
      this.converging = false;
      this._beforeConverging = null;
      this.loadProject(back.project, back);
      this.applyControls(back.values ?? {}, 'Converge when still');
      return this.compile();
    }
    if (this.isMultipass) throw new Error('only a single-pass shader converges: this one has buffers of its own');
    this._beforeConverging = {
      project: this.project,
      info: this.projectInfo,
      name: this.fileName,
      origin: this.origin,
      url: this.shaderUrl,
      values: structuredClone(this.values),
    };
    const tabs = progressiveTabs(this.source);
    this.pause();
    this.converging = true;
    this.loadProject(tabs.model, { converging: true, name: this.fileName, origin: this.origin, url: this.shaderUrl });
    this.applyControls({ SHOW_SAMPLE_COUNT: 1 }, 'Converge when still');
    return this.compile();
  }

  /**
   * loadProject + compile: resolves on success, rejects with the compile error.
   * @param {MultipassShader} project
   * @param {{name?: string, origin?: RaytracerApp['origin'], url?: string|null, info?: object | null}} [from]
   */
  setProject(project, from = {}) {
    this.loadProject(project, from);
    return this.compile();
  }

  /**
   * Sets controls by name ({NAME: value}; vectors as arrays or "x,y,z"). Values are coerced into
   * range; unknown names and unreadable values are warned about and skipped. Resolves once the
   * change is on screen (after a recompile, for compile-time controls).
   * @param {Record<string, unknown>} changes
   * @param {string} [from] who asks, in warnings
   * @returns {Promise<void>}
   */
  setControls(changes, from = 'setControls') {
    const recompile = this.applyControls(changes, from);
    if (recompile)
      this.compile().catch(() => {}); // errors are shown on the page
    else this.requestRender();
    return this.whenCompiled();
  }

  /**
   * setControls without drawing or compiling.
   * @param {Record<string, unknown>} changes
   * @param {string} [from] who asks, in warnings
   * @returns {boolean} true if a compile-time control changed
   */
  applyControls(changes, from = 'setControls') {
    let recompile = false;
    for (const { control, value } of readControlChanges(this.controls, changes, from)) {
      const name = control.name;
      const changed = JSON.stringify(value) !== JSON.stringify(this.values[name]);
      this.values[name] = value;
      if (control.kind === 'define') recompile ||= changed;
      else {
        this.renderer.setControlUniform(name, value);
        // Before the first compile there is nothing on screen: that compile takes the new
        // values as constants.
        if (changed && this.renderer.hasProgram && this.liveForm.moved()) recompile = true;
      }
    }
    this.emit('state');
    return recompile;
  }

  /** The controls whose values differ from the shader's defaults. */
  changedControls() {
    return changedValues(this.controls, this.values);
  }

  /**
   * Compiles the source with the current compile-time values. On success the new shader is
   * drawn; on failure the error is shown and the last shader that compiled keeps running.
   */
  compile() {
    if (this.renderer.contextLost) {
      // compiled when the context comes back: this job ends as the compile started then does
      /** @type {Promise<void>} */
      const job = new Promise((resolve) => this.once('context', () => resolve(this._latestCompile)));
      this._latestCompile = job;
      return job;
    }
    const hostBlock = this.notice ? '' : hostControlBlock(this.controls, this.values, this.liveForm.asConstants ? this.values : null);
    const fileName = this.fileName;
    /** @type {ShaderVersion} */
    /** @type {ShaderVersion} */
    const version = {
      project: this.project,
      info: this.projectInfo,
      name: fileName,
      origin: this.origin,
      url: this.shaderUrl,
      values: structuredClone(this.values),
    };
    const job = this.renderer.compile(this.project, hostBlock, fileName).then(
      () => {
        this._running = version;
        if (job !== this._latestCompile) return;
        this.compileErrors = [];
        this.compiled++;
        this.emit('compile', null, fileName);
        this.requestRender();
      },
      (error) => {
        if (job === this._latestCompile) {
          this.compileErrors = error.messages ?? [];
          console.warn(error.message);
          this.emit('compile', error, fileName); // `ready` rejects if no shader runs at all
        }
        throw error;
      },
    );
    this._latestCompile = job;
    return job;
  }

  /** Resolves when no compile is under way (whatever the outcome). */
  async whenCompiled() {
    let job;
    do {
      job = this._latestCompile;
      await job?.catch(() => {});
    } while (job !== this._latestCompile);
  }

  // ---- time ------------------------------------------------------------------------------------

  play() {
    this.inputs.play();
    this._lastFrameAt = null;
    this.emit('state');
    this.requestRender();
  }

  pause() {
    this.inputs.pause();
    this.emit('state');
  }

  togglePlay() {
    if (this.inputs.playing) this.pause();
    else this.play();
  }

  /** iTime and iFrame back to 0; draws that frame even while paused. */
  restart() {
    this.inputs.restart();
    this.renderer.clearBuffers(); // Shadertoy's rewind clears every buffer too
    this.emit('state');
    this.requestRender();
  }

  /** @param {number} seconds */
  setTime(seconds) {
    this.inputs.setTime(Math.max(0, Number(seconds) || 0));
    this.emit('state');
    this.requestRender();
  }

  /** @param {number} speed */
  setSpeed(speed) {
    this.inputs.setSpeed(Math.max(0, Number(speed) || 0));
    this.emit('state');
  }

  /** @param {number[]} mouse iMouse, [x, y, z, w] in device pixels, until the next click */
  setMouse(mouse) {
    this.inputs.setMouse(mouse);
    this.requestRender();
  }

  // ---- size ------------------------------------------------------------------------------------

  /** @param {number} scale resolution scale of the device pixels */
  setScale(scale) {
    this.canvasSize.scale = scale;
    this.emit('state');
    this.requestRender();
  }

  /** @param {number} cap cap on the drawing buffer's longer side, in device pixels (0: none) */
  setCap(cap) {
    this.canvasSize.cap = Math.max(0, Math.round(Number(cap) || 0));
    this.emit('state');
    this.requestRender();
  }

  // ---- the GPU context -------------------------------------------------------------------------

  _watchContext() {
    this.renderer.onContext = (lost) => {
      if (lost) {
        this.emit('context', true);
        this.emit('state');
        return;
      }
      // the worker's state went with the context: programs are compiled again from ours; after
      // a hang (the browser resets a GPU held too long), the last shader that finished a frame
      const back = this.hangGuard?.backFor(this.project, this.values);
      if (back) this.runVersion(back);
      this._resend();
      this.compile().catch(() => {}); // shown on the page
      this.emit('context', false); // after the compile started: the compiles asked for meanwhile end with it
      this.emit('state');
      this.requestRender();
    };
  }

  /**
   * Loads a shader as it ran (its tabs and its control values); call compile() after.
   * @param {ShaderVersion} version
   */
  runVersion(version) {
    this.loadProject(version.project, version);
    this.applyControls(version.values ?? {}, 'the last shader that finished');
  }

  /** Gives the worker the control uniforms and the channels again (a new worker, a new context). */
  _resend() {
    this.renderer.setControlUniforms(this.controls, this.values);
    this.channelImages.forEach((image, i) => image && this.renderer.setChannel(i, image));
  }

  /**
   * The watchdog's way out: stops the render worker (and the draw that would not end) and runs
   * the last shader a frame was finished with, in a new one. On a real GPU that draws at once
   * (the browser resets a GPU held too long); on SwiftShader the endless draw keeps the GPU
   * process busy, and the new worker waits with it.
   */
  async goBack() {
    const back = this.lastFinished;
    await this.renderer.respawn();
    this._drawing = null;
    if (back) this.runVersion(back);
    this._resend();
    this.compile().catch(() => {});
    this.requestRender();
  }

  // ---- drawing ---------------------------------------------------------------------------------

  /** Draws at the next animation frame (once, however often it is asked, and never while a frame is under way). */
  requestRender() {
    this._dirty = true;
    this.stillFrames = 0;
    this._schedule();
  }

  _schedule() {
    if (!this._raf && !this._drawing) this._raf = requestAnimationFrame((now) => this._tick(now));
  }

  /** Whether converging asks for another frame: while the view is still, up to convergeFrames. */
  get _converging() {
    return this.converging && this.stillFrames < this.convergeFrames;
  }

  /** @param {number} now */
  _tick(now) {
    this._raf = 0;
    if (this._drawing || !(this._dirty || this.inputs.playing || this._converging)) return;
    const readBack = this.readBackNext;
    this.readBackNext = false;
    this.drawFrame(now, readBack).catch(() => {}); // a lost context: the page says so
  }

  /**
   * Draws one frame (after the one under way, if any), and resolves once it is on the canvas:
   * with its pixels (RGBA8, rows top to bottom) when `readBack`, null when no shader runs or the
   * context is lost.
   * @param {number} [now] timestamp in ms (performance.now() or a rAF time)
   * @param {boolean} [readBack]
   * @returns {Promise<{pixels: Uint8Array | null, width: number, height: number, frame: number} | null>}
   */
  async drawFrame(now = performance.now(), readBack = false) {
    while (this._drawing) await this._drawing.catch(() => {});
    if (this.renderer.contextLost || !this.renderer.hasProgram) return null;
    const { width, height } = this.canvasSize.target();
    this._dirty = false;
    const inputs = { ...this.inputs.beginFrame(width, height, now), keyboard: this.keyboard.data.slice() };
    const running = this._running;
    const drawing = this.renderer.drawFrame(inputs, readBack);
    this._drawing = drawing;
    let drawn;
    try {
      drawn = await drawing;
    } finally {
      if (this._drawing === drawing) this._drawing = null;
    }
    this.inputs.endFrame();
    if (this.keyboard.endFrame()) this.requestRender(); // "pressed this frame" is over
    this.framesRendered++;
    this.lastFinished = running;
    if (this.inputs.playing) {
      // the clock when the frame was drawn, not when it was due: on a slow GPU the animation
      // frames' timestamps run ahead of the drawing (frame-timer.js)
      const drawnAt = performance.now();
      if (this._lastFrameAt !== null) this.emit('frame', drawnAt - this._lastFrameAt);
      this._lastFrameAt = drawnAt;
    } else {
      this._lastFrameAt = null;
    }
    const result = { pixels: drawn.pixels, width, height, frame: inputs.frame };
    this.emit('drawn', result);
    this.stillFrames++;
    if (this.inputs.playing || this._dirty || this._converging) this._schedule();
    return result;
  }

  /** Puts a bitmap from the worker on the canvas (sized to it: the mouse maps through that size). */
  _show(bitmap) {
    if (this.canvas.width !== bitmap.width || this.canvas.height !== bitmap.height) {
      this.canvas.width = bitmap.width;
      this.canvas.height = bitmap.height;
    }
    this.screen.transferFromImageBitmap(bitmap);
  }

  // ---- output ----------------------------------------------------------------------------------

  /**
   * The last drawn frame drawn again at width × height (default: its own size), with the same
   * iTime, iFrame, iDate, and iMouse scaled to the new size. Rows top to bottom.
   * @param {{width: number, height: number} | null} [size]
   * @returns {Promise<{width:number, height:number, data:Uint8Array}>}
   */
  async capture(size = null) {
    if (!this.renderer.hasProgram || this.renderer.contextLost) throw new Error('nothing to capture: no shader is running');
    if (!this.inputs.last) await this.drawFrame();
    const last = /** @type {import('./shadertoy-inputs.js').FrameInputs} */ (this.inputs.last);
    // a multipass shader's buffers are the canvas's size: its Image pass is drawn again over them
    // as they are, which only means the same picture at the same size
    const wanted = size && !this.isMultipass ? size : { width: last.width, height: last.height };
    const rounded = { width: Math.max(1, Math.round(wanted.width)), height: Math.max(1, Math.round(wanted.height)) };
    const { width, height } = fitGpu(rounded, this.renderer.maxSize, 'screenshot size');
    return { width, height, data: await this.renderer.redraw(last, width, height) };
  }

  /**
   * Loads an image (URL, File or Blob) into iChannel0..3; null empties the channel.
   * @param {number} index
   * @param {string | Blob | null} source
   */
  async setChannel(index, source) {
    if (!(index >= 0 && index <= 3)) throw new Error(`no channel ${index}: iChannel0..3`);
    const image = source === null ? null : await loadImage(source);
    await this.renderer.setChannel(index, image);
    this.channelImages[index] = image;
    this.channelUrls[index] = typeof source === 'string' ? source : null;
    this.emit('state');
    this.requestRender();
  }
}
