// `shaderproof test`'s runner in real Chromium (tests/unit/test-runner.test.js does the same without
// one, in milliseconds): a first case whose page stops answering (its script made to spin, as a
// page held by a shader that never ends is) is given up and its browser replaced, the next case
// runs, the reports are written and no browser is left behind (issue 45, item 1); --jobs 3 gives
// the reports of one worker, in the same order (item 8).

import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import { io } from '../../src/api/io.js';
import { main } from '../../src/cli/main.js';
import { startSession } from '../../src/headless/session.js';
import { runTest } from '../../src/runner/corpus.js';
import { builtPage } from '../../src/headless/page-server.js';

let folder = '';
beforeAll(async () => {
  folder = fs.mkdtempSync(path.join(os.tmpdir(), 'shaderproof-workers-'));
  await builtPage(); // the harness built dist/ for this run
});
afterAll(() => fs.rmSync(folder, { recursive: true, force: true }));

const write = (name, text) => {
  fs.mkdirSync(path.dirname(path.join(folder, name)), { recursive: true });
  fs.writeFileSync(path.join(folder, name), text);
};

/** Runs `body` with io captured: { value, out, err } (lines). */
async function captured(body) {
  const out = [];
  const err = [];
  const saved = { ...io };
  io.out = (line) => out.push(...line.split('\n')) > 0;
  io.err = (line) => err.push(...line.split('\n')) > 0;
  try {
    return { value: await body(), out, err };
  } finally {
    Object.assign(io, saved);
  }
}

/** The processes this test process started that are still running (its browsers). */
const children = () =>
  execFileSync('ps', ['-o', 'pid=,comm=', '--ppid', String(process.pid)], { encoding: 'utf8' })
    .split('\n')
    .filter((line) => line.trim() && !/\sps$/.test(line));

const GRADIENT = 'void mainImage(out vec4 c, in vec2 f) { c = vec4(f / iResolution.xy, 0.25, 1.0); }\n';

/**
 * How long the runner waits for a sign of life here: the page's start (a browser's launch, a
 * page's load and first frame: ~1 s here, several beside other work) must fit in it.
 */
const SILENCE_MS = 8_000;

describe('a page that stops answering (issue 45, item 1)', () => {
  test('as the first case: given up after the silence limit, its browser replaced; the next case runs; the reports are written', async () => {
    write('stuck/a-stuck.glsl', GRADIENT);
    write('stuck/b-ok.glsl', GRADIENT.replace('0.25', '0.5'));
    write('stuck/shaderproof.json', JSON.stringify({ defaults: { size: '32x18' } }));
    const values = { out: path.join(folder, 'stuck-out'), jobs: '1' };
    const update = await captured(() => runTest({ values: { ...values, update: true }, positionals: [path.join(folder, 'stuck')] }));
    expect(update.value, update.out.join('\n')).toBe(0);

    // a-stuck.glsl draws once; then its page's script spins for good and it is drawn again
    /** @param {any} options */
    const start = async (options) => {
      const session = await startSession(options);
      return {
        ...session,
        /** @param {string} query */
        async draw(query) {
          if (!query.includes('a-stuck.glsl')) return session.draw(query);
          await session.draw(query);
          await session.client()?.page.evaluate(() => void setTimeout(() => { for (;;); }, 0)); // prettier-ignore
          return session.draw(query);
        },
      };
    };
    const started = Date.now();
    const run = await captured(() => runTest({ values, positionals: [path.join(folder, 'stuck')] }, { start, silenceMs: SILENCE_MS }));
    const took = Date.now() - started;
    expect(run.value).toBe(1);
    const lines = run.out.filter((line) => /^(pass|FAIL) /.test(line));
    expect(lines).toHaveLength(2);
    expect(lines[0]).toMatch(
      /^FAIL {2}a-stuck\.glsl +\d+ ms {2}the browser stopped answering: no word from it for 8 s; it was replaced and the run went on$/,
    );
    expect(lines[1]).toMatch(/^pass {2}b-ok\.glsl /);
    expect(run.out.at(-1)).toMatch(/^1 passed, 1 failed, in [\d.]+ s; junit\.xml and index\.html in /);
    expect(took, 'the silence limit, then a browser for the next case').toBeLessThan(SILENCE_MS + 20_000);
    expect(fs.readFileSync(path.join(values.out, 'junit.xml'), 'utf8')).toMatch(
      /name="a-stuck\.glsl"[^>]*>\s*<failure message="the browser stopped answering/,
    );
    expect(fs.readFileSync(path.join(values.out, 'index.html'), 'utf8')).toContain('data-case="b-ok.glsl"');
    expect(children(), 'no browser is left running').toEqual([]);
  });
});

describe('--jobs N (issue 45, item 8)', () => {
  test('--jobs 3 prints and writes what one worker does, in the same order', async () => {
    write('jobs/pass.glsl', GRADIENT);
    write('jobs/changed.glsl', GRADIENT.replace('0.25', '0.3'));
    write('jobs/broken.glsl', 'void mainImage(out vec4 c, in vec2 f) {\n    c = vec4(nope, 1.0);\n}\n');
    write('jobs/later.glsl', GRADIENT.replace('0.25', '0.9'));
    write('jobs/skipped.glsl', GRADIENT);
    write('jobs/sub/deeper.glsl', GRADIENT.replace('f /', '1.0 - f /'));
    write('jobs/shaderproof.json', JSON.stringify({ defaults: { size: '32x18' }, cases: { 'skipped.glsl': { skip: 'on purpose' } } }));
    const dir = path.join(folder, 'jobs');
    const update = await captured(() => main(['test', dir, '--update', '--out', path.join(folder, 'jobs-update')]));
    expect(update.out.join('\n')).toMatch(/5 passed, 1 failed/);
    write('jobs/changed.glsl', GRADIENT.replace('0.25', '0.6'));
    const strip = (text) => text.replace(/time="[\d.]+"/g, 'time=""').replace(/<span data-volatile>[^<]*<\/span>/g, '');
    const runs = [];
    for (const jobs of ['1', '3']) {
      const out = path.join(folder, `jobs-${jobs}`);
      const run = await captured(() => main(['test', dir, '--out', out, '--jobs', jobs]));
      expect(run.value).toBe(1);
      expect(run.err[0]).toMatch(new RegExp(`^6 of 6 cases, drawn by .*SwiftShader.*, ${jobs} workers?; iDate at iTime 0: `));
      runs.push({
        lines: run.out.map((line) => line.replace(/ +\d+ ms( {2}|$)/, ' ms ').replace(/in [\d.]+ s;.*/, 'in s')),
        junit: strip(fs.readFileSync(path.join(out, 'junit.xml'), 'utf8')),
        html: strip(fs.readFileSync(path.join(out, 'index.html'), 'utf8')),
        files: fs.readdirSync(out, { recursive: true }).map(String).sort(),
      });
    }
    const said = runs[0].lines.filter((line) => /^(pass|FAIL|skip) |^\d+ passed/.test(line));
    expect(said.map((line) => line.split(/ +/).slice(0, 2).join(' '))).toEqual([
      'FAIL broken.glsl',
      'FAIL changed.glsl',
      'pass later.glsl',
      'pass pass.glsl',
      'skip skipped.glsl',
      'pass sub/deeper.glsl',
      '4 passed,',
    ]);
    expect(runs[1]).toEqual(runs[0]);
    expect(children(), 'no browser is left running').toEqual([]);
  });
});
