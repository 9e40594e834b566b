// Multipass Shadertoy shaders (issue 13), the renderer-independent half: the model and its
// schedule (src/shadertoy/multipass.js), Shadertoy's JSON in and out (multipass-json.js), one
// pass composed in Shadertoy's header with its compile errors named by tab (header.js,
// pass-errors.js), and the keyboard texture (keyboard.js). The passes and the schedule are also
// run on SwiftShader through the raw WebGL2 page (tests/multipass-runner.js).
import { afterAll, describe, expect, test } from 'vitest';
import { composeImageShader, composePassShader, countNewlines, locatePassLine } from '../src/shadertoy/header.js';
import { KeyboardState, keyCodeOf, ROW_HELD, ROW_PRESSED, ROW_TOGGLED } from '../src/shadertoy/keyboard.js';
import { fromShadertoyJson, toShadertoyJson } from '../src/shadertoy/multipass-json.js';
import { MultipassError, frameSchedule, renderOrder, sameModel, singlePass } from '../src/shadertoy/multipass.js';
import { formatPassMessages, parsePassShaderLog } from '../src/shadertoy/pass-errors.js';
import { userLineOffset } from '../src/shadertoy/shader-errors.js';
import { disconnect } from './harness/page.js';
import { composeModel, runPasses } from './multipass-runner.js';

afterAll(disconnect);

const MAIN = 'void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n    fragColor = vec4(1.0);\n}\n';
const sampler = (filter = 'linear', wrap = 'clamp', vflip = 'true') => ({ filter, wrap, vflip, srgb: 'false', internal: 'byte' });

/** A shader as the site exports it today: string ids, `type`, `filepath`. Buffer A feeds itself, Image reads A. */
const SITE_EXPORT = {
  Shader: {
    ver: '0.1',
    info: { id: 'xxxxxx', name: 'Feedback', username: 'tester', description: 'written here', tags: ['test'] },
    renderpass: [
      {
        inputs: [
          {
            id: '4dXGR8',
            filepath: '/media/previz/buffer00.png',
            previewfilepath: '/media/previz/buffer00.png',
            type: 'buffer',
            channel: 0,
            sampler: sampler('nearest'),
            published: 1,
          },
        ],
        outputs: [{ id: '4dfGRr', channel: 0 }],
        code: MAIN,
        name: 'Image',
        description: '',
        type: 'image',
      },
      {
        inputs: [
          {
            id: '4dXGR8',
            filepath: '/media/previz/buffer00.png',
            previewfilepath: '/media/previz/buffer00.png',
            type: 'buffer',
            channel: 1,
            sampler: sampler('linear', 'repeat'),
            published: 1,
          },
          {
            id: '4dXGRr',
            filepath: '/presets/tex00.jpg',
            previewfilepath: '/presets/tex00.jpg',
            type: 'keyboard',
            channel: 3,
            sampler: sampler(),
            published: 1,
          },
        ],
        outputs: [{ id: '4dXGR8', channel: 0 }],
        code: MAIN,
        name: 'Buffer A',
        description: 'the state',
        type: 'buffer',
      },
      { inputs: [], outputs: [], code: 'float twice(float x) { return 2.0 * x; }', name: 'Common', description: '', type: 'common' },
    ],
  },
};

/** The older style: numeric ids, `ctype`, `src`, flags as strings; a pass named "Buf B". */
const LEGACY_EXPORT = {
  Shader: {
    ver: '0.1',
    info: { name: 'Legacy' },
    renderpass: [
      {
        inputs: [
          {
            id: 258,
            src: '/presets/previz/buffer01.png',
            ctype: 'buffer',
            channel: 2,
            sampler: sampler('mipmap', 'repeat', 'false'),
            published: 1,
          },
        ],
        outputs: [{ id: 37, channel: 0 }],
        code: MAIN,
        name: 'Image',
        description: '',
        type: 'image',
      },
      { inputs: [], outputs: [{ id: 258, channel: 0 }], code: MAIN, name: 'Buf B', description: '', type: 'buffer' },
    ],
  },
};

