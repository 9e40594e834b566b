// Where a comparison's pixels differ (src/headless/compare.js) and how every report says it
// (src/shared/differences.js): the box of a known difference, the first pixels with both
// images' values, one pixel said in the singular, and the viewer's opening zoom at it.

import { describe, expect, test } from 'vitest';
import { compareImages } from '../../src/headless/compare.js';
import { differLine, pixelCount } from '../../src/shared/differences.js';
import { viewerLayout } from '../../src/runner/report/viewer.js';

/** A w×h image of one colour, with `changed` pixels [x, y, rgba] set. */
const picture = (w, h, changed = []) => {
  const data = new Uint8Array(w * h * 4);
  for (let i = 0; i < data.length; i += 4) data.set([40, 80, 120, 255], i);
  for (const [x, y, rgba] of changed) data.set(rgba, (y * w + x) * 4);
  return { width: w, height: h, data };
};
const compare = (actual, reference) => compareImages(actual, reference, { threshold: 0, includeAA: true });

describe('where pixels differ', () => {
  test.each([
    ['none', [], 0, null],
    ['one pixel', [[12, 7, [254, 0, 0, 255]]], 1, { left: 12, top: 7, right: 12, bottom: 7 }],
    [
      'three apart',
      [
        [10, 5, [0, 0, 0, 255]],
        [90, 30, [0, 0, 0, 255]],
        [40, 60, [0, 0, 0, 255]],
      ],
      3,
      { left: 10, top: 5, right: 90, bottom: 60 },
    ],
  ])('%s: the count and the bounding box', (_, changed, count, box) => {
    const { diffPixels, where } = compare(picture(100, 80, changed), picture(100, 80));
    expect(diffPixels).toBe(count);
    expect(where?.box ?? null).toEqual(box);
  });

  test('a filled 81×56 box: every pixel counted, the first five row by row with both values', () => {
    const changed = [];
    for (let y = 5; y <= 60; y++) for (let x = 10; x <= 90; x++) changed.push([x, y, [40, 200, 120, 255]]);
    const { diffPixels, where } = compare(picture(100, 80, changed), picture(100, 80));
    expect(diffPixels).toBe(81 * 56);
    expect(where?.first).toEqual(
      [10, 11, 12, 13, 14].map((x) => ({ x, y: 5, reference: [40, 80, 120, 255], actual: [40, 200, 120, 255] })),
    );
    expect(differLine(diffPixels, 0, where)).toBe('4,536 pixels differ from the reference (at most 0 may) in x 10–90, y 5–60');
  });
});

describe('how a count is said', () => {
  const one = {
    box: { left: 12, top: 7, right: 12, bottom: 7 },
    first: [{ x: 12, y: 7, reference: [255, 0, 0, 255], actual: [254, 0, 0, 255] }],
  };
  const row = { box: { left: 3, top: 9, right: 8, bottom: 9 }, first: [] };
  test.each([
    [1, 0, one, '1 pixel differs from the reference (at most 0 may) at (12, 7): reference 255,0,0,255, actual 254,0,0,255'],
    [1, 0, null, '1 pixel differs from the reference (at most 0 may)'],
    [6, 1, row, '6 pixels differ from the reference (at most 1 may) in x 3–8, y 9'],
    [4800, 2000, row, '4,800 pixels differ from the reference (at most 2,000 may) in x 3–8, y 9'],
  ])('%i pixels, at most %i', (count, allowed, where, said) => {
    expect(differLine(count, allowed, where)).toBe(said);
  });

  test.each([
    [0, '0 pixels'],
    [1, '1 pixel'],
    [2, '2 pixels'],
    [57600, '57,600 pixels'],
  ])('%i: %s', (count, said) => expect(pixelCount(count)).toBe(said));
});

describe('the viewer opens at the difference', () => {
  const at = (left, top, right, bottom) => ({ box: { left, top, right, bottom }, first: [] });
  test.each([
    ['no difference: whole, at 1×', { width: 320, height: 180 }, null, { zoom: 1, center: [160, 90], view: { width: 320, height: 180 } }],
    ['one pixel: 8×, centred on it', { width: 320, height: 180 }, at(12, 7, 12, 7), { zoom: 8, center: [12.5, 7.5] }],
    ['a wide box: the most that shows it', { width: 320, height: 180 }, at(10, 5, 90, 60), { zoom: 1, center: [50.5, 33] }],
    ['a small render starts enlarged', { width: 32, height: 18 }, at(12, 7, 12, 7), { zoom: 8, view: { width: 256, height: 144 } }],
    [
      'a large render: fit in the viewport first',
      { width: 1920, height: 1080 },
      null,
      { zoom: 440 / 1920, view: { width: 440, height: 248 } },
    ],
  ])('%s', (_, size, where, expected) => {
    expect(viewerLayout(size, where)).toMatchObject(expected);
  });
});
