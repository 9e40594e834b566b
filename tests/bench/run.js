// The benchmark: speed against error, for the project's shader across its quality controls, in
// the page's uniform form, with its savings switched off (savings-off.glsl), an empty shader
// (the floor), and four peers (tests/bench/peers/): the assignment's algorithm, sphere tracing,
// a plain analytic tracer spliced into the project's file, and a standalone plain tracer that
// shares no line with the project (standalone.glsl: what the project's structure costs).
//
//   npm run bench              640x360 and 1280x720, 15 timed frames after 3 warm-up frames
//   npm run bench -- --report  the tables, chart and docs/benchmark.md section again from results.json
//   npm run bench -- --quick   every variant once at 160x90 (CI runs this so the benchmark
//                              cannot rot; it asserts no time and writes no results)
//   npm run bench -- --gpu     the same on the machine's own GPU instead of SwiftShader (with
//                              --quick too); it prints the GPU's renderer string, stops with an
//                              error if WebGL2 is missing or a software renderer, and writes
//                              tests/bench/results-gpu.json and results-gpu.md only
//   npm run bench -- --only 'project, 1 spp' --only standalone
//                              only the variants whose name contains one of the --only strings
//                              (add --size 640x360 for one size)
//                              (with --quick or --gpu too): their times and errors printed,
//                              interleaved as in a full run; no targets, nothing written
//
// Each variant is compiled inside Shadertoy's header and timed in headless Chromium on
// SwiftShader (tests/harness/, and timer.js: all variants in one page, interleaved round by
// round, a frame being a draw plus a 1-pixel read-back, so the rendering is what is timed). Its
// last frame is compared with the converged float64 reference
// of the project's scene at its default settings (src/reference/, 64 jittered samples per pixel
// at both sizes, texture point-sampled, so that every variant is ranked at both): RMSE and the fraction of pixels off by
// more than 2/255 (src/reference/error.js). Writes tests/bench/results.json, results.md, chart.svg, and
// the table in docs/benchmark.md.

import fs from 'node:fs';
import path from 'node:path';
import { composeImageShader, hostControlBlock } from '../../src/shadertoy/header.js';
import { parseControls } from '../../src/shadertoy/controls.js';
import { REPO_ROOT, SHADER_FILE } from '../harness/config.js';
import { rendererLabel } from '../../src/engine/browser.js';
import { withHarness } from '../harness/setup.js';
import { replaceMarkedSection } from '../scripts/readme-section.js';
import { measureVariants } from './measure.js';
import { renderRawShader } from '../harness/raw-webgl.js';
import { EXTRA_SAMPLES_VIEW, countExtraSamplePixels } from '../../src/raytracer/extra-samples.js';
import { composePeer } from './peers/compose-peer.js';
import { paretoFront, chartSvg } from './chart.js';
import {
  ONE_TRACE_SITE,
  PAGE_FORM,
  PLAIN,
  SAVINGS_OFF,
  SCENES_GROUP,
  STANDALONE,
  sceneVariant,
  adaptiveSamples,
  evaluateAdaptiveTargets,
  evaluateSceneTargets,
  evaluateTargets,
  sphereTracing,
  uniformSamples,
} from './targets.js';

const quick = process.argv.includes('--quick');
// --report: the tables, chart and docs/benchmark.md section again from the last results.json, nothing measured.
const reportOnly = process.argv.includes('--report');
// --gpu: the machine's own GPU (startHarness({ gpu: true })), into files of its own, so that the
// SwiftShader results, chart and docs/benchmark.md table are never overwritten by a GPU run.
const gpu = process.argv.includes('--gpu');
// --only NAME (any number of times): the variants whose name contains one of them (a timed
// comparison of a few, side by side). Names hold commas, so each string is a flag of its own.
const onlyParts = process.argv.flatMap((arg, i) => (arg === '--only' ? [process.argv[i + 1] ?? ''] : []));
const only = onlyParts.length ? onlyParts : null;
if (only?.some((part) => !part || part.startsWith('--'))) {
  console.error("npm run bench -- --only: each --only takes a part of a variant's name, e.g. --only 'project, 1 spp'");
  process.exit(1);
}
const OUTPUT = gpu
  ? {
      json: 'results-gpu.json',
      markdown: 'results-gpu.md',
      chart: null,
      readme: false,
      written: 'tests/bench/results-gpu.json and results-gpu.md',
    }
  : {
      json: 'results.json',
      markdown: 'results.md',
      chart: 'chart.svg',
      readme: true,
      written: 'tests/bench/results.json, results.md, chart.svg and the table in docs/benchmark.md',
    };
