// The render worker: the page's GPU work, off the page's main thread. It owns an OffscreenCanvas
// of its own (not one transferred from the page: a transferred canvas ties the page's main
// thread to the GPU, and one endless draw then freezes the whole page), draws frames there in
// bands (band-planner.js), polls a fence after each band instead of waiting for the GPU, and
// hands each finished frame to the page as an ImageBitmap, which the page's canvas shows.
// Nothing the page's script does ever waits for the GPU; the page (render-client.js) sees the
// bands come in and knows when they stop coming.
//
// Messages from the page (render-client.js), each {type, ...}:
//   init                      → ready {maxSize, info} | failed {name, message}
//   compile {id, project, hostBlock, fileName}  → compiled {id, error?}: every pass of a shader
//   clearBuffers              Restart: every buffer of a multipass shader to 0
//   controlUniforms {controls, values}, controlUniform {name, value}, channel {index, image}
//   frame {id, inputs, readBack}     a frame for the page, drawn band by band:
//                             → bandStarted when a band goes to the GPU, band {id, y, height,
//                               bitmap?} when the GPU has finished it (a bitmap now and
//                               then: the frame building up), then drawn {id, bitmap, pixels?,
//                               gpuTimes}; pixels (readBack) are RGBA8, rows top to bottom
//   capture {id, inputs, width, height, allPasses}   the same frame at another size, off screen
//                               (allPasses: every pass, buffers included, at their size)
//                             → band …, then captured {id, pixels}
//   bench {id, inputs, n}     n whole frames back to back, each waited for → benched {id, times}
//   loseContext, restoreContext      WEBGL_lose_context, for tests of a lost context
// and unprompted: context {lost}; jobFailed {id, message} for a frame or capture the context
// took with it.
//
// A change (a compile that succeeds, a uniform, a channel) while a frame is being drawn starts
// that frame again from its first band: what the page shows next has the change throughout.

import { ShaderRenderer } from './renderer.js';
import { writeUniforms } from './shadertoy-inputs.js';
import { BandPlanner } from './band-planner.js';
import { flipRows } from './pixels.js';

/** How often an unfinished band's fence is looked at (browsers clamp shorter timeouts to ~4 ms). */
const POLL_MS = 2;
/** How often a frame that is still being drawn is shown as far as it got. */
const PRESENT_EVERY_MS = 250;

/** @type {(message: any, transfer?: Transferable[]) => void} */
const post = (message, transfer = []) => /** @type {any} */ (self).postMessage(message, transfer);

/**
 * @typedef {object} Job a frame or a capture under way
 * @property {number} id
 * @property {'frame' | 'capture'} kind
 * @property {import('./shadertoy-inputs.js').FrameInputs} inputs
 * @property {number} width
 * @property {number} height
 * @property {boolean} readBack
 * @property {any} target the render target drawn into
 * @property {number} step the pass being drawn (an index into renderer.steps; a capture draws
 *   only the last, the Image pass, over the buffers as they are)
 * @property {number} y rows of it done
 * @property {boolean} redo something changed while a band was being drawn: it starts again
 * @property {boolean} [allPasses] a capture that draws every pass (a recorded frame)
 */

/** @type {ShaderRenderer | null} */
let renderer = null;
const planner = new BandPlanner();
/** @type {Job | null} */
let job = null;
/** Jobs waiting for the one under way. @type {Job[]} */
const waiting = [];
/** The band the GPU is drawing. @type {{sync: WebGLSync, rows: number, started: number} | null} */
let band = null;
let lastPresent = 0;
/** WEBGL_lose_context, kept from the loss it caused for the restore. @type {WEBGL_lose_context | null} */
let loseContext = null;

function start() {
  const canvas = new OffscreenCanvas(1, 1);
  try {
    renderer = new ShaderRenderer(canvas);
  } catch (error) {
    post({ type: 'failed', name: error.name, message: error.message });
    return;
  }
  canvas.addEventListener('webglcontextlost', (event) => {
    event.preventDefault(); // tells the browser we want it back (three.js does too)
    band = null;
    for (const lost of [job, ...waiting]) if (lost) post({ type: 'jobFailed', id: lost.id, message: 'the GPU context was lost' });
    job = null;
    waiting.length = 0;
    post({ type: 'context', lost: true });
  });
  canvas.addEventListener('webglcontextrestored', () => {
    // three.js has rebuilt its state; programs and textures are made again from our objects
    renderer.forgetCompiled();
    planner.forget();
    post({ type: 'context', lost: false });
  });
  post({ type: 'ready', maxSize: renderer.maxSize, info: renderer.info() });
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
  if (band || !renderer || renderer.contextLost) return;
  if (!job) {
    job = waiting.shift() ?? null;
    if (!job) return;
    if (job.kind === 'frame' && (job.width !== renderer.width || job.height !== renderer.height)) {
      renderer.setSize(job.width, job.height);
      planner.forget();
    }
  }
  if (!renderer.hasProgram) {
    post({ type: 'jobFailed', id: job.id, message: 'no shader has compiled' });
    job = null;
    return pump();
  }
  const gl = renderer.gl;
  const steps = renderer.steps;
  // a capture draws only the Image pass over the buffers as they are, unless it is a recorded
  // frame of a multipass shader (allPasses); a new shader meanwhile may have fewer passes
  if ((job.kind === 'capture' && !job.allPasses) || job.step >= steps.length) job.step = steps.length - 1;
  const step = steps[job.step];
  const first = job.step === 0 && job.y === 0;
  const last = job.step === steps.length - 1;
  if (first && job.kind === 'frame') {
    renderer.gpuTimer.begin();
    if (job.inputs.keyboard) renderer.setKeyboard(job.inputs.keyboard);
  }
  const rows = planner.rows(job.width, job.height - job.y);
  writeUniforms(renderer.uniforms, job.inputs, { width: job.width, height: job.height });
  const target = renderer.beginStep(step, job.width, job.height) ?? job.target;
  renderer.drawRows(job.y, job.y + rows, target);
  if (last && job.y + rows >= job.height && job.kind === 'frame') renderer.gpuTimer.end();
  const sync = gl.fenceSync(gl.SYNC_GPU_COMMANDS_COMPLETE, 0);
  gl.flush();
  band = { sync, rows, started: performance.now() };
  post({ type: 'bandStarted' });
  setTimeout(poll, POLL_MS);
}

