// What the page says, in one place: the notes at the top of the canvas that block nothing (what
// a loaded shader cannot have, a file that could not be read, kept work restored), and the
// messages in the overlay (ui/overlay.js) about what the app reports: compile errors, a lost
// context, a frame that may never finish, a page that could not start. What the tests read of
// the same states (data-error, data-hung, ...) is the hook's: page-marks.js.

import { sayOnce } from '../../shared/said-once.js';
import { formatCompileMessages } from '../../shadertoy/pass-errors.js';
import { goBack } from '../../player/app/gpu-context.js';
import { element } from './dom.js';
import { VALUE_NOTES_TITLE, watchdogDetail, watchdogTitle } from '../../player/words.js';

/** @typedef {import('../../player/app/app.js').ShaderApp} ShaderApp */
/** @typedef {import('./overlay.js').Overlay} Overlay */
/** @typedef {import('../../player/app/events.js').Notice} Notice */

/**
 * The toast after a channel got what was chosen for it.
 * @param {number} index
 * @param {string | File | null} source a file, 'webcam:' or 'mic:', or null (emptied)
 */
export function channelLoaded(index, source) {
  if (source === null) return `Emptied iChannel${index}`;
  if (source === 'webcam:') return `The webcam is in iChannel${index}`;
  if (source === 'mic:') return `The microphone is in iChannel${index}`;
  return `Loaded ${typeof source === 'string' ? source : source.name} into iChannel${index}`;
}

// ---- notes on the canvas ---------------------------------------------------------------------

const NOTE_ID = 'load-notes';

/** A "✕" that closes `note`. @param {HTMLElement} note @param {string} label */
function closeButton(note, label) {
  const close = element('button', { type: 'button', 'aria-label': label }, '✕');
  close.addEventListener('click', () => note.remove());
  return close;
}

/**
 * The notes, at the top right of the stage under the toast (index.html's #messages, one column:
 * they stack, none over another); made on first use where the page has no such column.
 * @param {HTMLElement} stage
 */
function notesColumn(stage) {
  let column = document.getElementById('notes');
  if (!column) {
    column = element('div', { id: 'notes' });
    (document.getElementById('messages') ?? stage).append(column);
  }
  return column;
}

/**
 * Shows a note at the top right of the canvas (replacing the one with its id), or removes it
 * when `lines` is empty.
 * @param {HTMLElement} stage
 * @param {string} id
 * @param {string} title
 * @param {string[]} lines one a line
 * @param {'note' | 'error'} [kind] an error is marked as one
 * @returns {HTMLElement | null}
 */
function showNote(stage, id, title, lines, kind = 'note') {
  document.getElementById(id)?.remove();
  if (!lines.length) return null;
  const note = element('div', { id, class: kind, role: 'status' });
  const list = element('ul', {}, ...lines.map((line) => element('li', {}, line)));
  note.append(element('strong', {}, title), closeButton(note, 'Close this note'), list);
  notesColumn(stage).append(note);
  return note;
}

/**
 * The note on a loaded shader: what it cannot have (media its JSON names), each thing once
 * (sayOnce), or why a file could not be read as a shader (`kind` 'error'). (The command line
 * reads the lines one by one, as data: the hook's notes().)
 * @param {HTMLElement} stage
 * @param {string} title
 * @param {string[]} lines
 * @param {'note' | 'error'} [kind]
 */
export const showLoadNotes = (stage, title, lines, kind = 'note') => showNote(stage, NOTE_ID, title, sayOnce(lines), kind);

/**
 * The note that a Sound tab waits for the person (browsers start no sound before a click or a
 * key on the page), shown while `waiting`.
 * @param {HTMLElement} stage
 * @param {boolean} waiting
 */
export const soundNote = (stage, waiting) =>
  showNote(
    stage,
    'sound-note',
    'This shader has a Sound tab',
    waiting ? ['It plays once you click or press a key on the page: browsers start no sound before.'] : [],
  );

