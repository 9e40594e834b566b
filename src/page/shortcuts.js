// The page's keyboard shortcuts: Space plays and pauses, R restarts, F toggles fullscreen.
//
// They work whatever toolbar button has focus: a focused button would otherwise take Space (and
// Enter) as a click of its own, so that Space after clicking "Screenshot" saved a second PNG.
// They never fire while typing: in the editor, a panel field, a text box or a drop-down.

/** Inputs whose keys are not text: a shortcut pressed on them is still a shortcut. */
const NOT_TEXT_INPUTS = new Set(['range', 'button', 'submit', 'reset', 'color', 'file', 'image']);

/**
 * Whether a key pressed on `target` is typing (or a widget's own key), not a page shortcut.
 * @param {EventTarget | null} target
 */
export function isTyping(target) {
  if (!(target instanceof Element)) return false;
  if (target.closest('textarea, select, [contenteditable=""], [contenteditable="true"], .cm-editor')) return true;
  const input = target.closest('input');
  return Boolean(input && !NOT_TEXT_INPUTS.has(input.type));
}

/**
 * @param {Record<string, () => void>} keys what each key does, by KeyboardEvent.code
 *   (e.g. {Space: togglePlay, KeyR: restart, KeyF: toggleFullscreen})
 */
export function installShortcuts(keys) {
  /** @param {KeyboardEvent} event */
  const isShortcut = (event) =>
    Object.hasOwn(keys, event.code) && !event.ctrlKey && !event.metaKey && !event.altKey && !isTyping(event.target);

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
