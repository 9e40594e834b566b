// Entry point of the interactive page (index.html): reads the URL, starts the app (app/) on the
// page's canvas with the built-in raytracer (shaders/raytrace.glsl, or the shader a link or
// ?shader= names), builds the page's widgets (ui/), shows what the app reports (ui/notices.js:
// the overlay, the notes, the toasts) and installs window.shaderEngine (hook/page-hook.js: the
// engine's hook and the widgets' methods). The raytracer's own parts plug in here: its
// convergence (src/raytracer/convergence.js) and its debug view's note (extra-samples.js).

import builtinSource from '../../shaders/raytrace.glsl?raw';
import { PageHook, installPage } from './page-hook.js';
import { installFailedHook } from '../player/hook/failed-hook.js';
import { installUi } from './wiring.js';
import { Overlay } from './ui/overlay.js';
import { showAppOnPage, showStartupFailure, showValueNotes } from './ui/notices.js';
import { parseUrlParams } from '../shared/url-params.js';
import { fetchShader, shaderName } from '../player/io/shader-loader.js';
import { startPage } from '../player/start-page.js';
import { openShader } from '../player/io/open-shader.js';
import { Recorder } from '../player/io/recorder.js';
import { linkedShader, openView, useBuiltinShader } from '../player/open-view.js';
import { singlePass } from '../shadertoy/multipass.js';
import { raytracerConvergence } from '../raytracer/convergence.js';
import { extraSamplesViewNote } from '../raytracer/extra-samples.js';

/** The built-in raytracer's file name: the page's built-in shader. */
const BUILTIN_NAME = 'shaders/raytrace.glsl';
/** @param {string} text the built-in raytracer's text (at start, and after a hot update) */
const useRaytracer = (text) => useBuiltinShader({ name: BUILTIN_NAME, text, what: 'the built-in raytracer' });
useRaytracer(builtinSource);

async function start() {
  const overlay = new Overlay(/** @type {HTMLElement} */ (document.getElementById('overlay')));
  const started = await startPage((error) => {
    showStartupFailure(overlay, error);
    installFailedHook(error, PageHook);
  });
  if (!started) return null;
  const { app, params } = started;
  app.converge.use(raytracerConvergence);
  const noticeAfterCompile = showAppOnPage(app, overlay);
  const recorder = new Recorder(app); // the page's: the Record dialog and window.shaderEngine share it
  const ui = installUi(app, { builtinSource, recorder, viewNote: extraSamplesViewNote });
  overlay.onLine = (line, pass) => ui.editor.goToLine(line, pass);
  // what opening a view reports (open-view.js), shown as a person sees it
  const stage = /** @type {HTMLElement} */ (document.getElementById('stage'));
  app.on('notice', (_, notice) => noticeAfterCompile(notice));
  app.on('values', (_, lines) => showValueNotes(stage, lines));
  app.on('say', (_, text) => ui.toast(text));
  /** @type {import('../player/open-view.js').KeepWork} */
  const keep = (pageKey, first) => ui.kept.open(pageKey, first);
  /**
   * window.shaderEngine.open(query): the page as a fresh load of `query` (a URL's ?… and #…) gives
   * it, its widgets too: the inspector off, the notes of the view before gone, the panel at the
   * view's scale and cap.
   * @param {string} query
   */
  const open = async (query) => {
    const url = new URL(query, location.href);
    ui.inspection.reset();
    document.getElementById('notes')?.replaceChildren();
    try {
      await openView(app, parseUrlParams(url.search, url.href), { hash: url.hash, again: true, keep });
    } finally {
      const size = app.canvasSize;
      ui.panel.setView({ scale: size.scale, cap: size.cap, sizeFixed: Boolean(size.fixed) });
    }
  };
  // the first view starts compiling only after this task: the hook's marks follow it from its start
  const ready = openView(app, params, { hash: location.hash, keep });
  ready.catch(() => {}); // shown on the page; `ready` rejects
  installPage(app, { ready, open, recorder }, ui);

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

/** @type {import('../player/app/app.js').ShaderApp | null} */
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
    if (module) useRaytracer(module.default);
    if (!app || !module || app.origin !== 'builtin') return;
    app.setProject(singlePass(module.default)).catch(() => {});
  });
  import.meta.hot.on('glsl-file-changed', ({ url }) => reloadChangedShader(url));
}

// Served by the command line's `open` (src/headless/page-server.js), the page hears of a saved file
// through Server-Sent Events at the address this tag names.
const fileEvents = document.querySelector('meta[name="shaderproof-file-events"]')?.getAttribute('content');
if (fileEvents) {
  new EventSource(fileEvents).addEventListener('message', (event) => {
    const { url } = JSON.parse(event.data);
    reloadChangedShader(url);
  });
}
