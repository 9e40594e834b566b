// window.shaderEngine on the engine page (installEngine): what a headless run needs of the engine
// and no more. The command line (src/headless/client.js), the test harness and the benchmark drive
// it; the interactive page adds its own widgets' methods for its tests (page-hook.js). Each
// method is documented here once; the hook's type is the class itself (EngineHook: the command
// line's client reads the window through hook-window.js's HookedWindow; tests/globals.ts declares
// the window's field as page-hook.js's PageHook). A page that could not start has a hook of the
// same methods, each rejecting (failed-hook.js).
//
//   ready                 Promise: resolves after the first frame has been drawn; rejects with
//                         the error when WebGL2 is missing or the first compile fails.
//   settled()             Promise: resolves once the first source is in and no compile is under
//                         way (what the methods below wait for first).
//   open(query)           Promise: the page as a fresh load of `query` ("?shader=…&size=…&time=…
//                         &NAME=value", and a "#source=…" fragment) would give it, without a
//                         reload (open-view.js): its shader, controls, size, clock, mouse,
//                         channels and notes (and on the interactive page, its kept edits; the
//                         inspector off). Resolves once its
//                         first frame is drawn; rejects with the compile error, or with why
//                         its shader could not be loaded (never the built-in in its place).
//   readPixels()          Promise<{width, height, data}>: draws one frame and reads it back (the
//                         render worker keeps each frame in a render target). `data` is base64
//                         of RGBA8 pixels, rows top to bottom, alpha 255 (as the canvas shows).
//   readFrame()           Promise<{width, height, iFrame, data}>: the last frame drawn, read back
//                         as it was drawn; draws nothing (a view's still is its frame 0, as
//                         open() drew it). `data` as readPixels's.
//   renderFrames(n)       Promise<{median, times}>: the render worker draws n whole frames back
//                         to back, each a single draw followed by a 1-pixel readPixels so the
//                         GPU has finished; `times` are the n per-frame times in ms, `median`
//                         their median.
//   setControls({NAME: value})   Promise: sets shader controls (as the URL does: coerced into
//                         range, unknown names warned about); resolves once compiled.
//   setSource(glsl)       Promise<{ok, error?}>: compiles another Image-tab source.
//   setProject(json)      Promise<{ok, error?, notes}>: runs a multipass shader given as
//                         Shadertoy's JSON export (an object or its text).
//   setConverging(on, {frames, overlays}?)  Promise: "Converge when still" on or off
//                         (app.converge): frames: how many still frames to draw (default: the
//                         form's most); overlays false: the form's on-screen overlays off (a
//                         sample count drawn over the picture), for a render of the picture alone.
//   play(), pause(), togglePlay(), restart(), setTime(seconds), setSpeed(s), setMouse([x, y, z, w]),
//   resetView()          iMouse back to how the page opened (the toolbar's "Reset view")
//   nextFrame()           Promise<{width, height, data, iFrame}>: the next frame the page draws by
//                         itself (after a click, a key, a play tick), read back; rows top to
//                         bottom. Asks for no frame.
//   loseContext(), restoreContext()   the render worker's context lost or restored through
//                         WEBGL_lose_context (the tests of a lost context).
//   capture({width, height}?)  Promise<{width, height, data}>: the last frame drawn again off
//                         screen at that size (default: the canvas's), as the Screenshot button
//                         saves it.
//   captureTile({x, y, width, height, fullWidth, fullHeight})  Promise<{width, height, data}>:
//                         the tile at (x, y) (from the bottom left) of the last frame drawn at
//                         fullWidth × fullHeight, for a picture larger than one draw (the
//                         command line's --tile); x and y even keep the quads of the whole
//                         picture. A shader with buffers rejects.
//   captureFloat()        Promise<{width, height, data}>: the last frame's Image pass drawn again
//                         in RGBA32F, its colours as the shader wrote them (unclamped, NaN and
//                         infinity kept), rows top to bottom; `data` is base64 of the floats'
//                         bytes (little-endian), as the inspector reads a pixel.
//   setChannel(i, url|null)    Promise: an image into iChannel i (null: black again).
//   loadShader(url)       Promise<{ok, error?}>: fetches and runs a shader as ?shader= does
//                         (GLSL, or Shadertoy's JSON export).
//   record({format, frames | duration, fps, width, height})  Promise<{format, frames, fps,
//                         width, height, codec, mimeType, data}>: records the shader frame by
//                         frame as the Record button does (recorder.js: 'webm' or 'png', a .zip
//                         of PNGs); `data` is the file as base64. Rejects with RecordingCancelled
//                         after cancelRecording().
//   frameAt({frame, fps, width, height})  Promise<{width, height, data}>: frame `frame` as
//                         record() would draw it (iTime = frame / fps, iFrame = frame), and no
//                         file: a shader with buffers has every frame before it drawn first
//                         (recorder.js frameAt); no cap on `frame`. `data` is base64 RGBA8, rows
//                         top to bottom. Its progress is recording()'s.
//   renderSound({time, duration})  Promise<{sampleRate, channels, samples, data}>: the Sound
//                         tab's samples from `time` (default 0) for `duration` seconds (default
//                         60, as the site's WAV export), drawn as the site draws them
//                         (sound/sound-pass.js); `data` is base64 of interleaved little-endian
//                         Int16 (left, right). Rejects for a shader without a Sound tab.
//   loopCuts(reset?)      Promise<{enabled, cuts, unchecked}>: what llvmpipe's loop limit cut short
//                         since the last reset, pass by pass (gpu/loop-cuts.js), and the passes
//                         drawn unchecked; enabled: whether passes are guarded (on llvmpipe).
//   setLoopGuard({stopOnCut, guard})  whether a frame with a cut stops at that band (the
//                         command line's default renderer then draws it again with SwiftShader);
//                         guard false: passes compiled after are not guarded (to time the guard).
//   cancelRecording()     stops the recording under way (this one or the Record button's).
//   recording()           {busy, done, total}: whether a recording is under way, and how many
//                         frames of the last record() or frameAt() are done, of how many.
//   notes(), hang(), info()   what the page says of itself, as data (engine-state.js).
//
// The page's state is also on the page as attributes the tests wait on (page-marks.js:
// data-error, data-context, data-hung on <html>, data-frame on the canvas).
//
// Every method waits for `ready` and for any compile under way, so a call right after
// setControls() sees the new values.

