// The render worker's scheduler: the frames, captures and probes the page asks for, queued, and
// drawn one band at a time. Each band is a few rows of one pass (band-planner.js sizes it to the
// GPU's measured speed), sent to the GPU with a fence that is polled, never waited on, so the
// worker keeps answering while a heavy frame is drawn. A change to what the picture depends on
// (changed()) starts the frame under way again. A program's first draw is a band of no pixel
// (SwiftShader compiles it then), which waits until the page has painted what it was sent
// (paint-gate.js). What the page is told of the bands ('bandStarted', 'band', 'awaitingPaint') is
// protocol.js's; render-worker.js turns the page's requests into this scheduler's jobs.

import { writeUniforms } from '../uniforms.js';
import { BandPlanner } from './band-planner.js';
import { PaintGate } from './paint-gate.js';
import { CubeBuffer } from '../channels/cube-buffer.js';
import { TILE_OFFSET_UNIFORM } from '../../../shadertoy/header.js';

/** @typedef {import('../renderer.js').ShaderRenderer} ShaderRenderer */
/** @typedef {import('../protocol.js').FrameInputs} FrameInputs */
/** @typedef {import('../protocol.js').DrawnFrame} DrawnFrame */
/** @typedef {import('../protocol.js').ProbedPixel} ProbedPixel */
/** @typedef {ReturnType<typeof import('../protocol.js').serve>} Tell */

/** How often an unfinished band's fence is looked at (browsers clamp shorter timeouts to ~4 ms). */
const POLL_MS = 2;
/** How often a frame that is still being drawn is shown as far as it got. */
const PRESENT_EVERY_MS = 250;

/**
 * A frame, a capture or a probe under way: a probe reads the last frame drawn at its pixel (y
 * from the bottom).
 * @typedef {JobState & JobKind} Job
 * @typedef {{kind: 'frame' | 'capture', inputs: FrameInputs} | {kind: 'probe', inputs: null, pixel: {x: number, y: number}, warmUp?: boolean, withPath?: boolean}} JobKind
 */

/**
 * @typedef {object} JobState
 * @property {number} width
 * @property {number} height
 * @property {boolean} readBack
 * @property {boolean} [progressive] a frame shown as it builds up (the page's 'frame' request)
 * @property {any} target the render target drawn into
 * @property {number} step the pass being drawn (an index into renderer.steps; a capture draws
 *   only the last, the Image pass, over the buffers as they are)
 * @property {number} y rows of it done
 * @property {boolean} redo something changed while a band was being drawn: it starts again
 * @property {boolean} [mediaSet] its moving channels' textures are in (FrameInputs.media)
 * @property {boolean} [allPasses] a capture that draws every pass (a recorded frame)
 * @property {boolean} [float] a capture read as RGBA32F
 * @property {'aa-pixels'} [program] a capture of the path probe's mainImage instead of the Image pass
 * @property {{x: number, y: number, fullWidth: number, fullHeight: number}} [tile] a capture of
 *   the tile at (x, y) (from the bottom left) of a fullWidth × fullHeight picture (renderer.tiled())
 * @property {(result: any) => void} resolve
 * @property {(error: Error) => void} reject
 */

/** A band of rows: the step it draws (the band planner learns each one's cost) and its first row. @typedef {{step: object, y: number}} BandPass */

/** The fields a job is queued with; the scheduler adds its progress and its promise's ends. @typedef {Omit<JobState, 'step' | 'y' | 'redo' | 'resolve' | 'reject'> & JobKind} JobFields */

export class BandScheduler {
  /**
   * @param {() => ShaderRenderer | null} made the renderer, once the worker has made it
   * @param {Tell} tell sends an event to the page
   */
  constructor(made, tell) {
    this._made = made;
    this._tell = tell;
    this._planner = new BandPlanner();
    /** @type {Job | null} */
    this._job = null;
    /** A compiled path probe's first draw is still to come (warmProbe's job). */
    this._probeWarming = false;
    /** Jobs waiting for the one under way. @type {Job[]} */
    this._waiting = [];
    /** The band the GPU is drawing (`warmUp`: a new program's first draw, see pump; `pass`: what the planner learns its cost for). @type {{sync: WebGLSync, rows: number, started: number, warmUp: boolean, pass: BandPass | null} | null} */
    this._band = null;
    /** The programs (materials) drawn at least once since they compiled. @type {WeakSet<object>} */
    this._drawnPrograms = new WeakSet();
    this._lastPresent = 0;
    /** The inputs of the last frame finished (a probe and readFrame read that frame). @type {FrameInputs | null} */
    this.lastFrame = null;
    /** A program's first draw waits until the page has painted the bitmaps it was sent. */
    this.paints = new PaintGate(
      () => this._tell('awaitingPaint', {}),
      () => this.pump(),
    );
  }