/** withHarness, on the GPU with --gpu (its renderer printed); with no hardware GPU, a clear stop. */
async function withBenchHarness(body) {
  try {
    return await withHarness(
      async (context) => {
        if (gpu) console.log(`GPU renderer: ${context.environment.renderer} (${context.environment.chromium})`);
        return body(context);
      },
      { gpu },
    );
  } catch (error) {
    if (error.code !== 'NO_HARDWARE_GPU') throw error;
    console.error(
      `\nnpm run bench -- --gpu: ${error.message}\nNothing was measured. The default benchmark, on SwiftShader, is \`npm run bench\`.`,
    );
    process.exit(1);
  }
}
// --size WxH: that size alone (with --only: a quicker comparison; a full run keeps both sizes).
const sizeArg = process.argv[process.argv.indexOf('--size') + 1];
const sizeMatch = process.argv.includes('--size') ? /^(\d+)x(\d+)$/.exec(sizeArg ?? '') : null;
if (process.argv.includes('--size') && !sizeMatch) {
  console.error(`npm run bench -- --size: expected WxH such as 640x360, got "${sizeArg ?? ''}"`);
  process.exit(1);
}
if (sizeMatch && !only) {
  console.error('npm run bench -- --size: only with --only (a full run measures both sizes, as its tables show)');
  process.exit(1);
}
const SIZES = sizeMatch
  ? [[Number(sizeMatch[1]), Number(sizeMatch[2])]]
  : quick
    ? [[160, 90]]
    : [
        [640, 360],
        [1280, 720],
      ];
// Each variant is compiled COPIES times (the copies differ by a comment) and timed as separate
// programs, their frames pooled: on SwiftShader one compilation of a shader can run 20-40%
// slower than another of the same text, for as long as it lives (seen for the project's shader:
// 34.3, 34.0, 33.9 ms for three copies in one run, 34.8 and 41.7 in another), so one program a
// variant would rank variants by luck.
const COPIES = quick ? 1 : 3;
const FRAMES = quick ? 1 : 5; // timed frames per copy
const WARMUP = quick ? 1 : 2; // per copy
const REFERENCE_SAMPLES_PER_AXIS = () => (quick ? 2 : 8);
const BENCH_DIR = path.join(REPO_ROOT, 'tests', 'bench');
const read = (file) => fs.readFileSync(file, 'utf8');

const source = read(SHADER_FILE);
const controls = parseControls(source);
const uniformValues = controls.filter((c) => c.kind === 'uniform').map((c) => ({ name: c.name, type: c.type, value: c.default }));
const defaults = Object.fromEntries(controls.map((c) => [c.name, c.default]));

// Every variant is compiled in the paste form (the live controls as constants with their
// default values: the shader as Shadertoy compiles it, and as the page runs it while its
// controls rest) but the one marked `uniforms`, the page's form while a control moves.
const pasteForm = (text, defines = {}, extra = '') =>
  composeImageShader(text, { hostBlock: hostControlBlock(controls, defines, defaults) + extra }).code;
/** The project's shader with some compile-time controls changed; one sample per pixel unless they say otherwise. */
const ONE_SAMPLE = { SAMPLES: 1, ADAPTIVE_AA: 0 };
const project = (defines = {}) => pasteForm(source, { ...ONE_SAMPLE, ...defines });
const composed = (file, dir = path.join(BENCH_DIR, 'peers')) => composePeer(source, read(path.join(dir, file)), { peerName: file });
const peer = (file, extra = '') => pasteForm(composed(file), ONE_SAMPLE, extra);
const EMPTY = composeImageShader(
  'void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n    fragColor = vec4(0.5, 0.5, 0.5, 1.0);\n}\n',
).code;