import { toBase64 } from '../../shared/pixels.js';
import { median } from '../../shared/stats.js';
import { openShader, openShaderUrl } from '../io/open-shader.js';
import { singlePass } from '../../shadertoy/multipass.js';
import { SAMPLE_RATE, toPcm16 } from '../../shadertoy/sound.js';
import { hasSound, sampleRange, soundSamples } from '../sound/samples.js';
import { markApp } from '../page-marks.js';
import { EngineState } from './engine-state.js';

/** @typedef {import('../app/app.js').ShaderApp} ShaderApp */
/** An image read back: base64 RGBA8, rows top to bottom. @typedef {{width: number, height: number, data: string}} HookImage */

/**
 * What an entry page gives the hook: its `ready` (the first frame), open() (open-view.js as that
 * page opens a view) and the recorder it owns.
 * @typedef {object} EngineHost
 * @property {Promise<void>} ready
 * @property {(query: string) => Promise<void>} open
 * @property {import('../io/recorder.js').Recorder} recorder
 */

export class EngineHook {
  /** The app the hook drives. */
  #app;
  /** @type {EngineHost['open']} */
  #open;
  #recorder;
  /** One open() at a time; the one before is waited for. @type {Promise<unknown>} */
  #opening = Promise.resolve();
  /** The last record()'s progress: frames done of total. */
  #recorded = { done: 0, total: 0 };
  /** What the page says of itself (notes, hang, info). @type {EngineState} */
  #state;

  /**
   * @param {ShaderApp} app
   * @param {EngineHost} host
   */
  constructor(app, { ready, open, recorder }) {
    this.#app = app;
    this.#open = open;
    this.#recorder = recorder;
    /** Resolves after the first frame has been drawn; rejects when the first compile fails. */
    this.ready = ready;
    this.#state = new EngineState(app);
  }

  /** The first source may still be on its way (?shader= is fetched): calls wait for it. */
  async #loaded() {
    await (this.#app.loading ?? Promise.resolve()).catch(() => {});
  }

