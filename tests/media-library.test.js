// Conformance of the site's media library (issue 37, items 2 and 3): textures, cubemaps and
// volumes a Shadertoy JSON names by the site's paths, from a media folder (the page's ?media=,
// the command line's --media DIR and --fetch-media), each read back through tiny shaders and
// checked against what the test computes itself from the files it wrote:
// - a texture through four samplers (nearest, linear, mipmap; clamp, repeat; vflip on and off);
// - a cubemap's 24 quadrants, with vflip off and on, where the texel a direction reads follows
//   the OpenGL ES 3.0 cube map selection table (§3.8.10, Table 3.21) and the site's upload
//   (effect.js / piLibs.js, src/shadertoy/media.js: faces in file order, each flipped with vflip,
//   +Y and −Y traded);
// - volumes of the site's .bin format (bytes of three channels, float of one), every texel;
// - a grey-noise texture the site uploads as one channel by its asset id;
// - music a buffer pass names: its 512 x 2 texture and iChannelTime (music-fixture.js).
// No file of the site's media is used: every one is made here.

import { execFile } from 'node:child_process';
import fs from 'node:fs';
import http from 'node:http';
import os from 'node:os';
import path from 'node:path';
import { promisify } from 'node:util';
import { PNG } from 'pngjs';
import { describe, expect, test } from 'vitest';
import { REPO_ROOT } from './harness/config.js';
import { decodeWav } from '../src/shared/wav.js';
import { cubeFaceOrder, mediaFiles, mediaPath, parseVolume, writeVolume } from '../src/shadertoy/media.js';
import { pixel, readPixels, sharePageAcrossTests, withPage, withServedDir } from './page-helpers.js';
import { MUSIC_READER, checkMusic, toneSamples, wav } from './music-fixture.js';
import { cubeLookup } from './cube-lookup.js';
import { loadNotes } from './page-multipass-helpers.js';

const BIN = path.join(REPO_ROOT, 'bin', 'shaderproof.js');
const run = promisify(execFile);

/** 8-bit output of a value the GPU filtered (an average of texels): one step of rounding each way. */
const FILTERED = 1;

// ---- the media, made here ---------------------------------------------------------------------

/** A w × h PNG from a function of (x, y), y counted from the file's top row. */
function png(width, height, colourAt) {
  const out = new PNG({ width, height });
  for (let y = 0; y < height; y++) for (let x = 0; x < width; x++) out.data.set([...colourAt(x, y), 255], (y * width + x) * 4);
  return PNG.sync.write(out);
}

/** The 2 × 2 texture, by the file's rows (top first). */
const TEXELS = [
  [
    [200, 0, 0],
    [0, 200, 0],
  ],
  [
    [0, 0, 200],
    [100, 100, 100],
  ],
];
const AVERAGE = [0, 1, 2].map((c) => TEXELS.flat().reduce((sum, t) => sum + t[c], 0) / 4);

/** Cube face `f`'s texel at the file's (row, col): every quadrant of every face its own colour. */
const faceTexel = (f, row, col) => [20 + 40 * f, 30 + 60 * (row * 2 + col), 77];

/** The volume of bytes, three channels: texel (x, y, z) is (40 + 100x, 40 + 100y, 40 + 100z). */
const byteTexel = (x, y, z) => [40 + 100 * x, 40 + 100 * y, 40 + 100 * z];
/** The volume of float, one channel. */
const floatTexel = (x, y, z) => (1 + x + 2 * y + 4 * z) / 10;
const CORNERS = [0, 1, 2, 3, 4, 5, 6, 7].map((i) => /** @type {[number, number, number]} */ ([i & 1, (i >> 1) & 1, (i >> 2) & 1]));

