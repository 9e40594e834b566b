// What the engine page says of itself, as data (window.shaderEngine's notes(), hang() and info():
// engine-hook.js): the same facts the interactive page shows as notes and messages (ui/notices.js),
// in the same words (words.js), kept from the app's events.
//
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

import { missingLines } from '../io/project-files.js';
import { VALUE_NOTES_TITLE, missingNotesTitle, watchdogDetail, watchdogTitle } from '../words.js';

/** @typedef {import('../app/app.js').ShaderApp} ShaderApp */
/** A note beside the picture, as data. @typedef {{kind: 'missing' | 'values', title: string, lines: string[]}} HookNote */

export class EngineState {
  #app;
  /** The last view's values not used as given (open-view.js). @type {string[]} */
  #valueLines = [];
  /** The watchdog's last word: null while drawing goes on. @type {{seconds: number, phase: string} | null} */
  #watchdog = null;
  /** 'shader-compile' while no shader could run (page-marks.js says the same as data-error). @type {string | null} */
  #compileError = null;

  /** @param {ShaderApp} app */
  constructor(app) {
    this.#app = app;
    app.on('values', (_, lines) => (this.#valueLines = lines));
    app.on('hang', (_, seconds, phase = 'drawing') => (this.#watchdog = seconds === null ? null : { seconds, phase }));
    app.on('compile', (_, error) => {
      if (!error) this.#compileError = null;
      else if (!app.compiles.hasProgram) this.#compileError = 'shader-compile';
    });
  }

  /** @returns {HookNote[]} */
  notes() {
    // each line as the app has it ("PASS, iChannelN: WHAT"): the page's note says each once
    // (sayOnce, src/shared/said-once.js), and so does the command line, in the same words
    const app = this.#app;
    const missing = missingLines(app);
    const values = this.#valueLines;
    return [
      ...(missing.length ? [{ kind: /** @type {const} */ ('missing'), title: missingNotesTitle(app.fileName), lines: missing }] : []),
      ...(values.length ? [{ kind: /** @type {const} */ ('values'), title: VALUE_NOTES_TITLE, lines: [...values] }] : []),
    ];
  }

  /** @returns {{phase: string, seconds: number, message: string} | null} */
  hang() {
    if (!this.#watchdog) return null;
    const { seconds, phase } = this.#watchdog;
    const name = this.#app.fileName;
    const back = this.#app.frames.lastFinished?.name ?? null;
    const detail = watchdogDetail(name, Math.floor(seconds), phase, back);
    return { phase, seconds, message: `${watchdogTitle(name, phase)}: ${detail.replace(/\s+/g, ' ')}` };
  }

  info() {
    const app = this.#app;
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
      /** @type {string | null} */
      error: this.#compileError,
    };
  }
}
