// Work is never lost: the one owner of the policy of kept edits. What the editor's text is
// called ("NAME (edited)", "untitled" after a paste over everything), when it is kept (what the
// user typed and a shader they made; not a file the page loaded in its place), what a reload
// restores (with a note that can discard it, and says while the edits do not compile) and what
// a link opened afresh does with edits of its shader (sets them aside and offers them, never runs
// them in its place), and which shipped file the editor's text is an edit of (for a short link).
// The storage itself, its keys and slots, is io/kept-source.js's; the notes' words are
// ui/notices.js's.

import { KeptSource, sharedKey } from '../player/io/kept-source.js';
import { deserializeProject, serializeProject } from '../player/io/project-files.js';
import { BUILTIN_BASE } from '../player/io/share-link.js';
import { sayOnNote, showKeptOffer, showRestoredNote } from './ui/notices.js';

/** @typedef {import('../player/app/app.js').ShaderApp} ShaderApp */
/** @typedef {import('../player/app/app.js').ShaderVersion} ShaderVersion */
/** @typedef {import('../shadertoy/multipass.js').MultipassShader} MultipassShader */
/** @typedef {import('../player/io/kept-source.js').NamedSource} NamedSource */

/** Whether this load is the same page again (a reload, back or forward), not a link opened afresh. */
function reopened() {
  const navigation = /** @type {PerformanceNavigationTiming | undefined} */ (performance.getEntriesByType?.('navigation')[0]);
  return navigation?.type === 'reload' || navigation?.type === 'back_forward';
}

export class KeptWork {
  /**
   * @param {ShaderApp} app
   * @param {string} builtinSource the built-in raytracer's text (a link to an edit of it says so)
   * @param {KeptSource} [store] where the edits are kept (the browser's localStorage)
   */
  constructor(app, builtinSource, store = new KeptSource()) {
    this.app = app;
    this.builtinSource = builtinSource;
    this.store = store;
    // a file the page loaded (not the editor's text): edits from now on derive from it
    app.on('source', () => {
      if (app.origin !== 'editor') this.store.loadedFile({ name: app.fileName, source: serializeProject(app.project) });
    });
  }

  /**
   * The name of the editor's text: "untitled" after a paste over everything, else "NAME (edited)".
   * @param {MultipassShader} project
   * @param {boolean} [pasted]
   */
  nameFor(project, pasted = false) {
    return this.store.nameFor(serializeProject(project), pasted);
  }

  /**
   * A shader pasted in by its own name (a Shadertoy export): edits from now on derive from it.
   * @param {string} name
   * @param {MultipassShader} project
   */
  loadedFile(name, project) {
    this.store.loadedFile({ name, source: serializeProject(project) });
  }

  /**
   * The editor's text changed. What the user typed is kept, and a shader they made (pasted,
   * restored); a file the page loaded instead (a dropped one, the one the watchdog went back to)
   * is not theirs to keep, and leaves what is kept alone.
   * @param {MultipassShader} project
   * @param {boolean} typed
   * @param {boolean} [pastedOver] a paste replaced the whole text
   */
  edited(project, typed, pastedOver = false) {
    const text = serializeProject(project);
    if (typed || this.app.origin === 'editor' || text === this.store.pageFile?.source) this.store.save(text, pastedOver);
  }

  /**
   * The file the page ships that the editor's text is an edit of (the built-in raytracer, or the
   * ?shader= file), or null (a paste, a dropped file, a link's own shader).
   * @returns {{base: string, source: string} | null}
   */
  shippedBase() {
    const { app, store } = this;
    const base = store.base;
    if (!base || store.pasted || app.origin !== 'editor') return null;
    if (app.shaderUrl) return base === store.pageFile ? { base: app.shaderUrl, source: base.source } : null;
    return base.source === this.builtinSource ? { base: BUILTIN_BASE, source: this.builtinSource } : null;
  }

  /**
   * The page's shader is loaded (the ?shader= file, the built-in one, or the shader a link
   * carries): edits kept for it, every tab of a multipass one, come back on a reload, with a note
   * that can discard them. A link opened afresh runs what it names: kept edits of that shader are
   * set aside and offered, never run in its place.
   * @param {string} pageKey the file's URL or name as the page was given it (a link's own shader
   *   is kept by its name and text instead)
   * @param {{project: MultipassShader, from: {name: string, origin: ShaderApp['origin'], info?: object | null}}} first what the page loaded
   * @returns {(() => ShaderVersion) | null} edits restored: the file, to run while they do not compile
   */
  open(pageKey, { project, from }) {
    const { app, store } = this;
    const stage = /** @type {HTMLElement} */ (document.getElementById('stage'));
    const file = { name: from.name, source: serializeProject(project) };
    const own = app.version(); // the file as it is, before any edit of it
    const kept = store.open(from.origin === 'editor' ? sharedKey(file) : pageKey, file);
    /** @param {NamedSource} edits */
    const load = (edits) =>
      app.loadProject(deserializeProject(edits.source), { name: edits.name, origin: 'editor', info: from.info ?? null });
    if (kept && reopened()) {
      load(kept);
      const note = showRestoredNote(stage, kept.name, () => app.setProject(project, from).catch(() => {}));
      // the note belongs to the text it restored: once that is edited or replaced, Discard would
      // throw away what it did not restore
      const stale = (/** @type {string} */ text) => text !== kept.source && note.remove();
      store.watch(stale);
      app.on('source', () => stale(serializeProject(app.project)));
      // edits that do not compile (kept mid-work): the file runs until they do, and the note says so
      app.on('compile', () => {
        const standing = app.compiles.running?.load === own.load;
        sayOnNote(note, standing ? `They do not compile yet: the picture is ${from.name} as the file has it, until they do.` : null);
      });
      // with the values the page runs (a link's): those of the file's controls
      return () => ({
        ...own,
        values: Object.fromEntries(Object.keys(own.values ?? {}).flatMap((name) => (name in app.values ? [[name, app.values[name]]] : []))),
      });
    }
    if (kept) store.setAside();
    const earlier = store.earlier();
    if (!earlier) return null;
    showKeptOffer(stage, earlier.name, {
      open: () => {
        store.forgetEarlier();
        load(earlier);
        app.compiles.compile().catch(() => {});
      },
      discard: () => store.forgetEarlier(),
    });
    return null;
  }
}
