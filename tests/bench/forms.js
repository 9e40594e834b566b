// The shader's SwiftShader forms against the branchy forms a GPU rewards, in the shader itself,
// on both CPU renderers interleaved. SwiftShader runs both sides of every `if` and a loop's body
// at least once (branches.js); the shader is written for that (its header: selects, all() and
// any() instead of && and ||, no early returns, every object asked for every ray). Each row here
// is the project's text with one family of those forms turned back into branches, timed beside
// the shader as it is, so that a form is chosen by what it costs on each renderer.
//
//   npm run bench:forms                       640x360, both CPU renderers, 3 compilations x 5
//                                             frames; writes the table between the forms
//                                             markers in docs/benchmark.md
//   npm run bench:forms -- --quick            every variant once at 160x90, nothing written (CI)
//   npm run bench:forms -- --renderer NAME    one renderer (renderer-set.js), nothing written
//   npm run bench:forms -- --frames N         N timed frames a compilation
//
// An edit must apply (variant-text.js edit): a renamed function fails the script instead of
// timing the shader twice.

import fs from 'node:fs';
import path from 'node:path';
import { REPO_ROOT, SHADER_FILE } from '../support/config.js';
import { rendererLabel } from '../../src/headless/browser.js';
import { replaceMarkedSection } from '../scripts/readme-section.js';
import { measureScript, pairedRatio } from './measure.js';
import { CPU_RENDERERS, RENDERER_TITLES } from './renderer-set.js';
import { branchyConditions, edit } from './variant-text.js';
import { pasteFormOf } from './variant-text.js';

const argv = process.argv.slice(2);
const quick = argv.includes('--quick');
const source = fs.readFileSync(SHADER_FILE, 'utf8');
const pasteForm = pasteFormOf(source);

/** Early returns: each intersector leaves as soon as its ray is known to miss. */
function earlyReturns(text) {
  let out = edit(
    text,
    '    float q = -b - (b >= 0.0 ? 1.0 : -1.0) * sqrt(max(disc, 0.0));\n    float c = dot(f, f) - radius * radius;',
    '    if (disc < 0.0) return MISS;\n    float q = -b - (b >= 0.0 ? 1.0 : -1.0) * sqrt(max(disc, 0.0));\n    float c = dot(f, f) - radius * radius;',
  );
  out = edit(
    out,
    '    bool outside = tEnter > 0.0;\n',
    '    if (tEnter > tExit || tExit <= 0.0) return MISS;\n    bool outside = tEnter > 0.0;\n',
  );
  out = edit(
    out,
    '                             along + cone.boundRadius > 0.0, tShift < tMax));\n',
    '                             along + cone.boundRadius > 0.0, tShift < tMax));\n    if (!inBound) return MISS;\n',
  );
  return edit(out, '    hi = all(bvec2(inBound, inRange)) ? hi : lo;\n', '    if (!(inBound && inRange)) return MISS;\n');
}

/** The new object asked only by rays that meet its bounding sphere (the skip a GPU rewards). */
function boundingSkip(text) {
  const call = '    hit = nearer(hit, intersectObject(ro, rd, s.object, skipId == ID_OBJECT ? 0.0 : hit.t), ID_OBJECT);\n';
  return edit(
    edit(
      text,
      '// ---- the scene -----',
      [
        '#if SCENE == 2',
        'bool meetsBound(vec3 ro, vec3 rd, Object o, float tMax) { return shiftToBound(ro, rd, o.center, o.boundRadius, tMax).y > 0.0; }',
        '#else',
        'bool meetsBound(vec3 ro, vec3 rd, Object o, float tMax) { return shiftToBound(ro, rd, o.boundCenter, o.boundRadius, tMax).y > 0.0; }',
        '#endif',
        '// ---- the scene -----',
      ].join('\n'),
    ),
    call,
    `    if (meetsBound(ro, rd, s.object, hit.t)) {\n    ${call}    }\n`,
  );
}

