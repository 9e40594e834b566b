// The progressive raytracer (issue 13): its tabs are built from shaders/raytrace.glsl
// (src/raytracer/progressive.js), its fingerprint covers every control, its jitter is the float64
// reference's, its tabs compile in Shadertoy's exact header, and on SwiftShader 64 still frames
// converge to the reference's 64 samples of the same sequence, then restart from one sample
// after a camera change.
import fs from 'node:fs';
import { afterAll, describe, expect, test } from 'vitest';
import { parseControls } from '../../src/shadertoy/controls.js';
import { composeCommonShader, hostControlBlock } from '../../src/shadertoy/header.js';
import {
  MAX_SAMPLES,
  RAYTRACE_FIRST_BUFFER_LINE,
  fingerprintInputs,
  progressiveJitter,
  progressiveTabs,
} from '../../src/raytracer/progressive.js';
import { imageError, formatImageError } from '../../src/reference/error.js';
import { renderReference } from '../../src/reference/render.js';
import { SHADER_FILE } from '../support/config.js';
import { disconnect, decodeRgba } from '../support/page.js';
import { composeModel, runPasses } from '../support/multipass-runner.js';

afterAll(disconnect);

const source = fs.readFileSync(SHADER_FILE, 'utf8');
const tabs = progressiveTabs(source);

describe('progressive tabs, built from raytrace.glsl', () => {
  test('Buffer A holds the file verbatim, its mainImage renamed by a macro; Common reads no uniform', () => {
    expect(tabs.bufferA.startsWith('#define EDGE_TESTS 0\n#define mainImage raytraceMainImage\n' + source + '#undef mainImage\n')).toBe(
      true,
    );
    expect(tabs.bufferA.split('\n')[RAYTRACE_FIRST_BUFFER_LINE - 1]).toBe(source.split('\n')[0]);
    expect(tabs.bufferA).toMatch(/void mainImage\(out vec4 fragColor, in vec2 fragCoord\)/);
    expect(tabs.image).toMatch(/void mainImage\(out vec4 fragColor, in vec2 fragCoord\)/);
    expect(tabs.common).not.toMatch(/\bi(Time|Resolution|Mouse|Frame|Channel\d)\b/);
  });

  test('the fingerprint hashes iResolution, iMouse, iTime and every component of every control', () => {
    const controls = parseControls(source);
    expect(controls.length).toBeGreaterThan(20);
    const inputs = fingerprintInputs(controls);
    for (const name of ['iResolution.x', 'iResolution.y', 'iMouse.x', 'iMouse.y', 'iMouse.z', 'iMouse.w', 'iTime'])
      expect(inputs).toContain(name);
    const size = { float: 1, int: 1, bool: 1, vec2: 2, vec3: 3, vec4: 4 };
    for (const c of controls) {
      const mine = inputs.filter((e) => new RegExp(`\\b${c.name}\\b`).test(e));
      expect(mine.length, `${c.name} (${c.type}) in the fingerprint`).toBe(size[c.type]);
      for (const e of mine) expect(tabs.bufferA, `${e} hashed in Buffer A`).toContain(`h = progressiveMix(h, ${e});`);
    }
    // One source of truth: a control added to the block is in the fingerprint with no other edit.
    const added = source.replace('#endif', 'const vec2  NEW_KNOB = vec2(1.0); // ui: New knob | 0 .. 2\n#endif');
    expect(progressiveTabs(added).bufferA).toContain('h = progressiveMix(h, NEW_KNOB.y);');
  });

  test('the controls are the raytracer’s and the sample-count switch', () => {
    expect(tabs.controls.map((c) => c.name)).toEqual([...parseControls(source).map((c) => c.name), 'SHOW_SAMPLE_COUNT']);
  });

  test('the model: Buffer A reads itself, Image reads Buffer A', () => {
    const [a, image] = tabs.model.passes;
    expect(a).toMatchObject({ kind: 'buffer', buffer: 'A', channels: [{ kind: 'buffer', buffer: 'A' }, null, null, null] });
    expect(image).toMatchObject({ kind: 'image', channels: [{ kind: 'buffer', buffer: 'A' }, null, null, null] });
  });

  test('the jitter is a deterministic sequence in [0, 1) of multiples of 2^-24, different per pixel', () => {
    const seen = new Set();
    for (let n = 0; n < 64; n++) {
      const [x, y] = progressiveJitter(5, 7, n);
      for (const v of [x, y]) {
        expect(v).toBeGreaterThanOrEqual(0);
        expect(v).toBeLessThan(1);
        expect(Number.isInteger(v * 2 ** 24)).toBe(true);
      }
      seen.add(`${x},${y}`);
    }
    expect(seen.size).toBe(64);
    expect(progressiveJitter(5, 7, 3)).toEqual(progressiveJitter(5, 7, 3));
    expect(progressiveJitter(5, 7, 0)).not.toEqual(progressiveJitter(6, 7, 0));
    // Low discrepancy: 64 samples put 4 +- 2 points in each of the 16 cells of a 4x4 grid.
    const cells = new Array(16).fill(0);
    for (let n = 0; n < 64; n++) {
      const [x, y] = progressiveJitter(2, 3, n);
      cells[Math.floor(x * 4) + 4 * Math.floor(y * 4)]++;
    }
    for (const c of cells) expect(Math.abs(c - 4)).toBeLessThanOrEqual(2);
  });

  test('the reference averages the same samples: one sample is the jittered point sample', () => {
    const view = { width: 8, height: 6, time: 0, mouse: [0, 0, 0, 0] };
    const one = renderReference(source, view, { mode: 'progressive', samples: 1 });
    const two = renderReference(source, view, { mode: 'progressive', samples: 2 });
    expect(one.rgb.length).toBe(8 * 6 * 3);
    expect(Array.from(one.rgb)).not.toEqual(Array.from(two.rgb));
    expect(MAX_SAMPLES).toBeGreaterThanOrEqual(64);
  });
});

