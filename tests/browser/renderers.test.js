// What draws (src/headless/renderers.js, browser.js): which renderer a verb gets, how Mesa is
// found, and that each renderer asked for is the one that draws, never another in its place.
import fs from 'node:fs';
import path from 'node:path';
import { describe, expect, test } from 'vitest';
import { startBrowser } from '../../src/headless/browser.js';
import { killBrowser } from '../../src/headless/watch.js';
import { MESA_PACKAGES, chooseRenderer, drawnBy, findMesa, mesaMissingLine, suiteRenderer } from '../../src/headless/renderers.js';

/** A machine's file system for findMesa: the files it has, and its folders' listings. */
function machine(files) {
  const set = new Set(files);
  return [(file) => set.has(file), (dir) => files.filter((f) => f.startsWith(`${dir}/`)).map((f) => f.slice(dir.length + 1))];
}
const DEBIAN_12 = [
  '/usr/share/glvnd/egl_vendor.d/50_mesa.json',
  '/usr/lib/x86_64-linux-gnu/libEGL_mesa.so.0',
  '/usr/lib/x86_64-linux-gnu/dri/swrast_dri.so',
];
const MESA_24 = [
  '/usr/share/glvnd/egl_vendor.d/50_mesa.json',
  '/usr/lib/aarch64-linux-gnu/libEGL_mesa.so.0',
  '/usr/lib/aarch64-linux-gnu/libgallium-24.2.8-1.so',
];

describe('findMesa', () => {
  /** @type {Array<[string, string[], string[]]>} [machine, its files, what is missing] */
  const CASES = [
    ['Debian 12 (Mesa 22: dri/swrast_dri.so)', DEBIAN_12, []],
    ['Mesa 24 on arm64 (libgallium)', MESA_24, []],
    ['no Mesa at all', [], ["Mesa's EGL", "Mesa's llvmpipe driver"]],
    ['EGL without its driver', DEBIAN_12.slice(0, 2), ["Mesa's llvmpipe driver"]],
    ['a driver without EGL', DEBIAN_12.slice(2), ["Mesa's EGL"]],
  ];
  test.each(CASES)('%s', (_, files, missing) => {
    const found = findMesa(...machine(files));
    expect(found.missing.map((line) => line.replace(/ \(.*/, ''))).toEqual(missing);
  });

  test('a missing Mesa is one line that names the Debian packages and the other renderer', () => {
    const line = mesaMissingLine(findMesa(...machine([])).missing);
    expect(line).not.toContain('\n');
    expect(line).toContain(`apt-get install -y ${MESA_PACKAGES.join(' ')}`);
    expect(line).toContain('--renderer swiftshader');
  });
});

describe('chooseRenderer: the flag, else the verb\'s default; "auto" is llvmpipe where Mesa is', () => {
  const withMesa = () => ({ missing: [] });
  const withoutMesa = () => ({ missing: ["Mesa's EGL"] });
  /** @type {Array<[string, {renderer?: string, gpu?: boolean}, any, any, string]>} */
  const CASES = [
    ['no flag, auto, Mesa here', {}, 'auto', withMesa, 'llvmpipe'],
    ['no flag, auto, no Mesa', {}, 'auto', withoutMesa, 'swiftshader'],
    ["no flag, the references' renderer", {}, 'swiftshader', withMesa, 'swiftshader'],
    ['--renderer swiftshader', { renderer: 'swiftshader' }, 'auto', withMesa, 'swiftshader'],
    ['--renderer llvmpipe without Mesa (said by the launch)', { renderer: 'llvmpipe' }, 'auto', withoutMesa, 'llvmpipe'],
    ['--gpu', { gpu: true }, 'auto', withMesa, 'gpu'],
    ['--gpu --renderer gpu', { gpu: true, renderer: 'gpu' }, 'swiftshader', withMesa, 'gpu'],
  ];
  test.each(CASES)('%s', (_, asked, fallback, mesa, expected) => {
    expect(chooseRenderer(asked, fallback, /** @type {any} */ (mesa))).toBe(expected);
  });
  test.each([
    [{ renderer: 'vulkan' }, /--renderer vulkan: not a renderer/],
    [{ renderer: 'llvmpipe', gpu: true }, /--gpu and --renderer llvmpipe disagree/],
  ])('%j is refused', (asked, said) => {
    expect(() => chooseRenderer(asked, 'auto')).toThrow(said);
  });
  test('the suite: SwiftShader unless SHADERPROOF_RENDERER names another; a typo is refused', () => {
    expect(suiteRenderer({})).toBe('swiftshader');
    expect(suiteRenderer({ SHADERPROOF_RENDERER: 'llvmpipe' })).toBe('llvmpipe');
    expect(() => suiteRenderer({ SHADERPROOF_RENDERER: 'llvmpie' })).toThrow(/SHADERPROOF_RENDERER=llvmpie: not a renderer/);
  });
});

describe('the renderer asked for is the one that draws', () => {
  test.each([
    ['swiftshader', /SwiftShader/],
    ['llvmpipe', /llvmpipe/],
  ])('%s', async (renderer, name) => {
    const started = await startBrowser({ renderer: /** @type {any} */ (renderer) });
    try {
      expect(started.environment.renderer).toMatch(name);
      expect(started.environment.rendererName).toBe(renderer);
      expect(drawnBy(/** @type {any} */ (renderer), started.environment.renderer)).toBe(true);
    } finally {
      await started.close();
    }
  });

  test('llvmpipe on a machine without Mesa: one line with the packages, before any browser starts', async () => {
    const noMesa = () => findMesa(...machine([]));
    await expect(startBrowser({ renderer: 'llvmpipe', mesa: noMesa })).rejects.toThrow(/^llvmpipe needs Mesa.*apt-get install -y libegl1/);
  });

  test('llvmpipe whose EGL does not start: said, never SwiftShader in its place', async () => {
    const broken = () => ({ vendorFile: '/nonexistent/50_mesa.json', egl: 'x', driver: 'y', missing: [] });
    await expect(startBrowser({ renderer: 'llvmpipe', mesa: broken })).rejects.toThrow(
      /llvmpipe was asked for, but (there is no WebGL2|WebGL2 is ".*").*libegl-mesa0.*--renderer swiftshader/,
    );
  });
});

describe('a browser leaves nothing in the temporary folder', () => {
  test('killed (as the watchdog kills a hung one), its profile and its singleton-socket folder go with close()', async () => {
    const started = await startBrowser({ renderer: 'swiftshader', probe: false });
    const flag = started.browser.process()?.spawnargs.find((arg) => arg.startsWith('--user-data-dir=')) ?? '';
    const profile = flag.slice('--user-data-dir='.length);
    const owner = path.dirname(fs.readlinkSync(path.join(profile, 'SingletonSocket')));
    expect(owner).toMatch(/org\.chromium\./);
    killBrowser(started.browser); // Chromium gets no chance to remove its own folder
    await started.close();
    expect([fs.existsSync(profile), fs.existsSync(owner)]).toEqual([false, false]);
  });
});
