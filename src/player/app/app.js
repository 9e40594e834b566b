// The page's state: one shader (its tabs and where it came from), its control values, the
// Shadertoy inputs, the canvas, and the parts that each own a piece of the rest: when to draw
// (frame-loop.js), the compiles (compile-job.js), "Converge when still" (converge.js), the
// channels' images (channels.js), the canvas's size (canvas-size.js), which form the live
// controls compile in (live-controls.js), and the render worker's client (render-client.js, the
// GPU side: gpu/). A lost context and the watchdog's way back are gpu-context.js's. This module
// composes them and is the public API the page's widgets and the hook (hook/) use.
//
// The app touches no part of the page but its canvas: what it has to tell (a change of state, a
// compile's outcome, a lost context, each frame drawn) it emits as events (events.js), and the
// page shows them (ui/).
//
// Past 400 lines because it is the app's whole public API, one short method a call, each handing
// the work to the part that owns it; what is more than that lives in those parts.

import { hostControlBlock } from '../../shadertoy/header.js';
import { KeyboardState } from '../../shadertoy/keyboard.js';
import { frameSchedule, singlePass } from '../../shadertoy/multipass.js';
import { RenderClient } from './render-client.js';
import { ShadertoyInputs } from './shadertoy-inputs.js';
import { CanvasSize } from './canvas-size.js';
import { controlsOf, readControlChanges } from './control-values.js';
import { Emitter } from './events.js';
import { LiveControlForm } from './live-controls.js';
import { Converge } from './converge.js';
import { FrameLoop } from './frame-loop.js';
import { watchContext } from './gpu-context.js';
import { CompileJob } from './compile-job.js';
import { Channels } from './channels.js';
import { MediaLibrary } from '../inputs/media-library.js';

/** @typedef {import('../../shadertoy/controls.js').Control} Control */
/** @typedef {import('./events.js').AppEvents} AppEvents */
/** @typedef {import('../../shadertoy/multipass.js').MultipassShader} MultipassShader */
/**
 * A shader as it ran: its tabs, where it came from, its control values, and which load of a
 * shader it is (a new number each time a shader replaces another: app.loadProject).
 * @typedef {{project: MultipassShader, info: object | null, name: string, origin: ShaderApp['origin'], url: string | null, values?: Record<string, any>, load?: number}} ShaderVersion
 */
/**
 * Where a shader given to loadProject comes from. `continues`: it is the shader on screen going
 * on (an edit typed in the editor, "Converge when still"), whose clock runs on; anything else is
 * a new shader, which starts at iFrame 0 (Shadertoy's contract).
 * @typedef {{name?: string, origin?: ShaderApp['origin'], url?: string|null, info?: object | null, continues?: boolean}} ProjectFrom
 */

/**
 * What runs instead of a shader that hung (io/hang-guard.js's HangGuard): the last shader that
 * finished a frame before `project` with `values` hung, or null.
 * @typedef {{backFor: (project: MultipassShader, values: Record<string, any>) => ShaderVersion | null}} HangFallback
 */

