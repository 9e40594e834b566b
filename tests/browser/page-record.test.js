// Recording (src/player/io/recorder.js, src/studio/ui/toolbar/record-dialog.js), end to end in the real browser: a
// test shader that paints iFrame, iTime and iTimeDelta as colour is recorded frame by frame at a
// fixed frame rate and size, through window.shaderEngine.record() and through the toolbar's
// "Record" button; the WebM is read back in Node with mediabunny (frame count, size, times; its
// frames, decoded by the browser's VideoDecoder, show their iFrame and iTime), the PNG sequence
// with fflate and pngjs (frame count, size, and each frame's iFrame and iTime in its colour).
// Cancel stops a recording and nothing is saved.
import { unzipSync } from 'fflate';
import { ALL_FORMATS, BufferSource, EncodedPacketSink, Input } from 'mediabunny';
import { PNG } from 'pngjs';
import { afterAll, describe, expect, test } from 'vitest';
import { disconnect } from '../support/page.js';
import { button, info, typeInEditor, withControl, withPage } from '../support/page-helpers.js';
import { captureDownloads } from '../support/downloads.js';
import { hook } from '../support/hook.js';

afterAll(disconnect);

/** Paints rgb(16·iFrame, 100·iTime, 1000·iTimeDelta) / 255 everywhere. */
const CLOCK_SHADER = `void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(float(iFrame) * 16.0, iTime * 100.0, iTimeDelta * 1000.0, 255.0) / 255.0;
}
`;
const FPS = 10;
const FRAMES = 6;

/** What the clock shader paints in frame i at FPS. */
const expectedColour = (i) => [16 * i, Math.round((100 * i) / FPS), 1000 / FPS];

/** Opens the page at 64×36 playing the clock shader. */
async function openClockShader(page, goto) {
  await goto('?size=64x36');
  const outcome = await hook(page).setSource(CLOCK_SHADER);
  expect(outcome).toEqual({ ok: true });
}

/** The WebM's video track: size, codec and its packets' times (seconds), read with mediabunny. */
async function readWebm(bytes) {
  const input = new Input({ source: new BufferSource(bytes), formats: ALL_FORMATS });
  expect(await input.getMimeType()).toMatch(/^video\/webm/);
  const track = await input.getPrimaryVideoTrack();
  expect(track, 'the WebM has a video track').toBeTruthy();
  const times = [];
  const keys = [];
  for await (const packet of new EncodedPacketSink(track).packets()) {
    times.push(packet.timestamp);
    keys.push(packet.type === 'key');
  }
  return { width: track.displayWidth, height: track.displayHeight, codec: track.codec, times, keys };
}

function expectWebm(webm, { width, height, frames, fps }) {
  expect(['vp8', 'vp9']).toContain(webm.codec);
  expect({ width: webm.width, height: webm.height }).toEqual({ width, height });
  expect(webm.times.length, 'frames in the WebM').toBe(frames);
  webm.times.forEach((t, i) => expect(t).toBeCloseTo(i / fps, 3));
  expect(webm.keys[0], 'the first frame is a key frame').toBe(true);
}

/**
 * The WebM's frames decoded by the browser's VideoDecoder (mediabunny demuxes it here, in Node):
 * the colour at each frame's centre.
 */
async function decodeWebmInPage(page, bytes) {
  const input = new Input({ source: new BufferSource(bytes), formats: ALL_FORMATS });
  const track = await input.getPrimaryVideoTrack();
  const config = await track.getDecoderConfig();
  const packets = [];
  for await (const packet of new EncodedPacketSink(track).packets()) {
    packets.push({ type: packet.type, timestamp: packet.timestamp, data: Buffer.from(packet.data).toString('base64') });
  }
  return page.evaluate(
    async (config, packets) => {
      const colours = [];
      const decoder = new VideoDecoder({
        output: (frame) => {
          const canvas = new OffscreenCanvas(frame.displayWidth, frame.displayHeight);
          const context = canvas.getContext('2d');
          context.drawImage(frame, 0, 0);
          frame.close();
          colours.push([...context.getImageData(canvas.width >> 1, canvas.height >> 1, 1, 1).data.subarray(0, 3)]);
        },
        error: () => {}, // flush() rejects with it
      });
      decoder.configure(config);
      for (const p of packets) {
        const data = Uint8Array.from(atob(p.data), (c) => c.charCodeAt(0));
        decoder.decode(new EncodedVideoChunk({ type: p.type, timestamp: Math.round(p.timestamp * 1e6), data }));
      }
      await decoder.flush();
      decoder.close();
      return colours;
    },
    config,
    packets,
  );
}

