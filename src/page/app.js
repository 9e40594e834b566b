// The page's state and frame loop: one shader source, its control values, the Shadertoy inputs,
// the canvas size, and when to draw. The drawing itself is done by the render worker
// (render-client.js, render-worker.js): the app asks for one frame at a time, and asks for the
// next only when that one is done, so frames never queue up behind a heavy one; while playing it
// asks again at the next animation frame, while paused only on demand (a control change, a
// resize, the mouse). A change made while a frame is being drawn reaches the worker at once and
// applies from its next band. When to draw is frame-loop.js's; the compiles compile-job.js's;
// "Converge when still" converge.js's; a lost context and the watchdog's way back
// gpu-context.js's; the shader's keys keyboard-input.js's.
//
// The app touches no part of the page but its canvas: what it has to tell (a change of state, a
// compile's outcome, a lost context, each frame drawn) it emits as events (events.js), and the
// page shows it (main.js: the overlay and the data-* attributes; ui.js: the widgets). The
// canvas's size is canvas-size.js's business.

import { parseControls } from '../shadertoy/controls.js';
import { RenderClient } from './render-client.js';
import { ShadertoyInputs } from './shadertoy-inputs.js';
import { CanvasSize } from './canvas-size.js';
import { carriedOverValues, changedValues, readControlChanges } from './control-values.js';
import { Emitter } from './events.js';
import { LiveControlForm } from './live-controls.js';
import { loadImage } from './shader-loader.js';
import { KeyboardState } from '../shadertoy/keyboard.js';
import { frameSchedule, singlePass } from '../shadertoy/multipass.js';
import { MAX_SAMPLES, missingRaytracerFunctions } from '../shadertoy/progressive.js';
import { setConverging } from './converge.js';
import { FrameLoop } from './frame-loop.js';
import { watchKeyboard } from './keyboard-input.js';
import { goBack, watchContext } from './gpu-context.js';
import { compileShader, whenCompiled } from './compile-job.js';

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
    /** When to draw, and drawing (frame-loop.js). */
    this.frames = new FrameLoop(this);
    renderer.onPicture = (bitmap) => this.frames.show(bitmap);
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
    watchContext(this);
    // a key redraws only a shader that reads the keyboard (any other has nothing new to show)
    watchKeyboard(this.keyboard, () => this.readsKeyboard && this.requestRender());
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

  /** Whether "Converge when still" can run this shader (the raytracer: progressive.js). */
  get canConverge() {
    return !this.isMultipass && missingRaytracerFunctions(this.source).length === 0;
  }

  /** Whether some pass of the shader reads Shadertoy's keyboard texture. */
  get readsKeyboard() {
    return this.project.passes.some((pass) => pass.channels.some((channel) => channel?.kind === 'keyboard'));
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
   * "Converge when still" (converge.js): a single-pass shader runs as its progressive form, the
   * clock paused; off, the shader as it was. Frames keep coming while the view is still, up to
   * `frames` (MAX_SAMPLES by default), and start again from one sample after any change.
   * @param {boolean} on
   * @param {{frames?: number}} [options]
   * @returns {Promise<void>}
   */
  setConverging(on, options = {}) {
    return setConverging(this, on, options);
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
    return compileShader(this);
  }

  /** Resolves when no compile is under way (whatever the outcome). */
  whenCompiled() {
    return whenCompiled(this);
  }

  // ---- time ------------------------------------------------------------------------------------

  play() {
    this.inputs.play();
    this.frames.lastFrameAt = null;
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

  /**
   * Loads a shader as it ran (its tabs and its control values); call compile() after.
   * @param {ShaderVersion} version
   */
  runVersion(version) {
    this.loadProject(version.project, version);
    this.applyControls(version.values ?? {}, 'the last shader that finished');
  }

  /**
   * The watchdog's way out: stops the render worker (and the draw that would not end) and runs
   * the last shader a frame was finished with, in a new one (gpu-context.js).
   */
  goBack() {
    return goBack(this);
  }

  // ---- drawing ---------------------------------------------------------------------------------

  /** Draws at the next animation frame (once, however often it is asked, and never while a frame is under way). */
  requestRender() {
    this.frames.request();
  }

  /**
   * Draws one frame (after the one under way, if any), and resolves once it is on the canvas:
   * with its pixels (RGBA8, rows top to bottom) when `readBack`, null when no shader runs or the
   * context is lost.
   * @param {number} [now] timestamp in ms (performance.now() or a rAF time)
   * @param {boolean} [readBack]
   */
  drawFrame(now = performance.now(), readBack = false) {
    return this.frames.draw(now, readBack);
  }

  // ---- output ----------------------------------------------------------------------------------

  /**
   * The last drawn frame drawn again at width × height (default: its own size), with the same
   * iTime, iFrame, iDate, and iMouse scaled to the new size. Rows top to bottom.
   * @param {{width: number, height: number} | null} [size]
   * @returns {Promise<{width:number, height:number, data:Uint8Array}>}
   */
  capture(size = null) {
    return this.frames.capture(size);
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
