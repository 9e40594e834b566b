// Re-intersection properties of every GLSL intersector (after pbrt-v4's shapes_test.cpp, which
// spawns rays from hit points and requires that they never hit the shape again), on the GPU,
// with secondary rays started exactly as the scene starts them (radiance() in the shader):
//
// - From a hit point p with normal n (p = ro + t rd, re-projected onto the surface for the
//   sphere and the plane as reprojectOnSurface does), a ray into the outward hemisphere starts at
//   offsetAlong(p, +n) and the shape is NOT skipped. That is the plan for the torus, which is not
//   convex; the scene skips a convex solid instead, which needs no test, so for those this is a
//   stronger property than the scene relies on. Such a ray may hit the shape again only where the
//   float64 twin says it comes back (the torus can), and then at the twin's t.
// - A ray into the inward hemisphere starts at offsetAlong(p, -n), as a ray inside a solid does,
//   and must find the far side (every primitive but the plane, which bounds no solid).
//
// The test's main computes the first hit, the point, the start and a direction from two random
// numbers in the GPU's own normal frame, and writes the start and direction back, so the float64
// twin is asked about exactly the same secondary ray. Shapes small (1e-2) and large (1e2), seen
// from near (3 sizes) and far (1e3 sizes) with the eye at the origin as the scene has it, and
// the whole set moved to 1e3 from the origin.

import { afterAll, describe, expect, it } from 'vitest';
import { SHADERTOY_HEADER } from '../../src/shadertoy/header.js';
import { add, dot, length, normalize, scale, sub } from '../../src/reference/vec3.js';
import { disconnect } from '../support/page.js';
import { evaluateFloatShader } from '../support/raw-webgl/raw-webgl.js';
import { sequence } from '../intersector-cases/rays.js';
import { GLSL_CALLS, KINDS, f32, judge, reference, shaderSource } from '../support/tables/intersector-kinds.js';

const PROPERTY_MAIN = `${GLSL_CALLS}
uniform highp sampler2D rayTable;  // 5 texels a ray: (ro, kind), (rd, inward), params 0-3, params 4-7, (cos, azimuth)
void main() {
    int i = int(gl_FragCoord.x);
    vec4 a = texelFetch(rayTable, ivec2(i, 0), 0);
    vec4 d = texelFetch(rayTable, ivec2(i, 1), 0);
    vec4 p = texelFetch(rayTable, ivec2(i, 2), 0);
    vec4 q = texelFetch(rayTable, ivec2(i, 3), 0);
    vec4 u = texelFetch(rayTable, ivec2(i, 4), 0);
    int kind = int(a.w);
    vec4 first = intersectKind(kind, a.xyz, d.xyz, p, q, T_INFINITY);
    vec3 n = first.yzw;
    vec3 hit = a.xyz + first.x * d.xyz;
    hit = kind == ${KINDS.sphere} ? p.xyz + p.w * n : hit;
    hit = kind == ${KINDS.plane} ? vec3(hit - (dot(p.xyz, hit) + p.w) * p.xyz) : hit;
    vec3 side = d.w > 0.5 ? -n : n;
    vec3 e1 = normalize(cross(side, abs(side.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0)));
    vec3 e2 = cross(side, e1);
    vec3 rd = normalize(u.x * side + sqrt(max(1.0 - u.x * u.x, 0.0)) * (cos(u.y) * e1 + sin(u.y) * e2));
    vec3 ro = offsetAlong(hit, side);
    vec4 second = intersectKind(kind, ro, rd, p, q, T_INFINITY);
    int row = int(gl_FragCoord.y);
    shadertoy_out_color = row == 0 ? first : (row == 1 ? vec4(ro, 0.0) : (row == 2 ? vec4(rd, 0.0) : second));
}
`;

