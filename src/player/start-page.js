// The start of either page (main.js: the interactive page; engine-main.js: the engine page the
// command line draws on), once: the app on the page's canvas at its URL's view, with the
// watchdog's memory of a shader that hung (io/hang-guard.js); or, when it could not start (no
// WebGL2, a worker that did not come up), null, after `failed` has said so (each page in its own
// way, and each installs its failed hook: hook/failed-hook.js).

import { ShaderApp } from './app/app.js';
import { parseUrlParams } from '../shared/url-params.js';
import { fetchMedia, loadChannel, shaderName } from './io/shader-loader.js';
import { HangGuard, watchHangs } from './io/hang-guard.js';
import { builtinName } from './open-view.js';

/**
 * Starts the app on #view at the view of the page's URL. Null when it could not start.
 * @param {(error: Error) => void} failed says that the page could not start, and why
 * @returns {Promise<{app: ShaderApp, params: ReturnType<typeof parseUrlParams>} | null>}
 */
export async function startPage(failed) {
  const canvas = /** @type {HTMLCanvasElement} */ (document.getElementById('view'));
  const params = parseUrlParams(location.search, location.href);
  let app;
  try {
    app = await ShaderApp.start({
      canvas,
      loadChannel,
      fetchMedia,
      fileName: params.shader ? shaderName(params.shader) : builtinName(),
      size: params.size ?? null,
      scale: params.scale ?? 1,
      cap: params.cap ?? 0,
      playing: params.time === undefined, // ?time=T shows that instant, paused
    });
  } catch (error) {
    failed(error);
    return null;
  }
  watchHangs(app, new HangGuard());
  return { app, params };
}
