// Where the inspector's boxes lie (src/studio/inspect/box-layout.js, loupe.js; issue 24, item 3):
// at 1280x800, 800x600 and on a phone (390x844), with a comparison's box and a pinned pixel in
// each part of the canvas, the readout and the comparison's box stay inside the canvas, apart,
// with their buttons in them, and off the pinned pixel; the magnifier lies on the stage (the
// panel beside it would clip it), beside the cursor, clear of the boxes where a side is, and
// hides while the pointer is over a box. After a click that pins a pixel (issue 45, item 11), the
// readout comes up where the magnifier was: the magnifier moves off it, or hides.

import { afterAll, describe, expect, test } from 'vitest';
import { disconnect } from '../support/page.js';
import { withPage, sharePageAcrossTests } from '../support/page-helpers.js';
import { hook } from '../support/hook.js';

// not a test of loading the page: the tests share one, brought to each view by open()
sharePageAcrossTests();

afterAll(disconnect);

/** The pinned pixels, as fractions of the canvas (u right, v down): each corner's part and the middle. */
const PINS = [
  [0.3, 0.75],
  [0.15, 0.12],
  [0.85, 0.85],
  [0.85, 0.1],
  [0.5, 0.5],
];

/** The boxes' rectangles on the page, the canvas's (on the stage), and each box's ✕. */
const geometry = (page) =>
  page.evaluate(() => {
    const rect = (/** @type {Element | null} */ e) => {
      if (!e || getComputedStyle(e).display === 'none') return null;
      const r = e.getBoundingClientRect();
      return { left: r.left, top: r.top, right: r.right, bottom: r.bottom };
    };
    const stage = rect(document.getElementById('stage'));
    const view = rect(document.getElementById('view'));
    const canvas = {
      left: Math.max(stage.left, view.left),
      top: Math.max(stage.top, view.top),
      right: Math.min(stage.right, view.right),
      bottom: Math.min(stage.bottom, view.bottom),
    };
    const close = (box) => rect(document.querySelector(`${box} header button[aria-label^="Close"]`));
    return {
      canvas,
      stage,
      readout: rect(document.querySelector('.inspector')),
      compare: rect(document.querySelector('.compare')),
      readoutClose: close('.inspector'),
      compareClose: close('.compare'),
      pin: rect(document.querySelector('.pinned-marker')),
      loupe: rect(document.querySelector('.loupe-box')),
    };
  });

const inside = (inner, outer) =>
  inner.left >= outer.left - 0.5 && inner.top >= outer.top - 0.5 && inner.right <= outer.right + 0.5 && inner.bottom <= outer.bottom + 0.5;
const overlap = (a, b) => a.left < b.right && b.left < a.right && a.top < b.bottom && b.top < a.bottom;
const centre = (r) => ({
  left: (r.left + r.right) / 2,
  top: (r.top + r.bottom) / 2,
  right: (r.left + r.right) / 2,
  bottom: (r.top + r.bottom) / 2,
});

describe('the inspector covers nothing it describes', () => {
  test.each([
    [1280, 800],
    [800, 600],
    [390, 844],
  ])('at %ix%i: the boxes stay inside the canvas, apart and off the pinned pixel; the magnifier stays clear', async (width, height) => {
    await withPage(
      async ({ page, goto }) => {
        await goto('?time=0&SAMPLES=1&scale=0.25'); // the canvas fills its place, at a sixteenth of its pixels
        await hook(page).compareWithFloat64();
        const { width: w, height: h } = await hook(page).info();
        for (const [u, v] of PINS) {
          const [x, y] = [Math.floor(u * w), h - 1 - Math.floor(v * h)];
          await hook(page).inspect(x, y);
          const g = await geometry(page);
          const where = `pixel ${x}, ${y} pinned: ${JSON.stringify(g)}`;
          expect(g.readout && g.compare && g.pin, where).toBeTruthy();
          for (const name of ['readout', 'compare']) {
            expect(inside(g[name], g.canvas), `${where}: the ${name} inside the canvas`).toBe(true);
            expect(inside(g[`${name}Close`], g[name]), `${where}: the ${name}'s ✕ inside it`).toBe(true);
            expect(overlap(g[name], centre(g.pin)), `${where}: the ${name} off the pinned pixel`).toBe(false);
          }
          expect(overlap(g.readout, g.compare), `${where}: the boxes apart`).toBe(false);
        }

        const g = await geometry(page);
        const hover = async (clientX, clientY) => {
          await page.mouse.move(clientX, clientY);
          return (await geometry(page)).loupe;
        };
        // over a box: no magnifier (it would cover the box's own buttons)
        expect(await hover((g.readout.left + g.readout.right) / 2, g.readout.top + 8), 'over the readout').toBe(null);
        // near the canvas's right edge, by the panel: wholly on the stage
        const edge = await hover(g.canvas.right - 3, (g.canvas.top + g.canvas.bottom) / 2);
        expect(edge && inside(edge, g.stage), `near the right edge: ${JSON.stringify(edge)} on the stage ${JSON.stringify(g.stage)}`).toBe(
          true,
        );
        // just outside a box, on the canvas: beside the cursor, clear of both boxes where a side has room
        const gapX = (g.readout.left + g.readout.right) / 2;
        const gapY = g.readout.top > g.canvas.top + 200 ? g.readout.top - 6 : g.readout.bottom + 6;
        const near = await hover(gapX, gapY);
        expect(near, 'just outside the readout: the magnifier shows').not.toBe(null);
        if (width >= 800) {
          expect(overlap(near, g.readout), `${JSON.stringify(near)} clear of the readout ${JSON.stringify(g.readout)}`).toBe(false);
          expect(overlap(near, g.compare), `${JSON.stringify(near)} clear of the comparison ${JSON.stringify(g.compare)}`).toBe(false);
        }
      },
      { viewport: { width, height, deviceScaleFactor: 1 } },
    );
  });
});

