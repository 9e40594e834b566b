// The speed issue's targets, checked against one benchmark run at one size (1 sample per pixel,
// the default view): figures, not timed tests. Each returns whether it is met and a sentence.

import { paretoFront } from './chart.js';

const by = (results, name) => {
  const r = results.find((x) => x.name === name);
  if (!r) throw new Error(`benchmark: no result for "${name}"`);
  return r;
};
const x = (a, b) => `${(a / b).toFixed(2)}×`;
const ms = (r) => `${r.medianMs.toFixed(1)} ms`;

export const uniformSamples = (spp) => `project, ${spp} spp`;
export const adaptiveSamples = (spp) => `project, adaptive, ${spp} samples at edges`;
const PROJECT = uniformSamples(1);
export const PAGE_FORM = 'project, page form (uniforms), 1 spp';
export const SAVINGS_OFF = 'project, savings off';
export const ONE_TRACE_SITE = 'project, one trace site (alternating loop)';
export const PLAIN = 'plain analytic (peer 3)';
export const STANDALONE = 'standalone plain (peer 4)';
export const sphereTracing = (steps) => `sphere tracing, ${steps} steps (peer 2)`;
export const SCENES_GROUP = 'project: other scenes';
export const sceneVariant = (scene) => `project, ${['cone', 'cylinder', 'torus'][scene]} scene, 1 spp`;

export function evaluateTargets(results) {
  const ours = by(results, PROJECT);
  const targets = [];

  // 1. At least as fast as the plain analytic peer, at 10x lower RMSE or better.
  const plain = by(results, PLAIN);
  targets.push({
    met: ours.medianMs <= plain.medianMs && plain.rmse / ours.rmse >= 10,
    text: `${x(plain.medianMs, ours.medianMs)} the speed of the plain analytic peer (${ms(plain)} against ${ms(ours)}) at ${x(plain.rmse, ours.rmse)} lower RMSE (${ours.rmse.toFixed(4)} against ${plain.rmse.toFixed(4)}) (target: at least 1× the speed, at least 10× lower RMSE)`,
  });

  // 1b. Within 1.3x of the standalone plain peer: a whole shader of the same scene and rays that
  //     shares no line with the project (peers/standalone.glsl), so that the gap is what the
  //     project's structure costs.
  const standalone = by(results, STANDALONE);
  targets.push({
    met: ours.medianMs <= 1.3 * standalone.medianMs,
    text: `the project at 1 spp takes ${x(ours.medianMs, standalone.medianMs)} the standalone plain peer's time (${ms(ours)} against ${ms(standalone)}; RMSE ${ours.rmse.toFixed(4)} against ${standalone.rmse.toFixed(4)}) (target: at most 1.3×)`,
  });

  // 2. At least 3x faster than 128-step sphere tracing and 2x faster than 256-step.
  for (const [steps, factor] of [
    [128, 3],
    [256, 2],
  ]) {
    const rival = by(results, sphereTracing(steps));
    targets.push({
      met: rival.medianMs / ours.medianMs >= factor,
      text: `${x(rival.medianMs, ours.medianMs)} faster than sphere tracing at ${steps} steps (${ms(rival)}, RMSE ${rival.rmse.toFixed(4)}) (target: ${factor}×)`,
    });
  }

  // 3. The page's form (live controls as uniforms) within 1.2x of the paste form.
  const page = by(results, PAGE_FORM);
  targets.push({
    met: page.medianMs <= 1.2 * ours.medianMs,
    text: `the page's form with uniforms takes ${x(page.medianMs, ours.medianMs)} the paste form's time (${ms(page)} against ${ms(ours)}) (target: at most 1.2×)`,
  });

  // 4. Every project variant at 1 spp on the Pareto front (its quality settings; not the other
  //    forms of the same image: savings off, one trace site, the uniform form), and "savings
  //    off" slower than the default.
  const front = new Set(paretoFront(results).map((r) => r.name));
  const otherForms = new Set([SAVINGS_OFF, ONE_TRACE_SITE, PAGE_FORM]);
  const off = results.filter(
    (r) => r.group.startsWith('project') && r.samplesPerPixel === 1 && !otherForms.has(r.name) && !front.has(r.name),
  );
  targets.push({
    met: off.length === 0,
    text:
      off.length === 0
        ? 'every project variant at 1 spp is on the Pareto front (target: all)'
        : `project variants at 1 spp not on the Pareto front: ${off.map((r) => `${r.name} (${ms(r)}, RMSE ${r.rmse.toFixed(4)})`).join('; ')} (target: none)`,
  });
  const savingsOff = by(results, SAVINGS_OFF);
  targets.push({
    met: savingsOff.medianMs > ours.medianMs,
    text: `"savings off" takes ${x(savingsOff.medianMs, ours.medianMs)} the default's time (${ms(savingsOff)}), RMSE ${savingsOff.rmse.toFixed(4)} against ${ours.rmse.toFixed(4)} (target: slower than the default)`,
  });
  return targets;
}

