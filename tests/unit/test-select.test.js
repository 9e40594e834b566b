// Choosing the cases of `shaderproof test` (src/runner/select.js, corpus.js, watch.js) without a
// browser: files, sub-folders and view names as arguments, --grep, --update of the chosen cases
// only, --last-failed and --watch, with the sessions of tests/support/fake-session.js (a colour
// from the shader's name). tests/browser/cli-select.test.js runs a file, --grep and --watch through the
// real command line and Chromium.

import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import { io } from '../../src/api/io.js';
import { runTest } from '../../src/runner/corpus.js';
import { findCases, readManifest } from '../../src/runner/manifest.js';
import { LAST_RUN_FILE, pickCases, readGrep, readLastRun, readSelection, testFolderOf } from '../../src/runner/select.js';
import { readPng, writePng } from '../../src/headless/png.js';
import { fakeSession } from '../support/fake-session.js';

let root = '';
const SHADER = 'void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n';

/** Writes `files` (path → text) under root/`name`, afresh; returns that folder. */
function tree(name, files) {
  const dir = path.join(root, name);
  fs.rmSync(dir, { recursive: true, force: true });
  for (const [file, text] of Object.entries(files)) {
    fs.mkdirSync(path.dirname(path.join(dir, file)), { recursive: true });
    fs.writeFileSync(path.join(dir, file), text);
  }
  return dir;
}

/** A test folder: a manifest with two views of a shader outside it, files at its top and in sub/. */
const SUITE = {
  'suite/shaderproof.json': JSON.stringify({ cases: { orbit: { shader: '../scene.glsl' }, 'close/up': { shader: '../scene.glsl' } } }),
  'suite/a.glsl': SHADER,
  'suite/b.glsl': SHADER,
  'suite/sub/c.glsl': SHADER,
  'suite/sub/d.json': '{}',
  'suite/__references__/a.glsl.png': '',
  'scene.glsl': SHADER,
  'loose/e.glsl': SHADER,
};

beforeAll(() => {
  root = fs.mkdtempSync(path.join(os.tmpdir(), 'shaderproof-select-'));
  tree('s', SUITE);
});
afterAll(() => fs.rmSync(root, { recursive: true, force: true }));

/** The names that `args` (relative to root/s) choose with `values`' --grep. */
function chosen(args, values = {}) {
  const selection = readSelection(args.map((a) => path.join(root, 's', a)));
  const all = findCases(selection.dir, readManifest(selection.dir));
  return { dir: path.relative(root, selection.dir), names: pickCases(all, selection, readGrep(values), 'suite').map((c) => c.name) };
}

describe('which cases the arguments choose', () => {
  const ALL = ['a.glsl', 'b.glsl', 'close/up', 'orbit', 'sub/c.glsl', 'sub/d.json'];
  // [what, arguments, flags, test folder, cases]
  /** @type {Array<[string, string[], Record<string, string>, string, string[]]>} */
  const CHOSEN = [
    ['the folder: every case', ['suite'], {}, 's/suite', ALL],
    ['one file: that case', ['suite/b.glsl'], {}, 's/suite', ['b.glsl']],
    ["a sub-folder's file: a case of the folder above, by its path", ['suite/sub/c.glsl'], {}, 's/suite', ['sub/c.glsl']],
    ['a sub-folder and a file: one run of both', ['suite/sub/', 'suite/a.glsl'], {}, 's/suite', ['a.glsl', 'sub/c.glsl', 'sub/d.json']],
    ['a view by its name', ['suite/orbit'], {}, 's/suite', ['orbit']],
    ['a folder of views by its name', ['suite/close'], {}, 's/suite', ['close/up']],
    ['--grep, case-insensitive', ['suite'], { grep: 'ORBIT|^sub/c' }, 's/suite', ['orbit', 'sub/c.glsl']],
    ['--grep /PATTERN/, as written', ['suite'], { grep: '/B\\.glsl/' }, 's/suite', []],
    ['--grep /PATTERN/i', ['suite'], { grep: '/B\\.glsl/i' }, 's/suite', ['b.glsl']],
    ['--grep-invert', ['suite'], { 'grep-invert': '\\.(glsl|json)$' }, 's/suite', ['close/up', 'orbit']],
    ['--grep and --grep-invert', ['suite'], { grep: 'sub/', 'grep-invert': 'json' }, 's/suite', ['sub/c.glsl']],
    ['a file of a folder with no manifest nor references: its own folder', ['loose/e.glsl'], {}, 's/loose', ['e.glsl']],
  ];
  test.each(CHOSEN)('%s', (_, args, values, dir, names) => {
    if (!names.length) {
      expect(() => chosen(args, values)).toThrow(/no case of the 6 chosen in suite matches --grep\/--grep-invert/);
      return;
    }
    expect(chosen(args, values)).toEqual({ dir, names });
  });

  // [what, arguments, the line]
  /** @type {Array<[string, string[], RegExp]>} */
  const REFUSED = [
    [
      'two test folders',
      ['suite/a.glsl', 'loose/e.glsl'],
      /a\.glsl and \S+e\.glsl are cases of two test folders \(\S+suite and \S+loose\)/,
    ],
    [
      'a name that is no file and no view',
      ['suite/nothing'],
      /suite\/nothing: no such file, nor a view named nothing in suite's shaderproof\.json$/,
    ],
    [
      'a reference',
      ['suite/__references__/a.glsl.png'],
      /a\.glsl\.png: not a shader \(a case is a \.glsl or \.json file, or a folder of them\)$/,
    ],
    ['a name that is no file, where no manifest is', ['loose/nothing.glsl'], /loose\/nothing\.glsl: no such file or folder$/],
    ['the manifest', ['suite/shaderproof.json'], /shaderproof\.json: a manifest, not a case; give its folder to run its cases$/],
    ['a folder of no case', ['suite/__references__'], /__references__: no case under it/],
  ];
  test.each(REFUSED)('refused: %s', (_, args, line) => {
    expect(() => chosen(args)).toThrow(line);
  });

  test('the test folder: the nearest with a manifest or references, from the folder itself up', () => {
    expect(testFolderOf(path.join(root, 's/suite/sub'))).toBe(path.join(root, 's/suite'));
    expect(testFolderOf(path.join(root, 's/suite'))).toBe(path.join(root, 's/suite'));
    expect(testFolderOf(path.join(root, 's/loose'))).toBe(null);
  });
});