/** The shapes, each of size s about centre c, as params of their kind. */
const SHAPES = {
  plane: (s, c) => {
    const n = normalize([0.05, 1, 0.1]);
    return [...n, -dot(n, c)];
  },
  sphere: (s, c) => [...c, 0.8 * s],
  box: (s, c) => [...c, 0.5 * s, 0.3 * s, 0.7 * s],
  cone: (s, c) => [...add(c, [0, -0.85 * s, 0]), ...add(c, [0, 0.85 * s, 0]), 0.55 * s, 0],
  cylinder: (s, c) => [...sub(c, scale(normalize([1, 2, -0.5]), 0.8 * s)), ...add(c, scale(normalize([1, 2, -0.5]), 0.8 * s)), 0.4 * s],
  torus: (s, c) => [...c, 0.3, 1, 0.2, 0.7 * s, 0.25 * s],
  'thin torus': (s, c) => [...c, -0.2, 1, 0.4, 0.7 * s, 0.02 * s],
  'fat torus': (s, c) => [...c, 1, 0.1, 0.3, 0.6 * s, 0.57 * s],
};
const kindOf = (shape) => (shape.includes('torus') ? 'torus' : shape);

/** Whether p is inside the closed solid (float64), from the shape's definition. */
function insideSolid(kind, params, p) {
  if (kind === 'sphere') return length(sub(p, params.slice(0, 3))) < params[3];
  if (kind === 'box') return [0, 1, 2].every((i) => Math.abs(p[i] - params[i]) < params[3 + i]);
  if (kind === 'torus') {
    const A = normalize(params.slice(3, 6));
    const w = sub(p, params.slice(0, 3));
    const y = dot(w, A);
    return Math.hypot(length(sub(w, scale(A, y))) - params[6], y) < params[7];
  }
  // Cone and cylinder: between the caps, inside the radius at that height.
  const pa = params.slice(0, 3);
  const axis = sub(params.slice(3, 6), pa);
  const H = length(axis);
  const A = scale(axis, 1 / H);
  const w = sub(p, pa);
  const y = dot(w, A);
  const radius = kind === 'cone' ? params[6] + ((params[7] - params[6]) * y) / H : params[6];
  return y > 0 && y < H && length(sub(w, scale(A, y))) < radius;
}

/** The configurations: size, the eye, the shape's centre. */
function configurations(random) {
  const unit = () => normalize([random() - 0.5, random() - 0.5, random() - 0.5]);
  const configs = [];
  for (const size of [1e-2, 1, 1e2]) {
    for (const distance of [3, 1e3])
      configs.push({ size, eye: [0, 0, 0], center: scale(unit(), distance * size), label: `size ${size}, seen from ${distance} sizes` });
  }
  for (const size of [1, 1e2]) {
    const eye = [1e3 * size, -2e3 * size, 1.5e3 * size];
    configs.push({ size, eye, center: add(eye, scale(unit(), 3 * size)), label: `size ${size}, 2.7e3 sizes from the origin` });
  }
  return configs;
}

/** Eye rays that hit the shape in float64 (rounded to float32), and secondary rays from each. */
function makeRays(shape, seed) {
  const random = sequence(seed);
  const kind = kindOf(shape);
  const rays = [];
  for (const config of configurations(random)) {
    const params = f32(SHAPES[shape](config.size, config.center));
    for (let found = 0, tries = 0; found < 24 && tries < 2000; tries++) {
      const target = add(config.center, scale([random() - 0.5, random() - 0.5, random() - 0.5], 2 * config.size));
      const ro = f32(config.eye);
      const rd = f32(normalize(sub(target, config.eye)));
      if (!(reference({ kind, ro, rd, params })[0] > 0)) continue;
      found++;
      for (let j = 0; j < 8; j++) {
        const inward = j >= 4;
        if (inward && kind === 'plane') continue;
        // Half the directions uniform over the hemisphere, half grazing (cos 1e-1 to 1e-6).
        const cos = j % 2 ? random() : 10 ** (-1 - 5 * random());
        rays.push({ kind, ro, rd, params, inward, u: [cos, 2 * Math.PI * random()], config: config.label });
      }
    }
  }
  return rays;
}

