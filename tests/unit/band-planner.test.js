// How a frame is cut into bands (src/player/gpu/bands/band-planner.js), drawn here on paper: each
// pass a cost per pixel the test chooses, row by row, each band timed as that cost. No band of a
// heavy but finite frame may come near the watchdog's limit (5 s of the GPU process's CPU time)
// whatever the passes before it cost, or the rows drawn last (issue 50: a shader of two buffers
// and a heavy Image pass was killed at 320x180, its Image pass sized from its buffers' cost; a
// frame whose floor is dear and sky cheap, sized at its floor from its sky).

import { describe, expect, test } from 'vitest';
import { BandPlanner } from '../../src/player/gpu/bands/band-planner.js';

/**
 * Draws a frame of `passes` (each `{cost(row): ms a pixel}`) at width × height: every band, its
 * pass's index, its first row, its rows and its ms.
 * @param {BandPlanner} planner
 * @param {{cost: (row: number) => number}[]} passes
 * @param {number} width
 * @param {number} height
 */
function drawFrame(planner, passes, width, height) {
  const bands = [];
  for (const [index, pass] of passes.entries()) {
    for (let y = 0; y < height;) {
      const rows = planner.rows(pass, width, y, height - y);
      let ms = 0;
      for (let row = y; row < y + rows; row++) ms += pass.cost(row) * width;
      planner.measured(pass, width, y, rows, ms);
      bands.push({ pass: index, y, rows, ms });
      y += rows;
    }
  }
  return bands;
}

const longest = (bands) => Math.max(...bands.map((band) => band.ms));

describe('the band planner', () => {
  test('a pass not timed yet starts with a thin band of about 640 pixels, never under two rows', () => {
    const planner = new BandPlanner();
    const pass = {};
    expect(planner.rows(pass, 320, 0, 180)).toBe(2);
    expect(planner.rows(pass, 64, 0, 36)).toBe(10);
    expect(planner.rows(pass, 1280, 0, 720)).toBe(2);
    expect(planner.rows(pass, 320, 0, 3), 'an odd remainder goes with its band').toBe(3);
  });

  test('two buffers, cheap, and an Image pass of 1.2 ms a pixel (a minute at 320x180): no band of it past 0.8 s', () => {
    const planner = new BandPlanner();
    const passes = [{ cost: () => 0.0005 }, { cost: () => 0.001 }, { cost: () => 1.2 }];
    const bands = drawFrame(planner, passes, 320, 180);
    const image = bands.filter((band) => band.pass === 2);
    expect(image[0].rows).toBe(2);
    expect(longest(image)).toBeLessThan(800);
    // the next frame of it: each pass sized from its own cost, at once (a buffer in one band)
    const next = drawFrame(planner, passes, 320, 180);
    expect(next.filter((band) => band.pass < 2)).toHaveLength(2);
    expect(longest(next)).toBeLessThan(800);
  });

  test('a floor of 0.5 ms a pixel under a sky of 0.001: the next frame starts at the floor as small as the first did', () => {
    const planner = new BandPlanner();
    const passes = [{ cost: (/** @type {number} */ row) => (row < 120 ? 0.5 : 0.001) }];
    const first = drawFrame(planner, passes, 640, 360);
    expect(longest(first)).toBeLessThan(700);
    const next = drawFrame(planner, passes, 640, 360);
    expect(next[0].rows).toBe(2);
    expect(longest(next)).toBeLessThan(700);
    expect(next.length, 'the sky in few bands').toBeLessThan(first.length);
  });

  test('a cheap frame grows to one band: after a few on its first frame, one on the next', () => {
    const planner = new BandPlanner();
    const passes = [{ cost: () => 0.00001 }];
    const first = drawFrame(planner, passes, 1280, 720);
    expect(first.map((band) => band.rows)).toEqual([2, 16, 128, 574]);
    expect(drawFrame(planner, passes, 1280, 720)).toHaveLength(1);
    planner.forget();
    expect(drawFrame(planner, passes, 1280, 720), 'forgotten: thin again').toHaveLength(4);
  });

  test('a row not drawn yet costs what the band before it did; the last band of a frame does not start the next small', () => {
    const planner = new BandPlanner();
    const pass = {};
    planner.measured(pass, 100, 0, 10, 10); // 0.01 ms a pixel
    expect(planner.rows(pass, 100, 10, 1000)).toBe(80); // eight times the rows, under the budget's 100
    planner.measured(pass, 100, 10, 80, 800); // 0.1 ms a pixel: ten times dearer
    expect(planner.rows(pass, 100, 90, 1000)).toBe(10);
    expect(planner.rows(pass, 100, 0, 1000), 'from row 0: its own cost, then the dear rows').toBe(18);
    planner.measured(pass, 100, 998, 2, 0.02); // a remainder of two rows, cheap
    expect(planner.rows(pass, 100, 998, 1000)).toBeGreaterThan(16);
  });

  test('a cost that climbs tenfold across the frame: no band past ten budgets', () => {
    const planner = new BandPlanner();
    const passes = [{ cost: (/** @type {number} */ row) => (row < 360 ? 0.01 : 0.1) }];
    expect(longest(drawFrame(planner, passes, 1280, 720))).toBeLessThan(1000);
  });
});
