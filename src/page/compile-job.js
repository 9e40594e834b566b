// The app's compiles (app.compile, app.whenCompiled): the shader with its control values, sent
// to the render worker to compile. Compiles may overlap (a control dragged through compile-time
// values): only the latest one started reports its outcome (the 'compile' event, the app's
// compileErrors), and a compile asked for while the context is lost waits for its return. The
// shader that compiled is kept as it ran (a ShaderVersion: what the watchdog goes back to).

import { hostControlBlock } from '../shadertoy/header.js';

/** @typedef {import('./app.js').RaytracerApp} RaytracerApp */
/** @typedef {import('./app.js').ShaderVersion} ShaderVersion */

/**
 * The app's shader as it is now: its tabs, where it came from, and a copy of its control values.
 * @param {RaytracerApp} app
 * @returns {ShaderVersion}
 */
export function currentVersion(app) {
  return {
    project: app.project,
    info: app.projectInfo,
    name: app.fileName,
    origin: app.origin,
    url: app.shaderUrl,
    values: structuredClone(app.values),
  };
}

/**
 * Compiles the app's source with its current compile-time values. On success the new shader is
 * drawn; on failure the error is shown and the last shader that compiled keeps running.
 * @param {RaytracerApp} app
 * @returns {Promise<void>}
 */
export function compileShader(app) {
  if (app.renderer.contextLost) {
    // compiled when the context comes back: this job ends as the compile started then does
    /** @type {Promise<void>} */
    const job = new Promise((resolve) => app.once('context', () => resolve(app._latestCompile)));
    app._latestCompile = job;
    return job;
  }
  const hostBlock = app.notice ? '' : hostControlBlock(app.controls, app.values, app.liveForm.asConstants ? app.values : null);
  const fileName = app.fileName;
  const version = currentVersion(app);
  const job = app.renderer.compile(app.project, hostBlock, fileName).then(
    () => {
      app._running = version;
      if (job !== app._latestCompile) return;
      app.compileErrors = [];
      app.compiled++;
      app.emit('compile', null, fileName);
      app.requestRender();
    },
    (error) => {
      if (job === app._latestCompile) {
        app.compileErrors = error.messages ?? [];
        console.warn(error.message);
        app.emit('compile', error, fileName); // `ready` rejects if no shader runs at all
      }
      throw error;
    },
  );
  app._latestCompile = job;
  return job;
}

/**
 * Resolves when no compile is under way (whatever the outcome).
 * @param {RaytracerApp} app
 */
export async function whenCompiled(app) {
  let job;
  do {
    job = app._latestCompile;
    await job?.catch(() => {});
  } while (job !== app._latestCompile);
}
