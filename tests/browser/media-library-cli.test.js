// The site's media from the command line (issue 37, items 2 and 3): --media DIR, --fetch-media
// against a loopback "site" and its cache, test --media, --channelN volumes and cubemaps, a Sound
// tab reading media into a WAV, and each mistake a person makes said in one line; every picture
// and sample checked against what media-fixture.js computes.

import { execFile } from 'node:child_process';
import fs from 'node:fs';
import http from 'node:http';
import os from 'node:os';
import path from 'node:path';
import { promisify } from 'node:util';
import { PNG } from 'pngjs';
import { describe, expect, test } from 'vitest';
import { REPO_ROOT } from '../support/config.js';
import { decodeWav } from '../../src/shared/wav.js';
import { mediaFiles, writeVolume } from '../../src/shadertoy/media.js';
import { pixel } from '../support/page-helpers.js';
import {
  CORNERS,
  CUBE_DIRECTIONS,
  CUBE_SHADER,
  TEXELS,
  byteTexel,
  centre,
  checkRow,
  cubeCases,
  cubeExpected,
  glslVec,
  input,
  probeCode,
  shaderJson,
  writeMedia,
} from '../support/fixtures/media-fixture.js';

const BIN = path.join(REPO_ROOT, 'bin', 'shaderproof.js');
const run = promisify(execFile);

describe('the site’s media from the command line, against what the test computes', () => {
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

      // a folder without the faces: said once for both channels, with the file it lacks; --strict refuses
      fs.mkdirSync(path.join(folder, 'empty'));
      const without = await shaderproof('render', 'cube.json', '--size', size, '--media', 'empty', '-o', 'b.png');
      expect(without.code).toBe(0);
      expect(without.stderr).toMatch(
        /warning: cube\.json: Image, iChannel0 and iChannel1: the site's cubemap \/media\/a\/cube\.png: a\/cube\.png is not in --media \S+empty \(--fetch-media downloads what it lacks\); both channels are black/,
      );
      const strict = await shaderproof('render', 'cube.json', '--size', size, '--strict', '-o', 'c.png');
      expect(strict.code).toBe(1);
      expect(strict.stderr).toMatch(
        /--strict: nothing written, .*needs the site's media: give --media DIR \(a folder laid out as the site's paths\) or --fetch-media/,
      );
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
      expect([gone.code, gone.stderr.trim()]).toEqual([1, 'shaderproof render: --channel0 one/gone.bin: no such file']);
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
