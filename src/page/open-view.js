// The page opened at a URL's view: the shader (the one a link carries in its #source=, the
// ?shader= file, or the built-in raytracer), its controls, size, clock, mouse and channels, the
// edits kept for it (kept-work.js), and the notes on what it could not have. The page's own load (main.js) and
// window.raytracer.open() (automation.js) both go through openView, so that a page put in a
// state by open() is the page a fresh load of that URL gives (tests/page-open.test.js holds the
// two pixel-identical).

import { showValueNotes } from './ui/notices.js';
import { fetchShader, shaderName } from './io/shader-loader.js';
import { BUILTIN_BASE, sourceFromHash } from './io/share-link.js';
import { readShader } from './io/open-shader.js';
import { CHANNEL_PARAMS } from '../shared/url-params.js';
import { singlePass } from '../shadertoy/multipass.js';

/** @typedef {import('./app/app.js').RaytracerApp} RaytracerApp */
/** @typedef {import('./io/hang-guard.js').HangGuard} HangGuard */
/**
 * What a view needs of the page's widgets: the interactive page's (ui/ui.js installUi), or the
 * engine page's stand-ins (engine-main.js: no toast, no kept work, no inspector, no panel).
 * @typedef {object} PageUi
 * @property {(text: string) => void} toast
 * @property {{open: (pageKey: string, first: FirstSource) => (() => ShaderVersion) | null}} kept
 * @property {{reset: () => void}} inspection
 * @property {{setView: (view: {scale: number, cap: number, sizeFixed: boolean}) => void}} panel
 */
/** @typedef {ReturnType<typeof import('../shared/url-params.js').parseUrlParams>} UrlParams */

export const BUILTIN_NAME = 'shaders/raytrace.glsl';

/** @typedef {import('./ui/notices.js').Notice} Notice */
/** @typedef {import('./app/app.js').ShaderVersion} ShaderVersion */
/**
 * @typedef {object} FirstSource the shader the page opens with
 * @property {import('../shadertoy/multipass.js').MultipassShader} project
 * @property {{name: string, origin: RaytracerApp['origin'], url?: string | null, info?: object | null}} from
 * @property {Notice} [notice]
 */

/**
 * The built-in raytracer's text, as main.js imports it (`?raw`). Only main.js imports the file: it
 * accepts the file's hot updates under `npm run dev`, and a second importer that does not would
 * make Vite reload the whole page instead.
 */
let builtinSource = '';
/** @param {string} text the built-in raytracer's text (main.js: at start, and after a hot update) */
export function useBuiltinSource(text) {
  builtinSource = text;
}

/**
 * The built-in raytracer, with a notice when the page was asked for another shader (and then
 * `failed`: why that shader could not be had, in one line).
 * @param {Notice} [notice]
 * @returns {FirstSource & {failed?: string}}
 */
const builtin = (notice) => ({
  project: singlePass(builtinSource),
  from: { name: BUILTIN_NAME, origin: 'builtin' },
  notice,
  ...(notice ? { failed: `${notice.title}: ${notice.detail.split('\n')[0]}` } : {}),
});

/**
 * The shader a link carries in its fragment (#source=), or the built-in raytracer with a notice
 * when it cannot be read; null when the fragment holds none.
 * @param {string} hash
 * @returns {Promise<FirstSource | null>}
 */
