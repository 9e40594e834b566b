// The app's ways back when the GPU side goes (app.js): a lost WebGL context, and a render worker
// stopped by the watchdog (a draw that would not end). Either way the worker's state is gone, so
// the app gives it the control uniforms and the channels again and compiles its shader again;
// after a hang, the one to compile is the last shader that finished a frame (io/hang-guard.js),
// not the one that hung.

/** @typedef {import('./app.js').ShaderApp} ShaderApp */

/**
 * Follows the worker's context: 'context' and 'state' events, and on its return a compile.
 * @param {ShaderApp} app
 */
export function watchContext(app) {
  app.gpu.on('context', (_, lost) => {
    if (lost) {
      app.emit('context', true);
      app.emit('state');
      return;
    }
    // the worker's state went with the context: programs are compiled again from ours; after
    // a hang (the browser resets a GPU held too long), the last shader that finished a frame
    app.compiles.forget();
    const back = app.hangGuard?.backFor(app.project, app.values);
    if (back) app.runVersion(back, 'the last shader that finished');
    resend(app);
    app.compiles.compile().catch(() => {}); // shown on the page
    app.emit('context', false); // after the compile started: the compiles asked for meanwhile end with it
    app.emit('state');
    app.frames.request();
  });
}

/**
 * Gives the worker the control uniforms and the channels again (a new worker, a new context).
 * @param {ShaderApp} app
 */
function resend(app) {
  app.gpu.tell('controlUniforms', { controls: app.controls, values: app.values });
  app.channels.resend();
  app.media.resend();
}

/**
 * The watchdog's way out: stops the render worker (and the draw that would not end) and runs
 * the last shader a frame was finished with, in a new one. On a real GPU that draws at once
 * (the browser resets a GPU held too long); on SwiftShader the endless draw keeps the GPU
 * process busy, and the new worker waits with it.
 * @param {ShaderApp} app
 */
export async function goBack(app) {
  const back = app.frames.lastFinished;
  await app.gpu.respawn();
  app.frames.forgetDrawing();
  app.compiles.forget();
  if (back) app.runVersion(back, 'the last shader that finished');
  resend(app);
  app.compiles.compile().catch(() => {});
  app.frames.request();
}