  /** The renderer. Only the worker's start can fail to make it, and then nothing is asked of it. */
  get _renderer() {
    const renderer = this._made();
    if (!renderer) throw new Error('the renderer was not made');
    return renderer;
  }

  /** A frame or capture, queued; resolves when it is done. @param {JobFields} fields */
  enqueue(fields) {
    return new Promise((resolve, reject) => {
      this._waiting.push({ ...fields, step: 0, y: 0, redo: false, resolve, reject });
      this.pump();
    });
  }

  /**
   * A frame for the page: it replaces one that has not started yet.
   * @param {{inputs: FrameInputs, readBack: boolean, progressive: boolean}} frame
   * @returns {Promise<DrawnFrame>}
   */
  frame({ inputs, readBack, progressive }) {
    this._dropWaiting((queued) => queued.kind === 'frame', 'replaced by a newer frame');
    const { width, height } = inputs;
    return this.enqueue({ kind: 'frame', inputs, width, height, readBack, progressive, target: this._renderer.frameTarget });
  }

  /**
   * A probe of one pixel of the last frame: it replaces one that has not started (but a warm-up).
   * @param {{x: number, y: number}} pixel
   * @returns {Promise<ProbedPixel>}
   */
  probe(pixel) {
    this._dropWaiting((queued) => queued.kind === 'probe' && !queued.warmUp, 'replaced by a newer probe');
    return this._enqueueProbe(pixel);
  }

  /**
   * Compiles the path probe (`compile`), then queues its first draw behind what is asked already:
   * a pixel asked for before that is read without waiting for it (startProbe).
   * @param {() => Promise<void>} compile
   */
  async warmProbe(compile) {
    this._probeWarming = true;
    try {
      await compile();
      if (this.lastFrame) await this._enqueueProbe({ x: 0, y: 0 }, true);
    } finally {
      this._probeWarming = false;
    }
  }

  /** The last frame drawn for the page, read back from its target as it was drawn. */
  readFrame() {
    if (!this.lastFrame) throw new Error('no frame has been drawn yet');
    if (this._job?.kind === 'frame') throw new Error('a frame is under way: its target is being drawn');
    return this._renderer.readOpaque(this._renderer.frameTarget, this.lastFrame.width, this.lastFrame.height);
  }

  /** Something the picture depends on changed: the frame under way starts again, and its cost is
   * learnt again (a control can make a shader far heavier). */
  changed() {
    this._planner.forget();
    if (!this._job) return;
    this._job.y = 0;
    this._job.redo = Boolean(this._band); // the band in flight has the old state
  }

  /** The context was lost: every job fails, and the last frame's target is gone with it. */
  contextLost() {
    this._band = null;
    for (const lost of [this._job, ...this._waiting]) lost?.reject(new Error('the GPU context was lost'));
    this._job = null;
    this._waiting.length = 0;
    this.lastFrame = null; // readFrame and a probe wait for a new frame
  }

  /** The context is back: the bands' cost is learnt again. */
  contextRestored() {
    this._planner.forget();
  }

  /** @param {(job: Job) => boolean} match @param {string} why */
  _dropWaiting(match, why) {
    const stale = this._waiting.findIndex(match);
    if (stale >= 0) this._waiting.splice(stale, 1)[0].reject(new Error(why));
  }

  /**
   * A probe of one pixel of the last frame (warmUp: the path probe's first draw, warmProbe's).
   * @param {{x: number, y: number}} pixel
   */
  _enqueueProbe(pixel, warmUp = false) {
    return this.enqueue({ kind: 'probe', inputs: null, width: 1, height: 1, readBack: true, target: null, pixel, warmUp });
  }

