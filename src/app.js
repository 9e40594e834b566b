// The page's state and frame loop: one shader source, its control values, the Shadertoy inputs,
// the canvas size, and when to draw. While playing it draws every animation frame; while paused
// it draws on demand (a control change, a resize, the mouse), once per request.

import { coerceControlValue, controlDefaults, parseControls } from './controls.js';
import { hostControlBlock } from './shadertoy.js';
import { ShaderRenderer } from './renderer.js';
import { ShadertoyInputs } from './shadertoy-inputs.js';
import { Panel } from './panel.js';

export class RaytracerApp {
  /**
   * @param {object} options
   * @param {HTMLCanvasElement} options.canvas
   * @param {import('./overlay.js').Overlay} options.overlay
   * @param {string} options.fileName the shader's name in error messages
   * @param {{width:number, height:number}} [options.size] fixed drawing-buffer size (device px)
   * @param {number} [options.scale] resolution scale of the device pixels (without a fixed size)
   * @param {boolean} [options.playing]
   * Throws WebGL2UnavailableError when there is no WebGL2.
   */
  constructor({ canvas, overlay, fileName, size = null, scale = 1, playing = true }) {
    this.canvas = canvas;
    this.overlay = overlay;
    this.fileName = fileName;
    this.renderer = new ShaderRenderer(canvas);
    this.inputs = new ShadertoyInputs();
    this.inputs.playing = playing;
    this.inputs.attach(canvas);
    this.inputs.onMouseChange = () => this.requestRender();

    this.source = '';
    this.controls = [];
    this.values = {};
    this.notice = null; // a problem with the control block, shown with the overlay
    this.fixedSize = size;
    this.scale = scale;
    this.framesRendered = 0;

    this._latestCompile = null;
    this._raf = 0;
    this._frameTime = { last: null, average: null, shown: 0 };

    this.ready = new Promise((resolve, reject) => {
      this._readyResolve = resolve;
      this._readyReject = reject;
    });
    this.ready.catch(() => {}); // a failure is reported on the page; callers may still await it

    this.panel = new Panel({
      playing,
      scale,
      scaleLocked: Boolean(size),
      onPlay: (play) => (play ? this.play() : this.pause()),
      onScale: (s) => this.setScale(s),
      onControl: (name, value) => this.setControls({ [name]: value }, 'panel'),
    });
    if (!playing) this.panel.setFrameTime('paused');
    this._watchSize();
    canvas.addEventListener('webglcontextlost', () => this.overlay.show('The GPU context was lost.', 'Waiting for the browser to restore it…'));
    canvas.addEventListener('webglcontextrestored', () => this.compile().catch(() => {}));
  }

  // ---- source and controls ---------------------------------------------------------------------

  /**
   * Takes a new shader source: reads its control block (keeping current values of controls that
   * survive), rebuilds the panel. Call compile() after.
   */
  loadSource(source) {
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
    this.controls = controls;
    this.values = values;
    this.renderer.setControlUniforms(controls, values);
    this.panel.setControls(controls, values);
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
      const changed = JSON.stringify(value) !== JSON.stringify(this.values[name]);
      this.values[name] = value;
      if (control.kind === 'uniform') this.renderer.setControlUniform(name, value);
      else if (changed) recompile = true;
    }
    this.panel.sync(this.values);
    return recompile;
  }

  /**
   * Compiles the source with the current compile-time values. On success the new shader is
   * drawn; on failure the error is shown and the last shader that compiled keeps running.
   */
  compile() {
    const defines = Object.fromEntries(this.controls.filter((c) => c.kind === 'define').map((c) => [c.name, this.values[c.name]]));
    const hostBlock = this.notice ? '' : hostControlBlock(this.controls, defines);
    const job = this.renderer.compile(this.source, hostBlock, this.fileName).then(
      () => {
        if (job !== this._latestCompile) return;
        if (this.notice) this.overlay.show(`Control block of ${this.fileName} not read`, this.notice);
        else this.overlay.hide();
        delete document.documentElement.dataset.error;
        this.requestRender();
      },
      (error) => {
        if (job === this._latestCompile) {
          const fallback = this.renderer.hasProgram ? ' (still showing the last version that compiled)' : '';
          this.overlay.show(`${this.fileName} did not compile${fallback}`, error.report ?? error.message);
          console.warn(error.message);
          if (!this.renderer.hasProgram) {
            document.documentElement.dataset.error = 'shader-compile';
            this._readyReject(error);
          }
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

  // ---- time, size ------------------------------------------------------------------------------

  play() {
    this.inputs.play();
    this._frameTime.last = null;
    this.panel.setPlaying(true);
    this.requestRender();
  }

  pause() {
    this.inputs.pause();
    this.panel.setPlaying(false);
    this.panel.setFrameTime('paused');
  }

  setScale(scale) {
    this.scale = scale;
    this.requestRender();
  }

  /** The drawing-buffer size for the current layout, in device pixels. */
  targetSize() {
    if (this.fixedSize) return this.fixedSize;
    const dpr = window.devicePixelRatio || 1;
    return {
      width: Math.max(1, Math.round(this.canvas.clientWidth * dpr * this.scale)),
      height: Math.max(1, Math.round(this.canvas.clientHeight * dpr * this.scale)),
    };
  }

  /** A fixed size is in device pixels: its CSS size is that over devicePixelRatio, unscaled. */
  _fitFixedSize() {
    if (!this.fixedSize) return;
    const dpr = window.devicePixelRatio || 1;
    this.canvas.style.width = `${this.fixedSize.width / dpr}px`;
    this.canvas.style.height = `${this.fixedSize.height / dpr}px`;
  }

  _watchSize() {
    this._fitFixedSize();
    const check = () => {
      this._fitFixedSize();
      const { width, height } = this.targetSize();
      if (width !== this.canvas.width || height !== this.canvas.height) this.requestRender();
    };
    new ResizeObserver(check).observe(this.canvas);
    window.addEventListener('resize', check); // also catches devicePixelRatio changes
  }

  // ---- drawing ---------------------------------------------------------------------------------

  /** Draws at the next animation frame (once, however often it is asked). */
  requestRender() {
    if (!this._raf) this._raf = requestAnimationFrame((now) => this._tick(now));
  }

  _tick(now) {
    this._raf = 0;
    this.renderNow(now);
    this._trackFrameTime(now);
    if (this.inputs.playing) this.requestRender();
  }

  /**
   * Draws one frame now (synchronously). Returns false when no shader has compiled yet.
   * @param {number} now timestamp in ms (performance.now() or a rAF time)
   */
  renderNow(now = performance.now()) {
    const { width, height } = this.targetSize();
    this.renderer.setSize(width, height);
    if (!this.renderer.hasProgram) return false;
    this.inputs.beginFrame(this.renderer.uniforms, this.renderer.width, this.renderer.height, now);
    this.renderer.render();
    this.inputs.endFrame();
    this.framesRendered++;
    this.canvas.dataset.frame = String(this.framesRendered);
    if (this.framesRendered === 1) this._readyResolve();
    return true;
  }

  /** A smoothed interval between consecutive animation frames while playing, for the panel. */
  _trackFrameTime(now) {
    const t = this._frameTime;
    if (!this.inputs.playing) {
      t.last = null;
      return;
    }
    if (t.last !== null) {
      const dt = now - t.last;
      t.average = t.average === null ? dt : t.average * 0.9 + dt * 0.1;
      if (now - t.shown > 250) {
        t.shown = now;
        this.panel.setFrameTime(t.average);
      }
    }
    t.last = now;
  }
}
