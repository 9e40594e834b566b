// Multipass Shadertoy shaders (issue 13), the renderer-independent half: the schedule
// (src/shadertoy/multipass.js), one pass composed in Shadertoy's header with its compile errors
// named by tab (header.js, pass-errors.js), and both run on SwiftShader through the raw WebGL2
// page (tests/support/multipass-runner.js). The JSON format: multipass-json.test.js; the keyboard
// texture: keyboard.test.js.
import { afterAll, describe, expect, test } from 'vitest';
import { TILE_OFFSET_UNIFORM, composeImageShader, composePassShader, countNewlines, locatePassLine } from '../../src/shadertoy/header.js';
import { buffersNeedingMipmaps, frameSchedule, renderOrder, singlePass } from '../../src/shadertoy/multipass.js';
import { formatPassMessages, parsePassShaderLog } from '../../src/shadertoy/pass-errors.js';
import { userLineOffset } from '../../src/shadertoy/shader-errors.js';
import { disconnect } from '../support/page.js';
import { composeModel, runPasses } from '../support/multipass-runner.js';

afterAll(disconnect);

const MAIN = 'void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n    fragColor = vec4(1.0);\n}\n';

describe('render order and frame lag', () => {
  const ch = (buffer) => ({ kind: 'buffer', buffer, sampler: { filter: 'nearest', wrap: 'clamp', vflip: false } });
  const pass = (name, buffer, channels) => ({
    name,
    kind: buffer ? 'buffer' : 'image',
    buffer,
    code: MAIN,
    channels: [...channels, null, null, null, null].slice(0, 4),
  });
  // Listed out of order on purpose: the order is A, B, C, D, Image whatever the list says.
  const model = {
    common: null,
    passes: [
      pass('Image', null, [ch('D'), ch('A')]),
      pass('Buffer D', 'D', [ch('C'), ch('D')]),
      pass('Buffer B', 'B', [ch('A'), ch('C'), ch('B')]),
      pass('Buffer A', 'A', [ch('A'), ch('B')]),
      pass('Buffer C', 'C', [ch('D')]),
    ],
  };
  test('passes paint A, B, C, D, then Image', () => {
    expect(renderOrder(/** @type {any} */ (model)).map((p) => p.name)).toEqual(['Buffer A', 'Buffer B', 'Buffer C', 'Buffer D', 'Image']);
  });
  test.each([
    ['Buffer A', 0, 'A', 'previous'], // itself
    ['Buffer A', 1, 'B', 'previous'], // a later buffer
    ['Buffer B', 0, 'A', 'current'], // an earlier buffer
    ['Buffer B', 1, 'C', 'previous'],
    ['Buffer B', 2, 'B', 'previous'],
    ['Buffer C', 0, 'D', 'previous'],
    ['Buffer D', 0, 'C', 'current'],
    ['Buffer D', 1, 'D', 'previous'],
    ['Image', 0, 'D', 'current'],
    ['Image', 1, 'A', 'current'],
  ])('%s iChannel%i reads Buffer %s of the %s frame', (name, channel, buffer, frame) => {
    const step = frameSchedule(/** @type {any} */ (model)).find((s) => s.pass.name === name);
    expect(step.bindings[channel]).toMatchObject({ source: 'buffer', buffer, frame, resolution: 'canvas', samplerType: '2D' });
    expect(step.target).toBe(name === 'Image' ? 'screen' : name.slice(-1));
  });
  test('buffers read with the mipmap filter get their mipmaps regenerated', () => {
    const m = structuredClone(model);
    m.passes[0].channels[1].sampler.filter = 'mipmap';
    expect([...buffersNeedingMipmaps(/** @type {any} */ (m))]).toEqual(['A']);
    expect(buffersNeedingMipmaps(/** @type {any} */ (model)).size).toBe(0);
  });
  test('empty channels are nothing, with zero resolution; the keyboard is 256 x 3', () => {
    const m = singlePass(MAIN);
    m.passes[0].channels[2] = { kind: 'keyboard', sampler: { filter: 'linear', wrap: 'repeat', vflip: true } };
    const [step] = frameSchedule(m);
    expect(step.bindings[0]).toMatchObject({ source: 'none', resolution: [0, 0, 0] });
    expect(step.bindings[2]).toMatchObject({ source: 'keyboard', resolution: [256, 3, 1], sampler: { filter: 'nearest', wrap: 'clamp' } });
  });
});

