// The page's state as attributes, for the tests, the harness and the command line (src/headless/)
// to wait on, part of the hook's contract (hook/engine-hook.js installs them): on <html>,
// data-error="shader-compile" while no shader could run ("webgl2" or "startup" when the page
// could not start), data-context="lost" while the GPU context is gone, data-hung="true" while a
// frame may never finish and "compiling" while a program's first draw is taking long (the
// watchdog: render-client.js); on the canvas, data-frame, the number of frames drawn. What a
// person reads about the same things is ui/notices.js's.
//
// The same facts, and the line the engine page shows, are kept as data too (window.pageMarks):
// the command line asks a page that stopped answering what it was doing (src/headless/client.js
// describePage), before its hook may be there, and reads no attribute or element of the page.

/** @typedef {import('./app/app.js').ShaderApp} ShaderApp */

/**
 * The page's marks as data: frames drawn, the start-up or compile error, the context and the
 * watchdog's state, and the status line's text (engine-status.js).
 * @typedef {{frame: number | null, error: string | null, context: string | null, hung: string | null, status: string | null}} PageMarks
 */

/** window.pageMarks, made on first use. @returns {PageMarks} */
export function pageMarks() {
  const page = /** @type {Window & {pageMarks?: PageMarks}} */ (window);
  page.pageMarks ??= { frame: null, error: null, context: null, hung: null, status: null };
  return page.pageMarks;
}

/**
 * Keeps the attributes in step with what the app reports.
 * @param {ShaderApp} app
 */
export function markApp(app) {
  const root = document.documentElement.dataset;
  const marks = pageMarks();
  app.on('compile', (_, error) => {
    if (!error) delete root.error;
    else if (!app.compiles.hasProgram) root.error = 'shader-compile';
    marks.error = root.error ?? null;
  });
  app.on('context', (_, lost) => {
    if (lost) root.context = 'lost';
    else delete root.context;
    marks.context = root.context ?? null;
  });
  app.on('hang', (_, seconds, phase = 'drawing') => {
    if (seconds === null) delete root.hung;
    else root.hung = phase === 'drawing' ? 'true' : 'compiling';
    marks.hung = root.hung ?? null;
  });
  app.on('drawn', () => {
    app.canvas.dataset.frame = String(app.frames.count);
    marks.frame = app.frames.count;
  });
}

/**
 * The page could not start: data-error="webgl2" without WebGL2, else "startup".
 * @param {Error} error
 */
export function markStartupFailure(error) {
  document.documentElement.dataset.error = error.name === 'WebGL2UnavailableError' ? 'webgl2' : 'startup';
  pageMarks().error = document.documentElement.dataset.error;
}
