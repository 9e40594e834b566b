// Shadertoy's Cube A pass (issue 38, item 1; src/shadertoy/cube-a.js): its texel rays are the
// directions a samplerCube lookup takes to each texel; it is composed, scheduled, read and written
// in the site's JSON as the site does; and on the page and in the command line a Cube A whose
// faces encode their own ray direction is read back along known directions, each colour computed
// here, not a golden. It reads itself as its previous frame, and Restart clears it.

import { execFile } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { promisify } from 'node:util';
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import { CUBE_A_SIZE, faceDirection } from '../../src/shadertoy/cube-a.js';
import { composePassShader } from '../../src/shadertoy/header.js';
import { frameSchedule } from '../../src/shadertoy/multipass.js';
import { fromShadertoyJson, toShadertoyJson } from '../../src/shadertoy/multipass-json.js';
import { builtPage } from '../../src/headless/page-server.js';
import { deserializeProject } from '../../src/player/io/project-files.js';
import { REPO_ROOT } from '../support/config.js';
import { readPng } from '../support/images.js';
import { editorTabs, exportJsonFile } from '../support/page-multipass-helpers.js';
import { pixel, readPixels, sharePageAcrossTests, withPage } from '../support/page-helpers.js';
import { cubeLookup } from '../support/tables/cube-lookup.js';
import { hook } from '../support/hook.js';

sharePageAcrossTests();

describe('the faces and their texels', () => {
  // texel centres across each face: corners, edges' middles and an inner texel
  const TEXELS = [0, 1, 511, 777, CUBE_A_SIZE - 1];
  test.each([0, 1, 2, 3, 4, 5])('face %i: every texel’s ray is the direction a samplerCube lookup takes to that texel', (face) => {
    for (const x of TEXELS)
      for (const y of TEXELS) {
        const { face: read, s, t } = cubeLookup(faceDirection(face, x + 0.5, y + 0.5));
        expect(read).toBe(face);
        // float64 here: the texel's own centre back, to far better than a texel
        expect(s * CUBE_A_SIZE - 0.5).toBeCloseTo(x, 9);
        expect(t * CUBE_A_SIZE - 0.5).toBeCloseTo(y, 9);
      }
  });
});

/** A channel reading Cube A, as the site writes it: type "cubemap", Cube A's id and preview file. */
const cubeInput = (channel, filter = 'linear') => ({
  id: '4dX3Rr',
  filepath: '/media/previz/cubemap00.png',
  previewfilepath: '/media/previz/cubemap00.png',
  type: 'cubemap',
  channel,
  sampler: { filter, wrap: 'clamp', vflip: 'false', srgb: 'false', internal: 'byte' },
  published: 1,
});

/** A shader with a Cube A pass and an Image pass, as the site exports it. */
const exportOf = ({ cube, cubeInputs = [], image, imageInputs = [cubeInput(0)] }) => ({
  Shader: {
    ver: '0.1',
    info: { id: 'cubeA', name: 'cube a', description: 'written here' },
    renderpass: [
      { inputs: imageInputs, outputs: [{ id: '4dfGRr', channel: 0 }], code: image, name: 'Image', description: '', type: 'image' },
      { inputs: cubeInputs, outputs: [{ id: '4dX3Rr', channel: 0 }], code: cube, name: 'Cube A', description: '', type: 'cubemap' },
    ],
  },
});

/** Cube A's faces: each texel's own ray direction, mapped from [-1, 1] to [0, 1]. */
const DIRECTION_CUBE = `void mainCubemap(out vec4 fragColor, in vec2 fragCoord, in vec3 rayOri, in vec3 rayDir) {
    fragColor = vec4(rayDir * 0.5 + 0.5, 1.0);
}`;

/**
 * Directions to read back, one per cell of a 4 × 4 grid: the six axes, rays near three corners,
 * and off-axis rays on every face (a face drawn flipped or turned shows there). None lies exactly
 * on an edge or a corner: there the texels the filter takes from the neighbouring faces are the
 * driver's choice (SwiftShader reads (1, 1, 1) as the colour of (1, 1, −1)), not the site's.
 */
