// What `npm pack` ships (issue 45, item 7): package.json's "files" lists each thing the package
// needs, and nothing else gets in. The command line's modules are what bin/shaderproof.js imports,
// and the Node API's what src/api/index.js imports, followed file by file, with the API's
// declarations (types/, made by prepack); the page it serves is the built page's HTML, its bundles and the example
// shaders it serves by URL. Whatever else lies in dist/ (vite copies all of public/ there: the
// README's pictures, the tests' ignored public/test-*/ folders) stays out, so the test plants
// such files before it packs.

import { execFile } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { promisify } from 'node:util';
import { expect, test } from 'vitest';
import { builtPage } from '../../src/headless/page-server.js';
import { REPO_ROOT } from '../support/config.js';

const run = promisify(execFile);

/**
 * The text of a module without its comments (a JSDoc `import('…')` type is no import). Line
 * comments go first: one may hold a glob such as `examples/*.glsl`, which would open a block.
 */
const withoutComments = (text) => text.replace(/(^|[^:'"`\\])\/\/.*$/gm, '$1').replace(/\/\*[\s\S]*?\*\//g, '');

/**
 * Every module `entry` loads, itself included, following relative imports (static, dynamic and
 * bare `import '../x.js'`), as paths relative to the repository.
 * @param {string} entry
 */
function moduleGraph(entry) {
  const seen = new Set();
  const visit = (file) => {
    if (seen.has(file)) return;
    seen.add(file);
    const text = withoutComments(fs.readFileSync(file, 'utf8'));
    for (const m of text.matchAll(/\bfrom\s*'(\.[^']+)'|\bimport\(\s*'(\.[^']+)'\s*\)|\bimport\s+'(\.[^']+)'/g))
      visit(path.resolve(path.dirname(file), m[1] ?? m[2] ?? m[3]));
  };
  visit(path.join(REPO_ROOT, entry));
  return [...seen].map((file) => path.relative(REPO_ROOT, file).split(path.sep).join('/'));
}

/**
 * The files under a folder of the repository, relative to it, that `keep` accepts.
 * @param {string} dir
 * @param {(name: string) => boolean} [keep]
 */
const filesUnder = (dir, keep = () => true) =>
  fs
    .readdirSync(path.join(REPO_ROOT, dir), { recursive: true, withFileTypes: true })
    .filter((entry) => entry.isFile() && keep(entry.name))
    .map((entry) => path.relative(REPO_ROOT, path.join(entry.parentPath, entry.name)).split(path.sep).join('/'));

test('npm pack ships the command line, the Node API and its types, the built page and its example shaders, and nothing else', async () => {
  const dist = await builtPage();
  // the API's declarations, as prepack makes them (types/, git-ignored)
  await run('npm', ['run', '--silent', 'build:types'], { cwd: REPO_ROOT, timeout: 120_000 });
  // what a test run or a README picture leaves in dist/ (public/ is copied there whole)
  const planted = [path.join(dist, 'test-pack-probe', 'probe.glsl'), path.join(dist, 'pack-probe.png')];
  for (const file of planted) {
    fs.mkdirSync(path.dirname(file), { recursive: true });
    fs.writeFileSync(file, 'planted by tests/browser/package-files.test.js\n');
  }
  let packed;
  try {
    // --ignore-scripts: prepack would build the page again; it is built above
    const { stdout } = await run('npm', ['pack', '--dry-run', '--json', '--ignore-scripts'], { cwd: REPO_ROOT, timeout: 60_000 });
    packed = JSON.parse(stdout)[0].files.map((/** @type {{path: string}} */ f) => f.path);
  } finally {
    fs.rmSync(path.join(dist, 'test-pack-probe'), { recursive: true, force: true });
    fs.rmSync(path.join(dist, 'pack-probe.png'), { force: true });
  }
  const expected = [
    'CHANGELOG.md',
    'LICENSE',
    'README.md',
    'package.json',
    ...moduleGraph('bin/shaderproof.js'),
    ...moduleGraph('src/api/index.js'),
    ...filesUnder('types', (name) => name.endsWith('.d.ts')),
    'dist/index.html',
    'dist/engine.html',
    ...filesUnder('dist/assets'),
    // the notices of what the page's bundles compile in (ogv.js, libogg, libtheora: their BSD
    // licences ask for them wherever the code ships compiled)
    ...filesUnder('dist/licenses'),
    ...filesUnder('dist/examples', (name) => name.endsWith('.glsl')),
    ...filesUnder('dist/shaders', (name) => name.endsWith('.glsl')),
  ];
  expect(expected).toContain('src/headless/page-server.js'); // the graph was followed
  expect(expected).toContain('types/src/api/index.d.ts'); // package.json's "types"
  expect(packed.sort()).toEqual([...new Set(expected)].sort());
});
