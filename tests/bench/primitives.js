// What each intersector costs on SwiftShader: one call a pixel, the eye ray of a 640x360 view that
// the shape about half fills, shaded by its normal; interleaved frames, medians. The torus also
// with each of its two Newton loops cut to one trip, to show how much of its cost the loops are
// (SwiftShader runs a 2x2 quad through every trip any of its pixels needs).
//
//   npm run bench:primitives

import fs from 'node:fs';
import { SHADERTOY_HEADER } from '../../src/shadertoy/header.js';
import { SHADER_FILE } from '../harness/config.js';
import { withHarness } from '../harness/setup.js';
import { timeShaders } from './timer.js';

const source = fs.readFileSync(SHADER_FILE, 'utf8');
const main = (call) => `
void main() {
    vec2 uv = (2.0 * gl_FragCoord.xy - iResolution.xy) / iResolution.y;
    vec3 ro = vec3(0.3, 2.5, 6.0);
    vec3 rd = normalize(vec3(uv, -2.0) + vec3(0.0, -0.3, 0.0));
    vec4 h = ${call};
    shadertoy_out_color = vec4(h.x > 0.0 ? 0.5 + 0.5 * h.yzw : vec3(0.1), 1.0);
}
`;
const torus = (r) => `intersectTorus(ro, rd, makeTorus(vec3(0.0, 0.5, 0.0), vec3(0.0, 1.0, 0.2), 1.4, ${r}), T_MAX)`;
const oneTripEach = source.replace('trip == 12', 'trip == 1').replace('trip == 16', 'trip == 1');
const VARIANTS = [
  ['nothing', 'vec4(-1.0, 0.0, 0.0, 0.0)'],
  ['sphere', 'intersectSphere(ro, rd, vec3(0.0, 0.5, 0.0), 1.3, T_MAX)'],
  ['cone', 'intersectCone(ro, rd, makeCone(vec3(0.0, -0.8, 0.0), vec3(0.0, 1.8, 0.0), 1.3, 0.0), T_MAX)'],
  ['cylinder', 'intersectCylinder(ro, rd, makeCylinder(vec3(0.0, -0.8, 0.0), vec3(0.0, 1.8, 0.0), 1.1), T_MAX)'],
  ['torus (r = 0.32 R)', torus('0.45')],
  ['torus (r = 0.036 R)', torus('0.05')],
  ['torus, one trip a loop', torus('0.45'), oneTripEach],
];

await withHarness(async () => {
  const shaders = VARIANTS.map(([, call, text = source]) => ({ code: SHADERTOY_HEADER + text + main(call) }));
  const results = await timeShaders(shaders, { width: 640, height: 360, frames: 25, warmup: 3 });
  console.log('| intersector, one call a pixel (640x360) | median ms |\n|---|---|');
  VARIANTS.forEach(([name], i) => {
    const r = results[i];
    if (r.error) throw new Error(`${name}: ${r.error}`);
    const sorted = r.times.slice().sort((a, b) => a - b);
    console.log(`| ${name} | ${sorted[sorted.length >> 1].toFixed(1)} |`);
  });
});
