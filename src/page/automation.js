// window.raytracer: the page's API, which the command line, the test harness and the benchmark
// drive (on the engine page, engine-main.js, or the interactive page, main.js). Documented here
// once; its type is the hook itself (RaytracerHook below), which tests/globals.ts and the
// engine's waits (src/engine/watch.js) take from here.
//
//   ready                 Promise: resolves after the first frame has been drawn; rejects with
//                         the error when WebGL2 is missing or the first compile fails.
//   open(query)           Promise: the page as a fresh load of `query` ("?shader=…&size=…&time=…
//                         &NAME=value", and a "#source=…" fragment) would give it, without a
//                         reload (open-view.js): its shader, controls, size, clock, mouse,
//                         channels, kept edits and notes; the inspector off. Resolves once its
//                         first frame is drawn; rejects with the compile error, or with why
//                         its shader could not be loaded (never the built-in in its place).
//   readPixels()          Promise<{width, height, data}>: draws one frame and reads it back (the
//                         render worker keeps each frame in a render target). `data` is base64
//                         of RGBA8 pixels, rows top to bottom, alpha 255 (as the canvas shows).
//   readFrame()           Promise<{width, height, iFrame, data}>: the last frame drawn, read back
//                         as it was drawn; draws nothing (a view's still is its frame 0, as
//                         open() drew it). `data` as readPixels's.
//   renderFrames(n)       Promise<{median, times}>: the render worker draws n whole frames back
//                         to back, each a single draw followed by a 1-pixel readPixels so the
//                         GPU has finished; `times` are the n per-frame times in ms, `median`
//                         their median.
//   setControls({NAME: value})   Promise: sets shader controls (as the URL does: coerced into
//                         range, unknown names warned about); resolves once compiled.
//   setSource(glsl)       Promise<{ok, error?}>: compiles another Image-tab source.
//   setProject(json)      Promise<{ok, error?, notes}>: runs a multipass shader given as
//                         Shadertoy's JSON export (an object or its text).
//   setConverging(on, {frames}?)  Promise: "Converge when still" on or off (app.setConverging):
//                         frames: how many still frames to draw (default 4096).
//   play(), pause(), togglePlay(), restart(), setTime(seconds), setSpeed(s), setMouse([x, y, z, w]),
//   resetView()          iMouse back to how the page opened (the toolbar's "Reset view")
//   nextFrame()           Promise<{width, height, data, iFrame}>: the next frame the page draws by
//                         itself (after a click, a key, a play tick), read back; rows top to
//                         bottom. Asks for no frame.
//   loseContext(), restoreContext()   the render worker's context lost or restored through
//                         WEBGL_lose_context (the tests of a lost context).
//   capture({width, height}?)  Promise<{width, height, data}>: the last frame drawn again off
//                         screen at that size (default: the canvas's), as the Screenshot button
//                         saves it.
//   captureTile({x, y, width, height, fullWidth, fullHeight})  Promise<{width, height, data}>:
//                         the tile at (x, y) (from the bottom left) of the last frame drawn at
//                         fullWidth × fullHeight, for a picture larger than one draw (the
//                         command line's --tile); x and y even keep the quads of the whole
//                         picture. A shader with buffers rejects.
//   captureFloat()        Promise<{width, height, data}>: the last frame's Image pass drawn again
//                         in RGBA32F, its colours as the shader wrote them (unclamped, NaN and
//                         infinity kept), rows top to bottom; `data` is base64 of the floats'
//                         bytes (little-endian), as the inspector reads a pixel.
//   setChannel(i, url|null)    Promise: an image into iChannel i (null: black again).
//   loadShader(url)       Promise<{ok, error?}>: fetches and runs a shader as ?shader= does
//                         (GLSL, or Shadertoy's JSON export).
//   shareUrl()            Promise<string>: the link "Copy link" copies (reproduces this view).
//   editorSource()        the text of the editor's current tab (what it holds, compiled or not).
//   record({format, frames | duration, fps, width, height})  Promise<{format, frames, fps,
//                         width, height, codec, mimeType, data}>: records the shader frame by
//                         frame as the Record button does (recorder.js: 'webm' or 'png', a .zip
//                         of PNGs); `data` is the file as base64. Rejects with RecordingCancelled
//                         after cancelRecording().
//   frameAt({frame, fps, width, height})  Promise<{width, height, data}>: frame `frame` as
//                         record() would draw it (iTime = frame / fps, iFrame = frame), and no
//                         file: a shader with buffers has every frame before it drawn first
//                         (recorder.js frameAt); no cap on `frame`. `data` is base64 RGBA8, rows
//                         top to bottom. Its progress is recording()'s.
//   renderSound({time, duration})  Promise<{sampleRate, channels, samples, data}>: the Sound
//                         tab's samples from `time` (default 0) for `duration` seconds (default
//                         60, as the site's WAV export), drawn as the site draws them
//                         (sound/sound-pass.js); `data` is base64 of interleaved little-endian
//                         Int16 (left, right). Rejects for a shader without a Sound tab.
//   soundState()          {available (a Sound tab), context (the AudioContext's state, null
//                         before the first click or key), muted, plan ({sample, when, rate,
//                         time}: sample `sample` plays at audio-clock time `when`, planned at
//                         iTime `time`: sound/schedule.js; null when silent), now (the audio
//                         clock), sources (blocks playing or scheduled), level (RMS)}
//   setMuted(on)          the Sound tab's mute button
//   cancelRecording()     stops the recording under way (this one or the Record button's).
//   recording()           {busy, done, total}: whether a recording is under way, and how many
//                         frames of the last record() or frameAt() are done, of how many.
//   inspect(x, y)         Promise<Readout>: Inspect on, pixel (x, y) pinned (y from the bottom:
//                         fragCoord - 0.5) and read: its float colour, the canvas's byte, each
//                         buffer, and for the raytracer its ray path and the float64 reference's
//                         colour and path (inspect/inspector.js: Readout); resolves once all of
//                         it is in (a path probe that compiles first included).
//   inspection()          {active, pinned, problem, readout}: the inspector as it is now.
//   unpin()               unpins the pixel (Esc).
//   compareWithFloat64()  Promise<{width, height, figures: {float, canvas}, extraSampleShare,
//                         frame, ms, caveat}>: "Compare with float64" on the frame on the canvas
//                         (inspect/compare.js; figures as src/reference/error.js gives them);
//                         rejects with why it cannot.
//   comparison()          {running, error, stale, shown}: the comparison's state on the page.
//   notes()               [{kind, title, lines}]: the notes beside the picture, as data: what the
//                         shader goes without (kind 'missing': "PASS, iChannelN: WHAT", a line
//                         for each place, as the app has them) and the values of the last view not used as given
//                         ('values'); a note with no lines is left out.
//   hang()                null, or {phase, seconds, message}: the watchdog's message while a
//                         band has gone unfinished ('compiling': a program's first draw;
//                         'drawing': it may never finish), in the words the page shows.
//   info()                {renderer (UNMASKED_RENDERER_WEBGL), vendor, version, shadingLanguage,
//                         width, height, frame (frames drawn since the page started),
//                         iFrame (the next frame's), time, playing, speed, mouse (iMouse),
//                         controls: {NAME: value}, fileName, shaderUrl, origin, contextLost,
//                         compiled (successful compiles so far), liveControls ('constants' while
//                         the shader on screen has the live controls compiled in, 'uniforms'
//                         while they move: see live-controls.js), hung (the watchdog's verdict:
//                         a band has gone TIMEOUTS.hangMs unfinished: timeouts.js), watchdog
//                         (null, 'compiling': a program's first draw is taking long, or
//                         'drawing': hung), progress ({y,
//                         height, bands}: how far the frame being drawn has got; null if none),
//                         band ({seconds, compiling}: the band the GPU is on; null if none),
//                         converging, stillFrames (frames since the last change), error
//                         ('shader-compile' while no shader could run, else null)}
//
// The page's state is also on the page as attributes the tests wait on (page-marks.js:
// data-error, data-context, data-hung on <html>, data-frame on the canvas).
//
// Every method waits for `ready` and for any compile under way, so a call right after
// setControls() sees the new values.

