// Entry point: reads the URL, starts the raytracer on the page's canvas with shaders/raytrace.glsl
// (or the shader named by ?shader=), shows what the app reports (the overlay, the data-*
// attributes), builds the page's widgets (toolbar, panel, editor), and installs window.raytracer
// (src/page/automation.js).

import builtinSource from '../../shaders/raytrace.glsl?raw';
import { RaytracerApp } from './app.js';
import { installAutomation, installFailedAutomation } from './automation.js';
import { Overlay } from './overlay.js';
import { CHANNEL_PARAMS, parseUrlParams } from './url-params.js';
import { fetchShader, shaderName } from './shader-loader.js';
import { installUi } from './ui.js';
import { HangGuard, watchHangs } from './hang-guard.js';
import { sourceFromHash } from './share-link.js';
import { sharedKey, showRestoredNote } from './kept-source.js';
import { formatShaderMessages } from '../shadertoy/shader-errors.js';
import { formatPassMessages } from '../shadertoy/pass-errors.js';
import { singlePass } from '../shadertoy/multipass.js';
import { deserializeProject, isJsonName, projectTabs, readShaderText, serializeProject } from './project-files.js';

const BUILTIN_NAME = 'shaders/raytrace.glsl';

/** @typedef {{title: string, detail: string, actions?: Array<{label: string, run: () => void}>}} Notice */
/**
 * @typedef {object} FirstSource the shader the page opens with
 * @property {import('../shadertoy/multipass.js').MultipassShader} project
 * @property {{name: string, origin: 'builtin' | 'url' | 'editor', url?: string, info?: object | null}} from
 * @property {Notice} [notice]
 */

/**
 * A compile message as the error box shows it: "Buffer A:12: error: ..." for a tab of a
 * multipass shader, "NAME:12: error: ..." for a single-pass one; the line's text under it.
 * @param {RaytracerApp} app
 * @param {string} fileName
 */
function messageFormatter(app, fileName) {
  const tabs = Object.fromEntries(projectTabs(app.project).map((t) => [t.name, t.code]));
  const source = app.source;
  return (/** @type {{severity: string, pass?: string | null, line: number | null, message: string}} */ m) =>
    m.pass ? formatPassMessages([{ ...m, pass: m.pass }], tabs) : formatShaderMessages([m], source, fileName);
}

/**
 * The page could not start (no WebGL2, most likely): say so on the page, not in a blank one.
 * @param {Overlay} overlay
 * @param {Error} error
 */
function showStartupFailure(overlay, error) {
  const noWebGL2 = error.name === 'WebGL2UnavailableError';
  document.documentElement.dataset.error = noWebGL2 ? 'webgl2' : 'startup';
  overlay.show(noWebGL2 ? 'WebGL2 is not available' : 'The raytracer could not start', error.message);
}

/**
 * Shows what the app reports: compile errors, an unreadable control block and a lost context in
 * the overlay; and, for the tests and the automation, data-error="shader-compile" on <html>
 * while no shader could run, data-context="lost" while the GPU context is gone, and on the
 * canvas data-frame, the number of frames drawn.
 * @param {RaytracerApp} app
 * @param {Overlay} overlay
 * @returns {(notice: Notice) => void} shows a notice once the next compile succeeds (instead of
 *   hiding the overlay)
 */
function showAppOnPage(app, overlay) {
  const root = document.documentElement.dataset;
  /** @type {Notice | null} */
  let pending = null;
  app.on('compile', (_, error, fileName) => {
    if (error) {
      const fallback = app.renderer.hasProgram ? ' (still showing the last version that compiled)' : '';
      const title = `${fileName} did not compile${fallback}`;
      if (error.messages?.length) overlay.showMessages(title, error.messages, messageFormatter(app, fileName));
      else overlay.show(title, error.report ?? error.message);
      if (!app.renderer.hasProgram) root.error = 'shader-compile';
      return;
    }
    if (app.notice) overlay.show(`Control block of ${fileName} not read`, app.notice);
    else if (pending) overlay.showActions(pending.title, pending.detail, pending.actions ?? []);
    else overlay.hide();
    pending = null;
    delete root.error;
  });
  app.on('context', (_, lost) => {
    if (lost) {
      root.context = 'lost';
      overlay.show(
        'The GPU context was lost',
        'The browser took the graphics context away (a driver reset, or too many pages using the GPU). The picture comes back when the browser restores it.',
      );
    } else {
      delete root.context;
    }
  });
  app.on('drawn', () => (app.canvas.dataset.frame = String(app.framesRendered)));
  showWatchdog(app, overlay);
  return (notice) => (pending = notice);
}

