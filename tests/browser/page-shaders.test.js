// Any Shadertoy Image shader in the page: the three example shaders of public/examples (a
// raymarched 3D scene, a 2D pattern, and an inspector driven by iMouse, iFrame and iDate) load
// with ?shader=, run without a change, and draw the same pixels as the same file compiled in
// Shadertoy's header in a raw WebGL2 context with the same uniforms. The inspector then checks
// each input's semantics against real pointer, touch and keyboard input.
import { afterAll, describe, expect, test } from 'vitest';
import { composeImageShader } from '../../src/shadertoy/header.js';
import { assertNotBlank, expectImagesMatch } from '../support/images.js';
import { disconnect } from '../support/page.js';
import { renderRawShader } from '../support/raw-webgl/raw-webgl.js';
import {
  canvasBox,
  checkResults,
  dataAt,
  decodeInputs,
  exampleSource,
  info,
  nextFrame,
  pixel,
  readPixels,
  withPage,
} from '../support/page-helpers.js';

afterAll(disconnect);

const W = 160;
const H = 90;

// time and iMouse for the comparison: a drag released at (40, 59) that went down at (100, 30)
const EXAMPLES = [
  { name: 'raymarch', kind: 'raymarched 3D scene with a control block', time: 1.25, mouse: [100, 40, -30, -20] },
  { name: 'pattern', kind: '2D pattern', time: 2.5, mouse: [0, 0, 0, 0] },
  { name: 'inputs', kind: 'iMouse / iFrame / iDate inspector', time: 1.25, mouse: [40, 59, -100, -30] },
];

describe("example shaders run unchanged and match Shadertoy's header", () => {
  test.each(EXAMPLES.map((e) => [e.name, e.kind, e]))('%s (%s)', async (_, __, example) => {
    const query = `?shader=examples/${example.name}.glsl&size=${W}x${H}&time=${example.time}&mouse=${example.mouse.join(',')}`;
    let page;
    /** @type {number} */
    let frame;
    await withPage(async ({ page: p, goto }) => {
      await goto(query);
      page = await readPixels(p);
      frame = (await info(p)).frame;
      const state = await info(p);
      expect(state).toMatchObject({
        fileName: `${example.name}.glsl`,
        origin: 'url',
        shaderUrl: `examples/${example.name}.glsl`,
        time: example.time,
        playing: false,
      });
    });
    assertNotBlank(page, `${example.name} in the page`);

    const { code } = composeImageShader(exampleSource(example.name));
    const raw = await renderRawShader(code, {
      width: W,
      height: H,
      uniforms: { iTime: example.time, iMouse: example.mouse, iFrame: frame - 1 },
    });
    expect(raw.stage, raw.log).toBeUndefined();
    expect(raw.glError).toBe(0);
    expectImagesMatch(`example-${example.name}`, page, raw, {
      actualLabel: `${example.name} in the page`,
      expectedLabel: 'the Shadertoy-header render',
    });
  });
});