async function runRays(rays) {
  const width = rays.length;
  const table = new Float32Array(width * 5 * 4);
  const texel = (row, i, values) => table.set(values, (row * width + i) * 4);
  rays.forEach((r, i) => {
    const p = [...r.params, 0, 0, 0, 0, 0, 0, 0, 0].slice(0, 8);
    texel(0, i, [...r.ro, KINDS[r.kind]]);
    texel(1, i, [...r.rd, r.inward ? 1 : 0]);
    texel(2, i, p.slice(0, 4));
    texel(3, i, p.slice(4, 8));
    texel(4, i, [...r.u, 0, 0]);
  });
  const code = SHADERTOY_HEADER + shaderSource() + PROPERTY_MAIN;
  const out = await evaluateFloatShader(code, { width, height: 4, table, tableHeight: 5, tableUniform: 'rayTable' });
  const at = (row, i) => Array.from(out.slice((row * width + i) * 4, (row * width + i) * 4 + 4));
  return rays.map((r, i) => ({ first: at(0, i), ro: at(1, i).slice(0, 3), rd: at(2, i).slice(0, 3), second: at(3, i) }));
}

describe('secondary rays from hit points, started as the scene starts them', () => {
  afterAll(() => disconnect());
  for (const [index, shape] of Object.keys(SHAPES).entries()) {
    it(`${shape}: leaving rays come back only where float64 does; rays from inside find the far side`, async () => {
      const rays = makeRays(shape, 100 + index);
      const results = await runRays(rays);
      const failures = [];
      const count = { leaving: 0, comesBack: 0, inward: 0, startsInside: 0, hitsFarSide: 0, firstMissed: 0, pushedOut: {} };
      rays.forEach((r, i) => {
        const { first, ro, rd, second } = results[i];
        if (!(first[0] > 0)) {
          count.firstMissed++; // a float64 hit the GLSL missed: the hard-case tests judge those
          return;
        }
        const name = `${shape} (${r.config}) ${r.inward ? 'inward' : 'leaving'} #${i}`;
        // A hit's t is conditioned by 1 / |rd.n| (a grazing direction from inside meets the far
        // side at a grazing angle too): stated per ray, from the float64 normal.
        const want = reference({ kind: r.kind, ro, rd, params: r.params });
        const grazing = want[0] > 0 ? Math.asin(Math.min(1, Math.abs(dot(rd, want.slice(1))) / length(rd))) : undefined;
        const secondary = { kind: r.kind, ro, rd, params: r.params, name, note: `cos ${r.u[0].toExponential(1)}`, grazing };
        if (!second.every(Number.isFinite)) failures.push(`${secondary.name}: not finite`);
        if (r.inward) {
          count.inward++;
          // A start pushed out of the solid by the offset (a thin part) says nothing about rays
          // from inside: counted, not judged.
          if (!insideSolid(r.kind, r.params, ro)) {
            count.pushedOut[r.config] = (count.pushedOut[r.config] ?? 0) + 1;
            return;
          }
          count.startsInside++;
          if (second[0] > 0) count.hitsFarSide++;
          failures.push(...judge({ ...secondary, expect: 'hit' }, second).failures);
        } else {
          count.leaving++;
          if (want[0] > 0) count.comesBack++;
          failures.push(...judge({ ...secondary, expect: 'agree' }, second).failures);
        }
      });
      console.log(
        `${shape}: ${count.leaving} leaving rays (${count.comesBack} come back to it in float64), ${count.inward} inward rays (${count.startsInside} start inside, ${count.hitsFarSide} find the far side); ${count.firstMissed} eye rays missed in float32`,
      );
      if (Object.keys(count.pushedOut).length)
        console.log(`${shape}: starts pushed out of the solid by offsetAlong: ${JSON.stringify(count.pushedOut)}`);
      expect(failures.slice(0, 10)).toEqual([]);
      expect(count.leaving).toBeGreaterThan(700);
      expect(count.hitsFarSide).toBe(count.startsInside);
      // offsetAlong moves p by 256 ulps of its largest coordinate (3e-5 of it), so it crosses a
      // part thinner than that: the thin torus (tube diameter 0.04 s) 2.7e3 sizes from the origin
      // (an offset of 0.06 s; in the scene, positions are relative to the eye, so that is the
      // distance that counts). Everywhere else the starts are inside but for a few at the cone's
      // apex, where the normal is any.
      const pushedOut = Object.entries(count.pushedOut).filter(
        ([config]) => !(shape === 'thin torus' && config.includes('from the origin')),
      );
      if (shape !== 'plane') expect(pushedOut.reduce((n, [, k]) => n + k, 0)).toBeLessThan(0.02 * count.inward);
    });
  }
});
