// "Compare with float64" (src/studio/inspect/compare.js), in the real page: its figures for a view
// are the ones `npm run accuracy` computes for it (tests/scripts/accuracy-report.js: the page's
// 8-bit frame against renderReference with the same rays, the extra samples where the shader's
// "Extra samples" view puts them: tests/support/reference/same-ray.js), computed here in Node; the page answers while the reference
// renders and says how far it has got; Cancel stops it; a click on the heat map pins that pixel in
// the inspector; a shader that is not the raytracer, a multipass one and a debug view are told
// so in a box that offers no map controls; a comparison under way is not started again.

import fs from 'node:fs';
import { afterAll, describe, expect, test } from 'vitest';
import { formatImageError } from '../../src/reference/error.js';
import { SHADER_FILE } from '../support/config.js';
import { disconnect } from '../support/page.js';
import { measureSameRay } from '../support/reference/same-ray.js';
import { viewQuery } from '../support/tables/views.js';
import { button, canvasBox, withPage, sharePageAcrossTests } from '../support/page-helpers.js';
import { exportOf } from '../support/page-multipass-helpers.js';
import { hook } from '../support/hook.js';

// not a test of loading the page: the tests share one, brought to each view by open()
sharePageAcrossTests();

afterAll(disconnect);

const source = fs.readFileSync(SHADER_FILE, 'utf8');
const VIEWPORT = { width: 1280, height: 800, deviceScaleFactor: 1 };

/** What the accuracy report measures for a view: its same-ray error, and the share of pixels with extra samples. */
const accuracyReportFigures = (view) => measureSameRay(source, view);

// The accuracy report's views (its size, 320x180; 1 sample per pixel and adaptive anti-aliasing,
// 16 samples at edges, the defaults), each scene's.
const VIEWS = [
  ['the default view, 1 sample per pixel', { time: 0, SAMPLES: 1 }],
  ['the default view, adaptive anti-aliasing', { time: 0 }],
  ['the cylinder scene, adaptive anti-aliasing', { time: 0, SCENE: 1 }],
  ['the torus scene, 1 sample per pixel', { time: 0, SCENE: 2, SAMPLES: 1 }],
];

