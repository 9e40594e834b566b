// Work is never lost, and an edited shader has a name of its own.
//
// While the editor's text differs from the file the page loads on a reload (the ?shader= file or
// the page's built-in shader), it is kept in the browser's localStorage under that file's name; a
// reload restores it, with a note whose "Discard" goes back to the file. A link opened afresh
// opens what it names: edits kept for that file are set aside (a slot of their own, so that new
// edits do not overwrite them) and offered, never run in its place. The kept text carries its
// name: the file it came from marked as edited ("scene.glsl (edited)"), or "untitled" after a
// paste that replaced the whole text.

import { editedName } from './file-names.js';

const PREFIX = 'shadertoy-runner.source:';
/** The slot of edits set aside by a link that named their file (after the file's own key). */
const EARLIER = ' (earlier)';

/** @typedef {{name: string, source: string}} NamedSource */

/**
 * The storage key of a shader a link carries in itself (#source=): its name and a hash of its
 * text, so that each shared shader keeps its own edits.
 * @param {NamedSource} shared
 */
export function sharedKey({ name, source }) {
  return `#${name}@${textHash(source)}`;
}

/**
 * A text's FNV-1a hash (32 bits) in 8 hex digits: which version of a file a kept edit or a
 * link's patch was made from. Not a safeguard against tampering, only against another version.
 * @param {string} text
 */
export function textHash(text) {
  let hash = 0x811c9dc5;
  for (let i = 0; i < text.length; i++) hash = Math.imul(hash ^ text.charCodeAt(i), 0x01000193) >>> 0;
  return hash.toString(16).padStart(8, '0');
}

export class KeptSource {
  /** @param {Storage | null} [storage] */
  constructor(storage = KeptSource.localStorage()) {
    this.storage = storage;
    /** The storage key of the page's file, once it is loaded. @type {string | null} */
    this.key = null;
    /** What a reload loads. @type {NamedSource | null} */
    this.pageFile = null;
    /** The file the editor's text derives from (the page's file or a dropped one). @type {NamedSource | null} */
    this.base = null;
    /** Whether a paste replaced the whole text since that file was loaded. */
    this.pasted = false;
    /** @type {Array<(text: string) => void>} */
    this._watchers = [];
  }

  /** @returns {Storage | null} */
  static localStorage() {
    try {
      return window.localStorage;
    } catch {
      return null; // storage disabled: nothing is kept
    }
  }

  /**
   * The page's file is loaded: returns the text kept for it, if any (and different from it).
   * @param {string} key the file's URL or name, as the page was given it
   * @param {NamedSource} file
   * @returns {NamedSource | null}
   */
  open(key, file) {
    this.key = PREFIX + key;
    this.pageFile = file;
    this.loadedFile(file);
    const kept = this._read(this.key);
    if (!kept || kept.source === file.source) return null;
    this.pasted = kept.name === 'untitled';
    return kept;
  }

  /** @param {string} key @returns {NamedSource | null} */
  _read(key) {
    try {
      const kept = JSON.parse(this.storage?.getItem(key) ?? 'null');
      if (!kept || typeof kept.source !== 'string') return null;
      return { source: kept.source, name: typeof kept.name === 'string' ? kept.name : editedName(this.pageFile?.name ?? 'shader') };
    } catch (error) {
      console.warn(`Kept shader source unreadable, ignored: ${error.message}`);
      return null;
    }
  }

  /** @param {string} key @param {NamedSource | null} value */
  _write(key, value) {
    try {
      if (value) this.storage?.setItem(key, JSON.stringify(value));
      else this.storage?.removeItem(key);
    } catch (error) {
      console.warn(`Could not keep the shader source in the browser's storage: ${error.message}`);
    }
  }

  /** The page opened its file, not the edits kept for it: they move to a slot of their own. */
  setAside() {
    if (!this.key) return;
    const kept = this._read(this.key);
    if (kept) this._write(this.key + EARLIER, kept);
    this._write(this.key, null);
    this.pasted = false;
  }

  /** The edits a link set aside, if any (and different from the page's file). @returns {NamedSource | null} */
  earlier() {
    const earlier = this.key ? this._read(this.key + EARLIER) : null;
    return earlier && earlier.source !== this.pageFile?.source ? earlier : null;
  }

  /** The edits set aside are taken back into the editor, or thrown away: their slot is emptied. */
  forgetEarlier() {
    if (this.key) this._write(this.key + EARLIER, null);
  }

  /**
   * A file was loaded (the page's, a dropped one, ...): edits from now on derive from it.
   * @param {NamedSource} file
   */
  loadedFile(file) {
    this.base = file;
    this.pasted = false;
  }

  /**
   * The name of the editor's text.
   * @param {string} text
   * @param {boolean} [pasted] a paste replaced the whole text
   */
  nameFor(text, pasted = false) {
    if (pasted) this.pasted = true;
    if (this.base && text === this.base.source) return this.base.name;
    return this.pasted || !this.base ? 'untitled' : editedName(this.base.name);
  }

  /**
   * Keeps the editor's text while it differs from the page's file (forgets it otherwise).
   * @param {string} text
   * @param {boolean} [pasted] a paste replaced the whole text (it is "untitled" from now on)
   */
  save(text, pasted = false) {
    if (!this.key) return;
    this._write(this.key, this.pageFile && text === this.pageFile.source ? null : { name: this.nameFor(text, pasted), source: text });
    for (const watch of this._watchers) watch(text);
  }

  /** Calls `onSave(text)` after every save (the restored note goes once its text is edited). @param {(text: string) => void} onSave */
  watch(onSave) {
    this._watchers.push(onSave);
  }
}
