// A compile error names the tab it is in and the user's own line in that tab, whatever tabs the
// shader has (issue 45, item 2): a JSON with only Sound and Image tabs said "x.json:3" with a line
// of the Sound tab, or threw "Cannot read properties of undefined". Every combination of Common,
// Buffers A–D, Cube A and Sound beside Image is composed as the render worker composes it, given
// a compiler log that points at the broken line, and read back through the worker's own mapping
// (pass-errors.js: passCheck, passMessages, formatCompileMessages, which the command line's
// report and the page's note are both made of). Then a few of them compile on SwiftShader in the
// page, whose report and note are read, and one goes through the command line.

import { execFile } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { promisify } from 'node:util';
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import { composePassShader, hostControlBlock } from '../../src/shadertoy/header.js';
import { channelTypes } from '../../src/shadertoy/multipass.js';
import { fromShadertoyJson } from '../../src/shadertoy/multipass-json.js';
import { formatCompileMessages, passCheck, passMessages } from '../../src/shadertoy/pass-errors.js';
import { userLineOffset } from '../../src/shadertoy/shader-errors.js';
import { composeSoundShader } from '../../src/shadertoy/sound.js';
import { builtPage } from '../../src/headless/page-server.js';
import { REPO_ROOT } from '../support/config.js';
import { sharePageAcrossTests, withPage } from '../support/page-helpers.js';
import { hook } from '../support/hook.js';

sharePageAcrossTests();

/** Each tab's entry point, on its line 1; every tab has a length of its own (a line number that lands in the wrong tab shows). */
const TABS = /** @type {const} */ ({
  Common: { type: 'common', id: null, lines: 4, entry: 'float common_half(float x) { return 0.5 * x; }' },
  'Buffer A': { type: 'buffer', id: '4dXGR8', lines: 5, entry: 'void mainImage(out vec4 c, in vec2 f) { c = vec4(0.1); }' },
  'Buffer B': { type: 'buffer', id: 'XsXGR8', lines: 6, entry: 'void mainImage(out vec4 c, in vec2 f) { c = vec4(0.2); }' },
  'Buffer C': { type: 'buffer', id: '4sXGR8', lines: 7, entry: 'void mainImage(out vec4 c, in vec2 f) { c = vec4(0.3); }' },
  'Buffer D': { type: 'buffer', id: 'XdfGR8', lines: 8, entry: 'void mainImage(out vec4 c, in vec2 f) { c = vec4(0.4); }' },
  'Cube A': {
    type: 'cubemap',
    id: '4dX3Rr',
    lines: 9,
    entry: 'void mainCubemap(out vec4 c, in vec2 f, in vec3 o, in vec3 d) { c = vec4(d, 1.0); }',
  },
  Image: { type: 'image', id: '4dfGRr', lines: 10, entry: 'void mainImage(out vec4 c, in vec2 f) { c = vec4(0.5); }' },
  // shorter than the Image tab: a line of Image's read in it was past its end
  Sound: { type: 'sound', id: '4dfGRn', lines: 3, entry: 'vec2 mainSound(int s, float t) { return vec2(0.0); }' },
});
/** @typedef {keyof typeof TABS} TabName */

const BAD = 'float broken_here() { return undefinedThing; }';

/**
 * A tab's text: its entry point on line 1, comments after, and BAD on line `bad` (none: 0).
 * @param {TabName} tab
 * @param {number} bad
 */
function tabText(tab, bad) {
  const { lines, entry } = TABS[tab];
  return Array.from({ length: lines }, (_, i) => (i === 0 ? entry : i + 1 === bad ? BAD : `// ${tab}, line ${i + 1}`)).join('\n');
}

/**
 * The site's export of a shader with these tabs (Image always), the Sound tab listed first, the
 * rest after Image in reverse: the order of a file's list must not matter.
 * @param {TabName[]} tabs
 * @param {TabName} badTab
 * @param {number} badLine
 */
function exportOf(tabs, badTab, badLine) {
  const order = /** @type {TabName[]} */ (['Sound', 'Image', ...tabs.filter((t) => t !== 'Sound' && t !== 'Image').reverse()]);
  const renderpass = order
    .filter((tab) => tab === 'Image' || tabs.includes(tab))
    .map((tab) => ({
      inputs: [],
      outputs: TABS[tab].id ? [{ id: TABS[tab].id, channel: 0 }] : [],
      code: tabText(tab, tab === badTab ? badLine : 0),
      name: tab,
      description: '',
      type: TABS[tab].type,
    }));
  return { Shader: { ver: '0.1', info: { id: 'tst045', name: 'errors', description: 'written for the tests' }, renderpass } };
}