import { toBase64 } from '../shared/pixels.js';
import { median } from '../shared/stats.js';
import { openShader, openShaderUrl } from './io/open-shader.js';
import { singlePass } from '../shadertoy/multipass.js';
import { SAMPLE_RATE, toPcm16 } from '../shadertoy/sound.js';
import { hasSound, sampleRange, soundSamples } from './sound/samples.js';
import { markApp, markStartupFailure } from './page-marks.js';
import { missingLines } from './io/project-files.js';
import { VALUE_NOTES_TITLE, missingNotesTitle, watchdogDetail, watchdogTitle } from './ui/notices.js';

/** The window, with the hook. @type {Window & {raytracer?: object}} */
const hooked = window;

/**
 * What an entry page gives the hook: open() (open-view.js), the recorder it owns, and on the
 * interactive page (main.js) its widgets; the engine page (engine-main.js) has none, and the
 * methods that need them (the inspector, the comparison, the link, the editor) reject there.
 * @typedef {object} HookHost
 * @property {(query: string) => Promise<void>} open
 * @property {import('./io/recorder.js').Recorder} recorder
 * @property {ReturnType<typeof import('./ui/ui.js').installUi>} [ui]
 */

/**
 * @param {import('./app/app.js').RaytracerApp} app (a page that could not start has installFailedAutomation)
 * @param {Promise<void>} ready
 * @param {HookHost} host
 */
