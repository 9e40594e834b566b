// "Converge when still" (app.converge): the built-in raytracer (or an edit that keeps its camera
// and radiance functions: progressive.js calls them) runs as its progressive multipass form
// (progressive.js: Buffer A adds one jittered sample per pixel per frame while nothing changes;
// Image shows the mean and the sample count), with the clock paused so that the view is still;
// off, the shader as it was, with its control values. It owns whether the app converges, the
// shader it converges from, and how many still frames it asks for; the frame loop asks it
// whether another frame is wanted.

import { MAX_SAMPLES, missingRaytracerFunctions, progressiveTabs } from '../../raytracer/progressive.js';

/** @typedef {import('./app.js').RaytracerApp} RaytracerApp */
/** @typedef {import('./app.js').ShaderVersion} ShaderVersion */

/**
 * What converging uses of the app (app.js builds it): the shader it reads, and the app's
 * methods that load, set and compile another (each field stays its owner's).
 * @typedef {object} ConvergeHost
 * @property {() => string} source the Image tab's text (RaytracerApp.source)
 * @property {() => boolean} isMultipass whether the shader has a Common tab or a buffer
 * @property {RaytracerApp['version']} version
 * @property {RaytracerApp['loadProject']} loadProject
 * @property {RaytracerApp['runVersion']} runVersion
 * @property {RaytracerApp['applyControls']} applyControls
 * @property {RaytracerApp['pause']} pause
 * @property {() => Promise<void>} compile the app's shader compiled (CompileJob.compile)
 * @property {() => void} requestFrame a frame drawn (FrameLoop.request)
 */

export class Converge {
  /** @param {ConvergeHost} host */
  constructor(host) {
    this._host = host;
    /** Whether the shader runs as its progressive form. */
    this.on = false;
    /** Frames drawn while the view is still: then its buffer sums no more. */
    this.frames = MAX_SAMPLES;
    /** The single-pass shader that converges (turning it off goes back to it). @type {ShaderVersion | null} */
    this._before = null;
  }

  /** Whether "Converge when still" can run the app's shader (the raytracer: progressive.js). */
  get available() {
    const host = this._host;
    return !host.isMultipass() && missingRaytracerFunctions(host.source()).length === 0;
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
   * coming while the view is still, up to `frames` (MAX_SAMPLES by default), and start again
   * from one sample after any change.
   * @param {boolean} on
   * @param {{frames?: number}} [options]
   * @returns {Promise<void>}
   */
  async set(on, { frames = MAX_SAMPLES } = {}) {
    const host = this._host;
    this.frames = Math.max(1, Math.min(MAX_SAMPLES, Math.round(frames)));
    if (on === this.on) return host.requestFrame();
    if (!on) {
      const back = /** @type {ShaderVersion} */ (this._before);
      this.drop();
      host.runVersion(back, 'Converge when still', { continues: true });
      return host.compile();
    }
    if (host.isMultipass()) throw new Error('only the raytracer converges: this shader has buffers of its own');
    const missing = missingRaytracerFunctions(host.source());
    if (missing.length) throw new Error(`only the raytracer converges (shaders/raytrace.glsl): this shader has no ${missing.join(', ')}`);
    const before = host.version();
    const tabs = progressiveTabs(host.source());
    host.pause();
    host.loadProject(tabs.model, { name: before.name, origin: before.origin, url: before.url, continues: true });
    this.on = true;
    this._before = before;
    host.applyControls({ SHOW_SAMPLE_COUNT: 1 }, 'Converge when still');
    return host.compile();
  }
}