// group: which series a variant belongs to on the chart; spp: samples per pixel.
export const ALL_VARIANTS = [
  { name: 'empty shader (floor)', group: 'floor', spp: 1, code: () => EMPTY },
  ...[1, 4, 9, 16].map((spp) => ({
    name: uniformSamples(spp),
    group: 'project: samples',
    spp,
    code: () => project({ SAMPLES: spp, ADAPTIVE_AA: 0 }),
  })),
  // Adaptive anti-aliasing: spp is what an edge pixel gets; the others take one sample.
  ...[4, 9, 16].map((spp) => ({
    name: adaptiveSamples(spp),
    group: 'project: adaptive',
    spp,
    adaptive: true,
    code: () => project({ SAMPLES: spp, ADAPTIVE_AA: 1 }),
  })),
  ...[0, 1, 2, 4].map((bounces) => ({
    name: `project, bounces ${bounces}`,
    group: 'project: bounces',
    spp: 1,
    code: () => project({ BOUNCES: bounces }),
  })),
  { name: 'project, no shadows', group: 'project: features', spp: 1, code: () => project({ SHADOWS: 0 }) },
  { name: 'project, primary rays only', group: 'project: features', spp: 1, code: () => project({ SHADOWS: 0, BOUNCES: 0 }) },
  { name: 'project, unfiltered stripes', group: 'project: features', spp: 1, code: () => project({ TEXTURE_FILTER: 0 }) },
  {
    name: PAGE_FORM,
    group: 'project: page form',
    spp: 1,
    uniforms: true,
    code: () => composeImageShader(source, { hostBlock: hostControlBlock(controls, ONE_SAMPLE) }).code,
  },
  { name: SAVINGS_OFF, group: 'project: savings off', spp: 1, code: () => pasteForm(composed('savings-off.glsl'), ONE_SAMPLE) },
  { name: ONE_TRACE_SITE, group: 'project: one trace site', spp: 1, code: () => pasteForm(composed('one-trace-site.glsl'), ONE_SAMPLE) },
  { name: 'assignment (peer 1)', group: 'peer: assignment', spp: 1, code: () => peer('assignment.glsl') },
  ...[32, 64, 128, 256].map((steps) => ({
    name: sphereTracing(steps),
    group: 'peer: sphere tracing',
    spp: 1,
    code: () => peer('sdf.glsl', `#define MAX_STEPS ${steps}\n`),
  })),
  { name: PLAIN, group: 'peer: plain analytic', spp: 1, code: () => peer('plain.glsl') },
  // A whole shader of its own, in Shadertoy's header only: none of the project's text.
  {
    name: STANDALONE,
    group: 'peer: standalone plain',
    spp: 1,
    code: () => composeImageShader(read(path.join(BENCH_DIR, 'peers', 'standalone.glsl'))).code,
  },
  // The other scenes (SCENE): their frame times, and their error against their own converged
  // reference (they are other pictures: off the chart and the Pareto front).
  ...[1, 2].map((scene) => ({
    name: sceneVariant(scene),
    group: SCENES_GROUP,
    spp: 1,
    scene,
    code: () => project({ SCENE: scene }),
  })),
];

/** The variants this run measures: all of them, or those that --only names. */
export const VARIANTS = only ? ALL_VARIANTS.filter((v) => only.some((part) => v.name.includes(part))) : ALL_VARIANTS;
if (!VARIANTS.length) {
  console.error(
    `npm run bench -- --only ${only.map((part) => JSON.stringify(part)).join(' --only ')}: no variant's name contains that; the names:\n  ${ALL_VARIANTS.map((v) => v.name).join('\n  ')}`,
  );
  process.exit(1);
}

/**
 * The fraction of pixels to which an adaptive variant gave extra samples: its "Extra samples" debug
 * view, rendered once, counted by its colours.
 */
async function extraSampleFraction(variant, width, height) {
  const shown = await renderRawShader(project({ SAMPLES: variant.spp, ADAPTIVE_AA: 1, ...EXTRA_SAMPLES_VIEW }), { width, height });
  if (shown.stage) throw new Error(`${variant.name}, edge view: ${shown.stage}: ${shown.log}`);
  return countExtraSamplePixels(shown) / (width * height);
}

