// Shadertoy's multipass in the page (issue 13): buffers render in the order A, B, C, D, then
// Image; a pass reading itself sees its own last frame, an earlier buffer this frame's output, a
// later one last frame's; Common is prepended to every pass; Restart clears every buffer and
// iFrame; a resize keeps what the buffers hold; the keyboard texture; per-channel filter and
// wrap. Each case is a small shader written here, given to the page as Shadertoy's JSON export
// (the older numeric-id style: buffers 257–260, the keyboard 33).

import { unzipSync } from 'fflate';
import { PNG } from 'pngjs';
import { describe, expect, test } from 'vitest';
import { info, nextFrame, pixel, readPixels, withPage, sharePageAcrossTests } from '../support/page-helpers.js';
import { hook } from '../support/hook.js';

// not a test of loading the page: the tests share one, brought to each view by open()
sharePageAcrossTests();

const SIZE = 'size=32x18&time=0'; // paused: each readPixels() draws exactly one frame

const IDS = { A: 257, B: 258, C: 259, D: 260, keyboard: 33 };

/**
 * An input of a pass, as the export writes it.
 * @param {number} channel
 * @param {'A' | 'B' | 'C' | 'D' | 'keyboard'} what
 * @param {{filter?: string, wrap?: string}} [sampler]
 */
function input(channel, what, { filter = 'nearest', wrap = 'clamp' } = {}) {
  return {
    id: IDS[what],
    channel,
    ctype: what === 'keyboard' ? 'keyboard' : 'buffer',
    src: what === 'keyboard' ? '/presets/tex00.jpg' : `/media/previz/buffer0${'ABCD'.indexOf(what)}.png`,
    sampler: { filter, wrap, vflip: 'false', srgb: 'false', internal: 'byte' },
  };
}

/**
 * A Shadertoy export: `passes` maps 'Common', 'A'..'D', 'Image' to {code, inputs}.
 * @param {Record<string, {code: string, inputs?: object[]}>} passes
 */
function exportOf(passes) {
  const renderpass = Object.entries(passes).map(([name, { code, inputs = [] }]) => {
    if (name === 'Common') return { inputs: [], outputs: [], code, name: 'Common', description: '', type: 'common' };
    if (name === 'Image') return { inputs, outputs: [{ id: 37, channel: 0 }], code, name: 'Image', description: '', type: 'image' };
    return { inputs, outputs: [{ id: IDS[name], channel: 0 }], code, name: `Buffer ${name}`, description: '', type: 'buffer' };
  });
  return { Shader: { ver: '0.1', info: { id: 'test', name: 'test', description: 'written here' }, renderpass } };
}

/** An Image pass that shows channel 0's texel under the pixel, each component over 255. */
const SHOW_CHANNEL0 = `void mainImage(out vec4 c, in vec2 p) { c = vec4(texelFetch(iChannel0, ivec2(p), 0).xyz / 255.0, 1.0); }`;

/** Opens the page and runs `json`, checking it compiled. */
async function run(page, goto, json, query = SIZE) {
  await goto(`?${query}`);
  const outcome = await hook(page).setProject(json);
  expect(outcome.error ?? null).toBe(null);
  return outcome;
}

/**
 * Runs an Image pass that reads the keyboard in iChannel0 and shows `rgb` (texel(key, row) is the
 * keyboard texture's texel).
 * @param {string} rgb three GLSL floats
 */
async function runKeyboardShader(page, goto, rgb) {
  const code = `float texel(int key, int row) { return texelFetch(iChannel0, ivec2(key, row), 0).x; }
void mainImage(out vec4 c, in vec2 p) { c = vec4(${rgb}, 1.0); }`;
  return run(page, goto, exportOf({ Image: { code, inputs: [input(0, 'keyboard')] } }));
}

