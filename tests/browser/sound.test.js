// The Sound tab (issue 38, items 2 and 3): `mainSound` rendered on the GPU as the site renders it
// (src/shadertoy/sound.js), its samples in a WAV from the command line, in a recording's Opus
// track, and checked against what is computed here: tones at known frequencies and amplitudes
// (a DFT at their bins), no jump at the site's block boundaries, and the site's packing with its
// byte-wise clamping and 16-bit quantisation.

import { execFile } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { promisify } from 'node:util';
import { ALL_FORMATS, BufferSource, Input } from 'mediabunny';
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import { builtPage } from '../../src/headless/page-server.js';
import { BLOCK_SAMPLES, SAMPLE_RATE, soundBlocks, toPcm16, toPlayed, unpackBlock } from '../../src/shadertoy/sound.js';
import { decodeWav, encodeWav } from '../../src/shared/wav.js';
import { rmsDifference, spectrumDifference } from '../../src/runner/sound-compare.js';
import { disconnect } from '../support/page.js';
import { REPO_ROOT } from '../support/config.js';
import { withPage } from '../support/page-helpers.js';
import { LEAD_SECONDS, PLAY_SAMPLES, blocksToPlay, driftAt, planPlayback, sampleAt } from '../../src/player/sound/schedule.js';
import { hook } from '../support/hook.js';

afterAll(disconnect);

const IMAGE = 'void mainImage(out vec4 c, in vec2 f) { c = vec4(0.2, 0.4, 0.6, 1.0); }';

/** A Shadertoy export with an Image tab and this Sound tab. */
const withSound = (sound) =>
  JSON.stringify({
    Shader: {
      ver: '0.1',
      info: { name: 'sound' },
      renderpass: [
        { inputs: [], outputs: [{ id: '4dfGRr', channel: 0 }], code: IMAGE, name: 'Image', description: '', type: 'image' },
        { inputs: [], outputs: [], code: sound, name: 'Sound', description: '', type: 'sound' },
      ],
    },
  });

/** Amplitude of frequency f in x (a DFT at that one frequency: x holds whole periods of it). */
function amplitude(x, f) {
  let re = 0;
  let im = 0;
  for (let i = 0; i < x.length; i++) {
    const a = (2 * Math.PI * f * i) / SAMPLE_RATE;
    re += x[i] * Math.cos(a);
    im += x[i] * Math.sin(a);
  }
  return (2 * Math.hypot(re, im)) / x.length;
}

/** Channel c of interleaved 16-bit samples, in [-1, 1). */
const channel = (pcm, c) => Float64Array.from({ length: pcm.length / 2 }, (_, i) => pcm[2 * i + c] / 32768);

/** The page's samples [time, time + duration) of the shader on it (window.shaderEngine.renderSound). */
async function pageSound(page, time, duration) {
  const { data } = await hook(page).renderSound({ time, duration });
  const bytes = Buffer.from(data, 'base64');
  return new Int16Array(bytes.buffer, bytes.byteOffset, bytes.byteLength / 2);
}

/** Runs a page test on a shader with this Sound tab. */
async function onPage(sound, body) {
  await withPage(async ({ page, goto }) => {
    await goto('?size=64x36&time=0');
    const result = await hook(page).setProject(withSound(sound));
    expect(result.ok, result.error).toBe(true);
    await body(page);
  });
}

/** `seconds` of a stereo sine at f Hz, amplitude a, `delay` samples late. */
const sine = (f, a, seconds = 0.5, delay = 0) =>
  Int16Array.from({ length: 2 * Math.round(seconds * SAMPLE_RATE) }, (_, i) =>
    Math.round(32767 * a * Math.sin((2 * Math.PI * f * (Math.floor(i / 2) - delay)) / SAMPLE_RATE)),
  );