async function main() {
  console.log(
    `benchmark${quick ? ' (quick)' : ''}${only ? ' (--only)' : ''}: ${VARIANTS.length} variants at ${SIZES.map((s) => s.join('x')).join(' and ')}`,
  );
  const results = reportOnly ? JSON.parse(read(path.join(BENCH_DIR, OUTPUT.json))) : [];
  const failures = [];
  if (!reportOnly)
    await withBenchHarness(async (context) => {
      for (const [width, height] of SIZES) {
        const measured = await measureVariants(VARIANTS, {
          source,
          width,
          height,
          copies: COPIES,
          frames: FRAMES,
          warmup: WARMUP,
          referenceSamplesPerAxis: REFERENCE_SAMPLES_PER_AXIS(),
          uniformValues,
        });
        for (const { variant, error: failure, ...result } of measured) {
          if (failure) {
            failures.push(`${variant.name} at ${width}x${height}: ${failure}`);
            continue;
          }
          const extra = variant.adaptive ? await extraSampleFraction(variant, width, height) : undefined;
          const entry = {
            name: variant.name,
            group: variant.group,
            width,
            height,
            samplesPerPixel: variant.spp,
            ...result,
            ...(extra === undefined ? {} : { extraSampleFraction: extra }),
            chromium: context.environment.chromium,
            renderer: context.environment.renderer,
          };
          results.push(entry);
          const extraNote = extra === undefined ? '' : `, extra samples in ${(100 * extra).toFixed(2)}% of pixels`;
          console.log(
            `  ${variant.name}: ${entry.medianMs.toFixed(1)} ms (min ${entry.minMs.toFixed(1)}), RMSE ${entry.rmse.toFixed(4)}, >2/255 ${(100 * entry.over2).toFixed(2)}%${extraNote}`,
          );
        }
      }
    });
  if (failures.length) {
    console.error(`\n${failures.length} variant(s) failed:\n  ${failures.join('\n  ')}`);
    process.exit(1);
  }
  if (quick) {
    console.log(`\nquick run: all ${VARIANTS.length} variants compiled, rendered and were measured; nothing written.`);
    return;
  }
  if (only) {
    console.log(`\n--only: ${VARIANTS.length} of ${ALL_VARIANTS.length} variants measured; no targets, nothing written.`);
    return;
  }

  if (!reportOnly) fs.writeFileSync(path.join(BENCH_DIR, OUTPUT.json), JSON.stringify(results, null, 2) + '\n');
  const [w, h] = SIZES[0];
  const atSize = (width) => results.filter((r) => r.width === width);
  // the other scenes are other pictures: not on the chart, not on the Pareto front of this one
  const sameScene = (width) => atSize(width).filter((r) => r.group !== SCENES_GROUP);
  if (OUTPUT.chart)
    fs.writeFileSync(
      path.join(BENCH_DIR, OUTPUT.chart),
      chartSvg(sameScene(w), { title: `Time against error at ${w}×${h} (SwiftShader, 2 cores)` }),
    );
  const front = new Set(paretoFront(sameScene(w)).map((r) => r.name));
  const table = (width) => {
    const rows = atSize(width);
    const floor = rows.find((r) => r.group === 'floor');
    return [
      `| variant | spp | extra samples | median ms | min–max ms | RMSE | >2/255 |${width === w ? ' Pareto |' : ''}`,
      `|---|---|---|---|---|---|---|${width === w ? '---|' : ''}`,
      ...rows.map(
        (r) =>
          `| ${r.name} | ${r.samplesPerPixel}${r.extraSampleFraction === undefined ? '' : ' at edges'} | ${r.extraSampleFraction === undefined ? '' : `${(100 * r.extraSampleFraction).toFixed(2)}% of pixels`} | ${r.medianMs.toFixed(1)} | ${r.minMs.toFixed(1)}–${r.maxMs.toFixed(1)} | ${r.rmse.toFixed(4)} | ${(100 * r.over2).toFixed(2)}% |${width === w ? (front.has(r.name) ? ' ● |' : ' |') : ''}`,
      ),
      '',
      `Floor: the empty shader takes ${floor.medianMs.toFixed(1)} ms at this size.`,
    ].join('\n');
  };
  const targets = evaluateTargets(sameScene(w));
  const sceneTargets = evaluateSceneTargets(atSize(w));
  const markdown = [
    `Measured by \`npm run bench\` on ${rendererLabel(results[0].renderer)}, ${results[0].chromium}; median of ${COPIES * FRAMES} frames (${COPIES} compilations of each variant, ${FRAMES} frames each after ${WARMUP} warm-up frames), all interleaved frame by frame. Error against the converged float64 reference of the default scene (the other scenes: against their own).`,
    '',
    `### ${w}×${h}`,
    '',
    table(w),
    '',
    `### ${SIZES[1][0]}×${SIZES[1][1]}`,
    '',
    table(SIZES[1][0]),
    '',
    `### Targets at ${w}×${h}, 1 sample per pixel`,
    '',
    ...targets.map((t) => `- ${t.met ? 'met' : '**missed**'}: ${t.text}`),
    '',
    ...SIZES.flatMap(([width, height]) => [
      `### Targets at ${width}×${height}, adaptive anti-aliasing`,
      '',
      ...evaluateAdaptiveTargets(sameScene(width)).map((t) => `- ${t.met ? 'met' : '**missed**'}: ${t.text}`),
      '',
    ]),
    `### Targets at ${w}×${h}, the scenes`,
    '',
    ...sceneTargets.map((t) => `- ${t.met ? 'met' : '**missed**'}: ${t.text}`),
  ].join('\n');
  fs.writeFileSync(path.join(BENCH_DIR, OUTPUT.markdown), markdown + '\n');
  if (OUTPUT.readme) replaceMarkedSection(path.join(REPO_ROOT, 'docs', 'benchmark.md'), 'bench', markdown);
  console.log(`\n${markdown}\n\nwrote ${OUTPUT.written}`);
}

await main();
