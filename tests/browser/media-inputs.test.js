// Conformance of the moving channels (issue 37, items 3 and 5): a video and a music file in
// iChannel0, in the page and from the command line, each checked against what the test computes
// itself. The video is made here by the page's own recorder from a shader whose frame i is the
// grey i·40, so frame i of the file is known; the music is a WAV written here, one sine at the
// centre of FFT bin 20, so its spectrum row has one peak whose byte the Web Audio spec's analyser
// formula gives, and its waveform row is the file's samples. The texture and iChannelTime are
// read back through tiny shaders.

import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { unzipSync } from 'fflate';
import { PNG } from 'pngjs';
import { describe, expect, test } from 'vitest';
import { runShaderproof } from '../support/shaderproof-child.js';
import { readPng } from '../support/images.js';
import { CHROME_ARGS, launchBrowser } from '../../src/headless/browser.js';
import { spectrumTexture } from '../../src/player/inputs/spectrum.js';
import { pixel, readPixels, withPage, withServedDir } from '../support/page-helpers.js';
import { MUSIC_READER, RATE, checkMusic, toneSamples, wav } from '../support/fixtures/music-fixture.js';
import { hook } from '../support/hook.js';

// ---- the video: 6 frames at 10 fps, frame i all grey i·40 -----------------------------------
const VIDEO = { frames: 6, fps: 10, step: 40 };
const VIDEO_DURATION = VIDEO.frames / VIDEO.fps;
const FRAME_GREY = `void mainImage(out vec4 c, in vec2 p) { c = vec4(vec3(float(iFrame) * ${VIDEO.step}.0 / 255.0), 1.0); }\n`;
/** The video's picture in r, iChannelTime as a share of the video's length in g, its width in b. */
const VIDEO_READER = `void mainImage(out vec4 c, in vec2 p) {
  c = vec4(texture(iChannel0, vec2(0.5)).r, iChannelTime[0] / ${VIDEO_DURATION.toFixed(3)}, iChannelResolution[0].x / 255.0, 1.0);
}\n`;
/** The frame a video at `fps` shows at iTime t, looped, and its iChannelTime: computed here. */
const videoAt = (t) => {
  const local = t % VIDEO_DURATION;
  return { index: Math.floor(local * VIDEO.fps + 1e-9), local };
};

const shaderproof = (cwd, ...args) => runShaderproof(args, { cwd, timeout: 120_000 });