/**
 * The watchdog's message (render-client.js): a frame that has gone seconds without progress may
 * never finish. It offers to go back to the last shader that finished a frame; it goes away by
 * itself when the drawing goes on. data-hung="true" on <html> while it shows.
 * @param {RaytracerApp} app
 * @param {Overlay} overlay
 */
function showWatchdog(app, overlay) {
  const root = document.documentElement.dataset;
  app.on('hang', (_, seconds) => {
    if (seconds === null) {
      if (root.hung) overlay.hide();
      delete root.hung;
      return;
    }
    const first = !root.hung;
    root.hung = 'true';
    if (!first) return; // the message stays as it is; the seconds are in its text from the start
    const back = app.lastFinished;
    const detail = [
      `${app.fileName} has been drawing one frame for ${Math.round(seconds)} s without finishing a band of it: it may never finish (an endless loop, or far too much work per pixel).`,
      'On a real GPU the browser resets the GPU after several seconds of this, and the page comes back with the last shader that finished a frame. SwiftShader (the CPU renderer) has no such reset: the draw goes on until the browser is closed.',
      back ? `Going back runs ${back.name} again; the text that hung stays in the editor's undo history (Ctrl+Z).` : '',
    ]
      .filter(Boolean)
      .join('\n');
    const actions = back
      ? [
          {
            label: `Go back to ${back.name}`,
            run: () => {
              overlay.show(`Going back to ${back.name}…`, 'Starting the renderer again.');
              app.goBack().catch((error) => {
                console.warn(error.message);
                overlay.show(
                  'The GPU did not come back',
                  `${error.message}: the draw that never ends still holds the GPU. On SwiftShader it does until the browser closes: close the browser and open the page again, and it runs ${back.name}.`,
                );
              });
            },
          },
        ]
      : [];
    overlay.showActions(`${app.fileName} may never finish`, detail, actions);
  });
}

/** The built-in raytracer, with a notice when the page was asked for another shader. @param {Notice} [notice] @returns {FirstSource} */
const builtin = (notice) => ({ project: singlePass(builtinSource), from: { name: BUILTIN_NAME, origin: 'builtin' }, notice });

/**
 * The first shader: the one a link carries (#source=), the ?shader= file, or the built-in
 * raytracer (also when those cannot be had or read: then with a notice that says so). A text
 * that is Shadertoy's JSON export (a .json file, or any text that looks like JSON) is read as one.
 * @param {{shader?: string, refusedShader?: {url: string, why: string}}} params
 * @returns {Promise<FirstSource>}
 */
async function initialSource(params) {
  try {
    const shared = await sourceFromHash(location.hash);
    if (shared) {
      const { model, info } = readShaderText(shared.source);
      return { project: model, from: { name: shared.name, origin: 'editor', info } };
    }
  } catch (error) {
    console.warn(`The shader in the link's #source= could not be read: ${error.message}`);
    return builtin({
      title: 'Could not read the shader in this link',
      detail: `${error.message}\nShowing the built-in raytracer instead.`,
    });
  }
  if (params.refusedShader) {
    const { url, why } = params.refusedShader;
    return builtin({ title: `Could not load ${url}`, detail: `${why}.\nShowing the built-in raytracer (${BUILTIN_NAME}) instead.` });
  }
  if (!params.shader) return builtin();
  try {
    const text = await fetchShader(params.shader);
    const { model, info } = readShaderText(text, { json: isJsonName(params.shader) });
    return { project: model, from: { name: shaderName(params.shader), origin: 'url', url: params.shader, info } };
  } catch (error) {
    console.warn(`URL parameter shader=${params.shader}: ${error.message}`);
    return builtin({
      title: `Could not load ${params.shader}`,
      detail: `${error.message}\nShowing the built-in raytracer (${BUILTIN_NAME}) instead.`,
    });
  }
}

