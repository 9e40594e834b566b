// Shadertoy's JSON format (issue 13): multipass-json.js loading exports written here (the
// site's current style, the legacy style, media the page cannot have, sound and cubemap passes,
// malformed files refused naming the pass) and writing them back losslessly.
import { describe, expect, test } from 'vitest';
import { fromShadertoyJson, toShadertoyJson } from '../../src/shadertoy/multipass-json.js';
import { MultipassError, frameSchedule, sameModel, singlePass } from '../../src/shadertoy/multipass.js';

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

  test('media the page cannot have: black channels and a note each; the Cube A and Sound tabs passes of their own', () => {
    const { model, notes } = fromShadertoyJson(MEDIA_EXPORT);
    expect(model.passes.map((p) => [p.name, p.kind])).toEqual([
      ['Image', 'image'],
      ['Sound', 'sound'],
      ['Cube A', 'cubemap'],
    ]);
    expect(model.passes[0].channels.map((c) => [c.kind, 'supported' in c ? c.supported : true])).toEqual([
      ['texture', false],
      ['video', false],
      ['cubemap', false],
      ['webcam', false],
    ]);
    expect(notes).toHaveLength(4);
    expect(notes[0]).toMatch(/^Image, iChannel0: the site's texture \/media\/a\/0a4056.*is not available here; the channel is black$/);
    expect(notes.join('\n')).not.toMatch(/Sound/); // it plays (sound.js)
    expect(notes.join('\n')).not.toMatch(/Cube A/); // it runs (tests/browser/cube-a.test.js)
    const bindings = frameSchedule(model).at(-1).bindings;
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

  test('a channel reading a buffer or Cube A that no pass writes is black, as on the site, and said', () => {
    const dangling = broken((s) => {
      s.renderpass[0].inputs[0].id = '4sXGR8'; // Buffer C
      s.renderpass[0].inputs[0].filepath = '/media/previz/buffer02.png';
      s.renderpass[0].inputs.push({ channel: 3, type: 'cubemap', id: '4dX3Rr', filepath: '/media/previz/cubemap00.png', sampler: {} });
    });
    const { model } = fromShadertoyJson(dangling);
    const image = frameSchedule(model).find((step) => step.target === 'screen');
    expect(image?.bindings[0]).toMatchObject({ source: 'black', samplerType: '2D', resolution: 'canvas' });
    expect(image?.bindings[0].note).toBe('Image, iChannel0: reads Buffer C, which no pass writes; the channel is black, as on the site');
    expect(image?.bindings[3]).toMatchObject({ source: 'black', samplerType: 'Cube', resolution: [0, 0, 0] });
    expect(image?.bindings[3].note).toMatch(/^Image, iChannel3: reads Cube A, which no pass writes/);
  });
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

/** The exports every round trip is tried on. @type {Array<[string, any]>} */
const EXPORT_STYLES = [
  ['site style', SITE_EXPORT],
  ['legacy style', LEGACY_EXPORT],
  ['media, sound and cubemap', MEDIA_EXPORT],
];

describe('Shadertoy JSON: round trips', () => {
  test.each(EXPORT_STYLES)('json → model → json keeps every field (%s)', (_, json) => {
    const { model, info } = fromShadertoyJson(json);
    const written = toShadertoyJson(model, info);
    expectKeeps(written, json);
  });

  test.each(EXPORT_STYLES)('model → json → model is the same model (%s)', (_, json) => {
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
