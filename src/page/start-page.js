// The start of either page (main.js: the interactive page; engine-main.js: the engine page the
// command line draws on), once: the app on the page's canvas at its URL's view, or, when it could
// not start (no WebGL2, a worker that did not come up), that said on the page and a hook whose
// every method rejects with it; then the watchdog and what the app reports shown on the overlay.

import { RaytracerApp } from './app/app.js';
import { installFailedAutomation } from './automation.js';
import { Overlay } from './ui/overlay.js';
import { showAppOnPage, showStartupFailure } from './ui/notices.js';
import { parseUrlParams } from '../shared/url-params.js';
import { fetchMedia, loadChannel, shaderName } from './io/shader-loader.js';
import { HangGuard, watchHangs } from './io/hang-guard.js';
import { BUILTIN_NAME } from './open-view.js';

/**
 * Starts the app on #view at the view of the page's URL. Null when it could not start.
 * @returns {Promise<{app: RaytracerApp, overlay: Overlay, params: ReturnType<typeof parseUrlParams>,
 *   noticeAfterCompile: ReturnType<typeof showAppOnPage>} | null>}
 */
export async function startPage() {
  const canvas = /** @type {HTMLCanvasElement} */ (document.getElementById('view'));
  const overlay = new Overlay(/** @type {HTMLElement} */ (document.getElementById('overlay')));
  const params = parseUrlParams(location.search, location.href);
  let app;
  try {
    app = await RaytracerApp.start({
      canvas,
      loadChannel,
      fetchMedia,
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
  watchHangs(app, new HangGuard());
  const noticeAfterCompile = showAppOnPage(app, overlay);
  return { app, overlay, params, noticeAfterCompile };
}
