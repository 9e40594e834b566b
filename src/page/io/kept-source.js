// Work is never lost, and an edited shader has a name of its own.
//
// While the editor's text differs from the file the page loads on a reload (the ?shader= file or
// the built-in raytracer), it is kept in the browser's localStorage under that file's name; on
// the next load the page restores it, says so in a note with a "Discard" button that goes back
// to the file. The kept text carries its name: the file it came from marked as edited
// ("raytrace.glsl (edited)"), or "untitled" after a paste that replaced the whole text.

import { editedName } from './file-names.js';

const PREFIX = 'shadertoy-runner.source:';

/** @typedef {{name: string, source: string}} NamedSource */

/**
 * The storage key of a shader a link carries in itself (#source=): its name and a hash of its
 * text (FNV-1a, 32 bits), so that each shared shader keeps its own edits.
 * @param {NamedSource} shared
 */
export function sharedKey({ name, source }) {
  let hash = 0x811c9dc5;
  for (let i = 0; i < source.length; i++) hash = Math.imul(hash ^ source.charCodeAt(i), 0x01000193) >>> 0;
  return `#${name}@${hash.toString(16).padStart(8, '0')}`;
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
    try {
      const kept = JSON.parse(this.storage?.getItem(this.key) ?? 'null');
      if (kept && typeof kept.source === 'string' && kept.source !== file.source) {
        const name = typeof kept.name === 'string' ? kept.name : editedName(file.name);
        this.pasted = name === 'untitled';
        return { source: kept.source, name };
      }
    } catch (error) {
      console.warn(`Kept shader source unreadable, ignored: ${error.message}`);
    }
    return null;
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
   */
  save(text) {
    if (!this.key || !this.storage) return;
    try {
      if (this.pageFile && text === this.pageFile.source) this.storage.removeItem(this.key);
      else this.storage.setItem(this.key, JSON.stringify({ name: this.nameFor(text), source: text }));
    } catch (error) {
      console.warn(`Could not keep the shader source in the browser's storage: ${error.message}`);
    }
  }
}