const DIRECTIONS = [
  [1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0],
  [0, 0, 1], [0, 0, -1], [1, 0.9, 0.8], [-0.8, 1, -0.9],
  [0.9, -0.8, -1], [1, 0.5, 0.25], [-1, 0.25, -0.5], [0.3, 1, -0.6],
  [0.5, -1, 0.2], [-0.4, 0.2, 1], [0.6, -0.3, -1], [-0.7, -0.8, 0.75],
]; // prettier-ignore

const GRID = 4;
const CELL = 8; // pixels a side: a 32 × 32 canvas

/** The Image pass: in each cell, Cube A sampled along that cell's direction. */
const SAMPLE_IMAGE = `const vec3 DIRECTIONS[${DIRECTIONS.length}] = vec3[](${DIRECTIONS.map((d) => `vec3(${d.map((v) => v.toFixed(2)).join(', ')})`).join(', ')});
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    ivec2 cell = ivec2(fragCoord) / ${CELL};
    fragColor = vec4(texture(iChannel0, DIRECTIONS[cell.y * ${GRID} + cell.x]).rgb, 1.0);
}`;

/**
 * How far a read-back byte may be from the colour computed here: 0.5 for the 8-bit frame's
 * rounding, plus the half float's spacing below 1 (2^-11, 0.13 of a byte) and the linear filter's
 * blend of the texels around the ray, whose directions differ from it by at most a texel's width
 * (2/1024 on the face, under 0.26 of a byte once mapped to [0, 1]): under one byte in all.
 */
const BYTE_TOLERANCE = 1;

/**
 * The smallest mipmap level is made by ten halvings in half float: each may round by half a
 * half-float step (2^-12 of a value under 1, 0.06 of a byte), 0.6 of a byte in all, plus the 8-bit
 * frame's 0.5: under two bytes.
 */
const MIPMAP_TOLERANCE = 2;

/** The colour DIRECTION_CUBE stores for direction `d`, as 0–255. */
const expectedBytes = (d) => {
  const length = Math.hypot(...d);
  return d.map((v) => 255 * (v / length / 2 + 0.5));
};

/** Checks each cell's centre pixel of a 32 × 32 picture (rows top to bottom) against its direction: every direction off by more than the tolerance is listed. */
function expectDirections(image) {
  const wrong = [];
  DIRECTIONS.forEach((d, i) => {
    const x = (i % GRID) * CELL + CELL / 2;
    const yFromBottom = Math.floor(i / GRID) * CELL + CELL / 2;
    const got = pixel(image, x, image.height - 1 - yFromBottom);
    const want = expectedBytes(d);
    if (got.some((value, c) => Math.abs(value - want[c]) > BYTE_TOLERANCE)) wrong.push(`(${d}): got ${got}, want ${want.map(Math.round)}`);
  });
  expect(wrong).toEqual([]);
}

