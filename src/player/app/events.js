// The app's events (app.js), and the small typed emitter that sends them: the app's way of
// telling the page what happened without touching the page (the page's widgets, ui/, and the
// hook, hook/, listen). The render client (render-client.js) sends its own events with it.

/**
 * A frame the app drew and showed.
 * @typedef {object} DrawnEvent
 * @property {Uint8Array | null} pixels RGBA8, rows top to bottom, when it was asked for (FrameLoop.readBackNextFrame)
 * @property {number} width
 * @property {number} height
 * @property {number} frame its iFrame
 * @property {number | null} interval ms since the frame before, on the page's clock, while frames
 *   follow one another (playing, or converging); null for a frame on its own
 * @property {number[]} gpuTimes GPU times (ms) that came in with it (gpu/gpu-timer.js; empty
 *   where the browser does not measure them)
 */

/**
 * Something the page should tell a person about the view it opened, once its shader has compiled
 * (open-view.js): its title, its text, and what the person can do about it.
 * @typedef {{title: string, detail: string, actions?: Array<{label: string, run: () => void}>}} Notice
 */

/**
 * The app's events, and what each passes its listeners after the app itself.
 * @typedef {object} AppEvents
 * @property {[]} state the play state, time, speed, size settings, controls or channels changed
 * @property {[frame: DrawnEvent]} drawn a frame was drawn and shown
 * @property {[error: (Error & {report?: string, messages?: Array<{severity: string, line: number | null, message: string}>}) | null, fileName: string]} compile the latest compile ended: null on
 *   success, else its error (app.compiles.hasProgram tells whether an older shader still runs)
 * @property {[]} source a new source was loaded (its controls read)
 * @property {[]} notes what the shader goes without changed (its media came, or could not)
 * @property {[lines: string[]]} values the values of the view last opened that were not used as
 *   given (a link's or the hook's: a control clamped into range), each line what was used instead
 * @property {[notice: Notice]} notice a notice on the view being opened (open-view.js: the shader
 *   asked for could not be had, or hung last time, and another runs in its place), to be shown
 *   once the next compile succeeds
 * @property {[text: string]} say a one-line message for a person (a channel that could not load)
 * @property {[lost: boolean]} context the GPU context was lost (true) or restored (false)
 * @property {[seconds: number | null, phase?: import('./render-client.js').HangPhase]} hang a frame has gone that long without finishing a band
 *   ('compiling': a program's first draw, which compiles it on SwiftShader)
 *   (render-client.js's watchdog); null when drawing goes on again
 */

/**
 * @template {Record<string, unknown[]>} E each event's name and the arguments its listeners get
 */
export class Emitter {
  constructor() {
    /** @type {{[K in keyof E]?: Array<(emitter: this, ...args: E[K]) => void>}} */
    this._listeners = {};
  }

  /**
   * @template {keyof E} K
   * @param {K} event
   * @param {(emitter: this, ...args: E[K]) => void} listener
   */
  on(event, listener) {
    (this._listeners[event] ??= []).push(listener);
  }

  /**
   * Calls `listener` on the event's next emission only.
   * @template {keyof E} K
   * @param {K} event
   * @param {(emitter: this, ...args: E[K]) => void} listener
   */
  once(event, listener) {
    /** @type {(emitter: this, ...args: E[K]) => void} */
    const once = (...args) => {
      const list = this._listeners[event] ?? [];
      list.splice(list.indexOf(once), 1);
      listener(...args);
    };
    this.on(event, once);
  }

  /**
   * Calls the event's listeners now, in the order they were added.
   * @template {keyof E} K
   * @param {K} event
   * @param {E[K]} args
   */
  emit(event, ...args) {
    for (const listener of [...(this._listeners[event] ?? [])]) listener(this, ...args);
  }
}