describe('uniform semantics (public/examples/inputs.glsl)', () => {
  const QUERY = `?shader=examples/inputs.glsl&size=${W}x${H}&time=1.25`;

  test('iResolution, fragCoord, iTime, iTimeDelta, iDate and every in-shader rule', async () => {
    await withPage(async ({ page, goto }) => {
      await goto(QUERY);
      const image = await readPixels(page);
      expect(
        Object.values(checkResults(image)).every((r) => r === 'pass'),
        JSON.stringify(checkResults(image), null, 1),
      ).toBe(true);
      const v = decodeInputs(image);
      expect([v.resX, v.resY, v.resZ1000]).toEqual([W, H, 1000]); // iResolution.z = 1
      expect(v.timeMs).toBe(1250);
      expect(v.delta1e5).toBe(1667); // 1/60 s while paused
      // iDate: local time of the frozen clock (2024-01-15 12:00:00, TZ=UTC); month counts from 0
      expect([v.year, v.month, v.day, v.seconds]).toEqual([2024, 0, 15, 43200]);
      // fragCoord is the pixel centre: 2 x fragCoord = 2 x + 1 on every pixel of the x cell,
      // and 2 y + 1 on every row of the y cell (rows counted from the bottom)
      for (let x = 140; x < 150; x++) for (let y = 0; y < 10; y++) expect(dataAt(image, x, y)).toBe(2 * x + 1);
      for (let x = 150; x < 160; x++) for (let y = 0; y < 10; y++) expect(dataAt(image, x, y)).toBe(2 * y + 1);
    });
  });

  test('iFrame counts drawn frames from 0, and Restart (R) sets it back to 0', async () => {
    await withPage(async ({ page, goto }) => {
      await goto(QUERY);
      const first = await readPixels(page);
      const drawn = (await info(page)).frame;
      expect(decodeInputs(first).iFrame).toBe(drawn - 1); // the first frame the page drew was iFrame 0
      const restarted = await nextFrame(page);
      await page.keyboard.press('KeyR');
      const frame0 = await restarted();
      expect(decodeInputs(frame0).iFrame).toBe(0);
      expect(frame0.iFrame).toBe(0);
      expect(decodeInputs(await readPixels(page)).iFrame).toBe(1);
      expect(decodeInputs(await readPixels(page)).iFrame).toBe(2);
    });
  });

  // Each step: what the pointer does, then the iMouse of the frame the page draws for it, in terms
  // of the device pixel (x, y) under the pointer (y up) at the press and now.
  const MOUSE_STEPS = [
    { act: 'press at (40, 30)', expect: (press, now) => [now.x, now.y, press.x, press.y] }, // z, w > 0 on the press frame
    { act: 'drag to (100, 60)', expect: (press, now) => [now.x, now.y, press.x, -press.y] }, // held: z > 0, w < 0 after it
    { act: 'release', expect: (press, now) => [now.x, now.y, -press.x, -press.y] }, // released: z < 0, xy frozen
  ];

  /**
   * Fraction of the pixels of an image row (or column) that are light grey or white.
   * @param {{width: number, height: number, data: Buffer}} image
   * @param {{row: number, column?: undefined} | {column: number, row?: undefined}} line y of the row (from the top), or x of the column
   */
  function lightFraction(image, { row, column }) {
    const points =
      row !== undefined
        ? [...Array(image.width).keys()].map((x) => [x, row])
        : [...Array(image.height - 20).keys()].map((y) => [column, y]);
    return points.filter(([x, y]) => Math.min(...pixel(image, x, y)) > 100).length / points.length;
  }

  test.each([
    ['mouse', { width: 800, height: 600, deviceScaleFactor: 1 }],
    ['touch (phone)', { width: 400, height: 700, deviceScaleFactor: 1, hasTouch: true, isMobile: true }],
  ])('iMouse from a real %s drag: signs, click position, the pixel under the pointer', async (kind, viewport) => {
    await withPage(
      async ({ page, goto }) => {
        await goto(QUERY);
        const box = await canvasBox(page);
        expect([box.width, box.height]).toEqual([W, H]);
        // where the browser says the pointer is, as the device pixel under it (y up)
        await page.evaluate(() => {
          const record = (event) => (window.__pointer = { clientX: event.clientX, clientY: event.clientY });
          document.addEventListener('pointerdown', record, true);
          document.addEventListener('pointermove', record, true);
        });
        const underPointer = async () => {
          const { clientX, clientY } = await page.evaluate(() => window.__pointer);
          return { x: Math.floor(clientX - box.left), y: Math.floor(H - (clientY - box.top)) };
        };
        /** @type {(x: number, y: number) => [number, number]} */
        const at = (x, y) => [box.left + x + 0.5, box.top + y + 0.5];
        const touch = kind !== 'mouse';
        const actions = {
          'press at (40, 30)': () =>
            touch ? page.touchscreen.touchStart(...at(40, 30)) : page.mouse.move(...at(40, 30)).then(() => page.mouse.down()),
          'drag to (100, 60)': () => (touch ? page.touchscreen.touchMove(...at(100, 60)) : page.mouse.move(...at(100, 60))),
          release: () => (touch ? page.touchscreen.touchEnd() : page.mouse.up()),
        };
        let press;
        let now;
        for (const step of MOUSE_STEPS) {
          const frame = await nextFrame(page);
          await actions[step.act]();
          const image = await frame();
          if (step.act !== 'release') now = await underPointer();
          press ??= now;
          expect(Math.abs(now.x - (step.act.includes('40') ? 40 : 100))).toBeLessThanOrEqual(1); // the pointer is where we put it
          const mouse = decodeInputs(image).mouse;
          expect(mouse, `${kind}: ${step.act}`).toEqual(step.expect(press, now));
          expect(
            Object.values(checkResults(image)).every((r) => r === 'pass'),
            `${step.act}: ${JSON.stringify(checkResults(image))}`,
          ).toBe(true);
          // the crosshair runs through the pixel under the pointer: its row and column are light,
          // the row above is not
          const row = H - 1 - now.y;
          expect(lightFraction(image, { row }), `${step.act}: crosshair row`).toBeGreaterThan(0.7);
          expect(lightFraction(image, { column: now.x }), `${step.act}: crosshair column`).toBeGreaterThan(0.7);
          expect(lightFraction(image, { row: row - 1 }), `${step.act}: the row above`).toBeLessThan(0.5);
        }
        // after the release, xy stays where the drag ended
        const released = [now.x, now.y, -press.x, -press.y];
        expect(decodeInputs(await readPixels(page)).mouse).toEqual(released);
        expect((await info(page)).mouse).toEqual(released);
      },
      { viewport },
    );
  });
});
