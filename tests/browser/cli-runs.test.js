// What a new user hit with the command line (issue 36, items 1 to 6), run as they ran it: the
// repository's bin/shaderproof.js in a folder of their own, each run its own Chromium. A clock
// and a frame-rate reader draw the same on every run and the right values, computed here; frame
// N past the recorder's cap is frame N; no bad input touches an output file already there; a
// control out of range is said.

import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { unzipSync } from 'fflate';
import { PNG } from 'pngjs';
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import { DEFAULT_DATE } from '../../src/api/view-options.js';
import { builtPage } from '../../src/headless/page-server.js';
import { runShaderproof } from '../support/shaderproof-child.js';
import { readPng } from '../support/images.js';

let folder = '';
beforeAll(async () => {
  folder = fs.mkdtempSync(path.join(os.tmpdir(), 'shaderproof-runs-'));
  await builtPage(); // the harness built dist/ for this run: no build inside a test's time
});
afterAll(() => fs.rmSync(folder, { recursive: true, force: true }));

/** Runs the command in the folder: { code, stdout, stderr }. */
const shaderproof = (...args) => runShaderproof(args, { cwd: folder, timeout: 100_000 });

const write = (name, text) => {
  fs.mkdirSync(path.dirname(path.join(folder, name)), { recursive: true });
  fs.writeFileSync(path.join(folder, name), text);
};
const byte = (v) => Math.round(Math.min(1, Math.max(0, v)) * 255);
const fract = (v) => v - Math.floor(v);

/** The seconds of iDate in three scales: a real date moves the blue channel within milliseconds. */
const CLOCK = `void mainImage(out vec4 c, in vec2 f) {
    c = vec4(fract(iDate.w / 60.0), fract(iDate.w / 3600.0), fract(iDate.w * 10.0), 1.0);
}
`;
/** iFrameRate / 255, iTimeDelta x 3, and iTime x 10 / 255 (none half-way between two bytes). */
const RATE = `void mainImage(out vec4 c, in vec2 f) {
    c = vec4(iFrameRate / 255.0, iTimeDelta * 3.0, iTime * 10.0 / 255.0, 1.0);
}
`;

describe('issue 36: determinism by default', () => {
  test('a clock and a frame-rate reader pass their own references a while later, at the values computed here', async () => {
    write('shaders/clock.glsl', CLOCK);
    write('shaders/rate.glsl', RATE);
    write('shaders/shaderproof.json', JSON.stringify({ defaults: { size: '8x4', time: 2.5 } }));
    const update = await shaderproof('test', 'shaders', '--update', '--out', 'report');
    expect(update.code, update.stdout + update.stderr).toBe(0);
    expect(update.stderr).toContain(`iDate at iTime 0: ${new Date(DEFAULT_DATE).toISOString()}`);
    await new Promise((resolve) => setTimeout(resolve, 1_100)); // a real clock's blue would move
    const again = await shaderproof('test', 'shaders', '--out', 'report');
    expect(again.code, again.stdout).toBe(0);
    expect(again.stdout).toMatch(/2 passed, 0 failed/);
    expect(fs.readFileSync(path.join(folder, 'report/junit.xml'), 'utf8')).toContain(
      '<property name="iDate" value="2024-01-15T12:00:00.000Z"/>',
    );

    const seconds = (Date.parse(DEFAULT_DATE) % 86_400_000) / 1000 + 2.5; // local = UTC in the browser
    const clock = readPng(path.join(folder, 'shaders/__references__/clock.glsl.png'));
    expect([...clock.data.subarray(0, 3)]).toEqual([byte(fract(seconds / 60)), byte(fract(seconds / 3600)), byte(fract(seconds * 10))]);
    // a paused still: the schedule's rate (60 fps), not a measured one
    const rate = readPng(path.join(folder, 'shaders/__references__/rate.glsl.png'));
    expect([...rate.data.subarray(0, 3)]).toEqual([byte(60 / 255), byte(3 / 60), byte(25 / 255)]);
  });

  test("--date moves iDate, and a recording's frames have the schedule's iFrameRate and iTimeDelta", async () => {
    write('shaders/clock.glsl', CLOCK);
    write('shaders/rate.glsl', RATE);
    const out = await shaderproof('render', 'shaders/clock.glsl', '-o', 'clock.png', '--size', '4x4', '--date', '2030-06-01T00:30:00Z');
    expect(out.code, out.stderr).toBe(0);
    expect(out.stdout).toContain('iDate 2030-06-01T00:30:00.000Z');
    expect([...readPng(path.join(folder, 'clock.png')).data.subarray(0, 3)]).toEqual([0, byte(0.5), 0]);
    const recorded = await shaderproof('record', 'shaders/rate.glsl', '-o', 'rate.zip', '--size', '4x4', '--frames', '3', '--fps', '24');
    expect(recorded.code, recorded.stderr).toBe(0);
    const files = unzipSync(fs.readFileSync(path.join(folder, 'rate.zip')));
    const pixels = Object.keys(files)
      .sort()
      .map((name) => [...PNG.sync.read(Buffer.from(files[name])).data.subarray(0, 3)]);
    expect(pixels).toEqual([0, 1, 2].map((i) => [byte(24 / 255), byte(3 / 24), byte(((i / 24) * 10) / 255)]));
  });
});

