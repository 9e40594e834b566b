// Choosing cases through the real command line and Chromium (bin/shaderproof.js, each run its own
// process): cases by their files, and --watch rerunning a saved shader in the browser it kept.
// tests/unit/test-select.test.js checks the choosing itself without a browser.

import { spawn } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import { builtPage } from '../../src/headless/page-server.js';
import { REPO_ROOT } from '../support/config.js';
import { runShaderproof } from '../support/shaderproof-child.js';

let folder = '';
beforeAll(async () => {
  folder = fs.mkdtempSync(path.join(os.tmpdir(), 'shaderproof-cli-select-'));
  await builtPage(); // the harness built dist/ for this run: no build inside a test's time
});
afterAll(() => fs.rmSync(folder, { recursive: true, force: true }));

const shaderproof = (...args) => runShaderproof(args, { cwd: folder, timeout: 90_000 });

/** A colour of its own for each case. @param {string} rgb */
const shader = (rgb) => `void mainImage(out vec4 c, in vec2 f) { c = vec4(${rgb}, 1.0); }\n`;

const write = (name, text) => {
  fs.mkdirSync(path.dirname(path.join(folder, name)), { recursive: true });
  fs.writeFileSync(path.join(folder, name), text);
};

describe('choosing cases, through Chromium', () => {
  test('cases by their files, --watch: a saved shader reruns in the kept browser, the reports follow, Ctrl-C exits with the latest results', async () => {
    write('corpus/a.glsl', shader('1.0, 0.0, 0.0'));
    write('corpus/b.glsl', shader('0.0, 1.0, 0.0'));
    write('corpus/c.glsl', shader('0.0, 0.0, 1.0'));
    write('corpus/shaderproof.json', JSON.stringify({ defaults: { size: '32x18' } }));
    const update = await shaderproof('test', 'corpus', '--update', '--out', 'report', '--jobs', '1');
    expect(update.code, update.stderr).toBe(0);

    const bin = path.join(REPO_ROOT, 'bin/shaderproof.js');
    const args = ['test', 'corpus/a.glsl', 'corpus/b.glsl', '--watch', '--out', 'report', '--jobs', '1'];
    const child = spawn(process.execPath, [bin, ...args], { cwd: folder, stdio: ['ignore', 'pipe', 'pipe'] });
    let said = '';
    child.stdout.on('data', (chunk) => (said += chunk));
    child.stderr.on('data', (chunk) => (said += chunk));
    const exited = new Promise((resolve) => child.on('exit', (code) => resolve(code)));
    /** Waits at most `ms` for `pattern` to have been said `count` times. */
    const waitFor = async (pattern, count, ms) => {
      const until = Date.now() + ms;
      while ((said.match(pattern) ?? []).length < count) {
        if (Date.now() > until || child.exitCode !== null) throw new Error(`no ${pattern} within ${ms} ms:\n${said}`);
        await new Promise((resolve) => setTimeout(resolve, 100));
      }
    };
    try {
      await waitFor(/^watching 2 cases \(0 failing\)/gm, 1, 60_000);
      write('corpus/a.glsl', shader('0.0, 0.0, 1.0'));
      await waitFor(/^rerunning 1 case: a\.glsl$/gm, 1, 10_000);
      await waitFor(/^watching 2 cases \(1 failing\)/gm, 1, 30_000);
      expect(said.match(/^(pass|FAIL) {2}\S+/gm)).toEqual(['pass  a.glsl', 'pass  b.glsl', 'FAIL  a.glsl']);
      expect(said.match(/^\d of 3 cases, drawn by /gm), 'the files chosen, then the one saved').toEqual([
        '2 of 3 cases, drawn by ',
        '1 of 3 cases, drawn by ',
      ]);
      const junit = fs.readFileSync(path.join(folder, 'report/junit.xml'), 'utf8');
      expect(junit).toMatch(/<testsuites tests="2" failures="1"/);
      child.kill('SIGINT');
      expect(await exited, 'a case fails: exit 1').toBe(1);
    } finally {
      if (child.exitCode === null) child.kill('SIGKILL');
    }
  });
});
