// "Converge when still" (app.setConverging): the built-in raytracer (or an edit that keeps its
// camera and radiance functions: progressive.js calls them) runs
// as its progressive multipass form (progressive.js: Buffer A adds one jittered sample per pixel
// per frame while nothing changes; Image shows the mean and the sample count), with the clock
// paused so that the view is still; off, the shader as it was, with its control values. Kept
// apart from app.js, which only asks for frames while a converging view is still (frame-loop.js).

import { MAX_SAMPLES, missingRaytracerFunctions, progressiveTabs } from '../shadertoy/progressive.js';
import { currentVersion } from './compile-job.js';

/**
 * Turns converging on or off for `app`; resolves once the shader it runs then has compiled.
 * Frames keep coming while the view is still, up to `frames` (MAX_SAMPLES by default), and start
 * again from one sample after any change.
 * @param {import('./app.js').RaytracerApp} app
 * @param {boolean} on
 * @param {{frames?: number}} [options]
 * @returns {Promise<void>}
 */
export async function setConverging(app, on, { frames = MAX_SAMPLES } = {}) {
  app.convergeFrames = Math.max(1, Math.min(MAX_SAMPLES, Math.round(frames)));
  if (on === app.converging) return app.requestRender();
  if (!on) {
    const back = /** @type {import('./app.js').ShaderVersion} */ (app._beforeConverging);
    app.converging = false;
    app._beforeConverging = null;
    app.loadProject(back.project, back);
    app.applyControls(back.values ?? {}, 'Converge when still');
    return app.compile();
  }
  if (app.isMultipass) throw new Error('only the raytracer converges: this shader has buffers of its own');
  const missing = missingRaytracerFunctions(app.source);
  if (missing.length) throw new Error(`only the raytracer converges (shaders/raytrace.glsl): this shader has no ${missing.join(', ')}`);
  app._beforeConverging = currentVersion(app);
  const tabs = progressiveTabs(app.source);
  app.pause();
  app.converging = true;
  app.loadProject(tabs.model, { converging: true, name: app.fileName, origin: app.origin, url: app.shaderUrl });
  app.applyControls({ SHOW_SAMPLE_COUNT: 1 }, 'Converge when still');
  return app.compile();
}
