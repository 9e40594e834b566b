// One size of a benchmark: every variant timed in one page, interleaved round by round
// (timer.js), and each one's last image compared with the converged float64 reference of its
// scene. Shared by the benchmark (run.js) and the ablation (ablation.js), so that both measure
// the same way.

import { imageError } from '../../src/reference/error.js';
import { median } from '../../src/shared/stats.js';
import { renderReferenceParallel } from '../harness/reference-threads.js';
import { timeShaders } from './timer.js';

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
 * @returns {Promise<Array<{variant: V, error?: string, medianMs?: number, minMs?: number, maxMs?: number, frames?: number, rmse?: number, over2?: number}>>}
 */
export async function measureVariants(variants, options) {
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
  process.stdout.write(`  timing ${variants.length} variants x ${copies} copies, ${warmup} warm-up + ${frames} timed rounds: `);
  const programs = variants.flatMap((v) => {
    const code = v.code();
    return Array.from({ length: copies }, (_, k) => ({ code: `${code}\n// copy ${k}\n`, uniforms: v.uniforms ? uniformValues : [] }));
  });
  const runs = await timeShaders(programs, { width, height, frames, warmup, onRound: (round) => process.stdout.write(`${round + 1} `) });
  console.log('done');
  return variants.map((variant, i) => {
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
      rmse: error.rmse,
      over2: error.over2,
    };
  });
}
