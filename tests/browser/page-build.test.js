// The first run in a clone builds the page (src/headless/page-build.js) and prints nothing of the
// bundler: not Vite's banner, the files it wrote or rolldown's plugin-timings table, only the
// one line that says why it takes longer. A build that fails says why in one line, then its log;
// --verbose says the log as it goes. The clone here is a copy of the checkout without dist/ (its
// node_modules a link to this one's), so the shared dist/ of a parallel run is never touched.

import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import { buildPage } from '../../src/headless/page-build.js';
import { REPO_ROOT } from '../support/config.js';
import { runShaderproof } from '../support/shaderproof-child.js';

/** What the bundler says when it is let: none of it belongs on a quiet run's stderr. */
const BUNDLER_WORDS = ['PLUGIN_TIMINGS', 'vite v', 'built in', 'dist/assets', 'modules transformed'];

/** The checkout's files a build and a render need (public/'s test files left out, as git ignores them). */
const CLONE_FILES = ['bin', 'src', 'shaders', 'public', 'vite.config.js', 'package.json'];

const SHADER = 'void mainImage(out vec4 c, in vec2 f) { c = vec4(f.x / 8.0, 0.5, 0.0, 1.0); }\n';

let work = '';
let clone = '';

beforeAll(() => {
  work = fs.mkdtempSync(path.join(os.tmpdir(), 'shaderproof-build-'));
  clone = path.join(work, 'clone');
  for (const name of CLONE_FILES)
    fs.cpSync(path.join(REPO_ROOT, name), path.join(clone, name), {
      recursive: true,
      filter: (from) => !/^(test-|hmr-test-)/.test(path.basename(from)),
    });
  fs.symlinkSync(path.join(REPO_ROOT, 'node_modules'), path.join(clone, 'node_modules'), 'dir');
  fs.writeFileSync(path.join(work, 'still.glsl'), SHADER);
});

afterAll(() => fs.rmSync(work, { recursive: true, force: true }));

/** `shaderproof render` of the clone, on a small still. @param {string[]} [more] */
const render = (more = []) =>
  runShaderproof(['render', 'still.glsl', '-o', 'still.png', '--size', '8x4', ...more], {
    cwd: work,
    timeout: 240_000,
    bin: path.join(clone, 'bin', 'shaderproof.js'),
  });

describe('the first run in a clone with no dist/', () => {
  test('a build that fails says why in one line, then its log, and draws nothing', async () => {
    const entry = path.join(clone, 'src', 'player', 'engine-main.js');
    const good = fs.readFileSync(entry, 'utf8');
    fs.writeFileSync(entry, `${good}\nconst broken = ;\n`);
    try {
      const out = await render();
      expect(out.code, out.stderr).toBe(1);
      const lines = out.stderr.trimEnd().split('\n');
      expect(lines[0]).toBe('building the page (vite build), once…');
      expect(lines[1]).toMatch(
        /^shaderproof render: could not build the page \(vite build\): .*Unexpected token at \S*engine-main\.js:\d+:\d+; fix that/,
      );
      expect(lines.slice(2).join('\n')).toContain('Build failed'); // the log follows, indented
      expect(lines.slice(2).every((line) => line.startsWith('  '))).toBe(true);
      expect(fs.existsSync(path.join(work, 'still.png'))).toBe(false);
    } finally {
      fs.writeFileSync(entry, good);
    }
  });

  test('a build that works prints one line of its own and nothing of the bundler', async () => {
    const out = await render();
    expect(out.code, out.stderr).toBe(0);
    expect(out.stderr.trimEnd().split('\n')).toEqual(['building the page (vite build), once…']);
    for (const words of BUNDLER_WORDS) expect(out.stdout + out.stderr).not.toContain(words);
    expect(fs.existsSync(path.join(clone, 'dist', 'engine.html'))).toBe(true);
    expect(fs.existsSync(path.join(work, 'still.png'))).toBe(true);
  });
});

describe('buildPage', () => {
  /** A page of one module, built into a folder of its own: cheap, and nothing of the checkout's. */
  const tinyPage = () => {
    const root = fs.mkdtempSync(path.join(work, 'tiny-'));
    fs.mkdirSync(path.join(root, 'src'));
    fs.writeFileSync(path.join(root, 'src', 'index.html'), '<!doctype html><script type="module" src="./main.js"></script>\n');
    fs.writeFileSync(path.join(root, 'src', 'main.js'), 'document.title = "tiny";\n');
    const configFile = path.join(root, 'vite.config.mjs');
    fs.writeFileSync(
      configFile,
      `export default ${JSON.stringify({ root: path.join(root, 'src'), build: { outDir: path.join(root, 'dist') } })};\n`,
    );
    return { root, configFile };
  };

  test.each([
    ['says nothing without verbose', false, (/** @type {string[]} */ said) => expect(said).toEqual([])],
    ['says the log with verbose', true, (/** @type {string[]} */ said) => expect(said.join('\n')).toMatch(/vite v.*\n[\s\S]*built in/)],
  ])('%s', async (_, verbose, check) => {
    const { root, configFile } = tinyPage();
    /** @type {string[]} */
    const said = [];
    await buildPage({ configFile, verbose, say: (line) => said.push(line) });
    check(said);
    expect(fs.existsSync(path.join(root, 'dist', 'index.html'))).toBe(true);
  });
});
