// The command line's words for every flag and value it cannot use (issue 36, item 7), in-process:
// each is refused before any browser starts, in one line of the project's words that names the
// flag and says what to do, with exit 2 (src/cli/main.js, arguments.js, view-options.js). None
// may be another tool's message (node:util parseArgs's "Option '--x' argument is ambiguous",
// Node's "EISDIR: illegal operation").

import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import { main } from '../src/cli/main.js';
import { io, progressBar } from '../src/cli/io.js';

let folder = '';
let shader = '';
beforeAll(() => {
  folder = fs.mkdtempSync(path.join(os.tmpdir(), 'shaderproof-usage-'));
  shader = path.join(folder, 'a.glsl');
  fs.writeFileSync(shader, 'void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n');
  fs.mkdirSync(path.join(folder, 'somedir'));
});
afterAll(() => fs.rmSync(folder, { recursive: true, force: true }));

/** Runs main() with io captured: { code, out, err } (lines). */
async function shaderproof(args) {
  const out = [];
  const err = [];
  const saved = { ...io };
  io.out = (line) => {
    return out.push(...line.split('\n')) > 0;
  };
  io.err = (line) => {
    return err.push(...line.split('\n')) > 0;
  };
  try {
    const code = await main(args);
    return { code, out, err };
  } finally {
    Object.assign(io, saved);
  }
}

/** Words that are another tool's, not ours. */
const FOREIGN = /Option '|ERR_[A-Z_]+|EISDIR|ENOENT|illegal operation|ambiguous|at .*\.js:\d+/;

describe('a bad flag or value: one line, exit 2, the flag named, before any browser', () => {
  const render = (...flags) => ['render', '<shader>', '-o', 'x.png', ...flags];
  // [what, argv, what the line says]
  /** @type {Array<[string, string[], RegExp]>} */
  const CASES = [
    ['an unknown flag', render('--sise', '64x36'), /no flag --sise/],
    ['a flag with no value', render('--size'), /--size needs a value/],
    ['a flag followed by another', render('--size', '--time', '1'), /--size needs a value/],
    ['a value to a switch', render('--gpu=yes'), /--gpu takes no value/],
    ['an unknown renderer', render('--renderer', 'vulkan'), /--renderer vulkan: not a renderer; one of swiftshader, llvmpipe, gpu/],
    ['--gpu with another renderer', render('--gpu', '--renderer', 'llvmpipe'), /--gpu and --renderer llvmpipe disagree: give one/],
    ['--size not WxH', render('--size', '64by36'), /--size 64by36: expected WIDTHxHEIGHT/],
    ['--size past the page', render('--size', '100000x100000'), /--size 100000x100000: one draw is at most 16384 px a side.*--tile/],
    ['--size past a tiled still', render('--size', '100000x100000', '--tile', '512'), /a tiled still is at most 256 megapixels/],
    ['--time negative', render('--time', '-1'), /--time -1: expected a number of at least 0/],
    ['--time not a number', render('--time', 'noon'), /--time noon: expected a number/],
    ['--frame negative', render('--frame', '-3'), /--frame -3: expected a whole number of at least 0/],
    ['--frame a fraction', render('--frame', '2.5'), /--frame 2.5: expected a whole number/],
    ['--time and --frame', render('--time', '1', '--frame', '2'), /--time and --frame: give one/],
    ['--mouse of three', render('--mouse', '1,2,3'), /--mouse 1,2,3: expected x,y or x,y,z,w/],
    ['--mouse negative, of three', render('--mouse', '-5,10,-1'), /--mouse -5,10,-1: expected x,y or x,y,z,w/],
    ['--set without =', render('--set', 'CONE'), /--set CONE: expected NAME=VALUE/],
    ['--date not a date', render('--date', 'yesterday'), /--date yesterday: expected an ISO 8601 date/],
    ['--fps zero', render('--fps', '0'), /--fps 0: expected a number from 1 to 240/],
    ['--converge zero', render('--converge', '0'), /--converge 0: expected a whole number of at least 1/],
    ['--tile odd', render('--tile', '255'), /--tile 255: the tile size must be even/],
    ['--watchdog negative', render('--watchdog', '-2'), /--watchdog -2: expected a number of at least 0.1/],
    ['-o of another kind', ['render', '<shader>', '-o', 'x.jpg'], /-o x\.jpg: a render is a \.png file/],
    ['no -o', ['render', '<shader>'], /render: -o OUT\.png is required/],
    ['two shaders', ['render', '<shader>', '<shader>', '-o', 'x.png'], /expected one SHADER file/],
    ['record: --frames past the recorder', ['record', '<shader>', '-o', 'x.zip', '--frames', '40000'], /--frames 40000: .*from 1 to 36000/],
    ['record: --fps past the recorder', ['record', '<shader>', '-o', 'x.zip', '--fps', '500'], /--fps 500: .*from 1 to 120/],
    ['record: -o of another kind', ['record', '<shader>', '-o', 'x.gif'], /-o x\.gif: a recording is a \.webm video or a \.zip/],
    ['test: --shard', ['test', '<folder>', '--shard', '3/2'], /--shard 3\/2: expected i\/n/],
    ['test: --date', ['test', '<folder>', '--date', 'soon'], /--date soon: expected an ISO 8601 date/],
    ['open: --port', ['open', '<shader>', '--port', 'x'], /--port x/],
  ];
  test.each(CASES)('%s', async (_, argv, said) => {
    const args = argv.map((a) => (a === '<shader>' ? shader : a === '<folder>' ? folder : a));
    const { code, err } = await shaderproof(args);
    const lines = err.filter(Boolean);
    expect(code, lines.join('\n')).toBe(2);
    expect(lines.length, lines.join('\n')).toBe(1);
    expect(lines[0]).toMatch(new RegExp(`^shaderproof ${args[0]}: `));
    expect(lines[0]).toMatch(said);
    expect(lines[0]).toMatch(/--help lists the flags\)$/);
    expect(lines[0]).not.toMatch(FOREIGN);
  });
});

