// The page opened at a URL's view: the shader (the one a link carries in its #source=, the
// ?shader= file, or the page's built-in shader), its controls, size, clock, mouse and channels,
// the edits kept for it (the interactive page's kept-work.js, given as `keep`), and the notes on
// what it could not have. Both pages' own loads (main.js, engine-main.js) and
// window.shaderEngine.open() (hook/engine-hook.js) go through openView, so that a page put in a
// state by open() is the page a fresh load of that URL gives (tests/browser/page-open.test.js holds the
// two pixel-identical).
//
// It shows nothing itself: what a person should be told comes out as the app's events, as data
// ('values': the values not used as given; 'notice': a notice to show once the shader compiles;
// 'say': a one-line message), which the interactive page shows (main.js) and the engine's hook
// gives back (hook/engine-state.js notes()).

import { fetchShader, shaderName } from './io/shader-loader.js';
import { BUILTIN_BASE, sourceFromHash } from './io/share-link.js';
import { readShader } from './io/open-shader.js';
import { CHANNEL_PARAMS } from '../shared/url-params.js';
import { singlePass } from '../shadertoy/multipass.js';

/** @typedef {import('./app/app.js').ShaderApp} ShaderApp */
/** @typedef {import('./io/hang-guard.js').HangGuard} HangGuard */
/** @typedef {ReturnType<typeof import('../shared/url-params.js').parseUrlParams>} UrlParams */
/** @typedef {import('./app/events.js').Notice} Notice */
/** @typedef {import('./app/app.js').ShaderVersion} ShaderVersion */
/**
 * @typedef {object} FirstSource the shader the page opens with
 * @property {import('../shadertoy/multipass.js').MultipassShader} project
 * @property {{name: string, origin: ShaderApp['origin'], url?: string | null, info?: object | null}} from
 * @property {Notice} [notice]
 */
/**
 * The interactive page's kept work (kept-work.js KeptWork.open): given the page's key and the
 * shader it opens with, what the first compile falls back on (its kept edits), or null.
 * @typedef {(pageKey: string, first: FirstSource) => (() => ShaderVersion) | null} KeepWork
 */

/**
 * The page's built-in shader: what it runs with no ?shader= and no #source=, and in place of one
 * that cannot be had on its own load. The studio gives its own (src/studio/main.js, which
 * imports its text `?raw` and accepts its hot updates under `npm run dev`: a second importer
 * that does not would make Vite reload the whole page instead); the engine page's is a black
 * start shader (engine-main.js), so that it never loads the studio's.
 * @typedef {{name: string, text: string, what: string}} BuiltinShader name: its file name; what:
 *   how a notice names it ("the built-in shader")
 */
/** @type {BuiltinShader} */
let builtinShader = { name: 'builtin.glsl', text: '', what: 'the built-in shader' };
/** @param {BuiltinShader} shader the page's built-in shader (at start, and after a hot update) */
export function useBuiltinShader(shader) {
  builtinShader = shader;
}
/** The page's built-in shader's file name. */
export const builtinName = () => builtinShader.name;

/**
 * The built-in shader, with a notice when the page was asked for another shader (and then
 * `failed`: why that shader could not be had, in one line).
 * @param {Notice} [notice]
 * @returns {FirstSource & {failed?: string}}
 */
const builtin = (notice) => ({
  project: singlePass(builtinShader.text),
  from: { name: builtinShader.name, origin: 'builtin' },
  notice,
  ...(notice ? { failed: `${notice.title}: ${notice.detail.split('\n')[0]}` } : {}),
});

/**
 * The shader a link carries in its fragment (#source=), or the built-in shader with a notice
 * when it cannot be read; null when the fragment holds none.
 * @param {string} hash
 * @returns {Promise<FirstSource | null>}
 */
export async function linkedShader(hash) {
  try {
    // a patch link's base: the built-in shader, or a file the page serves
    const baseText = async (/** @type {string} */ base) => (base === BUILTIN_BASE ? builtinShader.text : fetchShader(base));
    const shared = await sourceFromHash(hash, baseText);
    if (!shared) return null;
    const { project, from } = readShader(shared.source, { name: shared.name, origin: 'editor' });
    const notice = shared.note ? { title: `${shared.name}: made against another version of its file`, detail: shared.note } : undefined;
    return { project, from: { ...from, name: shared.name }, notice };
  } catch (error) {
    console.warn(`The shader in the link's #source= could not be read: ${error.message}`);
    return builtin({
      title: 'Could not read the shader in this link',
      detail: `${error.message.startsWith('its ') ? `The link's ${error.message.slice(4)}` : `The link's shader: ${error.message}`}.\n${instead()}`,
    });
  }
}

/**
 * The first shader: the one a link carries (#source=), the ?shader= file, or the built-in
 * shader (also when those cannot be had or read: then with a notice that says so). A text
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
    return builtin({ title: `Could not load ${url}`, detail: `${why}.\n${instead()}` });
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
      detail: `${error.message}\n${instead()}`,
    });
  }
}

/** What a notice says runs instead. */
const instead = () => `Showing ${builtinShader.what} (${builtinShader.name}) instead.`;