describe('passes and their order', () => {
  test('a pass reading itself sees its last frame: a counter that goes up by one each frame, with iFrame', async () => {
    await withPage(async ({ page, goto }) => {
      await run(
        page,
        goto,
        exportOf({
          A: {
            code: `void mainImage(out vec4 c, in vec2 p) { c = vec4(texelFetch(iChannel0, ivec2(p), 0).x + 1.0, float(iFrame), 0.0, 1.0); }`,
            inputs: [input(0, 'A')],
          },
          Image: { code: SHOW_CHANNEL0, inputs: [input(0, 'A')] },
        }),
      );
      const frames = [];
      for (let i = 0; i < 3; i++) frames.push(pixel(await readPixels(page), 5, 5));
      const [first] = frames;
      expect(first[0]).toBeGreaterThan(0);
      expect(frames).toEqual([0, 1, 2].map((k) => [first[0] + k, first[1] + k, 0]));
    });
  });

  test('a buffer reads an earlier buffer as of this frame and a later one as of last frame; Common is in every pass', async () => {
    await withPage(async ({ page, goto }) => {
      const frameValue = `void mainImage(out vec4 c, in vec2 p) { c = vec4(twice(float(iFrame)) / 2.0); }`;
      const copy0 = `void mainImage(out vec4 c, in vec2 p) { c = texelFetch(iChannel0, ivec2(p), 0); }`;
      await run(
        page,
        goto,
        exportOf({
          Common: { code: 'float twice(float x) { return 2.0 * x; }' },
          A: { code: frameValue },
          B: { code: copy0, inputs: [input(0, 'A')] }, // A is earlier: this frame's
          C: { code: copy0, inputs: [input(0, 'D')] }, // D is later: last frame's
          D: { code: frameValue },
          Image: {
            code: `void mainImage(out vec4 c, in vec2 p) {
    ivec2 q = ivec2(p);
    c = vec4(texelFetch(iChannel0, q, 0).x, texelFetch(iChannel1, q, 0).x, twice(float(iFrame)) / 2.0, 255.0) / 255.0;
}`,
            inputs: [input(0, 'B'), input(1, 'C')],
          },
        }),
      );
      await readPixels(page);
      const [b, c, frame] = pixel(await readPixels(page), 3, 3);
      expect(frame).toBeGreaterThan(0);
      expect(b, 'B read A of this frame').toBe(frame);
      expect(c, 'C read D of last frame').toBe(frame - 1);
    });
  });
});

