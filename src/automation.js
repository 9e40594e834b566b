// window.raytracer: the page's hook for the test harness and the benchmark.
//
//   ready                 Promise: resolves after the first frame has been drawn; rejects with
//                         the error when WebGL2 is missing or the first compile fails.
//   readPixels()          Promise<{width, height, data}>: draws one frame and reads it back in
//                         the same task (no preserveDrawingBuffer needed). `data` is base64 of
//                         RGBA8 pixels, rows top to bottom.
//   renderFrames(n)       Promise<{median, times}>: draws n frames back to back, each followed by
//                         a 1-pixel gl.readPixels so the GPU has finished; `times` are the n
//                         per-frame times in ms, `median` their median.
//   setControls({NAME: value})   Promise: sets shader controls (as the URL does: coerced into
//                         range, unknown names warned about); resolves once compiled.
//   setSource(glsl)       Promise<{ok, error?}>: compiles another Image-tab source.
//   play(), pause(), setTime(seconds), setMouse([x, y, z, w])
//   info()                {renderer (UNMASKED_RENDERER_WEBGL), vendor, version, shadingLanguage,
//                         width, height, frame, time, playing, mouse (iMouse),
//                         controls: {NAME: value}}
//
// Every method waits for `ready` and for any compile under way, so a call right after
// setControls() sees the new values.

function toBase64(bytes) {
  let binary = '';
  for (let i = 0; i < bytes.length; i += 0x8000) binary += String.fromCharCode.apply(null, bytes.subarray(i, i + 0x8000));
  return btoa(binary);
}

/** GL rows run bottom to top; images run top to bottom. */
function flipRows(pixels, width, height) {
  const row = width * 4;
  const out = new Uint8Array(pixels.length);
  for (let y = 0; y < height; y++) out.set(pixels.subarray((height - 1 - y) * row, (height - y) * row), y * row);
  return out;
}

function median(values) {
  const sorted = [...values].sort((a, b) => a - b);
  const mid = sorted.length >> 1;
  return sorted.length % 2 ? sorted[mid] : (sorted[mid - 1] + sorted[mid]) / 2;
}

/**
 * @param {import('./app.js').RaytracerApp | null} app null when the page could not start
 * @param {Promise<void>} ready
 */
export function installAutomation(app, ready) {
  const settled = async () => {
    await ready;
    await app.whenCompiled();
  };

  window.raytracer = {
    ready,

    async readPixels() {
      await settled();
      app.renderNow();
      const { width, height } = app.renderer;
      const pixels = app.renderer.readPixels();
      return { width, height, data: toBase64(flipRows(pixels, width, height)) };
    },

    async renderFrames(n = 1) {
      await settled();
      const times = [];
      for (let i = 0; i < n; i++) {
        const start = performance.now();
        app.renderNow();
        app.renderer.readPixels(0, 0, 1, 1);
        times.push(performance.now() - start);
      }
      return { median: median(times), times };
    },

    async setControls(changes) {
      await ready.catch(() => {});
      await app.setControls(changes);
    },

    async setSource(source) {
      app.loadSource(source);
      try {
        await app.compile();
        return { ok: true };
      } catch (error) {
        return { ok: false, error: error.report ?? error.message };
      }
    },

    play: () => app.play(),
    pause: () => app.pause(),
    setTime(seconds) {
      app.inputs.setTime(Number(seconds));
      app.requestRender();
    },
    setMouse(mouse) {
      app.inputs.setMouse(mouse);
      app.requestRender();
    },

    info() {
      return {
        ...app.renderer.info(),
        width: app.renderer.width,
        height: app.renderer.height,
        frame: app.framesRendered,
        time: app.inputs.time,
        playing: app.inputs.playing,
        mouse: app.inputs.mouse(),
        controls: structuredClone(app.values),
      };
    },
  };
}

/** The hook for a page that could not start: `ready` rejects with `error`, and so does the rest. */
export function installFailedAutomation(error) {
  const failed = Promise.reject(error);
  failed.catch(() => {}); // reported on the page
  const fail = async () => failed;
  window.raytracer = {
    ready: failed,
    readPixels: fail,
    renderFrames: fail,
    setControls: fail,
    setSource: fail,
    play() {},
    pause() {},
    setTime() {},
    setMouse() {},
    info: () => ({ error: error.message }),
  };
}
