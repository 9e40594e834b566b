// The pixel inspector's state (the widget is inspector-panel.js): whether Inspect is on (a click
// on the canvas then pins a pixel instead of moving iMouse), the pinned pixel, and what it reads
// there. The pinned pixel is read again after every frame the page draws (one read at a time,
// at most every MIN_INTERVAL_MS), so it follows time, the mouse and the controls; it keeps its
// place in the picture when the canvas changes size.
//
// A read (a 'probe' of the render worker, gpu/probe.js) gives the Image pass's colour there in
// float, before the 8-bit rounding, the byte the canvas shows, and every buffer's value; for the
// raytracer also the path of the pixel's ray from the shader's own path probe (probe-program.js)
// and the float64 reference's colour and path for that pixel (reference-client.js).

import { Emitter } from '../../player/app/events.js';
import { objectNames, readPath } from '../../raytracer/path-probe.js';
import { edgeKind } from '../../raytracer/extra-samples.js';

/** @typedef {import('../../player/app/app.js').ShaderApp} ShaderApp */
/** @typedef {import('./probe-program.js').ProbeProgram} ProbeProgram */
/** @typedef {import('./reference-client.js').ReferenceClient} ReferenceClient */
/** @typedef {import('../../raytracer/path-probe.js').PathRay} PathRay */

/** Reads of a pinned pixel follow one another at most this often. */
const MIN_INTERVAL_MS = 100;
/** What the readout says while the GPU context is gone. */
const LOST = 'The GPU context was lost: the readout comes back with the picture.';

/**
 * What the inspector read at the pinned pixel.
 * @typedef {object} Readout
 * @property {{x: number, y: number}} pixel its column and row (y from the bottom)
 * @property {number[]} fragCoord the pixel's fragCoord (its centre)
 * @property {{time: number, frame: number, width: number, height: number}} frame the frame read
 * @property {number[]} color the Image pass's RGBA there, float, before the 8-bit rounding
 * @property {number[]} canvas the RGBA bytes the canvas shows there
 * @property {Array<{name: string, value: number[]}>} buffers each buffer's RGBA32F value there
 * @property {{rays: Array<PathRay & {object: string}>, radiance: number[], extraSamples: boolean | null} | null} path
 *   the path of the ray through the pixel's centre, from the shader's path probe
 * @property {string | null} pathNote why there is no path (yet)
 * @property {{rgb: number[], difference: number[], path: Array<PathRay & {object: string}>} | null} reference
 *   the float64 reference's colour for the pixel and its path; `difference` is the shader's
 *   colour (clamped, as the canvas shows it) minus the reference's, in units of 1/255
 * @property {string | null} referenceNote why there is no reference colour (yet)
 * @property {boolean} complete nothing more is coming for this frame (path and reference settled)
 */

/**
 * @typedef {object} InspectorEvents
 * @property {[]} mode Inspect turned on or off, or the pinned pixel changed
 * @property {[]} readout a new readout (or a message about one)
 */

/** @extends {Emitter<InspectorEvents>} */
export class Inspector extends Emitter {
  /**
   * @param {ShaderApp} app
   * @param {ProbeProgram} program the path probe
   * @param {ReferenceClient} reference the float64 reference's workers
   */
  constructor(app, program, reference) {
    super();
    this.app = app;
    this.program = program;
    this.reference = reference;
    /** Inspect mode: a click on the canvas pins a pixel. */
    this.active = false;
    /** The pinned pixel, in the frame of `of` (y from the bottom). @type {{x: number, y: number, of: {width: number, height: number}} | null} */
    this.pinned = null;
    /** The last readout of the pinned pixel. @type {Readout | null} */
    this.readout = null;
    /** What went wrong with the last read (a lost context, no frame yet). @type {string | null} */
    this.problem = null;
    this._wanted = false;
    this._running = false;
    this._lastStart = 0;
    /** The reference's answer for a pixel and view, kept while they stay. @type {{key: string, answer: Promise<any>} | null} */
    this._referenceFor = null;
    /** The names of the shader's objects, read from the shader it was read of. @type {{source: string, controls: object, name: ReturnType<typeof objectNames>} | null} */
    this._objects = null;

    app.on('drawn', (_, frame) => {
      if (!this.pinned) return;
      const { of } = this.pinned;
      if (of.width !== frame.width || of.height !== frame.height) this._rescale(frame.width, frame.height);
      this.request();
    });
    app.on('context', (_, lost) => {
      if (!lost) return this.request();
      this.problem = LOST;
      this.emit('readout');
    });
  }

