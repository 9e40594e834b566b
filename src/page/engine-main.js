// The engine page's entry (engine.html): only what draws, for the command line. The app (its
// Shadertoy inputs, passes and render worker), the recorder, the watchdog and window.raytracer,
// and none of the interactive page's widgets (main.js: the editor, the panel, the inspector, kept
// work), whose code the engine page never loads. A view is opened as on the interactive page
// (open-view.js), and what it says, a compile error, the watchdog, what a shader went without,
// is shown as a person would see it (the overlay, the notes) and comes back to the command line
// as data through window.raytracer (notes(), hang(), info()). Its start is main.js's
// (start-page.js).

import builtinSource from '../../shaders/raytrace.glsl?raw';
import { installAutomation } from './automation.js';
import { missingNotesTitle, showLoadNotes } from './ui/notices.js';
import { parseUrlParams } from '../shared/url-params.js';
import { missingLines } from './io/project-files.js';
import { Recorder } from './io/recorder.js';
import { openView, useBuiltinSource } from './open-view.js';
import { startPage } from './start-page.js';

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
  const started = await startPage();
  if (!started) return;
  const { app, params, noticeAfterCompile } = started;
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