/** runTest on fake sessions with io captured: { code, out, err, sessions }. */
async function run(args, values, { stopped = undefined, onErr = (/** @type {string} */ line) => {} } = {}) {
  const out = [];
  const err = [];
  const saved = { ...io };
  io.out = (line) => out.push(...line.split('\n')) > 0;
  io.err = (line) => (onErr(line), err.push(...line.split('\n')) > 0);
  io.isTerminal = () => false;
  let sessions = 0;
  try {
    const start = async () => (sessions++, /** @type {any} */ (fakeSession('swiftshader')));
    const code = await runTest(
      { values: { out: path.join(root, 'out'), jobs: '1', ...values }, positionals: args },
      { start, silenceMs: 2_000, stopped },
    );
    return {
      code,
      out,
      err,
      sessions,
      lines: out.filter((line) => /^(pass|FAIL|skip) /.test(line)).map((line) => line.slice(0, 6) + line.slice(6).split(' ')[0]),
    };
  } finally {
    Object.assign(io, saved);
  }
}

/** A folder of three cases with their references. */
async function folderWithReferences(name) {
  const dir = tree(name, { 'a.glsl': SHADER, 'b.glsl': SHADER, 'sub/c.glsl': SHADER });
  const update = await run([dir], { update: true });
  expect(update.code, update.err.join('\n')).toBe(0);
  return dir;
}

/** Each file under `dir`: its bytes and mtime. */
const snapshot = (dir) =>
  Object.fromEntries(
    fs
      .readdirSync(dir, { recursive: true, encoding: 'utf8' })
      .map((name) => path.join(dir, name))
      .filter((file) => fs.statSync(file).isFile())
      .map((file) => [path.relative(dir, file), { bytes: fs.readFileSync(file).toString('base64'), mtime: fs.statSync(file).mtimeMs }]),
  );

