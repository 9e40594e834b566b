// The per-primitive table: speed against error for each intersector, the project's against the
// closed form a Shadertoy author writes from iq's published formulas (tests/bench/peers/iq/).
//
//   npm run bench:primitives              times and judges; writes tests/bench/primitives.md and
//                                         the table in docs/numerics.md (a few minutes)
//   npm run bench:primitives -- --quick   every program at 32x18, one warm-up and one timed frame,
//                                         and the hard cases judged; writes nothing (a smoke run,
//                                         about 25 s, so that it cannot rot)
//
// Speed: a micro-benchmark of CALLS intersector calls a pixel at 640x360 (timingMain below), each
// on its own ray; the same loop with a stand-in that costs nothing but reading the ray is the
// baseline (its median frame), subtracted from every frame, so what is left is the calls alone. All
// programs' frames are interleaved (timer.js), so a machine that slows down slows all alike.
// Every form is compiled COPIES times (SwiftShader runs one compilation of a text up to 40%
// slower than another, for as long as it lives: see run.js). Reported as ns a call (= ms a
// million calls): median and min-max over all frames of all copies.
// Error: the hard cases of tests/intersector-cases/ for that primitive, judged by the project's
// own verdict (primitive-peers.js): the share wrong, and the t error on transversal hits.

import fs from 'node:fs';
import path from 'node:path';
import { SHADERTOY_HEADER } from '../../src/shadertoy/header.js';
import { median } from '../../src/shared/stats.js';
import { K, shaderSource } from '../support/tables/intersector-kinds.js';
import { REPO_ROOT } from '../support/config.js';
import { rendererLabel } from '../../src/headless/browser.js';
import { withHarness } from '../support/setup.js';
import { replaceMarkedSection } from '../scripts/readme-section.js';
import { PRIMITIVE_KINDS, judgeHardCases, withIqPeers } from './primitive-peers.js';
import { primitivesMarkdown } from './primitives-report.js';
import { timeShaders } from './timer.js';

const quick = process.argv.includes('--quick');
const [WIDTH, HEIGHT] = quick ? [32, 18] : [640, 360];
const CALLS = 32;
const FOCAL = 5.0; // the image plane's distance, in units of half the view's height
const COPIES = quick ? 1 : 3;
const FRAMES = quick ? 1 : 12; // timed frames a copy
const WARMUP = quick ? 1 : 2;

// The eye at (0.3, 2.5, 6) looks at (0, 0.5, 0) with a vertical field of view of 23 degrees;
// each shape, about there, fills about half the view (the share of the timed rays that hit is in
// the table). The plane lies 1 below the eye, parallel to the view direction: its horizon halves
// the view, and the rays near it meet it far away and at a grazing angle, as a ground's do.
// Both sides run this same call text (the iq peer's #defines rename it): the shape's parameters
// are constants, so what depends on the shape alone (our makeCone, the ba and m0 of iq's form) the
// compiler may fold or hoist for either; what depends on the ray it cannot.
const SHAPES = {
  plane: 'intersectPlane(ro, rd, vec4(up, 1.0 - dot(up, EYE)), T_INFINITY)',
  sphere: 'intersectSphere(ro, rd, vec3(0.0, 0.5, 0.0), 1.3, T_INFINITY)',
  box: 'intersectBox(ro, rd, vec3(0.0, 0.5, 0.0), vec3(1.1, 0.95, 0.95), T_INFINITY)',
  cone: 'intersectCone(ro, rd, makeCone(vec3(0.0, -1.0, 0.0), vec3(0.0, 2.0, 0.0), 2.0, 0.0), T_INFINITY)',
  cylinder: 'intersectCylinder(ro, rd, makeCylinder(vec3(0.0, -0.8, 0.0), vec3(0.0, 1.8, 0.0), 1.1), T_INFINITY)',
  torus: 'intersectTorus(ro, rd, makeTorus(vec3(0.0, 0.5, 0.0), vec3(0.0, 1.0, 0.2), 1.4, 0.45), T_INFINITY)',
};
// The baseline's stand-in: reads the whole ray, costs a dot product.
const NO_CALL = 'vec4(dot(ro, rd), rd)';

