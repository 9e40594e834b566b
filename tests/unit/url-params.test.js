// The URL contract (src/shared/url-params.js) without a browser: what each parameter reads as, that bad
// values are clamped or ignored with a warning naming them, and that formatUrlParams writes what
// parseUrlParams reads back.
import { describe, expect, test } from 'vitest';
import { formatUrlParams, parseUrlParams } from '../../src/shared/url-params.js';
import { MAX_PIXELS, clampSize } from '../../src/shared/canvas-limits.js';

const BASE = 'http://127.0.0.1:5173/';

describe('parseUrlParams reads good values', () => {
  test.each([
    ['time', '?time=2.5', { time: 2.5 }],
    ['mouse, four values', '?mouse=1,2,-3,-4', { mouse: [1, 2, -3, -4] }],
    ['mouse, two values', '?mouse=10,20', { mouse: [10, 20, 0, 0] }],
    ['size', '?size=320x180', { size: { width: 320, height: 180 } }],
    ['scale', '?scale=0.5', { scale: 0.5 }],
    ['cap', '?cap=1280', { cap: 1280 }],
    ['speed', '?speed=2', { speed: 2 }],
    ['date, UTC', '?date=2024-01-15T12:00:00Z', { date: Date.UTC(2024, 0, 15, 12) }],
    ['date alone (UTC midnight)', '?date=2025-06-01', { date: Date.UTC(2025, 5, 1) }],
    ['fps', '?fps=30', { fps: 30 }],
    ['relative shader URL', '?shader=examples/pattern.glsl', { shader: 'examples/pattern.glsl' }],
    ['same-origin absolute shader URL', `?shader=${BASE}x.glsl`, { shader: `${BASE}x.glsl` }],
    ['a channel', '?iChannel2=img/noise.png', { channels: [undefined, undefined, 'img/noise.png'] }],
    ['a control', '?BOUNCES=2&LIGHT=1,2,3', { controls: { BOUNCES: '2', LIGHT: '1,2,3' } }],
  ])('%s', (_, search, expected) => {
    const params = parseUrlParams(search, BASE);
    expect(params.warnings).toEqual([]);
    expect(params).toMatchObject(expected);
  });
});

describe('parseUrlParams warns about bad values and never throws', () => {
  // Each parameter with the bad values it is given: value → what is used (a clamped value), or
  // {} for a value ignored. One warning each.
  /** @type {Record<string, Array<[string, object?]>>} */
  const BAD_VALUES = {
    time: [['NaN'], ['abc'], ['-5', { time: 0 }], ['1e300', { time: 1e6 }]],
    mouse: [['1,2,three,4'], ['Infinity,1']],
    size: [['0x0'], ['widexhigh'], ['100000x100000']],
    scale: [['9', { scale: 1 }], ['NaN']],
    cap: [['3', { cap: 16 }]],
    speed: [['-1', { speed: 0 }]],
    date: [['yesterday'], ['12'], ['2024-13-45']],
    fps: [['0', { fps: 1 }], ['1000', { fps: 240 }], ['fast']],
    shader: [['https://example.com/x.glsl'], ['javascript:alert(1)'], ['']],
    iChannel0: [['https://example.com/a.png']],
    'a b': [['1']], // a name that is no control name
  };
  /** @type {Array<[string, string, string, object]>} */
  const cases = Object.entries(BAD_VALUES).flatMap(([key, values]) =>
    values.map(
      ([value, expected = {}]) =>
        /** @type {[string, string, string, object]} */ ([`${key}=${value}`, `?${new URLSearchParams([[key, value]])}`, key, expected]),
    ),
  );
  test.each(cases)('%s', (_, search, key, expected) => {
    const params = parseUrlParams(search, BASE);
    expect(params.warnings.length).toBe(1);
    expect(params.warnings[0]).toContain(`${key}=`);
    expect(params).toMatchObject(expected);
    if (key === 'size' && params.size) expect(params.size.width * params.size.height).toBeLessThanOrEqual(MAX_PIXELS);
  });

  test('an absurd size keeps its aspect and fits the limits', () => {
    const { width, height } = clampSize({ width: 100000, height: 50000 });
    expect(width * height).toBeLessThanOrEqual(MAX_PIXELS);
    expect(Math.abs(width / height - 2)).toBeLessThan(0.01);
    expect(clampSize({ width: 20000, height: 10 })).toEqual({ width: 16384, height: 8 });
    expect(clampSize({ width: 640, height: 360 })).toEqual({ width: 640, height: 360 });
  });
});

