// Never come back with the shader that hung. When the watchdog (app/render-client.js) says a shader
// may never finish, the page notes it in localStorage with the last shader that finished a frame.
// If the GPU is then reset (Chrome's GPU watchdog on real hardware: a lost and restored context)
// or the page is reloaded (the way out on SwiftShader, where the endless draw goes on until the
// browser closes), the page runs that last shader instead, and says so; the text that hung is
// kept in the note, to be put back into the editor (not run) when the user asks. A frame of it
// that does finish clears the note: it was only slow. A shader whose first draw is still
// compiling (SwiftShader compiles on it: render-client.js) is noted too, as compiling: a reload
// in the middle of a long compile says so, and offers to run it anyway.

const KEY = 'shadertoy-runner.hung';

/** @typedef {import('../app/app.js').ShaderVersion} ShaderVersion */
/** @typedef {{key: string, name: string, project: import('../../shadertoy/multipass.js').MultipassShader, version?: ShaderVersion, back: ShaderVersion | null, phase?: import('../app/render-client.js').HangPhase, seconds?: number}} HangNote */

/**
 * A short fingerprint of a shader's tabs and control values (FNV-1a, 32 bits, over their JSON):
 * the note names what hung without keeping whole texts to compare. The values count: a control
 * can make a shader hang (a loop bound).
 * @param {import('../../shadertoy/multipass.js').MultipassShader} project
 * @param {Record<string, any>} [values]
 */
export function projectKey(project, values = {}) {
  const text = JSON.stringify([project, values]);
  let hash = 0x811c9dc5;
  for (let i = 0; i < text.length; i++) hash = Math.imul(hash ^ text.charCodeAt(i), 0x01000193) >>> 0;
  return `${hash.toString(16)}-${text.length}`;
}

export class HangGuard {
  /** @param {Storage | null} [storage] */
  constructor(storage = globalThis.localStorage ?? null) {
    this.storage = storage;
  }

  /** @returns {HangNote | null} */
  get note() {
    try {
      return JSON.parse(this.storage?.getItem(KEY) ?? 'null');
    } catch {
      return null;
    }
  }

  /**
   * The shader that is drawing now may never finish.
   * @param {ShaderVersion} hung
   * @param {ShaderVersion | null} last the last shader that finished a frame
   * @param {{phase?: import('../app/render-client.js').HangPhase, seconds?: number}} [how] still compiling, or drawing; for how long
   */
  record(hung, last, { phase = 'drawing', seconds } = {}) {
    const key = projectKey(hung.project, hung.values);
    const back = last && projectKey(last.project, last.values) !== key ? last : null;
    /** @type {HangNote} */
    const note = { key, name: hung.name, project: hung.project, version: hung, back, phase, seconds };
    try {
      this.storage?.setItem(KEY, JSON.stringify(note));
    } catch {
      // storage full or refused: the watchdog's message still stands
    }
  }

  clear() {
    this.storage?.removeItem(KEY);
  }

  /**
   * What to run instead of `project` when it is the one that hung: the last shader that finished
   * a frame before it (null: run it; nothing better is known).
   * @param {import('../../shadertoy/multipass.js').MultipassShader} project
   * @param {Record<string, any>} values
   * @returns {ShaderVersion | null}
   */
  backFor(project, values) {
    const note = this.note;
    return note && note.back && note.key === projectKey(project, values) ? note.back : null;
  }
}

/**
 * Watches an app: notes a hang, clears the note when a frame finishes after all.
 * @param {import('../app/app.js').ShaderApp} app
 * @param {HangGuard} guard
 */
export function watchHangs(app, guard) {
  app.setHangGuard(guard);
  app.on('hang', (_, seconds, phase) => {
    if (seconds !== null) guard.record(app.version(), app.frames.lastFinished, { phase, seconds });
  });
  app.on('drawn', () => {
    const drawn = app.frames.lastFinished; // the shader this frame was drawn with
    if (drawn && guard.note?.key === projectKey(drawn.project, drawn.values)) guard.clear();
  });
}