/** @extends {Emitter<AppEvents>} */
export class ShaderApp extends Emitter {
  /**
   * Use ShaderApp.start (the render worker starts first).
   * @param {object} options
   * @param {RenderClient} options.gpu a started render worker's client
   * @param {HTMLCanvasElement} options.canvas
   * @param {import('./channels.js').ChannelLoader} options.loadChannel the channels' files fetched, images decoded (io/shader-loader.js)
   * @param {import('../inputs/media-library.js').FetchMedia} options.fetchMedia a media file's bytes (io/shader-loader.js)
   * @param {string} options.fileName the shader's name in error messages
   * @param {{width:number, height:number} | null} [options.size] fixed drawing-buffer size (device px)
   * @param {number} [options.scale] resolution scale of the device pixels (without a fixed size)
   * @param {number} [options.cap] cap on the drawing buffer's longer side (device px; 0: none)
   * @param {boolean} [options.playing]
   */
  constructor({ gpu, canvas, loadChannel, fetchMedia, fileName, size = null, scale = 1, cap = 0, playing = true }) {
    super();
    this.canvas = canvas;
    /** The shader's name in messages and downloads. */
    this.fileName = fileName;
    /** The render worker, through its client: the GPU side (gpu/). */
    this.gpu = gpu;
    gpu.on('hang', (_, seconds, phase) => this.emit('hang', seconds, phase));
    this.inputs = new ShadertoyInputs();
    if (!playing) this.inputs.pause();
    this.inputs.attach(canvas);
    this.inputs.onMouseChange = () => this.frames.request();
    /** The drawing buffer's size: fixed, or the layout's with scale and cap. */
    this.canvasSize = new CanvasSize(canvas, { maxSide: () => this.gpu.maxSize, fixed: size, scale, cap });
    /** The images in iChannel0..3. */
    this.channels = new Channels(gpu, loadChannel);
    /** The site's media the shader's channels name, from a media folder (none until setBase). */
    this.media = new MediaLibrary(gpu, fetchMedia);
    /** Shadertoy's keyboard texture, for the passes that read it (the page's keys: ui/keys.js). */
    this.keyboard = new KeyboardState();

    /** The shader: its tabs (a plain file is one Image tab). @type {MultipassShader} */
    this.project = singlePass('');
    /** The JSON `info` the shader came with (kept for an export), null for a plain file. @type {object | null} */
    this.projectInfo = null;
    /** What the page cannot give the shader (media a JSON names: black channels). @type {string[]} */
    this.notes = [];
    /** Where the source came from. @type {'builtin' | 'url' | 'editor' | 'file'} */
    this.origin = 'builtin';
    /** The shader's URL as the page was given it, when it came from one (for a shared link). @type {string | null} */
    this.shaderUrl = null;
    /** Shaders loaded so far, each one in place of another (ShaderVersion.load). */
    this._loads = 0;
    /** @type {Control[]} */
    this.controls = [];
    /** The controls' current values, by name. @type {Record<string, any>} */
    this.values = {};
    /** Why the control block could not be read (the shader then runs with its own defaults). @type {string | null} */
    this.notice = null;
    /** The first source on its way (the page's, while it fetches it: setLoading). @type {Promise<void> | null} */
    this.loading = null;
    /** What to run instead of a shader that hung (io/hang-guard.js: setHangGuard), once the page has one. @type {HangFallback | null} */
    this.hangGuard = null;

    /** When to draw, and drawing. */
    this.frames = new FrameLoop({
      gpu,
      canvas,
      inputs: this.inputs,
      canvasSize: this.canvasSize,
      keyboard: this.keyboard,
      readsKeyboard: () => this.readsKeyboard,
      // a frame waits for the site's media its shader names (the first frame of a shader, mostly)
      withMedia: (frame, running) => this.media.frameInputs(() => this.channels.withMedia(frame, running), running),
      isMultipass: () => this.isMultipass,
      hasProgram: () => this.compiles.hasProgram,
      versionOf: (serial) => this.compiles.versionOf(serial),
      onScreen: () => this.compiles.running,
      wantsFrame: (stillFrames) => this.converge.wantsFrame(stillFrames),
      emitDrawn: (frame) => this.emit('drawn', frame),
    });
    /** Compiling the shader, and the shader on screen. */
    this.compiles = new CompileJob({
      gpu,
      version: () => this.version(),
      hostBlock: () => (this.notice ? '' : hostControlBlock(this.controls, this.values, this.liveForm.asConstants ? this.values : null)),
      onceContext: (listener) => this.once('context', listener),
      emitCompile: (error, fileName) => this.emit('compile', error, fileName),
      requestFrame: () => this.frames.request(),
      startClock: () => this.startClock(),
      playing: () => this.inputs.playing,
      setPlaying: (play) => (play ? this.play() : this.pause()),
    });
    /** "Converge when still". */
    this.converge = new Converge({
      source: () => this.source,
      isMultipass: () => this.isMultipass,
      version: () => this.version(),
      loadProject: (project, from) => this.loadProject(project, from),
      runVersion: (version, from, options) => this.runVersion(version, from, options),
      applyControls: (changes, from) => this.applyControls(changes, from),
      pause: () => this.pause(),
      compile: () => this.compiles.compile(),
      requestFrame: () => this.frames.request(),
    });
    /** Whether the next compile takes the live controls as constants or as uniforms. */
    this.liveForm = new LiveControlForm(() => this.compiles.compile().catch(() => {})); // failures are shown on the page

    /** Resolves after the first frame is drawn; rejects if the first compile fails. @type {Promise<void>} */
    this.ready = new Promise((resolve, reject) => {
      this.once('drawn', () => resolve());
      this.on('compile', (_, error) => {
        if (error && !this.compiles.hasProgram) reject(error);
      });
    });
    this.ready.catch(() => {}); // a failure is reported on the page; callers may still await it

    this.canvasSize.watch(() => this.frames.resized());
    watchContext(this);
  }