/** Every combination of the optional tabs (Image is always there). */
const OPTIONAL = /** @type {TabName[]} */ (['Common', 'Buffer A', 'Buffer B', 'Buffer C', 'Buffer D', 'Cube A', 'Sound']);
const COMBINATIONS = Array.from({ length: 2 ** OPTIONAL.length }, (_, bits) => [
  ...OPTIONAL.filter((_, i) => bits & (1 << i)),
  /** @type {TabName} */ ('Image'),
]);

/**
 * The report of the pass the broken line is compiled in, as the render worker makes it: the pass
 * composed (composePassShader, or composeSoundShader for the Sound tab; a Common error is the
 * Image pass's), a driver log pointing at the line of the composed code that holds BAD, mapped
 * back and formatted.
 * @param {import('../../src/shadertoy/multipass.js').MultipassShader} model
 * @param {TabName} badTab
 */
function workerReport(model, badTab) {
  const pass = model.passes.find((p) => p.name === (badTab === 'Common' ? 'Image' : badTab));
  if (!pass) throw new Error(`no pass ${badTab}`);
  const composed =
    pass.kind === 'sound'
      ? composeSoundShader(pass.code, { common: model.common, channelTypes: channelTypes(pass) })
      : composePassShader(pass.code, {
          common: model.common,
          hostBlock: hostControlBlock([]),
          kind: /** @type {'image' | 'buffer' | 'cubemap'} */ (pass.kind),
          name: pass.name,
          channelTypes: channelTypes(pass),
        });
  const logLine = composed.code.split('\n').indexOf(BAD) + 1;
  const log = `ERROR: 0:${logLine}: 'undefinedThing' : undeclared identifier\nERROR: 1 compilation errors.  No code generated.\n\0`;
  const check = passCheck(model, pass, composed);
  const offset = userLineOffset(composed.code, composed.code, composed.firstSourceLine, check.userText);
  return formatCompileMessages(passMessages(log, offset, check), model, 'errors.json');
}

/**
 * What the report says first: the tab (or, for a shader of one tab, the file) and the line.
 * @param {TabName[]} tabs
 * @param {TabName} badTab
 * @param {number} line
 */
const expectedReport = (tabs, badTab, line) =>
  `${tabs.length > 1 ? badTab : 'errors.json'}:${line}: error: 'undefinedThing' : undeclared identifier\n    ${BAD}`;

describe('every combination of tabs: the tab and the line in it', () => {
  const cases = COMBINATIONS.flatMap((tabs) => tabs.flatMap((tab) => [3, TABS[tab].lines].map((line) => ({ tabs, tab, line }))));
  test(`${cases.length} broken lines in ${COMBINATIONS.length} shaders`, () => {
    const wrong = [];
    for (const { tabs, tab, line } of cases) {
      const { model } = fromShadertoyJson(exportOf(tabs, tab, line));
      let report;
      try {
        report = workerReport(model, tab);
      } catch (error) {
        report = `threw ${error.message}`;
      }
      const expected = expectedReport(tabs, tab, line);
      if (report !== expected) wrong.push(`[${tabs.join(', ')}] ${tab}:${line}\n  said:     ${report}\n  expected: ${expected}`);
    }
    expect(wrong.join('\n')).toBe('');
  });
});

// Compiled for real: what failed in issue 45 and a shader with every kind of pass.
/** @type {Array<[string, TabName[], TabName, number]>} */
const COMPILED = [
  ['Sound and Image, Image line 3', ['Sound', 'Image'], 'Image', 3],
  ["Sound and Image, Image's last line", ['Sound', 'Image'], 'Image', TABS.Image.lines],
  ["Sound and Image, the Sound tab's line 2", ['Sound', 'Image'], 'Sound', 2],
  ['every kind of pass, Cube A', ['Common', 'Buffer A', 'Cube A', 'Sound', 'Image'], 'Cube A', 4],
  ['every kind of pass, Common', ['Common', 'Buffer A', 'Cube A', 'Sound', 'Image'], 'Common', 3],
  ['Image alone in a JSON: the file and its line', ['Image'], 'Image', 6],
];