describe('a file that cannot be a shader: one line in our words, exit 1, before any browser', () => {
  /** @type {Array<[string, string, RegExp]>} */
  const CASES = [
    ['a folder', 'somedir', /somedir: a folder, not a shader file \(shaderproof test DIR runs every shader in a folder\)$/],
    ['no such file', 'missing.glsl', /missing\.glsl: no such file$/],
    ['not GLSL', 'notes.txt', /notes\.txt: not a shader: no mainImage\(\)/],
    ['not JSON', 'broken.json', /broken\.json: not a shader: not valid JSON/],
  ];
  test.each(CASES)('%s', async (_, name, said) => {
    if (name === 'notes.txt') fs.writeFileSync(path.join(folder, name), 'shopping list\n');
    if (name === 'broken.json') fs.writeFileSync(path.join(folder, name), '{"Shader": ');
    const { code, err } = await shaderproof(['render', path.join(folder, name), '-o', path.join(folder, 'x.png')]);
    expect(code).toBe(1);
    expect(err.filter(Boolean).length, err.join('\n')).toBe(1);
    expect(err[0]).toMatch(said);
    expect(err[0]).not.toMatch(FOREIGN);
  });
});

test('long work shows its progress on a terminal, in place, and nothing in a log', () => {
  const written = [];
  const saved = { isTerminal: io.isTerminal, write: process.stderr.write };
  process.stderr.write = /** @type {any} */ ((chunk) => written.push(String(chunk)) > 0);
  try {
    for (const terminal of [true, false]) {
      io.isTerminal = () => terminal;
      written.length = 0;
      const bar = progressBar('samples');
      bar.update(0, 4096);
      bar.update(2048, 4096);
      bar.update(2048, 4096); // the same line is not written again
      bar.end();
      if (terminal)
        expect(written).toEqual([`\r[${'.'.repeat(30)}] 0/4096 samples`, `\r[${'#'.repeat(15)}${'.'.repeat(15)}] 2048/4096 samples`, '\n']);
      else expect(written).toEqual([]);
    }
  } finally {
    io.isTerminal = saved.isTerminal;
    process.stderr.write = saved.write;
  }
});
