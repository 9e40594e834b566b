// What does a CPU renderer skip? The experiments behind the shader's structure (docs/benchmark.md,
// "What the CPU renderers reward"): the same 60 sin() calls run straight, behind an `if` that no
// pixel takes (decided per pixel, and on a uniform), and in loops of 0, 1 and 2 trips written two
// ways (condition at the top, as a `for` reads; exit at the bottom, as the shader's loops are
// written); conditions joined with && and with all(); then the project's shader with one extra
// radiance() call behind `if (iFrame < 0)`, which never runs. On a GPU the guarded versions cost
// next to nothing. On SwiftShader (2x2 quads as SIMD lanes) an `if` costs its whole body and a
// loop one body per trip, plus one more when the condition is tested at the top; this measures
// whether llvmpipe (8 lanes) does the same.
//
//   npm run bench:branches                        both CPU renderers, interleaved; 640x360,
//                                                 median of 15 frames; writes the table between
//                                                 the branches markers in docs/benchmark.md
//   npm run bench:branches -- --renderer NAME     one renderer (renderer-set.js), nothing written

import fs from 'node:fs';
import { composeImageShader, hostControlBlock } from '../../src/shadertoy/header.js';
import { controlDefaults, parseControls } from '../../src/shadertoy/controls.js';
import { median } from '../../src/shared/stats.js';
import path from 'node:path';
import { REPO_ROOT, SHADER_FILE } from '../support/config.js';
import { rendererLabel } from '../../src/headless/browser.js';
import { replaceMarkedSection } from '../scripts/readme-section.js';
import { CPU_RENDERERS, RENDERER_TITLES, renderersAsked, withRenderers } from './renderer-set.js';
import { timeShadersOn } from './timer.js';
import { pairedRatio } from './measure.js';

const CALLS = 60;
const body = Array.from({ length: CALLS }, (_, i) => `        x = sin(x * 1.${i % 10} + 0.${i % 7});`).join('\n');
// `never` is false for every pixel, but the compiler cannot know it.
const image = (code) =>
  composeImageShader(
    `void mainImage(out vec4 c, in vec2 f) {\n    float x = f.x * 0.001;\n    bool never = f.x < -1.0;\n${code}\n    c = vec4(x);\n}\n`,
  ).code;
const topLoop = (trips) => image(`    int n = never ? 7 : ${trips};\n    for (int k = 0; k < n; k++) {\n${body}\n    }`);
const bottomLoop = (trips) =>
  image(`    int n = never ? 7 : ${trips};\n    for (int k = 0;; k++) {\n${body}\n        if (k + 1 >= n) break;\n    }`);
// Sixty tests of four conditions each, joined with && or with all(bvec4(...)).
const tests = (join) =>
  Array.from(
    { length: CALLS },
    (_, i) =>
      `        { float u = x * 1.${i % 10} + 0.1; bool b = ${join(['u > 0.1', 'u < 0.9', 'x > 0.05', 'x < 0.5'])}; x = fract(x + (b ? u : -u)); }`,
  ).join('\n');
const project = fs.readFileSync(SHADER_FILE, 'utf8');
// The project at one sample per pixel: its controls at their defaults but for the samples.
const controls = parseControls(project);
const onePixelSample = (text) =>
  composeImageShader(text, { hostBlock: hostControlBlock(controls, { SAMPLES: 1, ADAPTIVE_AA: 0 }, controlDefaults(controls)) }).code;
const call = '    vec3 pixelColor = sampleRadiance(view, fragCoord, 1.0, key, keyNormal);';
if (!project.includes(call)) throw new Error(`branches: ${SHADER_FILE} no longer has "${call.trim()}"`);

// [what it is, the shader, the row it is compared with (its frame over that row's frame in the
// same round, the median over the rounds), if any]
/** @type {Array<[string, string, number?]>} */
const CASES = [
  [`${CALLS} sin() calls, straight`, image(body)],
  ['the same behind if (never)', image(`    if (never) {\n${body}\n    }`), 0],
  ['the same behind if (iFrame < 0): a uniform condition', image(`    if (iFrame < 0) {\n${body}\n    }`), 0],
  ['in a for loop with the condition at the top, 0 trips', topLoop(0), 0],
  ['the same, 1 trip', topLoop(1), 0],
  ['the same, 2 trips', topLoop(2), 0],
  ['in a loop with the exit at the bottom, 1 trip', bottomLoop(1), 0],
  ['the same, 2 trips', bottomLoop(2), 0],
  [`${CALLS} tests of four conditions joined with all(bvec4(...))`, image(tests((c) => `all(bvec4(${c.join(', ')}))`))],
  ['the same joined with &&', image(tests((c) => c.join(' && '))), 8],
  ['the project shader (one sample per pixel)', onePixelSample(project)],
  [
    'the same + radiance() behind if (iFrame < 0)',
    onePixelSample(
      project.replace(call, `${call}\n    if (iFrame < 0) pixelColor += sampleRadiance(view, fragCoord.yx, 1.0, key, keyNormal);`),
    ),
    10,
  ],
];

const FRAMES = 15;
let renderers;
try {
  renderers = renderersAsked(process.argv.slice(2));
} catch (error) {
  console.error(`npm run bench:branches -- ${error.message}`);
  process.exit(1);
}
const measured = await withRenderers(renderers, async (started) => {
  const runs = await timeShadersOn(
    started,
    CASES.map(([, code]) => ({ code })),
    { width: 640, height: 360, frames: FRAMES, warmup: 2 },
  );
  return started.map((r, i) => ({ environment: r.environment, name: r.name, runs: runs[i] }));
});
for (const { name, runs } of measured)
  runs.forEach((r, i) => {
    if (r.error) throw new Error(`${CASES[i][0]} on ${name}: ${r.error}`);
  });
const cell = (times) => `${median(times).toFixed(1)} (${Math.min(...times).toFixed(1)}–${Math.max(...times).toFixed(1)})`;
const ratio = (runs, i) => {
  const base = CASES[i][2];
  return base === undefined ? '' : `${pairedRatio({ rounds: [runs[i].times] }, { rounds: [runs[base].times] }).toFixed(2)}×`;
};
const table = [
  `Measured by \`npm run bench:branches\` at 640×360 on ${measured.map((m) => rendererLabel(m.environment.renderer)).join(' and ')}, ${measured[0].environment.chromium}: median (min–max) of ${FRAMES} frames in ms${measured.length > 1 ? ', the renderers interleaved round by round' : ''}; *×*: the median over the rounds of the row's frame over the same round's frame of the row it is compared with (60 sin() calls straight; the conditions joined with all(); the project shader).`,
  '',
  `| form | ${measured.map((m) => `${RENDERER_TITLES[m.name]} ms | ×`).join(' | ')} |`,
  `|---|${measured.map(() => '---:|---:|').join('')}`,
  ...CASES.map(([label], i) => `| ${label} | ${measured.map((m) => `${cell(m.runs[i].times)} | ${ratio(m.runs, i)}`).join(' | ')} |`),
].join('\n');
console.log(table);
if (renderers.join() === CPU_RENDERERS.join()) {
  replaceMarkedSection(path.join(REPO_ROOT, 'docs', 'benchmark.md'), 'branches', table);
  console.log('\nwrote the branches table in docs/benchmark.md');
}
