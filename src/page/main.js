// Entry point: reads the URL, starts the app (app/) on the page's canvas with
// shaders/raytrace.glsl (or the shader a link or ?shader= names), builds the page's widgets (ui/),
// shows what the app reports (ui/notices.js), and installs window.raytracer (automation.js).

import builtinSource from '../../shaders/raytrace.glsl?raw';
import { RaytracerApp } from './app/app.js';
import { installAutomation, installFailedAutomation } from './automation.js';
import { Overlay } from './ui/overlay.js';
import { installUi } from './ui/ui.js';
import { sayOnNote, showAppOnPage, showKeptOffer, showRestoredNote, showStartupFailure, showValueNotes } from './ui/notices.js';
import { CHANNEL_PARAMS, parseUrlParams } from './io/url-params.js';
import { fetchShader, shaderName } from './io/shader-loader.js';
import { HangGuard, watchHangs } from './io/hang-guard.js';
import { BUILTIN_BASE, sourceFromHash } from './io/share-link.js';
import { sharedKey } from './io/kept-source.js';
import { deserializeProject, serializeProject } from './io/project-files.js';
import { openShader, readShader } from './io/open-shader.js';
import { singlePass } from '../shadertoy/multipass.js';

const BUILTIN_NAME = 'shaders/raytrace.glsl';

/** @typedef {import('./ui/notices.js').Notice} Notice */
/** @typedef {import('./app/app.js').ShaderVersion} ShaderVersion */
/**
 * @typedef {object} FirstSource the shader the page opens with
 * @property {import('../shadertoy/multipass.js').MultipassShader} project
 * @property {{name: string, origin: RaytracerApp['origin'], url?: string | null, info?: object | null}} from
 * @property {Notice} [notice]
 */

/** The built-in raytracer, with a notice when the page was asked for another shader. @param {Notice} [notice] @returns {FirstSource} */
const builtin = (notice) => ({ project: singlePass(builtinSource), from: { name: BUILTIN_NAME, origin: 'builtin' }, notice });

/**
 * The shader a link carries in its fragment (#source=), or the built-in raytracer with a notice
 * when it cannot be read; null when the fragment holds none.
 * @param {string} hash
 * @returns {Promise<FirstSource | null>}
 */
async function linkedShader(hash) {
  try {
    // a patch link's base: the built-in raytracer, or a file the page serves
    const baseText = async (/** @type {string} */ base) => (base === BUILTIN_BASE ? builtinSource : fetchShader(base));
    const shared = await sourceFromHash(hash, baseText);
    if (!shared) return null;
    const { project, from } = readShader(shared.source, { name: shared.name, origin: 'editor' });
    const notice = shared.note ? { title: `${shared.name}: made against another version of its file`, detail: shared.note } : undefined;
    return { project, from: { ...from, name: shared.name }, notice };
  } catch (error) {
    console.warn(`The shader in the link's #source= could not be read: ${error.message}`);
    return builtin({
      title: 'Could not read the shader in this link',
      detail: `${error.message.startsWith('its ') ? `The link's ${error.message.slice(4)}` : `The link's shader: ${error.message}`}.\nShowing the built-in raytracer (${BUILTIN_NAME}) instead.`,
    });
  }
}

/**
 * The first shader: the one a link carries (#source=), the ?shader= file, or the built-in
 * raytracer (also when those cannot be had or read: then with a notice that says so). A text
 * that is Shadertoy's JSON export (a .json file, or any text that looks like JSON) is read as one.
 * @param {{shader?: string, refusedShader?: {url: string, why: string}}} params
 * @returns {Promise<FirstSource>}
 */
async function initialSource(params) {
  const linked = await linkedShader(location.hash);
  if (linked) return linked;
  if (params.refusedShader) {
    const { url, why } = params.refusedShader;
    return builtin({ title: `Could not load ${url}`, detail: `${why}.\nShowing the built-in raytracer (${BUILTIN_NAME}) instead.` });
  }
  if (!params.shader) return builtin();
  try {
    const url = params.shader;
    const { project, from } = readShader(await fetchShader(url), { name: shaderName(url), origin: 'url', url });
    return { project, from: { ...from, name: shaderName(url) } };
  } catch (error) {
    console.warn(`URL parameter shader=${params.shader}: ${error.message}`);
    return builtin({
      title: `Could not load ${params.shader}`,
      detail: `${error.message}\nShowing the built-in raytracer (${BUILTIN_NAME}) instead.`,
    });
  }
}

/** A console warning as the page's note says it: without the console's "who says". @param {string} warning */
const plainWarning = (warning) => warning.replace(/^(URL parameter |URL: )/, '');

/** Whether this load is the same page again (a reload, back or forward), not a link opened afresh. */
function reopened() {
  const navigation = /** @type {PerformanceNavigationTiming | undefined} */ (performance.getEntriesByType?.('navigation')[0]);
  return navigation?.type === 'reload' || navigation?.type === 'back_forward';
}

/**
 * Work is never lost (io/kept-source.js): edits kept for the page's shader (the ?shader= file, the
 * built-in one, or the shader a link carries), every tab of a multipass one, come back on a
 * reload, with a note that can discard them. A link opened afresh runs what it names: kept edits
 * of that shader are set aside and offered, never run in its place.
 * @param {RaytracerApp} app
 * @param {{kept: import('./io/kept-source.js').KeptSource}} ui the page's kept edits
 * @param {string | undefined} shader the ?shader= parameter
 * @param {FirstSource} first what the page loaded
 * @returns {(() => ShaderVersion) | null} edits restored: the file, to run while they do not compile
 */