/** The adaptive frame's extra samples in a loop of their own, entered only by a marked pixel. */
function extraSamplesApart(text) {
  return edit(
    text,
    '        pixelColor = i <= 1 ? c : pixelColor + c;\n        if (any(bvec2(!edge, i == N * N))) break;\n    }\n',
    [
      '        pixelColor = c;',
      '        break;',
      '    }',
      '    if (edge) {',
      '        pixelColor = vec3(0.0);',
      '        for (int k = 0; k < N * N; k++) {',
      '            vec2 offset = (vec2(k % N, k / N) + 0.5) / float(N) - 0.5;',
      '            pixelColor += radiance(s, eyeRay(camera, fragCoord + offset, 1.0 / float(N)), pixelSpread / float(N), key, keyNormal);',
      '        }',
      '    }',
      '',
    ].join('\n'),
  );
}

const ADAPTIVE = { SAMPLES: 16, ADAPTIVE_AA: 1 };
const TORUS = { SCENE: 2 };
// base: the row each is compared with (the shader as it is, in the same scene and settings).
const VARIANTS = [
  { name: 'the shader as it is (default scene, 1 spp)', base: 0, code: () => pasteForm(source) },
  { name: '&& and || where it has all() and any()', base: 0, code: () => pasteForm(branchyConditions(source)) },
  { name: 'early returns in the intersectors', base: 0, code: () => pasteForm(earlyReturns(source)) },
  { name: 'the cone behind a bounding-sphere if', base: 0, code: () => pasteForm(boundingSkip(source)) },
  { name: 'the shader as it is (torus scene, 1 spp)', base: 4, scene: 2, code: () => pasteForm(source, TORUS) },
  { name: 'torus scene: early returns in the intersectors', base: 4, scene: 2, code: () => pasteForm(earlyReturns(source), TORUS) },
  { name: 'torus scene: the torus behind a bounding-sphere if', base: 4, scene: 2, code: () => pasteForm(boundingSkip(source), TORUS) },
  { name: 'the shader as it is (adaptive 16 at edges)', base: 7, code: () => pasteForm(source, ADAPTIVE) },
  {
    name: 'adaptive: the extra samples in a loop only marked pixels enter',
    base: 7,
    code: () => pasteForm(extraSamplesApart(source), ADAPTIVE),
  },
];

const { renderers, results, width, height, copies: COPIES, frames: FRAMES } = await measureScript('forms', VARIANTS, source, argv);
const agreed = (values) => (new Set(values).size === 1 ? values[0] : values.join(' / '));
const rows = VARIANTS.map((variant, i) => {
  const cells = results.flatMap(({ measured }) => {
    const m = measured[i];
    const ratio = i === variant.base ? '' : `${pairedRatio(m, measured[variant.base]).toFixed(2)}×`;
    return [`${m.medianMs.toFixed(1)} (${m.minMs.toFixed(1)}–${m.maxMs.toFixed(1)})`, ratio];
  });
  const rmse = agreed(results.map(({ measured }) => measured[i].rmse.toFixed(4)));
  return `| ${variant.name} | ${cells.join(' | ')} | ${rmse} |`;
});
const header = ['form', ...results.flatMap(({ name }) => [`${RENDERER_TITLES[name]} ms`, '× as it is']), 'RMSE'];
const table = [
  `Measured by \`npm run bench:forms\` on ${results.map((r) => rendererLabel(r.environment.renderer)).join(' and ')}, ${results[0].environment.chromium}, ${width}×${height}: median (min–max) of ${COPIES * FRAMES} frames (${COPIES} compilations × ${FRAMES}), all rows interleaved in one page per renderer${results.length > 1 ? ', the renderers round by round' : ''}. *× as it is*: the median over the rounds of the row's frame over the same round's frame of the shader as it is (the row above it that says so). RMSE against the converged float64 reference of the row's scene (one value where the renderers agree to the digits shown).`,
  '',
  `| ${header.join(' | ')} |`,
  `|${header.map((_, i) => (i === 0 ? '---|' : '---:|')).join('')}`,
  ...rows,
].join('\n');
console.log(`\n${table}`);
if (quick) {
  console.log(`\nquick run: all ${VARIANTS.length} forms compiled, rendered and measured on ${renderers.join(' and ')}; nothing written.`);
} else if (renderers.join() === CPU_RENDERERS.join()) {
  replaceMarkedSection(path.join(REPO_ROOT, 'docs', 'benchmark.md'), 'forms', table);
  console.log('\nwrote the forms table in docs/benchmark.md');
}
