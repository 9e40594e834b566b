// Conformance of the site's Theora videos (`.ogv`, Theora video and Vorbis sound; issue 45, item
// 3), which Chromium no longer decodes: the page and the command line read the fixture
// (theora-fixture.js) through tiny shaders, at chosen iTimes, and each texel, iChannelTime and
// iChannelResolution is checked against the frame the fixture was made of, computed there. The
// decoder is loaded only by a shader that uses such a video: a page without one asks for none of
// it. The decoding itself, without a browser: theora.test.js.

import crypto from 'node:crypto';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { unzipSync } from 'fflate';
import { PNG } from 'pngjs';
import { describe, expect, test } from 'vitest';
import { runShaderproof } from '../support/shaderproof-child.js';
import { readPixels, solid, withPage, withServedDir } from '../support/page-helpers.js';
import { checkRow } from '../support/fixtures/media-fixture.js';
import { loadNotes } from '../support/page-multipass-helpers.js';
import { THEORA_FILE, THEORA_READER, expectedProbes, theoraJson } from '../support/fixtures/theora-fixture.js';
import { hook } from '../support/hook.js';

/** The site names a video by a hash of it: so does the test. */
const HASHED = `${crypto.createHash('sha256').update(fs.readFileSync(THEORA_FILE)).digest('hex')}.ogv`;
/** iTimes in an order that steps on within a keyframe's frames, past a keyframe, back, and round the loop. */
const TIMES = [0, 0.05, 0.15, 0.25, 0.45, 0.15, 0.35, 0.55, 0.65, 1.35];
/** What the page asks for when it loads the decoder: its module and its two WebAssembly files. */
const DECODER = /theora-video|ogv-demuxer-ogg-wasm|ogv-decoder-video-theora-wasm/;

const shaderproof = (cwd, ...args) => runShaderproof(args, { cwd, timeout: 120_000 });
const both = (/** @type {number} */ t) => [...expectedProbes(t), ...expectedProbes(t)];