describe('Cube A in the site’s JSON and the schedule', () => {
  const { model, notes } = fromShadertoyJson(exportOf({ cube: DIRECTION_CUBE, cubeInputs: [cubeInput(1)], image: SAMPLE_IMAGE }));
  test('it is a pass of its own, read as a cube map by Image and by itself, with no note', () => {
    expect(notes).toEqual([]);
    expect(model.passes.map((p) => [p.name, p.kind])).toEqual([
      ['Image', 'image'],
      ['Cube A', 'cubemap'],
    ]);
    const schedule = frameSchedule(model);
    expect(schedule.map((s) => [s.pass.name, s.target])).toEqual([
      ['Cube A', 'cube'],
      ['Image', 'screen'],
    ]);
    const image = schedule[1].bindings[0];
    expect(image).toMatchObject({ source: 'cubebuffer', frame: 'current', samplerType: 'Cube', resolution: [1024, 1024, 1] });
    expect(schedule[0].bindings[1]).toMatchObject({ source: 'cubebuffer', frame: 'previous', samplerType: 'Cube' });
  });
  test('a buffer reads Cube A as of last frame (the site paints the buffers first), and Cube A reads a buffer as of this frame', () => {
    const json = exportOf({
      cube: DIRECTION_CUBE,
      cubeInputs: [{ ...cubeInput(0), id: '4dXGR8', type: 'buffer', filepath: '/media/previz/buffer00.png' }],
      image: SAMPLE_IMAGE,
    });
    json.Shader.renderpass.push({
      inputs: [cubeInput(0)],
      outputs: [{ id: '4dXGR8', channel: 0 }],
      code: 'void mainImage(out vec4 c, in vec2 f) { c = vec4(0.0); }',
      name: 'Buffer A',
      description: '',
      type: 'buffer',
    });
    const schedule = frameSchedule(fromShadertoyJson(json).model);
    expect(schedule.map((s) => s.pass.name)).toEqual(['Buffer A', 'Cube A', 'Image']);
    expect(schedule[0].bindings[0]).toMatchObject({ source: 'cubebuffer', frame: 'previous' });
    expect(schedule[1].bindings[0]).toMatchObject({ source: 'buffer', buffer: 'A', frame: 'current' });
  });
  test('its header declares mainCubemap, the face uniforms, and samplerCube for the channel reading it', () => {
    const { code } = composePassShader(DIRECTION_CUBE, { kind: 'cubemap', channelTypes: ['2D', 'Cube', '2D', '2D'] });
    expect(code).toContain('void mainCubemap(out vec4 c, in vec2 f, in vec3 ro, in vec3 rd);');
    expect(code).toContain('uniform vec3 unCorners[5];');
    expect(code).toContain('uniform samplerCube iChannel1;');
    expect(code).not.toContain('void mainImage(out vec4 c, in vec2 f);');
  });
  test('a shader kept in the browser before Cube A ran here (its cubemap pass in `extra`) comes back with the pass', () => {
    const json = exportOf({ cube: DIRECTION_CUBE, image: SAMPLE_IMAGE });
    const [image, cube] = json.Shader.renderpass;
    // as the page kept it then: the pass aside, and the input reading it a cubemap it could not have
    const old = fromShadertoyJson({ Shader: { ...json.Shader, renderpass: [{ ...image, inputs: [] }] } }).model;
    const sampler = /** @type {const} */ ({ filter: 'linear', wrap: 'clamp', vflip: false });
    old.passes[0].channels[0] = { kind: 'cubemap', src: '/media/previz/cubemap00.png', supported: false, sampler, extra: { id: '4dX3Rr' } };
    old.extra = { ...old.extra, unsupportedPasses: [cube] };
    const kept = deserializeProject(JSON.stringify(old));
    expect(kept.passes.map((p) => p.kind)).toEqual(['image', 'cubemap']);
    expect(kept.passes[0].channels[0]?.kind).toBe('cubebuffer');
    expect(kept.extra?.unsupportedPasses).toBeUndefined();
  });
  test.each([
    ['site', (json) => json],
    [
      'older (numeric ids, ctype, src)',
      (json) => JSON.parse(JSON.stringify(json).replaceAll('"4dX3Rr"', '41').replaceAll('"4dfGRr"', '37')),
    ],
  ])('a %s-style export survives the trip: the same model, Cube A written back as the site writes it', (_, style) => {
    const loaded = fromShadertoyJson(style(exportOf({ cube: DIRECTION_CUBE, cubeInputs: [cubeInput(1)], image: SAMPLE_IMAGE })));
    const written = toShadertoyJson(loaded.model);
    expect(fromShadertoyJson(written).model).toEqual(loaded.model);
    const cube = written.Shader.renderpass.find((p) => p.type === 'cubemap');
    expect(cube?.name).toBe('Cube A');
    expect(cube?.outputs[0].id).toBe(loaded.model.extra?.style ? 41 : '4dX3Rr');
  });
});