  /** Inspect on or off (off keeps the pinned pixel, unread, until it is on again). @param {boolean} on */
  setActive(on) {
    this.active = on;
    this.emit('mode');
    this.request();
  }

  /**
   * Pins pixel (x, y) of the frame on the canvas (y from the bottom) and reads it.
   * @param {number} x
   * @param {number} y
   */
  pin(x, y) {
    const { width, height } = this.app.frames.size;
    if (!width || !height) throw new Error('no frame has been drawn yet');
    const clamp = (v, n) => Math.min(n - 1, Math.max(0, Math.floor(v)));
    this.pinned = { x: clamp(x, width), y: clamp(y, height), of: { width, height } };
    this.readout = null;
    this.problem = null;
    this._lastStart = 0; // a new pin is read at once; only re-reads after frames are spaced
    this.emit('mode');
    this.emit('readout');
    this.request();
  }

  unpin() {
    this.pinned = null;
    this.readout = null;
    this.problem = null;
    this.emit('mode');
    this.emit('readout');
  }

  /** Reads the pinned pixel again (soon: one read at a time, MIN_INTERVAL_MS apart), while Inspect is on. */
  request() {
    if (!this.pinned || !this.active) return;
    this._wanted = true;
    if (!this._running) this._run();
  }

  /**
   * The next complete readout of the pinned pixel (its path and reference settled).
   * @returns {Promise<Readout>}
   */
  complete() {
    return new Promise((resolve, reject) => {
      const check = () => {
        if (!this.pinned) return reject(new Error('no pixel is pinned'));
        if (this.readout?.complete) return resolve(this.readout);
        this.once('readout', check);
      };
      check();
    });
  }

  async _run() {
    this._running = true;
    try {
      while (this._wanted && this.pinned && this.active) {
        this._wanted = false;
        const wait = this._lastStart + MIN_INTERVAL_MS - performance.now();
        if (wait > 0) await new Promise((resolve) => setTimeout(resolve, wait));
        this._lastStart = performance.now();
        await this._read();
      }
    } finally {
      this._running = false;
    }
  }

  /** The names of the app's shader's objects (its ids and SCENE's choices), read once a shader. */
  _objectNames() {
    const { source, controls } = this.app;
    if (this._objects?.source !== source || this._objects.controls !== controls)
      this._objects = { source, controls, name: objectNames(source, controls) };
    return this._objects.name;
  }