// 160x90: big enough for every object and edge of the default view, small enough that the
// float64 reference's 64 samples per pixel take seconds.
const WIDTH = 160;
const HEIGHT = 90;
const FRAMES = 64;

/** Buffer A's floats as an image of means, rows top to bottom (GL reads bottom-up). */
function meanImage(floats, width, height) {
  const rgb = new Float64Array(width * height * 3);
  for (let row = 0; row < height; row++) {
    const y = height - 1 - row;
    for (let x = 0; x < width; x++) {
      const i = (y * width + x) * 4;
      const count = x === 0 && y < 2 ? floats[i + 4 + 3] : floats[i + 3];
      for (let c = 0; c < 3; c++) rgb[(row * width + x) * 3 + c] = Math.min(Math.max(floats[i + c] / count, 0), 1);
    }
  }
  return { width, height, rgb };
}

function counts(floats, width, height) {
  const out = new Set();
  for (let y = 0; y < height; y++) for (let x = 1; x < width; x++) out.add(floats[(y * width + x) * 4 + 3]);
  return [...out];
}

describe('progressive raytracer on SwiftShader', () => {
  test('its tabs compile in Shadertoy’s header, bare (as pasted) and with the page’s host block', async () => {
    for (const hostBlock of ['', hostControlBlock(tabs.controls)]) {
      const passes = composeModel(tabs.model, { hostBlock });
      const result = await runPasses(passes, { width: 4, height: 4, frames: [{ capture: true }] });
      expect(result.error, `${result.error}\n${result.log ?? ''}`).toBeUndefined();
    }
  });

  test('its Common tab compiles on its own as the site checks it (raytrace.glsl there would not: it reads iTime)', async () => {
    const alone = (code) =>
      runPasses([{ name: 'Common', target: 'screen', code: composeCommonShader(code).code, bindings: [null, null, null, null] }], {
        width: 1,
        height: 1,
        frames: [{}],
      });
    expect((await alone(tabs.common)).error).toBeUndefined();
    const raytracer = await alone(source);
    expect(raytracer.error).toMatch(/Common failed to compile/);
    expect(raytracer.log).toMatch(/iTime/);
  });

  test(`${FRAMES} still frames converge to the float64 reference with ${FRAMES} samples of the same sequence; a camera change restarts from one`, async () => {
    // (camera above the ground: an eye under the plane sees its grazing horizon differently in float32)
    const moved = [40, 70, 40, -70];
    const frames = [
      ...Array.from({ length: FRAMES }, (_, i) => ({ capture: i === FRAMES - 1 })),
      { uniforms: { iMouse: moved }, capture: true },
    ];
    const result = await runPasses(composeModel(tabs.model), { width: WIDTH, height: HEIGHT, frames });
    expect(result.error, `${result.error}\n${result.log ?? ''}`).toBeUndefined();
    const [still, after] = result.captures;

    expect(counts(still.buffers.A, WIDTH, HEIGHT)).toEqual([FRAMES]);
    const reference = renderReference(
      source,
      { width: WIDTH, height: HEIGHT, time: 0, mouse: [0, 0, 0, 0] },
      { mode: 'progressive', samples: FRAMES },
    );
    const floatError = imageError(meanImage(still.buffers.A, WIDTH, HEIGHT), reference);
    const screen = { width: WIDTH, height: HEIGHT, data: decodeRgba(still.screen, WIDTH, HEIGHT, 'progressive image') };
    const screenError = imageError(screen, reference);
    console.log(
      `progressive, ${FRAMES} frames at ${WIDTH}x${HEIGHT}: buffer mean ${formatImageError(floatError)}; image ${formatImageError(screenError)}`,
    );
    expect(floatError.nonFinite).toBe(0);
    expect(screenError.rmse).toBeLessThan(2e-3);
    expect(screenError.maxAbs).toBeLessThanOrEqual(8 / 255);

    // After the camera moved: every pixel holds one sample again, the new view's first.
    expect(counts(after.buffers.A, WIDTH, HEIGHT)).toEqual([1]);
    const first = renderReference(source, { width: WIDTH, height: HEIGHT, time: 0, mouse: moved }, { mode: 'progressive', samples: 1 });
    const afterError = imageError({ width: WIDTH, height: HEIGHT, data: decodeRgba(after.screen, WIDTH, HEIGHT, 'after') }, first);
    console.log(`progressive, one frame after the camera moved: ${formatImageError(afterError)}`);
    expect(afterError.rmse).toBeLessThan(2e-3);
    expect(afterError.over2).toBeLessThan(1e-3);
  });

  test('restarts on a time change, a resize and a Restart (iFrame 0), and keeps counting otherwise', async () => {
    const t1 = { iTime: 1 };
    /** @type {Array<{uniforms?: object, capture?: boolean, resize?: [number, number]}>} */
    const frames = [
      { capture: true }, // 1 sample
      {},
      { capture: true }, // 3
      { uniforms: t1, capture: true }, // the time moved: 1
      { uniforms: t1 },
      { uniforms: t1, capture: true }, // 3
      { uniforms: t1, resize: [12, 6], capture: true }, // resized: 1
      { uniforms: { ...t1, iFrame: 0 }, capture: true }, // Restart: 1
      { uniforms: { ...t1, iFrame: 1 }, capture: true }, // 2
    ];
    const result = await runPasses(composeModel(tabs.model), { width: 16, height: 8, frames });
    expect(result.error, `${result.error}\n${result.log ?? ''}`).toBeUndefined();
    expect(result.captures.map((c) => counts(c.buffers.A, c.width, c.height))).toEqual([[1], [3], [1], [3], [1], [1], [2]]);
  });

  test('SHOW_SAMPLE_COUNT draws the count at the top left and nothing else', async () => {
    const run = async (show) => {
      const passes = composeModel(tabs.model, { hostBlock: hostControlBlock(tabs.controls, { SHOW_SAMPLE_COUNT: show }) });
      const result = await runPasses(passes, {
        width: 64,
        height: 36,
        frames: Array.from({ length: 12 }, (_, i) => ({ capture: i === 11 })),
      });
      expect(result.error, `${result.error}\n${result.log ?? ''}`).toBeUndefined();
      return decodeRgba(result.captures[0].screen, 64, 36, 'image');
    };
    const [plain, labelled] = [await run(0), await run(1)];
    // "12" in 3-pixel cells after a one-cell margin: rows 0..20, columns 0..26 (two digits and a gap).
    let inside = 0;
    let outside = 0;
    for (let row = 0; row < 36; row++) {
      for (let x = 0; x < 64; x++) {
        const i = (row * 64 + x) * 4;
        const differs = [0, 1, 2].some((c) => plain[i + c] !== labelled[i + c]);
        if (row < 21 && x < 27) inside += differs ? 1 : 0;
        else outside += differs ? 1 : 0;
      }
    }
    expect(outside).toBe(0);
    expect(inside).toBeGreaterThan(100);
    // The "1" of "12": its middle column (cells x = 1, at pixels 6..8 after the margin) is white.
    const at = (x, row) => [...labelled.subarray((row * 64 + x) * 4, (row * 64 + x) * 4 + 3)];
    expect(at(7, 10)).toEqual([255, 255, 255]);
    expect(at(4, 10)).toEqual([0, 0, 0]);
  });
});