describe('issue 12: cap=0, reserved names, repeated keys', () => {
  test('cap=0 means no cap, as the panel\'s "No cap" (not a cap clamped up to 16 px)', () => {
    for (const search of ['?cap=0', '?cap=0.0', '?cap=%200']) {
      const params = parseUrlParams(search, BASE);
      expect(params.warnings, search).toEqual([]);
      expect(params.cap, search).toBe(0);
    }
    // a cap between 0 and the minimum is still a cap, clamped
    expect(parseUrlParams('?cap=0.4', BASE)).toMatchObject({ cap: 16 });
  });

  test('__proto__= is warned about like any name that is no control, and sets no prototype', () => {
    for (const key of ['__proto__', 'gl_FragCoord', 'A__B']) {
      const params = parseUrlParams(`?${key}=1&BOUNCES=2`, BASE);
      expect(params.warnings.length, key).toBe(1);
      expect(params.warnings[0], key).toContain(`${key}=1 ignored`);
      expect(Object.keys(params.controls), key).toEqual(['BOUNCES']);
      expect(Object.getPrototypeOf(params.controls), key).not.toBe(1);
    }
    const params = parseUrlParams('?__proto__=1', BASE);
    expect(params.warnings.length).toBe(1);
    expect(Object.keys(params.controls)).toEqual([]);
  });

  test('control names that are Object.prototype members are plain controls', () => {
    const params = parseUrlParams('?constructor=2&toString=3&hasOwnProperty=4', BASE);
    expect(params.warnings).toEqual([]);
    expect({ ...params.controls }).toEqual({ constructor: '2', toString: '3', hasOwnProperty: '4' });
    // and a name that is not in the URL is not in the map, whatever Object.prototype holds
    expect('valueOf' in params.controls).toBe(false);
  });

  test.each([
    ['time', '?time=1&time=2', { time: 2 }],
    ['a bad last value still wins: the earlier is not used', '?time=1&time=abc', {}],
    ['a control', '?BOUNCES=1&BOUNCES=3', { controls: { BOUNCES: '3' } }],
    ['shader', '?shader=a.glsl&shader=b.glsl', { shader: 'b.glsl' }],
  ])('a repeated key is warned about and its last value is used: %s', (_, search, expected) => {
    const params = parseUrlParams(search, BASE);
    const key = search.slice(1, search.indexOf('='));
    const repeated = params.warnings.filter((w) => w.includes('more than once'));
    expect(repeated.length, params.warnings.join('\n')).toBe(1);
    expect(repeated[0]).toContain(`${key}=`);
    expect(repeated[0]).toContain(`the last one is used (${search.slice(search.lastIndexOf('&') + 1)})`);
    expect(params).toMatchObject(expected);
    if (!('time' in expected) && key === 'time') expect(params.time).toBeUndefined();
  });
});

test('formatUrlParams writes what parseUrlParams reads', () => {
  const state = {
    shader: 'examples/raymarch.glsl',
    size: { width: 160, height: 90 },
    time: 3.3,
    mouse: [40, 59, -40, -59],
    speed: 2,
    date: Date.UTC(2024, 0, 15, 12),
    fps: 30,
    channels: [null, 'img/a.png'],
    media: '/site-media/',
    controls: { TWIST: 2.2, ALBEDO: [0.5, 0.25, 1], MAX_STEPS: 64, FLAG: true },
  };
  const query = formatUrlParams(state);
  expect(query).toBe(
    '?shader=examples/raymarch.glsl&size=160x90&time=3.3&mouse=40,59,-40,-59&speed=2&date=2024-01-15T12%3A00%3A00.000Z&fps=30&iChannel1=img/a.png&media=/site-media/&TWIST=2.2&ALBEDO=0.5,0.25,1&MAX_STEPS=64&FLAG=true',
  );
  const back = parseUrlParams(query, BASE);
  expect(back.warnings).toEqual([]);
  expect(back).toMatchObject({
    shader: state.shader,
    size: state.size,
    time: 3.3,
    mouse: state.mouse,
    speed: 2,
    date: state.date,
    fps: 30,
  });
  expect(back.channels[1]).toBe('img/a.png');
  expect(back.media).toBe('/site-media/');
  // a media folder of another origin is refused, and said
  expect(parseUrlParams('?media=https://elsewhere.example/media/', BASE).warnings[0]).toMatch(
    /media=.* ignored: only files served by this page's server .*; the site's media a shader names stay black/,
  );
  expect(back.controls).toEqual({ TWIST: '2.2', ALBEDO: '0.5,0.25,1', MAX_STEPS: '64', FLAG: 'true' });
  // the built-in shader, no mouse, real time: only size and time
  expect(formatUrlParams({ size: { width: 8, height: 4 }, time: 0, mouse: [0, 0, 0, 0] })).toBe('?size=8x4&time=0');
});