describe('moving channels: video and music, against what the test computes', () => {
  test('a video and a tone in iChannel0: the page and the command line give the computed frames, rows and iChannelTime', async () => {
    const folder = fs.mkdtempSync(path.join(os.tmpdir(), 'shaderproof-media-'));
    try {
      await withServedDir('test-media', async (dir, base) => {
        fs.writeFileSync(path.join(dir, 'grey.glsl'), FRAME_GREY);
        fs.writeFileSync(path.join(dir, 'video-reader.glsl'), VIDEO_READER);
        fs.writeFileSync(path.join(dir, 'music-reader.glsl'), MUSIC_READER);
        const samples = toneSamples();
        fs.writeFileSync(path.join(dir, 'tone.wav'), wav(samples));
        await withPage(async ({ page, goto, errors }) => {
          // the video, made by the page's recorder: frame i is grey i·40
          await goto(`?shader=/${base}/grey.glsl&size=8x8&time=0`);
          const recording = await hook(page).record({ format: 'webm', frames: VIDEO.frames, fps: VIDEO.fps, width: 8, height: 8 });
          fs.writeFileSync(path.join(dir, 'clip.webm'), Buffer.from(recording.data, 'base64'));
          fs.copyFileSync(path.join(dir, 'clip.webm'), path.join(folder, 'clip.webm'));

          await goto(`?shader=/${base}/video-reader.glsl&size=8x8&time=0&iChannel0=/${base}/clip.webm`);
          for (const t of [0, 0.05, 0.15, 0.35, 0.59, 0.65, 1.25]) {
            await hook(page).setTime(t);
            const [r, g, b] = pixel(await readPixels(page), 4, 4);
            const { index, local } = videoAt(t);
            expect(Math.abs(r - index * VIDEO.step), `iTime ${t}: grey ${r} is frame ${index}'s ${index * VIDEO.step}`).toBeLessThanOrEqual(
              6,
            );
            expect(Math.abs(g - (local / VIDEO_DURATION) * 255), `iTime ${t}: iChannelTime`).toBeLessThanOrEqual(1.5);
            expect(b, `iTime ${t}: iChannelResolution.x`).toBe(8);
          }

          await goto(`?shader=/${base}/music-reader.glsl&size=512x2&time=0&iChannel0=/${base}/tone.wav`);
          for (const t of [0.8, 1.9]) {
            await hook(page).setTime(t);
            checkMusic(await readPixels(page), samples, t, `page, iTime ${t}`);
          }
          // playing (heard where the browser lets it start), then paused: frames go on, nothing fails
          await goto(`?shader=/${base}/music-reader.glsl&size=512x2&iChannel0=/${base}/tone.wav`);
          for (let i = 0; i < 3; i++) await hook(page).nextFrame();
          await hook(page).pause();
          expect(errors).toEqual([]);
        });
        fs.copyFileSync(path.join(dir, 'tone.wav'), path.join(folder, 'tone.wav'));
        fs.copyFileSync(path.join(dir, 'video-reader.glsl'), path.join(folder, 'video-reader.glsl'));
        fs.copyFileSync(path.join(dir, 'music-reader.glsl'), path.join(folder, 'music-reader.glsl'));

        // the command line: frames at iTime i / 5 get the video's frames for those times
        const recorded = await shaderproof(
          folder,
          'record',
          'video-reader.glsl',
          '--channel0',
          'clip.webm',
          '--frames',
          '4',
          '--fps',
          '5',
          '--size',
          '8x8',
          '-o',
          'out.zip',
        );
        expect(recorded.code, recorded.stderr).toBe(0);
        const files = unzipSync(fs.readFileSync(path.join(folder, 'out.zip')));
        Object.keys(files)
          .sort()
          .forEach((name, i) => {
            const png = PNG.sync.read(Buffer.from(files[name]));
            const { index } = videoAt(i / 5);
            const r = png.data[(4 * 8 + 4) * 4];
            expect(Math.abs(r - index * VIDEO.step), `record frame ${i}: grey ${r} is video frame ${index}`).toBeLessThanOrEqual(6);
          });

        const rendered = await shaderproof(
          folder,
          'render',
          'music-reader.glsl',
          '--channel0',
          'tone.wav',
          '--time',
          '1.9',
          '--size',
          '512x2',
          '-o',
          'music.png',
        );
        expect(rendered.code, rendered.stderr).toBe(0);
        checkMusic(readPng(path.join(folder, 'music.png')), samples, 1.9, 'render --time 1.9');
      });
    } finally {
      fs.rmSync(folder, { recursive: true, force: true });
    }
  }, 240_000);

  // The webcam and the microphone are the page's (getUserMedia); the test's headless Chromium has
  // neither device nor permission, so the page says so in one line and leaves the channel empty,
  // and the command line refuses them in one line before any browser starts.
  test.each([
    ['webcam:', 'webcam', /^no webcam: |^this browser gives no webcam/],
    ['mic:', 'microphone', /^no microphone: |^this browser gives no microphone/],
  ])(
    'setChannel(0, %s) without a %s says why in one line, and the channel stays empty',
    async (source, _, message) => {
      await withServedDir('test-device', async (dir, base) => {
        fs.writeFileSync(path.join(dir, 'reader.glsl'), VIDEO_READER);
        await withPage(async ({ page, goto }) => {
          await goto(`?shader=/${base}/reader.glsl&size=8x8&time=0`);
          const outcome = await page.evaluate(
            (s) =>
              Promise.race([
                window.shaderEngine.setChannel(0, s).then(
                  () => 'loaded',
                  (e) => String(e.message),
                ),
                new Promise((resolve) => setTimeout(() => resolve('no answer in 10 s'), 10_000)),
              ]),
            source,
          );
          expect(outcome).toMatch(message);
          expect(outcome).not.toContain('\n');
          expect(pixel(await readPixels(page), 4, 4)).toEqual([0, 0, 0]);
        });
      });
    },
    60_000,
  );

  test.each(['mic', 'webcam'])('shaderproof render --channel0 %s: one line, exit 2', async (device) => {
    const folder = fs.mkdtempSync(path.join(os.tmpdir(), 'shaderproof-device-'));
    try {
      fs.writeFileSync(path.join(folder, 'a.glsl'), VIDEO_READER);
      const { code, stderr } = await shaderproof(folder, 'render', 'a.glsl', '--channel0', device, '-o', 'a.png');
      expect(code).toBe(2);
      expect(stderr.trim().split('\n')).toHaveLength(1);
      expect(stderr).toMatch(new RegExp(`--channel0 ${device}: the command line has no (webcam|microphone) \\(the page has\\); give a`));
      expect(fs.existsSync(path.join(folder, 'a.png'))).toBe(false);
    } finally {
      fs.rmSync(folder, { recursive: true, force: true });
    }
  });

  test('a music frame is a function of its iTime: drawn after frames 0..N-1 or alone, the same bytes', () => {
    const samples = toneSamples();
    const at = (i) => samples[i % samples.length] / 32768;
    const step = RATE / 30; // a recording at 30 fps
    const blocks = new Map();
    let inTurn = spectrumTexture(at, 0, step, blocks);
    for (let i = 0; i <= 60; i++) inTurn = spectrumTexture(at, i * step, step, blocks);
    expect(Array.from(inTurn)).toEqual(Array.from(spectrumTexture(at, 60 * step, step)));
  });

  // With Chromium's fake camera and microphone (a moving picture, a beeping tone), the
  // devices reach the shader as the site gives them: the camera's picture at its own size, the
  // microphone's 512 × 2 texture.
  test('the webcam and the microphone of a fake device reach iChannel0 at their sizes', async () => {
    await withServedDir('test-fake-device', async (dir, base) => {
      fs.writeFileSync(
        path.join(dir, 'size.glsl'),
        'void mainImage(out vec4 c, in vec2 p) { c = vec4(iChannelResolution[0].xy / 2048.0, texture(iChannel0, vec2(0.5)).g, 1.0); }\n',
      );
      await withPage(async ({ context }) => {
        const browser = await launchBrowser({
          args: [...CHROME_ARGS, '--use-fake-device-for-media-stream', '--use-fake-ui-for-media-stream'],
        });
        try {
          const page = await browser.newPage();
          await page.goto(`${context.baseUrl}/?shader=/${base}/size.glsl&size=8x8&time=0`, { waitUntil: 'load' });
          await page.waitForFunction(() => window.shaderEngine || document.documentElement.dataset.error, { polling: 50, timeout: 20_000 });
          expect(
            await page.evaluate(() =>
              window.shaderEngine.ready.then(
                () => 'ok',
                (e) => String(e?.message ?? e),
              ),
            ),
          ).toBe('ok');
          // the page asks for 1280 × 720 (ideal), which the fake camera gives
          /** @type {Array<[string, number, number]>} */
          const devices = [
            ['webcam:', 1280, 720],
            ['mic:', 512, 2],
          ];
          for (const [source, width, height] of devices) {
            const outcome = await page.evaluate(
              (s) =>
                window.shaderEngine.setChannel(0, s).then(
                  () => 'ok',
                  (e) => e.message,
                ),
              source,
            );
            expect(outcome, source).toBe('ok');
            const r = await hook(page).readPixels();
            const [red, green] = Buffer.from(r.data, 'base64');
            expect([red, green], `${source}: iChannelResolution.xy / 2048`).toEqual([
              Math.round((width / 2048) * 255),
              Math.round((height / 2048) * 255),
            ]);
          }
        } finally {
          await browser.close();
        }
      });
    });
  }, 90_000);
});
