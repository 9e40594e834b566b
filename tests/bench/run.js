// The benchmark: speed against error, for the project's shader across its quality controls and
// its peers (variants.js), on each CPU renderer side by side: SwiftShader and llvmpipe.
//
//   npm run bench              640x360 and 1280x720, on SwiftShader and llvmpipe interleaved
//                              round by round (renderer-set.js), 3 compilations x 5 timed frames
//                              after 2 warm-up frames
//   npm run bench -- --renderer llvmpipe
//                              one renderer (swiftshader, llvmpipe or gpu; $SHADERPROOF_RENDERER
//                              too): its figures in results.json are replaced, the other's kept
//   npm run bench -- --report  the tables, charts and docs/benchmark.md section again from results.json
//   npm run bench -- --quick   every variant once at 160x90, on both renderers (CI runs this so
//                              that the benchmark cannot rot; it asserts no time and writes nothing)
//   npm run bench -- --gpu     the same as --renderer gpu: the machine's own GPU instead (with
//                              --quick too); it prints the GPU's renderer string, stops with an
//                              error if WebGL2 is missing or a software renderer, and writes
//                              tests/bench/results-gpu.json and results-gpu.md only
//   npm run bench -- --only 'project, 1 spp' --only standalone
//                              only the variants whose name contains one of the --only strings
//                              (add --size 640x360 for one size)
//                              (with --quick or --renderer too): their times and errors printed,
//                              interleaved as in a full run; no targets, nothing written
//   npm run bench -- --frames N
//                              N timed frames a compilation (5 unless said): for a busy machine
//
// Each variant is compiled inside Shadertoy's header and timed in headless Chromium (timer.js:
// all variants in one page per renderer, interleaved round by round, a frame being a draw plus a
// 1-pixel read-back, so the rendering is what is timed). Its last frame is compared with the
// converged float64 reference of the project's scene at its default settings (src/reference/,
// 64 jittered samples per pixel at both sizes, texture point-sampled, so that every variant is
// ranked at both): RMSE and the fraction of pixels off by more than 2/255
// (src/reference/error.js). Writes tests/bench/results.json (keyed by renderer: results-file.js),
// results.md, chart.svg (SwiftShader) and chart-llvmpipe.svg, and the tables in
// docs/benchmark.md (report.js).

import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { REPO_ROOT } from '../support/config.js';
import { replaceMarkedSection } from '../scripts/readme-section.js';
import { measureVariantsOn } from './measure.js';
import { renderRawShader } from '../support/raw-webgl/raw-webgl.js';
import { countExtraSamplePixels } from '../../src/raytracer/extra-samples.js';
import { chartSvg } from './chart.js';
import { ALL_VARIANTS, extraSamplesView, source, uniformValues } from './variants.js';
import { RENDERER_TITLES, renderersAsked, withRenderers } from './renderer-set.js';
import { mergeResults, readResults } from './results-file.js';
import { benchMarkdown, comparisonTable } from './report.js';
import { SCENES_GROUP } from './targets.js';

const argv = process.argv.slice(2);
const quick = argv.includes('--quick');
// --report: the tables, charts and docs/benchmark.md section again from the last results.json, nothing measured.
const reportOnly = argv.includes('--report');
/** @type {import('./renderer-set.js').RendererName[]} */
let renderers;
try {
  renderers = renderersAsked(argv);
} catch (error) {
  console.error(`npm run bench -- ${error.message}`);
  process.exit(1);
}
// the GPU's figures go into files of their own, so that the CPU renderers' results, charts and
// docs/benchmark.md table are never overwritten by a GPU run
const gpu = renderers.includes('gpu');
// --only NAME (any number of times): the variants whose name contains one of them (a timed
// comparison of a few, side by side). Names hold commas, so each string is a flag of its own.
const onlyParts = argv.flatMap((arg, i) => (arg === '--only' ? [argv[i + 1] ?? ''] : []));
const only = onlyParts.length ? onlyParts : null;
if (only?.some((part) => !part || part.startsWith('--'))) {
  console.error("npm run bench -- --only: each --only takes a part of a variant's name, e.g. --only 'project, 1 spp'");
  process.exit(1);
}
const BENCH_DIR = path.join(REPO_ROOT, 'tests', 'bench');
const OUTPUT = gpu
  ? { json: 'results-gpu.json', markdown: 'results-gpu.md', charts: false, docs: false }
  : { json: 'results.json', markdown: 'results.md', charts: true, docs: true };
