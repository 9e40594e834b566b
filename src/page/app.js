// The page's state and frame loop: one shader source, its control values, the Shadertoy inputs,
// the canvas size, and when to draw. While playing it draws every animation frame; while paused
// it draws on demand (a control change, a resize, the mouse), once per request.

import { coerceControlValue, controlDefaults, parseControls } from '../shadertoy/controls.js';
import { hostControlBlock } from '../shadertoy/header.js';
import { ShaderRenderer } from './renderer.js';
import { ShadertoyInputs, writeUniforms } from './shadertoy-inputs.js';
import { clampSize } from './url-params.js';
import { flipRows } from './pixels.js';

/**
 * How long the live controls must rest before the shader is recompiled with them as constants.
 * A `const` control is a uniform in the page so that a slider applies without a compile; but
 * then the compiler folds nothing, and the frame costs more than the pasted shader's (measured
 * on SwiftShader at 640x360: npm run bench, "page form (uniforms)"). So while the controls are
 * still, the page runs the shader exactly as it pastes, with the current values as constants,
 * and goes back to the uniform form (kept compiled) as soon as one moves.
 */
export const SPECIALIZE_AFTER_MS = 400;


export class RaytracerApp {
  /**
   * @param {object} options
   * @param {HTMLCanvasElement} options.canvas
   * @param {import('./overlay.js').Overlay} options.overlay
   * @param {string} options.fileName the shader's name in error messages
   * @param {{width:number, height:number}} [options.size] fixed drawing-buffer size (device px)
   * @param {number} [options.scale] resolution scale of the device pixels (without a fixed size)
   * @param {number} [options.cap] cap on the drawing buffer's longer side (device px; 0: none)
   * @param {boolean} [options.playing]
   * Throws WebGL2UnavailableError when there is no WebGL2.
   */
  constructor({ canvas, overlay, fileName, size = null, scale = 1, cap = 0, playing = true }) {
    this.canvas = canvas;
    this.overlay = overlay;
    this.fileName = fileName;
    this.renderer = new ShaderRenderer(canvas);
    this.inputs = new ShadertoyInputs();
    this.inputs.playing = playing;
    this.inputs.attach(canvas);
    this.inputs.onMouseChange = () => this.requestRender();

    this.source = '';
    /** Where the source came from: 'builtin', 'url' (shaderUrl), 'editor' or 'file'. */
    this.origin = 'builtin';
    /** The shader's URL as the page was given it, when it came from one (for a shared link). */
    this.shaderUrl = null;
    this.channelUrls = [null, null, null, null];
    this.controls = [];
    this.values = {};
    this.notice = null; // a problem with the control block, shown with the overlay
    this.pendingNotice = null; // {title, detail}: shown instead of hiding the overlay after the next compile
    this.fixedSize = size ? this._fitGpu(size, 'size') : null;
    this.scale = scale;
    this.cap = cap;
    this.framesRendered = 0;
    this.compiled = 0; // successful compiles
    this.compileErrors = []; // messages of the last failed compile ({line, message}), [] after success

    /** Listeners the page's widgets hang on: each gets the app. */
    this.listeners = { state: [], frame: [], compile: [], source: [] };

    this._latestCompile = null;
    /** Whether the next compile takes the live controls as constants (see SPECIALIZE_AFTER_MS). */
    this.liveAsConstants = true;
    this._specializeTimer = 0;
    this._raf = 0;
    this._frameWaiters = [];
    this._lastFrameAt = null;

    this.ready = new Promise((resolve, reject) => {
      this._readyResolve = resolve;
      this._readyReject = reject;
    });
    this.ready.catch(() => {}); // a failure is reported on the page; callers may still await it

    this._watchSize();
    this._watchContext();
  }

  on(event, listener) {
    this.listeners[event].push(listener);
  }

  _emit(event, ...args) {
    for (const listener of this.listeners[event]) listener(this, ...args);
  }

  // ---- source and controls ---------------------------------------------------------------------

  /**
   * Takes a new shader source: reads its control block (keeping current values of controls that
   * survive), rebuilds the panel. Call compile() after.
   * @param {string} source
   * @param {{name?: string, origin?: string, url?: string|null}} [from] where it came from
   */
  loadSource(source, from = {}) {
    let controls = [];
    this.notice = null;
    try {
      controls = parseControls(source);
    } catch (error) {
      this.notice = `${error.message}\nThe shader runs with its own defaults and no panel controls.`;
    }
    const values = controlDefaults(controls);
    for (const c of controls) {
      const old = this.controls.find((o) => o.name === c.name && o.type === c.type);
      const kept = old ? coerceControlValue(c, this.values[c.name]) : undefined;
      if (kept !== undefined) values[c.name] = kept;
    }
    this.source = source;
    this.liveAsConstants = true;
    clearTimeout(this._specializeTimer);
    if (from.name) this.fileName = from.name;
    if (from.origin) {
      this.origin = from.origin;
      this.shaderUrl = from.origin === 'url' ? from.url : from.origin === 'editor' ? this.shaderUrl : null;
    }
    this.controls = controls;
    this.values = values;
    this.renderer.setControlUniforms(controls, values);
    this._emit('source');
  }