function poll() {
  if (!band || !renderer) return; // the context was lost meanwhile
  const gl = renderer.gl;
  if (gl.getSyncParameter(band.sync, gl.SYNC_STATUS) !== gl.SIGNALED) {
    setTimeout(poll, POLL_MS);
    return;
  }
  gl.deleteSync(band.sync);
  const { rows, started } = band;
  band = null;
  bandDone(rows, performance.now() - started);
  pump();
}

/** @param {number} rows @param {number} ms */
function bandDone(rows, ms) {
  if (!job || !renderer) return;
  planner.measured(job.width, rows, ms);
  if (job.redo) job.redo = false;
  else job.y += rows;
  if (job.y >= job.height && job.step < renderer.steps.length - 1) {
    renderer.endStep(renderer.steps[job.step]); // a buffer is done: the next pass reads it
    job.step++;
    job.y = 0;
  }
  const done = job.y >= job.height;
  const now = performance.now();
  if (!done) {
    const show = job.kind === 'frame' && now - lastPresent > PRESENT_EVERY_MS;
    if (show) lastPresent = now;
    const bitmap = show ? renderer.present() : null;
    post({ type: 'band', id: job.id, y: job.y, height: job.height, bitmap }, bitmap ? [bitmap] : []);
    return;
  }
  const finished = job;
  job = null;
  if (finished.kind === 'frame') {
    lastPresent = now;
    const pixels = finished.readBack ? readOpaque(finished.target, finished.width, finished.height) : null;
    const bitmap = renderer.present();
    post(
      { type: 'drawn', id: finished.id, bitmap, pixels, gpuTimes: renderer.gpuTimer.poll() },
      pixels ? [bitmap, pixels.buffer] : [bitmap],
    );
  } else {
    const pixels = readOpaque(finished.target, finished.width, finished.height);
    finished.target.dispose();
    post({ type: 'captured', id: finished.id, pixels }, [pixels.buffer]);
  }
}

/** A target's pixels as the page shows them: rows top to bottom, alpha 1 (the page's canvas has none). */
function readOpaque(target, width, height) {
  const pixels = flipRows(renderer.readTarget(target), width, height);
  for (let i = 3; i < pixels.length; i += 4) pixels[i] = 255;
  return pixels;
}

const handlers = {
  init: start,

  async compile({ id, project, hostBlock, fileName }) {
    try {
      await renderer.compile(project, hostBlock, fileName);
      changed();
      post({ type: 'compiled', id });
    } catch (error) {
      post({ type: 'compiled', id, error: { name: error.name, message: error.message, report: error.report, messages: error.messages } });
    }
    pump();
  },

  clearBuffers() {
    renderer.buffers.clear();
    changed();
  },

  controlUniforms({ controls, values }) {
    renderer.setControlUniforms(controls, values);
    changed();
  },

  controlUniform({ name, value }) {
    renderer.setControlUniform(name, value);
    changed();
  },

  channel({ index, image }) {
    renderer.setChannel(index, image);
    changed();
  },

  frame({ id, inputs, readBack }) {
    // a frame the page asks for replaces one that has not started yet
    const stale = waiting.findIndex((queued) => queued.kind === 'frame');
    if (stale >= 0) post({ type: 'jobFailed', id: waiting.splice(stale, 1)[0].id, message: 'replaced by a newer frame' });
    const { width, height } = inputs;
    waiting.push({ id, kind: 'frame', inputs, width, height, readBack, target: renderer.frameTarget, step: 0, y: 0, redo: false });
    pump();
  },

  capture({ id, inputs, width, height, allPasses }) {
    waiting.push({
      id,
      kind: 'capture',
      inputs,
      width,
      height,
      readBack: true,
      target: renderer.makeTarget(width, height),
      allPasses,
      step: 0,
      y: 0,
      redo: false,
    });
    pump();
  },

  bench({ id, inputs, n }) {
    const times = [];
    renderer.setSize(inputs.width, inputs.height);
    writeUniforms(renderer.uniforms, inputs);
    for (let i = 0; i < n; i++) {
      const begun = performance.now();
      renderer.render();
      renderer.readTarget(renderer.frameTarget, 0, 0, 1, 1); // waits until the GPU has finished
      times.push(performance.now() - begun);
    }
    post({ type: 'benched', id, times });
  },

  loseContext() {
    loseContext = renderer.gl.getExtension('WEBGL_lose_context');
    loseContext?.loseContext();
  },

  restoreContext() {
    loseContext?.restoreContext(); // the extension is not to be had while the context is lost
  },
};

self.onmessage = ({ data }) => {
  const handler = handlers[data.type];
  if (!handler) throw new Error(`render worker: no message ${data.type}`);
  handler(data);
};
