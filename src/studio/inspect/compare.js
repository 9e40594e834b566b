// "Compare with float64" (the widget is compare-view.js): the frame on the canvas against the
// float64 reference (src/reference/render.js) with the shader's own rays, as `npm run accuracy`
// measures it. The reference renders in workers (reference-client.js), band by band; the page
// draws nothing meanwhile but what it would draw anyway, and says how far the reference has got.
//
// What is compared: the frame's Image pass drawn again in RGBA32F (the shader's float32 colours,
// before the 8-bit rounding) and the frame's 8-bit pixels (what the canvas shows, the accuracy
// report's measure), each against the reference. With adaptive anti-aliasing the reference takes
// its extra samples in the pixels the shader took them in: those the path probe's mainImage shows
// (probe-program.js: the shader's "pixels with extra samples" view).
//
// Only the built-in raytracer has a float64 twin (and edits of it that keep its functions, whose
// control block and constants the reference reads; their code is not followed). The comparison
// pauses the clock: what it measured stays on the canvas; any change after marks it out of date.

import { extraSampleMask } from '../../raytracer/extra-samples.js';
import { Emitter } from '../../player/app/events.js';
import { ReferenceCancelled } from './reference-client.js';

/** @typedef {import('../../player/app/app.js').ShaderApp} ShaderApp */
/** @typedef {import('./probe-program.js').ProbeProgram} ProbeProgram */
/** @typedef {import('./reference-client.js').ReferenceClient} ReferenceClient */
/** @typedef {{pixels: number, rmse: number, psnr: number, maxAbs: number, over1: number, over2: number, nonFinite: number}} ImageError */

/**
 * A finished comparison.
 * @typedef {object} ComparisonResult
 * @property {number} width
 * @property {number} height
 * @property {Float32Array} floatError each pixel's worst channel of |float32 − float64|, rows top to bottom
 * @property {Float32Array} canvasError the same for the 8-bit pixels the canvas shows
 * @property {{float: ImageError, canvas: ImageError}} figures error.js's figures for both
 * @property {Uint8Array} picture the frame's RGBA8 pixels, rows top to bottom
 * @property {number | null} extraSampleShare the share of pixels that took the grid of extra samples (adaptive only)
 * @property {{time: number, frame: number}} frame the frame compared
 * @property {Record<string, number>} ms how long each part took: picture, extraSamples, reference, total
 * @property {string | null} caveat what the reference does not follow (an edited shader's code)
 */

/**
 * @typedef {object} ComparisonEvents
 * @property {[]} progress a phase started, or the reference got further
 * @property {[]} result a comparison finished, failed, was cancelled, or went out of date
 */

/** @extends {Emitter<ComparisonEvents>} */
export class Comparison extends Emitter {
  /**
   * @param {ShaderApp} app
   * @param {ProbeProgram} program
   * @param {ReferenceClient} reference
   * @param {string} builtinSource the built-in raytracer's text (an edit's code is not the reference's)
   */
  constructor(app, program, reference, builtinSource) {
    super();
    this.app = app;
    this.program = program;
    this.reference = reference;
    this.builtinSource = builtinSource;
    /** The comparison under way: what it is doing, and how far the reference has got. @type {{phase: string, rows: number, of: number} | null} */
    this.running = null;
    /** The last comparison's result. @type {ComparisonResult | null} */
    this.result = null;
    /** Why the last comparison failed. @type {string | null} */
    this.error = null;
    /** The view changed since the result was measured. */
    this.stale = false;
    /** What the result was measured on (to tell when it goes out of date). @type {string | null} */
    this._measured = null;
    this._serial = 0;
    const check = () => {
      if (this.result && !this.stale && this._measured !== this._viewKey()) {
        this.stale = true;
        this.emit('result');
      }
    };
    app.on('drawn', check);
    app.on('state', check);
    app.on('source', check);
  }

  /** Why the app's shader cannot be compared, or null. */
  get unavailable() {
    if (this.app.converge.on)
      return 'Compare with float64 measures one frame of the raytracer, not the mean that "Converge when still" sums: turn that off (Controls → View) to compare';
    const why = this.program.unavailable;
    return why
      ? `Compare with float64 is for the built-in raytracer: ${why.replace(/^the path is for the built-in raytracer: /, '')}`
      : null;
  }