describe('Cube A on the page', () => {
  // within a cell the direction is one constant, so the mipmap filter reads level 0 as linear
  // does; nearest reads a texel whose ray is at most half a texel away
  test.each(['linear', 'nearest', 'mipmap'])(
    'a Cube A whose faces encode their ray direction, read with the %s filter, reads back along 16 directions as computed here',
    async (filter) => {
      await withPage(async ({ page, goto }) => {
        await goto('?size=32x32&time=0');
        const json = exportOf({ cube: DIRECTION_CUBE, image: SAMPLE_IMAGE, imageInputs: [cubeInput(0, filter)] });
        const outcome = await hook(page).setProject(json);
        expect(outcome.error ?? null).toBe(null);
        expect(outcome.notes ?? []).toEqual([]);
        expectDirections(await readPixels(page));
      });
    },
  );

  test('read with the mipmap filter, its smallest level is each face’s mean colour, made after the faces are drawn', async () => {
    // every face stores (rayDir * 0.5 + 0.5); by symmetry its mean is 0.5 but along the face's own
    // axis, 0.5 ± 0.5 m, where m is the mean over the texels of the axis component 1/|(1, a, b)|
    let sum = 0;
    for (let y = 0; y < CUBE_A_SIZE; y++)
      for (let x = 0; x < CUBE_A_SIZE; x++) sum += 1 / Math.hypot(...faceDirection(0, x + 0.5, y + 0.5));
    const m = sum / CUBE_A_SIZE ** 2;
    const axes = DIRECTIONS.slice(0, 6);
    const image = SAMPLE_IMAGE.replace(
      'texture(iChannel0, DIRECTIONS[cell.y * 4 + cell.x])',
      'textureLod(iChannel0, DIRECTIONS[cell.y * 4 + cell.x], 10.0)',
    );
    expect(image).not.toBe(SAMPLE_IMAGE);
    await withPage(async ({ page, goto }) => {
      await goto('?size=32x32&time=0');
      const json = exportOf({ cube: DIRECTION_CUBE, image, imageInputs: [cubeInput(0, 'mipmap')] });
      expect((await hook(page).setProject(json)).error ?? null).toBe(null);
      const frame = await readPixels(page);
      const wrong = axes.flatMap((d, i) => {
        const got = pixel(frame, (i % GRID) * CELL + CELL / 2, frame.height - 1 - (Math.floor(i / GRID) * CELL + CELL / 2));
        const want = d.map((v) => 255 * (0.5 + 0.5 * m * v));
        return got.some((value, c) => Math.abs(value - want[c]) > MIPMAP_TOLERANCE)
          ? [`(${d}): got ${got}, want ${want.map(Math.round)}`]
          : [];
      });
      expect(wrong).toEqual([]);
    });
  });

  test('Cube A reads itself as its previous frame (a counter of 1/255 a frame) and Restart clears it', async () => {
    // the counter's value and iFrame, read along one direction in every pixel
    const counter = exportOf({
      cube: `void mainCubemap(out vec4 c, in vec2 f, in vec3 ro, in vec3 rd) { c = vec4(texture(iChannel0, rd).x + 1.0 / 255.0, 0.0, 0.0, 1.0); }`,
      cubeInputs: [cubeInput(0, 'nearest')],
      image: `void mainImage(out vec4 c, in vec2 f) { c = vec4(texture(iChannel0, vec3(0.3, -0.5, 1.0)).x, float(iFrame) / 255.0, 0.0, 1.0); }`,
    });
    await withPage(async ({ page, goto }) => {
      await goto('?size=8x8&time=0');
      expect((await hook(page).setProject(counter)).error ?? null).toBe(null);
      const frames = [];
      for (let i = 0; i < 3; i++) frames.push(pixel(await readPixels(page), 4, 4).slice(0, 2));
      // painted before Image: Image sees this frame's count, one more than iFrame
      frames.forEach(([count, frame]) => expect(count).toBe(frame + 1));
      expect(frames.map(([, frame]) => frame - frames[0][1])).toEqual([0, 1, 2]);
      await hook(page).restart();
      const [count, frame] = pixel(await readPixels(page), 4, 4);
      expect(frame).toBeLessThan(frames[0][1] + 3);
      expect(count, 'cleared on Restart: counting again from 0 with iFrame').toBe(frame + 1);
    });
  });

  test('Restart clears every texel of Cube A, however its last band was cut', async () => {
    // A counter heavy enough that a frame is many bands (about 0.1 s each: band-planner.js), so
    // that the last band of the cube pass starts above a face's bottom row. That band's scissor
    // stays on the target, and a clear through it (three.js clears within the target's scissor)
    // cleared only the rows above it: Restart left the count of the rows below.
    const counter = exportOf({
      cube: `void mainCubemap(out vec4 c, in vec2 f, in vec3 ro, in vec3 rd) {
    float w = 0.0;
    for (int i = 0; i < 48; i++) w += sin(rd.x * float(i) + iTime);
    c = vec4(texture(iChannel0, rd).x + 1.0 / 255.0 + w * 1e-30, 0.0, 0.0, 1.0);
}`,
      cubeInputs: [cubeInput(0, 'nearest')],
      // the +Z face near its bottom row (left half) and near its top row (right half)
      image: `void mainImage(out vec4 c, in vec2 f) {
    vec3 d = f.x < 4.0 ? vec3(0.3, 0.9, 1.0) : vec3(0.3, -0.9, 1.0);
    c = vec4(texture(iChannel0, d).x, float(iFrame) / 255.0, 0.0, 1.0);
}`,
    });
    await withPage(async ({ page, goto }) => {
      await goto('?size=8x8&time=0');
      expect((await hook(page).setProject(counter)).error ?? null).toBe(null);
      const first = await readPixels(page);
      const counted = pixel(first, 2, 4)[1] + 1; // painted before Image: one more than iFrame
      expect([pixel(first, 2, 4)[0], pixel(first, 6, 4)[0]]).toEqual([counted, counted]);
      await hook(page).restart();
      const frame = await readPixels(page);
      const iFrame = pixel(frame, 2, 4)[1];
      expect([pixel(frame, 2, 4)[0], pixel(frame, 6, 4)[0]], 'cleared on Restart: counting again from 0 with iFrame').toEqual([
        iFrame + 1,
        iFrame + 1,
      ]);
    });
  });

  test('the editor shows its tab, and "Export JSON" keeps the Cube A pass', async () => {
    await withPage(async ({ page, goto }) => {
      await goto('?size=32x32&time=0');
      const json = exportOf({ cube: DIRECTION_CUBE, image: SAMPLE_IMAGE });
      expect((await hook(page).setProject(json)).error ?? null).toBe(null);
      expect((await editorTabs(page)).names).toEqual(['Cube A', 'Image']);
      const exported = JSON.parse((await exportJsonFile(page)).text);
      expect(fromShadertoyJson(exported).model).toEqual(fromShadertoyJson(json).model);
    });
  });
});

describe('Cube A in the command line', () => {
  let folder = '';
  beforeAll(async () => {
    folder = fs.mkdtempSync(path.join(os.tmpdir(), 'shaderproof-cube-'));
    await builtPage(); // the harness built dist/ for this run: no build inside a test's time
  });
  afterAll(() => fs.rmSync(folder, { recursive: true, force: true }));

  test('shaderproof render draws a JSON with a Cube A pass, with no warning, as computed here', async () => {
    fs.writeFileSync(path.join(folder, 'cube.json'), JSON.stringify(exportOf({ cube: DIRECTION_CUBE, image: SAMPLE_IMAGE })));
    const { stderr } = await promisify(execFile)(
      process.execPath,
      [path.join(REPO_ROOT, 'bin', 'shaderproof.js'), 'render', 'cube.json', '-o', 'cube.png', '--size', '32x32'],
      { cwd: folder, timeout: 100_000 },
    );
    expect(stderr).toBe('');
    const png = readPng(path.join(folder, 'cube.png'));
    expectDirections({ width: png.width, height: png.height, data: png.data });
  });
});
