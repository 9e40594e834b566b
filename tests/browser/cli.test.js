// The command line as a person gets it: `npm pack`, the tarball installed in an empty folder
// outside the repository, and `npx shaderproof …` there on shaders the tests write there. Each
// verb is checked against what it must equal: a render against Shadertoy's header drawn in plain
// WebGL2 and against the page's golden of the same view, a recording against its frames, a test
// run against a changed shader and one that never finishes, `open` against a saved file.

import { execFile, spawn } from 'node:child_process';
import fs from 'node:fs';
import http from 'node:http';
import os from 'node:os';
import path from 'node:path';
import { promisify } from 'node:util';
import { unzipSync } from 'fflate';
import { PNG } from 'pngjs';
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import { formatImageError, imageError } from '../../src/reference/error.js';
import { renderReference } from '../../src/reference/render.js';
import { composeImageShader } from '../../src/shadertoy/header.js';
import { builtPage } from '../../src/headless/page-server.js';
import { GOLDEN_DIR, REPO_ROOT, SHADER_FILE } from '../support/config.js';
import { runShaderproof } from '../support/shaderproof-child.js';
import { readPng, sameImage } from '../support/images.js';
import { disconnect, openPage } from '../support/page.js';
import { renderRawShader } from '../support/raw-webgl/raw-webgl.js';
import { hook } from '../support/hook.js';

const run = promisify(execFile);

let packed = '';
afterAll(async () => {
  await disconnect();
  for (const dir of [folder, packed]) if (dir) fs.rmSync(dir, { recursive: true, force: true });
});

/** A shader of the inputs a still can fix: iResolution, iTime, iMouse. */
const WAVES = `void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    float ring = length(fragCoord - iMouse.xy) / iResolution.y;
    fragColor = vec4(uv, 0.5 + 0.5 * sin(12.0 * ring - 3.0 * iTime), 1.0);
}
`;
/** Screen-space derivatives of a pattern that changes from pixel to pixel. */
const DERIVATIVES = `void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float v = sin(fragCoord.x * fragCoord.y * 0.013 + iTime);
    fragColor = vec4(abs(dFdx(v)) * 4.0, abs(dFdy(v)) * 4.0, fwidth(v), 1.0);
}
`;
/** iFrame, iTime x 60 and iChannel0's blue, for --frame and --channel0. */
const FRAMED = `void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(float(iFrame) / 255.0, iTime * 60.0 / 255.0, texture(iChannel0, vec2(0.5)).b, 1.0);
}
`;
/** iFrame and iTime in colour, for the recordings. */
const CLOCK = `void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(float(iFrame) / 255.0, fract(iTime), fragCoord.x / iResolution.x, 1.0);
}
`;
/** The loop's exit depends on a sum that never gets there (tests/browser/page-heavy.test.js). */
const ENDLESS = `void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float sum = 0.0;
    for (int i = 0; ; i++) {
        sum += abs(sin(float(i) + fragCoord.x));
        if (sum < -1.0) break;
    }
    fragColor = vec4(sum, 0.0, 0.0, 1.0);
}
`;

let folder = '';
let bin = '';

/** Runs the installed command in the folder: { code, stdout, stderr }. */
const shaderproof = (args, { env = {} } = {}) => runShaderproof(args, { cwd: folder, bin, env, timeout: 90_000 });

const write = (name, text) => {
  fs.mkdirSync(path.dirname(path.join(folder, name)), { recursive: true });
  fs.writeFileSync(path.join(folder, name), text);
};

beforeAll(async () => {
  packed = fs.mkdtempSync(path.join(os.tmpdir(), 'shaderproof-pack-'));
  folder = fs.mkdtempSync(path.join(os.tmpdir(), 'shaderproof-user-'));
  // the harness built dist/ for this run (page-server.js): packed as it is, not built again
  await builtPage();
  const { stdout } = await run('npm', ['pack', '--silent', '--ignore-scripts', '--pack-destination', packed], { cwd: REPO_ROOT });
  const tarball = path.join(packed, stdout.trim().split('\n').at(-1) ?? '');
  fs.writeFileSync(path.join(folder, 'package.json'), JSON.stringify({ name: 'my-shaders', private: true }));
  // from npm's cache where it has the packages (npm ci filled it), else the registry
  await run('npm', ['install', '--prefer-offline', '--no-audit', '--no-fund', tarball], { cwd: folder });
  bin = path.join(folder, 'node_modules', 'shaderproof', 'bin', 'shaderproof.js');
  expect(fs.existsSync(bin), 'the tarball installs bin/shaderproof.js').toBe(true);
}, 180_000);

