// Entry point: reads the URL, starts the raytracer on the page's canvas with shaders/raytrace.glsl
// (or the shader named by ?shader=), builds the page's widgets (toolbar, panel, editor), and
// installs window.raytracer (src/page/automation.js).

import builtinSource from '../../shaders/raytrace.glsl?raw';
import { RaytracerApp } from './app.js';
import { installAutomation, installFailedAutomation } from './automation.js';
import { Overlay } from './overlay.js';
import { CHANNEL_PARAMS, parseUrlParams } from './url-params.js';
import { fetchShader, shaderName } from './shader-loader.js';
import { installUi } from './ui.js';

const BUILTIN_NAME = 'shaders/raytrace.glsl';

/** The page could not start (no WebGL2, most likely): say so on the page, not in a blank one. */
function showStartupFailure(overlay, error) {
  const noWebGL2 = error.name === 'WebGL2UnavailableError';
  document.documentElement.dataset.error = noWebGL2 ? 'webgl2' : 'startup';
  overlay.show(noWebGL2 ? 'WebGL2 is not available' : 'The raytracer could not start', error.message);
}

/** The first source: the ?shader= file, or the built-in raytracer (also when that file cannot be had). */
async function initialSource(app, params) {
  if (!params.shader) return { source: builtinSource, from: { name: BUILTIN_NAME, origin: 'builtin' } };
  try {
    const source = await fetchShader(params.shader);
    return { source, from: { name: shaderName(params.shader), origin: 'url', url: params.shader } };
  } catch (error) {
    console.warn(`URL parameter shader=${params.shader}: ${error.message}`);
    app.pendingNotice = {
      title: `Could not load ${params.shader}`,
      detail: `${error.message}\nShowing the built-in raytracer (${BUILTIN_NAME}) instead.`,
    };
    return { source: builtinSource, from: { name: BUILTIN_NAME, origin: 'builtin' } };
  }
}

function start() {
  const canvas = document.getElementById('view');
  const overlay = new Overlay(document.getElementById('overlay'));
  const params = parseUrlParams(location.search, location.href);
  for (const warning of params.warnings) console.warn(warning);

  let app;
  try {
    app = new RaytracerApp({
      canvas,
      overlay,
      fileName: params.shader ? shaderName(params.shader) : BUILTIN_NAME,
      size: params.size ?? null,
      scale: params.scale ?? 1,
      cap: params.cap ?? 0,
      playing: params.time === undefined, // ?time=T shows that instant, paused
    });
  } catch (error) {
    showStartupFailure(overlay, error);
    installFailedAutomation(error);
    return null;
  }

  if (params.time !== undefined) app.inputs.setTime(params.time);
  if (params.speed !== undefined) app.inputs.setSpeed(params.speed);
  if (params.mouse) app.inputs.setMouse(params.mouse);
  const ui = installUi(app);
  installAutomation(app, app.ready, ui);

  params.channels.forEach((url, i) => {
    if (!url) return;
    app.setChannel(i, url).catch((error) => {
      console.warn(`URL parameter ${CHANNEL_PARAMS[i]}=${url} ignored: ${error.message}`);
      ui.toast(`Could not load ${url} into iChannel${i}`);
    });
  });

  app.loading = initialSource(app, params).then(({ source, from }) => {
    app.loadSource(source, from);
    app.applyControls(params.controls, 'URL');
    app.compile().catch(() => {}); // shown on the page; `ready` rejects
    app.requestRender();
  });
  return app;
}

const app = start();

// Under `npm run dev`, editing a shader recompiles it in place (errors go to the overlay): the
// built-in one through its `?raw` import, a ?shader= file through the dev server's
// glsl-file-changed event (vite.config.js). A shader edited in the page's editor is left alone.
if (import.meta.hot) {
  import.meta.hot.accept('../../shaders/raytrace.glsl?raw', (module) => {
    if (!app || !module || app.origin !== 'builtin') return;
    app.setSource(module.default).catch(() => {});
  });
  import.meta.hot.on('glsl-file-changed', async ({ url }) => {
    if (!app || app.origin !== 'url' || !app.shaderUrl) return;
    if (new URL(app.shaderUrl, location.href).pathname !== url) return;
    const shaderUrl = app.shaderUrl;
    try {
      const source = await fetchShader(shaderUrl);
      if (app.origin !== 'url' || app.shaderUrl !== shaderUrl) return; // replaced meanwhile
      await app.setSource(source, { name: shaderName(shaderUrl), origin: 'url', url: shaderUrl });
    } catch (error) {
      console.warn(`${shaderUrl} changed but could not be reloaded: ${error.message}`);
    }
  });
}
