// Shadertoy's keyboard input: a 256 x 3 single-channel 8-bit texture, one texel per legacy
// keyCode, read with texelFetch(iChannelN, ivec2(keyCode, row), 0).x:
//   row 0: 1 while the key is held,
//   row 1: 1 on the frame the key went down (cleared after each frame is painted),
//   row 2: flips between 0 and 1 at every press.
// As the site does it (https://www.shadertoy.com/js/effect.js, Effect.SetKeyDown / SetKeyUp /
// the end of Effect.Paint; iq's "Input - Keyboard", https://www.shadertoy.com/view/lsXGzf):
// - a key-down for a key already held changes nothing (auto-repeat neither presses nor toggles);
// - a key-up clears rows 0 and 1 (a key pressed and released between two frames is never seen
//   as pressed: the site behaves so, and so does this);
// - after every painted frame row 1 is cleared;
// - keys are the browser's legacy `keyCode` (the site passes `ev.keyCode`): 'A' is 65, '0' is
//   48, the arrows 37–40, space 32. The texture is created nearest/clamp (TEXFMT.C1I8).

/** The texture's size: 256 keys by 3 rows. */
const KEYBOARD_WIDTH = 256;
const KEYBOARD_HEIGHT = 3;
export const ROW_HELD = 0;
export const ROW_PRESSED = 1;
export const ROW_TOGGLED = 2;

// KeyboardEvent.code to the legacy keyCode browsers give on a US layout (the codes that do not
// follow a pattern; letters, digits, numpad digits and F-keys are computed below).
const CODE_TO_KEYCODE = Object.freeze({
  Backspace: 8,
  Tab: 9,
  Enter: 13,
  NumpadEnter: 13,
  ShiftLeft: 16,
  ShiftRight: 16,
  ControlLeft: 17,
  ControlRight: 17,
  AltLeft: 18,
  AltRight: 18,
  Pause: 19,
  CapsLock: 20,
  Escape: 27,
  Space: 32,
  PageUp: 33,
  PageDown: 34,
  End: 35,
  Home: 36,
  ArrowLeft: 37,
  ArrowUp: 38,
  ArrowRight: 39,
  ArrowDown: 40,
  PrintScreen: 44,
  Insert: 45,
  Delete: 46,
  MetaLeft: 91,
  MetaRight: 92,
  ContextMenu: 93,
  NumpadMultiply: 106,
  NumpadAdd: 107,
  NumpadSubtract: 109,
  NumpadDecimal: 110,
  NumpadDivide: 111,
  NumLock: 144,
  ScrollLock: 145,
  Semicolon: 186,
  Equal: 187,
  Comma: 188,
  Minus: 189,
  Period: 190,
  Slash: 191,
  Backquote: 192,
  BracketLeft: 219,
  Backslash: 220,
  BracketRight: 221,
  Quote: 222,
  IntlBackslash: 226,
});

// KeyboardEvent.key names of keys that have no single-character key: the keys whose `key` is
// their `code` (Enter, Tab, the arrows, Home, ...), and the modifiers and space, whose `key`
// names no side.
const KEY_TO_KEYCODE = Object.freeze({
  ...Object.fromEntries(
    ['Backspace', 'Tab', 'Enter', 'Pause', 'CapsLock', 'Escape', 'PageUp', 'PageDown', 'End', 'Home', 'Insert', 'Delete']
      .concat(['ArrowLeft', 'ArrowUp', 'ArrowRight', 'ArrowDown'])
      .map((name) => [name, CODE_TO_KEYCODE[name]]),
  ),
  Shift: 16,
  Control: 17,
  Alt: 18,
  Meta: 91,
  ' ': 32,
});

/**
 * The legacy keyCode Shadertoy indexes its keyboard texture by, for a keyboard event: the
 * event's own `keyCode` where the browser gives one, else from `code` (the physical key, US
 * layout), else from `key`. Null for a key outside 1..255 or one it cannot name.
 * @param {{keyCode?: number, code?: string, key?: string}} event
 * @returns {number | null}
 */
export function keyCodeOf(event) {
  const direct = event.keyCode;
  if (typeof direct === 'number' && Number.isInteger(direct) && direct > 0) return direct < KEYBOARD_WIDTH ? direct : null;
  const code = event.code ?? '';
  let m;
  if ((m = code.match(/^Key([A-Z])$/))) return m[1].charCodeAt(0);
  if ((m = code.match(/^Digit([0-9])$/))) return 48 + Number(m[1]);
  if ((m = code.match(/^Numpad([0-9])$/))) return 96 + Number(m[1]);
  if ((m = code.match(/^F([1-9]|1[0-2])$/))) return 111 + Number(m[1]);
  if (Object.hasOwn(CODE_TO_KEYCODE, code)) return CODE_TO_KEYCODE[code];
  const key = event.key ?? '';
  if (/^[a-zA-Z0-9]$/.test(key)) return key.toUpperCase().charCodeAt(0);
  if (Object.hasOwn(KEY_TO_KEYCODE, key)) return KEY_TO_KEYCODE[key];
  return null;
}

/** The keyboard texture's state, kept as the site keeps it. */
export class KeyboardState {
  constructor() {
    /** The texture's bytes, row 0 first (the order texImage2D uploads: row 0 is texel y = 0). */
    this.data = new Uint8Array(KEYBOARD_WIDTH * KEYBOARD_HEIGHT);
  }

  /**
   * A key went down. Returns whether the texture changed (false for a repeat while held).
   * @param {number | null} keyCode
   */
  keyDown(keyCode) {
    if (!validKey(keyCode)) return false;
    const d = this.data;
    if (d[keyCode + ROW_HELD * KEYBOARD_WIDTH] === 255) return false;
    d[keyCode + ROW_HELD * KEYBOARD_WIDTH] = 255;
    d[keyCode + ROW_PRESSED * KEYBOARD_WIDTH] = 255;
    d[keyCode + ROW_TOGGLED * KEYBOARD_WIDTH] = 255 - d[keyCode + ROW_TOGGLED * KEYBOARD_WIDTH];
    return true;
  }

  /**
   * A key went up: not held, and not pressed this frame either. Returns whether anything changed.
   * @param {number | null} keyCode
   */
  keyUp(keyCode) {
    if (!validKey(keyCode)) return false;
    const d = this.data;
    const changed = d[keyCode + ROW_HELD * KEYBOARD_WIDTH] !== 0 || d[keyCode + ROW_PRESSED * KEYBOARD_WIDTH] !== 0;
    d[keyCode + ROW_HELD * KEYBOARD_WIDTH] = 0;
    d[keyCode + ROW_PRESSED * KEYBOARD_WIDTH] = 0;
    return changed;
  }

  /** A frame has been painted: clear row 1 (pressed this frame). Returns whether anything changed. */
  endFrame() {
    const row = this.data.subarray(ROW_PRESSED * KEYBOARD_WIDTH, (ROW_PRESSED + 1) * KEYBOARD_WIDTH);
    const changed = row.some((v) => v !== 0);
    row.fill(0);
    return changed;
  }

  /** Every key up and every toggle off (a new shader; the site's Restart does not do this). */
  reset() {
    this.data.fill(0);
  }

  /**
   * One texel as the shader reads it: 0 or 1.
   * @param {number} keyCode
   * @param {0 | 1 | 2} row
   */
  read(keyCode, row) {
    return this.data[keyCode + row * KEYBOARD_WIDTH] / 255;
  }
}

/** @type {(k: number | null) => k is number} */
const validKey = (k) => k !== null && Number.isInteger(k) && k > 0 && k < KEYBOARD_WIDTH;