export function installAutomation(app, ready, { open, recorder, ui: pageUi }) {
  markApp(app);
  /** The page's widgets, for the methods that need them; the engine page has none. */
  const widgets = () => {
    if (!pageUi) throw new Error('not on the engine page (engine.html), which only draws: open the full page (index.html)');
    return pageUi;
  };
  // the first source may still be on its way (?shader= is fetched): calls wait for it
  const loaded = () => (app.loading ?? Promise.resolve()).catch(() => {});
  // A first compile that failed rejects `ready` for good; once another shader has compiled,
  // that old error no longer stands in the way.
  const settled = async () => {
    await loaded();
    await app.compiles.settled();
    if (!app.compiles.hasProgram) await ready;
  };

  /** One open() at a time; the one before is waited for. @type {Promise<unknown>} */
  let opening = Promise.resolve();
  /** The last record()'s progress: frames done of total. */
  let recorded = { done: 0, total: 0 };
  /** The last view's values not used as given (open-view.js). @type {string[]} */
  let valueLines = [];
  app.on('values', (_, lines) => (valueLines = lines));
  /** The watchdog's last word: null while drawing goes on. @type {{seconds: number, phase: string} | null} */
  let watchdog = null;
  app.on('hang', (_, seconds, phase = 'drawing') => (watchdog = seconds === null ? null : { seconds, phase }));
  /** 'shader-compile' while no shader could run (page-marks.js says the same as data-error). @type {string | null} */
  let compileError = null;
  app.on('compile', (_, error) => {
    if (!error) compileError = null;
    else if (!app.compiles.hasProgram) compileError = 'shader-compile';
  });

  const hook = {
    ready,

    async open(query) {
      const previous = opening;
      const next = (async () => {
        await previous.catch(() => {});
        await loaded();
        await app.compiles.settled();
        await open(query);
      })();
      opening = next;
      return next;
    },

    async readPixels() {
      await settled();
      const drawn = await app.frames.draw(performance.now(), true);
      if (!drawn?.pixels) throw new Error(app.gpu.contextLost ? 'the GPU context is lost' : 'no shader is running');
      return { width: drawn.width, height: drawn.height, data: toBase64(drawn.pixels) };
    },

    async readFrame() {
      await settled();
      const drawn = await app.frames.readLast();
      return { width: drawn.width, height: drawn.height, iFrame: drawn.frame, data: toBase64(drawn.data) };
    },

    async renderFrames(n = 1) {
      await settled();
      await app.frames.draw(); // sizes the worker's frame, as the page draws it
      const inputs = app.frames.last;
      if (!inputs) throw new Error(app.gpu.contextLost ? 'the GPU context is lost' : 'no shader is running');
      const times = await app.gpu.ask('bench', { inputs, n });
      return { median: median(times), times };
    },

    async setControls(changes) {
      await loaded(); // the shader's controls are known; its first frame need not be drawn yet
      await app.setControls(changes);
    },

    async setSource(source) {
      await loaded();
      try {
        await app.setProject(singlePass(source), { origin: 'editor' });
        return { ok: true };
      } catch (error) {
        return { ok: false, error: error.report ?? error.message };
      }
    },

    async setProject(json) {
      await loaded();
      try {
        const text = typeof json === 'string' ? json : JSON.stringify(json);
        const opened = openShader(app, text, { name: app.fileName, origin: 'editor', json: true });
        await opened.running;
        return { ok: true, notes: [...opened.notes, ...app.notes] };
      } catch (error) {
        return { ok: false, error: error.report ?? error.message, notes: [] };
      }
    },

    async setConverging(on, options = {}) {
      await settled();
      await app.converge.set(Boolean(on), options);
    },

    play: () => app.play(),
    pause: () => app.pause(),
    togglePlay: () => app.togglePlay(),
    restart: () => app.restart(),
    setTime: (seconds) => app.setTime(seconds),
    setSpeed: (speed) => app.setSpeed(speed),
    setMouse: (mouse) => app.setMouse(mouse),
    resetView: () => app.resetView(),

    // read in the same task as the frame was drawn (no preserveDrawingBuffer)
    async nextFrame() {
      app.frames.readBackNextFrame();
      const drawn = await new Promise((resolve) => {
        const wait = (_, frame) => (frame.pixels ? resolve(frame) : app.once('drawn', wait));
        app.once('drawn', wait);
      });
      return { width: drawn.width, height: drawn.height, iFrame: drawn.frame, data: toBase64(drawn.pixels) };
    },

    loseContext: () => app.gpu.tell('loseContext', {}),
    restoreContext: () => app.gpu.tell('restoreContext', {}),

    async capture(size = null) {
      await settled();
      const { width, height, data } = await app.frames.capture(size);
      return { width, height, data: toBase64(data) };
    },

    async captureTile({ x, y, width, height, fullWidth, fullHeight }) {
      await settled();
      const inputs = app.frames.last;
      if (!inputs) throw new Error(app.gpu.contextLost ? 'the GPU context is lost' : 'no shader is running');
      const data = await app.gpu.ask('captureTile', { inputs, x, y, width, height, fullWidth, fullHeight });
      return { width, height, data: toBase64(data) };
    },

    async captureFloat() {
      await settled();
      const inputs = app.frames.last;
      if (!inputs) throw new Error(app.gpu.contextLost ? 'the GPU context is lost' : 'no shader is running');
      const { width, height } = inputs;
      const floats = await app.gpu.ask('captureFloat', { inputs, width, height });
      return { width, height, data: toBase64(new Uint8Array(floats.buffer, floats.byteOffset, floats.byteLength)) };
    },

    async setChannel(index, url) {
      await app.setChannel(index, url);
    },

    async loadShader(url) {
      await loaded();
      try {
        await openShaderUrl(app, url);
        return { ok: true };
      } catch (error) {
        return { ok: false, error: error.report ?? error.message };
      }
    },

    async inspect(x, y) {
      await settled();
      const ui = widgets();
      const { inspector } = ui.inspection;
      ui.inspection.pin(x, y);
      return structuredClone(await inspector.complete());
    },
    inspection() {
      const { inspector } = widgets().inspection;
      return structuredClone({
        active: inspector.active,
        pinned: inspector.pinned,
        problem: inspector.problem,
        readout: inspector.readout,
      });
    },
    unpin: () => widgets().inspection.inspector.unpin(),
    async compareWithFloat64() {
      await settled();
      const { figures, width, height, extraSampleShare, frame, ms, caveat } = await widgets().inspection.comparison.run();
      return { figures, width, height, extraSampleShare, frame, ms, caveat };
    },
    comparison() {
      const { running, error, stale, result } = widgets().inspection.comparison;
      return structuredClone({ running, error, stale, shown: result ? { width: result.width, height: result.height } : null });
    },

    shareUrl: () => widgets().shareUrl(),
    editorSource: () => widgets().editor.text,

    async record(request = {}) {
      await settled();
      recorded = { done: 0, total: 0 };
      const { bytes, ...result } = await recorder.record(request, (done, total) => (recorded = { done, total }));
      return { ...result, data: toBase64(bytes) };
    },
    /** @param {{frame: number, fps?: number, width?: number, height?: number}} request */
    async frameAt(request) {
      await settled();
      recorded = { done: 0, total: 0 };
      const { data, ...size } = await recorder.frameAt(request, (done, total) => (recorded = { done, total }));
      return { ...size, data: toBase64(data) };
    },
    /** @param {{time?: number, duration?: number}} [request] */
    async renderSound({ time = 0, duration = 60 } = {}) {
      await settled();
      if (!hasSound(app)) throw new Error('this shader has no Sound tab');
      const { first, count } = sampleRange(time, duration);
      const pcm = toPcm16(await soundSamples(app, first, count));
      return { sampleRate: SAMPLE_RATE, channels: 2, samples: count, data: toBase64(new Uint8Array(pcm.buffer)) };
    },
    soundState() {
      const player = widgets().sound;
      const context = player.context;
      return structuredClone({
        available: player.available,
        context: context?.state ?? null,
        muted: player.muted,
        plan: player.plan,
        now: context?.currentTime ?? null,
        sources: player.sourceCount,
        level: player.level(),
      });
    },
    /** @param {boolean} muted */
    setMuted: (muted) => widgets().sound.setMuted(Boolean(muted)),
    cancelRecording: () => recorder.cancel(),
    recording: () => ({ busy: recorder.busy, ...recorded }),

    notes() {
      // each line as the app has it ("PASS, iChannelN: WHAT"): the page's note says each once
      // (sayOnce, src/shared/said-once.js), and so does the command line, in the same words
      const missing = missingLines(app);
      return [
        ...(missing.length ? [{ kind: /** @type {const} */ ('missing'), title: missingNotesTitle(app.fileName), lines: missing }] : []),
        ...(valueLines.length ? [{ kind: /** @type {const} */ ('values'), title: VALUE_NOTES_TITLE, lines: [...valueLines] }] : []),
      ];
    },
    hang() {
      if (!watchdog) return null;
      const { seconds, phase } = watchdog;
      const back = app.frames.lastFinished?.name ?? null;
      const detail = watchdogDetail(app.fileName, Math.floor(seconds), phase, back);
      return { phase, seconds, message: `${watchdogTitle(app.fileName, phase)}: ${detail.replace(/\s+/g, ' ')}` };
    },

    info() {
      return {
        ...app.gpu.info(),
        ...app.frames.size,
        frame: app.frames.count,
        iFrame: app.inputs.frame,
        time: app.inputs.time,
        playing: app.inputs.playing,
        speed: app.inputs.speed,
        mouse: app.inputs.mouse(),
        controls: structuredClone(app.values),
        fileName: app.fileName,
        shaderUrl: app.shaderUrl,
        origin: app.origin,
        contextLost: app.gpu.contextLost,
        compiled: app.compiles.count,
        liveControls: app.liveForm.asConstants ? 'constants' : 'uniforms',
        hung: app.gpu.hung === 'drawing',
        watchdog: app.gpu.hung,
        progress: app.frames.progress,
        band: app.gpu.band,
        converging: app.converge.on,
        stillFrames: app.frames.stillFrames,
        error: compileError,
      };
    },
  };
  hooked.raytracer = hook;
  return hook;
}

