// The "Extra samples" debug view marks the pixels that took adaptive anti-aliasing's extra
// samples: with ADAPTIVE_AA off every pixel takes them, with SAMPLES at 1 none does, and either
// way it marks none. The page says which, over the canvas, while that view is on (issue 24, item
// 13), and nothing for the views that show what they mean.

import { describe, expect, test } from 'vitest';
import { withPage, sharePageAcrossTests } from '../support/page-helpers.js';
import { hook } from '../support/hook.js';

// not a test of loading the page: the tests share one, brought to each view by open()
sharePageAcrossTests();

const SIZE = 'size=64x36&time=0';

/** The note's text, or null while it is hidden. */
const viewNote = (page) =>
  page.evaluate(() => {
    const note = /** @type {HTMLElement | null} */ (document.querySelector('.view-note'));
    return note && !note.hidden && getComputedStyle(note).display !== 'none' ? note.textContent : null;
  });

describe('the "Extra samples" view says what it shows', () => {
  /** @type {Array<[string, string, RegExp | null]>} */
  const CASES = [
    ['adaptive anti-aliasing off', 'VIEW=5&ADAPTIVE_AA=0', /Adaptive anti-aliasing is off, so every pixel takes all 16 samples/],
    ['adaptive anti-aliasing off, 4 samples', 'VIEW=5&ADAPTIVE_AA=0&SAMPLES=4', /every pixel takes all 4 samples/],
    ['1 sample per pixel', 'VIEW=5&SAMPLES=1', /is 1, so no pixel takes extra samples/],
    ['adaptive anti-aliasing on: it marks the pixels', 'VIEW=5', null],
    ['the picture, adaptive anti-aliasing off', 'ADAPTIVE_AA=0', null],
  ];
  test.each(CASES)('%s', async (_, params, said) => {
    await withPage(async ({ page, goto }) => {
      await goto(`?${SIZE}&${params}`);
      const text = await viewNote(page);
      if (said) expect(text).toMatch(said);
      else expect(text).toBe(null);
    });
  });

  test('the note follows the controls: on with ADAPTIVE_AA off, gone with the picture', async () => {
    await withPage(async ({ page, goto }) => {
      await goto(`?${SIZE}&VIEW=5`);
      expect(await viewNote(page)).toBe(null);
      await hook(page).setControls({ ADAPTIVE_AA: 0 });
      expect(await viewNote(page)).toMatch(/every pixel takes all 16 samples/);
      await hook(page).setControls({ VIEW: 0 });
      expect(await viewNote(page)).toBe(null);
    });
  });
});