describe('compiled on SwiftShader: the report and the page’s note', () => {
  test.each(COMPILED)('%s', async (_, tabs, tab, line) => {
    await withPage(async ({ page, goto }) => {
      await goto('?size=16x8&time=0');
      const outcome = await hook(page).setProject(exportOf(tabs, tab, line));
      const first = `${tabs.length > 1 ? tab : '[^:]+'}:${line}: error: .*undefinedThing.*`;
      expect(outcome.ok).toBe(false);
      expect(outcome.error).toMatch(new RegExp(`^${first}\\n    ${escape(BAD)}$`, 'm'));
      const note = await page.$$eval('#overlay .error-line', (els) => els.map((e) => e.textContent ?? ''));
      expect(note.join('\n')).toMatch(new RegExp(`^${first}`, 'm'));
      expect(note.join('\n')).not.toMatch(/Cannot read|undefined \(reading/);
    });
  });
});

/** A string as a regular expression that matches it. @param {string} text */
const escape = (text) => text.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');

describe('the command line', () => {
  let folder = '';
  beforeAll(async () => {
    folder = fs.mkdtempSync(path.join(os.tmpdir(), 'shaderproof-errors-'));
    await builtPage();
  });
  afterAll(() => fs.rmSync(folder, { recursive: true, force: true }));

  test("a JSON with Sound and Image tabs, broken on Image's last line: the tab, the line, the line's text", async () => {
    const file = path.join(folder, 'wave.json');
    fs.writeFileSync(file, JSON.stringify(exportOf(['Sound', 'Image'], 'Image', TABS.Image.lines)));
    const result = await promisify(execFile)(
      process.execPath,
      [path.join(REPO_ROOT, 'bin/shaderproof.js'), 'render', file, '-o', 'x.png'],
      {
        cwd: folder,
        timeout: 100_000,
      },
    ).catch((error) => error);
    expect(result.code, result.stderr).toBe(1);
    expect(result.stderr).toMatch(new RegExp(`Image:${TABS.Image.lines}: error: .*undefinedThing.*\\n    ${escape(BAD)}`));
    expect(result.stderr).not.toMatch(/Cannot read|internal error/);
    expect(fs.existsSync(path.join(folder, 'x.png'))).toBe(false);
  });
});

// A global with a non-constant initializer (issue 45, item 5) is an error of GLSL ES 3.00 that
// the browser's compiler (ANGLE, the site's as well: it compiles every pass as #version 300 es)
// reports; the page says what it means, that Shadertoy rejects it too, and what to write
// instead. A built-in function of constants is a constant expression: it compiles and draws.
describe('a global initialized with a value that is not constant', () => {
  /** @type {Array<[string, string, string, number | null]>} [what, the globals, the colour's red, its byte (null: refused)] */
  const CASES = [
    ['a uniform', 'vec2 p = iResolution.xy;', 'p.x / 32.0', null],
    ['a uniform in an expression', 'float t0 = iTime * 2.0 + 1.0;', 't0', null],
    ['another global', 'float a = 0.5;\nfloat b = a * 2.0;', 'b', null],
    ["a function of the shader's", 'float f() { return 0.25; }\nfloat c = f();', 'c', null],
    ['a built-in function of constants', 'float g = sin(1.0);', 'g', Math.round(Math.sin(1) * 255)],
    ['a constant', 'const float k = 2.0;\nfloat m = k * 0.25;', 'm', Math.round(0.5 * 255)],
  ];
  test.each(CASES)('%s', async (_, globals, red, byte) => {
    const source = `${globals}\nvoid mainImage(out vec4 c, in vec2 f) {\n    c = vec4(${red}, 0.0, 0.0, 1.0);\n}\n`;
    await withPage(async ({ page, goto }) => {
      await goto('?size=16x8&time=0');
      const outcome = await hook(page).setSource(source);
      if (byte === null) {
        const line = globals.split('\n').length; // the initializer is on the globals' last line
        expect(outcome.ok).toBe(false);
        const [said, under] = String(outcome.error).split('\n');
        expect(said).toMatch(new RegExp(`:${line}: error: a global's initial value must be a constant expression in GLSL ES 3\\.00`));
        expect(said).toMatch(
          /Shadertoy rejects this shader as well: declare the global without a value and assign it at the start of mainImage/,
        );
        expect(under.trim()).toBe(globals.split('\n')[line - 1]);
        const note = await page.$$eval('#overlay .error-line', (els) => els.map((e) => e.textContent ?? ''));
        expect(note.join('\n')).toContain('Shadertoy rejects this shader as well');
      } else {
        expect(outcome).toEqual({ ok: true });
        const { data } = await hook(page).readPixels();
        expect(Buffer.from(data, 'base64')[0]).toBe(byte);
      }
    });
  });
});