/** The PNG sequence's frames, in order, decoded. */
function readPngZip(bytes) {
  const files = unzipSync(bytes);
  const names = Object.keys(files).sort();
  return names.map((name) => ({ name, ...PNG.sync.read(Buffer.from(files[name])) }));
}

/**
 * Runs `body(page, downloads)` on a page running the clock shader with the Record popover open,
 * its downloads captured.
 * @param {(page: import('puppeteer-core').Page, downloads: Awaited<ReturnType<typeof captureDownloads>>) => Promise<void>} body
 */
async function withRecordDialog(body) {
  let downloads;
  await withPage(async ({ page, goto }) => {
    await openClockShader(page, goto);
    downloads = await captureDownloads(page);
    await (await button(page, 'Record')).click();
    await body(page, downloads);
  }).finally(() => downloads?.close());
}

/** Sets a field of the Record popover as a person does: select it all, type the value. */
async function fill(page, label, value) {
  const input = await page.$(`.record-dialog ::-p-aria([name="${label}"])`);
  if (!input) throw new Error(`no field "${label}" in the Record popover`);
  await input.click({ count: 3 });
  await input.type(String(value));
}

describe('Recording', () => {
  test('raytracer.record(): a WebM of 6 frames at 10 fps at the canvas size decodes to 6 frames of 64×36 at i/10 s, each showing its iFrame and iTime', async () => {
    await withPage(async ({ page, goto }) => {
      await openClockShader(page, goto);
      expect((await info(page)).playing).toBe(true);
      const result = await hook(page).record({ format: 'webm', frames: FRAMES, fps: FPS });
      expect({ ...result, data: undefined }).toMatchObject({
        format: 'webm',
        frames: FRAMES,
        fps: FPS,
        width: 64,
        height: 36,
        mimeType: 'video/webm',
      });
      expectWebm(await readWebm(Buffer.from(result.data, 'base64')), { width: 64, height: 36, frames: FRAMES, fps: FPS });
      // lossy, but flat colours come back within a few levels: each frame shows its own iFrame and iTime
      const colours = await decodeWebmInPage(page, Buffer.from(result.data, 'base64'));
      expect(colours.length).toBe(FRAMES);
      colours.forEach((rgb, i) =>
        expectedColour(i).forEach((v, c) => expect(Math.abs(rgb[c] - v), `decoded frame ${i}: rgb(${rgb})`).toBeLessThanOrEqual(4)),
      );
      expect((await info(page)).playing, 'the page plays again after recording').toBe(true);
    });
  });

  test("raytracer.record(): a PNG sequence holds one PNG per frame, of the chosen size, each painted with its frame's iFrame, iTime and iTimeDelta", async () => {
    await withPage(async ({ page, goto }) => {
      await openClockShader(page, goto);
      await hook(page).pause();
      const result = await hook(page).record({ format: 'png', frames: FRAMES, fps: FPS, width: 40, height: 30 });
      expect(result).toMatchObject({ format: 'png', mimeType: 'application/zip', frames: FRAMES, width: 40, height: 30 });
      const images = readPngZip(new Uint8Array(Buffer.from(result.data, 'base64')));
      expect(images.map((image) => image.name)).toEqual([0, 1, 2, 3, 4, 5].map((i) => `frame-000${i}.png`));
      images.forEach((image, i) => {
        expect({ width: image.width, height: image.height }).toEqual({ width: 40, height: 30 });
        for (const [x, y] of [
          [0, 0],
          [39, 29],
          [20, 15],
        ]) {
          const at = (y * image.width + x) * 4;
          const rgba = [...image.data.subarray(at, at + 4)];
          expectedColour(i).forEach((v, c) =>
            expect(Math.abs(rgba[c] - v), `${image.name} (${x}, ${y}) rgba(${rgba})`).toBeLessThanOrEqual(1),
          );
          expect(rgba[3]).toBe(255);
        }
      });
      expect((await info(page)).playing, 'a paused page stays paused').toBe(false);
    });
  });

  test('the toolbar\'s "Record" button: format, frames, fps and size in its popover, a progress bar, and a WebM download', async () => {
    await withRecordDialog(async (page, downloads) => {
      expect(await page.$eval('.record-dialog', (d) => !(/** @type {HTMLElement} */ (d).hidden))).toBe(true);
      expect(await page.$eval('.record-dialog [aria-label="Width"]', (i) => /** @type {HTMLInputElement} */ (i).value)).toBe('64');
      await page.select('.record-dialog [aria-label="Format"]', 'webm');
      await fill(page, 'Frames per second', FPS);
      await fill(page, 'Frames', FRAMES);
      await fill(page, 'Width', 48);
      await fill(page, 'Height', 28);
      expect(
        await page.$eval('.record-dialog [aria-label="Duration (s)"]', (i) => Number(/** @type {HTMLInputElement} */ (i).value)),
      ).toBeCloseTo(FRAMES / FPS, 5);
      await (await page.$('.record-dialog ::-p-aria([name="Start"][role="button"])')).click();
      const file = await downloads.next();
      expect(file.name).toMatch(/-48x28-10fps-6f\.webm$/);
      expectWebm(await readWebm(file.bytes), { width: 48, height: 28, frames: FRAMES, fps: FPS });
      expect(await page.$eval('progress', (p) => p.value)).toBe(1);
      expect(
        await page.$eval('.record-dialog', (d) => /** @type {HTMLElement} */ (d).hidden),
        'the popover closes when the file is saved',
      ).toBe(true);
      expect((await info(page)).playing).toBe(true);
    });
  });

  test('Cancel stops a recording: nothing is saved, the page plays again; raytracer.cancelRecording() rejects record()', async () => {
    await withRecordDialog(async (page, downloads) => {
      await fill(page, 'Frames', 3000);
      await (await page.$('.record-dialog ::-p-aria([name="Start"][role="button"])')).click();
      await page.waitForFunction(() => document.querySelector('.record-dialog progress').getAttribute('value') !== '0', { polling: 20 });
      expect((await info(page)).playing, 'the live loop is paused while recording').toBe(false);
      await (await page.$('.record-dialog ::-p-aria([name="Cancel"][role="button"])')).click();
      await page.waitForFunction(() => !window.shaderEngine.recording().busy, { polling: 20 });
      expect(await page.$eval('.record-status', (s) => s.textContent)).toMatch(/cancelled/i);
      expect(await page.$eval('progress', (p) => p.value)).toBe(0);
      expect((await info(page)).playing).toBe(true);

      const outcome = await page.evaluate(async () => {
        const recording = window.shaderEngine.record({ frames: 3000, fps: 30 });
        while (!window.shaderEngine.recording().busy) await new Promise((r) => setTimeout(r, 5));
        await new Promise((r) => setTimeout(r, 50));
        window.shaderEngine.cancelRecording();
        return recording.then(
          () => 'finished',
          (error) => error.name,
        );
      });
      expect(outcome).toBe('RecordingCancelled');
      await new Promise((r) => setTimeout(r, 1000));
      expect(downloads.pending(), 'nothing was downloaded').toEqual([]);
    });
  });

  // One file stem for every download (issue 17): the recording of an edited shader was named
  // "raytrace-…" while its screenshot was "raytrace-edited-…".
  test('an edited shader\'s recording and screenshot carry the same name: "raytrace-edited-…"', async () => {
    let downloads;
    await withPage(async ({ page, goto }) => {
      await goto('?size=32x18&time=1&BOUNCES=0'); // the built-in raytracer, small and cheap
      downloads = await captureDownloads(page);
      await typeInEditor(page, '\n// edited', 'end');
      await withControl(page, 'Enter');
      await page.waitForFunction(() => window.shaderEngine.info().fileName === 'raytrace.glsl (edited)', { polling: 50 });
      await (await button(page, 'Screenshot')).click();
      expect((await downloads.next()).name).toMatch(/^raytrace-edited-t1\.00-32x18\.png$/);
      await (await button(page, 'Record')).click();
      await fill(page, 'Frames per second', FPS);
      await fill(page, 'Frames', 2);
      await (await page.$('.record-dialog ::-p-aria([name="Start"][role="button"])')).click();
      expect((await downloads.next()).name).toBe(`raytrace-edited-32x18-${FPS}fps-2f.webm`);
    }).finally(() => downloads?.close());
  });
});
