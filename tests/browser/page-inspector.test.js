// The pixel inspector (src/studio/inspect/inspector.js), in the real page: a pinned pixel's colour
// in float agrees with the 8-bit pixel the frame has there, for a single-pass shader, a multipass
// one (whose buffers it reads too) and the raytracer (at an edge pixel as well, where the
// adaptive anti-aliasing reads the 2x2 quad's derivatives); it follows time and controls; a
// click in Inspect mode pins a pixel instead of moving iMouse; and the raytracer's path, read
// from the shader's own path probe, is the float64 reference's, ray for ray.

import fs from 'node:fs';
import { afterAll, describe, expect, test } from 'vitest';
import { referencePixel } from '../../src/reference/render.js';
import { SHADER_FILE } from '../support/config.js';
import { disconnect } from '../support/page.js';
import { button, canvasBox, info, readPixels, withPage } from '../support/page-helpers.js';
import { exportOf } from '../support/page-multipass-helpers.js';
import { hook } from '../support/hook.js';

afterAll(disconnect);

const source = fs.readFileSync(SHADER_FILE, 'utf8');
const VIEWPORT = { width: 1280, height: 800, deviceScaleFactor: 1 };
const SIZE = [320, 180];
const DEFAULT_VIEW = `?size=${SIZE.join('x')}&time=0`;

/** Float32's unit roundoff. */
const U = 2 ** -24;

/** The inspector's readout of pixel (x, y), y from the bottom. @returns {Promise<import('../globals.js').Readout>} */
const inspect = (page, x, y) => hook(page).inspect(x, y);

/** The RGBA bytes of a frame at pixel (x, y), y from the bottom. */
function byteAt(image, x, y) {
  const i = ((image.height - 1 - y) * image.width + x) * 4;
  return [...image.data.subarray(i, i + 4)];
}

/**
 * Whether a float colour and the byte the frame holds agree within the 8-bit rounding: the byte
 * is one of the two integers nearest to clamp(f) × 255 (OpenGL ES 3.0 §2.1.6.1 lets the GPU
 * take either; "round to nearest is preferred"). A channel outside 0..1 clamps.
 */
function withinRounding(float, bytes) {
  return float.every((f, c) => Math.abs(Math.min(1, Math.max(0, f)) * 255 - bytes[c]) < 1);
}

// A single-pass shader whose channels change by many 8-bit steps from one pixel to the next, so
// that the float of the wrong pixel would not pass for the right one; blue goes past 1.
const GRADIENT = `void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(fract(fragCoord.x * 0.1234567), fract(fragCoord.y * 0.0765432), 0.2 + fragCoord.x * 0.004, 1.0);
}
`;

// A multipass shader: Buffer A holds values known here (two of them outside 0..1), Image shows
// them with a fraction, a scale and a value below 0.
const BUFFER_A = `void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(fragCoord.x / 7.0, fragCoord.y * 0.001, -2.5, 42.0);
}
`;
const IMAGE = `void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec4 a = texelFetch(iChannel0, ivec2(fragCoord), 0);
    fragColor = vec4(fract(a.x), a.y * 3.0, a.z, a.w);
}
`;
/** Buffer A's value at pixel (x, y), as the shader computes it. */
const bufferA = (x, y) => [(x + 0.5) / 7, (y + 0.5) * 0.001, -2.5, 42];

// Pixels at even and odd columns and rows (the probe draws the pixel's 2x2 quad), the corners
// (the float target grows to reach them) and, for the raytracer, a pixel on the sphere's
// silhouette that takes adaptive anti-aliasing's extra samples (found from its "Extra samples"
// view): its float must be the frame's too, derivatives and all.
/** @type {Array<[string, {setSource?: string, setProject?: object}, Array<[number, number]>]>} */
const FLOAT_CASES = [
  [
    'a single-pass shader',
    { setSource: GRADIENT },
    [
      [0, 0],
      [1, 1],
      [37, 22],
      [64, 101],
      [319, 179],
    ],
  ],
  [
    'a multipass shader',
    { setProject: exportOf({ bufferA: BUFFER_A, image: IMAGE }) },
    [
      [0, 0],
      [3, 2],
      [150, 91],
      [319, 179],
    ],
  ],
  [
    'the raytracer',
    {},
    [
      [96, 90],
      [103, 121],
      [200, 40],
      [2, 170],
    ],
  ],
];