describe('compare with float64', () => {
  test.each(VIEWS)("%s: the page's figures are npm run accuracy's same-ray figures", async (name, params) => {
    const view = { name, params };
    const { error: expected, share } = await accuracyReportFigures(view);
    await withPage(
      async ({ page, goto }) => {
        await goto(viewQuery(view).slice(1)); // without its leading slash: goto adds one
        const got = await hook(page).compareWithFloat64();
        const canvas = got.figures.canvas;
        console.log(
          `${name}: page ${formatImageError(canvas)}; accuracy report ${formatImageError(expected)}; float32 ${formatImageError(got.figures.float)}`,
        );
        // The same module computes both from the same 8-bit pixels and the same float64 rays, so
        // they agree to the last bits (1e-9 of the RMSE leaves room for nothing else)
        expect(Math.abs(canvas.rmse - expected.rmse), `RMSE ${canvas.rmse} against ${expected.rmse}`).toBeLessThanOrEqual(
          1e-9 * expected.rmse,
        );
        expect(canvas.maxAbs).toBeCloseTo(expected.maxAbs, 12);
        expect(canvas.over2).toBe(expected.over2);
        expect(canvas.nonFinite).toBe(0);
        expect(got.extraSampleShare, 'the extra samples where the shader took them').toBe(share);
        // before the 8-bit rounding the error is smaller still
        expect(got.figures.float.rmse).toBeLessThan(canvas.rmse);
        expect(got.caveat).toBe(null);
        // on the page: the heat map over the canvas, the figures beside it
        const map = await page.$eval('.heat-map', (c) => {
          const canvas = /** @type {HTMLCanvasElement} */ (c);
          return { shown: !canvas.hidden, size: [canvas.width, canvas.height] };
        });
        expect(map).toEqual({ shown: true, size: [320, 180] });
        expect(await page.$eval('.compare table.figures', (t) => t.textContent)).toContain(canvas.rmse.toExponential(2));
      },
      { viewport: VIEWPORT },
    );
  });

  test('the page answers while the reference renders, says how far it has got, and Cancel stops it', async () => {
    await withPage(
      async ({ page, goto }) => {
        await goto('?size=960x540&time=0&SAMPLES=1');
        await page.evaluate(() => {
          // the longest gap between 10 ms ticks of the page's own thread
          window.__longestGap = 0;
          let last = performance.now();
          setInterval(() => {
            const now = performance.now();
            window.__longestGap = Math.max(window.__longestGap, now - last);
            last = now;
          }, 10);
        });
        await (await button(page, 'Compare with float64')).click();
        await page.waitForFunction(() => window.shaderEngine.comparison().running?.rows > 0, { polling: 50 });
        const first = (await hook(page).comparison()).running;
        await page.waitForFunction((rows) => window.shaderEngine.comparison().running?.rows > rows, { polling: 50 }, first.rows);
        expect(first.of).toBe(540);
        expect(await page.$eval('.compare-progress', (p) => p.textContent)).toMatch(/float64 reference: \d+ of 540 rows/);
        expect(await page.$eval('.compare-progress progress', (p) => /** @type {HTMLProgressElement} */ (p).value)).toBeGreaterThan(0);
        // 2 cores, shared: the reference's worker has one. The page's thread does none of its work.
        expect(await page.evaluate(() => window.__longestGap), 'the longest the page went without running a 10 ms timer (ms)').toBeLessThan(
          500,
        );
        await (await page.$('.compare-progress button')).click(); // Cancel
        const after = await hook(page).comparison();
        expect(after.running).toBe(null);
        expect(after.error).toBe(null);
        expect(after.shown).toBe(null);
      },
      { viewport: VIEWPORT, deterministic: false },
    );
  });

  test('a click on the heat map pins that pixel in the inspector', async () => {
    await withPage(
      async ({ page, goto }) => {
        await goto('?size=320x180&time=0&SAMPLES=1');
        await hook(page).compareWithFloat64();
        const box = await canvasBox(page);
        // pixel (250, 179 - 130): clear of the comparison's box (upper left) and of the inspector (lower left)
        await page.mouse.click(box.left + (250.5 / 320) * box.width, box.top + (130.5 / 180) * box.height);
        await page.waitForFunction(() => window.shaderEngine.inspection().readout?.complete, { polling: 50 });
        const state = await hook(page).inspection();
        expect(state.active).toBe(true);
        expect(state.pinned).toMatchObject({ x: 250, y: 49 });
        expect(state.readout.reference, 'the pinned pixel has its float64 colour').not.toBe(null);
      },
      { viewport: VIEWPORT },
    );
  });

  // A heat map that no longer matches the picture is hidden, not left over it: dimmed after a
  // change of view (two spheres, translucent), or stretched to another canvas's shape after a
  // resize, at once (before the next frame says the comparison is out of date) and after.
  /** @type {Array<[string, (page: import('puppeteer-core').Page) => Promise<unknown>]>} */
  const CHANGES = [
    ['a control change', (page) => hook(page).setControls({ LIGHT_POSITION: [4, 3, 2] })],
    ['a resize', (page) => page.setViewport({ width: 1000, height: 800, deviceScaleFactor: 1 })],
  ];
  test.each(CHANGES)('after %s the out-of-date heat map is hidden, never dimmed or stretched over the picture', async (_, change) => {
    await withPage(
      async ({ page, goto }) => {
        await goto('?time=0&SAMPLES=1&scale=0.25'); // the canvas fills the stage, at a quarter of its pixels
        await hook(page).compareWithFloat64();
        const map = () =>
          page.evaluate(() => {
            const m = /** @type {HTMLCanvasElement} */ (document.querySelector('.heat-map'));
            const v = document.getElementById('view').getBoundingClientRect();
            const r = m.getBoundingClientRect();
            return {
              shown: getComputedStyle(m).display !== 'none',
              over: [r.width, r.height],
              canvas: [v.width, v.height],
              // the map's height over the canvas's box were its pixels square: not stretched
              unstretched: (v.width * m.height) / m.width,
            };
          });
        expect((await map()).shown, 'the map, measured').toBe(true);
        await change(page);
        // what the next paint shows (a resize is laid out, and observed, before it)
        await page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => resolve(null))));
        const now = await map();
        if (now.shown) {
          now.over.forEach((v, i) => expect(Math.abs(v - now.canvas[i]), 'a map shown covers the canvas exactly').toBeLessThan(1));
          expect(Math.abs(now.unstretched - now.canvas[1]), "a map shown has the canvas's shape").toBeLessThanOrEqual(1);
        }
        await page.waitForFunction(() => window.shaderEngine.comparison().stale, { polling: 50 });
        expect((await map()).shown, 'out of date: hidden').toBe(false);
        expect(await page.$eval('.compare', (box) => box.textContent)).toMatch(/Out of date: .*its map is hidden/);
      },
      { viewport: VIEWPORT },
    );
  });

  // A refusal is not a comparison: its box is titled so, without the map's controls and legend,
  // and says why (no toast repeats it, half under the box). The reference draws the picture
  // only: a debug view compared with it would be all error.
  /** @type {Array<[string, string, {setProject?: object}, RegExp]>} */
  const REFUSALS = [
    [
      'a shader that is not the raytracer',
      '?shader=examples/pattern.glsl&size=160x90&time=0',
      {},
      /Compare with float64 is for the built-in raytracer: this shader has no frameView, sampleRadiance/,
    ],
    [
      'a multipass shader',
      '?size=160x90&time=0',
      { setProject: exportOf() },
      /Compare with float64 is for the built-in raytracer: this shader has buffers of its own/,
    ],
    [
      'a debug view',
      '?size=160x90&time=0&VIEW=1',
      {},
      /The float64 reference draws the picture, not the "Normals" view: set View to Picture to compare/,
    ],
  ];
  test.each(REFUSALS)('%s: the box says it cannot compare, and why, with no map controls', async (_, query, shader, why) => {
    await withPage(
      async ({ page, goto, warnings }) => {
        await goto(query);
        if (shader.setProject) expect((await hook(page).setProject(shader.setProject)).ok).toBe(true);
        await (await button(page, 'Compare with float64')).click();
        await page.waitForFunction(() => window.shaderEngine.comparison().error, { polling: 50 });
        const box = await page.$eval('.compare', (section) => {
          const shown = (selector) => {
            const e = /** @type {HTMLElement | null} */ (section.querySelector(selector));
            return Boolean(e && e.offsetParent !== null);
          };
          const named = (name) => [...section.querySelectorAll('button')].find((b) => b.textContent === name);
          return {
            title: section.querySelector('header strong')?.textContent,
            text: section.textContent,
            eightBit: Boolean(named('8-bit')?.offsetParent),
            map: Boolean(named('Map')?.offsetParent),
            legend: shown('.legend'),
          };
        });
        expect(box.title).toBe('Cannot compare with float64');
        expect(box.text).toMatch(why);
        expect({ eightBit: box.eightBit, map: box.map, legend: box.legend }, 'no map, so none of its controls').toEqual({
          eightBit: false,
          map: false,
          legend: false,
        });
        expect(await page.$eval('#toast', (t) => /** @type {HTMLElement} */ (t).hidden), 'no toast repeats the box').toBe(true);
        expect(warnings.some((w) => why.test(w))).toBe(true);
        expect((await hook(page).comparison()).shown).toBe(null);
        if (/VIEW=1/.test(query)) {
          const readout = await hook(page).inspect(80, 45);
          expect(readout.reference).toBe(null);
          expect(readout.referenceNote).toMatch(/draws the picture, not the "Normals" view/);
        }
      },
      { viewport: VIEWPORT },
    );
  });

  test('while a comparison runs its buttons wait, and a press does not start it again', async () => {
    await withPage(
      async ({ page, goto }) => {
        await goto('?size=640x360&time=0&SAMPLES=1');
        await hook(page).inspect(10, 10); // the readout's Compare button on the page
        await (await button(page, 'Compare with float64')).click();
        await page.waitForFunction(() => window.shaderEngine.comparison().running?.rows > 0, { polling: 20 });
        const disabled = await page.evaluate(() =>
          ['.compare header', '.inspector header'].map((where) =>
            [...document.querySelectorAll(`${where} button`)]
              .filter((b) => /Compare/.test(b.textContent ?? ''))
              .map((b) => /** @type {HTMLButtonElement} */ (b).disabled),
          ),
        );
        expect(disabled, '"Compare again" and the readout\'s "Compare with float64"').toEqual([[true], [true]]);
        const before = (await hook(page).comparison()).running;
        // the toolbar's button (enabled) does nothing while one runs
        await page.$eval('#toolbar [aria-label="Compare with float64"]', (b) => /** @type {HTMLButtonElement} */ (b).click());
        const after = (await hook(page).comparison()).running;
        expect(after?.phase, 'still the same comparison').toBe(before.phase);
        expect(after.rows).toBeGreaterThanOrEqual(before.rows);
        await (await page.$('.compare-progress button')).click(); // Cancel
        expect(
          await page.$eval(
            '.compare header',
            (h) => [...h.querySelectorAll('button')].find((b) => b.textContent === 'Compare again')?.disabled,
          ),
        ).toBe(false);
      },
      { viewport: VIEWPORT, deterministic: false },
    );
  });
});