describe('Restart, resize and inputs', () => {
  const COUNTER = exportOf({
    A: {
      code: `void mainImage(out vec4 c, in vec2 p) { c = vec4(texelFetch(iChannel0, ivec2(p), 0).x + 1.0, float(iFrame), 0.0, 1.0); }`,
      inputs: [input(0, 'A')],
    },
    Image: { code: SHOW_CHANNEL0, inputs: [input(0, 'A')] },
  });

  test('Restart clears every buffer and sets iFrame to 0', async () => {
    await withPage(async ({ page, goto }) => {
      await run(page, goto, COUNTER);
      for (let i = 0; i < 3; i++) await readPixels(page);
      expect(pixel(await readPixels(page), 5, 5)[0]).toBeGreaterThan(3);
      await hook(page).restart();
      // the counter starts again with iFrame: one more than iFrame in every frame after
      const [count, frame] = pixel(await readPixels(page), 5, 5);
      expect(frame).toBeLessThan(3);
      expect(count).toBe(frame + 1);
    });
  });

  test('a resize keeps what the buffers hold, texel for texel, where the new size overlaps the old', async () => {
    await withPage(
      async ({ page, goto }) => {
        await run(page, goto, COUNTER, 'time=0');
        for (let i = 0; i < 3; i++) await readPixels(page);
        const before = await readPixels(page);
        const counted = pixel(before, 2, before.height - 3)[0]; // lower left: kept by a shrink
        await page.setViewport({ width: 200, height: 150 });
        await page.waitForFunction((w) => window.shaderEngine.info().width !== w, {}, before.width);
        const after = await readPixels(page);
        expect(after.width).toBeLessThan(before.width);
        expect(pixel(after, 2, after.height - 3)[0], 'the count went on where the buffer was kept').toBeGreaterThan(counted);
        expect((await info(page)).frame).toBeGreaterThan(4); // iFrame kept counting
      },
      { viewport: { width: 320, height: 240 } },
    );
  });

  test('the keyboard texture: held, pressed this frame, toggled per press', async () => {
    await withPage(async ({ page, goto }) => {
      await runKeyboardShader(page, goto, 'texel(65, 0), texel(65, 1), texel(65, 2)');
      expect(pixel(await readPixels(page), 1, 1)).toEqual([0, 0, 0]);
      // the frame a key-down asks for has it pressed; that is over by the next one
      const pressedFrame = await nextFrame(page);
      await page.keyboard.down('KeyA');
      expect(pixel(await pressedFrame(), 1, 1), 'held, pressed, toggled on').toEqual([255, 255, 255]);
      expect(pixel(await readPixels(page), 1, 1), 'still held; pressed only on its first frame').toEqual([255, 0, 255]);
      await page.keyboard.up('KeyA');
      expect(pixel(await readPixels(page), 1, 1), 'up; the toggle stays').toEqual([0, 0, 255]);
      await page.keyboard.press('KeyA');
      expect(pixel(await readPixels(page), 1, 1), 'a second press toggles off').toEqual([0, 0, 0]);
    });
  });

  // One test of "is the user typing" for the page's shortcuts and the shader's keys (issue 17):
  // they disagreed on a focused slider, whose keys went to the shortcuts but not to the shader.
  test('keys on a focused slider reach the shader, but for those the slider moves on', async () => {
    await withPage(async ({ page, goto }) => {
      await runKeyboardShader(page, goto, 'texel(65, 2), texel(39, 2), 0.0'); // red: A toggled; green: ArrowRight (39) toggled
      await page.focus('#toolbar input[type="range"]');
      await page.keyboard.press('KeyA');
      expect(pixel(await readPixels(page), 1, 1), "A, typed on the time slider, is the shader's").toEqual([255, 0, 0]);
      await page.keyboard.press('ArrowRight');
      await page.waitForFunction(() => window.shaderEngine.info().time > 0, { polling: 20 });
      expect(pixel(await readPixels(page), 1, 1), "ArrowRight moved the slider, and is not the shader's").toEqual([255, 0, 0]);
      await page.keyboard.press('Space'); // a page shortcut still: Play
      expect((await info(page)).playing).toBe(true);
    });
  });

  test('each channel samples with its own filter and wrap', async () => {
    await withPage(async ({ page, goto }) => {
      // Buffer A: 0 in its left half, 255 in its right half
      const halves = `void mainImage(out vec4 c, in vec2 p) { c = vec4(p.x < iResolution.x / 2.0 ? 0.0 : 1.0); }`;
      // at uv.x = 0.5 (the edge between the halves) and 1.25 (past the right edge)
      const sample = `void mainImage(out vec4 c, in vec2 p) {
    float y = 0.5;
    c = vec4(texture(iChannel0, vec2(0.5, y)).x, texture(iChannel1, vec2(0.5, y)).x, texture(iChannel2, vec2(1.25, y)).x, 1.0);
}`;
      await run(
        page,
        goto,
        exportOf({
          A: { code: halves },
          Image: {
            code: sample,
            inputs: [
              input(0, 'A', { filter: 'linear' }),
              input(1, 'A', { filter: 'nearest' }),
              input(2, 'A', { filter: 'nearest', wrap: 'repeat' }),
            ],
          },
        }),
      );
      await readPixels(page);
      const [linear, nearest, repeated] = pixel(await readPixels(page), 1, 1);
      expect(Math.abs(linear - 128), `linear filtering halfway between 0 and 1 gave ${linear}`).toBeLessThanOrEqual(1);
      expect(nearest).toBe(255);
      expect(repeated, 'wrapped round to the left half').toBe(0);
    });
  });

  test('a recording of a multipass shader draws every pass each frame, at the canvas size, from cleared buffers', async () => {
    await withPage(async ({ page, goto }) => {
      await run(page, goto, COUNTER);
      for (let i = 0; i < 3; i++) await readPixels(page); // the live buffers have counted a while
      const result = await hook(page).record({ format: 'png', frames: 4, fps: 10, width: 64, height: 64 });
      expect([result.width, result.height], 'the canvas size, whatever was asked').toEqual([32, 18]);
      const files = unzipSync(new Uint8Array(Buffer.from(result.data, 'base64')));
      const counts = Object.keys(files)
        .sort()
        .map((name) => {
          const image = PNG.sync.read(Buffer.from(files[name]));
          const at = (5 * image.width + 5) * 4;
          return [image.data[at], image.data[at + 1]]; // the count, iFrame
        });
      expect(counts).toEqual([
        [1, 0],
        [2, 1],
        [3, 2],
        [4, 3],
      ]);
    });
  });
});