describe('the site’s Theora videos, against the frames the fixture was made of', () => {
  test('the page: a video channel (?iChannel0=) at each iTime, and a JSON’s from ?media= with vflip on and off; the decoder loaded only then, its licences in the build', async () => {
    await withServedDir('test-theora', async (dir, base) => {
      fs.copyFileSync(THEORA_FILE, path.join(dir, 'colours.ogv'));
      fs.mkdirSync(path.join(dir, 'media', 'a'), { recursive: true });
      fs.copyFileSync(THEORA_FILE, path.join(dir, 'media', 'a', HASHED));
      fs.writeFileSync(path.join(dir, 'reader.glsl'), THEORA_READER);
      fs.writeFileSync(path.join(dir, 'theora.json'), theoraJson(HASHED));
      fs.writeFileSync(path.join(dir, 'plain.glsl'), solid(10, 20, 30));
      await withPage(async ({ page, goto, errors }) => {
        const asked = [];
        page.on('request', (request) => {
          if (DECODER.test(request.url())) asked.push(request.url());
        });
        await goto(`?shader=/${base}/plain.glsl&size=4x1&time=0`);
        expect(asked, 'a shader without a Theora video loads no decoder').toEqual([]);

        await goto(`?shader=/${base}/reader.glsl&size=4x1&time=0&iChannel0=/${base}/colours.ogv`);
        for (const t of TIMES) {
          await hook(page).setTime(t);
          checkRow(await readPixels(page), expectedProbes(t), `page, ?iChannel0=colours.ogv, iTime ${t}`);
        }
        // its module and two WebAssembly files (a module preloaded and imported may be asked for twice)
        expect([...new Set(asked.map((url) => DECODER.exec(url)?.[0]))].sort(), asked.join(', ')).toEqual([
          'ogv-decoder-video-theora-wasm',
          'ogv-demuxer-ogg-wasm',
          'theora-video',
        ]);

        // the build carries the notices the decoder's licences ask of a binary copy
        for (const [file, holder] of [
          ['ogv.js.txt', 'Brooke Vibber'],
          ['libogg.txt', 'Xiph.org'],
          ['libtheora.txt', 'Xiph.org'],
        ]) {
          const response = await fetch(new URL(`/licenses/ogv/${file}`, page.url()));
          expect(response.status, file).toBe(200);
          expect(await response.text(), file).toContain(holder);
        }

        await goto(`?shader=/${base}/theora.json&size=8x1&time=0.45&media=/${base}/media/`);
        checkRow(await readPixels(page), both(0.45), 'page, ?media=, iTime 0.45');
        await hook(page).setTime(0.15);
        checkRow(await readPixels(page), both(0.15), 'page, ?media=, iTime 0.15');
        expect(errors).toEqual([]);
      });
    });
  });

  test('a page that cannot load its decoder says so in the channel’s note, and draws the channel black', async () => {
    await withServedDir('test-theora-missing', async (dir, base) => {
      fs.copyFileSync(THEORA_FILE, path.join(dir, 'colours.ogv'));
      fs.writeFileSync(path.join(dir, 'reader.glsl'), THEORA_READER);
      const refuse = async (page) => {
        await page.setRequestInterception(true);
        page.on('request', (request) => {
          if (/\.wasm$/.test(new URL(request.url()).pathname)) request.respond({ status: 404, body: '' });
          else request.continue();
        });
      };
      await withPage(
        async ({ page, goto, errors }) => {
          await goto(`?shader=/${base}/reader.glsl&size=4x1&time=0&iChannel0=/${base}/colours.ogv`);
          const lines = (await loadNotes(page))?.lines ?? [];
          expect(lines.join('\n')).toMatch(
            /^iChannel0: cannot play colours\.ogv as a video: the page could not load its Theora decoder \(\S+ogv-(demuxer|decoder)\S+\.wasm: HTTP 404\); build the page again \(npm run build\); the channel is black$/,
          );
          checkRow(await readPixels(page), [[[0, 0, 0], 0, 'the channel is black']], 'page without its decoder');
          expect(errors, 'nothing but the note: the 404s are not the page’s errors').toEqual([]);
        },
        { beforeLoad: refuse },
      );
    });
  });

  test('the command line: record with --channel0 x.ogv at each frame’s iTime; render of a JSON whose media folder has a/<hash>.ogv', async () => {
    const folder = fs.mkdtempSync(path.join(os.tmpdir(), 'shaderproof-theora-'));
    try {
      fs.copyFileSync(THEORA_FILE, path.join(folder, 'colours.ogv'));
      fs.writeFileSync(path.join(folder, 'reader.glsl'), THEORA_READER);
      fs.mkdirSync(path.join(folder, 'media', 'a'), { recursive: true });
      fs.copyFileSync(THEORA_FILE, path.join(folder, 'media', 'a', HASHED));
      fs.writeFileSync(path.join(folder, 'theora.json'), theoraJson(HASHED));

      // frames at iTime i / 8: frames 0, 1, 2, 3, 5, then round the loop 0, 1, 2
      const recorded = await shaderproof(
        folder,
        'record',
        'reader.glsl',
        '--channel0',
        'colours.ogv',
        '--frames',
        '8',
        '--fps',
        '8',
        '--size',
        '4x1',
        '-o',
        'out.zip',
      );
      expect(recorded.code, recorded.stderr).toBe(0);
      expect(recorded.stderr).not.toMatch(/warning/);
      const files = unzipSync(fs.readFileSync(path.join(folder, 'out.zip')));
      const names = Object.keys(files).sort();
      expect(names).toHaveLength(8);
      names.forEach((name, i) => checkRow(PNG.sync.read(Buffer.from(files[name])), expectedProbes(i / 8), `record --channel0, frame ${i}`));

      const rendered = await shaderproof(
        folder,
        'render',
        'theora.json',
        '--media',
        'media',
        '--time',
        '0.45',
        '--size',
        '8x1',
        '-o',
        'json.png',
      );
      expect(rendered.code, rendered.stderr).toBe(0);
      expect(rendered.stderr).not.toMatch(/warning/);
      checkRow(PNG.sync.read(fs.readFileSync(path.join(folder, 'json.png'))), both(0.45), 'render --media, iTime 0.45');
    } finally {
      fs.rmSync(folder, { recursive: true, force: true });
    }
  });
});
