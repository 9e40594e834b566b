// The command line's words for every flag and value it cannot use (issue 36, item 7), in-process:
// each is refused before any browser starts, in one line of the project's words that names the
// flag and says what to do, with exit 2 (src/cli/main.js, arguments.js, view-options.js). None
// may be another tool's message (node:util parseArgs's "Option '--x' argument is ambiguous",
// Node's "EISDIR: illegal operation").

import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import { main } from '../../src/cli/main.js';
import { io, progressBar, sayNotes } from '../../src/api/io.js';
import { sayOnce } from '../../src/shared/said-once.js';
import { commandLineWords, mediaFolders } from '../../src/api/media.js';
import { DEFAULT_SIZE as TEST_SIZE } from '../../src/runner/manifest.js';
import { MEDIA_WORDS } from '../../src/shadertoy/media.js';
import { jsonSyntaxError } from '../../src/shared/json-syntax.js';
import { chooseRenderer } from '../../src/headless/renderers.js';
import { referenceRenderer } from '../../src/runner/drawn-by.js';
import { REPO_ROOT } from '../support/config.js';

let folder = '';
let shader = '';
beforeAll(() => {
  folder = fs.mkdtempSync(path.join(os.tmpdir(), 'shaderproof-usage-'));
  shader = path.join(folder, 'a.glsl');
  fs.writeFileSync(shader, 'void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n');
  fs.mkdirSync(path.join(folder, 'somedir'));
  // two test folders: one with a manifest, one with references
  fs.mkdirSync(path.join(folder, 'one'));
  fs.writeFileSync(path.join(folder, 'one', 'shaderproof.json'), '{}');
  fs.mkdirSync(path.join(folder, 'two', '__references__'), { recursive: true });
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
    ['no -o', ['render', '<shader>'], /-o is required: the file to write, OUT\.png, OUT\.pfm or OUT\.wav/],
    ['record: no -o', ['record', '<shader>'], /-o OUT\.webm or -o OUT\.zip is required/],
    ['record: --time', ['record', '<shader>', '-o', 'x.zip', '--time', '1'], /--time and --frame are a render's/],
    [
      'test: two test folders',
      ['test', '<one>', '<two>'],
      /one and \S+two are cases of two test folders \(.*\): run shaderproof test once for each/,
    ],
    ['test: no DIR', ['test'], /expected a DIR, or cases of one \(shader files, sub-folders, view names\), got none/],
    ['test: --grep not a pattern', ['test', '<folder>', '-g', 'a('], /--grep a\(: not a regular expression/],
    [
      'test: --grep-invert not a pattern',
      ['test', '<folder>', '--grep-invert', '[z-a]'],
      /--grep-invert \[z-a\]: not a regular expression/,
    ],
    ['test: --watch --update', ['test', '<folder>', '--watch', '--update'], /--watch and --update: give one/],
    [
      '--channel0 a shader',
      render('--channel0', '<shader>'),
      /--channel0 \S+a\.glsl: a shader, not a channel's input; give an image, video or music file/,
    ],
    ['--channel1 a folder', render('--channel1', '<folder>'), /--channel1 \S+: a folder; give an image/],
    ['two shaders', ['render', '<shader>', '<shader>', '-o', 'x.png'], /expected one SHADER file/],
    ['record: --frames past the recorder', ['record', '<shader>', '-o', 'x.zip', '--frames', '40000'], /--frames 40000: .*from 1 to 36000/],
    ['record: --fps past the recorder', ['record', '<shader>', '-o', 'x.zip', '--fps', '500'], /--fps 500: .*from 1 to 120/],
    ['record: -o of another kind', ['record', '<shader>', '-o', 'x.gif'], /-o x\.gif: a recording is a \.webm video or a \.zip/],
    ['test: --shard', ['test', '<folder>', '--shard', '3/2'], /--shard 3\/2: expected i\/n/],
    ['test: --date', ['test', '<folder>', '--date', 'soon'], /--date soon: expected an ISO 8601 date/],
    ['open: --port', ['open', '<shader>', '--port', 'x'], /--port x/],
  ];
  test.each(CASES)('%s', async (_, argv, said) => {
    const places = { '<shader>': shader, '<folder>': folder, '<one>': path.join(folder, 'one'), '<two>': path.join(folder, 'two') };
    const args = argv.map((a) => places[a] ?? a);
    const { code, err } = await shaderproof(args);
    const lines = err.filter(Boolean);
    expect(code, lines.join('\n')).toBe(2);
    expect(lines.length, lines.join('\n')).toBe(1);
    expect(lines[0]).toMatch(new RegExp(`^shaderproof ${args[0]}: `));
    expect(lines[0], 'the verb said twice').not.toMatch(new RegExp(`^shaderproof ${args[0]}: ${args[0]}:`));
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
    [
      'not JSON',
      'broken.json',
      /broken\.json: not a shader: a Shadertoy export is JSON, and this is not \(line 1, column 12: the text ends where a value belongs\)$/,
    ],
    // the parser's own message quotes the text around the fault, line breaks and all
    ['not JSON, over lines', 'lines.json', /lines\.json: not a shader: .*\(line 4, column 3: "\]" where a value belongs\)$/],
  ];
  test.each(CASES)('%s', async (_, name, said) => {
    if (name === 'notes.txt') fs.writeFileSync(path.join(folder, name), 'shopping list\n');
    if (name === 'broken.json') fs.writeFileSync(path.join(folder, name), '{"Shader": ');
    if (name === 'lines.json') fs.writeFileSync(path.join(folder, name), '{\n "Shader": {\n  "renderpass": [1,\n  ]\n }\n}\n');
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

// Issue 45, item 6: what a new user read, each now one line in the project's words. The page's
// note lines are written here as the page writes them (src/player/inputs/media-library.js, with
// the words it shares with the command line: MEDIA_WORDS); cli-runs.test.js reads the same lines
// from a real run.
describe('one line in our words (issue 45, item 6)', () => {
  const TEXTURE = "the site's texture /media/a/0a40.png";
  /** A "went without" line as the page writes it. @param {string} pass @param {number} channel @param {string} why */
  const pageLine = (pass, channel, why) => `${pass}, iChannel${channel}: ${why}; the channel is black`;
  const noFolder = (pass) => pageLine(pass, 0, `${TEXTURE} ${MEDIA_WORDS.noFolder}`);
  /** @returns {import('../../src/headless/view.js').PageNote} */
  const missingNote = (/** @type {string[]} */ lines) => ({
    kind: 'missing',
    title: 'wave.json runs without some of what it asks for',
    lines,
  });

  /** Runs sayNotes with io captured: the lines it writes, or the error it throws. */
  function said(notes, options) {
    const err = [];
    const saved = io.err;
    io.err = (line) => err.push(line) > 0;
    try {
      sayNotes('wave.json', notes, options);
      return { err, error: null };
    } catch (error) {
      return { err, error: error.message };
    } finally {
      io.err = saved;
    }
  }

  test('a note names the file once, and the same input missing in three passes is one line naming them', () => {
    const lines = ['Buffer A', 'Buffer B', 'Image'].map((pass) => commandLineWords(noFolder(pass), { dir: null, fetch: false }));
    const { err } = said([
      missingNote(lines),
      { kind: 'values', title: 'Some values were not used as given', lines: ['SPEED: 9 is past its largest, 4'] },
    ]);
    expect(err).toEqual([
      `warning: wave.json: Buffer A, Buffer B and Image, iChannel0: ${TEXTURE} needs the site's media: give --media DIR (a folder laid out as the site's paths) or --fetch-media; all 3 channels are black`,
      'warning: wave.json: Some values were not used as given: SPEED: 9 is past its largest, 4',
    ]);
    expect(err.join('\n')).not.toMatch(/wave\.json: wave\.json|\?media=|the page's/);
  });

  test('--strict says that nothing was written, and not what would have been drawn instead', () => {
    const lines = [noFolder('Image'), pageLine('Buffer A', 2, 'a video input is not available here')];
    const { err, error } = said([missingNote(lines.map((l) => commandLineWords(l, undefined)))], { strict: true });
    expect(err).toEqual([]);
    expect(error).toBe(
      `wave.json: --strict: nothing written, as it goes without 2 of what it asks for, the first: Image, iChannel0: ${TEXTURE} needs the site's media: give --media DIR (a folder laid out as the site's paths) or --fetch-media`,
    );
    expect(error).not.toMatch(/black/);
  });

  test('a file --fetch-media could not download is said to be that, not to be missing from a folder never given', async () => {
    const shader = path.join(folder, 'fetching.json');
    const input = { id: 'x', channel: 0, type: 'texture', filepath: '/media/a/0a40.png', sampler: {} };
    const image = {
      type: 'image',
      name: 'Image',
      code: 'void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }',
      inputs: [input],
      outputs: [],
    };
    fs.writeFileSync(shader, JSON.stringify({ Shader: { info: { name: 'f' }, renderpass: [image] } }));
    const env = { origin: process.env.SHADERPROOF_MEDIA_ORIGIN, cache: process.env.SHADERPROOF_MEDIA_CACHE };
    process.env.SHADERPROOF_MEDIA_ORIGIN = 'http://127.0.0.1:9'; // a port fetch refuses at once: no request leaves
    process.env.SHADERPROOF_MEDIA_CACHE = path.join(folder, 'cache');
    const warnings = [];
    try {
      await mediaFolders(shader, { dir: null, fetch: true }, (line) => warnings.push(line));
    } finally {
      for (const [key, value] of [
        ['SHADERPROOF_MEDIA_ORIGIN', env.origin],
        ['SHADERPROOF_MEDIA_CACHE', env.cache],
      ])
        if (value === undefined) delete process.env[key];
        else process.env[key] = value;
    }
    expect(warnings).toEqual([
      expect.stringMatching(/^warning: media: \/media\/a\/0a40\.png could not be downloaded from http:\/\/127\.0\.0\.1:9: /),
    ]);
    const line = pageLine('Image', 0, `${TEXTURE}: a/0a40.png ${MEDIA_WORDS.notInFolder}`);
    expect(commandLineWords(line, { dir: null, fetch: true })).toBe(
      `Image, iChannel0: ${TEXTURE}: a/0a40.png could not be downloaded (the warning above says why); the channel is black`,
    );
    // and a file a given folder lacks is said to be missing from that folder, by its flag
    expect(commandLineWords(line.replaceAll('0a40', 'b1c2'), { dir: '/m', fetch: false })).toMatch(
      /a\/b1c2\.png is not in --media \/m \(--fetch-media downloads what it lacks\)/,
    );
  });

  test.each([
    [['Image, iChannel0: A'], ['Image, iChannel0: A']],
    [
      ['Image, iChannel0: A', 'Buffer A, iChannel0: A', 'Image, iChannel1: B'],
      ['Image and Buffer A, iChannel0: A', 'Image, iChannel1: B'],
    ],
    [['Image, iChannel0: A', 'Sound, iChannel2: A'], ["Image's iChannel0 and Sound's iChannel2: A"]],
    [['Image, iChannel0: A', 'Image, iChannel1: A'], ['Image, iChannel0 and iChannel1: A']],
    [
      ['Sound: no audio here', 'Sound: no audio here', 'Image, iChannel0: A'],
      ['Sound: no audio here', 'Image, iChannel0: A'],
    ],
  ])('merged: %j', (lines, merged) => {
    expect(sayOnce(lines)).toEqual(merged);
  });

  test('--channel0 of a file that is not there names the flag, before any browser', async () => {
    const { code, err } = await shaderproof([
      'render',
      shader,
      '-o',
      path.join(folder, 'x.png'),
      '--channel0',
      path.join(folder, 'nope.png'),
    ]);
    expect(code).toBe(1);
    expect(err.filter(Boolean)).toEqual([`shaderproof render: --channel0 ${path.join(folder, 'nope.png')}: no such file`]);
  });

  test("test's default size is in its --help and in the README", async () => {
    const size = `${TEST_SIZE.width}x${TEST_SIZE.height}`;
    const { code, out } = await shaderproof(['test', '--help']);
    expect(code).toBe(0);
    expect(out.join('\n')).toContain(`drawn at ${size} and iTime 0`);
    expect(fs.readFileSync(path.join(REPO_ROOT, 'README.md'), 'utf8')).toMatch(new RegExp(`\\| \`test DIR\` \\| [^|]*drawn at ${size}`));
  });

  test("--help opens with what draws by default, as the verbs choose it: llvmpipe where Mesa is, test its references' renderer", async () => {
    // the rule its words say (headless/renderers.js chooseRenderer, runner/drawn-by.js)
    const mesa = { vendorFile: '', egl: '', driver: '' };
    expect(chooseRenderer({}, 'auto', () => ({ ...mesa, missing: [] }))).toBe('llvmpipe');
    expect(chooseRenderer({}, 'auto', () => ({ ...mesa, missing: ['libEGL_mesa.so.0'] }))).toBe('swiftshader');
    const drawnBy = {
      renderer: /** @type {const} */ ('llvmpipe'),
      webgl: '',
      chromium: '',
      mesa: null,
      cpu: '',
      cpuFeatures: [],
      platform: '',
    };
    expect(referenceRenderer(drawnBy, true)).toBe('llvmpipe');
    expect(referenceRenderer(null, true)).toBe('swiftshader');
    const { code, out } = await shaderproof(['--help']);
    expect(code).toBe(0);
    const opening = out.slice(0, out.indexOf('')).join(' ');
    expect(opening).toMatch(/llvmpipe draws where Mesa is installed, else SwiftShader/);
    expect(opening).toMatch(/test draws with the renderer its references were drawn with/);
    const test = (await shaderproof(['test', '--help'])).out.join(' ');
    expect(test).toMatch(/else the renderer that drew the references \(--update records it in DIR\/__references__\/drawn-by\.json;/);
    expect(test).toMatch(/references written before that record are SwiftShader's/);
  });
});

/** [a text that is not JSON, where it stops being JSON] */
const NOT_JSON = [
  ['{"a": 1,}', 'line 1, column 9: "}" where a property name in double quotes belongs'],
  ['{"a" 1}', 'line 1, column 6: "1}" where \':\' belongs'],
  ['[1, 2', "line 1, column 6: the text ends where ',' or ']' belongs"],
  ['{"a": "x\ny"}', 'line 1, column 9: a line break or a control character inside a string (write it as \\n)'],
  ['{"a": "\\q"}', 'line 1, column 9: "q\\"}" where an escape (\\n, \\", \\u0041, …) belongs'],
  ['{"a": 1} x', 'line 1, column 10: "x" after the end of the JSON value'],
  ["{'a': 1}", 'line 1, column 2: "\'a\': 1}" where a property name in double quotes belongs'],
  ['{\n  "a": [\n    01\n  ]\n}', "line 3, column 6: \"1\" where ',' or ']' belongs"],
  ['', 'line 1, column 1: the text ends where a value belongs'],
];
test.each(NOT_JSON)('JSON broken where JSON.parse breaks: %j', (text, where) => {
  expect(() => JSON.parse(text)).toThrow();
  expect(jsonSyntaxError(text)).toBe(where);
});
test.each(['{}', '[]', '{"a": [1, -2.5e3, true, false, null, "\\u00e9\\n"], "b": {"c": ""}}', ' 7 ', '"x"'])('JSON: %j', (text) => {
  expect(() => JSON.parse(text)).not.toThrow();
  expect(jsonSyntaxError(text)).toBe(null);
});
