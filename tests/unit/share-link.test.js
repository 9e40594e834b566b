// A link carries an edit of a shader the page ships as a patch against that file (issue 24, item
// 14): the built-in raytracer deflates to ~34,000 characters, past the 8,000 a link may have, and
// a few changed lines are a few hundred. A page with another version of the file says so, and
// applies the patch where its context still matches.

import fs from 'node:fs';
import { describe, expect, test } from 'vitest';
import { BUILTIN_BASE, MAX_LINK_LENGTH, encodeSource, sourceFromHash, textFragment } from '../../src/player/io/share-link.js';
import { SHADER_FILE } from '../support/config.js';

const builtin = fs.readFileSync(SHADER_FILE, 'utf8');
const shipped = { base: BUILTIN_BASE, source: builtin };
const edit = (text) => text.replace('#define BOUNCES 3 ', '#define BOUNCES 1 ').replace('const float PI =', '// my note\nconst float PI =');
const edited = edit(builtin);
/** A page whose built-in raytracer is `text`. */
const pageWith = (text) => async (base) => (base === BUILTIN_BASE ? text : Promise.reject(new Error(`no ${base}`)));
const open = async (fields, text = builtin) => sourceFromHash(`#${fields}`, pageWith(text));

describe('an edit of the built-in raytracer', () => {
  test('travels as a patch far under the link limit, and opens as the same text', async () => {
    const fields = await textFragment(edited, 'raytrace.glsl (edited)', shipped);
    expect([...fields.keys()]).toEqual(['patch', 'base', 'hash', 'name']);
    const whole = await encodeSource(edited);
    expect(whole.length, 'the whole text would not fit').toBeGreaterThan(MAX_LINK_LENGTH);
    expect(fields.toString().length).toBeLessThan(1000);
    expect(await open(fields)).toEqual({ source: edited, name: 'raytrace.glsl (edited)', note: undefined });
  });

  test('made against another version that still has its lines: applies, and says so', async () => {
    const fields = await textFragment(edited, 'raytrace.glsl (edited)', shipped);
    const moved = builtin.replace('// ---- constants', '// a line the sender did not have\n// ---- constants');
    const opened = await open(fields, moved);
    expect(opened?.source).toBe(edit(moved));
    expect(opened?.note).toMatch(/made against another version of it than this page has; it applied/);
  });

  test('made against another version whose lines it changes differ: refused, in words', async () => {
    const fields = await textFragment(edited, 'raytrace.glsl (edited)', shipped);
    const changed = builtin.replace('#define BOUNCES 3 ', '#define BOUNCES 2 ');
    await expect(open(fields, changed)).rejects.toThrow(/was made against another version of it than this page has, and does not apply/);
  });

  test('a text the page does not ship, or one shorter whole, goes whole', async () => {
    const small = 'void mainImage(out vec4 c, in vec2 p) { c = vec4(1.0); }\n';
    expect([...(await textFragment(small, 'mine.glsl', null)).keys()]).toEqual(['source', 'name']);
    expect([...(await textFragment(small, 'mine.glsl', shipped)).keys()], 'shorter than its patch').toEqual(['source', 'name']);
    expect(await open(await textFragment(small, 'mine.glsl', null))).toEqual({ source: small, name: 'mine.glsl' });
  });

  test('a damaged patch says so', async () => {
    await expect(open('patch=AAAA&base=builtin&hash=0&name=x')).rejects.toThrow(/#patch= does not unpack/);
  });
});
