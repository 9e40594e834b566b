// `shaderproof test`'s manifest (src/runner/manifest.js), without a browser: what a case may
// say (a view of a shader elsewhere, a renderer's own tolerance, a comment), and the one line,
// exit 2, for each thing it cannot use, so that a typo never turns a check off in silence.

import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import { findCases, readManifest, toleranceFor } from '../../src/runner/manifest.js';

let folder = '';
const SHADER = 'void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n';

beforeAll(() => {
  folder = fs.mkdtempSync(path.join(os.tmpdir(), 'shaderproof-manifest-'));
  fs.mkdirSync(path.join(folder, 'dir'));
  fs.writeFileSync(path.join(folder, 'dir', 'a.glsl'), SHADER);
  fs.writeFileSync(path.join(folder, 'dir', 'notes.txt'), 'not a shader\n');
  fs.writeFileSync(path.join(folder, 'scene.glsl'), SHADER);
});
afterAll(() => fs.rmSync(folder, { recursive: true, force: true }));

/** The cases of `folder/dir` under `manifest`. */
function casesOf(manifest) {
  const dir = path.join(folder, 'dir');
  fs.writeFileSync(path.join(dir, 'shaderproof.json'), JSON.stringify(manifest));
  return findCases(dir, readManifest(dir));
}

describe('what a manifest says of its cases', () => {
  test('a view named by the manifest draws its "shader" (relative to DIR), sorted among the files, "defaults" saying it for all', () => {
    const cases = casesOf({
      defaults: { shader: '../scene.glsl', time: 1 },
      cases: { wide: { size: '64x32' }, 'close/up': { set: { ZOOM: 2 } }, 'a.glsl': { time: 2 } },
    });
    expect(cases.map((c) => [c.name, path.relative(folder, c.file), path.relative(folder, c.reference), c.kind])).toEqual([
      ['a.glsl', 'dir/a.glsl', 'dir/__references__/a.glsl.png', 'glsl'],
      ['close/up', 'scene.glsl', 'dir/__references__/close/up.png', 'glsl'],
      ['wide', 'scene.glsl', 'dir/__references__/wide.png', 'glsl'],
    ]);
    expect(cases.map((c) => [c.view.size, c.view.time, c.view.controls])).toEqual([
      [{ width: 320, height: 180 }, 2, []],
      [{ width: 320, height: 180 }, 1, [['ZOOM', '2']]],
      [{ width: 64, height: 32 }, 1, []],
    ]);
  });

  test("a renderer's own tolerance: the case's, with what it gives for that renderer (merged key by key over the defaults')", () => {
    const [a] = casesOf({
      defaults: { tolerance: { threshold: 0.05, maxDiffPixels: 57, llvmpipe: { threshold: 0.1 } } },
      cases: { 'a.glsl': { tolerance: { llvmpipe: { maxDiffPixels: 576 } }, '//': ['why: measured', 'on llvmpipe'] } },
    });
    expect(a.tolerance).toEqual({ threshold: 0.05, maxDiffPixels: 57 });
    expect(a.rendererTolerance).toEqual({ llvmpipe: { threshold: 0.1, maxDiffPixels: 576 } });
    expect(toleranceFor(a, 'llvmpipe')).toEqual({ threshold: 0.1, maxDiffPixels: 576 });
    expect(toleranceFor(a, 'swiftshader')).toEqual({ threshold: 0.05, maxDiffPixels: 57 });
    expect(toleranceFor(a, undefined)).toEqual({ threshold: 0.05, maxDiffPixels: 57 });
  });

  // [what, manifest, the line]
  /** @type {Array<[string, any, RegExp]>} */
  const REFUSED = [
    ['an unknown key at the top', { case: {} }, /shaderproof\.json: unknown key case \(expected "defaults" and "cases"\)$/],
    ['a comment that is not text', { '//': 3 }, /shaderproof\.json: "\/\/" is a comment: a string or a list of strings$/],
    [
      "a case's unknown key",
      { cases: { 'a.glsl': { tolerence: {} } } },
      /^shaderproof\.json: a\.glsl: unknown key tolerence \(a case may have /,
    ],
    ["a case's comment that is not text", { cases: { 'a.glsl': { '//': { a: 1 } } } }, /a\.glsl: "\/\/" is a comment/],
    ['a shader file that is not there', { cases: { 'b.glsl': {} } }, /^shaderproof\.json: no shader b\.glsl in /],
    [
      'a view with no shader',
      { cases: { wide: { size: '64x32' } } },
      /^shaderproof\.json: wide: no shader wide in DIR, and no "shader" to draw: a view names its shader, such as "shader": /,
    ],
    [
      'a view whose name is no file name',
      { cases: { 'two words': { shader: '../scene.glsl' } } },
      /^shaderproof\.json: two words: a case that is not a file under DIR is a view, and its name is its reference's file name/,
    ],
    [
      'a view of a file that is no shader',
      { cases: { v: { shader: 'notes.txt' } } },
      /v: "shader" is "notes\.txt", not a \.glsl or \.json file$/,
    ],
    [
      'a view of a shader that is not there',
      { cases: { v: { shader: '../gone.glsl' } } },
      /v: "shader" \.\.\/gone\.glsl: no such file \(a path relative to /,
    ],
    [
      'a shader file given a shader',
      { cases: { 'a.glsl': { shader: '../scene.glsl' } } },
      /^shaderproof\.json: a\.glsl: "shader" is for a view; a shader file under DIR draws itself$/,
    ],
    ['a tolerance that is not an object', { cases: { 'a.glsl': { tolerance: 5 } } }, /a\.glsl: "tolerance" is 5, not an object$/],
    ['defaults whose checks are not an object', { defaults: { checks: true } }, /defaults: "checks" is true, not an object$/],
    [
      'a tolerance not a number',
      { cases: { 'a.glsl': { tolerance: { threshold: 'x' } } } },
      /a\.glsl: tolerance threshold is "x", not a number >= 0$/,
    ],
    [
      'a tolerance of no renderer',
      { cases: { 'a.glsl': { tolerance: { llvmpipes: { maxDiffPixels: 3 } } } } },
      /a\.glsl: unknown tolerance llvmpipes \(expected threshold, maxDiffPixels, or a renderer's own: swiftshader, llvmpipe, gpu\)$/,
    ],
    [
      "a renderer's tolerance that is a number",
      { cases: { 'a.glsl': { tolerance: { llvmpipe: 3 } } } },
      /a\.glsl: tolerance llvmpipe is 3, not \{"threshold": t, "maxDiffPixels": n\}$/,
    ],
    [
      "a renderer's tolerance with an unknown key",
      { cases: { 'a.glsl': { tolerance: { llvmpipe: { maxDiff: 3 } } } } },
      /a\.glsl: unknown tolerance llvmpipe\.maxDiff \(expected threshold, maxDiffPixels\)$/,
    ],
    [
      "a renderer's tolerance below 0",
      { cases: { 'a.glsl': { tolerance: { llvmpipe: { maxDiffPixels: -1 } } } } },
      /a\.glsl: tolerance llvmpipe\.maxDiffPixels is -1, not a number >= 0$/,
    ],
  ];
  test.each(REFUSED)('%s: one line, exit 2', (_, manifest, said) => {
    let error;
    try {
      casesOf(manifest);
    } catch (caught) {
      error = caught;
    }
    expect(error?.message).toMatch(said);
    expect(error.message).not.toContain('\n');
    expect(error.exitCode).toBe(2);
  });
});
