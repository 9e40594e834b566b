// The path probe of the app's shader (src/raytracer/path-probe.js: the raytracer's file compiled
// once more, its radiance() recording each ray, its mainImage showing the pixels with extra
// samples), compiled in the render worker when the inspector or the comparison first needs it,
// and again when the shader or a compile-time control changes. It is compiled in the live
// controls' uniform form, so a slider that moves never waits for it (the page's uniform and
// constant forms draw the same picture: tests/browser/page-controls.test.js).
//
// Only the raytracer has one: a single-pass shader with the functions the probe calls (the
// progressive raytracer's test, raytracer/progressive.js) whose control block the page read.

import { extraSamplesValues } from '../../raytracer/extra-samples.js';
import { hostControlBlock } from '../../shadertoy/header.js';
import { missingRaytracerFunctions } from '../../raytracer/progressive.js';
import { PROBE_TEXELS, pathProbeHostBlock, pathProbeProject } from '../../raytracer/path-probe.js';

/** @typedef {import('../../player/app/app.js').ShaderApp} ShaderApp */

/**
 * Why there is no path while "Converge when still" runs the raytracer's progressive form: each of
 * its frames adds a jittered sample to a buffer, and the picture is their mean, which no one ray
 * path (and no one float64 colour) describes.
 */
const CONVERGING =
  'the path and the float64 colour are of one frame of the raytracer, not of the mean that "Converge when still" sums: turn that off (Controls → View) to see them';

export class ProbeProgram {
  /** @param {ShaderApp} app */
  constructor(app) {
    this.app = app;
    /** The key of the probe the worker holds (null: none). @type {string | null} */
    this.compiledKey = null;
    /** The compile under way, by key. @type {{key: string, done: Promise<void>} | null} */
    this._compiling = null;
    /** A key whose compile failed with a compile error: not tried again. @type {{key: string, error: Error} | null} */
    this.failed = null;
    /** The worker the probe was compiled in (a new worker after a hang has none). @type {Worker | null} */
    this._worker = null;
    // a lost context takes the program with it (and a compile it cut short was no verdict)
    app.on('context', () => {
      this.compiledKey = null;
      this.failed = null;
    });
  }

  /** Why the app's shader has no path probe, or null when it has one. */
  get unavailable() {
    const app = this.app;
    if (app.converge.on) return CONVERGING;
    if (app.isMultipass) return 'the path is for the built-in raytracer: this shader has buffers of its own';
    const missing = missingRaytracerFunctions(app.source);
    if (missing.length) return `the path is for the built-in raytracer: this shader has no ${missing.join(', ')}`;
    if (app.notice) return "the path needs the raytracer's control block, which the page could not read";
    return null;
  }

  /** What the probe of the app's shader as it is now compiles from (null: none). */
  get key() {
    return this.unavailable ? null : this._hostBlock() + '\n' + this.app.source;
  }

  /** Whether the worker holds the probe of the app's shader as it is now. */
  get ready() {
    const key = this.key;
    return key !== null && key === this.compiledKey && this._worker === this.app.gpu.worker;
  }

  /** Whether a compile of it is under way. */
  get compiling() {
    return this._compiling !== null && this._compiling.key === this.key;
  }

  /**
   * Compiles the probe of the app's shader unless the worker holds it; rejects with why there is
   * none (unavailable, or its compile error).
   * @returns {Promise<void>}
   */
  ensure() {
    const app = this.app;
    const key = this.key;
    if (key === null) return Promise.reject(new Error(this.unavailable ?? 'no path probe'));
    if (this.ready) return Promise.resolve();
    if (this.failed?.key === key) return Promise.reject(this.failed.error);
    if (this._compiling?.key === key) return this._compiling.done;
    const worker = app.gpu.worker;
    const done = app.gpu
      .ask('compileProbe', {
        project: pathProbeProject(app.source),
        hostBlock: pathProbeHostBlock(this._hostBlock()),
        fileName: app.fileName,
        key,
        texels: PROBE_TEXELS,
      })
      .then(
        () => {
          this.compiledKey = key;
          this._worker = worker;
        },
        (error) => {
          if (error.messages) this.failed = { key, error }; // a compile error; not a lost context
          throw error;
        },
      )
      .finally(() => {
        if (this._compiling?.done === done) this._compiling = null;
      });
    this._compiling = { key, done };
    return done;
  }

  /** The page's control block for the probe: the app's values, the live ones as uniforms, and the "Extra samples" view chosen. */
  _hostBlock() {
    const app = this.app;
    return hostControlBlock(app.controls, { ...app.values, ...extraSamplesValues(app.controls) });
  }

  /**
   * The label of the debug view the shader draws instead of the picture (its VIEW control set to
   * anything but its first choice, the picture), or null. The float64 reference draws the
   * picture only, so neither the comparison nor the inspector's float64 colour applies then.
   */
  get debugView() {
    const app = this.app;
    const control = app.controls.find((c) => c.name === 'VIEW');
    const value = app.values.VIEW;
    if (!control?.options || value === undefined || value === control.options[0].value) return null;
    return control.options.find((o) => o.value === value)?.label ?? String(value);
  }

  /** Whether the probe's mainImage shows which pixels took extra samples (the shader's VIEW control offers that view). */
  get showsAaPixels() {
    return extraSamplesValues(this.app.controls) !== null;
  }
}
