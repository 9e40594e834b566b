// The page's state as attributes, for the tests, the harness and the command line (src/engine/)
// to wait on, part of the hook's contract (hook/engine-hook.js installs them): on <html>,
// data-error="shader-compile" while no shader could run ("webgl2" or "startup" when the page
// could not start), data-context="lost" while the GPU context is gone, data-hung="true" while a
// frame may never finish and "compiling" while a program's first draw is taking long (the
// watchdog: render-client.js); on the canvas, data-frame, the number of frames drawn. What a
// person reads about the same things is ui/notices.js's.

/** @typedef {import('./app/app.js').RaytracerApp} RaytracerApp */

/**
 * Keeps the attributes in step with what the app reports.
 * @param {RaytracerApp} app
 */
export function markApp(app) {
  const root = document.documentElement.dataset;
  app.on('compile', (_, error) => {
    if (!error) delete root.error;
    else if (!app.compiles.hasProgram) root.error = 'shader-compile';
  });
  app.on('context', (_, lost) => {
    if (lost) root.context = 'lost';
    else delete root.context;
  });
  app.on('hang', (_, seconds, phase = 'drawing') => {
    if (seconds === null) delete root.hung;
    else root.hung = phase === 'drawing' ? 'true' : 'compiling';
  });
  app.on('drawn', () => (app.canvas.dataset.frame = String(app.frames.count)));
}

/**
 * The page could not start: data-error="webgl2" without WebGL2, else "startup".
 * @param {Error} error
 */
export function markStartupFailure(error) {
  document.documentElement.dataset.error = error.name === 'WebGL2UnavailableError' ? 'webgl2' : 'startup';
}
