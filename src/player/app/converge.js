// "Converge when still" (app.converge): a shader that has a progressive form runs as it (a
// multipass form that adds a sample per pixel each frame while nothing changes and shows their
// mean), with the clock paused so that the view is still; off, the shader as it was, with its
// control values. It owns whether the app converges, the shader it converges from, and how many
// still frames it asks for; the frame loop asks it whether another frame is wanted.
//
// Which shaders have a progressive form, and what it is, is not the engine's to know: it is
// plugged in from outside the player (use()), the interactive page's at its start, the engine
// page's when a converge is first asked for (src/engine-plug-ins.js: a chunk loaded then).

/** @typedef {import('./app.js').ShaderApp} ShaderApp */
/** @typedef {import('./app.js').ShaderVersion} ShaderVersion */

/**
 * What converging uses of the app (app.js builds it): the shader it reads, and the app's
 * methods that load, set and compile another (each field stays its owner's).
 * @typedef {object} ConvergeHost
 * @property {() => string} source the Image tab's text (ShaderApp.source)
 * @property {() => boolean} isMultipass whether the shader has a Common tab or a buffer
 * @property {ShaderApp['version']} version
 * @property {ShaderApp['loadProject']} loadProject
 * @property {ShaderApp['runVersion']} runVersion
 * @property {ShaderApp['applyControls']} applyControls
 * @property {ShaderApp['pause']} pause
 * @property {() => Promise<void>} compile the app's shader compiled (CompileJob.compile)
 * @property {() => void} requestFrame a frame drawn (FrameLoop.request)
 */

/**
 * A shader family's progressive form, plugged in by its side.
 * @typedef {object} ProgressiveForm
 * @property {string} name what converges, in errors ("the X shader")
 * @property {string} file the shader it is the form of (its path in the repository)
 * @property {number} maxSamples the most still frames a converge draws (and its default)
 * @property {(source: string) => string[]} missing what a single-pass shader's text lacks to
 *   converge (empty: it can)
 * @property {(source: string) => {model: import('../../shadertoy/multipass.js').MultipassShader}} form
 *   the shader's progressive multipass form
 * @property {Record<string, unknown>} controls control values set when it starts, for a person
 *   (a sample count drawn over the picture)
 * @property {string[]} overlays its live controls that draw over the picture (such as that
 *   count): a render that wants the picture alone sets them to 0 (overlaysOff)
 */
/** @typedef {ProgressiveForm | (() => Promise<ProgressiveForm>)} FormSource */

export class Converge {
  /** @param {ConvergeHost} host */
  constructor(host) {
    this._host = host;
    /** Whether the shader runs as its progressive form. */
    this.on = false;
    /** Frames drawn while the view is still: then its buffer sums no more. */
    this.frames = 0;
    /** The progressive form plugged in (use()), or what loads it; null: none, nothing converges. @type {FormSource | null} */
    this._form = null;
    /** The single-pass shader that converges (turning it off goes back to it). @type {ShaderVersion | null} */
    this._before = null;
  }

  /**
   * Plugs in the progressive form, or a function that loads it when a converge is first asked for.
   * @param {FormSource} form
   */
  use(form) {
    this._form = form;
  }

  /** The progressive form, loaded if it was plugged in as a loader; null without one. */
  async _loadForm() {
    if (typeof this._form === 'function') this._form = await this._form();
    return this._form;
  }

  /**
   * The on-screen overlays of the form the shader converges as, each at 0 ({NAME: 0}; none
   * while it does not converge).
   * @returns {Record<string, number>}
   */
  get overlaysOff() {
    const form = this.on ? /** @type {ProgressiveForm} */ (this._form) : null;
    return Object.fromEntries((form?.overlays ?? []).map((control) => [control, 0]));
  }

  /** Whether "Converge when still" can run the app's shader (a progressive form, loaded, that takes it). */
  get available() {
    const host = this._host;
    const form = this._form;
    return form !== null && typeof form !== 'function' && !host.isMultipass() && form.missing(host.source()).length === 0;
  }

  /**
   * Whether another frame is wanted after `stillFrames` frames of a still view.
   * @param {number} stillFrames
   */
  wantsFrame(stillFrames) {
    return this.on && stillFrames < this.frames;
  }

  /** Another shader was loaded: it does not converge (its progressive form is set() by itself). */
  drop() {
    this.on = false;
    this._before = null;
  }

  /**
   * Turns converging on or off; resolves once the shader it runs then has compiled. Frames keep
   * coming while the view is still, up to `frames` (the form's maxSamples by default, and at
   * most), and start again from one sample after any change.
   * @param {boolean} on
   * @param {{frames?: number}} [options]
   * @returns {Promise<void>}
   */
  async set(on, { frames } = {}) {
    const host = this._host;
    if (!on && !this.on) return host.requestFrame();
    const form = on ? await this._loadForm() : null;
    if (on && !form) throw new Error('no shader converges on this page: no progressive form is plugged in');
    const most = form?.maxSamples ?? this.frames;
    this.frames = Math.max(1, Math.min(most, Math.round(frames ?? most)));
    if (on === this.on) return host.requestFrame();
    if (!on) {
      const back = /** @type {ShaderVersion} */ (this._before);
      this.drop();
      host.runVersion(back, 'Converge when still', { continues: true });
      return host.compile();
    }
    const { name, file, missing: lacks, form: progressive, controls } = /** @type {ProgressiveForm} */ (form);
    if (host.isMultipass()) throw new Error(`only ${name} converges: this shader has buffers of its own`);
    const missing = lacks(host.source());
    if (missing.length) throw new Error(`only ${name} converges (${file}): this shader has no ${missing.join(', ')}`);
    const before = host.version();
    const tabs = progressive(host.source());
    host.pause();
    host.loadProject(tabs.model, { name: before.name, origin: before.origin, url: before.url, continues: true });
    this.on = true;
    this._before = before;
    host.applyControls(controls, 'Converge when still');
    return host.compile();
  }
}
