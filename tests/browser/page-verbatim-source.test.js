// The text of a pass reaches WebGL exactly as Shadertoy composes it (issue 37): its header with
// `main` right after the forward declaration of mainImage, the Common tab, a line break, the
// pass's tab, and nothing of three.js's shader preprocessing (`#include <…>` resolved even in a
// comment, `#pragma unroll_loop_start` blocks unrolled, prefixes before the text). Each case is a
// small shader that failed on the page before and draws on the site; each compile is read back
// from the render worker (gl.getShaderSource when it compiles) and compared with the composed
// text byte for byte; a compile error next to such a construct names its tab and the user's line.

import { describe, expect, test } from 'vitest';
import { composePassShader, hostControlBlock } from '../../src/shadertoy/header.js';
import { pixel, readPixels, sharePageAcrossTests, withPage } from '../support/page-helpers.js';
import { exportOf } from '../support/page-multipass-helpers.js';
import { hook } from '../support/hook.js';

sharePageAcrossTests();

const SIZE = 'size=32x18&time=0'; // paused: each readPixels() draws exactly one frame

/** A Common tab's line: nothing in it that matters to the case. */
const PLAIN_COMMON = 'float unused(float x) { return x; }\n';

/** A Buffer A with nothing in it that matters to the case. */
const PLAIN_BUFFER = 'void mainImage(out vec4 c, in vec2 p) { c = vec4(0.0); }\n';

/** An Image tab that shows Buffer A's texel under the pixel (the export binds A to iChannel0). */
const SHOW_BUFFER_A = 'void mainImage(out vec4 c, in vec2 p) { c = vec4(texelFetch(iChannel0, ivec2(p), 0).rgb, 1.0); }\n';

/** A Buffer A that writes one colour (k / 255), after a C++ include in a block comment. */
const INCLUDE_IN_COMMENT = `/*
#include <iostream>
*/
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(40.0, 80.0, 120.0, 255.0) / 255.0;
}
`;

/** An Image tab with a loop between three.js's unroll pragmas (which GLSL ignores): 0+1+2+3. */
const UNROLL_PRAGMAS = `void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float sum = 0.0;
    #pragma unroll_loop_start
    for (int i = 0; i < 4; i++) {
        sum += float(i);
    }
    #pragma unroll_loop_end
    fragColor = vec4(sum * 17.0, 0.0, 0.0, 255.0) / 255.0;
}
`;

// The well-known way to supersample a shader from its Common tab (our own writing of it): a macro
// renames the tab's mainImage to mainImage0 and puts before it a mainImage that averages it over
// a 2 × 2 grid of samples a quarter pixel off the centre. It works on the site because the site's
// `main` and its forward declaration of mainImage come before Common, where the macro is not
// defined yet.
const SAMPLE_OFFSETS = [-0.25, 0.25].flatMap((y) => [-0.25, 0.25].map((x) => [x, y]));
const SUPERSAMPLE =
  '#define mainImage mainImage0(out vec4 O, vec2 U); void mainImage(out vec4 O, vec2 U) { O = vec4(0); ' +
  'for (int k = 0; k < 4; k++) { vec4 s; mainImage0(s, U + (vec2(k % 2, k / 2) - 0.5) * 0.5); O += s / 4.0; } } void mainImage0\n';

/** An edge through every pixel's centre: the centre alone is one colour, the four samples two. */
const EDGE_AT_CENTRES = `void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(fract(fragCoord.x) < 0.5 ? 1.0 : 0.2, fract(fragCoord.y) < 0.5 ? 0.6 : 0.2, 0.0, 1.0);
}
`;

/** What the supersampled EDGE_AT_CENTRES draws at a pixel (x, y from the bottom), as bytes. */
function supersampledEdge(x, y) {
  const colour = (fx, fy) => [fx % 1 < 0.5 ? 1.0 : 0.2, fy % 1 < 0.5 ? 0.6 : 0.2, 0.0];
  const samples = SAMPLE_OFFSETS.map(([dx, dy]) => colour(x + 0.5 + dx, y + 0.5 + dy));
  return [0, 1, 2].map((c) => Math.round((255 * samples.reduce((sum, s) => sum + s[c], 0)) / samples.length));
}

/** Records, in the page's workers, the text of every shader WebGL compiles (gl.getShaderSource). */
async function recordCompiledSources(page) {
  for (const worker of page.workers()) {
    await worker.evaluate(() => {
      const scope = /** @type {any} */ (self);
      if (scope.__compiledSources || typeof WebGL2RenderingContext === 'undefined') return;
      scope.__compiledSources = [];
      const compile = WebGL2RenderingContext.prototype.compileShader;
      WebGL2RenderingContext.prototype.compileShader = function (shader) {
        scope.__compiledSources.push(this.getShaderSource(shader));
        return compile.call(this, shader);
      };
    });
  }
}