/** Media the page cannot have, a sound pass, a cubemap pass. */
const MEDIA_EXPORT = {
  Shader: {
    info: { name: 'Media' },
    renderpass: [
      {
        inputs: [
          {
            id: '4sfGRn',
            filepath: '/media/a/0a40562379b63dfb89227e6d172f39fdce9022cba76623f1054a2c83d6c0ba5d.png',
            type: 'texture',
            channel: 0,
            sampler: sampler('mipmap', 'repeat', 'false'),
            published: 1,
          },
          { id: 'XsfGRr', filepath: '/media/a/video.webm', type: 'video', channel: 1, sampler: sampler(), published: 1 },
          {
            id: '4sXGzn',
            filepath: '/media/a/cube.png',
            type: 'cubemap',
            channel: 2,
            sampler: sampler('mipmap', 'clamp', 'false'),
            published: 1,
          },
          { id: 'webcam', filepath: '', type: 'webcam', channel: 3, sampler: sampler(), published: 1 },
        ],
        outputs: [{ id: '4dfGRr', channel: 0 }],
        code: MAIN,
        name: 'Image',
        description: '',
        type: 'image',
      },
      {
        inputs: [],
        outputs: [],
        code: 'vec2 mainSound(int s, float t) { return vec2(0.0); }',
        name: 'Sound',
        description: '',
        type: 'sound',
      },
      { inputs: [], outputs: [{ id: '4dX3Rr', channel: 0 }], code: MAIN, name: 'Cube A', description: '', type: 'cubemap' },
    ],
  },
};