  /** Starts the next band, if the GPU is free and there is something to draw. */
  pump() {
    const made = this._made();
    if (this._band || !made || made.contextLost) return;
    const renderer = made;
    if (!this._job) {
      this._job = this._waiting.shift() ?? null;
      if (!this._job) return;
      if (this._job.kind === 'frame' && (this._job.width !== renderer.width || this._job.height !== renderer.height)) {
        renderer.setSize(this._job.width, this._job.height);
        this._planner.forget();
      }
    }
    const job = this._job;
    if (!renderer.hasProgram) {
      job.reject(new Error('no shader has compiled'));
      this._job = null;
      return this.pump();
    }
    if (job.kind === 'probe') return this._startProbe(job);
    const steps = renderer.steps;
    // a capture draws only the Image pass over the buffers as they are, unless it is a recorded
    // frame of a multipass shader (allPasses); a new shader meanwhile may have fewer passes
    if ((job.kind === 'capture' && !job.allPasses) || job.step >= steps.length) job.step = steps.length - 1;
    const step = steps[job.step];
    const first = job.step === 0 && job.y === 0;
    const last = job.step === steps.length - 1;
    if ((job.inputs.media || job.inputs.passMedia) && !job.mediaSet) {
      if (job.inputs.media) renderer.inputs.setMedia(job.inputs.media);
      if (job.inputs.passMedia) renderer.passMedia.setFrames(job.inputs.passMedia);
      job.mediaSet = true;
    }
    if (first && job.kind === 'frame') {
      renderer.gpuTimer.begin();
      if (job.inputs.keyboard) renderer.inputs.setKeyboard(job.inputs.keyboard);
    }
    const { tile } = job;
    writeUniforms(
      renderer.uniforms,
      job.inputs,
      tile ? { width: tile.fullWidth, height: tile.fullHeight } : { width: job.width, height: job.height },
    );
    const drawn = tile
      ? /** @type {import('../pass-compiler.js').Step} */ (renderer.tiledStep)
      : job.program === 'aa-pixels'
        ? renderer.probe.mainImageAt(0, 0)
        : step;
    if (tile) drawn.material.uniforms[TILE_OFFSET_UNIFORM].value = [tile.x, tile.y];
    const target = renderer.beginStep(drawn, job.width, job.height) ?? job.target;
    // SwiftShader turns a program into machine code on its first draw, not when it links (the
    // studio's built-in shader, torus scene: 22 ms to link, 2.4 s for its first draw, 17 ms for
    // the next band).
    // So a program's first draw is scissored to no pixel: SwiftShader compiles for it and runs the
    // shader nowhere. That band, the compile alone, the watchdog knows as compiling
    // (render-client.js) and the planner does not time; a loop that never ends runs only in the
    // bands after it, which the watchdog knows as drawing (a first quad of real pixels ran it
    // inside the compile's band, called compiling until TIMEOUTS.compileHangMs).
    if (!this._drawnPrograms.has(drawn.material)) {
      if (!this.paints.mayDraw()) return;
      this._drawnPrograms.add(drawn.material);
      renderer.drawRegion(target, 0, job.y, 0, 0);
      this._startBand(0, { warmUp: true, compiling: true });
      return;
    }
    // the Cube A pass is its six faces stacked, and a band stops at a face's top (renderer.js)
    const extent = CubeBuffer.extent(drawn, job.width, job.height);
    const rows = renderer.drawRows(job.y, job.y + this._planner.rows(drawn, extent.width, job.y, extent.height - job.y), target);
    if (last && job.y + rows >= job.height && job.kind === 'frame') renderer.gpuTimer.end();
    this._startBand(rows, { pass: { step: drawn, y: job.y } });
  }

  /**
   * The GPU has the band's draws: watch for its end.
   * @param {number} rows rows of the job it draws (0 for a warm-up)
   * @param {{warmUp?: boolean, compiling?: boolean, pass?: BandPass}} [options] warmUp: a new
   *   program's first draw, of no pixel (pump); compiling: the band includes a program's first
   *   draw (the watchdog is told so); pass: the step a band of rows draws and its first row
   */
  _startBand(rows, { warmUp = false, compiling = false, pass } = {}) {
    const gl = this._renderer.gl;
    const sync = gl.fenceSync(gl.SYNC_GPU_COMMANDS_COMPLETE, 0);
    if (!sync) return; // the context is lost: webglcontextlost rejects the jobs
    gl.flush();
    this._band = { sync, rows, started: performance.now(), warmUp, pass: pass ?? null };
    this._tell('bandStarted', { compiling });
    setTimeout(() => this._poll(), POLL_MS);
  }