describe('one pass composed in Shadertoy’s header', () => {
  const common = 'float twice(float x) {\n    return 2.0 * x;\n}\n';
  test('with no Common it is the Image tab’s composition exactly', () => {
    expect(composePassShader(MAIN).code).toBe(composeImageShader(MAIN).code);
    expect(composePassShader(MAIN, { hostBlock: '#define X 1\n' }).code).toBe(
      composeImageShader(MAIN, { hostBlock: '#define X 1\n' }).code,
    );
  });
  test('Common comes after the host block, then a line break, then the tab; sections locate both', () => {
    const composed = composePassShader(MAIN, { common, hostBlock: '#define HOST_CONTROLS\n', kind: 'buffer', name: 'Buffer A' });
    const lines = composed.code.split('\n');
    expect(lines[composed.firstSourceLine - 1]).toBe('float twice(float x) {');
    expect(composed.sections).toEqual([
      { name: 'Common', firstLine: 1, lineCount: 4 },
      { name: 'Buffer A', firstLine: 5, lineCount: 4 },
    ]);
    expect(lines[composed.firstSourceLine - 1 + 5 - 1]).toBe('void mainImage(out vec4 fragColor, in vec2 fragCoord) {');
    expect(locatePassLine(composed.sections, 2)).toEqual({ name: 'Common', line: 2 });
    expect(locatePassLine(composed.sections, 6)).toEqual({ name: 'Buffer A', line: 2 });
    expect(locatePassLine(composed.sections, 9)).toBeNull();
    // A buffer keeps its alpha; the Image forces it to 1.
    expect(composed.code).toContain('shadertoy_out_color = color;');
    expect(composePassShader(MAIN, { common }).code).toContain('shadertoy_out_color = vec4(color.xyz, 1.0);');
  });
  test("a tile (the command line's --tile) differs from Shadertoy's only by the host's offset uniform and its use in main", () => {
    const plain = composePassShader(MAIN, { hostBlock: '#define X 1\n' });
    const tiled = composePassShader(MAIN, { hostBlock: '#define X 1\n', tiled: true });
    const expected = plain.code
      .replace('void main(void) {', `uniform vec2 ${TILE_OFFSET_UNIFORM};\nvoid main(void) {`)
      .replace('mainImage(color, gl_FragCoord.xy);', `mainImage(color, gl_FragCoord.xy + ${TILE_OFFSET_UNIFORM});`);
    expect(tiled.code).toBe(expected);
    expect(tiled.firstSourceLine).toBe(plain.firstSourceLine + 1);
    expect(() => composePassShader(MAIN, { kind: 'buffer', tiled: true })).toThrow(/only the Image pass/);
  });
  test('channel types: samplerCube and sampler3D where the channels need them, same line count', () => {
    const composed = composePassShader(MAIN, { channelTypes: ['2D', 'Cube', '3D', '2D'] });
    expect(composed.code).toContain('uniform samplerCube iChannel1;');
    expect(composed.code).toContain('uniform sampler3D iChannel2;');
    expect(countNewlines(composed.code)).toBe(countNewlines(composeImageShader(MAIN).code));
  });
  test('log lines map to Common or the pass, with the line in that tab', () => {
    const composed = composePassShader(MAIN, { common, name: 'Image' });
    const offset = composed.firstSourceLine - 1; // the GPU compiled exactly this code
    const at = (rel) => rel + offset;
    const log = `ERROR: 0:${at(2)}: 'x' : undeclared identifier\nERROR: 0:${at(6)}: 'y' : syntax error\nERROR: 0:2: 'z' : in the header\nERROR: 3 compilation errors.`;
    const messages = parsePassShaderLog(log, offset, composed.sections);
    expect(messages).toEqual([
      { severity: 'error', pass: 'Common', line: 2, message: "'x' : undeclared identifier" },
      { severity: 'error', pass: 'Image', line: 2, message: "'y' : syntax error" },
      { severity: 'error', pass: null, line: null, message: "'z' : in the header" },
    ]);
    expect(formatPassMessages(messages, { Common: common, Image: MAIN })).toBe(
      "Common:2: error: 'x' : undeclared identifier\n    return 2.0 * x;\nImage:2: error: 'y' : syntax error\n    fragColor = vec4(1.0);\nerror: 'z' : in the header",
    );
  });
});