test("--frame N past the recorder's cap is frame N (issue 36, item 3)", async () => {
  write('framed.glsl', 'void mainImage(out vec4 c, in vec2 f) { c = vec4(float(iFrame % 256) / 255.0, fract(iTime), 0.0, 1.0); }\n');
  const out = await shaderproof('render', 'framed.glsl', '-o', 'framed.png', '--size', '4x4', '--frame', '99999');
  expect(out.code, out.stderr).toBe(0);
  expect([...readPng(path.join(folder, 'framed.png')).data.subarray(0, 2)]).toEqual([99999 % 256, byte(fract(99999 / 60))]);
});

describe('no bad input touches an output file already there (issue 36, item 4)', () => {
  const ENDLESS =
    'void mainImage(out vec4 c, in vec2 f) { float s = 0.0; for (int i = 0; ; i++) { s += abs(sin(float(i) + f.x)); if (s < -1.0) break; } c = vec4(s); }\n';
  /** @type {Array<[string, string, string, string[], RegExp]>} */
  const CASES = [
    [
      'a JSON that is not a Shadertoy export',
      'notshader.json',
      '{"not": "a shader"}',
      [],
      /notshader\.json: not a Shadertoy shader: no "renderpass" list/,
    ],
    ['a compile error', 'broken.glsl', 'void mainImage(out vec4 c, in vec2 f) { c = nope; }\n', [], /broken\.glsl:1: error: 'nope'/],
    [
      'a shader that never finishes',
      'endless.glsl',
      ENDLESS,
      ['--watchdog', '2'],
      /endless\.glsl: did not finish drawing a frame: one band of it used more than the watchdog's 2 s of the GPU process's CPU time; .*--watchdog S/,
    ],
    ['a float still of the same', 'endless.glsl', ENDLESS, ['--watchdog', '2', '-o', 'keep.pfm'], /did not finish drawing a frame/],
  ];
  test.each(CASES)('%s', async (_, name, text, flags, said) => {
    write(name, text);
    const output = flags.includes('-o') ? flags[flags.indexOf('-o') + 1] : 'keep.png';
    const before = Buffer.from(`the picture someone kept: ${name}`);
    fs.writeFileSync(path.join(folder, output), before);
    const out = await shaderproof('render', name, '-o', 'keep.png', '--size', '8x8', ...flags);
    expect(out.code, `stdout: ${out.stdout}\nstderr: ${out.stderr}`).toBe(1);
    // one line, or a compiler's report: a line per error at the file's own line, its source under it
    const lines = out.stderr.split('\n').filter(Boolean);
    expect(
      lines.slice(1).every((line) => line.startsWith(`${name}:`) || line.startsWith('    ')),
      out.stderr,
    ).toBe(true);
    expect(lines[0] ?? '', `stdout: ${out.stdout}\nstderr: ${out.stderr}`).toMatch(said);
    expect(fs.readFileSync(path.join(folder, output)).equals(before), `${output} is as it was`).toBe(true);
    expect(
      fs.readdirSync(folder).filter((f) => f.includes('partial')),
      'no temporary file left',
    ).toEqual([]);
  });
});

test('a control out of range is said as the page says it, and drawn clamped (issue 36, item 6)', async () => {
  write(
    'sized.glsl',
    '#ifndef HOST_CONTROLS\nconst float SIZE = 1.0; // ui: Size | 0.1 .. 2\n#endif\nvoid mainImage(out vec4 c, in vec2 f) { c = vec4(SIZE / 2.0, 0.0, 0.0, 1.0); }\n',
  );
  const out = await shaderproof('render', 'sized.glsl', '-o', 'sized.png', '--size', '4x4', '--set', 'SIZE=-5');
  expect(out.code, out.stderr).toBe(0);
  expect(out.stderr.trim()).toBe('warning: sized.glsl: Some values were not used as given: SIZE=-5 is out of range (0.1 .. 2): using 0.1.');
  expect(readPng(path.join(folder, 'sized.png')).data[0]).toBe(byte(0.1 / 2));
});