export async function linkedShader(hash) {
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
 * @param {string} hash the URL's fragment (#source=…)
 * @returns {Promise<FirstSource>}
 */
async function initialSource(params, hash) {
  const linked = await linkedShader(hash);
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

/**
 * Brings the page to the view `params` (parseUrlParams of a URL) and `hash` describe, as a load
 * of that URL does: on the page's own load with the app just started, or again later
 * (window.raytracer.open) with the page as it was left: then what the last view left behind (an
 * inspected pixel, a comparison, notes, the controls' values, the clock, the channels) goes first.
 * Resolves once the view's first frame is drawn; rejects with the compile error when its shader
 * does not compile. A page's own load runs the built-in raytracer, with a note, when the shader
 * asked for cannot be had; window.raytracer.open() (`again`) rejects with why instead: a render
 * of the built-in in its place would claim what did not happen.
 * @param {RaytracerApp} app
 * @param {PageUi} ui
 * @param {UrlParams} params
 * @param {{hash: string, noticeAfterCompile: (notice: Notice) => void, again?: boolean}} options
 * @returns {Promise<void>}
 */
export async function openView(app, ui, params, { hash, noticeAfterCompile, again = false }) {
  const stage = /** @type {HTMLElement} */ (document.getElementById('stage'));
  for (const warning of params.warnings) console.warn(warning);
  const first = initialSource(params, hash); // fetched meanwhile
  if (again) await leaveView(app, ui, params);
  if (params.time !== undefined) app.inputs.setTime(params.time);
  if (params.speed !== undefined) app.inputs.setSpeed(params.speed);
  app.inputs.setSchedule({ date: params.date ?? null, fps: params.fps ?? null }); // none given: real and measured
  if (params.mouse) app.inputs.setMouse(params.mouse, { start: true });
  const channelLoads = params.channels.map((url, i) =>
    url
      ? app.setChannel(i, url).catch((error) => {
          console.warn(`URL parameter ${CHANNEL_PARAMS[i]}=${url} ignored: ${error.message}`);
          ui.toast(`Could not load ${url} into iChannel${i}`);
          app.emit('notes'); // the page's note says it too (channels.js failures)
        })
      : null,
  );
  const opened = first.then((loaded) => {
    if (again && 'failed' in loaded && typeof loaded.failed === 'string') throw new Error(loaded.failed);
    if (loaded.notice) noticeAfterCompile(loaded.notice);
    app.media.setBase(params.media ?? null);
    app.loadProject(loaded.project, loaded.from);
    const standIn = ui.kept.open(params.shader ?? BUILTIN_NAME, loaded); // kept-work.js
    const { warnings } = app.applyControls(params.controls, 'URL');
    avoidHungShader(app, noticeAfterCompile); // after the link's values: a value can be what hung
    const valueLines = [...params.warnings, ...warnings].map(plainWarning);
    app.emit('values', valueLines); // the hook's notes() (automation.js)
    showValueNotes(stage, valueLines);
    return standIn;
  });
  app.setLoading(opened.then(() => {}));
  const standIn = await opened;
  const compiled = app.compiles.compile({ orElse: standIn?.() });
  if (!again) {
    compiled.catch(() => {}); // shown on the page; `ready` rejects
    app.frames.request();
    return app.ready;
  }
  await compiled;
  await Promise.all(channelLoads); // its frame is drawn with its channels, or said without them
  // the view's clock from its start, as on a fresh page: iFrame 0 at the view's iTime, cleared buffers
  await app.frames.idle();
  app.inputs.restart();
  app.gpu.tell('clearBuffers', {});
  app.inputs.setTime(params.time ?? 0);
  await app.frames.draw();
}

/**
 * What the page holds from the view before, undone, so that the next view starts as a fresh
 * page would: the inspector and the comparison off, the notes gone, the clock stopped at 0 with
 * the view's play state, speed, mouse, size and channels, and no control values carried over.
 * @param {RaytracerApp} app
 * @param {PageUi} ui
 * @param {UrlParams} params
 */
async function leaveView(app, ui, params) {
  ui.inspection.reset();
  document.getElementById('notes')?.replaceChildren();
  app.inputs.pause();
  await app.frames.idle();
  app.inputs.restart();
  if (params.time === undefined) app.inputs.play(); // ?time=T: that instant, paused
  app.inputs.setSpeed(params.speed ?? 1);
  app.inputs.setStartMouse(params.mouse ?? null);
  app.canvasSize.setFixed(params.size ?? null);
  app.canvasSize.setScale(params.scale ?? 1);
  app.canvasSize.setCap(params.cap ?? 0);
  ui.panel.setView({ scale: app.canvasSize.scale, cap: app.canvasSize.cap, sizeFixed: Boolean(app.canvasSize.fixed) });
  await Promise.all(params.channels.map((url, i) => (url || !app.channels.inUse(i) ? null : app.setChannel(i, null))));
  app.channels.failures.fill(null); // what the view before could not load is not this view's
  app.forgetValues();
}
