// Entry point: reads the URL, starts the raytracer on the page's canvas with
// shaders/raytrace.glsl, and installs window.raytracer (src/automation.js).

import shaderSource from '../shaders/raytrace.glsl?raw';
import { RaytracerApp } from './app.js';
import { installAutomation, installFailedAutomation } from './automation.js';
import { Overlay } from './overlay.js';
import { parseUrlParams } from './url-params.js';

const SHADER_FILE = 'shaders/raytrace.glsl';

/** The page could not start (no WebGL2, most likely): say so on the page, not in a blank one. */
function showStartupFailure(overlay, error) {
  const noWebGL2 = error.name === 'WebGL2UnavailableError';
  document.documentElement.dataset.error = noWebGL2 ? 'webgl2' : 'startup';
  overlay.show(noWebGL2 ? 'WebGL2 is not available' : 'The raytracer could not start', error.message);
}

function start() {
  const canvas = document.getElementById('view');
  const overlay = new Overlay(document.getElementById('overlay'));
  const params = parseUrlParams(location.search);
  for (const warning of params.warnings) console.warn(warning);

  let app;
  try {
    app = new RaytracerApp({
      canvas,
      overlay,
      fileName: SHADER_FILE,
      size: params.size ?? null,
      scale: params.scale ?? 1,
      playing: params.time === undefined, // ?time=T shows that instant, paused
    });
  } catch (error) {
    showStartupFailure(overlay, error);
    installFailedAutomation(error);
    return null;
  }

  if (params.time !== undefined) app.inputs.setTime(params.time);
  if (params.mouse) app.inputs.setMouse(params.mouse);
  app.loadSource(shaderSource);
  app.applyControls(params.controls, 'URL');
  installAutomation(app, app.ready);
  app.compile().catch(() => {}); // shown on the page; `ready` rejects
  app.requestRender();
  return app;
}

const app = start();

// Editing the shader under `npm run dev` recompiles it in place (errors go to the overlay).
if (import.meta.hot) {
  import.meta.hot.accept('../shaders/raytrace.glsl?raw', (module) => {
    if (!app || !module) return;
    app.loadSource(module.default);
    app.compile().catch(() => {});
  });
}
