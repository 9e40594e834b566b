// The Node API's shape (docs/api.md), without a browser: what the package's entry exports, where
// package.json points (its exports and types, as tsconfig.types.json writes them), the one error
// class, compare() on pixels, option errors said in the API's words before any browser starts,
// and docs/api.md's first example being docs/examples/api-first.mjs word for word.

import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { describe, expect, test } from 'vitest';
import { REPO_ROOT } from '../support/config.js';
import * as api from '../../src/api/index.js';

const read = (file) => fs.readFileSync(path.join(REPO_ROOT, file), 'utf8');
const pkg = JSON.parse(read('package.json'));
/** tsconfig.types.json, its comments taken out. */
const typesConfig = JSON.parse(read('tsconfig.types.json').replace(/^\s*\/\/.*$/gm, ''));

describe('the package', () => {
  test('is shaderproof, public, its entry the API and its types where tsc writes them', () => {
    expect(pkg).toMatchObject({ name: 'shaderproof', license: 'MIT', bin: { shaderproof: 'bin/shaderproof.js' } });
    expect(pkg.private).toBeUndefined();
    expect(pkg.version).toMatch(/^\d+\.\d+\.\d+$/);
    expect(pkg.exports['.'].default).toBe('./src/api/index.js');
    expect(pkg.exports['./package.json']).toBe('./package.json');
    const { outDir, rootDir } = typesConfig.compilerOptions;
    const written = `./${path.posix.join(outDir, path.posix.relative(rootDir, typesConfig.files[0])).replace(/\.js$/, '.d.ts')}`;
    expect([pkg.types, pkg.exports['.'].types]).toEqual([written, written]);
    expect(pkg.files).toContain(`${outDir}/`);
    expect(read('.gitignore').split('\n')).toContain(outDir);
    expect(pkg.scripts.prepack).toContain('build:types');
    expect(read('LICENSE')).toMatch(/^MIT License/);
  });

  test('the entry exports the five functions and the one error class, and nothing else', () => {
    expect(Object.keys(api).sort()).toEqual(['ShaderproofError', 'compare', 'openSession', 'record', 'render', 'test']);
    const error = new api.ShaderproofError('what to do', 2);
    expect(error).toBeInstanceOf(Error);
    expect(error).toMatchObject({ message: 'what to do', exitCode: 2, hung: false, compile: false });
  });

  test("docs/api.md's first example is docs/examples/api-first.mjs, word for word", () => {
    const block = /```js\n([\s\S]*?)```/.exec(read('docs/api.md'))?.[1];
    expect(block).toBe(read('docs/examples/api-first.mjs'));
  });
});

/** An image of `width`x1 grey pixels, `changed` of them white. */
const grey = (width, changed = 0) => {
  const data = new Uint8Array(width * 4).fill(128);
  data.fill(255, 0, changed * 4);
  return { width, height: 1, data };
};

describe('compare', () => {
  test.each([
    ['the same pixels', grey(4), grey(4), {}, { ok: true, diffPixels: 0, failure: null }],
    [
      'one pixel off, none allowed',
      grey(4, 1),
      grey(4),
      {},
      {
        ok: false,
        diffPixels: 1,
        failure: '1 pixel differs from the reference (at most 0 may) at (0, 0): reference 128,128,128,128, actual 255,255,255,255',
      },
    ],
    ['one pixel off, one allowed', grey(4, 1), grey(4), { maxDiffPixels: 1 }, { ok: true, diffPixels: 1, failure: null }],
    ['one pixel off, within the threshold', grey(4, 1), grey(4), { threshold: 1 }, { ok: true, diffPixels: 0, failure: null }],
    ['two sizes', grey(4), grey(3), {}, { ok: false, diffPixels: null, failure: 'the render is 4x1, the reference 3x1' }],
  ])('%s', (_, actual, reference, tolerance, expected) => {
    expect(api.compare(actual, reference, tolerance)).toMatchObject(expected);
  });

  test("reads PNG bytes as pixels, and gives the diff's PNG", () => {
    const off = api.compare(grey(4, 1), grey(4));
    const diff = /** @type {NonNullable<typeof off.diff>} */ (off.diff);
    expect(api.compare(diff.png(), diff)).toMatchObject({ ok: true, diffPixels: 0 });
  });

  test.each([
    ['not a PNG file', Buffer.from('not a png'), /^actual: the bytes is no PNG file/],
    ['no such file', '/nonexistent/a.png', /^actual: \/nonexistent\/a\.png is no PNG file/],
    ['pixels of the wrong length', { width: 2, height: 2, data: new Uint8Array(3) }, /^actual: give a PNG file's path or bytes/],
  ])('%s is a ShaderproofError', (_, actual, message) => {
    expect(() => api.compare(/** @type {any} */ (actual), grey(4))).toThrow(api.ShaderproofError);
    expect(() => api.compare(/** @type {any} */ (actual), grey(4))).toThrow(message);
  });
});

describe('an option that cannot be used fails before any browser starts, in the API’s words', () => {
  test.each([
    [{ size: '64by36' }, 'size 64by36: expected WIDTHxHEIGHT in pixels, such as 640x360'],
    [{ renderer: /** @type {any} */ ('vulkan') }, /^renderer vulkan: not a renderer; one of /],
    [{ tile: 3 }, /^tile 3: the tile size must be even/],
  ])('%o', async (options, message) => {
    const session = await api.openSession({ renderer: /** @type {any} */ (options).renderer }).catch((error) => error);
    const error =
      session instanceof Error
        ? session
        : await session
            .render('x.glsl', options)
            .catch((e) => e)
            .finally(() => session.close());
    expect(error).toBeInstanceOf(api.ShaderproofError);
    expect(error.exitCode).toBe(2);
    expect(error.message).toMatch(message);
  });

  test("test()'s grep that keeps no case", async () => {
    const folder = fs.mkdtempSync(path.join(os.tmpdir(), 'shaderproof-api-grep-'));
    try {
      fs.writeFileSync(path.join(folder, 'waves.glsl'), 'void mainImage(out vec4 c, in vec2 p) { c = vec4(1.0); }\n');
      const error = await api.test(folder, { grep: 'clouds', out: path.join(folder, 'out') }).catch((e) => e);
      expect(error).toBeInstanceOf(api.ShaderproofError);
      expect(error.message).toMatch(/no case of the 1 chosen in .* matches grep\/grepInvert \(/);
    } finally {
      fs.rmSync(folder, { recursive: true, force: true });
    }
  });

  test('a shader that is neither a path nor { source }', async () => {
    await expect(api.render(/** @type {any} */ ({ text: 'x' }))).rejects.toThrow(
      'shader: give the path of a .glsl or .json file, or { source: "…its text…" }',
    );
  });
});