  /** A probe's draws (probe.js), over the last frame drawn: one band of its own. @param {Job & {kind: 'probe'}} probe */
  _startProbe(probe) {
    const renderer = this._renderer;
    const lastFrame = this.lastFrame;
    if (!lastFrame) {
      probe.reject(new Error('no frame has been drawn yet'));
      this._job = null;
      return this.pump();
    }
    const { width, height } = lastFrame;
    const { x, y } = probe.pixel;
    if (!(x >= 0 && y >= 0 && x < width && y < height)) {
      probe.reject(new Error(`pixel (${x}, ${y}) is outside the ${width}x${height} frame`));
      this._job = null;
      return this.pump();
    }
    writeUniforms(renderer.uniforms, lastFrame);
    // The path probe's first draw compiles it (pump: seconds for the torus scene), and the watchdog
    // is told so. A pixel asked for while that draw is still to come (warmProbe's job, queued
    // behind it) gets its colour at once, without the path.
    const material = renderer.probe.step?.material;
    const warm = Boolean(material) && this._drawnPrograms.has(material);
    probe.withPath = Boolean(material) && (warm || probe.warmUp || !this._probeWarming);
    const compiling = probe.withPath && !warm;
    if (compiling && !this.paints.mayDraw()) return;
    renderer.probe.draw(x, y, width, height, probe.withPath);
    if (compiling) this._drawnPrograms.add(/** @type {object} */ (material));
    this._startBand(1, { compiling });
  }

  _poll() {
    const band = this._band;
    if (!band || !this._made()) return; // the context was lost meanwhile
    const gl = this._renderer.gl;
    if (gl.getSyncParameter(band.sync, gl.SYNC_STATUS) !== gl.SIGNALED) {
      setTimeout(() => this._poll(), POLL_MS);
      return;
    }
    gl.deleteSync(band.sync);
    const { rows, started, warmUp, pass } = band;
    this._band = null;
    const job = this._job;
    if (warmUp) {
      if (job) job.redo = false; // it drew no rows: a change meanwhile has nothing to undo
      this._tell('band', { kind: 'compile', y: job?.y ?? 0, height: job?.height ?? 0, bitmap: null });
    } else this._bandDone(rows, performance.now() - started, pass);
    this.pump();
  }

  /** @param {number} rows @param {number} ms @param {BandPass | null} pass */
  _bandDone(rows, ms, pass) {
    const job = this._job;
    const renderer = this._made();
    if (!job || !renderer) return;
    if (job.kind === 'probe') {
      this._job = null;
      this._tell('band', { kind: 'probe', y: 1, height: 1, bitmap: null });
      // startProbe drew over lastFrame, and no frame can finish while the probe's band is the job
      const inputs = /** @type {FrameInputs} */ (this.lastFrame);
      /** @type {ProbedPixel} */
      const probed = { ...renderer.probe.read(job.pixel.x, job.pixel.y, job.withPath), inputs };
      job.resolve(probed);
      return;
    }
    const extent = CubeBuffer.extent(renderer.steps[job.step], job.width, job.height);
    if (pass) this._planner.measured(pass.step, extent.width, pass.y, rows, ms);
    // what llvmpipe's loop limit cut in the band (loop-cuts.js); told to, a frame with a cut goes
    // no further: its picture is not the shader's, and a loop that never ends costs the limit in
    // every pixel
    const cut = renderer.loopCuts.collect();
    if (job.redo) job.redo = false;
    else job.y += rows;
    if (cut && renderer.loopCuts.stopOnCut) {
      job.step = renderer.steps.length - 1;
      job.y = CubeBuffer.extent(renderer.steps[job.step], job.width, job.height).height;
    } else if (job.y >= extent.height && job.step < renderer.steps.length - 1) {
      renderer.endStep(renderer.steps[job.step]); // a buffer is done: the next pass reads it
      job.step++;
      job.y = 0;
    }
    // the pass now under way: the next one's rows start at 0 (the Cube A pass has more than the frame)
    const { height } = CubeBuffer.extent(renderer.steps[job.step], job.width, job.height);
    const done = job.y >= height;
    const now = performance.now();
    const show = !done && job.kind === 'frame' && job.progressive && now - this._lastPresent > PRESENT_EVERY_MS;
    if (show) this._lastPresent = now;
    this._tell('band', { kind: job.kind, y: job.y, height, bitmap: show ? renderer.present() : null });
    if (!done) return;
    this._job = null;
    if (job.kind === 'frame') {
      this._lastPresent = now;
      this.lastFrame = job.inputs;
      const pixels = job.readBack ? renderer.readOpaque(job.target, job.width, job.height) : null;
      /** @type {DrawnFrame} */
      const drawn = { bitmap: renderer.present(), pixels, gpuTimes: renderer.gpuTimer.poll(), program: renderer.installed };
      job.resolve(drawn);
    } else {
      const pixels = job.float
        ? renderer.readFloat(job.target, job.width, job.height)
        : renderer.readOpaque(job.target, job.width, job.height);
      job.target.dispose();
      job.resolve(pixels);
    }
  }
}