/**
 * The note on what the page did with values it could not use as given (a link's, the panel's or
 * the hook's are checked alike): each line says what was used instead, and why.
 * @param {HTMLElement} stage
 * @param {string[]} lines
 */
export const showValueNotes = (stage, lines) => showNote(stage, 'value-notes', VALUE_NOTES_TITLE, lines);

/**
 * A note about kept work, with its buttons, replacing any other: the first of the notes.
 * @param {HTMLElement} parent
 * @param {string} id
 * @param {string} text
 * @param {Array<{label: string, title: string, run: () => void}>} actions each closes the note
 * @param {string} closeLabel
 */
function keptWorkNote(parent, id, text, actions, closeLabel) {
  for (const old of ['restored-note', 'kept-offer']) document.getElementById(old)?.remove();
  const note = element('div', { id, class: 'kept-note', role: 'status' }, element('span', {}, text));
  for (const { label, title, run } of actions) {
    const button = element('button', { type: 'button', title }, label);
    button.addEventListener('click', () => {
      note.remove();
      run();
    });
    note.append(button);
  }
  note.append(closeButton(note, closeLabel));
  // first in the one column of notes: notes stack, none lies over another's buttons
  notesColumn(parent).prepend(note);
  return note;
}

/**
 * The note that says the page restored kept work, with a button that discards it. It belongs
 * to the text it restored: the page removes it once that text is edited or replaced.
 * @param {HTMLElement} parent
 * @param {string} name the restored shader's name
 * @param {() => void} discard goes back to the file
 * @returns {HTMLElement}
 */
export function showRestoredNote(parent, name, discard) {
  const discardEdits = { label: 'Discard edits', title: 'Go back to the file', run: discard };
  return keptWorkNote(
    parent,
    'restored-note',
    `Restored ${name} from this browser's storage (your last edits).`,
    [discardEdits],
    'Keep edits and close this note',
  );
}

/**
 * Says a second line on a kept-work note (null: takes it away).
 * @param {HTMLElement} note
 * @param {string | null} text
 */
export function sayOnNote(note, text) {
  note.querySelector('.note-more')?.remove();
  if (text) note.querySelector('span')?.after(element('small', { class: 'note-more' }, text));
}

/**
 * The note that offers edits a link's shader has in this browser: the link runs what it names,
 * and the edits wait, set aside, until opened or thrown away.
 * @param {HTMLElement} parent
 * @param {string} name the kept edits' name
 * @param {{open: () => void, discard: () => void}} choices
 * @returns {HTMLElement}
 */
export function showKeptOffer(parent, name, { open, discard }) {
  return keptWorkNote(
    parent,
    'kept-offer',
    `This link runs the shader it names. Your edits of it are kept in this browser: ${name}.`,
    [
      { label: 'Open my edits', title: 'Run the edits instead (the shader of the link stays a reload away)', run: open },
      { label: 'Discard them', title: 'Throw the kept edits away', run: discard },
    ],
    'Keep them for later and close this note',
  );
}

/**
 * The line at the bottom of the canvas that says why a debug view shows nothing, while it
 * applies: `viewNote` says it for the shader's controls and values (the raytracer's "Extra
 * samples" view with nothing to mark: src/raytracer/extra-samples.js extraSamplesViewNote, which
 * main.js gives), or null.
 * @param {ShaderApp} app
 * @param {HTMLElement} stage
 * @param {(controls: ShaderApp['controls'], values: ShaderApp['values']) => string | null} viewNote
 */
export function installViewNote(app, stage, viewNote) {
  const note = element('p', { class: 'view-note', role: 'status', hidden: true });
  stage.append(note);
  const update = () => {
    const text = viewNote(app.controls, app.values);
    note.hidden = text === null;
    if (text !== null && note.textContent !== text) note.textContent = text;
  };
  app.on('state', update);
  app.on('source', update);
  update();
  return note;
}

// ---- messages in the overlay ----------------------------------------------------------------