describe("test's comparison of sound (sound-compare.js)", () => {
  test.each([
    // what, actual, reference, RMS difference, spectrum difference (bounds)
    ['the same', sine(440, 0.5), sine(440, 0.5), [0, 0], [0, 0]],
    ['one 16-bit step off', sine(440, 0.5).map((v) => v + 1), sine(440, 0.5), [3e-5, 3.1e-5], [0, 0.001]],
    ['2% quieter', sine(440, 0.49), sine(440, 0.5), [0.006, 0.0075], [0.015, 0.025]],
    ['ten samples late', sine(440, 0.5, 0.5, 10), sine(440, 0.5), [0.1, 0.5], [0, 0.01]],
    ['another note', sine(660, 0.5), sine(440, 0.5), [0.4, 0.6], [1, 2.1]],
    ['silence against a tone', sine(440, 0), sine(440, 0.5), [0.35, 0.36], [0.99, 1.01]],
  ])('%s', (_, actual, reference, [rmsLow, rmsHigh], [specLow, specHigh]) => {
    const rms = rmsDifference(actual, reference);
    const spectrum = spectrumDifference(actual, reference);
    expect(rms).toBeGreaterThanOrEqual(rmsLow);
    expect(rms).toBeLessThanOrEqual(rmsHigh);
    expect(spectrum).toBeGreaterThanOrEqual(specLow);
    expect(spectrum).toBeLessThanOrEqual(specHigh);
  });
});

describe('the contract, computed here', () => {
  test('blocks are the site grid of 262,144 samples; words unpack as low + 256 high, played as -1 + 2u/65535', () => {
    expect(BLOCK_SAMPLES).toBe(512 * 512);
    expect(soundBlocks(0, 1)).toEqual([0]);
    expect(soundBlocks(BLOCK_SAMPLES - 1, 2)).toEqual([0, 1]);
    expect(soundBlocks(5.5 * SAMPLE_RATE, 2 * SAMPLE_RATE)).toEqual([0, 1]);
    const words = unpackBlock(new Uint8Array([0, 0, 255, 255, 0x34, 0x12, 0, 0x80]), 2);
    expect([...words]).toEqual([0, 65535, 0x1234, 0x8000]);
    expect([...toPcm16(words)]).toEqual([-32768, 32767, 0x1234 - 32768, 0]);
    const [left, right] = toPlayed(words);
    expect([left[0], right[0], right[1]]).toEqual([-1, 1, Math.fround(-1 + 65536 / 65535)]);
  });

  test('a WAV holds its samples as written: stereo, 16-bit, 44,100 Hz', () => {
    const pcm = Int16Array.from([0, -1, 32767, -32768, 1234, -4321]);
    const back = decodeWav(encodeWav(pcm, SAMPLE_RATE));
    expect(back.sampleRate).toBe(SAMPLE_RATE);
    expect(back.channels).toBe(2);
    expect([...back.pcm]).toEqual([...pcm]);
  });
});