describe('never a silent half-render (issue 37, item 4; its words: issue 45, item 6)', () => {
  /** An Image pass that reads a video it cannot have here and the texture its Sound tab reads. */
  const HALF = JSON.stringify({
    Shader: {
      info: { name: 'half' },
      renderpass: [
        {
          type: 'image',
          name: 'Image',
          code: 'void mainImage(out vec4 c, in vec2 f) { c = vec4(texture(iChannel1, f / iResolution.xy).rgb + 0.25, 1.0); }',
          inputs: [
            {
              id: 'XsfGRr',
              filepath: '/media/a/video.webm',
              type: 'video',
              channel: 1,
              sampler: { filter: 'linear', wrap: 'clamp', vflip: 'true', srgb: 'false', internal: 'byte' },
            },
            { id: 'XdX3Rn', filepath: '/media/a/noise.png', type: 'texture', channel: 0, sampler: {} },
          ],
          outputs: [{ id: '4dfGRr', channel: 0 }],
        },
        {
          type: 'sound',
          name: 'Sound',
          code: 'vec2 mainSound(int s, float t) { return vec2(sin(6.2831 * 440.0 * t)); }',
          inputs: [{ id: 'XdX3Rn', filepath: '/media/a/noise.png', type: 'texture', channel: 0, sampler: {} }],
          outputs: [],
        },
      ],
    },
  });
  const MEDIA = "needs the site's media: give --media DIR \\(a folder laid out as the site's paths\\) or --fetch-media";
  const VIDEO_LINE = new RegExp(
    `^warning: half\\.json: Image, iChannel1: the site's video /media/a/video\\.webm ${MEDIA}; the channel is black$`,
    'm',
  );
  // one texture, two passes: one line naming both
  const NOISE_LINE = new RegExp(
    `^warning: half\\.json: Image and Sound, iChannel0: the site's texture /media/a/noise\\.png ${MEDIA}; both channels are black$`,
    'm',
  );

  test('render and record say each missing input and pass as a warning; --strict fails and writes nothing', async () => {
    write('half.json', HALF);
    const out = await shaderproof('render', 'half.json', '-o', 'half.png', '--size', '8x8');
    expect(out.code, out.stderr).toBe(0);
    const warnings = out.stderr.split('\n').filter(Boolean);
    expect(warnings.length, out.stderr).toBe(2);
    expect(out.stderr).toMatch(VIDEO_LINE);
    expect(out.stderr).toMatch(NOISE_LINE);
    expect(out.stderr).not.toMatch(/half\.json: half\.json|\?media=|the page's/);

    fs.rmSync(path.join(folder, 'strict.png'), { force: true });
    const strict = await shaderproof('render', 'half.json', '-o', 'strict.png', '--size', '8x8', '--strict');
    expect(strict.code).toBe(1);
    expect(strict.stderr.trim()).toMatch(
      /^shaderproof render: half\.json: --strict: nothing written, as it goes without 2 of what it asks for, the first: /,
    );
    expect(strict.stderr).not.toMatch(/black/);
    expect(fs.existsSync(path.join(folder, 'strict.png'))).toBe(false);

    const recorded = await shaderproof('record', 'half.json', '-o', 'half.zip', '--size', '8x8', '--frames', '2');
    expect(recorded.code, recorded.stderr).toBe(0);
    expect(recorded.stderr).toMatch(VIDEO_LINE);
    // the zip has no place for the Sound tab: said, with the command that writes it
    expect(recorded.stderr).toMatch(
      /^warning: half\.zip: half\.json has a Sound tab, and a zip of PNGs holds no sound; shaderproof render half\.json -o half\.wav --duration 0\.066667 writes it/m,
    );
  });

  test('a --channelN file the browser cannot decode is said, and --strict refuses it', async () => {
    write('reader.glsl', 'void mainImage(out vec4 c, in vec2 f) { c = texture(iChannel0, f / iResolution.xy); }\n');
    write('garbage.png', 'not an image at all');
    const out = await shaderproof('render', 'reader.glsl', '--channel0', 'garbage.png', '-o', 'garbage-out.png', '--size', '4x4');
    expect(out.code, out.stderr).toBe(0);
    expect(out.stderr.trim()).toBe('warning: reader.glsl: iChannel0: cannot load garbage.png as an image; the channel is black');
    const strict = await shaderproof(
      'render',
      'reader.glsl',
      '--channel0',
      'garbage.png',
      '-o',
      'garbage-strict.png',
      '--size',
      '4x4',
      '--strict',
    );
    expect(strict.code).toBe(1);
    expect(fs.existsSync(path.join(folder, 'garbage-strict.png'))).toBe(false);
  });

  test('test fails a case that went without an input and writes no reference from it, unless its manifest allows it', async () => {
    write('half/half.json', HALF);
    const refused = await shaderproof('test', 'half', '--update', '--out', 'half-report');
    expect(refused.code).toBe(1);
    expect(refused.stdout).toMatch(/^FAIL {2}half\.json .*went without: Image, iChannel1: the site's video/m);
    expect(refused.stdout).toMatch(/no reference written from a render that went without/);
    expect(fs.existsSync(path.join(folder, 'half/__references__/half.json.png'))).toBe(false);

    write(
      'half/shaderproof.json',
      JSON.stringify({ cases: { 'half.json': { size: '8x8', allowMissing: ['iChannel1', 'Sound', 'Image/iChannel0'] } } }),
    );
    const allowed = await shaderproof('test', 'half', '--update', '--out', 'half-report');
    expect(allowed.code, allowed.stdout).toBe(0);
    expect(allowed.stdout).toMatch(/^pass {2}half\.json .*went without \(allowed\): Image, iChannel1/m);
    expect(fs.existsSync(path.join(folder, 'half/__references__/half.json.png'))).toBe(true);
  });
});