// CALLS calls a pixel, each on its own ray: the pixel's eye ray with its origin and direction
// moved within the pixel by the call index (a 2D golden-ratio sequence), so no call can be hoisted
// out of the loop or merged with another; every result goes into the colour, so none is dead. Red
// is the share of the calls that hit.
const timingMain = (call) => `
const vec3 EYE = vec3(0.3, 2.5, 6.0);
void main() {
    vec3 forward = normalize(vec3(0.0, 0.5, 0.0) - EYE);
    vec3 right = normalize(cross(forward, vec3(0.0, 1.0, 0.0)));
    vec3 up = cross(right, forward);
    vec2 uv = (2.0 * gl_FragCoord.xy - iResolution.xy) / iResolution.y;
    vec4 sum = vec4(0.0);
    float hits = 0.0;
    for (int i = 0; i < ${CALLS}; i++) {
        vec2 jitter = (fract(vec2(0.7548777, 0.5698403) * (float(i) + 0.5)) - 0.5) * (2.0 / iResolution.y);
        vec3 ro = EYE + 4.0 * (jitter.x * right + jitter.y * up);
        vec3 rd = normalize((uv.x + jitter.x) * right + (uv.y + jitter.y) * up + ${FOCAL.toFixed(1)} * forward);
        vec4 h = ${call};
        sum += h;
        hits += h.x > 0.0 ? 1.0 : 0.0;
    }
    shadertoy_out_color = vec4(hits / ${CALLS}.0, fract(sum.x * 0.01), 0.5 + 0.5 * sum.zw / ${CALLS}.0);
}
`;

const project = shaderSource();
const program = (text, call) => SHADERTOY_HEADER + text + timingMain(call);
// The programs: the baseline, then each primitive's own form and its iq-style peer.
const FORMS = [
  { kind: null, form: 'baseline', code: program(project, NO_CALL) },
  ...PRIMITIVE_KINDS.flatMap((kind) => [
    { kind, form: 'ours', code: program(project, SHAPES[kind]) },
    { kind, form: 'iq', code: program(withIqPeers([kind], project), SHAPES[kind]) },
  ]),
];

/**
 * Per form: ns a call, from each of its frames less the baseline's median frame (all its copies),
 * over the calls of a frame; and the share of calls that hit (the last frame's red channel).
 */
function perCall(runs) {
  const baseline = runs.slice(0, COPIES).flatMap((c) => c.times);
  const baselineMs = { median: median(baseline), min: Math.min(...baseline), max: Math.max(...baseline) };
  const nsPerCall = (ms) => ((ms - baselineMs.median) * 1e6) / (WIDTH * HEIGHT * CALLS);
  return FORMS.map((f, i) => {
    const copies = runs.slice(i * COPIES, (i + 1) * COPIES);
    const failed = copies.find((c) => c.error);
    if (failed) throw new Error(`${f.kind} (${f.form}): ${failed.error}`);
    const ns = copies.flatMap((c) => c.times.map(nsPerCall));
    const { data } = copies[COPIES - 1];
    let red = 0;
    for (let p = 0; p < data.length; p += 4) red += data[p];
    return {
      ...f,
      ns: { median: median(ns), min: Math.min(...ns), max: Math.max(...ns) },
      baselineMs,
      hitShare: red / 255 / (data.length / 4),
    };
  });
}

await withHarness(async (context) => {
  console.log(
    `primitives${quick ? ' (quick)' : ''}: ${FORMS.length} programs x ${COPIES} copies at ${WIDTH}x${HEIGHT}, ${CALLS} calls a pixel`,
  );
  process.stdout.write(`  timing, ${WARMUP} warm-up + ${FRAMES} timed rounds: `);
  const programs = FORMS.flatMap((f) => Array.from({ length: COPIES }, (_, k) => ({ code: `${f.code}\n// copy ${k}\n` })));
  const runs = await timeShaders(programs, {
    width: WIDTH,
    height: HEIGHT,
    frames: FRAMES,
    warmup: WARMUP,
    onRound: (round) => process.stdout.write(`${round + 1} `),
  });
  console.log('done');
  const timed = perCall(runs);
  process.stdout.write('  judging the hard cases: ');
  const errors = { ours: await judgeHardCases(project), iq: await judgeHardCases(withIqPeers()) };
  console.log('done');
  const ourWrong = PRIMITIVE_KINDS.filter((kind) => errors.ours[kind].wrong > 0);
  if (ourWrong.length)
    throw new Error(`the project's intersectors got hard cases wrong (${ourWrong.join(', ')}): run tests/browser/intersectors.test.js`);

  const markdown = primitivesMarkdown({
    timed,
    errors,
    setup: { width: WIDTH, height: HEIGHT, calls: CALLS, copies: COPIES, frames: FRAMES, warmup: WARMUP, K },
    environment: `${rendererLabel(context.environment.renderer)}, ${context.environment.chromium}`,
  });
  console.log(`\n${markdown}\n`);
  if (quick) {
    console.log('quick run: every program compiled and ran, every peer was judged; nothing written.');
    return;
  }
  fs.writeFileSync(path.join(REPO_ROOT, 'tests', 'bench', 'primitives.md'), markdown + '\n');
  replaceMarkedSection(path.join(REPO_ROOT, 'docs', 'numerics.md'), 'primitives', markdown);
  console.log('wrote tests/bench/primitives.md and the table in docs/numerics.md');
});
