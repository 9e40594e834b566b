// The Node API in a browser (docs/api.md): openSession draws two shaders, given as text and as a
// file, with the one Chromium it launched; compare() and the runner (test()) agree on pass and
// fail for a reference one pixel off, at no tolerance and at one pixel allowed.

import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import { compare, openSession, test as testFolder } from '../../src/api/index.js';
import { builtPage } from '../../src/headless/page-server.js';
import { decodePng, pngBytes } from '../../src/headless/png.js';

const GRADIENT = `void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(fragCoord.x / iResolution.x, fragCoord.y / iResolution.y, 0.25, 1.0);
}
`;
const FLAT = `void mainImage(out vec4 fragColor, in vec2 fragCoord) { fragColor = vec4(0.0, 0.5, 1.0, 1.0); }
`;

let folder = '';
beforeAll(async () => {
  folder = fs.mkdtempSync(path.join(os.tmpdir(), 'shaderproof-api-'));
  await builtPage(); // the harness built dist/ for this run
});
afterAll(() => fs.rmSync(folder, { recursive: true, force: true }));

describe('openSession', () => {
  test('draws two shaders with one browser: one given as text, one as a file', async () => {
    fs.writeFileSync(path.join(folder, 'flat.glsl'), FLAT);
    const session = await openSession({ renderer: 'swiftshader' });
    try {
      const gradient = await session.render({ source: GRADIENT }, { size: '16x8' });
      const flat = await session.render(path.join(folder, 'flat.glsl'), { size: { width: 4, height: 2 } });
      expect(session.launches()).toBe(1);
      expect([gradient.width, gradient.height, flat.width, flat.height]).toEqual([16, 8, 4, 2]);
      expect([...flat.data.subarray(0, 4)]).toEqual([0, 128, 255, 255]);
      // the top-left pixel: x near 0, y 7.5 / 8 (rows top to bottom), blue a quarter
      const [r, g, b] = gradient.data.subarray(0, 3);
      expect([r < 16, Math.abs(g - 239) <= 1, Math.abs(b - 64) <= 1]).toEqual([true, true, true]);
      expect(decodePng(gradient.png())).toMatchObject({ width: 16, height: 8 });
      expect(gradient.renderer).toMatch(/SwiftShader/);
    } finally {
      await session.close();
    }
  });
});

describe('compare agrees with the runner on a reference one pixel off', () => {
  test.each([
    ['at no tolerance, both fail', 0, false],
    ['with one pixel allowed, both pass', 1, true],
  ])('%s', async (_, maxDiffPixels, ok) => {
    const dir = fs.mkdtempSync(path.join(folder, 'case-'));
    fs.writeFileSync(path.join(dir, 'gradient.glsl'), GRADIENT);
    fs.writeFileSync(
      path.join(dir, 'shaderproof.json'),
      JSON.stringify({ defaults: { size: '16x8' }, cases: { 'gradient.glsl': { tolerance: { maxDiffPixels } } } }),
    );
    const updated = await testFolder(dir, { update: true, renderer: 'swiftshader', jobs: 1, out: path.join(dir, 'out'), reporters: [] });
    expect(updated).toMatchObject({ ok: true, passed: 1 });
    const referenceFile = path.join(dir, '__references__', 'gradient.glsl.png');
    const reference = decodePng(fs.readFileSync(referenceFile));
    const rendered = { ...reference, data: Uint8Array.from(reference.data) };
    reference.data[0] ^= 0xff; // one pixel's red inverted
    fs.writeFileSync(referenceFile, pngBytes(reference));

    const compared = compare(rendered, referenceFile, { threshold: 0, maxDiffPixels });
    const run = await testFolder(dir, { renderer: 'swiftshader', jobs: 1, out: path.join(dir, 'out'), reporters: ['junit'] });
    expect(compared).toMatchObject({ ok, diffPixels: 1 });
    expect(run).toMatchObject({ ok, passed: ok ? 1 : 0, failed: ok ? 0 : 1, reports: [path.join(dir, 'out', 'junit.xml')] });
    expect(run.cases[0].diffPixels).toBe(1);
    expect(run.cases[0].failures).toEqual(ok ? [] : [compared.failure]);
  });
});