/** A console warning as the page's note says it: without the console's "who says". @param {string} warning */
const plainWarning = (warning) => warning.replace(/^(URL parameter |URL: )/, '');

/**
 * The shader about to run is the one that hung last time (io/hang-guard.js): run the last one that
 * finished a frame instead, say so, and offer the text that hung back to the editor, not run.
 * @param {ShaderApp} app
 */
function avoidHungShader(app) {
  const guard = /** @type {HangGuard} */ (app.hangGuard);
  const back = guard.backFor(app.project, app.values);
  const hung = guard.note;
  if (!back || !hung) return;
  app.runVersion(back, 'the last shader that finished');
  const compiling = hung.phase === 'compiling';
  app.emit('notice', {
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
 * @param {ShaderApp} app
 * @param {ShaderVersion} version
 */
function runAgain(app, version) {
  app.runVersion(version, 'the shader that was compiling');
  app.compiles.compile().catch(() => {}); // shown on the page
}

/**
 * Brings the page to the view `params` (parseUrlParams of a URL) and `hash` describe, as a load
 * of that URL does: on the page's own load with the app just started, or again later
 * (window.shaderEngine.open) with the page as it was left: then what the last view left behind (the
 * controls' values, the clock, the channels) goes first; the interactive page clears its own
 * widgets (the inspector, its notes) itself (main.js). Resolves once the view's first frame is
 * drawn; rejects with the compile error when its shader does not compile. The interactive page's
 * own load runs its built-in shader, with a notice, when the shader asked for cannot be had;
 * `strict` (the engine page's load) and window.shaderEngine.open() (`again`) reject with why
 * instead: a render of the built-in in its place would claim what did not happen.
 * @param {ShaderApp} app
 * @param {UrlParams} params
 * @param {{hash: string, again?: boolean, strict?: boolean, keep?: KeepWork}} options keep: the
 *   interactive page's kept work (none on the engine page)
 * @returns {Promise<void>}
 */
export async function openView(app, params, { hash, again = false, strict = again, keep = () => null }) {
  for (const warning of params.warnings) console.warn(warning);
  const first = initialSource(params, hash); // fetched meanwhile
  if (again) await leaveView(app, params);
  if (params.time !== undefined) app.inputs.setTime(params.time);
  if (params.speed !== undefined) app.inputs.setSpeed(params.speed);
  app.inputs.setSchedule({ date: params.date ?? null, fps: params.fps ?? null }); // none given: real and measured
  if (params.mouse) app.inputs.setMouse(params.mouse, { start: true });
  const channelLoads = params.channels.map((url, i) =>
    url
      ? app.setChannel(i, url).catch((error) => {
          console.warn(`URL parameter ${CHANNEL_PARAMS[i]}=${url} ignored: ${error.message}`);
          app.emit('say', `Could not load ${url} into iChannel${i}`);
          app.emit('notes'); // the page's note says it too (channels.js failures)
        })
      : null,
  );
  const opened = first.then((loaded) => {
    if (strict && 'failed' in loaded && typeof loaded.failed === 'string') throw new Error(loaded.failed);
    if (loaded.notice) app.emit('notice', loaded.notice);
    app.media.setBase(params.media ?? null);
    app.loadProject(loaded.project, loaded.from);
    const standIn = keep(params.shader ?? builtinShader.name, loaded);
    const { warnings } = app.applyControls(params.controls, 'URL');
    avoidHungShader(app); // after the link's values: a value can be what hung
    app.emit('values', [...params.warnings, ...warnings].map(plainWarning));
    return standIn;
  });
  const loading = opened.then(() => {});
  loading.catch(() => {}); // why, if it fails, is openView's to say: it rejects with it
  app.setLoading(loading);
  const standIn = await opened;
  const compiled = app.compiles.compile({ orElse: standIn?.() });
  if (!again) {
    compiled.catch(() => {}); // the page says it; `ready` rejects
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
 * What the app holds from the view before, undone, so that the next view starts as a fresh page
 * would: the clock stopped at 0 with the view's play state, speed, mouse, size and channels, and
 * no control values carried over.
 * @param {ShaderApp} app
 * @param {UrlParams} params
 */
async function leaveView(app, params) {
  app.inputs.pause();
  await app.frames.idle();
  app.inputs.restart();
  if (params.time === undefined) app.inputs.play(); // ?time=T: that instant, paused
  app.inputs.setSpeed(params.speed ?? 1);
  app.inputs.setStartMouse(params.mouse ?? null);
  app.canvasSize.setFixed(params.size ?? null);
  app.canvasSize.setScale(params.scale ?? 1);
  app.canvasSize.setCap(params.cap ?? 0);
  await Promise.all(params.channels.map((url, i) => (url || !app.channels.inUse(i) ? null : app.setChannel(i, null))));
  app.channels.failures.fill(null); // what the view before could not load is not this view's
  app.forgetValues();
}
