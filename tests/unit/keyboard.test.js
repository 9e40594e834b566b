// Shadertoy's keyboard texture (issue 13): src/shadertoy/keyboard.js's state transitions, as the
// site keeps them, and the legacy keyCodes it indexes by.
import { describe, expect, test } from 'vitest';
import { KeyboardState, keyCodeOf, ROW_HELD, ROW_PRESSED, ROW_TOGGLED } from '../../src/shadertoy/keyboard.js';

describe('keyboard texture', () => {
  const A = 65;
  const row = (k, s) => [s.read(k, ROW_HELD), s.read(k, ROW_PRESSED), s.read(k, ROW_TOGGLED)];
  test.each([
    ['nothing', [], [0, 0, 0]],
    ['down', ['down'], [1, 1, 1]],
    ['down, a frame', ['down', 'frame'], [1, 0, 1]],
    ['down, auto-repeat, a frame', ['down', 'frame', 'down'], [1, 0, 1]],
    ['down, a frame, up', ['down', 'frame', 'up'], [0, 0, 1]],
    ['down, up before the frame (never seen pressed)', ['down', 'up'], [0, 0, 1]],
    ['two presses: the toggle is back off', ['down', 'frame', 'up', 'frame', 'down', 'frame'], [1, 0, 0]],
    ['three presses', ['down', 'up', 'down', 'up', 'down'], [1, 1, 1]],
  ])('%s', (_, events, expected) => {
    const s = new KeyboardState();
    for (const e of events) {
      if (e === 'down') s.keyDown(A);
      else if (e === 'up') s.keyUp(A);
      else s.endFrame();
    }
    expect(row(A, s)).toEqual(expected);
    // Other keys untouched; the texture is 256 x 3 bytes, row r at offset 256 r.
    expect(s.data).toHaveLength(768);
    expect(s.data.reduce((n, v, i) => n + (v !== 0 && i % 256 !== A ? 1 : 0), 0)).toBe(0);
    if (expected[2]) expect(s.data[2 * 256 + A]).toBe(255);
  });
  test('a repeat reports no change; keys outside 1..255 are ignored', () => {
    const s = new KeyboardState();
    expect(s.keyDown(A)).toBe(true);
    expect(s.keyDown(A)).toBe(false);
    expect(s.keyDown(300)).toBe(false);
    expect(s.keyDown(null)).toBe(false);
  });
  test.each([
    [{ keyCode: 37, code: 'ArrowLeft' }, 37],
    [{ code: 'KeyA', key: 'a' }, 65],
    [{ code: 'Digit7', key: '7' }, 55],
    [{ code: 'Space', key: ' ' }, 32],
    [{ code: 'ArrowDown', key: 'ArrowDown' }, 40],
    [{ code: 'Numpad3' }, 99],
    [{ code: 'F5' }, 116],
    [{ code: 'ShiftRight' }, 16],
    [{ code: 'Semicolon' }, 186],
    [{ key: 'q' }, 81],
    [{ key: 'Escape' }, 27],
    [{ code: 'Unidentified', key: 'Dead' }, null],
    [{ keyCode: 300 }, null],
  ])('keyCodeOf(%o) = %s', (event, code) => {
    expect(keyCodeOf(event)).toBe(code);
  });
});
