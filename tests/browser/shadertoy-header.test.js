// What the site's Image header declares besides the uniforms (issue 45, item 4; header.js cites
// the player it was read in): st_assert(bool) and st_assert(bool, int), with the pixel a failed
// one gives as the site's definition computes it here; the channel structs iCh0 … iCh3 (sampler,
// size, time, loaded), which the page fills as the site does; neither in a buffer's header; and
// no `iChannel[4]` of structs, which the site no longer declares. Every earlier shader still
// compiles: the channels stay iChannel0..3 (the rest of the suite draws them).

import { describe, expect, test } from 'vitest';
import { composeImageShader, SHADERTOY_HEADER } from '../../src/shadertoy/header.js';
import { renderRawShader } from '../support/raw-webgl/raw-webgl.js';
import { sharePageAcrossTests, withPage } from '../support/page-helpers.js';
import { hook } from '../support/hook.js';

sharePageAcrossTests();

/** What mainImage writes before each case's assertions: no component of it 0 or 1. */
const WRITTEN = [0.2, 0.4, 0.6];

/**
 * The pixel the site's Image pass gives (effect.js, MakeHeader_Image, as header.js cites it):
 * the output starts at 1; a failed st_assert(cond) sets its x to -1, st_assert(cond, v) its x,
 * y, z for v 0, 1, 2 and its w for any other v; then x < 0 makes the colour red, y < 0 green,
 * z < 0 blue, w < 0 yellow, each test after the one before; alpha is 1.
 * @param {Array<[boolean, number?]>} calls each st_assert's condition and v, in the order called
 * @param {number[]} written the colour mainImage left
 */
function siteStAssertPixel(calls, written = WRITTEN) {
  const out = [1, 1, 1, 1];
  for (const [cond, v] of calls) {
    if (cond) continue;
    const component = v === undefined || v === 0 ? 0 : v === 1 ? 1 : v === 2 ? 2 : 3;
    out[component] = -1;
  }
  let color = written;
  if (out[0] < 0) color = [1, 0, 0];
  if (out[1] < 0) color = [0, 1, 0];
  if (out[2] < 0) color = [0, 0, 1];
  if (out[3] < 0) color = [1, 1, 0];
  return [...color.map((c) => Math.round(c * 255)), 255];
}

/**
 * [what, the GLSL after the colour is written, the calls it makes at a pixel of row y (0: the
 * bottom), the colour it leaves if not WRITTEN]
 * @type {Array<[string, string, (y: number) => Array<[boolean, number?]>, number[]?]>}
 */
const CASES = [
  ['no assertion', '', () => []],
  ['st_assert(true)', 'st_assert(true);', () => [[true]]],
  ['st_assert(false)', 'st_assert(false);', () => [[false]]],
  ['st_assert(true, 2)', 'st_assert(true, 2);', () => [[true, 2]]],
  ['v 0', 'st_assert(false, 0);', () => [[false, 0]]],
  ['v 1', 'st_assert(false, 1);', () => [[false, 1]]],
  ['v 2', 'st_assert(false, 2);', () => [[false, 2]]],
  ['v 3', 'st_assert(false, 3);', () => [[false, 3]]],
  ['v 7', 'st_assert(false, 7);', () => [[false, 7]]],
  ['v -1', 'st_assert(false, -1);', () => [[false, -1]]],
  [
    'x, then y: green',
    'st_assert(false, 0); st_assert(false, 1);',
    () => [
      [false, 0],
      [false, 1],
    ],
  ],
  ['z, then x: blue', 'st_assert(false, 2); st_assert(false);', () => [[false, 2], [false]]],
  [
    'w, then y: yellow',
    'st_assert(false, 3); st_assert(false, 1);',
    () => [
      [false, 3],
      [false, 1],
    ],
  ],
  ['a colour written after a failed one', 'st_assert(false, 1); c = vec4(0.9);', () => [[false, 1]], [0.9, 0.9, 0.9]],
  ['a condition per pixel', 'st_assert(f.y < 1.0, 2);', (y) => [[y + 0.5 < 1, 2]]],
];