  /** loadSource + compile: resolves on success, rejects with the compile error. */
  setSource(source, from = {}) {
    this.loadSource(source, from);
    return this.compile();
  }

  /**
   * Sets controls by name ({NAME: value}; vectors as arrays or "x,y,z"). Values are coerced into
   * range; unknown names and unreadable values are warned about and skipped. Resolves once the
   * change is on screen (after a recompile, for compile-time controls).
   */
  setControls(changes, from = 'setControls') {
    const recompile = this.applyControls(changes, from);
    if (recompile) this.compile().catch(() => {}); // errors are shown on the page
    else this.requestRender();
    return this.whenCompiled();
  }

  /** setControls without drawing or compiling: returns true if a compile-time control changed. */
  applyControls(changes, from = 'setControls') {
    let recompile = false;
    for (const [name, raw] of Object.entries(changes)) {
      const control = this.controls.find((c) => c.name === name);
      if (!control) {
        console.warn(`${from}: ${name} ignored: no such shader control.`);
        continue;
      }
      const value = coerceControlValue(control, raw);
      if (value === undefined) {
        console.warn(`${from}: ${name}=${JSON.stringify(raw)} ignored: not a valid ${control.type}.`);
        continue;
      }
      if (typeof raw === 'string' && typeof value !== 'boolean') {
        const written = Array.isArray(value) ? raw.split(',').map(Number) : Number(raw);
        if (JSON.stringify(written) !== JSON.stringify(value)) console.warn(`${from}: ${name}=${raw} is out of range: using ${value}.`);
      }
      const changed = JSON.stringify(value) !== JSON.stringify(this.values[name]);
      this.values[name] = value;
      if (control.kind === 'define') recompile ||= changed;
      else {
        this.renderer.setControlUniform(name, value);
        // The shader on screen has the old value as a constant: back to the uniform form, and
        // to the constant form again once the controls rest. (Before the first compile there
        // is nothing on screen: that compile takes the new values as constants.)
        if (changed && this.renderer.hasProgram) {
          if (this.liveAsConstants) recompile = true;
          this.liveAsConstants = false;
          this._specializeWhenStill();
        }
      }
    }
    this._emit('state');
    return recompile;
  }

  _specializeWhenStill() {
    clearTimeout(this._specializeTimer);
    this._specializeTimer = setTimeout(() => {
      this.liveAsConstants = true;
      this.compile().catch(() => {}); // a failure is shown like any other
    }, SPECIALIZE_AFTER_MS);
  }

  /** The controls whose values differ from the shader's defaults. */
  changedControls() {
    const defaults = controlDefaults(this.controls);
    return Object.fromEntries(Object.entries(this.values).filter(([name, v]) => JSON.stringify(v) !== JSON.stringify(defaults[name])));
  }

