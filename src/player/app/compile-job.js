// The app's compiles (app.compiles): the shader with its control values, sent to the render
// worker to compile. Compiles may overlap (a control dragged through compile-time values): only
// the latest one started reports its outcome (the app's 'compile' event, `errors`), and a
// compile asked for while the context is lost waits for its return. It owns what compiling
// knows: the latest compile, the shader on screen as it ran (a ShaderVersion: what the watchdog
// goes back to), how many compiles succeeded, and the last one's errors.

import { hostControlBlock } from '../../shadertoy/header.js';
import { controlDefaults, projectControls } from '../../shadertoy/controls.js';

/** @typedef {import('./app.js').ShaderApp} ShaderApp */
/** @typedef {import('./app.js').ShaderVersion} ShaderVersion */

/**
 * What compiling uses of the app (app.js builds it): the shader and its controls' block, read at
 * each compile, and what it tells when one ends.
 * @typedef {object} CompileHost
 * @property {import('./render-client.js').RenderClient} gpu the render worker (contextLost, ask)
 * @property {ShaderApp['version']} version the shader as it is now
 * @property {() => string} hostBlock the controls' block with their current values, as the shader compiles now
 *   (header.js's hostControlBlock; empty when the shader's block could not be read)
 * @property {(listener: () => void) => void} onceContext calls `listener` at the app's next 'context' event
 * @property {(...args: import('./events.js').AppEvents['compile']) => void} emitCompile the app's 'compile' event
 * @property {() => void} requestFrame a frame drawn (FrameLoop.request)
 * @property {() => void} startClock a newly loaded shader starts at iFrame 0 (ShaderApp.startClock)
 * @property {() => boolean} playing whether the clock runs
 * @property {(play: boolean) => void} setPlaying plays or pauses the clock (ShaderApp.play, .pause)
 */

export class CompileJob {
  /** @param {CompileHost} host whose shader, controls and values are compiled */
  constructor(host) {
    this._host = host;
    /** The latest compile started. @type {Promise<void> | null} */
    this.latest = null;
    /** The shader on screen, as it compiled; null while none runs (before the first, after a lost context). @type {ShaderVersion | null} */
    this.running = null;
    /** Successful compiles so far. */
    this.count = 0;
    /** The messages of the last failed compile, [] after a success. @type {Array<{line: number | null, message: string}>} */
    this.errors = [];
    /** Whether the last compile to report failed (with no shader running, nothing is drawn). */
    this.failed = false;
    /** The clock was paused because a compile failed with no shader running: the next success plays it. */
    this.held = false;
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
    const host = this._host;
    if (host.gpu.contextLost) {
      // compiled when the context comes back: this job ends as the compile started then does
      /** @type {Promise<void>} */
      const job = new Promise((resolve) => host.onceContext(() => resolve(this.latest ?? undefined)));
      this.latest = job;
      return job;
    }
    const hostBlock = host.hostBlock();
    const version = host.version();
    const fileName = version.name;
    const serial = ++this._started;
    const job = host.gpu.ask('compile', { project: version.project, hostBlock, fileName, serial }).then(
      () => {
        if (serial > this._runningSerial) this._onScreen(version, serial);
        if (job !== this.latest) return;
        this.errors = [];
        this.failed = false;
        this.count++;
        if (this.held) host.setPlaying(true);
        host.emitCompile(null, fileName);
        host.requestFrame();
      },
      async (error) => {
        if (job !== this.latest) throw error;
        // the stand-in runs before the failure is told: `ready` rejects only if no shader runs at all
        if (orElse && !this.running) await this._standIn(orElse).catch(() => {});
        if (job === this.latest) {
          this.errors = error.messages ?? [];
          this.failed = true;
          // nothing runs, so nothing plays: the clock says so (Play shown, the Sound tab silent)
          if (!this.running && host.playing()) {
            host.setPlaying(false);
            this.held = true;
          }
          console.warn(error.message);
          host.emitCompile(error, fileName);
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
    const host = this._host;
    let controls = [];
    try {
      controls = projectControls(version.project);
    } catch {
      // a block it cannot read: it runs with its own defaults, as loadProject runs it
    }
    const values = { ...controlDefaults(controls), ...version.values };
    const serial = ++this._started;
    const hostBlock = controls.length ? hostControlBlock(controls, values, values) : '';
    await host.gpu.ask('compile', { project: version.project, hostBlock, fileName: version.name, serial });
    if (this.running || serial < this._runningSerial) return; // the app's own shader compiled meanwhile
    this._onScreen(version, serial);
    host.requestFrame();
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
      this._host.startClock();
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
