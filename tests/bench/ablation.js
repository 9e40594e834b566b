// Where the default frame's time goes: the project at 1 sample per pixel with one feature
// switched off at a time, beside the standalone plain peer (peers/standalone.glsl, which has none
// of them), all timed in one page at 640x360, interleaved, and each compared with the converged
// float64 reference. What a feature costs is the project's time less the variant's; what it buys
// is the error it removes (and, for some, what no RMSE shows: see each row's note).
//
//   npm run bench:ablation              640x360 on SwiftShader and llvmpipe, interleaved round by
//                                       round, 3 compilations x 5 frames each; writes the table
//                                       between the ablation markers in docs/benchmark.md
//   npm run bench:ablation -- --quick   every variant once at 160x90, nothing written (CI)
//   npm run bench:ablation -- --renderer NAME
//                                       one renderer (renderer-set.js), nothing written
//   npm run bench:ablation -- --frames N
//                                       N timed frames a compilation (5 unless said), for a
//                                       machine too busy for 15 frames to settle a median
//
// Each variant is the project's text with one edit, and the edit must apply: a renamed function
// fails the script instead of timing the project twice.

import fs from 'node:fs';
import path from 'node:path';
import { composeImageShader } from '../../src/shadertoy/header.js';
import { REPO_ROOT, SHADER_FILE } from '../support/config.js';
import { rendererLabel } from '../../src/headless/browser.js';
import { replaceMarkedSection } from '../scripts/readme-section.js';
import { replaceFunction } from '../support/tables/intersector-naive.js';
import { composePeer } from './peers/compose-peer.js';
import { measureScript, pairedRatio } from './measure.js';
import { CPU_RENDERERS, RENDERER_TITLES } from './renderer-set.js';
import { edit, pasteFormOf } from './variant-text.js';

const quick = process.argv.includes('--quick');
const BENCH_DIR = path.join(REPO_ROOT, 'tests', 'bench');
const read = (file) => fs.readFileSync(file, 'utf8');
const source = read(SHADER_FILE);
const pasteForm = pasteFormOf(source);

