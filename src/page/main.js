// Entry point: reads the URL, starts the app (app/) on the page's canvas with
// shaders/raytrace.glsl (or the shader a link or ?shader= names), builds the page's widgets (ui/),
// shows what the app reports (ui/notices.js), and installs window.raytracer (automation.js).

import builtinSource from '../../shaders/raytrace.glsl?raw';
import { installAutomation } from './automation.js';
import { installUi } from './ui/ui.js';
import { parseUrlParams } from '../shared/url-params.js';
import { fetchShader, shaderName } from './io/shader-loader.js';
import { startPage } from './start-page.js';
import { openShader } from './io/open-shader.js';
import { Recorder } from './io/recorder.js';
import { BUILTIN_NAME, linkedShader, openView, useBuiltinSource } from './open-view.js';
import { singlePass } from '../shadertoy/multipass.js';

useBuiltinSource(builtinSource);

async function start() {
  const page = await startPage();
  if (!page) return null;
  const { app, overlay, params, noticeAfterCompile } = page;
  const recorder = new Recorder(app); // the page's: the Record dialog and window.raytracer share it
  const ui = installUi(app, { builtinSource, recorder });
  overlay.onLine = (line, pass) => ui.editor.goToLine(line, pass);
  /** window.raytracer.open(query): the page as a fresh load of `query` (a URL's ?… and #…) gives it. */
  const open = (/** @type {string} */ query) => {
    const url = new URL(query, location.href);
    return openView(app, ui, parseUrlParams(url.search, url.href), { hash: url.hash, noticeAfterCompile, again: true });
  };
  // before the first shader opens: the hook's marks (page-marks.js) follow it from its start
  installAutomation(app, app.ready, { open, recorder, ui });
  const started = openView(app, ui, params, { hash: location.hash, noticeAfterCompile });
  started.catch(() => {}); // shown on the page; `ready` rejects

  // A second link opened in this tab that differs only in its fragment loads no page: its
  // #source= is opened here, as a link opened afresh is.
  window.addEventListener('hashchange', async () => {
    const linked = await linkedShader(location.hash);
    if (!linked) return;
    if (linked.notice) noticeAfterCompile(linked.notice);
    app.loadProject(linked.project, linked.from);
    ui.kept.open(BUILTIN_NAME, linked);
    app.compiles.compile().catch(() => {});
  });
  return app;
}

/** @type {import('./app/app.js').RaytracerApp | null} */
let app = null;
start().then((started) => (app = started));

/**
 * The ?shader= file at URL path `url` changed on disk: run it again in place (errors go to the
 * overlay). A shader edited in the page's editor, or replaced meanwhile, is left alone.
 * @param {string} url
 */
async function reloadChangedShader(url) {
  if (!app || app.origin !== 'url' || !app.shaderUrl) return;
  if (new URL(app.shaderUrl, location.href).pathname !== url) return;
  const shaderUrl = app.shaderUrl;
  try {
    const source = await fetchShader(shaderUrl);
    if (app.origin !== 'url' || app.shaderUrl !== shaderUrl) return; // replaced meanwhile
    await openShader(app, source, { name: shaderName(shaderUrl), origin: 'url', url: shaderUrl }).running;
  } catch (error) {
    console.warn(`${shaderUrl} changed but could not be reloaded: ${error.message}`);
  }
}

// Under `npm run dev`, editing a shader recompiles it in place: the built-in one through its
// `?raw` import, a ?shader= file through the dev server's glsl-file-changed event
// (vite.config.js).
if (import.meta.hot) {
  import.meta.hot.accept('../../shaders/raytrace.glsl?raw', (module) => {
    if (module) useBuiltinSource(module.default);
    if (!app || !module || app.origin !== 'builtin') return;
    app.setProject(singlePass(module.default)).catch(() => {});
  });
  import.meta.hot.on('glsl-file-changed', ({ url }) => reloadChangedShader(url));
}

// Served by the command line's `open` (src/engine/page-server.js), the page hears of a saved file
// through Server-Sent Events at the address this tag names.
const fileEvents = document.querySelector('meta[name="raytracer-file-events"]')?.getAttribute('content');
if (fileEvents) {
  new EventSource(fileEvents).addEventListener('message', (event) => {
    const { url } = JSON.parse(event.data);
    reloadChangedShader(url);
  });
}