// --size WxH: that size alone (with --only: a quicker comparison; a full run keeps both sizes).
const sizeArg = argv[argv.indexOf('--size') + 1];
const sizeMatch = argv.includes('--size') ? /^(\d+)x(\d+)$/.exec(sizeArg ?? '') : null;
if (argv.includes('--size') && !sizeMatch) {
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
// timed frames per copy (--frames N: more, for a busy machine)
const framesAt = argv.indexOf('--frames');
const FRAMES = quick ? 1 : framesAt >= 0 ? Number(argv[framesAt + 1]) : 5;
if (!(Number.isInteger(FRAMES) && FRAMES > 0)) {
  console.error(`npm run bench -- --frames: expected a whole number of frames, got "${argv[framesAt + 1] ?? ''}"`);
  process.exit(1);
}
const WARMUP = quick ? 1 : 2; // per copy
const REFERENCE_SAMPLES_PER_AXIS = quick ? 2 : 8;

/** The variants this run measures: all of them, or those that --only names. */
const VARIANTS = only ? ALL_VARIANTS.filter((v) => only.some((part) => v.name.includes(part))) : ALL_VARIANTS;
if (!VARIANTS.length) {
  console.error(
    `npm run bench -- --only ${only.map((part) => JSON.stringify(part)).join(' --only ')}: no variant's name contains that; the names:\n  ${ALL_VARIANTS.map((v) => v.name).join('\n  ')}`,
  );
  process.exit(1);
}

/**
 * The fraction of pixels to which an adaptive variant gave extra samples: its "Extra samples" debug
 * view, rendered once on that renderer, counted by its colours.
 */
async function extraSampleFraction(variant, width, height, on) {
  const shown = await renderRawShader(extraSamplesView(variant.spp), { width, height, on });
  if (shown.stage) throw new Error(`${variant.name}, edge view: ${shown.stage}: ${shown.log}`);
  return countExtraSamplePixels(shown) / (width * height);
}

/**
 * Every variant at every size on every renderer asked for, the renderers interleaved; their
 * results keyed by renderer (results-file.js), and the variants that failed.
 * @returns {Promise<{measured: import('./results-file.js').ResultsByRenderer, failures: string[]}>}
 */
async function measure() {
  /** @type {import('./results-file.js').Run} */
  const run = {
    started: new Date().toISOString(),
    renderers,
    cores: os.cpus().length,
    cpu: os.cpus()[0]?.model.trim() ?? 'unknown',
    loadAverage: [os.loadavg()[0]],
    copies: COPIES,
    frames: FRAMES,
    warmup: WARMUP,
  };
  const measured = Object.fromEntries(renderers.map((name) => [name, { run, results: [] }]));
  const failures = [];
  await withRenderers(renderers, async (started) => {
    for (const r of started) console.log(`${RENDERER_TITLES[r.name]}: ${r.environment.renderer} (${r.environment.chromium})`);
    for (const [width, height] of SIZES) {
      const perRenderer = await measureVariantsOn(started, VARIANTS, {
        source,
        width,
        height,
        copies: COPIES,
        frames: FRAMES,
        warmup: WARMUP,
        referenceSamplesPerAxis: REFERENCE_SAMPLES_PER_AXIS,
        uniformValues,
      });
      for (const [k, renderer] of started.entries()) {
        console.log(`  on ${RENDERER_TITLES[renderer.name]}:`);
        for (const { variant, error: failure, ...result } of perRenderer[k]) {
          if (failure) {
            failures.push(`${variant.name} at ${width}x${height} on ${renderer.name}: ${failure}`);
            continue;
          }
          const extra = variant.adaptive ? await extraSampleFraction(variant, width, height, renderer.on) : undefined;
          const entry = {
            name: variant.name,
            group: variant.group,
            width,
            height,
            samplesPerPixel: variant.spp,
            ...result,
            ...(extra === undefined ? {} : { extraSampleFraction: extra }),
            chromium: renderer.environment.chromium,
            renderer: renderer.environment.renderer,
          };
          measured[renderer.name].results.push(entry);
          const extraNote = extra === undefined ? '' : `, extra samples in ${(100 * extra).toFixed(2)}% of pixels`;
          console.log(
            `    ${variant.name}: ${entry.medianMs.toFixed(1)} ms (min ${entry.minMs.toFixed(1)}), RMSE ${entry.rmse.toFixed(4)}, >2/255 ${(100 * entry.over2).toFixed(2)}%${extraNote}`,
          );
        }
      }
    }
  });
  run.loadAverage.push(os.loadavg()[0]);
  return { measured, failures };
}

async function main() {
  console.log(
    `benchmark${quick ? ' (quick)' : ''}${only ? ' (--only)' : ''}: ${VARIANTS.length} variants at ${SIZES.map((s) => s.join('x')).join(' and ')} on ${renderers.map((r) => RENDERER_TITLES[r]).join(' and ')}`,
  );
  const file = path.join(BENCH_DIR, OUTPUT.json);
  let results = readResults(file);
  if (!reportOnly) {
    let outcome;
    try {
      outcome = await measure();
    } catch (error) {
      if (error.code !== 'NO_HARDWARE_GPU') throw error;
      console.error(
        `\nnpm run bench -- --gpu: ${error.message}\nNothing was measured. The benchmark on the CPU renderers is \`npm run bench\`.`,
      );
      process.exit(1);
    }
    if (outcome.failures.length) {
      console.error(`\n${outcome.failures.length} variant(s) failed:\n  ${outcome.failures.join('\n  ')}`);
      process.exit(1);
    }
    if (only) for (const [width] of SIZES) console.log(`\n${comparisonTable(outcome.measured, width)}`);
    if (quick || only) {
      console.log(
        quick
          ? `\nquick run: all ${VARIANTS.length} variants compiled, rendered and were measured on ${renderers.join(' and ')}; nothing written.`
          : `\n--only: ${VARIANTS.length} of ${ALL_VARIANTS.length} variants measured; no targets, nothing written.`,
      );
      return;
    }
    results = mergeResults(results, outcome.measured);
    fs.writeFileSync(file, JSON.stringify(results, null, 2) + '\n');
  }
  if (!Object.keys(results).length) {
    console.error(`npm run bench -- --report: there is no ${path.relative(REPO_ROOT, file)} to report; run npm run bench first.`);
    process.exit(1);
  }
  const written = [...(reportOnly ? [] : [OUTPUT.json]), OUTPUT.markdown].map((f) => `tests/bench/${f}`);
  if (OUTPUT.charts)
    for (const [name, { results: entries }] of Object.entries(results)) {
      const [w, h] = SIZES[0];
      const chart = name === 'swiftshader' ? 'chart.svg' : `chart-${name}.svg`;
      const shown = entries.filter((r) => r.width === w && r.group !== SCENES_GROUP);
      fs.writeFileSync(
        path.join(BENCH_DIR, chart),
        chartSvg(shown, {
          title: `Time against error at ${w}×${h} (${RENDERER_TITLES[name]}, ${results[name].run?.cores ?? os.cpus().length} cores)`,
        }),
      );
      written.push(`tests/bench/${chart}`);
    }
  const markdown = benchMarkdown(results);
  fs.writeFileSync(path.join(BENCH_DIR, OUTPUT.markdown), markdown + '\n');
  if (OUTPUT.docs) {
    replaceMarkedSection(path.join(REPO_ROOT, 'docs', 'benchmark.md'), 'bench', markdown);
    written.push('the tables in docs/benchmark.md');
  }
  console.log(`\n${markdown}\n\nwrote ${written.join(', ')}`);
}

await main();