  /**
   * Compiles the source with the current compile-time values. On success the new shader is
   * drawn; on failure the error is shown and the last shader that compiled keeps running.
   */
  compile() {
    if (this.renderer.contextLost) {
      // compiled when the context comes back (webglcontextrestored compiles the latest source)
      const job = new Promise((resolve, reject) => this._afterRestore.push({ resolve, reject }));
      this._latestCompile = job;
      return job;
    }
    const defines = Object.fromEntries(this.controls.filter((c) => c.kind === 'define').map((c) => [c.name, this.values[c.name]]));
    const hostBlock = this.notice ? '' : hostControlBlock(this.controls, defines, this.liveAsConstants ? this.values : null);
    const fileName = this.fileName;
    const job = this.renderer.compile(this.source, hostBlock, fileName).then(
      () => {
        if (job !== this._latestCompile) return;
        this.compileErrors = [];
        this.compiled++;
        if (this.notice) this.overlay.show(`Control block of ${fileName} not read`, this.notice);
        else if (this.pendingNotice) this.overlay.show(this.pendingNotice.title, this.pendingNotice.detail);
        else this.overlay.hide();
        this.pendingNotice = null;
        delete document.documentElement.dataset.error;
        this._emit('compile', null);
        this.requestRender();
      },
      (error) => {
        if (job === this._latestCompile) {
          const fallback = this.renderer.hasProgram ? ' (still showing the last version that compiled)' : '';
          this.compileErrors = error.messages ?? [];
          this.overlay.show(`${fileName} did not compile${fallback}`, error.report ?? error.message);
          console.warn(error.message);
          if (!this.renderer.hasProgram) {
            document.documentElement.dataset.error = 'shader-compile';
            this._readyReject(error);
          }
          this._emit('compile', error);
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
    this._emit('state');
    this.requestRender();
  }

  pause() {
    this.inputs.pause();
    this._emit('state');
  }

  togglePlay() {
    if (this.inputs.playing) this.pause();
    else this.play();
  }

  /** iTime and iFrame back to 0; draws that frame even while paused. */
  restart() {
    this.inputs.restart();
    this._emit('state');
    this.requestRender();
  }

  setTime(seconds) {
    this.inputs.setTime(Math.max(0, Number(seconds) || 0));
    this._emit('state');
    this.requestRender();
  }

  setSpeed(speed) {
    this.inputs.setSpeed(Math.max(0, Number(speed) || 0));
    this._emit('state');
  }

  setMouse(mouse) {
    this.inputs.setMouse(mouse);
    this.requestRender();
  }

  // ---- size ------------------------------------------------------------------------------------

  setScale(scale) {
    this.scale = scale;
    this._emit('state');
    this.requestRender();
  }

  /** Caps the drawing buffer's longer side at `cap` device pixels (0: no cap). */
  setCap(cap) {
    this.cap = Math.max(0, Math.round(Number(cap) || 0));
    this._emit('state');
    this.requestRender();
  }

  /** A size the GPU can draw: scaled down, with a warning, if a side exceeds its limit. */
  _fitGpu(size, what) {
    const max = this.renderer.maxSize;
    if (!max) return size;
    const fitted = clampSize(size, max);
    if (fitted.width !== size.width || fitted.height !== size.height) {
      console.warn(`${what} ${size.width}x${size.height} is larger than this GPU draws (${max} px a side): using ${fitted.width}x${fitted.height}`);
    }
    return fitted;
  }

  /** The drawing-buffer size for the current layout, in device pixels. */
  targetSize() {
    if (this.fixedSize) return this.fixedSize;
    const dpr = window.devicePixelRatio || 1;
    let width = Math.max(1, Math.round(this.canvas.clientWidth * dpr * this.scale));
    let height = Math.max(1, Math.round(this.canvas.clientHeight * dpr * this.scale));
    const longest = Math.max(width, height);
    const cap = Math.min(this.cap || Infinity, this.renderer.maxSize || Infinity);
    if (longest > cap) {
      width = Math.max(1, Math.round((width * cap) / longest));
      height = Math.max(1, Math.round((height * cap) / longest));
    }
    return { width, height };
  }

  /**
   * A fixed size is in device pixels: its CSS size is that over devicePixelRatio, unscaled, and
   * shrunk (keeping its aspect) when it would not fit the window.
   */
  _fitFixedSize() {
    if (!this.fixedSize) return;
    const dpr = window.devicePixelRatio || 1;
    const css = { width: this.fixedSize.width / dpr, height: this.fixedSize.height / dpr };
    const room = this.canvas.parentElement ?? document.documentElement;
    const k = Math.min(1, (room.clientWidth || css.width) / css.width, (room.clientHeight || css.height) / css.height);
    this.canvas.style.width = `${css.width * k}px`;
    this.canvas.style.height = `${css.height * k}px`;
  }

  _watchSize() {
    this._fitFixedSize();
    const check = () => {
      this._fitFixedSize();
      const { width, height } = this.targetSize();
      if (width !== this.canvas.width || height !== this.canvas.height) this.requestRender();
    };
    new ResizeObserver(check).observe(this.canvas);
    // the canvas's size in device pixels also changes with devicePixelRatio alone
    try {
      new ResizeObserver(check).observe(this.canvas, { box: 'device-pixel-content-box' });
    } catch {
      // not supported (Safari): the media query below catches ratio changes
    }
    if (this.fixedSize && this.canvas.parentElement) new ResizeObserver(check).observe(this.canvas.parentElement);
    window.addEventListener('resize', check);
    // A devicePixelRatio change (zoom, moving the window to another screen) need not resize
    // anything in CSS pixels: watch the ratio itself, re-arming the query for each new value.
    const watchRatio = () => {
      const query = matchMedia(`(resolution: ${window.devicePixelRatio || 1}dppx)`);
      query.addEventListener(
        'change',
        () => {
          check();
          watchRatio();
        },
        { once: true },
      );
    };
    watchRatio();
    // Not every ratio change fires those (emulated device metrics, some zoom paths): a cheap
    // check twice a second catches the rest.
    let ratio = window.devicePixelRatio;
    setInterval(() => {
      if (window.devicePixelRatio !== ratio) {
        ratio = window.devicePixelRatio;
        check();
      }
    }, 500);
  }

  // ---- the GPU context -------------------------------------------------------------------------

  _watchContext() {
    this._afterRestore = [];
    this.canvas.addEventListener('webglcontextlost', (event) => {
      event.preventDefault(); // tells the browser we want it back (three.js does too)
      document.documentElement.dataset.context = 'lost';
      this.overlay.show('The GPU context was lost', 'The browser took the graphics context away (a driver reset, or too many pages using the GPU). The picture comes back when the browser restores it.');
      this._emit('state');
    });
    this.canvas.addEventListener('webglcontextrestored', () => {
      delete document.documentElement.dataset.context;
      this.renderer.forgetCompiled();
      // three.js has rebuilt its state; programs and textures are made again from our objects.
      const waiting = this._afterRestore.splice(0);
      const job = this.compile();
      job.then(
        () => waiting.forEach((w) => w.resolve()),
        (error) => waiting.forEach((w) => w.reject(error)),
      );
      job.catch(() => {});
      this._emit('state');
      this.requestRender();
    });
  }

  // ---- drawing ---------------------------------------------------------------------------------

  /** Draws at the next animation frame (once, however often it is asked). */
  requestRender() {
    if (!this._raf) this._raf = requestAnimationFrame((now) => this._tick(now));
  }

  _tick(now) {
    this._raf = 0;
    const drawn = this.renderNow(now);
    if (drawn && this.inputs.playing) {
      if (this._lastFrameAt !== null) this._emit('frame', now - this._lastFrameAt);
      this._lastFrameAt = now;
    } else {
      this._lastFrameAt = null;
    }
    if (this.inputs.playing) this.requestRender();
  }

  /**
   * Draws one frame now (synchronously). Returns false when no shader has compiled yet or the
   * context is lost.
   * @param {number} now timestamp in ms (performance.now() or a rAF time)
   */
  renderNow(now = performance.now()) {
    if (this.renderer.contextLost) return false;
    const { width, height } = this.targetSize();
    this.renderer.setSize(width, height);
    if (!this.renderer.hasProgram) return false;
    this.inputs.beginFrame(this.renderer.uniforms, this.renderer.width, this.renderer.height, now);
    this.renderer.render();
    this.inputs.endFrame();
    this.framesRendered++;
    this.canvas.dataset.frame = String(this.framesRendered);
    if (this.framesRendered === 1) this._readyResolve();
    if (this._frameWaiters.length) {
      const pixels = this.renderer.readPixels();
      const frame = { width: this.renderer.width, height: this.renderer.height, pixels, iFrame: this.inputs.last.frame };
      for (const resolve of this._frameWaiters.splice(0)) resolve(frame);
    }
    return true;
  }

  /**
   * Resolves with the next frame the page draws by itself (rows bottom to top), read in the
   * same task: { width, height, pixels, iFrame }. Does not ask for a frame.
   */
  nextFrame() {
    return new Promise((resolve) => this._frameWaiters.push(resolve));
  }

  // ---- output ----------------------------------------------------------------------------------

  /**
   * The last drawn frame drawn again at width × height (default: the canvas size), with the same
   * iTime, iFrame, iDate, and iMouse scaled to the new size. Rows top to bottom.
   * @returns {{width:number, height:number, data:Uint8Array}}
   */
  capture(size = null) {
    if (!this.renderer.hasProgram || this.renderer.contextLost) throw new Error('nothing to capture: no shader is running');
    if (!this.inputs.last) this.renderNow();
    const last = this.inputs.last;
    const wanted = size ?? { width: last.width, height: last.height };
    const { width, height } = this._fitGpu({ width: Math.max(1, Math.round(wanted.width)), height: Math.max(1, Math.round(wanted.height)) }, 'screenshot size');
    writeUniforms(this.renderer.uniforms, last, { width, height });
    try {
      const pixels = this.renderer.renderOffscreen(width, height);
      return { width, height, data: flipRows(pixels, width, height) };
    } finally {
      writeUniforms(this.renderer.uniforms, last);
    }
  }

  /** Loads an image (URL, File or Blob) into iChannel0..3; null empties the channel. */
  async setChannel(index, source) {
    if (!(index >= 0 && index <= 3)) throw new Error(`no channel ${index}: iChannel0..3`);
    if (source === null) {
      this.renderer.setChannel(index, null);
      this.channelUrls[index] = null;
    } else {
      const isUrl = typeof source === 'string';
      const url = isUrl ? source : URL.createObjectURL(source);
      try {
        const image = new Image();
        image.src = url;
        await image.decode().catch(() => {
          throw new Error(`cannot load ${isUrl ? source : source.name ?? 'the image'} as an image`);
        });
        this.renderer.setChannel(index, image);
      } finally {
        if (!isUrl) setTimeout(() => URL.revokeObjectURL(url), 0);
      }
      this.channelUrls[index] = isUrl ? source : null;
    }
    this._emit('state');
    this.requestRender();
  }
}