/** iq's sphere, box, plane and cone (peers/iq/, early returns, textbook roots) in the scene walk. */
function iqIntersectors(text) {
  const iq = ['plane', 'sphere', 'box', 'cone']
    .map((name) => read(path.join(BENCH_DIR, 'peers', 'iq', `${name}.glsl`)).replace(/^#define .*$/gm, ''))
    .join('\n');
  let out = edit(text, '// ---- the new object ----', `${iq}\n// ---- the new object ----`);
  out = edit(out, 'intersectPlane(ro, rd, s.ground,', 'iqPlane(ro, rd, s.ground,');
  out = edit(out, 'intersectSphere(ro, rd, s.sphereCenter,', 'iqSphere(ro, rd, s.sphereCenter,');
  out = edit(out, 'intersectBox(ro, rd, s.cubeCenter,', 'iqBox(ro, rd, s.cubeCenter,');
  return edit(
    out,
    'return intersectCone(ro, rd, cone, tMax);',
    'return iqCone(ro, rd, IqCone(cone.base, cone.base + cone.axis * cone.height, cone.ra, cone.rb), tMax);',
  );
}

const PROJECT = 'the project, 1 spp';
const STANDALONE = 'standalone plain peer';
// feature: what is switched off; buys: what the project gets for it (beyond the RMSE column).
const VARIANTS = [
  { name: PROJECT, buys: '', code: () => pasteForm(source) },
  {
    name: STANDALONE,
    buys: 'none of the features below; point-sampled stripes (moiré at the horizon)',
    code: () => composeImageShader(read(path.join(BENCH_DIR, 'peers', 'standalone.glsl'))).code,
  },
  {
    name: 'texture filter and ray differentials off',
    buys: 'the stripes filtered over each footprint: no moiré, no crawling when the camera turns',
    code: () => pasteForm(source, { TEXTURE_FILTER: 0 }),
  },
  {
    name: "iq's intersectors (early returns, textbook roots)",
    buys: 'exact hard cases: far, thin, grazing and inside rays (docs/numerics.md: the iq forms get many wrong)',
    code: () => pasteForm(iqIntersectors(source)),
  },
  {
    name: 'sinCos: built-in sin and cos',
    buys: "a camera turned by the angle asked: SwiftShader's built-ins are off by ~1e-4, half a pixel at 640x360",
    code: () =>
      pasteForm(
        replaceFunction(source, 'vec2 sinCos(float angle) {', 'vec2 sinCos(float angle) {\n    return vec2(sin(angle), cos(angle));\n}\n'),
      ),
  },
  {
    name: 'ground band off',
    buys: "faces in the ground's plane (the cone's base, the cube's bottom) drawn as ground from below, not speckled",
    code: () =>
      pasteForm(edit(source, 'float band = GROUND_BAND_ULPS * EPS32 * (ground.x + maxAbs(ro) + abs(s.ground.w));', 'float band = 0.0;')),
  },
  {
    name: 're-projection and ulp offsets off',
    buys: 'no acne or speckle in shadows and reflections from hit points off their surface',
    code: () =>
      pasteForm(
        replaceFunction(
          replaceFunction(
            source,
            'vec3 reprojectOnSurface(Scene s, vec3 p, vec3 n, int id) {',
            'vec3 reprojectOnSurface(Scene s, vec3 p, vec3 n, int id) {\n    return p;\n}\n',
          ),
          'vec3 offsetByUlps(vec3 p, vec3 n, float ulps) {',
          'vec3 offsetByUlps(vec3 p, vec3 n, float ulps) {\n    return p;\n}\n',
        ),
      ),
  },
  {
    name: 'no 1/255 cut-off',
    buys: 'time: a path whose weight left cannot change the 8-bit output ends there',
    code: () => pasteForm(edit(source, 'throughput * mirror < 1.0 / 255.0', 'throughput * mirror < 0.0')),
  },
  {
    name: 'one trace site (alternating loop)',
    buys: '(the project has three trace sites: the eye ray before the loop, shadow and reflection rays in it)',
    code: () =>
      pasteForm(composePeer(source, read(path.join(BENCH_DIR, 'peers', 'one-trace-site.glsl')), { peerName: 'one-trace-site.glsl' })),
  },
  {
    name: 'savings off (loop tested at the top, && shadow ray, no cut-off)',
    buys: 'time: the structure that does only the work a pixel needs',
    code: () => pasteForm(composePeer(source, read(path.join(BENCH_DIR, 'peers', 'savings-off.glsl')), { peerName: 'savings-off.glsl' })),
  },
];

const argv = process.argv.slice(2);
const { renderers, results, width, height, copies: COPIES, frames: FRAMES } = await measureScript('ablation', VARIANTS, source, argv);
for (const { name, measured } of results) {
  console.log(`on ${RENDERER_TITLES[name]}:`);
  for (const m of measured)
    console.log(`  ${m.variant.name}: ${m.medianMs.toFixed(1)} ms, RMSE ${m.rmse.toFixed(4)}, >2/255 ${(100 * m.over2).toFixed(2)}%`);
}
if (quick) {
  console.log(
    `\nquick run: all ${VARIANTS.length} ablation variants compiled, rendered and measured on ${renderers.join(' and ')}; nothing written.`,
  );
  process.exit(0);
}
const agreed = (values) => (new Set(values).size === 1 ? values[0] : values.join(' / '));
const rows = VARIANTS.map((variant, i) => {
  const cells = results.flatMap(({ measured }) => {
    const m = measured[i];
    const project = measured[0];
    const change =
      i === 0
        ? ''
        : `${project.medianMs >= m.medianMs ? '−' : '+'}${Math.abs(project.medianMs - m.medianMs).toFixed(1)} ms, ${pairedRatio(m, project).toFixed(2)}×`;
    return [`${m.medianMs.toFixed(1)} (${m.minMs.toFixed(1)}–${m.maxMs.toFixed(1)})`, change];
  });
  const rmse = agreed(results.map(({ measured }) => measured[i].rmse.toFixed(4)));
  const over2 = agreed(results.map(({ measured }) => `${(100 * measured[i].over2).toFixed(2)}%`));
  return `| ${variant.name} | ${cells.join(' | ')} | ${rmse} | ${over2} | ${variant.buys} |`;
});
const header = [
  'variant',
  ...results.flatMap(({ name }) => [`${RENDERER_TITLES[name]} ms`, 'change']),
  'RMSE',
  '>2/255',
  'what the feature buys',
];
const table = [
  `Measured by \`npm run bench:ablation\` on ${results.map((r) => rendererLabel(r.environment.renderer)).join(' and ')}, ${results[0].environment.chromium}, ${width}×${height}, the default view at 1 sample per pixel: median (min–max) of ${COPIES * FRAMES} frames (${COPIES} compilations × ${FRAMES}), all variants interleaved in one page${results.length > 1 ? ' per renderer, the renderers round by round' : ''}; error against the converged float64 reference (64 spp; one value where the renderers agree to the digits shown). *Change*: the variant's time less the project's (− is time the feature costs), and the median over the rounds of the variant's frame over the project's in the same round.`,
  '',
  `| ${header.join(' | ')} |`,
  `|${header.map(() => '---|').join('')}`,
  ...rows,
].join('\n');
console.log(`\n${table}`);
if (renderers.join() === CPU_RENDERERS.join()) {
  replaceMarkedSection(path.join(REPO_ROOT, 'docs', 'benchmark.md'), 'ablation', table);
  console.log('\nwrote the ablation table in docs/benchmark.md');
}