  /**
   * Starts the render worker, then the app. Rejects with WebGL2UnavailableError when there is no
   * WebGL2.
   * @param {Omit<ConstructorParameters<typeof ShaderApp>[0], 'gpu'>} options
   */
  static async start(options) {
    return new ShaderApp({ ...options, gpu: await RenderClient.start() });
  }

  // ---- source and controls ---------------------------------------------------------------------

  /** The Image tab's text (the whole shader, for a plain file). */
  get source() {
    return this.project.passes.find((pass) => pass.kind === 'image')?.code ?? '';
  }

  /** Whether some pass of the shader reads Shadertoy's keyboard texture. */
  get readsKeyboard() {
    return this.project.passes.some((pass) => pass.channels.some((channel) => channel?.kind === 'keyboard'));
  }

  /** Whether the shader has a Common tab or a buffer (a Sound tab is no part of a frame). */
  get isMultipass() {
    return this.project.common !== null || this.project.passes.filter((pass) => pass.kind !== 'sound').length > 1;
  }

  /**
   * The shader as it is now: its tabs, where it came from, and a copy of its control values.
   * @returns {ShaderVersion}
   */
  version() {
    return {
      project: this.project,
      info: this.projectInfo,
      name: this.fileName,
      origin: this.origin,
      url: this.shaderUrl,
      values: structuredClone(this.values),
      load: this._loads,
    };
  }

  /**
   * Takes a new shader: reads its control blocks (one per tab at most; keeping current values of
   * controls that survive); the page rebuilds its panel on the 'source' event. Then compile
   * (setProject does both). A new shader (not `from.continues`) starts at iFrame 0 once it
   * compiles (compile-job.js).
   * @param {MultipassShader} project
   * @param {ProjectFrom} [from] where it came from
   */
  loadProject(project, from = {}) {
    if (!from.continues) this._loads++;
    const { controls, values, notice } = controlsOf(project, this.controls, this.values);
    this.notice = notice;
    this.project = project;
    this.projectInfo = from.info ?? null;
    this.notes = frameSchedule(project).flatMap((step) => step.bindings.flatMap((binding) => (binding.note ? [binding.note] : [])));
    this.media.load(project);
    if (this.media.pending) this.media.ready().then(() => this.project === project && this.emit('notes'));
    this.liveForm.reset();
    this.converge.drop();
    if (from.name) this.fileName = from.name;
    if (from.origin) {
      this.origin = from.origin;
      this.shaderUrl = from.origin === 'url' ? (from.url ?? null) : from.origin === 'editor' ? this.shaderUrl : null;
    }
    this.controls = controls;
    this.values = values;
    this.gpu.tell('controlUniforms', { controls, values });
    this.emit('source');
  }

  /** The next shader loaded starts from its own defaults (a new page's view: open-view.js), not from these values. */
  forgetValues() {
    this.controls = [];
    this.values = {};
  }

  /**
   * loadProject + compile: resolves on success, rejects with the compile error.
   * @param {MultipassShader} project
   * @param {ProjectFrom} [from]
   */
  setProject(project, from = {}) {
    this.loadProject(project, from);
    return this.compiles.compile();
  }

  /**
   * Loads a shader as it ran (its tabs and its control values); call compile() after.
   * @param {ShaderVersion} version
   * @param {string} from who asks, in warnings
   * @param {{continues?: boolean}} [options] continues: the clock runs on (see loadProject)
   */
  runVersion(version, from, { continues = false } = {}) {
    this.loadProject(version.project, { ...version, continues });
    this.applyControls(version.values ?? {}, from);
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
    const { recompile } = this.applyControls(changes, from);
    if (recompile)
      this.compiles.compile().catch(() => {}); // errors are shown on the page
    else this.frames.request();
    return this.compiles.settled();
  }