function keptWork(app, ui, shader, { project, from }) {
  const stage = /** @type {HTMLElement} */ (document.getElementById('stage'));
  const file = { name: from.name, source: serializeProject(project) };
  const own = app.version(); // the file as it is, before any edit of it
  const kept = ui.kept.open(from.origin === 'editor' ? sharedKey(file) : (shader ?? BUILTIN_NAME), file);
  /** @param {{name: string, source: string}} edits */
  const load = (edits) =>
    app.loadProject(deserializeProject(edits.source), { name: edits.name, origin: 'editor', info: from.info ?? null });
  if (kept && reopened()) {
    load(kept);
    const note = showRestoredNote(stage, kept.name, () => app.setProject(project, from).catch(() => {}));
    // the note belongs to the text it restored: once that is edited or replaced, Discard would
    // throw away what it did not restore
    const stale = (/** @type {string} */ text) => text !== kept.source && note.remove();
    ui.kept.watch(stale);
    app.on('source', () => stale(serializeProject(app.project)));
    // edits that do not compile (kept mid-work): the file runs until they do, and the note says so
    app.on('compile', (error) => {
      const standing = error && app.compiles.running?.load === own.load;
      sayOnNote(note, standing ? `They do not compile yet: the picture is ${from.name} as the file has it, until they do.` : null);
    });
    // with the values the page runs (a link's): those of the file's controls
    return () => ({
      ...own,
      values: Object.fromEntries(Object.keys(own.values ?? {}).flatMap((name) => (name in app.values ? [[name, app.values[name]]] : []))),
    });
  }
  if (kept) ui.kept.setAside();
  const earlier = ui.kept.earlier();
  if (!earlier) return null;
  showKeptOffer(stage, earlier.name, {
    open: () => {
      ui.kept.forgetEarlier();
      load(earlier);
      app.compiles.compile().catch(() => {});
    },
    discard: () => ui.kept.forgetEarlier(),
  });
  return null;
}

/**
 * The shader about to run is the one that hung last time (io/hang-guard.js): run the last one that
 * finished a frame instead, say so, and offer the text that hung back to the editor, not run.
 * @param {RaytracerApp} app
 * @param {(notice: Notice) => void} notice
 */
function avoidHungShader(app, notice) {
  const guard = /** @type {HangGuard} */ (app.hangGuard);
  const back = guard.backFor(app.project, app.values);
  const hung = guard.note;
  if (!back || !hung) return;
  app.runVersion(back, 'the last shader that finished');
  const compiling = hung.phase === 'compiling';
  notice({
    title: compiling ? `${hung.name} was still compiling when the page closed` : `${hung.name} did not finish drawing last time`,
    detail: compiling
      ? `It had been compiling for ${Math.round(hung.seconds ?? 0)} s (SwiftShader compiles a shader on its first draw; a large one takes a while, an endless loop never ends), so the page runs ${back.name}, the last shader that finished a frame. Run it again, or put it in the editor without running it.`
      : `It may never finish (an endless loop?), so the page runs ${back.name}, the last shader that finished a frame. The text that hung is kept: it goes back into the editor, not run, with the button below.`,
    actions: [
      ...(compiling && hung.version
        ? [{ label: `Run ${hung.name}`, run: () => runAgain(app, /** @type {ShaderVersion} */ (hung.version)) }]
        : []),
      { label: `Edit ${hung.name} (not run)`, run: () => app.loadProject(hung.project, { name: hung.name, origin: 'editor' }) },
    ],
  });
}

/**
 * Runs a shader as it ran before (its tabs and control values).
 * @param {RaytracerApp} app
 * @param {ShaderVersion} version
 */
function runAgain(app, version) {
  app.runVersion(version, 'the shader that was compiling');
  app.compiles.compile().catch(() => {}); // shown on the page
}

async function start() {
  const canvas = /** @type {HTMLCanvasElement} */ (document.getElementById('view'));
  const overlay = new Overlay(/** @type {HTMLElement} */ (document.getElementById('overlay')));
  const stage = /** @type {HTMLElement} */ (document.getElementById('stage'));
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
  if (params.mouse) app.inputs.setMouse(params.mouse, { start: true });
  const ui = installUi(app, { builtinSource });
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
    const standIn = keptWork(app, ui, params.shader, loaded);
    const { warnings } = app.applyControls(params.controls, 'URL');
    avoidHungShader(app, noticeAfterCompile); // after the link's values: a value can be what hung
    showValueNotes(stage, [...params.warnings, ...warnings].map(plainWarning));
    app.compiles.compile({ orElse: standIn?.() }).catch(() => {}); // shown on the page; `ready` rejects
    app.frames.request();
  });
  // A second link opened in this tab that differs only in its fragment loads no page: its
  // #source= is opened here, as a link opened afresh is.
  window.addEventListener('hashchange', async () => {
    const linked = await linkedShader(location.hash);
    if (!linked) return;
    if (linked.notice) noticeAfterCompile(linked.notice);
    app.loadProject(linked.project, linked.from);
    keptWork(app, ui, undefined, linked);
    app.compiles.compile().catch(() => {});
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
    app.setProject(singlePass(module.default)).catch(() => {});
  });
  import.meta.hot.on('glsl-file-changed', async ({ url }) => {
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
  });
}