describe('runs of chosen cases', () => {
  test('a file and a sub-folder run as one run, the count said against the whole folder', async () => {
    const dir = await folderWithReferences('chosen');
    const { code, lines, err } = await run([path.join(dir, 'b.glsl'), path.join(dir, 'sub')], {});
    expect(code).toBe(0);
    expect(lines).toEqual(['pass  b.glsl', 'pass  sub/c.glsl']);
    expect(err[0]).toMatch(/^2 of 3 cases, drawn by Fake renderer/);
  });

  test('--update of chosen cases writes their references only: the others and drawn-by.json keep their bytes and mtimes', async () => {
    const dir = await folderWithReferences('update');
    const references = path.join(dir, '__references__');
    // the references another colour, so that a rewrite shows in the bytes too
    for (const name of ['a.glsl.png', 'b.glsl.png', 'sub/c.glsl.png']) {
      const image = readPng(path.join(references, name));
      writePng(path.join(references, name), { ...image, data: image.data.map((v, i) => (i % 4 === 3 ? v : 255 - v)) });
    }
    await new Promise((resolve) => setTimeout(resolve, 20)); // a rewrite would have a later mtime
    const before = snapshot(references);
    const { code, lines } = await run([dir], { update: true, grep: '^b' });
    expect(code).toBe(0);
    expect(lines).toEqual(['pass  b.glsl']);
    const after = snapshot(references);
    expect(after['b.glsl.png'].bytes, 'the chosen case was written').not.toBe(before['b.glsl.png'].bytes);
    for (const name of ['a.glsl.png', path.join('sub', 'c.glsl.png'), 'drawn-by.json']) expect(after[name], name).toEqual(before[name]);
  });

  test('--update of chosen cases with another renderer than the others were drawn with is refused', async () => {
    const dir = await folderWithReferences('renderer');
    await expect(run([path.join(dir, 'a.glsl')], { update: true, renderer: 'llvmpipe' })).rejects.toThrow(
      /^--update of 1 of 3 cases with llvmpipe: the folder's other references are swiftshader's; update the whole folder to change what draws them \(shaderproof test \S+renderer --update\)$/,
    );
  });

  test('--last-failed runs what failed in the last run, and says when nothing did', async () => {
    const dir = await folderWithReferences('last');
    fs.copyFileSync(path.join(dir, '__references__/a.glsl.png'), path.join(dir, '__references__/b.glsl.png'));
    const first = await run([dir], {});
    expect([first.code, first.lines]).toEqual([1, ['pass  a.glsl', 'FAIL  b.glsl', 'pass  sub/c.glsl']]);
    expect(readLastRun(path.join(root, 'out'))).toEqual({ dir, status: 'failed', failed: ['b.glsl'], ran: 3 });
    // with no DIR: the last run's folder
    const again = await run([], { 'last-failed': true });
    expect([again.code, again.lines]).toEqual([1, ['FAIL  b.glsl']]);
    fs.rmSync(path.join(dir, '__references__/b.glsl.png'));
    await run([dir], { update: true, grep: '^b' });
    const none = await run([dir], { 'last-failed': true });
    expect([none.code, none.out, none.sessions]).toEqual([0, ['--last-failed: no case failed in the last run (of 1); nothing to run'], 0]);
    fs.rmSync(path.join(root, 'out', LAST_RUN_FILE));
    await expect(run([dir], { 'last-failed': true })).rejects.toThrow(
      /^--last-failed: no last run in \S+\.last-run\.json; run shaderproof test DIR first \(with the same --out\)$/,
    );
  });

  test('--watch reruns the case whose shader is saved, or whose reference changes, in the same browser', async () => {
    const dir = await folderWithReferences('watch');
    let stop = () => {};
    const stopped = new Promise((resolve) => (stop = () => resolve(undefined)));
    const said = [];
    /** Resolves when a line matching `pattern` has been said `count` times. */
    const waitFor = (pattern, count = 1) =>
      new Promise((resolve, reject) => {
        const id = setTimeout(() => reject(new Error(`no ${pattern} within 10 s: ${said.join(' | ')}`)), 10_000);
        const check = () => said.filter((line) => pattern.test(line)).length >= count && (clearTimeout(id), resolve(undefined));
        waiters.push(check);
        check();
      });
    const waiters = [];
    const running = run([dir], { watch: true }, { stopped, onErr: (line) => (said.push(line), waiters.forEach((w) => w())) });
    await waitFor(/^watching 3 cases \(0 failing\)/);
    fs.writeFileSync(path.join(dir, 'sub/c.glsl'), SHADER + '// saved\n');
    await waitFor(/^rerunning 1 case: sub\/c\.glsl$/);
    await waitFor(/^watching 3 cases/, 2);
    // b's reference another's: b reruns and fails, and the reports say so
    fs.copyFileSync(path.join(dir, '__references__/a.glsl.png'), path.join(dir, '__references__/b.glsl.png'));
    await waitFor(/^rerunning 1 case: b\.glsl$/);
    await waitFor(/^watching 3 cases \(1 failing\)/);
    stop();
    const { code, lines, sessions } = await running;
    expect(lines).toEqual(['pass  a.glsl', 'pass  b.glsl', 'pass  sub/c.glsl', 'pass  sub/c.glsl', 'FAIL  b.glsl']);
    expect(code, 'the exit code of the latest results').toBe(1);
    expect(sessions, 'one browser for every run').toBe(1);
    const junit = fs.readFileSync(path.join(root, 'out', 'junit.xml'), 'utf8');
    expect(junit).toMatch(/<testsuites tests="3" failures="1"/);
  });
});
