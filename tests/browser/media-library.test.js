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

import fs from 'node:fs';
import path from 'node:path';
import { describe, expect, test } from 'vitest';
import { cubeFaceOrder, mediaFiles, mediaPath, parseVolume, writeVolume } from '../../src/shadertoy/media.js';
import { readPixels, sharePageAcrossTests, withPage, withServedDir } from '../support/page-helpers.js';
import { checkMusic, toneSamples, wav } from '../support/fixtures/music-fixture.js';
import { loadNotes } from '../support/page-multipass-helpers.js';
import { MUSIC_SHADER, MUSIC_TIME, SHADERS, checkRow, input, shaderJson, writeMedia } from '../support/fixtures/media-fixture.js';
import { hook } from '../support/hook.js';

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
        const result = await hook(page).setProject(JSON.stringify(edited));
        expect(result.ok, result.error).toBe(true);
        checkRow(await readPixels(page), cases(), 'page, after an edit');
        await hook(page).loseContext();
        await page.waitForFunction(() => window.shaderEngine.info().contextLost);
        await hook(page).restoreContext();
        await page.waitForFunction(() => !window.shaderEngine.info().contextLost);
        checkRow(await readPixels(page), cases(), 'page, after a lost and restored context');
        page.off('request', count);
        expect(fetched, 'no media fetched again').toEqual([]);

        await goto(`?shader=/${base}/music.json&size=512x2&time=${MUSIC_TIME}&media=/${base}/media/`);
        checkMusic(await readPixels(page), samples, MUSIC_TIME, 'page, music a buffer pass names');
        // the page's "Copy link" keeps the media folder, so the link draws the same
        expect(await hook(page).shareUrl()).toContain(`media=/${base}/media/`);
        expect(errors).toEqual([]);
      });
    });
  });
});