// The anti-aliasing targets (issue 20), at each size: adaptive with 16 edge samples against
// uniform supersampling, and every adaptive variant on the front among the sampling choices.
const ADAPTIVE_TIME_TARGET = 2.0;
export function evaluateAdaptiveTargets(results) {
  const one = by(results, PROJECT);
  const four = by(results, uniformSamples(4));
  const sixteen = by(results, uniformSamples(16));
  const adaptive = by(results, adaptiveSamples(16));
  const targets = [];
  targets.push({
    met: adaptive.rmse <= 1.15 * sixteen.rmse,
    text: `adaptive (16 at edges) RMSE ${adaptive.rmse.toFixed(4)}, ${x(adaptive.rmse, sixteen.rmse)} uniform 16 spp's ${sixteen.rmse.toFixed(4)} (target: at most 1.15×)`,
  });
  targets.push({
    met: adaptive.over2 <= four.over2,
    text: `adaptive (16 at edges) has ${(100 * adaptive.over2).toFixed(2)}% of pixels over 2/255, uniform 4 spp ${(100 * four.over2).toFixed(2)}% (target: no more)`,
  });
  targets.push({
    met: adaptive.medianMs <= ADAPTIVE_TIME_TARGET * one.medianMs,
    text: `adaptive (16 at edges) takes ${x(adaptive.medianMs, one.medianMs)} the 1-spp time (${ms(adaptive)} against ${ms(one)}), with extra samples in ${(100 * adaptive.extraSampleFraction).toFixed(2)}% of pixels (target: at most ${ADAPTIVE_TIME_TARGET.toFixed(1)}×)`,
  });
  // On the front among the sampling choices: no uniform variant both faster and more accurate
  // than an adaptive one.
  const uniforms = [1, 4, 9, 16].map((spp) => by(results, uniformSamples(spp)));
  for (const spp of [4, 9, 16]) {
    const a = by(results, adaptiveSamples(spp));
    const better = uniforms.filter((u) => u.medianMs < a.medianMs && u.rmse < a.rmse);
    targets.push({
      met: better.length === 0,
      text: better.length
        ? `adaptive (${spp} at edges: ${ms(a)}, RMSE ${a.rmse.toFixed(4)}) is beaten by ${better.map((u) => `${u.name} (${ms(u)}, RMSE ${u.rmse.toFixed(4)})`).join(' and ')} (target: no uniform variant both faster and more accurate)`
        : `no uniform variant is both faster and more accurate than adaptive, ${spp} at edges (${ms(a)}, RMSE ${a.rmse.toFixed(4)})`,
    });
  }
  return targets;
}

// The primitives issue's targets: the default (cone) scene at least 1.3x the speed of the plain
// analytic peer, with its accuracy as before; the torus scene within 1.3x the cone scene's time.
export function evaluateSceneTargets(results) {
  const cone = by(results, PROJECT);
  const plain = by(results, PLAIN);
  const cylinder = by(results, sceneVariant(1));
  const torus = by(results, sceneVariant(2));
  return [
    {
      met: plain.medianMs >= 1.3 * cone.medianMs,
      text: `the cone scene at ${x(plain.medianMs, cone.medianMs)} the speed of the plain analytic peer (${ms(cone)} against ${ms(plain)}) (target: at least 1.3×)`,
    },
    {
      met: torus.medianMs <= 1.3 * cone.medianMs,
      text: `the torus scene takes ${x(torus.medianMs, cone.medianMs)} the cone scene's time (${ms(torus)} against ${ms(cone)}; RMSE ${torus.rmse.toFixed(4)} against its own converged reference) (target: at most 1.3×)`,
    },
    {
      met: true,
      text: `the cylinder scene takes ${x(cylinder.medianMs, cone.medianMs)} the cone scene's time (${ms(cylinder)}; RMSE ${cylinder.rmse.toFixed(4)} against its own converged reference) (no target)`,
    },
  ];
}

// Issue 44's targets, set for llvmpipe (and reported for every renderer): the project at 1 spp
// at least as fast as the standalone plain peer, adaptive 16 within 1.5x the 1-spp frame, the
// torus scene within 1.5x the cone scene.
const RENDERER_TARGETS = { standalone: 1.0, adaptive: 1.5, torus: 1.5 };
export function evaluateRendererTargets(results) {
  const one = by(results, PROJECT);
  const standalone = by(results, STANDALONE);
  const adaptive = by(results, adaptiveSamples(16));
  const torus = by(results, sceneVariant(2));
  return [
    {
      met: one.medianMs <= RENDERER_TARGETS.standalone * standalone.medianMs,
      text: `the project at 1 spp runs at ${x(standalone.medianMs, one.medianMs)} the standalone plain peer's speed (${ms(one)} against ${ms(standalone)}) (target: at least ${RENDERER_TARGETS.standalone.toFixed(1)}×)`,
    },
    {
      met: adaptive.medianMs <= RENDERER_TARGETS.adaptive * one.medianMs,
      text: `adaptive (16 at edges) takes ${x(adaptive.medianMs, one.medianMs)} the 1-spp time (${ms(adaptive)} against ${ms(one)}) (target: at most ${RENDERER_TARGETS.adaptive.toFixed(1)}×)`,
    },
    {
      met: torus.medianMs <= RENDERER_TARGETS.torus * one.medianMs,
      text: `the torus scene takes ${x(torus.medianMs, one.medianMs)} the cone scene's time (${ms(torus)} against ${ms(one)}) (target: at most ${RENDERER_TARGETS.torus.toFixed(1)}×)`,
    },
  ];
}