/** The fragment shaders compiled since the last call (those with a mainImage), and forgets them. */
async function takeCompiledSources(page) {
  const texts = [];
  for (const worker of page.workers()) {
    texts.push(...(await worker.evaluate(() => /** @type {any} */ (self).__compiledSources?.splice(0) ?? [])));
  }
  return texts.filter((text) => text.includes('mainImage'));
}

/**
 * The texts Shadertoy compiles for the export's passes (Buffer A and Image, each after Common),
 * with the page's host block (its controls: none here).
 */
function composedTexts({ common, bufferA, image }) {
  const hostBlock = hostControlBlock([]);
  return [
    composePassShader(bufferA, { common, hostBlock, kind: 'buffer', name: 'Buffer A' }).code,
    composePassShader(image, { common, hostBlock, kind: 'image', name: 'Image' }).code,
  ];
}

/** Opens the page, records its compiles, and runs the export of these tabs. */
async function runTabs(page, goto, tabs) {
  await goto(`?${SIZE}`);
  await recordCompiledSources(page);
  await takeCompiledSources(page);
  return hook(page).setProject(exportOf(tabs));
}

const DRAWS = [
  {
    name: 'a Buffer tab with `#include <iostream>` inside a /* */ comment',
    tabs: { common: PLAIN_COMMON, bufferA: INCLUDE_IN_COMMENT, image: SHOW_BUFFER_A },
    expected: () => [40, 80, 120],
  },
  {
    name: 'an Image tab with a `#pragma unroll_loop_start` … `unroll_loop_end` loop, left a loop',
    tabs: { common: PLAIN_COMMON, bufferA: PLAIN_BUFFER, image: UNROLL_PRAGMAS },
    expected: () => [102, 0, 0],
  },
  {
    name: 'the supersampling macro in Common, renaming the Image tab’s mainImage',
    tabs: { common: SUPERSAMPLE, bufferA: PLAIN_BUFFER, image: EDGE_AT_CENTRES },
    expected: supersampledEdge,
  },
];

describe('a pass reaches WebGL as the site composes it', () => {
  test.each(DRAWS)('$name: compiles, draws, and WebGL gets the composed text byte for byte', async ({ tabs, expected }) => {
    await withPage(async ({ page, goto }) => {
      const outcome = await runTabs(page, goto, tabs);
      expect(outcome.error ?? null).toBe(null);
      expect((await takeCompiledSources(page)).sort()).toEqual(composedTexts(tabs).sort());
      const image = await readPixels(page);
      for (const [x, y] of [
        [0, 0],
        [7, 5],
        [31, 17],
      ]) {
        expect(pixel(image, x, image.height - 1 - y), `pixel (${x}, ${y}) from the bottom`).toEqual(expected(x, y));
      }
    });
  });
});

const ERRORS = [
  {
    name: 'Buffer A, after an #include in a comment',
    tabs: { common: PLAIN_COMMON, bufferA: INCLUDE_IN_COMMENT.replace('vec4(40.0', 'vec4(undeclaredInBuffer'), image: SHOW_BUFFER_A },
    at: 'Buffer A:5',
    identifier: 'undeclaredInBuffer',
  },
  {
    name: 'Common, after the supersampling macro',
    tabs: { common: `${SUPERSAMPLE}float broken() { return undeclaredInCommon; }\n`, bufferA: PLAIN_BUFFER, image: EDGE_AT_CENTRES },
    at: 'Common:2',
    identifier: 'undeclaredInCommon',
  },
  {
    name: 'Image, after an unroll_loop block',
    tabs: { common: PLAIN_COMMON, bufferA: PLAIN_BUFFER, image: UNROLL_PRAGMAS.replace('sum * 17.0', 'sum * undeclaredInImage') },
    at: 'Image:8',
    identifier: 'undeclaredInImage',
  },
];

describe("a compile error is at the user's line", () => {
  test.each(ERRORS)('$name: the error is at $at', async ({ tabs, at, identifier }) => {
    await withPage(async ({ page, goto }) => {
      const outcome = await runTabs(page, goto, tabs);
      const report = String(outcome.error ?? '');
      // the report's message lines (each followed by the offending line, indented)
      const messages = report.split('\n').filter((line) => line && !line.startsWith('    '));
      // every message names a tab and a line in it (the driver warns of the unroll pragmas, which GLSL ignores)
      for (const message of messages) expect(message, report).toMatch(/^(Common|Buffer A|Image):\d+: (error|warning): /);
      const errors = messages.filter((message) => message.includes(': error: '));
      expect(errors.length, report).toBeGreaterThan(0);
      for (const error of errors) expect(error, report).toMatch(new RegExp(`^${at}: error: `));
      expect(report).toContain(identifier);
    });
  });
});
