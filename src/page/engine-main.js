// The engine page's entry (engine.html): only what draws, for the command line. The app (its
// Shadertoy inputs, passes and render worker), the recorder, the watchdog and window.raytracer,
// and none of the interactive page's widgets (main.js: the editor, the panel, the inspector, kept
// work), whose code the engine page never loads. A view is opened as on the interactive page
// (open-view.js), and what it says, a compile error, the watchdog, what a shader went without,
// goes where the command line reads it: the overlay, page-marks.js's attributes, the notes.

import builtinSource from '../../shaders/raytrace.glsl?raw';
import { RaytracerApp } from './app/app.js';
import { installAutomation, installFailedAutomation } from './automation.js';
import { Overlay } from './ui/overlay.js';
import { missingNotesTitle, showAppOnPage, showLoadNotes, showStartupFailure } from './ui/notices.js';
import { parseUrlParams } from '../shared/url-params.js';
import { fetchMedia, loadChannel, shaderName } from './io/shader-loader.js';
import { HangGuard, watchHangs } from './io/hang-guard.js';
import { missingLines } from './io/project-files.js';
import { Recorder } from './io/recorder.js';
import { BUILTIN_NAME, openView, useBuiltinSource } from './open-view.js';

useBuiltinSource(builtinSource);

/** The widgets a view touches, as the engine page has them: none. @type {import('./open-view.js').PageUi} */
const NO_WIDGETS = {
  toast: (text) => console.warn(text),
  kept: { open: () => null },
  inspection: { reset() {} },
  panel: { setView() {} },
};

async function start() {
  const stage = /** @type {HTMLElement} */ (document.getElementById('stage'));
  const canvas = /** @type {HTMLCanvasElement} */ (document.getElementById('view'));
  const overlay = new Overlay(/** @type {HTMLElement} */ (document.getElementById('overlay')));
  const params = parseUrlParams(location.search, location.href);
  let app;
  try {
    app = await RaytracerApp.start({
      canvas,
      loadChannel,
      fetchMedia,
      fileName: params.shader ? shaderName(params.shader) : BUILTIN_NAME,
      size: params.size ?? null,
      scale: params.scale ?? 1,
      cap: params.cap ?? 0,
      playing: params.time === undefined,
    });
  } catch (error) {
    showStartupFailure(overlay, error);
    installFailedAutomation(error);
    return;
  }
  watchHangs(app, new HangGuard());
  const noticeAfterCompile = showAppOnPage(app, overlay);
  const showNotes = () => showLoadNotes(stage, missingNotesTitle(app.fileName), missingLines(app));
  app.on('source', showNotes);
  app.on('notes', showNotes);
  const open = (/** @type {string} */ query) => {
    const url = new URL(query, location.href);
    return openView(app, NO_WIDGETS, parseUrlParams(url.search, url.href), { hash: url.hash, noticeAfterCompile, again: true });
  };
  installAutomation(app, app.ready, { open, recorder: new Recorder(app) });
  openView(app, NO_WIDGETS, params, { hash: location.hash, noticeAfterCompile }).catch(() => {}); // `ready` rejects
}

start();
