// The page's keys: its shortcuts (Space plays and pauses, R restarts, F toggles fullscreen) and
// the shader's keys (Shadertoy's keyboard texture, keyboard.js, for shaders that read it). One
// test decides whether a key is the user typing into a widget, for both: a key typed into the
// editor, a text field or a drop-down, or a key a focused slider moves on, is the widget's; any
// other key is the page's (a shortcut) and the shader's.
//
// Shortcuts work whatever toolbar button has focus: a focused button would otherwise take Space
// (and Enter) as a click of its own, so that Space after clicking "Screenshot" saved a second PNG.

import { keyCodeOf } from '../../shadertoy/keyboard.js';

/** Inputs whose keys are not text: a key pressed on them is not typing. */
const NOT_TEXT_INPUTS = new Set(['range', 'button', 'submit', 'reset', 'color', 'file', 'image']);
/** The keys a focused slider (<input type="range">) moves on: those are the slider's. */
const SLIDER_KEYS = new Set(['ArrowLeft', 'ArrowRight', 'ArrowUp', 'ArrowDown', 'Home', 'End', 'PageUp', 'PageDown']);

/**
 * Whether a key event is typing into a widget (or a widget's own key), not the page's or the
 * shader's.
 * @param {{target: EventTarget | null, key: string}} event
 */
export function isTyping({ target, key }) {
  if (!(target instanceof Element)) return false;
  if (target.closest('textarea, select, [contenteditable=""], [contenteditable="true"], .cm-editor')) return true;
  const input = target.closest('input');
  if (!input) return false;
  if (input.type === 'range') return SLIDER_KEYS.has(key);
  return !NOT_TEXT_INPUTS.has(input.type);
}

/**
 * Follows the window's keys into Shadertoy's keyboard texture, calling `onChange` when it changed.
 * @param {import('../../shadertoy/keyboard.js').KeyboardState} keyboard
 * @param {() => void} onChange
 */
export function watchKeyboard(keyboard, onChange) {
  window.addEventListener('keydown', (event) => {
    if (!isTyping(event) && keyboard.keyDown(keyCodeOf(event))) onChange();
  });
  window.addEventListener('keyup', (event) => {
    if (keyboard.keyUp(keyCodeOf(event))) onChange();
  });
  window.addEventListener('blur', () => {
    // keys released in another window never come back up here; toggles stay
    for (let key = 0; key < 256; key++) keyboard.keyUp(key);
    onChange();
  });
}

/**
 * @param {Record<string, () => void>} keys what each key does, by KeyboardEvent.code
 *   (e.g. {Space: togglePlay, KeyR: restart, KeyF: toggleFullscreen})
 */
export function installShortcuts(keys) {
  /** @param {KeyboardEvent} event */
  const isShortcut = (event) => Object.hasOwn(keys, event.code) && !event.ctrlKey && !event.metaKey && !event.altKey && !isTyping(event);

  window.addEventListener(
    'keydown',
    (event) => {
      if (event.defaultPrevented || !isShortcut(event)) return;
      event.preventDefault(); // no scrolling, and no click of a focused button
      if (event.repeat) return;
      keys[event.code]();
    },
    { capture: true },
  );
  // A button clicks itself on Space's keyup: that click belongs to the shortcut, not the button.
  window.addEventListener(
    'keyup',
    (event) => {
      if (isShortcut(event) && event.target instanceof Element && event.target.closest('button')) event.preventDefault();
    },
    { capture: true },
  );
}