function writeMedia(dir) {
  const a = path.join(dir, 'a');
  fs.mkdirSync(a, { recursive: true });
  fs.writeFileSync(
    path.join(a, 'tex.png'),
    png(2, 2, (x, y) => TEXELS[y][x]),
  );
  mediaFiles({ kind: 'cubemap', src: '/media/a/cube.png' }).forEach((file, f) =>
    fs.writeFileSync(
      path.join(dir, file),
      png(2, 2, (x, y) => faceTexel(f, y, x)),
    ),
  );
  const bytes = CORNERS.flatMap(([x, y, z]) => byteTexel(x, y, z));
  fs.writeFileSync(path.join(a, 'bytes.bin'), writeVolume({ width: 2, height: 2, depth: 2, channels: 3, data: Uint8Array.from(bytes) }));
  const floats = CORNERS.map(([x, y, z]) => floatTexel(x, y, z));
  fs.writeFileSync(
    path.join(a, 'floats.bin'),
    writeVolume({ width: 2, height: 2, depth: 2, channels: 1, format: 'float', data: Float32Array.from(floats) }),
  );
  fs.writeFileSync(
    path.join(a, 'noise.png'),
    png(2, 2, () => [200, 100, 50]),
  );
  // a cubemap whose third face is not square: said, not drawn black without a word
  mediaFiles({ kind: 'cubemap', src: '/media/a/odd.png' }).forEach((file, f) =>
    fs.writeFileSync(path.join(dir, file), f === 2 ? png(2, 4, () => [9, 9, 9]) : png(2, 2, () => [9, 9, 9])),
  );
}

// ---- the shaders: one probe a pixel, in one row ----------------------------------------------

/** @param {number} channel @param {string} type @param {string} file @param {{filter?: string, wrap?: string, vflip?: boolean, id?: string}} [sampler] */
const input = (channel, type, file, { filter = 'nearest', wrap = 'clamp', vflip = true, id = undefined } = {}) => ({
  channel,
  type,
  ...(id ? { id } : {}),
  filepath: file,
  previewfilepath: file,
  sampler: { filter, wrap, vflip: String(vflip), srgb: 'false', internal: 'byte' },
  published: 1,
});
const shaderJson = (inputs, code) =>
  JSON.stringify({
    Shader: {
      ver: '0.1',
      info: { name: 'media probe' },
      renderpass: [{ inputs, outputs: [{ id: '4dfGRr', channel: 0 }], code, name: 'Image', description: '', type: 'image' }],
    },
  });
/** A shader whose pixel i shows `probes[i]` (GLSL expressions of a vec4). */
const probeCode = (probes) =>
  `void mainImage(out vec4 c, in vec2 p) {\n  int i = int(p.x);\n  c = vec4(0.0, 0.0, 0.0, 1.0);\n${probes
    .map((probe, i) => `  if (i == ${i}) c = ${probe};`)
    .join('\n')}\n}\n`;
const glslVec = (v) => `vec${v.length}(${v.map((x) => x.toFixed(4)).join(', ')})`;

/** The texture through four samplers: [probe, expected RGB, tolerance, what]. */
const TEXTURE_CASES = [
  ['texture(iChannel0, vec2(0.25, 0.75))', TEXELS[0][0], 0, 'vflip: v = 0.75 is the top row'],
  ['texture(iChannel0, vec2(0.75, 0.25))', TEXELS[1][1], 0, 'vflip: v = 0.25 is the bottom row'],
  ['texture(iChannel1, vec2(0.25, 0.75))', TEXELS[1][0], 0, 'no vflip: v = 0.75 is the file’s second row'],
  ['texture(iChannel1, vec2(1.25, 0.25))', TEXELS[0][0], 0, 'repeat: u = 1.25 is u = 0.25'],
  ['texture(iChannel0, vec2(1.25, 0.75))', TEXELS[0][1], 0, 'clamp: u = 1.25 is the right column'],
  ['texture(iChannel2, vec2(0.5))', AVERAGE, FILTERED, 'linear: the middle is the four texels’ mean'],
  ['texture(iChannel2, vec2(0.25, 0.75))', TEXELS[0][0], 0, 'linear at a texel’s centre is that texel'],
  ['textureLod(iChannel3, vec2(0.25), 1.0)', AVERAGE, FILTERED, 'mipmap: level 1 is the mean'],
  ['textureLod(iChannel0, vec2(0.25, 0.75), 1.0)', TEXELS[0][0], 0, 'nearest has no mipmaps: level 0'],
];
const TEXTURE_SHADER = shaderJson(
  [
    input(0, 'texture', '/media/a/tex.png', { filter: 'nearest', wrap: 'clamp', vflip: true }),
    input(1, 'texture', '/media/a/tex.png', { filter: 'nearest', wrap: 'repeat', vflip: false }),
    input(2, 'texture', '/media/a/tex.png', { filter: 'linear', wrap: 'clamp', vflip: true }),
    input(3, 'texture', '/media/a/tex.png', { filter: 'mipmap', wrap: 'repeat', vflip: true }),
  ],
  probeCode(TEXTURE_CASES.map(([probe]) => probe)),
);