describe('the command line', () => {
  let folder = '';
  beforeAll(async () => {
    folder = fs.mkdtempSync(path.join(os.tmpdir(), 'shaderproof-sound-'));
    await builtPage();
  });
  afterAll(() => fs.rmSync(folder, { recursive: true, force: true }));

  /** Runs the command line in the folder: {code, stdout, stderr}. */
  const shaderproof = async (...args) => {
    try {
      const { stdout, stderr } = await promisify(execFile)(process.execPath, [path.join(REPO_ROOT, 'bin', 'shaderproof.js'), ...args], {
        cwd: folder,
        timeout: 100_000,
      });
      return { code: 0, stdout, stderr };
    } catch (error) {
      if (typeof error.code !== 'number') throw error;
      return { code: error.code, stdout: error.stdout, stderr: error.stderr };
    }
  };

  test("test compares a case's Sound tab with its reference WAV, written only by --update", async () => {
    const dir = path.join(folder, 'cases');
    fs.mkdirSync(dir, { recursive: true });
    const tone = (f) => withSound(`vec2 mainSound(int samp, float time) { return vec2(0.4 * sin(6.2831853 * ${f}.0 * time)); }`);
    fs.writeFileSync(path.join(dir, 'tone.json'), tone(440));
    const manifest = {
      cases: { 'tone.json': { size: '8x8', sound: { time: 1, duration: 0.5, tolerance: { rms: 1e-4, spectrum: 0.05 } } } },
    };
    fs.writeFileSync(path.join(dir, 'shaderproof.json'), JSON.stringify(manifest));
    const missing = await shaderproof('test', 'cases', '--out', 'report');
    expect(missing.code).toBe(1);
    expect(missing.stdout).toMatch(/no sound reference at .*tone\.json\.wav: run with --update/);
    expect((await shaderproof('test', 'cases', '--update', '--out', 'report')).code).toBe(0);
    const { pcm } = decodeWav(new Uint8Array(fs.readFileSync(path.join(dir, '__references__', 'tone.json.wav'))));
    expect(pcm.length).toBe(2 * 0.5 * SAMPLE_RATE);
    const same = await shaderproof('test', 'cases', '--out', 'report');
    expect(same.code, same.stdout).toBe(0);
    fs.writeFileSync(path.join(dir, 'tone.json'), tone(445)); // a little sharp: the picture is the same
    const sharp = await shaderproof('test', 'cases', '--out', 'report');
    expect(sharp.code).toBe(1);
    expect(sharp.stdout).toMatch(/sound: the RMS difference from the reference is/);
    expect(sharp.stdout).toMatch(/sound: the spectrum differs from the reference's by/);
    expect(fs.existsSync(path.join(folder, 'report', 'tone.json-actual.wav'))).toBe(true);
  });

  test('render -o OUT.wav: 440 Hz at 0.5 on the left and 660 Hz at 0.25 on the right, within 3%, from --time', async () => {
    const shader = path.join(folder, 'tones.json');
    fs.writeFileSync(
      shader,
      withSound(
        'vec2 mainSound(int samp, float time) { return vec2(0.5 * sin(6.2831853 * 440.0 * time), 0.25 * sin(6.2831853 * 660.0 * time)); }',
      ),
    );
    const wav = path.join(folder, 'tones.wav');
    const bin = path.join(REPO_ROOT, 'bin', 'shaderproof.js');
    const { stdout } = await promisify(execFile)(process.execPath, [bin, 'render', shader, '-o', wav, '--duration', '1', '--time', '5.5'], {
      cwd: folder,
      timeout: 100_000,
    });
    expect(stdout).toMatch(/tones\.wav: 1\.00 s of stereo 16-bit sound at 44100 Hz, from 5\.5 s/);
    const { pcm, sampleRate, channels } = decodeWav(new Uint8Array(fs.readFileSync(wav)));
    expect([sampleRate, channels, pcm.length]).toEqual([44_100, 2, 2 * 44_100]);
    const [left, right] = [channel(pcm, 0), channel(pcm, 1)];
    /** @type {Array<[Float64Array, number, number]>} */
    const cases = [
      [left, 440, 0.5],
      [right, 660, 0.25],
      [left, 660, 0],
      [right, 440, 0],
    ];
    for (const [x, f, want] of cases) {
      const got = amplitude(x, f);
      if (want) expect(Math.abs(got - want) / want, `${f} Hz: ${got}`).toBeLessThan(0.03);
      else expect(got, `${f} Hz where there is none`).toBeLessThan(0.005);
    }
  });
});

describe("the page: the site's blocks and packing", () => {
  test("a sine runs on across the site's block boundaries with no jump (its sample-to-sample difference)", async () => {
    const f = 100;
    await onPage(
      `vec2 mainSound(int samp, float time) { return vec2(0.5 * sin(6.2831853 * ${f}.0 * time), 0.5 * cos(6.2831853 * ${f}.0 * float(samp) / iSampleRate)); }`,
      async (page) => {
        for (const boundary of [BLOCK_SAMPLES, 2 * BLOCK_SAMPLES]) {
          const around = 2000;
          const pcm = await pageSound(page, (boundary - around) / SAMPLE_RATE, (2 * around) / SAMPLE_RATE);
          for (const c of [0, 1]) {
            const x = channel(pcm, c);
            const first = boundary - around;
            let worst = 0;
            for (let i = 1; i < x.length; i++) {
              const t = (first + i) / SAMPLE_RATE;
              const wave = (s) => (c === 0 ? 0.5 * Math.sin(2 * Math.PI * f * s) : 0.5 * Math.cos(2 * Math.PI * f * s));
              const want = wave(t) - wave(t - 1 / SAMPLE_RATE);
              worst = Math.max(worst, Math.abs(x[i] - x[i - 1] - want));
            }
            // one repeated or skipped sample would be off by a whole step (up to 0.007 here); float32
            // time at 12 s is good to 1e-6 s, a few 1e-4 of the wave
            expect(worst, `channel ${c} around sample ${boundary}`).toBeLessThan(2e-3);
          }
        }
      },
    );
  });

  test('out-of-range values clamp byte by byte and quantise to 16 bits, as the site packs them (computed here)', async () => {
    const values = [-1.5, -1.2, -1.0, -0.7, -1 / 65536, 0, 0.3, 0.99999, 1.0, 1.2, 1.5, 2.0];
    const table = values.map((v) => v.toPrecision(9)).join(', ');
    const code = `vec2 mainSound(int samp, float time) {
    float v[${values.length}] = float[](${table});
    float y = v[samp % ${values.length}];
    return vec2(y, -y);
}`;
    /** The site's packing in float32 (EffectPass.MakeHeader_Sound), each byte clamped by the RGBA8 target, unpacked to PCM. */
    const packed = (y) => {
      const v = Math.floor(Math.fround(Math.fround(0.5 + Math.fround(0.5 * Math.fround(y))) * 65536));
      const low = Math.min(255, Math.max(0, v - 256 * Math.floor(v / 256)));
      const high = Math.min(255, Math.max(0, Math.floor(v / 256)));
      return low + 256 * high - 32768;
    };
    await onPage(code, async (page) => {
      const pcm = await pageSound(page, 0, (2 * values.length) / SAMPLE_RATE);
      const got = Array.from({ length: 2 * values.length }, (_, i) => [pcm[2 * i], pcm[2 * i + 1]]);
      const want = Array.from({ length: 2 * values.length }, (_, i) => [
        packed(values[i % values.length]),
        packed(-values[i % values.length]),
      ]);
      expect(got).toEqual(want);
      // not a plain clamp: 1.2 comes out below full scale, its low byte having wrapped
      expect(packed(1.2)).toBeLessThan(packed(1.0) + 256);
    });
  });

  test('a WebM recording of a shader with a Sound tab carries an Opus track as long as its frames', async () => {
    await onPage('vec2 mainSound(int samp, float time) { return vec2(0.3 * sin(6.2831853 * 440.0 * time)); }', async (page) => {
      const recording = await hook(page).record({ format: 'webm', frames: 15, fps: 30, width: 64, height: 36 });
      expect(recording.audio).toBe('opus');
      const input = new Input({ source: new BufferSource(Buffer.from(recording.data, 'base64')), formats: ALL_FORMATS });
      const [audio] = await input.getAudioTracks();
      const [video] = await input.getVideoTracks();
      expect(audio?.codec).toBe('opus');
      expect(audio?.numberOfChannels).toBe(2);
      // 0.5 s of frames; Opus ends within a packet (20 ms) and its encoder's look-ahead of it
      expect(Math.abs((await audio.computeDuration()) - 0.5)).toBeLessThan(0.03);
      expect(await video.computeDuration()).toBeCloseTo(0.5, 2);
    });
  });
});

const TONES =
  'vec2 mainSound(int samp, float time) { return vec2(0.5 * sin(6.2831853 * 440.0 * time), 0.25 * sin(6.2831853 * 660.0 * time)); }';
/** Web Audio renders in quanta of 128 samples: the finest step a start can be placed at. */
const QUANTUM = 128;

describe("the page's playback, in step with iTime", () => {
  test('a Sound tab that does not compile is said at its own line, as the other tabs are', async () => {
    await withPage(async ({ page, goto }) => {
      await goto('?size=64x36&time=0');
      const json = withSound('vec2 mainSound(int samp, float time) {\n  return vec2(nope);\n}');
      const result = await hook(page).setProject(json);
      expect(result.ok).toBe(false);
      expect(result.error).toMatch(/^Sound:2: error: .*nope/im);
      expect(result.error).toMatch(/return vec2\(nope\);/);
    });
  });

  test.each([
    // clock, and the sample that plays when the sound starts (LEAD_SECONDS after now)
    [
      'from the start',
      { time: 0, speed: 1, playing: true, now: 3 },
      { sample: Math.round(LEAD_SECONDS * SAMPLE_RATE), when: 3 + LEAD_SECONDS, rate: 1 },
    ],
    [
      'after a seek to 7.25 s',
      { time: 7.25, speed: 1, playing: true, now: 50 },
      { sample: Math.round((7.25 + LEAD_SECONDS) * SAMPLE_RATE), when: 50 + LEAD_SECONDS, rate: 1 },
    ],
    [
      'at speed 2',
      { time: 1, speed: 2, playing: true, now: 0 },
      { sample: Math.round((1 + 2 * LEAD_SECONDS) * SAMPLE_RATE), when: LEAD_SECONDS, rate: 2 },
    ],
    ['paused', { time: 4, speed: 1, playing: false, now: 0 }, null],
    ['at speed 0', { time: 4, speed: 0, playing: true, now: 0 }, null],
    ['past the 180 s the site renders', { time: 180, speed: 1, playing: true, now: 0 }, null],
  ])('the plan %s', (_, clock, want) => {
    const plan = planPlayback(clock);
    expect(plan).toEqual(want);
    if (!plan) return;
    // a second later the sound is at iTime a second (of the clock's speed) later, to the sample
    expect(driftAt(plan, plan.when + 1, clock.time + LEAD_SECONDS * clock.speed + clock.speed)).toBeCloseTo(0, 4);
  });

  test('blocks follow one another with no gap or overlap, the first from the planned sample', () => {
    const plan = { sample: BLOCK_SAMPLES - 1000, when: 10, rate: 2 };
    const blocks = blocksToPlay(plan, 10 + 10);
    expect(blocks.map((b) => b.block)).toEqual([0, 1, 2, 3, 4]); // at speed 2 a block of 5.9 s lasts 3 s
    expect(blocks[0]).toEqual({ block: 0, offset: (BLOCK_SAMPLES - 1000) / SAMPLE_RATE, when: 10 });
    for (const b of blocks.slice(1)) {
      expect(b.offset).toBe(0);
      expect(sampleAt(plan, b.when)).toBeCloseTo(b.block * BLOCK_SAMPLES, 6);
    }
    const last = blocksToPlay({ sample: PLAY_SAMPLES - 10, when: 0, rate: 1 }, 1000);
    expect(last.map((b) => b.block)).toEqual([Math.floor(PLAY_SAMPLES / BLOCK_SAMPLES)]); // and no block past 180 s
  });

  test("on the page: silent and said so until a key; after a pause and a seek, the sample started is iTime's", async () => {
    await onPage(TONES, async (page) => {
      const state = () => hook(page).soundState();
      expect(await state()).toMatchObject({ available: true, context: null, plan: null });
      expect(await page.$eval('#sound-note', (n) => n.textContent)).toMatch(/plays once you click or press a key/);
      await hook(page).pause();
      await hook(page).setTime(7.25);
      await page.keyboard.press('Shift'); // the first interaction: the autoplay rule is met
      await page.waitForFunction(() => window.shaderEngine.soundState().context === 'running', { polling: 50 });
      expect(await page.$('#sound-note')).toBeNull();
      expect(await state()).toMatchObject({ plan: null, sources: 0 }); // paused: silent

      /** The plan's first sample is iTime's (when it was made, plus the lead) to within a quantum. */
      const inStep = async (time) => {
        await page.waitForFunction((t) => Math.abs((window.shaderEngine.soundState().plan?.time ?? -1) - t) < 0.5, { polling: 20 }, time);
        const { plan } = await state();
        if (!plan) throw new Error('no plan');
        expect(Math.abs(plan.sample - (plan.time + LEAD_SECONDS * plan.rate) * SAMPLE_RATE)).toBeLessThanOrEqual(QUANTUM);
        return plan;
      };
      await hook(page).play();
      const resumed = await inStep(7.25);
      expect(resumed.time).toBe(7.25); // paused at 7.25: it starts there, not where it was before
      await page.waitForFunction(() => window.shaderEngine.soundState().sources > 0, { polling: 20 });

      await hook(page).setTime(20); // a seek while playing
      const sought = await inStep(20);
      expect(sought.time).toBeGreaterThanOrEqual(20);

      await hook(page).pause();
      await page.waitForFunction(() => window.shaderEngine.soundState().sources === 0, { polling: 20 });
      expect((await state()).plan).toBeNull();

      await hook(page).setSpeed(2);
      await hook(page).play();
      expect((await inStep(20)).rate).toBe(2);
      await hook(page).setMuted(true);
      expect(await page.$eval('#toolbar .sound-mute', (b) => b.getAttribute('aria-pressed'))).toBe('true');
      await page.evaluate(() => {
        window.shaderEngine.setMuted(false);
        window.shaderEngine.setSpeed(1);
        window.shaderEngine.pause();
      });
    });
  });
});