/**
 * A compile message as the error box shows it: "Buffer A:12: error: ..." for a tab of a
 * multipass shader, "NAME:12: error: ..." for a single-pass one; the line's text under it.
 * @param {ShaderApp} app
 * @param {string} fileName
 */
function messageFormatter(app, fileName) {
  const project = app.project;
  return (/** @type {{severity: string, pass?: string | null, line: number | null, message: string}} */ m) =>
    formatCompileMessages([m], project, fileName);
}

/**
 * The page could not start (no WebGL2, most likely): say so on the page, not in a blank one.
 * @param {Overlay} overlay
 * @param {Error} error
 */
export function showStartupFailure(overlay, error) {
  const noWebGL2 = error.name === 'WebGL2UnavailableError';
  overlay.show(noWebGL2 ? 'WebGL2 is not available' : 'The raytracer could not start', error.message);
}

/**
 * Shows what the app reports: compile errors, an unreadable control block and a lost context in
 * the overlay.
 * @param {ShaderApp} app
 * @param {Overlay} overlay
 * @returns {(notice: Notice) => void} shows a notice once the next compile succeeds (instead of
 *   hiding the overlay)
 */
export function showAppOnPage(app, overlay) {
  /** @type {Notice | null} */
  let pending = null;
  app.on('compile', (_, error, fileName) => {
    if (error) {
      const fallback = app.compiles.hasProgram ? ' (still showing the last version that compiled)' : '';
      const title = `${fileName} did not compile${fallback}`;
      if (error.messages?.length) overlay.showMessages(title, error.messages, messageFormatter(app, fileName));
      else overlay.show(title, error.report ?? error.message);
      return;
    }
    if (app.notice) overlay.show(`Control block of ${fileName} not read`, app.notice);
    else if (pending) overlay.showActions(pending.title, pending.detail, pending.actions ?? []);
    else overlay.hide();
    pending = null;
  });
  app.on('context', (_, lost) => {
    if (!lost) return;
    overlay.show(
      'The GPU context was lost',
      'The browser took the graphics context away (a driver reset, or too many pages using the GPU). The picture comes back when the browser restores it.',
    );
  });
  showWatchdog(app, overlay);
  return (notice) => (pending = notice);
}

/**
 * The watchdog's message (render-client.js): a frame that has gone seconds without progress may
 * never finish; a program's first draw that takes long is still compiling, which SwiftShader
 * does on that draw. Either offers to go back to the last shader that finished a frame; it goes
 * away by itself when the drawing goes on.
 * @param {ShaderApp} app
 * @param {Overlay} overlay
 */
function showWatchdog(app, overlay) {
  /** The phase whose message shows (null: none). @type {string | null} */
  let shown = null;
  app.on('hang', (_, seconds, phase = 'drawing') => {
    if (seconds === null) {
      if (shown) overlay.hide();
      shown = null;
      return;
    }
    const back = app.frames.lastFinished;
    const detail = watchdogDetail(app.fileName, Math.floor(seconds), phase, back?.name ?? null);
    // the same phase: only the seconds move (the buttons, and a focus on one, stay)
    if (shown === phase) return overlay.setDetail(detail);
    shown = phase;
    const label = back ? goBackLabel(back.name, app.fileName) : '';
    const actions = back
      ? [
          {
            label,
            run: () => {
              overlay.show(`Going back to ${back.name}…`, 'Starting the renderer again.');
              goBack(app).catch((error) => {
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
    overlay.showActions(watchdogTitle(app.fileName, phase), detail, actions);
  });
}

/**
 * "Go back to NAME", or, when the shader on the GPU goes by the same name (two pastes are both
 * "untitled"), "Go back to the previous NAME", so that the two can be told apart.
 * @param {string} back the last shader that finished a frame
 * @param {string} current the shader that may never finish
 */
const goBackLabel = (back, current) => (back === current ? `Go back to the previous ${back}` : `Go back to ${back}`);
