// docs/ci.md's workflow cannot rot (issue 47, item 3): it installs the packages .ci/run installs
// (APT_PACKAGES), its `shaderproof test` command takes only flags `test` has, and its matrix and
// --shard count the same machines.

import fs from 'node:fs';
import path from 'node:path';
import { describe, expect, test } from 'vitest';
import { io } from '../../src/api/io.js';
import { main } from '../../src/cli/main.js';
import { REPO_ROOT } from '../support/config.js';

const recipe = fs.readFileSync(path.join(REPO_ROOT, 'docs', 'ci.md'), 'utf8');
const workflow = /```yaml\n([\s\S]*?)```/.exec(recipe)?.[1] ?? '';
const ciRun = fs.readFileSync(path.join(REPO_ROOT, '.ci', 'run'), 'utf8');

/** The packages of every `apt-get install` line of `text`, options left out. @param {string} text */
const installed = (text) =>
  [...text.matchAll(/apt-get install ([^\n&|;]*)/g)].flatMap((m) =>
    m[1]
      .trim()
      .split(/\s+/)
      .filter((word) => !word.startsWith('-')),
  );

/** What `shaderproof test --help` lists as its flags. */
async function testFlags() {
  const lines = [];
  const saved = { ...io };
  io.out = (line) => lines.push(line) > 0;
  try {
    expect(await main(['test', '--help'])).toBe(0);
  } finally {
    Object.assign(io, saved);
  }
  return new Set([...lines.join('\n').matchAll(/^ {2}(--[\w-]+)/gm)].map((m) => m[1]));
}

/**
 * Flags the workflow may use before `test --help` lists them: --renderer is the lead's, coming on
 * its own branch (render, record and test: swiftshader, llvmpipe or gpu).
 */
const COMING = new Set(['--renderer']);

describe('docs/ci.md, the CI recipe', () => {
  test('installs the packages .ci/run installs', () => {
    const list = /^APT_PACKAGES=\(([^)]*)\)$/m.exec(ciRun)?.[1].trim().split(/\s+/);
    expect(list).toEqual(['chromium', 'libegl1', 'libegl-mesa0', 'libgl1-mesa-dri']);
    expect(installed(ciRun), '.ci/run installs its list, and nothing else').toEqual(['"${APT_PACKAGES[@]}"']);
    expect(installed(workflow).sort()).toEqual([...(list ?? [])].sort());
    // the docker command that draws the references installs them too
    expect(installed(recipe.slice(recipe.indexOf('## Drawing the references'))).sort()).toEqual([...(list ?? [])].sort());
  });

  test('runs shaderproof test with flags it has, over as many shards as the matrix has machines', async () => {
    const commands = [...recipe.matchAll(/npx shaderproof test ([^\n']*)/g)].map((m) => m[1]);
    expect(commands.length).toBeGreaterThanOrEqual(2);
    const known = await testFlags();
    for (const command of commands) {
      const unknown = [...command.matchAll(/(^|\s)(--[\w-]+)/g)].map((m) => m[2]).filter((flag) => !known.has(flag) && !COMING.has(flag));
      expect(unknown, command).toEqual([]);
    }
    const machines = /shard: \[([^\]]*)\]/.exec(workflow)?.[1].split(',').map(Number);
    const shards = Number(/--shard \$\{\{ matrix\.shard \}\}\/(\d+)/.exec(workflow)?.[1]);
    expect(machines).toEqual(Array.from({ length: shards }, (_, i) => i + 1));
    expect(workflow).toMatch(/SHADERPROOF_MEDIA_CACHE: (\S+)[\s\S]*uses: actions\/cache@v\d[\s\S]*path: \1\n/);
    expect(workflow).toMatch(/if: always\(\)\n\s+uses: actions\/upload-artifact@v\d\n[\s\S]*path: shaderproof-output\//);
  });

  test('says where the package comes from (the registry, git or a tarball) and what `test` draws with without --renderer', () => {
    const pkg = JSON.parse(fs.readFileSync(path.join(REPO_ROOT, 'package.json'), 'utf8'));
    expect(pkg.private).toBeUndefined();
    const words = recipe.replace(/\s+/g, ' ');
    expect(words).toContain(`npm install --save-dev ${pkg.name}\``);
    expect(words).toContain('npm install --save-dev git+URL#COMMIT');
    // the tarball npm pack writes: its name and version are package.json's
    expect(words).toContain(`npm pack\` writes \`${pkg.name}-${pkg.version}.tgz\``);
    expect(words).toContain(`npm install --save-dev ./${pkg.name}-${pkg.version}.tgz`);
    // runner/corpus.js and drawn-by.js: the references' renderer; --update and a new folder as render
    expect(words).toMatch(/Without `--renderer` \(or `\$SHADERPROOF_RENDERER`\), `test` draws with the renderer that drew the references/);
    expect(words).toContain('`shaders/__references__/drawn-by.json`');
    expect(words).toMatch(/no references yet, draw with llvmpipe where Mesa is installed, else SwiftShader/);
    expect(words).not.toMatch(/Without the flag `test` draws with SwiftShader/);
  });
});