describe('multipass on SwiftShader (raw WebGL2, the schedule followed literally)', () => {
  const fetch = (channel) => `texelFetch(iChannel${channel}, ivec2(fragCoord), 0)`;
  const model = (passes, common = null) => ({
    common,
    passes: passes.map(([name, buffer, code, reads]) => ({
      name,
      kind: buffer ? 'buffer' : 'image',
      buffer,
      code: `void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n    ${code}\n}\n`,
      channels: [0, 1, 2, 3].map((i) =>
        reads[i] ? { kind: 'buffer', buffer: reads[i], sampler: { filter: 'nearest', wrap: 'clamp', vflip: false } } : null,
      ),
    })),
  });
  const first = async (m, frames) => {
    const result = await runPasses(composeModel(/** @type {any} */ (m)), {
      width: 4,
      height: 2,
      frames: Array.from({ length: frames }, (_, i) => ({ capture: i === frames - 1 })),
    });
    expect(result.error, `${result.error}\n${result.log ?? ''}`).toBeUndefined();
    return result.captures[0];
  };

  test('self-feedback: a counter in Buffer A increments every frame; Buffer B reads this frame’s A, A reads last frame’s B', async () => {
    const m = model([
      ['Buffer A', 'A', `fragColor = vec4(${fetch(0)}.x + 1.0, ${fetch(1)}.x, 0.0, 0.25);`, ['A', 'B']],
      ['Buffer B', 'B', `fragColor = vec4(${fetch(0)}.x, 0.0, 0.0, 1.0);`, ['A']],
      ['Image', null, `fragColor = vec4(${fetch(0)}.xy / 8.0, 0.0, 0.0);`, ['A']],
    ]);
    const capture = await first(m, 5);
    // After 5 frames: A counted 5; B copied this frame's A (5); A's .y is B of the frame before (4).
    expect(capture.buffers.A.slice(0, 4)).toEqual([5, 4, 0, 0.25]);
    expect(capture.buffers.B.slice(0, 4)).toEqual([5, 0, 0, 1]);
    // The buffer kept its alpha (0.25); the Image's alpha is forced to 1.
    const screen = Buffer.from(capture.screen, 'base64');
    expect([...screen.subarray(0, 4)]).toEqual([Math.round((5 / 8) * 255), Math.round((4 / 8) * 255), 0, 255]);
  });

  test('a Common function is used by two passes', async () => {
    const m = model(
      [
        ['Buffer A', 'A', 'fragColor = vec4(twice(3.0));', []],
        ['Image', null, `fragColor = vec4(twice(${fetch(0)}.x) / 16.0);`, ['A']],
      ],
      'float twice(float x) { return 2.0 * x; }',
    );
    const capture = await first(m, 1);
    expect(capture.buffers.A.slice(0, 4)).toEqual([6, 6, 6, 6]);
    expect([...Buffer.from(capture.screen, 'base64').subarray(0, 4)]).toEqual([191, 191, 191, 255]);
  });

  test('a compile error in Common and one in a pass name their tab and line', async () => {
    const m = model(
      [['Image', null, 'fragColor = vec4(undefinedThing);', []]],
      'float ok(float x) { return x; }\nfloat broken() { return missing; }\n',
    );
    const [pass] = composeModel(/** @type {any} */ (m));
    const result = await runPasses([pass], { width: 2, height: 2, frames: [{}] });
    expect(result.error).toMatch(/Image failed to compile/);
    const offset = userLineOffset(pass.code, pass.code, pass.composed.firstSourceLine, m.common);
    const messages = parsePassShaderLog(result.log, offset, pass.composed.sections).filter((msg) => msg.pass);
    expect(messages.map((msg) => `${msg.pass}:${msg.line}`)).toEqual(expect.arrayContaining(['Common:2', 'Image:2']));
  });
});