/** The 24 directions into a cube's quadrants: major axis k >> 2 (+X, −X, +Y, −Y, +Z, −Z), the others ±0.5. */
const CUBE_DIRECTIONS = Array.from({ length: 24 }, (_, k) => {
  const axis = k >> 2;
  const d = [0, 0, 0];
  d[axis >> 1] = axis & 1 ? -1 : 1;
  const others = [0, 1, 2].filter((c) => c !== axis >> 1);
  d[others[0]] = k & 1 ? 0.5 : -0.5;
  d[others[1]] = k & 2 ? 0.5 : -0.5;
  return d;
});

/**
 * The texel a direction reads, computed: the ES 3.0 table gives the face and (s, t), t = 0 the
 * first row uploaded; the site's upload gives which file and row that is.
 * @param {number[]} direction
 * @param {boolean} vflip
 */
function cubeExpected(direction, vflip) {
  const { face, s, t } = cubeLookup(direction);
  const col = s < 0.5 ? 0 : 1;
  const uploadedRow = t < 0.5 ? 0 : 1;
  const file = vflip && (face === 2 || face === 3) ? 5 - face : face; // the site's trade of +Y and −Y

  return faceTexel(file, vflip ? 1 - uploadedRow : uploadedRow, col);
}
const CUBE_SHADER = shaderJson(
  [input(0, 'cubemap', '/media/a/cube.png', { vflip: false }), input(1, 'cubemap', '/media/a/cube.png', { vflip: true })],
  probeCode([0, 1].flatMap((ch) => CUBE_DIRECTIONS.map((d) => `texture(iChannel${ch}, ${glslVec(d)})`))),
);
const cubeCases = () => [false, true].flatMap((vflip) => CUBE_DIRECTIONS.map((d) => cubeExpected(d, vflip)));

/** Every texel of both volumes (at texel centres), their alpha, sizes, and the one-channel texture. */
const centre = (v) => glslVec(v.map((c) => (c + 0.5) / 2));
const VOLUME_CASES = [
  ...CORNERS.map((v) => [`texture(iChannel0, ${centre(v)})`, byteTexel(...v), 0]),
  ...CORNERS.map((v) => [
    `vec4(texture(iChannel1, ${centre(v)}).r, texture(iChannel1, ${centre(v)}).g + texture(iChannel1, ${centre(v)}).b, texture(iChannel1, ${centre(v)}).a, 1.0)`,
    [floatTexel(...v) * 255, 0, 255],
    FILTERED,
  ]),
  ['vec4(vec3(texture(iChannel0, vec3(0.25)).a), 1.0)', [255, 255, 255], 0],
  ['vec4(iChannelResolution[0] * 10.0 / 255.0, 1.0)', [20, 20, 20], 0],
  ['texture(iChannel2, vec2(0.5))', [200, 0, 0], 0],
  ['vec4(vec3(texture(iChannel2, vec2(0.5)).a), 1.0)', [255, 255, 255], 0],
  ['vec4(iChannelResolution[2] * 10.0 / 255.0, 1.0)', [20, 20, 10], 0],
];
const VOLUME_SHADER = shaderJson(
  [
    input(0, 'volume', '/media/a/bytes.bin'),
    input(1, 'volume', '/media/a/floats.bin'),
    input(2, 'texture', '/media/a/noise.png', { id: 'Xdf3zn' }),
  ],
  probeCode(VOLUME_CASES.map(([probe]) => probe)),
);