  /**
   * Resolves once the first source is loaded and no compile is under way, with a shader to draw.
   * A first compile that failed rejects `ready` for good; once another shader has compiled, that
   * old error no longer stands in the way.
   */
  async settled() {
    await this.#loaded();
    await this.#app.compiles.settled();
    if (!this.#app.compiles.hasProgram) await this.ready;
  }

  /** Why there is no frame to read: no shader, or no context. */
  #nothing() {
    return new Error(this.#app.gpu.contextLost ? 'the GPU context is lost' : 'no shader is running');
  }

  /** @param {string} query */
  open(query) {
    const previous = this.#opening;
    const next = (async () => {
      await previous.catch(() => {});
      await this.#loaded();
      await this.#app.compiles.settled();
      await this.#open(query);
    })();
    this.#opening = next;
    return next;
  }

  /** @returns {Promise<HookImage>} */
  async readPixels() {
    await this.settled();
    const drawn = await this.#app.frames.draw(performance.now(), true);
    if (!drawn?.pixels) throw this.#nothing();
    return { width: drawn.width, height: drawn.height, data: toBase64(drawn.pixels) };
  }

  /** @returns {Promise<HookImage & {iFrame: number}>} */
  async readFrame() {
    await this.settled();
    const drawn = await this.#app.frames.readLast();
    return { width: drawn.width, height: drawn.height, iFrame: drawn.frame, data: toBase64(drawn.data) };
  }

  /** @param {number} [n] */
  async renderFrames(n = 1) {
    await this.settled();
    const app = this.#app;
    await app.frames.draw(); // sizes the worker's frame, as the page draws it
    const inputs = app.frames.last;
    if (!inputs) throw this.#nothing();
    /** @type {number[]} */
    const times = await app.gpu.ask('bench', { inputs, n });
    return { median: median(times), times };
  }

  /** @param {Record<string, unknown>} changes */
  async setControls(changes) {
    await this.#loaded(); // the shader's controls are known; its first frame need not be drawn yet
    await this.#app.setControls(changes);
  }

  /** @param {string} source */
  async setSource(source) {
    await this.#loaded();
    try {
      await this.#app.setProject(singlePass(source), { origin: 'editor' });
      return { ok: true };
    } catch (error) {
      return { ok: false, error: /** @type {string} */ (error.report ?? error.message) };
    }
  }

  /** @param {string | Record<string, unknown>} json Shadertoy's JSON export, or its text */
  async setProject(json) {
    await this.#loaded();
    const app = this.#app;
    try {
      const text = typeof json === 'string' ? json : JSON.stringify(json);
      const opened = openShader(app, text, { name: app.fileName, origin: 'editor', json: true });
      await opened.running;
      return { ok: true, notes: [...opened.notes, ...app.notes] };
    } catch (error) {
      return { ok: false, error: /** @type {string} */ (error.report ?? error.message), notes: /** @type {string[]} */ ([]) };
    }
  }

  /** @param {boolean} on @param {{frames?: number, overlays?: boolean}} [options] */
  async setConverging(on, { frames, overlays = true } = {}) {
    await this.settled();
    const converge = this.#app.converge;
    await converge.set(Boolean(on), { frames });
    const off = converge.overlaysOff;
    if (!overlays && Object.keys(off).length) await this.#app.setControls(off, 'setConverging');
  }

  play() {
    this.#app.play();
  }
  pause() {
    this.#app.pause();
  }
  togglePlay() {
    this.#app.togglePlay();
  }
  restart() {
    this.#app.restart();
  }
  /** @param {number} seconds */
  setTime(seconds) {
    this.#app.setTime(seconds);
  }
  /** @param {number} speed */
  setSpeed(speed) {
    this.#app.setSpeed(speed);
  }
  /** @param {number[]} mouse iMouse, [x, y, z, w] */
  setMouse(mouse) {
    this.#app.setMouse(mouse);
  }
  resetView() {
    this.#app.resetView();
  }

  /** Read in the same task as the frame was drawn (no preserveDrawingBuffer). @returns {Promise<HookImage & {iFrame: number}>} */
  async nextFrame() {
    const app = this.#app;
    app.frames.readBackNextFrame();
    /** @type {{width: number, height: number, frame: number, pixels: Uint8Array}} */
    const drawn = await new Promise((resolve) => {
      /** @param {unknown} _ @param {{pixels?: Uint8Array | null}} frame */
      const wait = (_, frame) => (frame.pixels ? resolve(/** @type {any} */ (frame)) : app.once('drawn', wait));
      app.once('drawn', wait);
    });
    return { width: drawn.width, height: drawn.height, iFrame: drawn.frame, data: toBase64(drawn.pixels) };
  }

  loseContext() {
    this.#app.gpu.tell('loseContext', {});
  }
  restoreContext() {
    this.#app.gpu.tell('restoreContext', {});
  }

  /** @param {{width: number, height: number} | null} [size] @returns {Promise<HookImage>} */
  async capture(size = null) {
    await this.settled();
    const { width, height, data } = await this.#app.frames.capture(size);
    return { width, height, data: toBase64(data) };
  }

  /**
   * @param {{x: number, y: number, width: number, height: number, fullWidth: number, fullHeight: number}} tile
   * @returns {Promise<HookImage>}
   */
  async captureTile({ x, y, width, height, fullWidth, fullHeight }) {
    await this.settled();
    const inputs = this.#app.frames.last;
    if (!inputs) throw this.#nothing();
    const data = await this.#app.gpu.ask('captureTile', { inputs, x, y, width, height, fullWidth, fullHeight });
    return { width, height, data: toBase64(data) };
  }

  /** @returns {Promise<HookImage>} */
  async captureFloat() {
    await this.settled();
    const inputs = this.#app.frames.last;
    if (!inputs) throw this.#nothing();
    const { width, height } = inputs;
    /** @type {Float32Array} */
    const floats = await this.#app.gpu.ask('captureFloat', { inputs, width, height });
    return { width, height, data: toBase64(new Uint8Array(floats.buffer, floats.byteOffset, floats.byteLength)) };
  }

  /** @param {number} index @param {string | null} url */
  async setChannel(index, url) {
    await this.#app.setChannel(index, url);
  }

  /** @param {string} url */
  async loadShader(url) {
    await this.#loaded();
    try {
      await openShaderUrl(this.#app, url);
      return { ok: true };
    } catch (error) {
      return { ok: false, error: /** @type {string} */ (error.report ?? error.message) };
    }
  }

  /** @param {import('../io/recorder.js').RecordRequest} [request] */
  async record(request = {}) {
    await this.settled();
    this.#recorded = { done: 0, total: 0 };
    const { bytes, ...result } = await this.#recorder.record(request, (done, total) => (this.#recorded = { done, total }));
    return { ...result, data: toBase64(bytes) };
  }

  /** @param {{frame: number, fps?: number, width?: number, height?: number}} request @returns {Promise<HookImage>} */
  async frameAt(request) {
    await this.settled();
    this.#recorded = { done: 0, total: 0 };
    const { data, ...size } = await this.#recorder.frameAt(request, (done, total) => (this.#recorded = { done, total }));
    return { ...size, data: toBase64(data) };
  }

  /** @param {{time?: number, duration?: number}} [request] */
  async renderSound({ time = 0, duration = 60 } = {}) {
    await this.settled();
    const app = this.#app;
    if (!hasSound(app)) throw new Error('this shader has no Sound tab');
    const { first, count } = sampleRange(time, duration);
    const pcm = toPcm16(await soundSamples(app, first, count));
    return { sampleRate: SAMPLE_RATE, channels: 2, samples: count, data: toBase64(new Uint8Array(pcm.buffer)) };
  }

  /**
   * What llvmpipe's loop limit cut short since the last reset (src/player/gpu/loop-cuts.js).
   * @param {boolean} [reset] start a new log
   * @returns {Promise<import('../gpu/protocol.js').LoopReport>}
   */
  loopCuts(reset = false) {
    return this.#app.gpu.ask('loopCuts', { reset });
  }

  /**
   * @param {{stopOnCut: boolean, guard?: boolean}} setting stopOnCut: whether a frame with a loop
   *   cut stops at that band (its picture thrown away); guard: whether passes compiled from now
   *   on are guarded on llvmpipe (false only to time the guard)
   */
  setLoopGuard({ stopOnCut, guard = true }) {
    this.#app.gpu.setLoopGuard({ stopOnCut, guard });
  }

  cancelRecording() {
    this.#recorder.cancel();
  }
  recording() {
    return { busy: this.#recorder.busy, ...this.#recorded };
  }

  notes() {
    return this.#state.notes();
  }
  hang() {
    return this.#state.hang();
  }
  info() {
    return this.#state.info();
  }
}

/**
 * Installs the engine's hook on the window for `app`, with the page's marks (page-marks.js).
 * @param {ShaderApp} app
 * @param {EngineHost} host
 */
export function installEngine(app, host) {
  markApp(app);
  return hookOnWindow(new EngineHook(app, host));
}

/**
 * Puts `hook` on the window as window.shaderEngine.
 * @template {EngineHook} T
 * @param {T} hook
 * @returns {T}
 */
export function hookOnWindow(hook) {
  /** @type {{shaderEngine: unknown}} */ (/** @type {unknown} */ (window)).shaderEngine = hook;
  return hook;
}
