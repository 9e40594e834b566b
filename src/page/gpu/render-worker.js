// The render worker: the page's GPU work, off the page's main thread. It owns an OffscreenCanvas
// of its own (not one transferred from the page: a transferred canvas ties the page's main
// thread to the GPU, and one endless draw then freezes the whole page), draws frames there in
// bands (band-planner.js), polls a fence after each band instead of waiting for the GPU, and
// hands each finished frame to the page as an ImageBitmap, which the page's canvas shows.
// Nothing the page's script does waits for the GPU, but painting those bitmaps does, so a draw
// that may never end waits until the page has painted them (paint-gate.js). The page
// (app/render-client.js) sees the bands come in and knows when they stop coming. What it is
// asked and what it answers is protocol.js's.

import { ShaderRenderer } from './renderer.js';
import { writeUniforms } from './uniforms.js';
import { BandPlanner } from './band-planner.js';
import { flipRows } from '../../shared/pixels.js';
import { serve } from './protocol.js';
import { PaintGate } from './paint-gate.js';
import { CubeBuffer } from './channels/cube-buffer.js';
import { TILE_OFFSET_UNIFORM } from '../../shadertoy/header.js';

/** @typedef {import('./protocol.js').FrameInputs} FrameInputs */
/** @typedef {import('./protocol.js').DrawnFrame} DrawnFrame */
/** @typedef {import('./protocol.js').ProbedPixel} ProbedPixel */

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
 * @property {number} step the pass being drawn (an index into renderer().steps; a capture draws
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

/** The renderer, once start() has made it. @type {ShaderRenderer | null} */
let made = null;
const planner = new BandPlanner();
/** @type {Job | null} */
let job = null;
/** A compiled path probe's first draw is still to come (compileProbe's warm-up job). */
let probeWarming = false;
/** Jobs waiting for the one under way. @type {Job[]} */
const waiting = [];
/** The band the GPU is drawing (`warmUp`: a new program's first draw, see pump; `compiling`: the
 * watchdog is told that it includes a compile). @type {{sync: WebGLSync, rows: number, started: number, warmUp: boolean} | null} */
let band = null;
/** The programs (materials) drawn at least once since they compiled. @type {WeakSet<object>} */
const drawnPrograms = new WeakSet();
let lastPresent = 0;
/** WEBGL_lose_context, kept from the loss it caused for the restore. @type {WEBGL_lose_context | null} */
let loseContext = null;
/** The inputs of the last frame finished (a probe reads that frame). @type {FrameInputs | null} */
let lastFrame = null;
/** A program's first draw waits until the page has painted the bitmaps it was sent. */
const paints = new PaintGate(
  () => tell('awaitingPaint', {}),
  () => pump(),
);

/**
 * The renderer. Only start() can fail to make it, and then the page is told 'failed' and asks
 * this worker nothing more.
 */
function renderer() {
  if (!made) throw new Error('the renderer was not made');
  return made;
}

/**
 * A frame or capture, queued; resolves when it is done.
 * @param {Omit<JobState, 'step' | 'y' | 'redo' | 'resolve' | 'reject'> & JobKind} fields
 */
function enqueue(fields) {
  return new Promise((resolve, reject) => {
    waiting.push({ ...fields, step: 0, y: 0, redo: false, resolve, reject });
    pump();
  });
}

/**
 * A probe of one pixel of the last frame (warmUp: the path probe's first draw, compileProbe's).
 * @param {{x: number, y: number}} pixel
 */
function enqueueProbe(pixel, warmUp = false) {
  return enqueue({ kind: 'probe', inputs: null, width: 1, height: 1, readBack: true, target: null, pixel, warmUp });
}

/** Something the picture depends on changed: the frame under way starts again, and its cost is
 * learnt again (a control can make a shader far heavier). */
function changed() {
  planner.forget();
  if (!job) return;
  job.y = 0;
  job.redo = Boolean(band); // the band in flight has the old state
}

/** Starts the next band, if the GPU is free and there is something to draw. */
function pump() {
  if (band || !made || renderer().contextLost) return;
  if (!job) {
    job = waiting.shift() ?? null;
    if (!job) return;
    if (job.kind === 'frame' && (job.width !== renderer().width || job.height !== renderer().height)) {
      renderer().setSize(job.width, job.height);
      planner.forget();
    }
  }
  if (!made.hasProgram) {
    job.reject(new Error('no shader has compiled'));
    job = null;
    return pump();
  }
  if (job.kind === 'probe') return startProbe(job);
  const steps = renderer().steps;
  // a capture draws only the Image pass over the buffers as they are, unless it is a recorded
  // frame of a multipass shader (allPasses); a new shader meanwhile may have fewer passes
  if ((job.kind === 'capture' && !job.allPasses) || job.step >= steps.length) job.step = steps.length - 1;
  const step = steps[job.step];
  const first = job.step === 0 && job.y === 0;
  const last = job.step === steps.length - 1;
  if ((job.inputs.media || job.inputs.passMedia) && !job.mediaSet) {
    if (job.inputs.media) renderer().setMedia(job.inputs.media);
    if (job.inputs.passMedia) renderer().passMedia.setFrames(job.inputs.passMedia);
    job.mediaSet = true;
  }
  if (first && job.kind === 'frame') {
    renderer().gpuTimer.begin();
    if (job.inputs.keyboard) renderer().setKeyboard(job.inputs.keyboard);
  }
  const { tile } = job;
  writeUniforms(
    renderer().uniforms,
    job.inputs,
    tile ? { width: tile.fullWidth, height: tile.fullHeight } : { width: job.width, height: job.height },
  );
  const drawn = tile
    ? /** @type {import('./pass-compiler.js').Step} */ (renderer().tiledStep)
    : job.program === 'aa-pixels'
      ? renderer().probe.mainImageAt(0, 0)
      : step;
  if (tile) drawn.material.uniforms[TILE_OFFSET_UNIFORM].value = [tile.x, tile.y];
  const target = renderer().beginStep(drawn, job.width, job.height) ?? job.target;
  // SwiftShader turns a program into machine code on its first draw, not when it links (the
  // raytracer's torus scene: 22 ms to link, 2.4 s for its first draw, 17 ms for the next band).
  // So a program's first draw is scissored to no pixel: SwiftShader compiles for it and runs the
  // shader nowhere. That band, the compile alone, the watchdog knows as compiling
  // (render-client.js) and the planner does not time; a loop that never ends runs only in the
  // bands after it, which the watchdog knows as drawing (a first quad of real pixels ran it
  // inside the compile's band, called compiling until TIMEOUTS.compileHangMs).
  if (!drawnPrograms.has(drawn.material)) {
    if (!paints.mayDraw()) return;
    drawnPrograms.add(drawn.material);
    renderer().drawRegion(target, 0, job.y, 0, 0);
    startBand(0, { warmUp: true, compiling: true });
    return;
  }
  // the Cube A pass is its six faces stacked, and a band stops at a face's top (renderer.js)
  const extent = CubeBuffer.extent(drawn, job.width, job.height);
  const rows = renderer().drawRows(job.y, job.y + planner.rows(extent.width, extent.height - job.y), target);
  if (last && job.y + rows >= job.height && job.kind === 'frame') renderer().gpuTimer.end();
  startBand(rows);
}

/**
 * The GPU has the band's draws: watch for its end.
 * @param {number} rows rows of the job it draws (0 for a warm-up)
 * @param {{warmUp?: boolean, compiling?: boolean}} [options] warmUp: a new program's first
 *   draw, of no pixel (pump); compiling: the band includes a program's first draw
 */
function startBand(rows, { warmUp = false, compiling = false } = {}) {
  const gl = renderer().gl;
  const sync = gl.fenceSync(gl.SYNC_GPU_COMMANDS_COMPLETE, 0);
  if (!sync) return; // the context is lost: webglcontextlost rejects the jobs
  gl.flush();
  band = { sync, rows, started: performance.now(), warmUp };
  tell('bandStarted', { compiling });
  setTimeout(poll, POLL_MS);
}

/** A probe's draws (probe.js), over the last frame drawn: one band of its own. @param {Job & {kind: 'probe'}} probe */
function startProbe(probe) {
  if (!lastFrame) {
    probe.reject(new Error('no frame has been drawn yet'));
    job = null;
    return pump();
  }
  const { width, height } = lastFrame;
  const { x, y } = probe.pixel;
  if (!(x >= 0 && y >= 0 && x < width && y < height)) {
    probe.reject(new Error(`pixel (${x}, ${y}) is outside the ${width}x${height} frame`));
    job = null;
    return pump();
  }
  writeUniforms(renderer().uniforms, lastFrame);
  // The path probe's first draw compiles it (pump: seconds for the torus scene), and the watchdog
  // is told so. A pixel asked for while that draw is still to come (compileProbe's warm-up job,
  // queued behind it) gets its colour at once, without the path.
  const material = renderer().probe.step?.material;
  const warm = Boolean(material) && drawnPrograms.has(material);
  probe.withPath = Boolean(material) && (warm || probe.warmUp || !probeWarming);
  const compiling = probe.withPath && !warm;
  if (compiling && !paints.mayDraw()) return;
  renderer().probe.draw(x, y, width, height, probe.withPath);
  if (compiling) drawnPrograms.add(/** @type {object} */ (material));
  startBand(1, { compiling });
}

function poll() {
  if (!band || !made) return; // the context was lost meanwhile
  const gl = renderer().gl;
  if (gl.getSyncParameter(band.sync, gl.SYNC_STATUS) !== gl.SIGNALED) {
    setTimeout(poll, POLL_MS);
    return;
  }
  gl.deleteSync(band.sync);
  const { rows, started, warmUp } = band;
  band = null;
  if (warmUp) {
    if (job) job.redo = false; // it drew no rows: a change meanwhile has nothing to undo
    tell('band', { kind: 'compile', y: job?.y ?? 0, height: job?.height ?? 0, bitmap: null });
  } else bandDone(rows, performance.now() - started);
  pump();
}

/** @param {number} rows @param {number} ms */
function bandDone(rows, ms) {
  if (!job || !made) return;
  if (job.kind === 'probe') {
    const probe = job;
    job = null;
    tell('band', { kind: 'probe', y: 1, height: 1, bitmap: null });
    // startProbe drew over lastFrame, and no frame can finish while the probe's band is the job
    const inputs = /** @type {FrameInputs} */ (lastFrame);
    /** @type {ProbedPixel} */
    const probed = { ...renderer().probe.read(probe.pixel.x, probe.pixel.y, probe.withPath), inputs };
    probe.resolve(probed);
    return;
  }
  const extent = CubeBuffer.extent(renderer().steps[job.step], job.width, job.height);
  planner.measured(extent.width, rows, ms);
  if (job.redo) job.redo = false;
  else job.y += rows;
  if (job.y >= extent.height && job.step < renderer().steps.length - 1) {
    renderer().endStep(renderer().steps[job.step]); // a buffer is done: the next pass reads it
    job.step++;
    job.y = 0;
  }
  // the pass now under way: the next one's rows start at 0 (the Cube A pass has more than the frame)
  const { height } = CubeBuffer.extent(renderer().steps[job.step], job.width, job.height);
  const done = job.y >= height;
  const now = performance.now();
  const show = !done && job.kind === 'frame' && job.progressive && now - lastPresent > PRESENT_EVERY_MS;
  if (show) lastPresent = now;
  tell('band', { kind: job.kind, y: job.y, height, bitmap: show ? renderer().present() : null });
  if (!done) return;
  const finished = job;
  job = null;
  if (finished.kind === 'frame') {
    lastPresent = now;
    lastFrame = finished.inputs;
    const pixels = finished.readBack ? readOpaque(finished.target, finished.width, finished.height) : null;
    /** @type {DrawnFrame} */
    const drawn = { bitmap: renderer().present(), pixels, gpuTimes: renderer().gpuTimer.poll(), program: renderer().installed };
    finished.resolve(drawn);
  } else {
    const pixels = finished.float
      ? readFloat(finished.target, finished.width, finished.height)
      : readOpaque(finished.target, finished.width, finished.height);
    finished.target.dispose();
    finished.resolve(pixels);
  }
}

/** A float target's pixels, RGBA32F, rows top to bottom. */
function readFloat(target, width, height) {
  const pixels = new Float32Array(width * height * 4);
  renderer().three.readRenderTargetPixels(target, 0, 0, width, height, pixels);
  const row = width * 4;
  const out = new Float32Array(pixels.length);
  for (let y = 0; y < height; y++) out.set(pixels.subarray((height - 1 - y) * row, (height - y) * row), y * row);
  return out;
}

/** A target's pixels as the page shows them: rows top to bottom, alpha 1 (the page's canvas has none). */
function readOpaque(target, width, height) {
  const pixels = flipRows(renderer().readTarget(target), width, height);
  for (let i = 3; i < pixels.length; i += 4) pixels[i] = 255;
  return pixels;
}

/** Makes the renderer on a canvas of the worker's own, and follows its context. */
function start() {
  const canvas = new OffscreenCanvas(1, 1);
  try {
    made = new ShaderRenderer(canvas);
  } catch (error) {
    tell('failed', { name: error.name, message: error.message });
    return;
  }
  canvas.addEventListener('webglcontextlost', (event) => {
    event.preventDefault(); // tells the browser we want it back (three.js does too)
    band = null;
    for (const lost of [job, ...waiting]) lost?.reject(new Error('the GPU context was lost'));
    job = null;
    waiting.length = 0;
    lastFrame = null; // its target is gone with the context: readFrame and a probe wait for a new frame
    tell('context', { lost: true });
  });
  canvas.addEventListener('webglcontextrestored', () => {
    // three.js has rebuilt its state; programs and textures are made again from our objects
    renderer().forgetCompiled();
    planner.forget();
    tell('context', { lost: false });
  });
  tell('ready', { maxSize: renderer().maxSize, info: renderer().info() });
}

/** The worker's scope as serve() sees it, counting the bitmaps that go to the page. */
const counted = {
  /** @param {any} message @param {Transferable[]} transfer */
  postMessage(message, transfer) {
    paints.sending(transfer);
    /** @type {any} */ (self).postMessage(message, transfer); // a worker's postMessage (the types know a window's)
  },
  /** @param {any} handler */
  set onmessage(handler) {
    self.onmessage = handler;
  },
};

const tell = serve(
  counted,
  {
    async compile({ project, hostBlock, fileName, serial }) {
      try {
        const sound = await renderer().sound.compile(project); // the Sound tab, if any (sound-pass.js)
        await renderer().compile(project, hostBlock, fileName, serial);
        if (renderer().installed === serial) renderer().sound.install(sound);
        changed();
        return null;
      } finally {
        pump();
      }
    },

    frame({ inputs, readBack, progressive }) {
      // a frame the page asks for replaces one that has not started yet
      const stale = waiting.findIndex((queued) => queued.kind === 'frame');
      if (stale >= 0) waiting.splice(stale, 1)[0].reject(new Error('replaced by a newer frame'));
      const { width, height } = inputs;
      return enqueue({ kind: 'frame', inputs, width, height, readBack, progressive, target: renderer().frameTarget });
    },

    readFrame() {
      if (!lastFrame) throw new Error('no frame has been drawn yet');
      if (job?.kind === 'frame') throw new Error('a frame is under way: its target is being drawn');
      return readOpaque(renderer().frameTarget, lastFrame.width, lastFrame.height);
    },

    capture({ inputs, width, height, allPasses, program }) {
      if (program && !renderer().probe.step) throw new Error('the path probe has not compiled');
      const target = renderer().makeTarget(width, height);
      return enqueue({ kind: 'capture', inputs, width, height, readBack: true, target, allPasses, program });
    },

    async captureTile({ inputs, x, y, width, height, fullWidth, fullHeight }) {
      const step = await renderer().tiled();
      if (renderer().tiledStep !== step) throw new Error('another shader was loaded meanwhile');
      const target = renderer().makeTarget(width, height);
      return enqueue({ kind: 'capture', inputs, width, height, readBack: true, target, tile: { x, y, fullWidth, fullHeight } });
    },

    captureFloat({ inputs, width, height }) {
      const target = renderer().makeTarget(width, height, true);
      return enqueue({ kind: 'capture', inputs, width, height, readBack: true, target, float: true });
    },

    async compileProbe({ project, hostBlock, fileName, key, texels }) {
      probeWarming = true;
      try {
        await renderer().probe.compile(project, hostBlock, fileName, key, texels);
        // its first draw, queued behind what is asked already: a pixel asked for before that is
        // read without waiting for it (startProbe); the reply comes once the probe is ready
        if (lastFrame) await enqueueProbe({ x: 0, y: 0 }, true);
      } finally {
        probeWarming = false;
      }
      return null;
    },

    probe({ x, y }) {
      // a newer probe replaces one that has not started
      const stale = waiting.findIndex((queued) => queued.kind === 'probe' && !queued.warmUp);
      if (stale >= 0) waiting.splice(stale, 1)[0].reject(new Error('replaced by a newer probe'));
      return enqueueProbe({ x, y });
    },

    sound({ first, count, date }) {
      return renderer().sound.render(first, count, date);
    },

    bench({ inputs, n }) {
      const times = [];
      renderer().setSize(inputs.width, inputs.height);
      writeUniforms(renderer().uniforms, inputs);
      for (let i = 0; i < n; i++) {
        const begun = performance.now();
        renderer().render();
        renderer().readTarget(renderer().frameTarget, 0, 0, 1, 1); // waits until the GPU has finished
        times.push(performance.now() - begun);
      }
      return times;
    },
  },
  {
    init: start,

    clearBuffers() {
      renderer().buffers.clear();
      renderer().cube.clear();
      changed();
    },

    controlUniforms({ controls, values }) {
      renderer().setControlUniforms(controls, values);
      changed();
    },

    controlUniform({ name, value }) {
      renderer().setControlUniform(name, value);
      changed();
    },

    channel({ index, image }) {
      renderer().setChannel(index, image);
      changed();
    },

    passMedia(media) {
      renderer().passMedia.set(media);
      changed();
    },

    settled({ bitmaps: count }) {
      paints.settle(count);
    },

    loseContext() {
      loseContext = renderer().gl.getExtension('WEBGL_lose_context');
      loseContext?.loseContext();
    },

    restoreContext() {
      loseContext?.restoreContext(); // the extension is not to be had while the context is lost
    },
  },
);