/**
 * Music a Buffer A pass names (not the Image pass: every pass's channels read the library), copied
 * to the screen by the Image pass: the 512 x 2 texture and iChannelTime as music-fixture.js reads them.
 */
const MUSIC_TIME = 1.9;
const MUSIC_SHADER = JSON.stringify({
  Shader: {
    ver: '0.1',
    info: { name: 'music in a buffer' },
    renderpass: [
      {
        inputs: [input(0, 'music', '/media/a/tone.wav', { filter: 'linear', vflip: false })],
        outputs: [{ id: '4dXGR8', channel: 0 }],
        code: MUSIC_READER,
        name: 'Buffer A',
        description: '',
        type: 'buffer',
      },
      {
        inputs: [{ ...input(0, 'buffer', '/media/previz/buffer00.png'), id: '4dXGR8' }],
        outputs: [{ id: '4dfGRr', channel: 0 }],
        code: 'void mainImage(out vec4 c, in vec2 p) { c = texelFetch(iChannel0, ivec2(p), 0); }\n',
        name: 'Image',
        description: '',
        type: 'image',
      },
    ],
  },
});

/** Checks one row of probes against [expected RGB, tolerance] each. */
function checkRow(image, cases, where) {
  cases.forEach(([expected, tolerance, what], i) => {
    const got = pixel(image, i, 0);
    const off = Math.max(...got.map((v, c) => Math.abs(v - expected[c])));
    expect(off, `${where}, probe ${i}${what ? ` (${what})` : ''}: got ${got}, expected ${expected.map(Math.round)}`).toBeLessThanOrEqual(
      tolerance + 0.5,
    );
  });
}

/** @type {Array<[string, string, () => any[]]>} */
const SHADERS = [
  ['texture.json', TEXTURE_SHADER, () => TEXTURE_CASES.map(([, e, t, what]) => [e, t, what])],
  ['cube.json', CUBE_SHADER, () => cubeCases().map((e, i) => [e, 0, `direction ${CUBE_DIRECTIONS[i % 24]}, vflip ${i >= 24}`])],
  ['volume.json', VOLUME_SHADER, () => VOLUME_CASES.map(([, e, t]) => [e, t])],
];

// ---- the data, without a browser ---------------------------------------------------------------

describe('the site’s media paths and volume format', () => {
  test.each([
    ['/media/a/abc.jpg', 'a/abc.jpg'],
    ['https://www.shadertoy.com/media/a/abc.png', 'a/abc.png'],
    ['/media/a/../../etc/passwd', null],
    ['/presets/tex00.jpg', null],
    ['/media/a/100%.png', null],
    ['/media/a/x%5C..%5Cy.png', null],
    ['/media/a/sky%23a.png', 'a/sky#a.png'],
    ['', null],
  ])('mediaPath(%j) is %j', (src, expected) => {
    expect(mediaPath(src)).toBe(expected);
  });

  test('a cubemap is six files, _1 to _5 beside the first; with vflip the Y faces trade places', () => {
    expect(mediaFiles({ kind: 'cubemap', src: '/media/a/sky.jpg' })).toEqual([
      'a/sky.jpg',
      'a/sky_1.jpg',
      'a/sky_2.jpg',
      'a/sky_3.jpg',
      'a/sky_4.jpg',
      'a/sky_5.jpg',
    ]);
    expect(cubeFaceOrder(['px', 'nx', 'py', 'ny', 'pz', 'nz'], true)).toEqual(['px', 'nx', 'ny', 'py', 'pz', 'nz']);
    expect(cubeFaceOrder(['px', 'nx', 'py', 'ny', 'pz', 'nz'], false)).toEqual(['px', 'nx', 'py', 'ny', 'pz', 'nz']);
  });

  test('a volume is read back as written; a file that is not one says why', () => {
    const data = Float32Array.from({ length: 24 }, (_, i) => i / 7);
    const read = parseVolume(writeVolume({ width: 2, height: 3, depth: 4, channels: 1, format: 'float', data }).slice().buffer);
    expect(read).toMatchObject({ width: 2, height: 3, depth: 4, channels: 1, format: 'float' });
    expect([...read.data]).toEqual([...data]);
    const bytes = writeVolume({ width: 2, height: 2, depth: 2, channels: 4, data: new Uint8Array(32).fill(9) });
    expect(() => parseVolume(bytes.slice(0, 30).buffer)).toThrow(/needs 32 bytes of texels, the file has 10/);
    expect(() => parseVolume(new ArrayBuffer(8))).toThrow(/shorter than its header/);
    const badFormat = bytes.slice();
    new DataView(badFormat.buffer).setUint16(18, 3, true);
    expect(() => parseVolume(badFormat.buffer)).toThrow(/format 3/);
  });
});