describe('Shadertoy JSON: loading', () => {
  test('an export in the site’s current style', () => {
    const { model, info, notes } = fromShadertoyJson(SITE_EXPORT);
    expect(info.name).toBe('Feedback');
    expect(notes).toEqual([]);
    expect(model.common).toBe('float twice(float x) { return 2.0 * x; }');
    const image = model.passes.find((p) => p.kind === 'image');
    const a = model.passes.find((p) => p.buffer === 'A');
    expect(image.channels).toEqual([
      { kind: 'buffer', buffer: 'A', sampler: { filter: 'nearest', wrap: 'clamp', vflip: true } },
      null,
      null,
      null,
    ]);
    expect(a).toMatchObject({ name: 'Buffer A', kind: 'buffer', code: MAIN, extra: { description: 'the state' } });
    expect(a.channels[1]).toEqual({ kind: 'buffer', buffer: 'A', sampler: { filter: 'linear', wrap: 'repeat', vflip: true } });
    expect(a.channels[3]).toEqual({ kind: 'keyboard', sampler: { filter: 'linear', wrap: 'clamp', vflip: true } });
  });

  test('an export in the older style (numeric ids, ctype, src)', () => {
    const { model } = fromShadertoyJson(LEGACY_EXPORT);
    expect(model.passes.map((p) => [p.name, p.buffer])).toEqual([
      ['Image', null],
      ['Buffer B', 'B'],
    ]);
    expect(model.passes[0].channels[2]).toMatchObject({
      kind: 'buffer',
      buffer: 'B',
      sampler: { filter: 'mipmap', wrap: 'repeat', vflip: false },
    });
  });

  test('media the page cannot have: black channels and a note each; sound and cubemap passes noted, not run', () => {
    const { model, notes } = fromShadertoyJson(MEDIA_EXPORT);
    expect(model.passes).toHaveLength(1);
    expect(model.passes[0].channels.map((c) => [c.kind, 'supported' in c ? c.supported : true])).toEqual([
      ['texture', false],
      ['video', false],
      ['cubemap', false],
      ['webcam', false],
    ]);
    expect(notes).toHaveLength(6);
    expect(notes[0]).toMatch(/^Image, iChannel0: the site's texture \/media\/a\/0a4056.*is not available here; the channel is black$/);
    expect(notes.join('\n')).toMatch(/Sound: sound passes are not played here/);
    expect(notes.join('\n')).toMatch(/Cube A: cubemap passes are not rendered here/);
    const bindings = frameSchedule(model)[0].bindings;
    expect(bindings.map((b) => [b.source, b.samplerType])).toEqual([
      ['black', '2D'],
      ['black', '2D'],
      ['black', 'Cube'],
      ['black', '2D'],
    ]);
  });

  test.each([
    ['the API’s {Shader: …}', (j) => j],
    ['the bare {info, renderpass}', (j) => j.Shader],
    ['an array of one', (j) => [j]],
    ['JSON text', (j) => JSON.stringify(j)],
  ])('accepts %s', (_, wrap) => {
    expect(fromShadertoyJson(wrap(SITE_EXPORT)).model.passes).toHaveLength(2);
  });

  const broken = (edit) => {
    const copy = structuredClone(SITE_EXPORT);
    edit(copy.Shader);
    return copy;
  };
  test.each([
    ['not JSON', '{"Shader": ', /not JSON/],
    ['no renderpass', { Shader: { info: {} } }, /no "renderpass" list/],
    ['two shaders', [SITE_EXPORT, SITE_EXPORT], /expected one shader, the file holds 2/],
    ['a channel out of range', broken((s) => (s.renderpass[0].inputs[0].channel = 5)), /^Image: an input on channel 5/],
    [
      'two inputs on a channel',
      broken((s) => s.renderpass[1].inputs.push({ ...s.renderpass[1].inputs[0] })),
      /^Buffer A, iChannel1: two inputs on one channel/,
    ],
    [
      'a buffer output that is no buffer',
      broken((s) => (s.renderpass[1].outputs[0].id = 999)),
      /^Buffer A: a buffer pass whose output 999/,
    ],
    [
      'an unknown input type',
      broken((s) => (s.renderpass[0].inputs[0].type = 'hologram')),
      /^Image, iChannel0: unknown input type "hologram"/,
    ],
    ['an unknown filter', broken((s) => (s.renderpass[0].inputs[0].sampler.filter = 'cubic')), /^Image, iChannel0: unknown filter "cubic"/],
    ['a pass without code', broken((s) => delete s.renderpass[1].code), /^Buffer A: has no code/],
    ['an unknown pass type', broken((s) => (s.renderpass[1].type = 'compute')), /^Buffer A: unknown pass type "compute"/],
    [
      'a buffer no pass writes',
      broken((s) => (s.renderpass[0].inputs[0].id = '4sXGR8')),
      /^Image, iChannel0: reads Buffer C, which no pass writes/,
    ],
    ['no Image pass', broken((s) => s.renderpass.splice(0, 1)), /exactly one Image pass, this one has 0/],
    [
      'two Buffer A passes',
      broken((s) => s.renderpass.push(structuredClone(s.renderpass[1]))),
      /Buffer A: Buffer A is written by two passes/,
    ],
  ])('refuses %s, saying where', (_, json, message) => {
    expect(() => fromShadertoyJson(json)).toThrow(MultipassError);
    expect(() => fromShadertoyJson(json)).toThrow(message);
  });
});

/** Every field of `original` is in `written` with the same value (written may add defaults). */
function expectKeeps(written, original, path = '') {
  if (Array.isArray(original)) {
    expect(Array.isArray(written), path).toBe(true);
    original.forEach((item, i) => {
      const twin =
        item && typeof item === 'object' && 'channel' in item && !('code' in item)
          ? written.find((w) => w.channel === item.channel)
          : item?.type
            ? written.find((w) => w.type === item.type && (w.outputs?.[0]?.id ?? null) === (item.outputs?.[0]?.id ?? null))
            : written[i];
      expectKeeps(twin, item, `${path}[${i}]`);
    });
  } else if (original && typeof original === 'object') {
    for (const [k, v] of Object.entries(original)) expectKeeps(written?.[k], v, `${path}.${k}`);
  } else {
    expect(written, path).toEqual(original);
  }
}

describe('Shadertoy JSON: round trips', () => {
  test.each([
    ['site style', SITE_EXPORT],
    ['legacy style', LEGACY_EXPORT],
    ['media, sound and cubemap', MEDIA_EXPORT],
  ])('json → model → json keeps every field (%s)', (_, json) => {
    const { model, info } = fromShadertoyJson(json);
    const written = toShadertoyJson(model, info);
    expectKeeps(written, json);
  });

  test.each([
    ['site style', SITE_EXPORT],
    ['legacy style', LEGACY_EXPORT],
    ['media, sound and cubemap', MEDIA_EXPORT],
  ])('model → json → model is the same model (%s)', (_, json) => {
    const { model, info } = fromShadertoyJson(json);
    expect(sameModel(fromShadertoyJson(toShadertoyJson(model, info)).model, model)).toBe(true);
  });

  test('a model built here (no extras) survives the trip, written in the site’s current style', () => {
    const model = {
      common: '// shared\n',
      passes: [
        {
          name: 'Image',
          kind: 'image',
          buffer: null,
          code: MAIN,
          channels: [
            null,
            { kind: 'buffer', buffer: 'B', sampler: { filter: 'mipmap', wrap: 'repeat', vflip: false } },
            null,
            { kind: 'keyboard', sampler: { filter: 'nearest', wrap: 'clamp', vflip: false } },
          ],
        },
        {
          name: 'Buffer B',
          kind: 'buffer',
          buffer: 'B',
          code: MAIN,
          channels: [{ kind: 'buffer', buffer: 'B', sampler: { filter: 'nearest', wrap: 'clamp', vflip: true } }, null, null, null],
        },
      ],
    };
    const json = toShadertoyJson(/** @type {any} */ (model));
    expect(json.Shader.renderpass[1].outputs).toEqual([{ id: 'XsXGR8', channel: 0 }]);
    expect(json.Shader.renderpass[0].inputs.find((i) => i.channel === 1)).toMatchObject({
      id: 'XsXGR8',
      type: 'buffer',
      channel: 1,
      filepath: '/media/previz/buffer01.png',
      sampler: { vflip: 'false' },
    });
    expect(fromShadertoyJson(json).model).toEqual(model);
    expect(sameModel(fromShadertoyJson(toShadertoyJson(singlePass(MAIN))).model, singlePass(MAIN))).toBe(true);
  });
});

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
  test('empty channels are nothing, with zero resolution; the keyboard is 256 x 3', () => {
    const m = singlePass(MAIN);
    m.passes[0].channels[2] = { kind: 'keyboard', sampler: { filter: 'linear', wrap: 'repeat', vflip: true } };
    const [step] = frameSchedule(m);
    expect(step.bindings[0]).toMatchObject({ source: 'none', resolution: [0, 0, 0] });
    expect(step.bindings[2]).toMatchObject({ source: 'keyboard', resolution: [256, 3, 1], sampler: { filter: 'nearest', wrap: 'clamp' } });
  });
});