/**
 * window.raytracer's type, from the hook itself: the tests, the benchmark and the engine's waits
 * read it (tests/globals.ts).
 * @typedef {ReturnType<typeof installAutomation>} RaytracerHook
 */

/** The hook for a page that could not start: `ready` rejects with `error`, and so does the rest. */
export function installFailedAutomation(error) {
  markStartupFailure(error);
  const failed = Promise.reject(error);
  failed.catch(() => {}); // reported on the page
  const fail = async () => failed;
  hooked.raytracer = {
    ready: failed,
    open: fail,
    readPixels: fail,
    readFrame: fail,
    renderFrames: fail,
    setControls: fail,
    setSource: fail,
    setProject: fail,
    setConverging: fail,
    nextFrame: fail,
    loseContext() {},
    restoreContext() {},
    capture: fail,
    captureFloat: fail,
    captureTile: fail,
    setChannel: fail,
    loadShader: fail,
    shareUrl: () => location.href,
    editorSource: () => '',
    inspect: fail,
    inspection: () => null,
    unpin() {},
    compareWithFloat64: fail,
    comparison: () => null,
    record: fail,
    frameAt: fail,
    cancelRecording() {},
    recording: () => ({ busy: false, done: 0, total: 0 }),
    notes: () => [],
    hang: () => null,
    play() {},
    pause() {},
    togglePlay() {},
    restart() {},
    setTime() {},
    setSpeed() {},
    setMouse() {},
    resetView() {},
    info: () => ({ error: error.message }),
  };
}
