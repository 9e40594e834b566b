// The loop guard's form of a pass (src/shadertoy/loop-guard.js, loop-statements.js), read as text:
// every loop found, whatever its form, each `break` given to the loop it leaves (not to a switch),
// a for's declarations kept in scope, and the pass refused, with why, where it cannot be read.
// What the form does on llvmpipe is tests/browser/loop-limit.test.js's.

import { describe, expect, test } from 'vitest';
import { guardLoops } from '../../src/shadertoy/loop-guard.js';
import { readStatements, sideEffectFree } from '../../src/shadertoy/loop-statements.js';
import { composePassShader } from '../../src/shadertoy/header.js';
import { composeSoundShader } from '../../src/shadertoy/sound.js';

/** A pass of `body` in mainImage, as the page composes it. @param {string} body @param {string} [before] */
const image = (body, before = '') =>
  composePassShader(`${before}\nvoid mainImage(out vec4 c, in vec2 f) {\n${body}\nc = vec4(0.0);\n}\n`, {
    kind: 'image',
    name: 'Image',
    channelTypes: ['2D', '2D', '2D', '2D'],
  }).code;

describe('the loops of a pass, each found', () => {
  test.each([
    ['for', 'for (int i = 0; i < 10; i++) c.x += 1.0;', 1],
    ['for (;;)', 'for (;;) { if (c.x > 1.0) break; c.x += 0.5; }', 1],
    ['while', 'float x = 0.0; while (x < 3.0) x += 1.0;', 1],
    ['do-while', 'float x = 0.0; do { x += 1.0; } while (x < 3.0);', 1],
    ['nested', 'for (int i = 0; i < 3; i++) for (int j = 0; j < 3; j++) { c.x += 1.0; }', 2],
    ['in sequence, in an if and its else', 'if (f.x > 1.0) { for (int i = 0; i < 2; i++) c.x++; } else while (c.x < 2.0) c.x++;', 2],
    ['from a macro', '#define LOOP(n) for (int i = 0; i < n; i++)\nLOOP(4) c.x += 1.0;', 1],
    ['none', 'c = vec4(1.0);', 0],
  ])('%s', (_, body, loops) => {
    const form = guardLoops(image(body));
    expect(form.loops).toBe(loops);
    if (loops === 0) expect(form).toMatchObject({ code: null, reason: 'no loops' });
    else expect(form.code).toMatch(/layout\(location = 1\) out vec4 shaderproof_loopGuard;/);
  });

  test('in a function the pass calls, in a struct-declaring pass with an interface of the header', () => {
    const before =
      'struct Hit { float t; vec3 n; };\nfloat march(vec3 p) { float t = 0.0; for (int i = 0; i < 64; i++) t += 0.1; return t; }';
    expect(guardLoops(image('Hit h = Hit(march(vec3(0.0)), vec3(1.0));', before)).loops).toBe(1);
  });

  test("the Sound tab's main writes the guard too", () => {
    const { code } = composeSoundShader('vec2 mainSound(int s, float t) { float x = 0.0; while (x < t) x += 1.0; return vec2(x); }');
    const form = guardLoops(code);
    expect(form.loops).toBe(1);
    expect(form.code).toMatch(/shaderproof_loopGuard = vec4\(shaderproof_loopCut \? 1\.0 : 0\.0, 0\.0, 0\.0, 1\.0\); \}\s*$/m);
  });
});

describe('a break is said for the loop it leaves', () => {
  test.each([
    ['of the loop', 'for (int i = 0; ; i++) { if (i > 3) break; }', 1],
    ['of a switch in the loop: none', 'for (int i = 0; i < 4; i++) { switch (i) { case 1: break; default: c.x++; break; } }', 0],
    ['of a loop in a switch in a loop', 'for (int i = 0; i < 4; i++) { switch (i) { case 1: for (;;) { break; } break; } }', 1],
    ['of the inner loop alone', 'for (int i = 0; i < 4; i++) { for (int j = 0; j < 4; j++) { if (j > i) break; } }', 1],
  ])('%s', (_, body, breaks) => {
    const { loops } = readStatements(body.replace(/^/, 'void main() {').concat('}'));
    expect(loops.reduce((sum, loop) => sum + loop.breaks.length, 0)).toBe(breaks);
  });

  test('the loop a break leaves sets its own flag before it (loops are numbered inner first)', () => {
    const form = guardLoops(image('for (int i = 0; i < 4; i++) { for (int j = 0; j < 4; j++) { if (j > i) break; } }'));
    expect(form.code).toMatch(/int j = 0; for .*\{ shaderproof_broke0 = true; break; \}/);
    expect(form.code).not.toMatch(/shaderproof_broke1 = true/);
  });
});

test("a for's declaration goes before it, in the loop's own block, and its condition is asked again after it", () => {
  const form = guardLoops(image('for (int i = 0; i < 10; i++) c.x += 1.0;'));
  expect(form.code).toMatch(
    /\{ bool shaderproof_live0 = true; bool shaderproof_broke0 = false; int i = 0; for \(; \(shaderproof_live0 = \(i < 10\)\); i\+\+\) c\.x \+= 1\.0; if \(shaderproof_live0 && !shaderproof_broke0 && \(i < 10\)\) shaderproof_loopCut = true; \}/,
  );
});

describe('a condition is asked again only where that has no side effect', () => {
  test.each([
    ['i < n', true],
    ['length(p) < 10.0 && t < tmax', true],
    ['texture(iChannel0, uv).x > 0.5', true],
    ['i++ < n', false],
    ['(x += 1.0) < 3.0', false],
    ['march(p) < 1.0', false],
    ['x == y && y != z && a <= b', true],
  ])('%s', (condition, free) => expect(sideEffectFree(condition)).toBe(free));
});

describe('a pass that cannot be read has no guarded form, and says why', () => {
  test.each([
    ['an unbalanced brace', 'for (int i = 0; i < 4; i++) { c.x++;', /^not read: /],
    ['a for with one ";"', 'for (int i = 0; i < 4) c.x++;', /^not read: a for \( with 1 ";"/],
    ['a macro called without its arguments', '#define M(a, b) a + b\nc.x = M(1.0);', /^not preprocessed: /],
  ])('%s', (_, body, reason) => {
    const form = guardLoops(image(body));
    expect(form.code).toBeNull();
    expect(form.reason).toMatch(reason);
  });
});