describe('shaderproof, installed from its tarball', () => {
  test('npx finds it, and each verb has a --help; a bad flag is one line that points to it, exit 2', async () => {
    const { stdout } = await run('npx', ['--no-install', 'shaderproof', '--help'], { cwd: folder });
    for (const verb of ['open', 'render', 'record', 'test']) expect(stdout).toContain(verb);
    for (const verb of ['open', 'render', 'record', 'test']) {
      const help = await shaderproof([verb, '--help']);
      expect(help.code).toBe(0);
      expect(help.stdout).toMatch(new RegExp(`^shaderproof ${verb} `));
    }
    const bad = await shaderproof(['render', 'x.glsl', '--sise', '64x36']);
    expect(bad.code).toBe(2);
    expect(bad.stderr.trim()).toBe('shaderproof render: no flag --sise (shaderproof render --help lists the flags)');
    const value = await shaderproof(['render', 'x.glsl', '-o', 'x.png', '--size', '64by36']);
    expect(value.code).toBe(2);
    expect(value.stderr.trim()).toBe(
      'shaderproof render: --size 64by36: expected WIDTHxHEIGHT in pixels, such as 640x360 (shaderproof render --help lists the flags)',
    );
  });

  test("render draws what Shadertoy's header draws, pixel for pixel, and says which renderer drew it", async () => {
    write('waves.glsl', WAVES);
    const mouse = [40, 20, 40, -20];
    const out = await shaderproof([
      'render',
      'waves.glsl',
      '-o',
      'out/waves.png',
      '--size',
      '96x54',
      '--time',
      '1.5',
      '--mouse',
      mouse.join(','),
    ]);
    expect(out.code, out.stderr).toBe(0);
    expect(out.stdout).toMatch(/^out\/waves\.png: 96x54, .*SwiftShader/);
    const image = readPng(path.join(folder, 'out/waves.png'));
    const raw = await renderRawShader(composeImageShader(WAVES).code, { width: 96, height: 54, uniforms: { iTime: 1.5, iMouse: mouse } });
    expect(raw.stage, raw.log).toBeUndefined();
    expect(sameImage(image, /** @type {any} */ (raw)), 'the render equals the Shadertoy-header render').toBe(true);
  });

  test('render --frame N draws frames 0..N (iFrame N, iTime N/60) with --channel0 an image file', async () => {
    const solid = new PNG({ width: 4, height: 4 });
    for (let i = 0; i < 16; i++) solid.data.set([40, 120, 200, 255], i * 4);
    fs.writeFileSync(path.join(folder, 'solid.png'), PNG.sync.write(solid));
    write('framed.glsl', FRAMED);
    const out = await shaderproof([
      'render',
      'framed.glsl',
      '--frame',
      '3',
      '--channel0',
      'solid.png',
      '--size',
      '8x8',
      '-o',
      'framed.png',
    ]);
    expect(out.code, out.stderr).toBe(0);
    const image = readPng(path.join(folder, 'framed.png'));
    // red: iFrame; green: iTime x 60; blue: the channel's own blue
    expect([...image.data.subarray(0, 4)]).toEqual([3, 3, 200, 255]);
  });

  test("render of the raytracer is the page's golden of the same view", async () => {
    const out = await shaderproof(['render', SHADER_FILE, '-o', 'default.png', '--size', '320x180', '--time', '0']);
    expect(out.code, out.stderr).toBe(0);
    expect(sameImage(readPng(path.join(folder, 'default.png')), readPng(path.join(GOLDEN_DIR, '__references__', 'default.png')))).toBe(
      true,
    );
  });

  test('render --tile 256 is the untiled render, pixel for pixel, derivatives included', async () => {
    // screen-space derivatives are taken across 2×2 quads: a tile that split one would show it
    write('derivatives.glsl', DERIVATIVES);
    const args = ['render', 'derivatives.glsl', '--size', '600x300', '--time', '1'];
    const whole = await shaderproof([...args, '-o', 'whole.png']);
    expect(whole.code, whole.stderr).toBe(0);
    const tiled = await shaderproof([...args, '--tile', '256', '-o', 'tiled.png']);
    expect(tiled.code, tiled.stderr).toBe(0);
    expect(sameImage(readPng(path.join(folder, 'tiled.png')), readPng(path.join(folder, 'whole.png')))).toBe(true);
    const odd = await shaderproof([...args, '--tile', '255', '-o', 'odd.png']);
    expect(odd.code).toBe(2);
    expect(odd.stderr).toMatch(/--tile 255: the tile size must be even/);
  });

  test('render --converge N is the raytracer converged over N samples, as the float64 reference with N samples', async () => {
    const samples = 8;
    const out = await shaderproof(['render', SHADER_FILE, '--converge', String(samples), '-o', 'converged.png', '--size', '64x36']);
    expect(out.code, out.stderr).toBe(0);
    const image = readPng(path.join(folder, 'converged.png'));
    const reference = renderReference(
      fs.readFileSync(SHADER_FILE, 'utf8'),
      { width: 64, height: 36, time: 0, mouse: [0, 0, 0, 0] },
      { mode: 'progressive', samples },
    );
    const error = imageError(image, reference);
    // tests/browser/page-converge.test.js's bounds, for its reason: the image is 8-bit
    expect(error.rmse, formatImageError(error)).toBeLessThan(2e-3);
    expect(error.maxAbs).toBeLessThanOrEqual(8 / 255);
  });

  test("errors: not a shader, a compile error at the file's own line, no Chromium", async () => {
    write('notes.glsl', 'just some notes\n');
    const notShader = await shaderproof(['render', 'notes.glsl', '-o', 'x.png']);
    expect(notShader.code).toBe(1);
    expect(notShader.stderr.trim()).toBe(
      'shaderproof render: notes.glsl: not a shader: no mainImage() in it (a Shadertoy Image tab defines one)',
    );
    write('sub/broken.glsl', 'void mainImage(out vec4 c, in vec2 f) {\n    c = vec4(nope, 1.0);\n}\n');
    const broken = await shaderproof(['render', 'sub/broken.glsl', '-o', 'x.png', '--size', '32x18']);
    expect(broken.code).toBe(1);
    expect(broken.stderr).toMatch(/^shaderproof render: sub\/broken\.glsl:2: error: 'nope' : undeclared identifier/);
    const noChrome = await shaderproof(['render', 'waves.glsl', '-o', 'x.png'], { env: { CHROME_PATH: '/nowhere/chromium' } });
    expect(noChrome.code).toBe(1);
    expect(noChrome.stderr).toMatch(/CHROME_PATH is \/nowhere\/chromium, which does not exist\. Install one with `apt-get/);
  });

  test('record writes a WebM of N frames and a zip of N PNGs, frame i at iFrame i', async () => {
    write('clock.glsl', CLOCK);
    const zip = await shaderproof(['record', 'clock.glsl', '-o', 'clock.zip', '--frames', '4', '--fps', '8', '--size', '32x18']);
    expect(zip.code, zip.stderr).toBe(0);
    expect(zip.stdout).toMatch(/^clock\.zip: 4 frames at 8 fps, 32x18, PNGs in a zip, .*SwiftShader/);
    const files = unzipSync(fs.readFileSync(path.join(folder, 'clock.zip')));
    const frames = Object.keys(files)
      .sort()
      .map((name) => PNG.sync.read(Buffer.from(files[name])));
    expect(frames.map((f) => [f.width, f.height, f.data[0], f.data[1]])).toEqual(
      [0, 1, 2, 3].map((i) => [32, 18, i, Math.round((i / 8) * 255)]),
    );
    const webm = await shaderproof(['record', 'clock.glsl', '-o', 'clock.webm', '--frames', '6', '--fps', '30', '--size', '64x36']);
    expect(webm.code, webm.stderr).toBe(0);
    expect(webm.stdout).toMatch(/^clock\.webm: 6 frames at 30 fps, 64x36, vp[89] video/);
    const { ALL_FORMATS, BufferSource, EncodedPacketSink, Input } = await import('mediabunny');
    const input = new Input({ source: new BufferSource(fs.readFileSync(path.join(folder, 'clock.webm'))), formats: ALL_FORMATS });
    const track = await input.getPrimaryVideoTrack();
    const times = [];
    for await (const packet of new EncodedPacketSink(/** @type {any} */ (track)).packets()) times.push(packet.timestamp);
    expect([track?.displayWidth, track?.displayHeight]).toEqual([64, 36]);
    expect(times.map((t) => Math.round(t * 30))).toEqual([0, 1, 2, 3, 4, 5]);
  });

  test('test: --update writes the references; a one-character change fails its case; an endless shader fails within the watchdog and the rest are reported', async () => {
    write('corpus/waves.glsl', WAVES);
    write('corpus/clock.glsl', CLOCK);
    write(
      'corpus/shaderproof.json',
      JSON.stringify({ defaults: { size: '48x27' }, cases: { 'waves.glsl': { time: 2, checks: { noNaN: true, deterministic: true } } } }),
    );
    const update = await shaderproof(['test', 'corpus', '--update', '--out', 'report']);
    expect(update.code, update.stderr).toBe(0);
    expect(fs.readdirSync(path.join(folder, 'corpus/__references__')).sort()).toEqual([
      'clock.glsl.png',
      'drawn-by.json',
      'waves.glsl.png',
    ]);
    // what drew them: the suite's SwiftShader (vitest.config.js)
    expect(JSON.parse(fs.readFileSync(path.join(folder, 'corpus/__references__/drawn-by.json'), 'utf8')).renderer).toBe('swiftshader');
    const reference = fs.readFileSync(path.join(folder, 'corpus/__references__/waves.glsl.png'));
    // one run for the two ways a case fails: a one-character change, and a shader that never
    // finishes (after which the rest still run, in a new browser)
    write('corpus/waves.glsl', WAVES.replace('12.0 * ring', '13.0 * ring'));
    write('corpus/endless.glsl', ENDLESS);
    const started = Date.now();
    const failed = await shaderproof(['test', 'corpus', '--out', 'report', '--watchdog', '2']);
    expect(failed.code).toBe(1);
    expect(failed.stdout).toMatch(/^FAIL {2}waves\.glsl .* pixels differ from the reference/m);
    expect(failed.stdout).toMatch(
      /^FAIL {2}endless\.glsl .*did not finish drawing a frame: one band of it used more than the watchdog's 2 s of the GPU process's CPU time/m,
    );
    expect(failed.stdout, 'the clock draws what it drew in another process').toMatch(/^pass {2}clock\.glsl/m);
    expect(failed.stdout).toMatch(/1 passed, 2 failed/);
    expect(Date.now() - started, 'the run took the watchdog, not a page timeout').toBeLessThan(30_000);
    expect(fs.existsSync(path.join(folder, 'report/waves.glsl-diff.png'))).toBe(true);
    const junit = fs.readFileSync(path.join(folder, 'report/junit.xml'), 'utf8');
    expect(junit).toMatch(/<testcase classname="shaderproof" name="waves\.glsl" [^>]*>\s*<failure message="[\d,]+ pixels differ/);
    expect(fs.readFileSync(path.join(folder, 'corpus/__references__/waves.glsl.png')).equals(reference), 'only --update writes').toBe(true);

    // the cases sorted (clock, endless, waves): shard 1 of 2 takes the first and the third
    const shard = await shaderproof(['test', 'corpus', '--out', 'report', '--shard', '1/2']);
    expect(shard.stdout.match(/^(pass|FAIL) {2}\S+/gm)).toEqual(['pass  clock.glsl', 'FAIL  waves.glsl']);
  });

  test('open serves the page on a file from anywhere on disk, and a save reloads it on the page', async () => {
    write('live.glsl', WAVES);
    const child = spawn(process.execPath, [bin, 'open', 'live.glsl'], { cwd: folder, stdio: ['ignore', 'pipe', 'pipe'] });
    try {
      const url = await new Promise((resolve, reject) => {
        child.stdout.on('data', (chunk) => resolve(String(chunk).trim()));
        child.on('exit', (code) => reject(new Error(`open exited with ${code}`)));
      });
      expect(url).toMatch(/^http:\/\/127\.0\.0\.1:\d+\/\?shader=\/__files\/\d+\/live\.glsl$/);
      // another host name (DNS rebinding) is refused: page-server-host.test.js has the cases
      const refused = await new Promise((resolve, reject) =>
        http
          .get(url, { headers: { host: `evil.example:${new URL(url).port}` } }, (res) => resolve(res.resume().statusCode))
          .on('error', reject),
      );
      expect(refused).toBe(403);
      const { page } = await openPage();
      try {
        await page.goto(`${url}&size=32x18&time=0`, { waitUntil: 'load' });
        await page.waitForFunction(() => window.shaderEngine);
        await hook(page).ready();
        const before = await hook(page)
          .info()
          .then((r) => r.compiled);
        expect(
          await hook(page)
            .info()
            .then((r) => r.fileName),
        ).toBe('live.glsl');
        write('live.glsl', WAVES.replace('vec4(uv,', 'vec4(1.0 - uv,'));
        await page.waitForFunction((n) => window.shaderEngine.info().compiled > n, { polling: 100, timeout: 20_000 }, before);
        expect(await hook(page).editorSource()).toContain('1.0 - uv');
      } finally {
        await page.close();
      }
    } finally {
      child.kill('SIGTERM');
    }
  });
});