  /** One read of the pinned pixel: the GPU's answer, then the path probe's and the reference's. */
  async _read() {
    const app = this.app;
    const pinned = this.pinned;
    if (!pinned) return;
    const program = this.program;
    const wantsPath = program.unavailable === null;
    let probed;
    try {
      // asked before the probe's compile, which the worker would do first (seconds for the torus)
      const asked = app.gpu.ask('probe', { x: pinned.x, y: pinned.y });
      if (wantsPath && !program.ready && !program.compiling) {
        // compiled once; the next read has the path (or says why not)
        program.ensure().then(
          () => this.request(),
          () => this.request(),
        );
      }
      probed = await asked;
    } catch (error) {
      if (/replaced by a newer/.test(error.message)) return;
      this.problem = app.gpu.contextLost ? LOST : `Could not read the pixel: ${error.message}.`;
      this.emit('readout');
      return;
    }
    if (pinned !== this.pinned) return;
    this.problem = null;
    const values = app.values;
    const objectName = this._objectNames();
    const named = (/** @type {PathRay} */ ray) => ({ ...ray, object: objectName(ray.id, values) });
    const { inputs, path } = probed;
    const pathOk = wantsPath && path && probed.probeKey === program.key;
    // the shader's own view of the pixels with extra samples: one of its colours, not its grey
    const tookExtraSamples = probed.shown ? edgeKind(probed.shown, 0) !== null : null;
    const decoded = pathOk ? readPath(path) : null;
    /** @type {Readout} */
    const readout = {
      pixel: { x: pinned.x, y: pinned.y },
      fragCoord: [pinned.x + 0.5, pinned.y + 0.5],
      frame: { time: inputs.time, frame: inputs.frame, width: inputs.width, height: inputs.height },
      color: probed.image,
      canvas: probed.canvas,
      buffers: Object.entries(probed.buffers).map(([name, value]) => ({ name: `Buffer ${name}`, value })),
      path: decoded
        ? {
            rays: decoded.rays.map(named),
            radiance: decoded.radiance,
            extraSamples: tookExtraSamples,
          }
        : null,
      pathNote: pathOk ? null : this._pathNote(),
      reference: null,
      referenceNote: wantsPath ? 'Computing the float64 reference…' : null,
      complete: false,
    };
    readout.complete = !wantsPath || (!pathOk && !program.compiling);
    if (!pathOk && wantsPath) readout.referenceNote = program.compiling ? 'Waits for the path probe.' : 'Needs the path probe.';
    this.readout = readout;
    this.emit('readout');
    if (!pathOk) return;

    const debugView = program.debugView;
    if (debugView) {
      readout.referenceNote = `The float64 reference draws the picture, not the "${debugView}" view on the canvas: set View to Picture to see its colour.`;
      readout.complete = true;
      this.emit('readout');
      return;
    }
    const extraSamples = this._extraSamples(tookExtraSamples);
    if (extraSamples === null) {
      readout.referenceNote =
        'The float64 reference needs to know which pixels took extra samples: this shader\'s VIEW control has no "Extra samples" view.';
      readout.complete = true;
      this.emit('readout');
      return;
    }
    const view = { width: inputs.width, height: inputs.height, time: inputs.time, mouse: inputs.mouse, controls: { ...values } };
    const key = JSON.stringify([pinned.x, pinned.y, view, extraSamples, app.source.length, program.key]);
    if (this._referenceFor?.key !== key) {
      const answer = this.reference.pixel({ source: app.source, view, x: pinned.x, y: pinned.y, extraSamples });
      this._referenceFor = { key, answer };
    }
    try {
      const { rgb, path } = await this._referenceFor.answer;
      const shown = readout.color.slice(0, 3).map((v) => Math.min(1, Math.max(0, v)));
      readout.reference = { rgb, difference: shown.map((v, i) => (v - rgb[i]) * 255), path: path.map(named) };
      readout.referenceNote = null;
    } catch (error) {
      readout.referenceNote = `The float64 reference failed: ${error.message}`;
    }
    readout.complete = true;
    if (this.readout === readout) this.emit('readout');
  }

  /**
   * Whether the reference samples the pixel with the grid of extra samples, as the shader did
   * (null: not known, the shader cannot show them).
   * @param {boolean | null} probed what the path probe's "pixels with extra samples" showed
   */
  _extraSamples(probed) {
    const values = this.app.values;
    if (!(values.SAMPLES > 1)) return false;
    if (!values.ADAPTIVE_AA) return true;
    return this.program.showsAaPixels ? probed === true : null;
  }

  /** Why the readout has no path. */
  _pathNote() {
    const program = this.program;
    const unavailable = program.unavailable;
    if (unavailable) return unavailable[0].toUpperCase() + unavailable.slice(1) + '.';
    if (program.failed?.key === program.key) return `The path probe did not compile: ${firstLine(program.failed.error)}`;
    if (program.compiling) return 'Compiling the path probe (the shader once more, recording its rays)…';
    return 'Waiting for the path probe.';
  }

  /** The canvas changed size: the pinned pixel keeps its place in the picture. */
  _rescale(width, height) {
    const { x, y, of } = /** @type {NonNullable<Inspector['pinned']>} */ (this.pinned);
    const at = (v, from, to) => Math.min(to - 1, Math.max(0, Math.floor(((v + 0.5) / from) * to)));
    this.pinned = { x: at(x, of.width, width), y: at(y, of.height, height), of: { width, height } };
    this.emit('mode');
  }
}

/** The first line of an error's report or message. @param {Error & {report?: string}} error */
function firstLine(error) {
  return (error.report || error.message).split('\n').find((line) => line.trim()) ?? error.message;
}