  /**
   * Compares the frame on the canvas with the float64 reference; resolves with the result.
   * Rejects with the reason when it cannot (or with ReferenceCancelled when cancelled).
   * @returns {Promise<ComparisonResult>}
   */
  async run() {
    const app = this.app;
    const serial = ++this._serial;
    this.reference.cancel();
    this.error = null;
    const unavailable = this.unavailable;
    if (unavailable) return this._fail(serial, new Error(unavailable));
    const debugView = this.program.debugView;
    if (debugView)
      return this._fail(
        serial,
        new Error(`The float64 reference draws the picture, not the "${debugView}" view: set View to Picture to compare.`),
      );
    const started = performance.now();
    /** @type {Record<string, number>} */
    const ms = {};
    try {
      if (app.inputs.playing) app.pause(); // what is measured stays on the canvas
      this._phase(serial, 'Drawing the frame');
      await app.compiles.settled();
      if (!app.compiles.hasProgram) throw new Error('no shader is running');
      await app.frames.idle(); // the frame under way is the one compared
      if (!app.frames.last) await app.frames.draw();
      const inputs = app.frames.last;
      if (!inputs) throw new Error('no frame was drawn: the GPU context is lost');
      const values = structuredClone(app.values);
      const source = app.source;
      const viewKey = this._viewKey();
      const { width, height } = inputs;
      const size = { inputs, width, height };

      this._phase(serial, 'Drawing the frame in float');
      let t = performance.now();
      const float = await app.gpu.ask('captureFloat', size);
      const picture = await app.gpu.ask('capture', { ...size, allPasses: false });
      ms.picture = performance.now() - t;

      /** @type {Uint8Array | null} */
      let mask = null;
      const adaptive = values.SAMPLES > 1 && Boolean(values.ADAPTIVE_AA);
      if (adaptive) {
        if (!this.program.showsAaPixels)
          throw new Error(
            'with adaptive anti-aliasing the reference needs the shader\'s "Extra samples" view (its VIEW control), which this shader lacks',
          );
        t = performance.now();
        this._phase(
          serial,
          this.program.ready ? 'Finding the pixels with extra samples' : 'Compiling the path probe (to find the pixels with extra samples)',
        );
        await this.program.ensure();
        this._phase(serial, 'Finding the pixels with extra samples');
        const shown = await app.gpu.ask('capture', { ...size, allPasses: false, program: 'aa-pixels' });
        mask = extraSampleMask({ width, height, data: shown });
        ms.extraSamples = performance.now() - t;
      }

      t = performance.now();
      this._phase(serial, 'float64 reference', height);
      const view = { width, height, time: inputs.time, mouse: inputs.mouse, controls: values };
      const rgb = await this.reference.image({ source, view, extraSamples: mask }, (rows) => {
        if (serial !== this._serial || !this.running) return;
        this.running.rows = rows;
        this.emit('progress');
      });
      ms.reference = performance.now() - t;

      const { imageError } = await import('../../reference/error.js');
      const clamp = (v) => Math.min(1, Math.max(0, v));
      const floatRgb = new Float64Array(width * height * 3);
      for (let i = 0; i < width * height; i++) for (let c = 0; c < 3; c++) floatRgb[3 * i + c] = clamp(float[4 * i + c]);
      const test = { width, height };
      const reference = { width, height, rgb };
      ms.total = performance.now() - started;
      /** @type {ComparisonResult} */
      const result = {
        width,
        height,
        floatError: worstChannel(floatRgb, (i) => i, rgb, width * height),
        canvasError: worstChannel(picture, (i) => 4 * Math.floor(i / 3) + (i % 3), rgb, width * height, 1 / 255),
        figures: { float: imageError({ ...test, rgb: floatRgb }, reference), canvas: imageError({ ...test, data: picture }, reference) },
        picture,
        extraSampleShare: mask ? mask.reduce((n, v) => n + v, 0) / mask.length : null,
        frame: { time: inputs.time, frame: inputs.frame },
        ms,
        caveat:
          source === this.builtinSource
            ? null
            : 'This shader is an edit of the raytracer: the reference follows its controls and constants, not its code.',
      };
      if (serial !== this._serial) throw new ReferenceCancelled();
      this.running = null;
      this.result = result;
      this.stale = this._viewKey() !== viewKey;
      this._measured = viewKey;
      this.emit('progress');
      this.emit('result');
      return result;
    } catch (error) {
      return this._fail(serial, error);
    }
  }

  /** Stops the comparison under way. */
  cancel() {
    this._serial++;
    this.reference.cancel();
    if (!this.running) return;
    this.running = null;
    this.emit('progress');
  }

  /** Forgets the result (the heat map goes). */
  clear() {
    this.result = null;
    this.error = null;
    this.stale = false;
    this.emit('result');
  }

  /** @param {number} serial @param {string} phase @param {number} [of] rows, for a progress bar */
  _phase(serial, phase, of = 0) {
    if (serial !== this._serial) throw new ReferenceCancelled();
    this.running = { phase, rows: 0, of };
    this.emit('progress');
  }

  /**
   * Says why the comparison ended, and throws it on.
   * @param {number} serial
   * @param {Error & {report?: string}} error
   * @returns {never}
   */
  _fail(serial, error) {
    if (serial === this._serial) {
      this.running = null;
      this.error = error instanceof ReferenceCancelled ? null : (error.report ?? error.message);
      this.emit('progress');
      this.emit('result');
    }
    throw error;
  }

  /** What a result depends on: the frame's inputs, the controls and the shader. */
  _viewKey() {
    const app = this.app;
    const last = app.frames.last;
    return JSON.stringify([last?.width, last?.height, last?.time, last?.mouse, app.values, app.source.length, app.fileName]);
  }
}

/**
 * Each pixel's worst channel of |test − reference|.
 * @param {ArrayLike<number>} test
 * @param {(i: number) => number} at where channel value i (3 a pixel) lies in `test`
 * @param {Float64Array} reference 3 a pixel
 * @param {number} pixels
 * @param {number} [scale] what a unit of `test` is
 */
function worstChannel(test, at, reference, pixels, scale = 1) {
  const out = new Float32Array(pixels);
  for (let p = 0; p < pixels; p++) {
    let worst = 0;
    for (let c = 0; c < 3; c++) worst = Math.max(worst, Math.abs(test[at(3 * p + c)] * scale - reference[3 * p + c]));
    out[p] = worst;
  }
  return out;
}