  /**
   * setControls without drawing or compiling. Values it cannot use as given are warned about on
   * the console and returned as `warnings` (what was used instead, and why).
   * @param {Record<string, unknown>} changes
   * @param {string} [from] who asks, in warnings
   * @returns {{recompile: boolean, warnings: string[]}} recompile: a compile-time control changed
   */
  applyControls(changes, from = 'setControls') {
    let recompile = false;
    const { read, warnings } = readControlChanges(this.controls, changes, from);
    for (const warning of warnings) console.warn(warning);
    for (const { control, value } of read) {
      const name = control.name;
      const changed = JSON.stringify(value) !== JSON.stringify(this.values[name]);
      this.values[name] = value;
      if (control.kind === 'define') recompile ||= changed;
      else {
        this.gpu.tell('controlUniform', { name, value });
        // Before the first compile there is nothing on screen: that compile takes the new
        // values as constants.
        if (changed && this.compiles.hasProgram && this.liveForm.moved()) recompile = true;
      }
    }
    this.emit('state');
    return { recompile, warnings };
  }

  // ---- time ------------------------------------------------------------------------------------

  play() {
    this.compiles.held = false;
    this.inputs.play();
    this.frames.restartInterval();
    this.emit('state');
    this.frames.request();
  }

  pause() {
    this.compiles.held = false;
    this.inputs.pause();
    this.channels.silence();
    this.media.silence();
    this.emit('state');
  }

  togglePlay() {
    if (this.inputs.playing) this.pause();
    else this.play();
  }

  /** iTime and iFrame back to 0; draws that frame even while paused (a frame under way is drawn again as iFrame 0: frame-loop.js). */
  restart() {
    this.inputs.restart();
    this.gpu.tell('clearBuffers', {}); // Shadertoy's rewind clears every buffer too
    this.emit('state');
    this.frames.request();
  }

  /**
   * A newly loaded shader has compiled: it starts at iFrame 0 and iTime 0 with cleared buffers.
   * Before any frame of the page (the first shader) the clock is where the page set it (a link's
   * ?time=).
   */
  startClock() {
    if (this.inputs.frame > 0 || this.frames.busy) this.restart();
  }

  /** @param {number} seconds */
  setTime(seconds) {
    this.inputs.setTime(Math.max(0, Number(seconds) || 0));
    this.emit('state');
    this.frames.request();
  }

  /** @param {number} speed */
  setSpeed(speed) {
    this.inputs.setSpeed(Math.max(0, Number(speed) || 0));
    this.frames.restartInterval(); // the frames before were at another speed (or none, at 0×)
    this.emit('state');
    this.frames.request();
  }

  /** @param {number[]} mouse iMouse, [x, y, z, w] in device pixels, until the next click */
  setMouse(mouse) {
    this.inputs.setMouse(mouse);
    this.frames.request();
  }

  /** iMouse back to how the page opened (a camera that follows the mouse back to its rest view). */
  resetView() {
    this.inputs.resetMouse();
    this.emit('state');
    this.frames.request();
  }

  // ---- what the page gives it -------------------------------------------------------------------

  /**
   * The source on its way (calls that need the shader's controls wait for it).
   * @param {Promise<void>} loading
   */
  setLoading(loading) {
    this.loading = loading;
  }

  /**
   * What remembers the shader that hung and what to run instead (io/hang-guard.js).
   * @param {HangFallback} guard
   */
  setHangGuard(guard) {
    this.hangGuard = guard;
  }

  // ---- size and channels -----------------------------------------------------------------------

  /** @param {number} scale resolution scale of the device pixels */
  setScale(scale) {
    this.canvasSize.setScale(scale);
    this.emit('state');
    this.frames.request();
  }

  /** @param {number} cap cap on the drawing buffer's longer side, in device pixels (0: none) */
  setCap(cap) {
    this.canvasSize.setCap(cap);
    this.emit('state');
    this.frames.request();
  }

  /**
   * Loads an image (URL, File or Blob) into iChannel0..3; null empties the channel.
   * @param {number} index
   * @param {string | Blob | null} source
   */
  async setChannel(index, source) {
    await this.channels.set(index, source);
    this.emit('state');
    this.frames.request();
  }
}
