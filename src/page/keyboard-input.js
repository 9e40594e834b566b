// The page's keys into Shadertoy's keyboard texture (keyboard.js), for shaders that read it (the
// app's keyboard state, sent with each frame). Keys typed into the editor or a field of the panel
// are the page's, not the shader's.

import { keyCodeOf } from '../shadertoy/keyboard.js';

/**
 * Follows the window's keys into `keyboard`, calling `onChange` when the texture changed.
 * @param {import('../shadertoy/keyboard.js').KeyboardState} keyboard
 * @param {() => void} onChange
 */
export function watchKeyboard(keyboard, onChange) {
  const typing = (/** @type {KeyboardEvent} */ event) => {
    const target = /** @type {HTMLElement | null} */ (event.target instanceof HTMLElement ? event.target : null);
    return Boolean(target?.closest('input, textarea, select, [contenteditable="true"], .cm-editor'));
  };
  window.addEventListener('keydown', (event) => {
    if (!typing(event) && keyboard.keyDown(keyCodeOf(event))) onChange();
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
