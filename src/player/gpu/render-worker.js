// The render worker: the page's GPU work, off the page's main thread. It owns an OffscreenCanvas
// of its own (not one transferred from the page: a transferred canvas ties the page's main
// thread to the GPU, and one endless draw then freezes the whole page), draws frames there in
// bands (bands/band-scheduler.js), polls a fence after each band instead of waiting for the GPU, and
// hands each finished frame to the page as an ImageBitmap, which the page's canvas shows.
// Nothing the page's script does waits for the GPU, but painting those bitmaps does, so a draw
// that may never end waits until the page has painted them (bands/paint-gate.js). The page
// (app/render-client.js) sees the bands come in and knows when they stop coming. What it is
// asked and what it answers is protocol.js's; this module makes the renderer, follows its
// context, and turns each request into the scheduler's job or the renderer's call.

import { ShaderRenderer } from './renderer.js';
import { setControlUniform, setControlUniforms, writeUniforms } from './uniforms.js';
import { serve } from './protocol.js';
import { BandScheduler } from './bands/band-scheduler.js';

/** The renderer, once start() has made it. @type {ShaderRenderer | null} */
let made = null;
/** WEBGL_lose_context, kept from the loss it caused for the restore. @type {WEBGL_lose_context | null} */
let loseContext = null;
/** The frames, captures and probes asked for, drawn band by band. */
const bands = new BandScheduler(
  () => made,
  (type, params) => tell(type, params),
);

/**
 * The renderer. Only start() can fail to make it, and then the page is told 'failed' and asks
 * this worker nothing more.
 */
function renderer() {
  if (!made) throw new Error('the renderer was not made');
  return made;
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
    bands.contextLost(); // its jobs fail; the last frame's target is gone with the context
    tell('context', { lost: true });
  });
  canvas.addEventListener('webglcontextrestored', () => {
    // three.js has rebuilt its state; programs and textures are made again from our objects
    renderer().forgetCompiled();
    renderer().loopCuts.forget();
    bands.contextRestored();
    tell('context', { lost: false });
  });
  tell('ready', { maxSize: renderer().maxSize, info: renderer().info() });
}

/** The worker's scope as serve() sees it, counting the bitmaps that go to the page. */
const counted = {
  /** @param {any} message @param {Transferable[]} transfer */
  postMessage(message, transfer) {
    bands.paints.sending(transfer);
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
        renderer().loopCuts.unchecked.clear(); // the passes of this shader say again
        const sound = await renderer().sound.compile(project); // the Sound tab, if any (sound-pass.js)
        await renderer().compile(project, hostBlock, fileName, serial);
        if (renderer().installed === serial) renderer().sound.install(sound);
        bands.changed();
        return null;
      } finally {
        bands.pump();
      }
    },

    frame: (params) => bands.frame(params),

    readFrame: () => bands.readFrame(),

    capture({ inputs, width, height, allPasses, program }) {
      if (program && !renderer().probe.step) throw new Error('the path probe has not compiled');
      const target = renderer().makeTarget(width, height);
      return bands.enqueue({ kind: 'capture', inputs, width, height, readBack: true, target, allPasses, program });
    },

    async captureTile({ inputs, x, y, width, height, fullWidth, fullHeight }) {
      const step = await renderer().tiled();
      if (renderer().tiledStep !== step) throw new Error('another shader was loaded meanwhile');
      const target = renderer().makeTarget(width, height);
      return bands.enqueue({ kind: 'capture', inputs, width, height, readBack: true, target, tile: { x, y, fullWidth, fullHeight } });
    },

    captureFloat({ inputs, width, height }) {
      const target = renderer().makeTarget(width, height, true);
      return bands.enqueue({ kind: 'capture', inputs, width, height, readBack: true, target, float: true });
    },

    async compileProbe({ project, hostBlock, fileName, key, texels }) {
      // the reply comes once the probe has compiled and drawn once (its first draw compiles it)
      await bands.warmProbe(() => renderer().probe.compile(project, hostBlock, fileName, key, texels));
      return null;
    },

    probe: ({ x, y }) => bands.probe({ x, y }),

    sound({ first, count, date }) {
      return renderer().sound.render(first, count, date);
    },

    loopCuts: ({ reset }) => renderer().loopCuts.report(reset),

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
      bands.changed();
    },

    controlUniforms({ controls, values }) {
      setControlUniforms(renderer().uniforms, controls, values);
      bands.changed();
    },

    controlUniform({ name, value }) {
      setControlUniform(renderer().uniforms, name, value);
      bands.changed();
    },

    channel({ index, image }) {
      renderer().inputs.setChannel(index, image);
      bands.changed();
    },

    passMedia(media) {
      renderer().passMedia.set(media);
      bands.changed();
    },

    loopGuard({ stopOnCut, guard }) {
      if (!made) return; // no WebGL2 (init said 'failed'): nothing is drawn, nor guarded
      const cuts = made.loopCuts;
      cuts.stopOnCut = stopOnCut;
      cuts.enabled = guard && cuts.onLlvmpipe;
    },

    settled({ bitmaps: count }) {
      bands.paints.settle(count);
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
