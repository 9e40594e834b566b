// What the engine page shows a person who opens it (engine.html): one line of plain text over the
// canvas while something stands in the way of its picture (the page could not start, the shader
// did not compile, the watchdog's message), in the words the hook gives the command line. The
// interactive page's overlay and notes (ui/) are not loaded here: the command line reads the
// same facts as data (hook/engine-state.js), and the line is kept as data too (page-marks.js
// window.pageMarks), which describePage (src/headless/client.js) reads of a page that stopped answering.

import { pageMarks } from './page-marks.js';

/** The page's status line (engine.html's #overlay, role="alert"). */
const line = () => /** @type {HTMLElement} */ (document.getElementById('overlay'));

/** @param {string | null} text shown, or hidden when null */
export function showStatus(text) {
  const status = line();
  status.hidden = text === null;
  status.textContent = text ?? '';
  pageMarks().status = text;
}

/**
 * Keeps the status line in step with the app: a compile error while no shader runs, the
 * watchdog's message while a band goes unfinished.
 * @param {import('./app/app.js').ShaderApp} app
 * @param {import('./hook/engine-hook.js').EngineHook} hook
 */
export function followStatus(app, hook) {
  app.on('compile', (_, error, fileName) =>
    showStatus(error ? `${fileName} did not compile: ${String(error.report ?? error.message).split('\n')[0]}` : null),
  );
  app.on('hang', () => showStatus(hook.hang()?.message ?? null));
}
