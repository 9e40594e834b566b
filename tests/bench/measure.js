// One size of a benchmark: every variant timed in one page, interleaved round by round
// (timer.js), and each one's last image compared with the converged float64 reference of its
// scene. Shared by the benchmark (run.js) and the ablation (ablation.js), so that both measure
// the same way.

import { imageError } from '../../src/reference/error.js';
import { median } from '../../src/shared/stats.js';
import { renderReferenceParallel } from '../support/reference/reference-threads.js';
import { timeShadersOn } from './timer.js';
import { renderersAsked, withRenderers } from './renderer-set.js';

/**
 * @typedef {object} Variant
 * @property {string} name
 * @property {() => string} code the whole fragment shader, in Shadertoy's header
 * @property {number} [scene] the SCENE its picture is of (0 unless said)
 * @property {boolean} [uniforms] compiled with the controls as uniforms (their default values)
 */

/**
 * @template {Variant} V
 * @param {V[]} variants
 * @param {object} options
 * @param {string} options.source the project's shader (the reference reads its scene from it)
 * @param {number} options.width
 * @param {number} options.height
 * @param {number} options.copies compilations of each variant (one can run slower than another of the same text)
 * @param {number} options.frames timed frames per copy
 * @param {number} options.warmup untimed rounds per copy
 * @param {number} options.referenceSamplesPerAxis the reference's jittered samples per pixel, per axis
 * @param {{name: string, type: string, value: number | boolean | number[]}[]} [options.uniformValues] for the variants marked `uniforms`
 * @returns {Promise<Array<Measured<V>>>}
 */
export async function measureVariants(variants, options) {
  const [measured] = await measureVariantsOn([{ on: undefined }], variants, options);
  return measured;
}

/**
 * @template V
 * @typedef {{variant: V, error?: string, medianMs?: number, minMs?: number, maxMs?: number, frames?: number, rmse?: number, over2?: number,
 *   rounds?: number[][]}} Measured
 * rounds: each copy's frame times in the order of the rounds, for pairedRatio
 */

/**
 * The median over every copy and round of a's frame over b's in the same round: a ratio of
 * times that a machine whose load comes and goes between rounds moves less than it moves the
 * ratio of the two medians (each round draws every variant within a second or two).
 * @param {{rounds: number[][]}} a
 * @param {{rounds: number[][]}} b
 */
export function pairedRatio(a, b) {
  return median(a.rounds.flatMap((frames, c) => frames.map((t, r) => t / b.rounds[c][r])));
}

/**
 * measureVariants on each of `renderers` (renderer-set.js), all interleaved in one run
 * (timer.js timeShadersOn), each compared with the same references.
 * @template {Variant} V
 * @param {Array<{on: import('./renderer-set.js').BenchRenderer['on'] | undefined}>} renderers
 * @param {V[]} variants
 * @param {Parameters<typeof measureVariants>[1]} options
 * @returns {Promise<Array<Array<Measured<V>>>>} one list a renderer, in order
 */
export async function measureVariantsOn(renderers, variants, options) {
  const { source, width, height, copies, frames, warmup, referenceSamplesPerAxis, uniformValues = [] } = options;
  /** The converged float64 reference of each scene (the default one, 0, for every variant but the scenes'). */
  const references = new Map();
  for (const scene of new Set(variants.map((v) => v.scene ?? 0))) {
    const spp = referenceSamplesPerAxis * referenceSamplesPerAxis;
    process.stdout.write(`${width}x${height}: converged float64 reference of scene ${scene} (${spp} spp) ... `);
    const started = Date.now();
    references.set(
      scene,
      await renderReferenceParallel(
        source,
        { width, height, time: 0, mouse: [0, 0, 0, 0], controls: scene ? { SCENE: scene } : {} },
        { mode: 'converged', samplesPerAxis: referenceSamplesPerAxis },
      ),
    );
    console.log(`${((Date.now() - started) / 1000).toFixed(0)} s`);
  }
  const on = renderers.length > 1 ? ` on ${renderers.length} renderers` : '';
  process.stdout.write(`  timing ${variants.length} variants x ${copies} copies${on}, ${warmup} warm-up + ${frames} timed rounds: `);
  const programs = variants.flatMap((v) => {
    const code = v.code();
    return Array.from({ length: copies }, (_, k) => ({ code: `${code}\n// copy ${k}\n`, uniforms: v.uniforms ? uniformValues : [] }));
  });
  const runsOn = await timeShadersOn(renderers, programs, {
    width,
    height,
    frames,
    warmup,
    onRound: (round) => process.stdout.write(`${round + 1} `),
  });
  console.log('done');
  return runsOn.map((runs) =>
    variants.map((variant, i) => {
      // One result per variant: the frames of all its copies, and the last copy's image.
      const ofVariant = runs.slice(i * copies, (i + 1) * copies);
      const failed = ofVariant.find((c) => c.error);
      if (failed) return { variant, error: failed.error };
      const times = ofVariant.flatMap((c) => c.times);
      const error = imageError(ofVariant[copies - 1], references.get(variant.scene ?? 0));
      return {
        variant,
        medianMs: median(times),
        minMs: Math.min(...times),
        maxMs: Math.max(...times),
        frames: times.length,
        rounds: ofVariant.map((c) => c.times),
        rmse: error.rmse,
        over2: error.over2,
      };
    }),
  );
}

/**
 * A comparison script's run (bench:forms, bench:ablation): the renderers (renderer-set.js) and
 * the frames (--frames N, 5 by default) its command line asks for, and every variant measured on
 * each (measureVariantsOn) at 640×360, 3 compilations of each (--quick: once, at 160×90, one
 * frame). A flag it cannot read, or a variant that failed, is said on stderr and the process
 * ends with 1.
 * @template {Variant} V
 * @param {string} script the npm script's name after `bench:`, in what it says
 * @param {V[]} variants
 * @param {string} source the shader the variants are forms of
 * @param {string[]} argv the script's arguments
 */
export async function measureScript(script, variants, source, argv) {
  const quick = argv.includes('--quick');
  let renderers;
  try {
    renderers = renderersAsked(argv);
  } catch (error) {
    console.error(`npm run bench:${script} -- ${error.message}`);
    process.exit(1);
  }
  const framesAt = argv.indexOf('--frames');
  const frames = quick ? 1 : framesAt >= 0 ? Number(argv[framesAt + 1]) : 5;
  if (!(Number.isInteger(frames) && frames > 0)) {
    console.error(`npm run bench:${script} -- --frames: expected a whole number of frames, got "${argv[framesAt + 1] ?? ''}"`);
    process.exit(1);
  }
  const copies = quick ? 1 : 3;
  const [width, height] = quick ? [160, 90] : [640, 360];
  const results = await withRenderers(renderers, async (started) => {
    const measured = await measureVariantsOn(started, variants, {
      source,
      width,
      height,
      copies,
      frames,
      warmup: quick ? 1 : 2,
      referenceSamplesPerAxis: quick ? 2 : 8,
    });
    return started.map((r, i) => ({ name: r.name, environment: r.environment, measured: measured[i] }));
  });
  const failed = results.flatMap((r) =>
    r.measured.filter((m) => m.error).map((m) => `${script}: ${m.variant.name} on ${r.name}: ${m.error}`),
  );
  if (failed.length) {
    console.error(failed.join('\n'));
    process.exit(1);
  }
  return { renderers, results, width, height, copies, frames };
}