describe('keyboard texture', () => {
  const A = 65;
  const row = (k, s) => [s.read(k, ROW_HELD), s.read(k, ROW_PRESSED), s.read(k, ROW_TOGGLED)];
  test.each([
    ['nothing', [], [0, 0, 0]],
    ['down', ['down'], [1, 1, 1]],
    ['down, a frame', ['down', 'frame'], [1, 0, 1]],
    ['down, auto-repeat, a frame', ['down', 'frame', 'down'], [1, 0, 1]],
    ['down, a frame, up', ['down', 'frame', 'up'], [0, 0, 1]],
    ['down, up before the frame (never seen pressed)', ['down', 'up'], [0, 0, 1]],
    ['two presses: the toggle is back off', ['down', 'frame', 'up', 'frame', 'down', 'frame'], [1, 0, 0]],
    ['three presses', ['down', 'up', 'down', 'up', 'down'], [1, 1, 1]],
  ])('%s', (_, events, expected) => {
    const s = new KeyboardState();
    for (const e of events) {
      if (e === 'down') s.keyDown(A);
      else if (e === 'up') s.keyUp(A);
      else s.endFrame();
    }
    expect(row(A, s)).toEqual(expected);
    // Other keys untouched; the texture is 256 x 3 bytes, row r at offset 256 r.
    expect(s.data).toHaveLength(768);
    expect(s.data.reduce((n, v, i) => n + (v !== 0 && i % 256 !== A ? 1 : 0), 0)).toBe(0);
    if (expected[2]) expect(s.data[2 * 256 + A]).toBe(255);
  });
  test('a repeat reports no change; keys outside 1..255 are ignored', () => {
    const s = new KeyboardState();
    expect(s.keyDown(A)).toBe(true);
    expect(s.keyDown(A)).toBe(false);
    expect(s.keyDown(300)).toBe(false);
    expect(s.keyDown(null)).toBe(false);
  });
  test.each([
    [{ keyCode: 37, code: 'ArrowLeft' }, 37],
    [{ code: 'KeyA', key: 'a' }, 65],
    [{ code: 'Digit7', key: '7' }, 55],
    [{ code: 'Space', key: ' ' }, 32],
    [{ code: 'ArrowDown', key: 'ArrowDown' }, 40],
    [{ code: 'Numpad3' }, 99],
    [{ code: 'F5' }, 116],
    [{ code: 'ShiftRight' }, 16],
    [{ code: 'Semicolon' }, 186],
    [{ key: 'q' }, 81],
    [{ key: 'Escape' }, 27],
    [{ code: 'Unidentified', key: 'Dead' }, null],
    [{ keyCode: 300 }, null],
  ])('keyCodeOf(%o) = %s', (event, code) => {
    expect(keyCodeOf(event)).toBe(code);
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