/**
 * Work is never lost (kept-source.js): edits kept for the page's shader (the ?shader= file, the
 * built-in one, or the shader a link carries), every tab of a multipass one, come back, with a
 * note that can discard them.
 * @param {RaytracerApp} app
 * @param {ReturnType<typeof installUi>} ui
 * @param {string | undefined} shader the ?shader= parameter
 * @param {FirstSource} first what the page loaded
 */
function restoreKeptWork(app, ui, shader, { project, from }) {
  const file = { name: from.name, source: serializeProject(project) };
  const kept = ui.kept.open(from.origin === 'editor' ? sharedKey(file) : (shader ?? BUILTIN_NAME), file);
  if (!kept) return;
  app.loadProject(deserializeProject(kept.source), { name: kept.name, origin: 'editor', info: from.info ?? null });
  showRestoredNote(document.getElementById('stage'), kept.name, () => {
    app.setProject(project, from).catch(() => {});
  });
}

/**
 * The shader about to run is the one that hung last time (hang-guard.js): run the last one that
 * finished a frame instead, say so, and offer the text that hung back to the editor, not run.
 * @param {RaytracerApp} app
 * @param {(notice: Notice) => void} notice
 */
function avoidHungShader(app, notice) {
  const guard = /** @type {HangGuard} */ (app.hangGuard);
  const back = guard.backFor(app.project, app.values);
  const hung = guard.note;
  if (!back || !hung) return;
  app.runVersion(back);
  notice({
    title: `${hung.name} did not finish drawing last time`,
    detail: `It may never finish (an endless loop?), so the page runs ${back.name}, the last shader that finished a frame. The text that hung is kept: it goes back into the editor, not run, with the button below.`,
    actions: [{ label: `Edit ${hung.name} (not run)`, run: () => app.loadProject(hung.project, { name: hung.name, origin: 'editor' }) }],
  });
}

async function start() {
  const canvas = /** @type {HTMLCanvasElement} */ (document.getElementById('view'));
  const overlay = new Overlay(document.getElementById('overlay'));
  const params = parseUrlParams(location.search, location.href);
  for (const warning of params.warnings) console.warn(warning);

  const first = initialSource(params); // fetched while the render worker starts
  let app;
  try {
    app = await RaytracerApp.start({
      canvas,
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
  if (params.time !== undefined) app.inputs.setTime(params.time);
  if (params.speed !== undefined) app.inputs.setSpeed(params.speed);
  if (params.mouse) app.inputs.setMouse(params.mouse);
  const ui = installUi(app);
  overlay.onLine = (line, pass) => ui.editor.goToLine(line, pass);
  installAutomation(app, app.ready, ui);

  params.channels.forEach((url, i) => {
    if (!url) return;
    app.setChannel(i, url).catch((error) => {
      console.warn(`URL parameter ${CHANNEL_PARAMS[i]}=${url} ignored: ${error.message}`);
      ui.toast(`Could not load ${url} into iChannel${i}`);
    });
  });

  app.loading = first.then((loaded) => {
    if (loaded.notice) noticeAfterCompile(loaded.notice);
    app.loadProject(loaded.project, loaded.from);
    restoreKeptWork(app, ui, params.shader, loaded);
    avoidHungShader(app, noticeAfterCompile);
    app.applyControls(params.controls, 'URL');
    app.compile().catch(() => {}); // shown on the page; `ready` rejects
    app.requestRender();
  });
  return app;
}

/** @type {RaytracerApp | null} */
let app = null;
start().then((started) => (app = started));

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
