// `shaderproof test`'s runner without a browser (src/runner/runner.js, guard.js, report/reporters.js):
// sessions made here draw a colour from the shader's name at once, or never answer, or throw,
// so that what the runner does about a case that takes its browser down (issue 45, item 1), the
// order of its reports with several workers (item 8), --reporter and the progress line (issue
// 47) are checked in milliseconds. tests/browser/test-workers.test.js does the same in real Chromium.

import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import { main } from '../../src/cli/main.js';
import { io } from '../../src/api/io.js';
import { runTest } from '../../src/runner/corpus.js';
import { silenceLimitMs } from '../../src/runner/guard.js';
import { readPng, writePng } from '../../src/headless/png.js';
import { fakeSession } from '../support/fake-session.js';

let folder = '';
beforeAll(() => {
  folder = fs.mkdtempSync(path.join(os.tmpdir(), 'shaderproof-runner-'));
});
afterAll(() => fs.rmSync(folder, { recursive: true, force: true }));

const SHADER = 'void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n';

/** A folder of cases named `names` (their text is the same: the fake session draws by name). */
function cases(dir, names) {
  fs.rmSync(path.join(folder, dir), { recursive: true, force: true });
  fs.mkdirSync(path.join(folder, dir, '__references__'), { recursive: true });
  for (const name of names) fs.writeFileSync(path.join(folder, dir, name), SHADER);
  return path.join(folder, dir);
}

/** runTest with io captured and fake sessions: { code, out, err, started } (lines; sessions started). */
async function run(dir, flags = {}, { silenceMs = 300, terminal = false, renderer = undefined } = {}) {
  const out = [];
  const err = [];
  const written = [];
  const saved = { ...io, write: process.stderr.write };
  io.out = (line) => out.push(...line.split('\n')) > 0;
  io.err = (line) => err.push(...line.split('\n')) > 0;
  io.isTerminal = () => terminal;
  process.stderr.write = /** @type {any} */ ((chunk) => written.push(String(chunk)) > 0);
  let started = 0;
  try {
    const values = { out: path.join(folder, `${path.basename(dir)}-out`), ...flags };
    const start = async () => (started++, /** @type {any} */ (fakeSession(renderer)));
    const code = await runTest({ values, positionals: [dir] }, { start, silenceMs });
    return { code, out, err, started, written, report: values.out };
  } finally {
    Object.assign(io, saved);
    process.stderr.write = saved.write;
  }
}

describe('one case never takes a run down (issue 45, item 1)', () => {
  test('a case whose browser never answers, or whose run throws, fails with one line; the others run; every report is written', async () => {
    const dir = cases('down', ['a-hang.glsl', 'b-ok.glsl', 'c-boom.glsl', 'd-ok.glsl', 'e-late.glsl']);
    await run(dir, { update: true, jobs: '1' });
    const started = Date.now();
    const { code, out, report, started: sessions } = await run(dir, { jobs: '1' });
    expect(code).toBe(1);
    const lines = out.filter((line) => /^(pass|FAIL) /.test(line));
    expect(lines.map((line) => line.slice(0, 18).trim())).toEqual([
      'FAIL  a-hang.glsl',
      'pass  b-ok.glsl',
      'FAIL  c-boom.glsl',
      'pass  d-ok.glsl',
      'FAIL  e-late.glsl',
    ]);
    expect(lines[0]).toMatch(/the browser stopped answering: no word from it for 0\.3 s; it was replaced and the run went on$/);
    expect(lines[2]).toMatch(
      /internal error: Cannot read properties of undefined \(reading 'trim'\) \(run again with --verbose for its stack, and report it\); the browser was replaced$/,
    );
    expect(lines[4]).toMatch(
      /the browser stopped answering \(opening a page: no answer within 120 s\); it was replaced and the run went on$/,
    );
    expect(out.at(-1)).toMatch(/^2 passed, 3 failed, in \d+\.\d s; junit\.xml and index\.html in /);
    expect(Date.now() - started, 'the hang is given up after the silence limit, not a page timeout').toBeLessThan(5_000);
    // the first session for the hang, a second for b-ok and c-boom, a third after the bug
    expect(sessions).toBe(3);
    const junit = fs.readFileSync(path.join(report, 'junit.xml'), 'utf8');
    expect([...junit.matchAll(/<testcase classname="shaderproof" name="([^"]+)"/g)].map((m) => m[1])).toEqual([
      'a-hang.glsl',
      'b-ok.glsl',
      'c-boom.glsl',
      'd-ok.glsl',
      'e-late.glsl',
    ]);
    expect(fs.readFileSync(path.join(report, 'index.html'), 'utf8')).toContain('the browser stopped answering');
  });

  test('the silence limit is the watchdog: a page start, a first frame and a band', () => {
    // the page's own limits (src/shared/timeouts.js): 20 s to start a worker, 30 s a first frame, 5 s a band
    expect(silenceLimitMs({ hangMs: 5_000, compileHangMs: 30_000 })).toBe(55_000);
    expect(silenceLimitMs({ hangMs: 2_000, compileHangMs: 2_000 })).toBe(24_000);
  });
});