/**
 * Where a person clicks to pin a pixel, as fractions of the canvas (u right, v down): the
 * readout then comes up beside the cursor, where the magnifier still is (issue 45, item 11).
 */
const CLICKS = [
  [0.3, 0.45],
  [0.2, 0.8],
  [0.7, 0.6],
  [0.45, 0.3],
  [0.85, 0.85],
  [0.6, 0.42],
  [0.15, 0.4],
  [0.9, 0.45],
];

describe('a pixel pinned with a click: the magnifier then covers no box', () => {
  test.each([
    [1280, 800],
    [800, 600],
  ])('at %ix%i: after each click, the magnifier and its label lie off the readout and the comparison', async (width, height) => {
    await withPage(
      async ({ page, goto }) => {
        await goto('?time=0&SAMPLES=1&scale=0.5');
        await hook(page).compareWithFloat64();
        await page.keyboard.press('KeyI'); // Inspect on
        const { canvas } = await geometry(page);
        let clicked = 0;
        let beside = 0;
        for (const [u, v] of CLICKS) {
          const x = canvas.left + u * (canvas.right - canvas.left);
          const y = canvas.top + v * (canvas.bottom - canvas.top);
          await page.mouse.move(x - 10, y - 10);
          await page.mouse.move(x, y, { steps: 3 });
          // a click on a box is the box's: only clicks on the canvas (or the heat map over it) pin
          if (!(await page.evaluate((px, py) => document.elementFromPoint(px, py)?.matches('#view, .heat-map'), x, y))) continue;
          clicked++;
          await page.mouse.down();
          await page.mouse.up();
          // the readout comes up and grows as its path and its float64 colour come in: each lays the boxes out
          await page.waitForFunction(
            ([cx, cy]) => {
              const { pinned, readout } = window.shaderEngine.inspection();
              return pinned && readout?.complete && Math.abs(readout.fragCoord[0] - cx) < 2 && Math.abs(readout.fragCoord[1] - cy) < 2;
            },
            { polling: 50 },
            await page.evaluate(
              (px, py) => {
                const c = /** @type {HTMLCanvasElement} */ (document.getElementById('view'));
                const r = c.getBoundingClientRect();
                return [((px - r.left) / r.width) * c.width, c.height - ((py - r.top) / r.height) * c.height];
              },
              x,
              y,
            ),
          );
          const g = await geometry(page);
          const where = `clicked at ${Math.round(x)}, ${Math.round(y)}: ${JSON.stringify(g)}`;
          expect(g.readout && g.compare, where).toBeTruthy();
          if (!g.loupe) continue; // hidden: it had no side clear of the boxes
          beside++;
          expect(overlap(g.loupe, g.readout), `${where}: the magnifier over the readout`).toBe(false);
          expect(overlap(g.loupe, g.compare), `${where}: the magnifier over the comparison`).toBe(false);
        }
        expect(clicked, 'clicks that pinned a pixel (the others fell on a box)').toBeGreaterThanOrEqual(3);
        // where the canvas has room beside the boxes, the magnifier stays beside the cursor
        if (width >= 1280) expect(beside, 'clicks after which the magnifier showed').toBeGreaterThan(0);
        await page.keyboard.press('KeyI');
      },
      { viewport: { width, height, deviceScaleFactor: 1 } },
    );
  });
});
