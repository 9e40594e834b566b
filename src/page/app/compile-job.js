// The app's compiles (app.compiles): the shader with its control values, sent to the render
// worker to compile. Compiles may overlap (a control dragged through compile-time values): only
// the latest one started reports its outcome (the app's 'compile' event, `errors`), and a
// compile asked for while the context is lost waits for its return. It owns what compiling
// knows: the latest compile, the shader on screen as it ran (a ShaderVersion: what the watchdog
// goes back to), how many compiles succeeded, and the last one's errors.

import { hostControlBlock } from '../../shadertoy/header.js';
import { controlDefaults, projectControls } from '../../shadertoy/controls.js';

/** @typedef {import('./app.js').RaytracerApp} RaytracerApp */
/** @typedef {import('./app.js').ShaderVersion} ShaderVersion */

export class CompileJob {
  /** @param {RaytracerApp} app whose shader, controls and values are compiled */
  constructor(app) {
    this.app = app;
    /** The latest compile started. @type {Promise<void> | null} */
    this.latest = null;
    /** The shader on screen, as it compiled; null while none runs (before the first, after a lost context). @type {ShaderVersion | null} */
    this.running = null;
    /** Successful compiles so far. */
    this.count = 0;
    /** The messages of the last failed compile, [] after a success. @type {Array<{line: number | null, message: string}>} */
    this.errors = [];
    this._started = 0;
    /** Which compile `running` is: one that finishes after a newer one is not drawn (gpu/renderer.js). */
    this._runningSerial = 0;
    /** The shader on screen before `running`, with its compile's number (a frame under way may still be its). @type {{serial: number, version: ShaderVersion} | null} */
    this._before = null;
    /** The load (ShaderVersion.load) whose clock was started: a newly loaded shader starts at iFrame 0. @type {number | undefined} */
    this._clockOf = 0;
  }

  /**
   * The shader a frame was drawn with, from the compile number the worker gives with it (null:
   * not known, as after a new worker).
   * @param {number} serial
   * @returns {ShaderVersion | null}
   */
  versionOf(serial) {
    if (serial === this._runningSerial) return this.running;
    return this._before?.serial === serial ? this._before.version : null;
  }

  /** True once some shader has compiled and runs (the worker draws nothing before). */
  get hasProgram() {
    return this.running !== null;
  }

  /** The worker lost its programs (a restored context, a new worker): nothing runs until the next compile. */
  forget() {
    this.running = null;
    this._before = null;
    this._runningSerial = this._started;
  }

  /**
   * Compiles the app's shader with its current compile-time values. On success the new shader is
   * drawn; on failure the error is shown and the last shader that compiled keeps running, or,
   * when none runs yet, `orElse` (the file a kept edit was made from: the picture is not black
   * while the edit does not compile).
   * @param {{orElse?: ShaderVersion | null}} [options]
   * @returns {Promise<void>}
   */
  compile({ orElse = null } = {}) {
    const app = this.app;
    if (app.gpu.contextLost) {
      // compiled when the context comes back: this job ends as the compile started then does
      /** @type {Promise<void>} */
      const job = new Promise((resolve) => app.once('context', () => resolve(this.latest ?? undefined)));
      this.latest = job;
      return job;
    }
    const hostBlock = app.notice ? '' : hostControlBlock(app.controls, app.values, app.liveForm.asConstants ? app.values : null);
    const version = app.version();
    const fileName = version.name;
    const serial = ++this._started;
    const job = app.gpu.ask('compile', { project: version.project, hostBlock, fileName, serial }).then(
      () => {
        if (serial > this._runningSerial) this._onScreen(version, serial);
        if (job !== this.latest) return;
        this.errors = [];
        this.count++;
        app.emit('compile', null, fileName);
        app.frames.request();
      },
      async (error) => {
        if (job !== this.latest) throw error;
        // the stand-in runs before the failure is told: `ready` rejects only if no shader runs at all
        if (orElse && !this.running) await this._standIn(orElse).catch(() => {});
        if (job === this.latest) {
          this.errors = error.messages ?? [];
          console.warn(error.message);
          app.emit('compile', error, fileName);
        }
        throw error;
      },
    );
    this.latest = job;
    return job;
  }

  /**
   * Compiles and runs another shader than the app's, as it ran (its control values, live ones
   * too, as constants: the worker's uniforms are the app's shader's), until the app's compiles.
   * @param {ShaderVersion} version
   */
  async _standIn(version) {
    const app = this.app;
    let controls = [];
    try {
      controls = projectControls(version.project);
    } catch {
      // a block it cannot read: it runs with its own defaults, as loadProject runs it
    }
    const values = { ...controlDefaults(controls), ...version.values };
    const serial = ++this._started;
    const hostBlock = controls.length ? hostControlBlock(controls, values, values) : '';
    await app.gpu.ask('compile', { project: version.project, hostBlock, fileName: version.name, serial });
    if (this.running || serial < this._runningSerial) return; // the app's own shader compiled meanwhile
    this._onScreen(version, serial);
    app.frames.request();
  }

  /**
   * `version`, compiled as compile number `serial`, is the shader on screen now.
   * @param {ShaderVersion} version
   * @param {number} serial
   */
  _onScreen(version, serial) {
    if (this.running) this._before = { serial: this._runningSerial, version: this.running };
    this.running = version;
    this._runningSerial = serial;
    // Shadertoy's contract: a shader loaded in place of another starts at iFrame 0 and iTime 0
    // with cleared buffers (its buffers may set themselves up on frame 0)
    if (version.load !== this._clockOf) {
      this._clockOf = version.load;
      this.app.startClock();
    }
  }

  /** Resolves when no compile is under way (whatever the outcome). */
  async settled() {
    let job;
    do {
      job = this.latest;
      await job?.catch(() => {});
    } while (job !== this.latest);
  }
}
