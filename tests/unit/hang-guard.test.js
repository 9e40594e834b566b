// The note that keeps the page from coming back with a shader that hung (src/player/io/hang-guard.js).
import { describe, expect, test } from 'vitest';
import { HangGuard, projectKey } from '../../src/player/io/hang-guard.js';
import { singlePass } from '../../src/shadertoy/multipass.js';

/** A Storage with only what the guard uses. */
function memoryStorage() {
  const items = new Map();
  return /** @type {Storage} */ (
    /** @type {unknown} */ ({
      getItem: (key) => items.get(key) ?? null,
      setItem: (key, value) => items.set(key, String(value)),
      removeItem: (key) => items.delete(key),
    })
  );
}

const GOOD = singlePass('void mainImage(out vec4 c, in vec2 p) { c = vec4(1.0); }');
const HUNG = singlePass('void mainImage(out vec4 c, in vec2 p) { for (;;) {} }');

/** The shader that hung, as the guard is told it (a ShaderVersion). */
const hungWith = (project, values) => ({
  project,
  values,
  name: 'hung.glsl',
  origin: /** @type {const} */ ('editor'),
  url: null,
  info: null,
});

describe('HangGuard', () => {
  test('a hang is noted with the last shader that finished; only that shader with those values is replaced', () => {
    const guard = new HangGuard(memoryStorage());
    const last = { project: GOOD, values: { N: 1 }, name: 'good.glsl', origin: 'editor', url: null, info: null };
    guard.record(hungWith(HUNG, { N: 1 }), /** @type {any} */ (last));
    expect(guard.backFor(HUNG, { N: 1 })).toEqual(last);
    expect(guard.backFor(HUNG, { N: 2 }), 'other values: another shader').toBeNull();
    expect(guard.backFor(GOOD, { N: 1 })).toBeNull();
    expect(guard.note?.project, 'the text that hung is kept').toEqual(HUNG);
    guard.clear();
    expect(guard.backFor(HUNG, { N: 1 })).toBeNull();
  });

  test('a control value alone can be what hung: the same tabs with other values are the way back', () => {
    const guard = new HangGuard(memoryStorage());
    const last = { project: GOOD, values: { WORK: 0 }, name: 'heavy.glsl', origin: 'url', url: 'heavy.glsl', info: null };
    guard.record(hungWith(GOOD, { WORK: 1e9 }), /** @type {any} */ (last));
    expect(guard.backFor(GOOD, { WORK: 1e9 })).toEqual(last);
    expect(projectKey(GOOD, { WORK: 0 })).not.toBe(projectKey(GOOD, { WORK: 1e9 }));
  });

  test('with nothing that finished before it, nothing replaces it; unreadable storage is no note', () => {
    const storage = memoryStorage();
    const guard = new HangGuard(storage);
    guard.record(hungWith(HUNG, {}), null);
    expect(guard.backFor(HUNG, {})).toBeNull();
    storage.setItem('shadertoy-runner.hung', '{not json');
    expect(guard.note).toBeNull();
  });
});