describe("the manifest's views and a renderer's own tolerance (issue 46, item 4)", () => {
  test("views of one shader outside DIR each have a reference; a renderer's own tolerance holds when that renderer draws", async () => {
    const dir = cases('views', []);
    fs.writeFileSync(path.join(folder, 'scene.glsl'), SHADER);
    const manifest = {
      defaults: { shader: '../scene.glsl' },
      cases: { near: {}, far: { tolerance: { llvmpipe: { maxDiffPixels: 16 } } } },
    };
    fs.writeFileSync(path.join(dir, 'shaderproof.json'), JSON.stringify(manifest));
    const update = await run(dir, { update: true, jobs: '1' });
    expect(update.code, update.err.join('\n')).toBe(0);
    expect(fs.readdirSync(path.join(dir, '__references__')).sort()).toEqual(['drawn-by.json', 'far.png', 'near.png']);
    // far's reference another colour: each of its 16 pixels differs from what is drawn
    const reference = path.join(dir, '__references__', 'far.png');
    const image = readPng(reference);
    writePng(reference, { ...image, data: image.data.map((v, i) => (i % 4 === 3 ? v : 255 - v)) });
    const swiftshader = await run(dir, { jobs: '1' }, { renderer: 'swiftshader' });
    expect(swiftshader.out.filter((line) => /^(pass|FAIL) /.test(line)).map((line) => line.replace(/\s+\d+ ms/, ''))).toEqual([
      'FAIL  far  16 pixels differ from the reference (at most 0 may) in x 0–3, y 0–3',
      'pass  near',
    ]);
    const llvmpipe = await run(dir, { jobs: '1' }, { renderer: 'llvmpipe' });
    expect(llvmpipe.code, llvmpipe.out.join('\n')).toBe(0);
    expect(llvmpipe.out.at(-1)).toMatch(/^2 passed, 0 failed/);
  });
});

describe('--jobs N (issue 45, item 8)', () => {
  test('the reports and the summary are those of one worker, in the same order', async () => {
    const names = ['a-slow.glsl', 'b.glsl', 'c-slow.glsl', 'd.glsl', 'e.glsl', 'f-slow.glsl', 'g.glsl'];
    const dir = cases('jobs', names);
    await run(dir, { update: true, jobs: '1' });
    // a changed reference fails its case: d.glsl's is another colour
    fs.writeFileSync(path.join(dir, '__references__', 'd.glsl.png'), fs.readFileSync(path.join(dir, '__references__', 'b.glsl.png')));
    const strip = (text) => text.replace(/time="[\d.]+"/g, 'time=""').replace(/<span data-volatile>[^<]*<\/span>/g, '');
    const outputs = [];
    for (const jobs of ['1', '3']) {
      const { out, report } = await run(dir, { jobs, out: path.join(folder, `jobs-out-${jobs}`) });
      outputs.push({
        lines: out.map((line) => line.replace(/ +\d+ ms( {2}|$)/, ' ms ').replace(/in \d+\.\d s;.*/, 'in s')),
        junit: strip(fs.readFileSync(path.join(report, 'junit.xml'), 'utf8')),
        html: strip(fs.readFileSync(path.join(report, 'index.html'), 'utf8')),
      });
    }
    expect(outputs[0].lines.filter((line) => / ms /.test(line))).toHaveLength(names.length);
    expect(outputs[1]).toEqual(outputs[0]);
  });

  test.each([
    ['0', /--jobs 0: expected a whole number from 1 to 32/],
    ['two', /--jobs two: expected a whole number/],
  ])('--jobs %s is refused before any browser starts', async (value, said) => {
    const err = [];
    const saved = { ...io };
    io.err = (line) => err.push(line) > 0;
    try {
      expect(await main(['test', folder, '--jobs', value])).toBe(2);
    } finally {
      Object.assign(io, saved);
    }
    expect(err.join('\n')).toMatch(said);
  });
});

describe('--reporter and the progress line (issue 47)', () => {
  test.each([
    [undefined, true, true, true],
    [['junit'], false, true, false],
    [['dot,html'], true, false, true],
    [['dot', 'junit'], true, true, false],
  ])('--reporter %j: case lines %s, junit.xml %s, index.html %s', async (reporter, dot, junit, html) => {
    const dir = cases('reporters', ['one.glsl']);
    const { out, report } = await run(dir, { update: true, ...(reporter ? { reporter } : {}) });
    expect(out.some((line) => line.startsWith('pass  one.glsl'))).toBe(dot);
    expect(fs.existsSync(path.join(report, 'junit.xml'))).toBe(junit);
    expect(fs.existsSync(path.join(report, 'index.html'))).toBe(html);
    expect(fs.existsSync(path.join(report, 'one.glsl-thumb.png')), 'a thumbnail only for the HTML report').toBe(html);
    expect(out.at(-2)).toMatch(/^1 passed, 0 failed, in /);
  });

  test('an unknown reporter is refused, naming the three', async () => {
    const err = [];
    const saved = { ...io };
    io.err = (line) => err.push(line) > 0;
    try {
      expect(await main(['test', folder, '--reporter', 'dot,tap'])).toBe(2);
    } finally {
      Object.assign(io, saved);
    }
    expect(err.join('\n')).toMatch(/--reporter tap: expected dot, junit, html/);
  });

  test('a terminal shows a progress line, cleared for each case line and at the end; a log gets none', async () => {
    const dir = cases('progress', ['a.glsl', 'b.glsl', 'c.glsl']);
    const onTerminal = await run(dir, { update: true }, { terminal: true });
    const CLEAR = '\r\x1b[2K'; // to the line's start, and the line erased (ANSI EL 2)
    const drawn = onTerminal.written.filter((chunk) => chunk.startsWith(`${CLEAR}[`)).map((chunk) => chunk.slice(CLEAR.length));
    expect(drawn[0]).toMatch(/^\[\.{24}\] 0\/3 cases · 0 failed · 0:00$/);
    expect(drawn.at(-1)).toMatch(/^\[#{24}\] 3\/3 cases · 0 failed · 0:0\d · about 0:00 left$/);
    expect(onTerminal.written.at(-1), 'the line is cleared at the end').toBe(CLEAR);
    const inLog = await run(dir, { update: true }, { terminal: false });
    expect(inLog.written.filter((chunk) => chunk.includes('\r'))).toEqual([]);
  });
});