// ---- the page and the command line -------------------------------------------------------------

describe('the site’s media from a folder, against what the test computes', () => {
  sharePageAcrossTests();

  test('the page: textures through four samplers, a cubemap both ways, volumes, a one-channel texture, music in a buffer', async () => {
    await withServedDir('test-media-library', async (dir, base) => {
      writeMedia(path.join(dir, 'media'));
      for (const [name, json] of SHADERS) fs.writeFileSync(path.join(dir, name), json);
      const samples = toneSamples();
      fs.writeFileSync(path.join(dir, 'media', 'a', 'tone.wav'), wav(samples));
      fs.writeFileSync(path.join(dir, 'music.json'), MUSIC_SHADER);
      await withPage(async ({ page, goto, errors }) => {
        for (const [name, , cases] of SHADERS) {
          const expected = cases();
          await goto(`?shader=/${base}/${name}&size=${expected.length}x1&time=0&media=/${base}/media/`);
          checkRow(await readPixels(page), expected, `page, ${name}`);
        }
        fs.writeFileSync(
          path.join(dir, 'odd.json'),
          shaderJson(
            [input(0, 'cubemap', '/media/a/odd.png')],
            'void mainImage(out vec4 c, in vec2 p) { c = texture(iChannel0, vec3(1.0, 0.0, 0.0)); }\n',
          ),
        );
        await goto(`?shader=/${base}/odd.json&size=2x2&time=0&media=/${base}/media/`);
        expect((await loadNotes(page))?.lines).toEqual([
          "Image, iChannel0: the site's cubemap /media/a/odd.png: a cubemap's faces are square and of one size, and a/odd_2.png is 2x4 where a/odd.png is 2x2; the channel is black",
        ]);

        // an edit that names the same media keeps them (nothing fetched again); a lost and
        // restored context gets them again
        const [name, json, cases] = SHADERS[0];
        await goto(`?shader=/${base}/${name}&size=${cases().length}x1&time=0&media=/${base}/media/`);
        const fetched = [];
        const count = (/** @type {import('puppeteer-core').HTTPRequest} */ request) => {
          if (request.url().includes('/media/a/')) fetched.push(request.url());
        };
        page.on('request', count);
        const edited = JSON.parse(json);
        edited.Shader.renderpass[0].code += '// an edit\n';
        const result = await page.evaluate((text) => window.raytracer.setProject(text), JSON.stringify(edited));
        expect(result.ok, result.error).toBe(true);
        checkRow(await readPixels(page), cases(), 'page, after an edit');
        await page.evaluate(() => window.raytracer.loseContext());
        await page.waitForFunction(() => window.raytracer.info().contextLost);
        await page.evaluate(() => window.raytracer.restoreContext());
        await page.waitForFunction(() => !window.raytracer.info().contextLost);
        checkRow(await readPixels(page), cases(), 'page, after a lost and restored context');
        page.off('request', count);
        expect(fetched, 'no media fetched again').toEqual([]);

        await goto(`?shader=/${base}/music.json&size=512x2&time=${MUSIC_TIME}&media=/${base}/media/`);
        checkMusic(await readPixels(page), samples, MUSIC_TIME, 'page, music a buffer pass names');
        // the page's "Copy link" keeps the media folder, so the link draws the same
        expect(await page.evaluate(() => window.raytracer.shareUrl())).toContain(`media=/${base}/media/`);
        expect(errors).toEqual([]);
      });
    });
  });

  test('the command line: --media draws them, a missing file is said, --fetch-media downloads once into its cache, --channelN takes a cubemap and a volume', async () => {
    const folder = fs.mkdtempSync(path.join(os.tmpdir(), 'shaderproof-library-'));
    const site = path.join(folder, 'site');
    writeMedia(path.join(site, 'media'));
    fs.writeFileSync(path.join(folder, 'cube.json'), CUBE_SHADER);
    const size = `${cubeCases().length}x1`;
    /** @type {Record<string, string | undefined>} */
    const env = { ...process.env, SHADERPROOF_MEDIA_CACHE: path.join(folder, 'cache') };
    const shaderproof = async (...args) => {
      try {
        const { stdout, stderr } = await run(process.execPath, [BIN, ...args], { cwd: folder, env, timeout: 120_000 });
        return { code: 0, stdout, stderr };
      } catch (error) {
        if (typeof error.code !== 'number') throw error;
        return { code: error.code, stdout: error.stdout, stderr: error.stderr };
      }
    };
    const readOut = (file) => PNG.sync.read(fs.readFileSync(path.join(folder, file)));
    const cubeRow = cubeCases().map((e) => [e, 0]);
    // a loopback "site" that serves /media/… and counts what it was asked for
    const asked = [];
    const server = http.createServer((req, res) => {
      asked.push(req.url);
      const file = path.join(site, decodeURIComponent(String(req.url)));
      if (file.startsWith(site + path.sep) && fs.existsSync(file)) res.writeHead(200).end(fs.readFileSync(file));
      else res.writeHead(404).end();
    });
    await new Promise((resolve) => server.listen(0, '127.0.0.1', () => resolve(undefined)));
    env.SHADERPROOF_MEDIA_ORIGIN = `http://127.0.0.1:${/** @type {import('node:net').AddressInfo} */ (server.address()).port}`;
    try {
      const drawn = await shaderproof('render', 'cube.json', '--size', size, '--media', path.join(site, 'media'), '-o', 'a.png');
      expect(drawn.code, drawn.stderr).toBe(0);
      expect(drawn.stderr).not.toMatch(/warning/);
      checkRow(readOut('a.png'), cubeRow, 'render --media');

      // a folder without the faces: each channel said, with the file it lacks; --strict refuses
      fs.mkdirSync(path.join(folder, 'empty'));
      const without = await shaderproof('render', 'cube.json', '--size', size, '--media', 'empty', '-o', 'b.png');
      expect(without.code).toBe(0);
      expect(without.stderr).toMatch(
        /warning: .*Image, iChannel0: the site's cubemap \/media\/a\/cube\.png: a\/cube\.png is not in the media folder; the channel is black/,
      );
      expect(without.stderr).toMatch(/Image, iChannel1: /);
      const strict = await shaderproof('render', 'cube.json', '--size', size, '--strict', '-o', 'c.png');
      expect(strict.code).toBe(1);
      expect(strict.stderr).toMatch(/--strict: .*needs the site's media: give a media folder/);
      expect(fs.existsSync(path.join(folder, 'c.png'))).toBe(false);

      // --fetch-media: the six faces downloaded once, then read from the cache with no server
      const fetched = await shaderproof('render', 'cube.json', '--size', size, '--fetch-media', '-o', 'd.png');
      expect(fetched.code, fetched.stderr).toBe(0);
      expect(fetched.stderr.match(/media: downloaded \/media\/a\/cube(_\d)?\.png/g)).toHaveLength(6);
      checkRow(readOut('d.png'), cubeRow, 'render --fetch-media');
      expect(asked.sort()).toEqual(
        mediaFiles({ kind: 'cubemap', src: '/media/a/cube.png' })
          .map((f) => `/media/${f}`)
          .sort(),
      );
      await new Promise((resolve) => server.close(() => resolve(undefined)));
      const cached = await shaderproof('render', 'cube.json', '--size', size, '--fetch-media', '-o', 'e.png');
      expect(cached.code, cached.stderr).toBe(0);
      expect(cached.stderr).not.toMatch(/downloaded|warning/);
      checkRow(readOut('e.png'), cubeRow, 'render --fetch-media from the cache');

      // a Sound tab reads the site's media too: a volume's texel and a texture's, as constant tones
      const soundJson = JSON.parse(shaderJson([], 'void mainImage(out vec4 c, in vec2 p) { c = vec4(0.0); }\n'));
      soundJson.Shader.renderpass.push({
        inputs: [input(0, 'volume', '/media/a/bytes.bin'), input(1, 'texture', '/media/a/tex.png')],
        outputs: [],
        code: 'vec2 mainSound(int s, float t) { return 0.5 * vec2(texture(iChannel0, vec3(0.25)).r, texture(iChannel1, vec2(0.25, 0.75)).r); }\n',
        name: 'Sound',
        description: '',
        type: 'sound',
      });
      fs.writeFileSync(path.join(folder, 'sound.json'), JSON.stringify(soundJson));
      const sounded = await shaderproof(
        'render',
        'sound.json',
        '--media',
        path.join(site, 'media'),
        '--duration',
        '0.05',
        '-o',
        'sound.wav',
      );
      expect(sounded.code, sounded.stderr).toBe(0);
      expect(sounded.stderr).not.toMatch(/warning/);
      const { pcm } = decodeWav(fs.readFileSync(path.join(folder, 'sound.wav')));
      // the site's 16-bit packing of y (src/shadertoy/sound.js): floor((0.5 + 0.5 y) 65536) - 32768
      const word = (y) => Math.floor((0.5 + 0.5 * y) * 65536) - 32768;
      const [left, right] = [word((0.5 * byteTexel(0, 0, 0)[0]) / 255), word((0.5 * TEXELS[0][0][0]) / 255)];
      for (let i = 0; i < pcm.length; i += 2) {
        expect(Math.abs(pcm[i] - left), `sample ${i / 2}, left: the volume's texel`).toBeLessThanOrEqual(1);
        expect(Math.abs(pcm[i + 1] - right), `sample ${i / 2}, right: the texture's texel`).toBeLessThanOrEqual(1);
      }

      // two volumes of one name in two folders, with a "%" and a "#" in it: each channel its own file
      const odd = '50%#v.bin';
      for (const [dir, value] of /** @type {Array<[string, number]>} */ ([
        ['one', 255],
        ['two', 64],
      ])) {
        fs.mkdirSync(path.join(folder, dir));
        fs.writeFileSync(
          path.join(folder, dir, odd),
          writeVolume({ width: 1, height: 1, depth: 1, channels: 1, data: Uint8Array.of(value) }),
        );
      }
      fs.writeFileSync(
        path.join(folder, 'two.glsl'),
        'void mainImage(out vec4 c, in vec2 p) { c = vec4(texture(iChannel0, vec3(0.5)).r, texture(iChannel1, vec3(0.5)).r, 0.0, 1.0); }\n',
      );
      const two = await shaderproof(
        'render',
        'two.glsl',
        '--channel0',
        `one/${odd}`,
        '--channel1',
        `two/${odd}`,
        '--size',
        '1x1',
        '-o',
        'two.png',
      );
      expect(two.code, two.stderr).toBe(0);
      expect(pixel(readOut('two.png'), 0, 0)).toEqual([255, 64, 0]);
      // a volume that is not there, and a cubemap with a face missing: said, nothing drawn
      const gone = await shaderproof('render', 'two.glsl', '--channel0', 'one/gone.bin', '--size', '1x1', '-o', 'gone.png');
      expect([gone.code, gone.stderr.trim()]).toEqual([1, 'shaderproof render: one/gone.bin: no such file']);
      fs.mkdirSync(path.join(folder, 'partial'));
      for (const face of ['sky.png', 'sky_1.png', 'sky_2.png'])
        fs.copyFileSync(path.join(site, 'media', 'a', 'tex.png'), path.join(folder, 'partial', face));
      const partial = await shaderproof('render', 'two.glsl', '--channel0', 'partial/sky.png', '--size', '1x1', '-o', 'gone.png');
      expect(partial.code).toBe(2);
      expect(partial.stderr).toMatch(
        /--channel0 partial\/sky\.png: a cubemap's first face, with 2 of its other five beside it; sky_3\.png, sky_4\.png, sky_5\.png missing/,
      );
      expect(fs.existsSync(path.join(folder, 'gone.png'))).toBe(false);

      // what a person gets wrong, each said in one line: a face other than the first, a volume
      // that is not one, a channel the JSON fills already, a folder laid out flat, a file for a folder
      const siteA = path.join(site, 'media', 'a');
      /** @type {Array<[string[], number, RegExp]>} */
      const refusals = [
        [['two.glsl', '--channel0', path.join(siteA, 'cube_2.png')], 2, /face 2 of a cubemap; give its first face, .*cube\.png/],
        [['two.glsl', '--channel0', 'partial/sky.png.bin'], 1, /no such file/],
        [
          ['cube.json', '--channel0', path.join(siteA, 'tex.png')],
          2,
          /--channel0 .*tex\.png: cube\.json's Image pass reads iChannel0 already \(its cubemap\)/,
        ],
        [['cube.json', '--media', path.join(siteA, 'tex.png')], 2, /--media .*tex\.png: a file, not a folder/],
      ];
      fs.writeFileSync(path.join(folder, 'partial', 'short.bin'), 'BIN');
      refusals.push([
        ['two.glsl', '--channel0', 'partial/short.bin'],
        1,
        /partial\/short\.bin: not a volume: 3 bytes, shorter than its header/,
      ]);
      for (const [args, code, said] of refusals) {
        const refused = await shaderproof('render', .../** @type {string[]} */ (args), '--size', '1x1', '-o', 'refused.png');
        expect([refused.code, refused.stderr], args.join(' ')).toEqual([code, expect.stringMatching(said)]);
      }
      expect(fs.existsSync(path.join(folder, 'refused.png'))).toBe(false);
      const flat = await shaderproof('render', 'cube.json', '--media', siteA, '--size', '1x1', '-o', 'flat.png');
      expect(flat.stderr).toMatch(
        /warning: --media .*\/a: a\/cube\.png is not there, but .*\/a\/cube\.png is: the folder is laid out as the site's paths/,
      );

      // test: --media holds for every case; without it the case fails and no reference is written
      fs.mkdirSync(path.join(folder, 'cases'));
      fs.writeFileSync(path.join(folder, 'cases', 'cube.json'), CUBE_SHADER);
      const updated = await shaderproof('test', 'cases', '--update', '--media', path.join(site, 'media'));
      expect(updated.code, updated.stdout + updated.stderr).toBe(0);
      const reference = path.join(folder, 'cases', '__references__', 'cube.json.png');
      const written = fs.readFileSync(reference);
      const bare = await shaderproof('test', 'cases');
      expect(bare.code).toBe(1);
      expect(bare.stdout + bare.stderr).toMatch(/needs the site's media/);
      expect(fs.readFileSync(reference).equals(written)).toBe(true);

      // --channelN: a cubemap (its faces beside it, as the site names them) and a volume, for a
      // .glsl, with the site's sampler for a new input of each kind (mipmapped: level 0 read here)
      const probes = [
        ...CUBE_DIRECTIONS.map((d) => [`textureLod(iChannel0, ${glslVec(d)}, 0.0)`, cubeExpected(d, false)]),
        ...CORNERS.map((v) => [`textureLod(iChannel1, ${centre(v)}, 0.0)`, byteTexel(...v)]),
      ];
      fs.writeFileSync(path.join(folder, 'channels.glsl'), probeCode(probes.map(([probe]) => probe)));
      const media = path.join(site, 'media', 'a');
      const channelled = await shaderproof(
        'render',
        'channels.glsl',
        '--channel0',
        path.join(media, 'cube.png'),
        '--channel1',
        path.join(media, 'bytes.bin'),
        '--size',
        `${probes.length}x1`,
        '-o',
        'f.png',
      );
      expect(channelled.code, channelled.stderr).toBe(0);
      expect(channelled.stderr).not.toMatch(/warning/);
      checkRow(
        readOut('f.png'),
        probes.map(([, expected]) => [expected, 0]),
        'render --channel0 cube.png --channel1 bytes.bin',
      );
    } finally {
      server.close();
      fs.rmSync(folder, { recursive: true, force: true });
    }
  });
});