describe('st_assert, as the site defines it', () => {
  test(`${CASES.length} cases, one a column, against the pixels the site's definition gives`, async () => {
    // one shader and one draw: column k runs case k
    const branches = CASES.map(([, glsl], k) => `    ${k ? 'else ' : ''}if (int(f.x) == ${k}) { ${glsl} }`).join('\n');
    const source = `void mainImage(out vec4 c, in vec2 f) {\n    c = vec4(${WRITTEN.join(', ')}, 0.5);\n${branches}\n}\n`;
    const height = 2;
    const raw = await renderRawShader(composeImageShader(source).code, { width: CASES.length, height });
    expect(raw.stage, raw.log).toBeUndefined();
    const wrong = [];
    CASES.forEach(([what, , calls, written], x) => {
      for (let y = 0; y < height; y++) {
        const at = ((height - 1 - y) * CASES.length + x) * 4; // rows come top to bottom
        const got = [.../** @type {Buffer} */ (raw.data).subarray(at, at + 4)];
        const expected = siteStAssertPixel(calls(y), written);
        if (got.join() !== expected.join()) wrong.push(`${what}, row ${y}: ${got} where the site gives ${expected}`);
      }
    });
    expect(wrong).toEqual([]);
  });

  test('the header declares both, in the Image pass only: a buffer calling st_assert fails to compile, as on the site', async () => {
    expect(SHADERTOY_HEADER).toContain('void st_assert(bool cond);\nvoid st_assert(bool cond, int v);\n');
    const pass = (name, type, code, outputs) => ({ inputs: [], outputs, code, name, description: '', type });
    const json = {
      Shader: {
        ver: '0.1',
        info: { id: 'tst045', name: 'asserts', description: 'written for the tests' },
        renderpass: [
          pass('Image', 'image', 'void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }', [{ id: '4dfGRr', channel: 0 }]),
          pass('Buffer A', 'buffer', 'void mainImage(out vec4 c, in vec2 f) {\n    st_assert(f.x > 0.0);\n    c = vec4(0.0);\n}', [
            { id: '4dXGR8', channel: 0 },
          ]),
        ],
      },
    };
    await withPage(async ({ page, goto }) => {
      await goto('?size=8x4&time=0');
      const outcome = await hook(page).setProject(json);
      expect(outcome.ok).toBe(false);
      expect(outcome.error).toMatch(/^Buffer A:2: error: .*st_assert/m);
    });
  });
});

describe('the channel structs iCh0 … iCh3', () => {
  test("Buffer A in iChannel0 (nearest) and iChannel1 (linear), nothing in iChannel2: each channel's texture with its own sampler, its size, its time, loaded or not", async () => {
    const image = [
      'void mainImage(out vec4 c, in vec2 f) {',
      '    vec2 uv = (f + vec2(0.25, 0.0)) / iResolution.xy; // a quarter texel right of the centre',
      '    bool ok = texelFetch(iCh0.sampler, ivec2(f), 0) == texelFetch(iChannel0, ivec2(f), 0)',
      '        && iCh0.loaded == 1 && iCh1.loaded == 1 && iCh2.loaded == 0',
      '        && iCh0.size == iChannelResolution[0] && iCh0.size == vec3(8.0, 4.0, 1.0) && iCh2.size == vec3(0.0)',
      '        && iCh0.time == iChannelTime[0];',
      '    c = vec4(texture(iCh0.sampler, uv).r, texture(iCh1.sampler, uv).r, ok ? 1.0 : 0.0, 1.0);',
      '}',
    ].join('\n');
    const bufferA = 'void mainImage(out vec4 c, in vec2 f) { c = vec4(f.x / 8.0, 0.0, 0.0, 1.0); }';
    const input = (channel, filter) => ({
      id: '4dXGR8',
      channel,
      type: 'buffer',
      filepath: '/media/previz/buffer00.png',
      sampler: { filter, wrap: 'clamp', vflip: 'false', srgb: 'false', internal: 'byte' },
    });
    const json = {
      Shader: {
        ver: '0.1',
        info: { id: 'tst045', name: 'structs', description: 'written for the tests' },
        renderpass: [
          {
            inputs: [input(0, 'nearest'), input(1, 'linear')],
            outputs: [{ id: '4dfGRr', channel: 0 }],
            code: image,
            name: 'Image',
            description: '',
            type: 'image',
          },
          { inputs: [], outputs: [{ id: '4dXGR8', channel: 0 }], code: bufferA, name: 'Buffer A', description: '', type: 'buffer' },
        ],
      },
    };
    await withPage(async ({ page, goto }) => {
      await goto('?size=8x4&time=0');
      const outcome = await hook(page).setProject(json);
      expect(outcome.error ?? null).toBe(null);
      const { width, data } = await hook(page).readPixels();
      const bytes = Buffer.from(data, 'base64');
      for (let x = 0; x < width; x++) {
        const [r, g, b, a] = bytes.subarray(x * 4, x * 4 + 4);
        // texel x holds (x + 0.5) / 8: nearest reads it, linear a quarter of the next (the last clamps)
        expect([r, b, a], `column ${x}`).toEqual([Math.round(((x + 0.5) / 8) * 255), 255, 255]);
        // 1 of 255: the filter's weights are fixed-point on the GPU
        expect(Math.abs(g - Math.round((Math.min(x + 0.75, 7.5) / 8) * 255)), `column ${x}: linear`).toBeLessThanOrEqual(1);
      }
    });
  });

  test("the older iChannel[4] of structs is not declared (the site's header declares it no more)", async () => {
    const raw = await renderRawShader(
      composeImageShader('void mainImage(out vec4 c, in vec2 f) { c = vec4(iChannel[0].resolution, 1.0); }').code,
      { width: 2, height: 2 },
    );
    expect(raw.stage).toBe('compile');
    expect(raw.log).toMatch(/iChannel/);
  });
});