describe('the pixel inspector', () => {
  test.each(FLOAT_CASES)(
    '%s: the float colour of a pinned pixel agrees with its 8-bit pixel within rounding',
    async (_, shader, pixels) => {
      await withPage(
        async ({ page, goto }) => {
          await goto(DEFAULT_VIEW);
          if (shader.setSource) expect(await hook(page).setSource(shader.setSource)).toEqual({ ok: true });
          if (shader.setProject) expect((await hook(page).setProject(shader.setProject)).ok).toBe(true);
          const image = await readPixels(page);
          for (const [x, y] of pixels) {
            const readout = await inspect(page, x, y);
            const bytes = byteAt(image, x, y);
            const where = `pixel ${x}, ${y}: float ${readout.color}, frame ${bytes}`;
            expect(readout.fragCoord, where).toEqual([x + 0.5, y + 0.5]);
            expect(withinRounding(readout.color, bytes), where).toBe(true);
            expect(readout.canvas, `${where}: the byte the inspector says the canvas shows`).toEqual(bytes);
            if (shader.setProject) {
              // Buffer A, read as it is (RGBA32F), and the Image pass's values outside 0..1 as they are
              const [a] = readout.buffers;
              expect(a.name).toBe('Buffer A');
              // within 8 u of the value: GLSL ES 3.00 (§4.5.1) allows a division 2.5 ulp (5 u)
              a.value.forEach((v, c) => {
                const want = bufferA(x, y)[c];
                expect(Math.abs(v - want), `${where}: Buffer A[${c}] ${v}, computed here ${want}`).toBeLessThanOrEqual(
                  8 * U * Math.abs(want),
                );
              });
              expect(readout.color[2], 'a value below 0, shown as it is').toBe(-2.5);
            } else expect(readout.buffers).toEqual([]);
            if (shader.setSource) expect(readout.path, 'no path for a shader that is not the raytracer').toBe(null);
          }
          if (shader.setSource) {
            const last = await hook(page)
              .inspection()
              .then((r) => r.readout);
            expect(last.color[2], 'blue past 1, shown as it is').toBeGreaterThan(1);
          }
        },
        { viewport: VIEWPORT },
      );
    },
  );

  test("the first pin shows the pixel's colour at once, and says the path is compiling", async () => {
    await withPage(
      async ({ page, goto }) => {
        await goto(DEFAULT_VIEW);
        // no path probe compiled yet: the colour read must not queue behind its compile
        await page.evaluate(() => {
          window.__complete = window.shaderEngine.inspect(96, 90);
        });
        const first = await page
          .waitForFunction(() => window.shaderEngine.inspection().readout, { polling: 20 })
          .then((handle) => handle.jsonValue());
        expect(first.color).toHaveLength(4);
        expect(first.path).toBe(null);
        expect(first.pathNote).toMatch(/^Compiling the path probe/);
        expect(first.complete).toBe(false);
        const complete = await page.evaluate(() => window.__complete);
        expect(complete.path?.rays.length, 'the path, once the probe compiled').toBeGreaterThan(0);
        expect(complete.color).toEqual(first.color);
      },
      { viewport: VIEWPORT },
    );
  });

  test('the pinned pixel follows time and controls', async () => {
    await withPage(
      async ({ page, goto }) => {
        await goto(DEFAULT_VIEW);
        const [x, y] = [96, 90];
        const first = await inspect(page, x, y);
        /** The first complete readout of a frame at iTime `time`. */
        const readoutAt = (time) =>
          page
            .waitForFunction(
              (t) => {
                const r = window.shaderEngine.inspection().readout;
                return r?.complete && r.frame.time === t && r;
              },
              { polling: 50 },
              time,
            )
            .then((handle) => handle.jsonValue());
        /** The first complete readout whose colour is not `color`. */
        const readoutOtherThan = (color) =>
          page
            .waitForFunction(
              (before) => {
                const r = window.shaderEngine.inspection().readout;
                return r?.complete && r.color.some((v, c) => v !== before[c]) && r;
              },
              { polling: 50 },
              color,
            )
            .then((handle) => handle.jsonValue());

        await hook(page).setTime(2.5); // the camera turns 4° a second
        const later = await readoutAt(2.5);
        expect(later.color, 'another colour once the camera has turned').not.toEqual(first.color);
        expect(withinRounding(later.color, byteAt(await readPixels(page), x, y))).toBe(true);

        // a frame under way may still have the old light: the readout that has another colour is the new light's
        await hook(page).setControls({ LIGHT_POSITION: [4, 3, 2] });
        const lit = await readoutOtherThan(later.color);
        expect(withinRounding(lit.color, byteAt(await readPixels(page), x, y))).toBe(true);
      },
      { viewport: VIEWPORT },
    );
  });

  test('Inspect: a click pins the pixel under it (not iMouse), Esc unpins, I leaves', async () => {
    await withPage(
      async ({ page, goto }) => {
        await goto(`?shader=examples/pattern.glsl&size=320x180&time=0`);
        await (await button(page, 'Inspect')).click();
        expect(await page.$eval('[aria-label="Inspect"]', (b) => b.getAttribute('aria-pressed'))).toBe('true');
        const box = await canvasBox(page);
        // the centre of pixel (40, 179 - 30): 40 columns in, 30 rows down
        await page.mouse.click(box.left + (40.5 / 320) * box.width, box.top + (30.5 / 180) * box.height);
        await page.waitForFunction(() => window.shaderEngine.inspection().readout?.complete, { polling: 50 });
        const state = await hook(page).inspection();
        expect(state.pinned).toMatchObject({ x: 40, y: 149 });
        expect((await info(page)).mouse, 'the click went to the inspector, not to iMouse').toEqual([0, 0, 0, 0]);
        expect(await page.$eval('.inspector', (p) => p.textContent)).toMatch(/fragCoord \(40\.5, 149\.5\)/);
        expect(state.readout.pathNote).toMatch(/built-in raytracer/);
        await page.keyboard.press('Escape');
        expect((await hook(page).inspection()).pinned).toBe(null);
        await page.keyboard.press('KeyI');
        expect((await hook(page).inspection()).active).toBe(false);
        expect(await page.$eval('.inspector', (p) => /** @type {HTMLElement} */ (p).hidden)).toBe(true);
      },
      { viewport: VIEWPORT },
    );
  });

  test('a lost context is said in the readout, and the readout comes back with the picture, path and all', async () => {
    await withPage(
      async ({ page, goto }) => {
        await goto(DEFAULT_VIEW);
        const before = await inspect(page, 96, 90);
        await hook(page).loseContext();
        await page.waitForFunction(() => /GPU context was lost/.test(document.querySelector('.inspector').textContent), { polling: 50 });
        await hook(page).restoreContext();
        // the path probe died with the context: it is compiled again
        const after = await page
          .waitForFunction(
            () => {
              const { readout, problem } = window.shaderEngine.inspection();
              return !problem && readout?.complete && readout.path && readout;
            },
            { polling: 50 },
          )
          .then((handle) => handle.jsonValue());
        expect(after.color).toEqual(before.color);
        expect(after.path.rays.map((r) => r.object)).toEqual(before.path.rays.map((r) => r.object));
      },
      { viewport: VIEWPORT },
    );
  });

  // Pixels of the default view (320x180, y from the bottom) whose centre ray meets the sphere and
  // then, reflected, something else (the float64 reference says what, and each pixel's eight
  // neighbours see the same objects, so no edge is in doubt).
  /** @type {Array<[string, [number, number], string[]]>} */
  const PATHS = [
    ['sphere, then the ground', [96, 90], ['sphere', 'ground', 'sky']],
    ['sphere, then the cube, then the ground', [137, 97], ['sphere', 'cube', 'ground', 'sky']],
    ['sphere, then the sky', [102, 110], ['sphere', 'sky']],
  ];

  test.each(PATHS)(
    "the raytracer's path at a pixel on the %s: the shader's own, ray for ray the float64 reference's",
    async (_, [x, y], objects) => {
      // the reference, here in Node: independent of the page's reference worker
      const view = { width: SIZE[0], height: SIZE[1], time: 0, mouse: [0, 0, 0, 0], controls: {} };
      const expected = referencePixel(source, view, x, y).path;
      await withPage(
        async ({ page, goto }) => {
          await goto(DEFAULT_VIEW);
          const readout = await inspect(page, x, y);
          expect(readout.pathNote).toBe(null);
          const rays = readout.path.rays;
          expect(rays.map((r) => r.object)).toEqual(objects);
          expect(rays.map((r) => r.id)).toEqual(expected.map((r) => r.id));
          // t within K u S (K = 32, as tests/browser/intersectors.test.js holds the intersectors), S the
          // distance the path has come from the eye, where its coordinates are taken from, plus
          // the scene's size (4)
          let travelled = 0;
          rays.forEach((ray, k) => {
            const twin = expected[k];
            if (twin.id < 0) return; // the sky: no hit to compare
            const bound = 32 * U * (travelled + twin.t + 4);
            expect(Math.abs(ray.t - twin.t), `ray ${k} (${ray.object}): t ${ray.t} against float64 ${twin.t}`).toBeLessThanOrEqual(bound);
            ray.normal.forEach((n, c) => expect(n, `ray ${k} normal`).toBeCloseTo(twin.normal[c], 4));
            expect(ray.lit, `ray ${k}: lit`).toBe(twin.lit);
            expect(ray.weight, `ray ${k}: weight`).toBeCloseTo(twin.weight, 6);
            travelled += twin.t;
          });
          // the page's own float64 answer (its worker) says the same, and the colour is within a step
          expect(readout.reference.path.map((r) => r.id)).toEqual(expected.map((r) => r.id));
          readout.reference.difference.forEach((d) => expect(Math.abs(d), 'shader − float64, in 1/255').toBeLessThan(1));
          expect(await page.$eval('.inspector table.path', (t) => t.textContent)).toMatch(new RegExp(objects.join('.*')));
        },
        { viewport: VIEWPORT },
      );
    },
  );
});
