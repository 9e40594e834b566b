// Helpers the case tables share: rays aimed at points, a reproducible random sequence, rotations.

import { cross, dot, normalize, sub } from '../../src/reference/vec3.js';

/** A ray from `from` towards `to`. */
export const aim = (from, to) => ({ ro: from, rd: normalize(sub(to, from)) });

/** A deterministic pseudo-random sequence in [0, 1), so the tables are the same every run. */
export function sequence(seed) {
  let state = seed >>> 0;
  return () => {
    state = (Math.imul(state, 1664525) + 1013904223) >>> 0;
    return state / 4294967296;
  };
}

/** dir rotated by `radians` about the unit `axis` (Rodrigues' formula). */
export function tilted(dir, radians, axis) {
  const c = Math.cos(radians);
  const s = Math.sin(radians);
  const k = axis;
  const kxv = cross(k, dir);
  const kdv = dot(k, dir);
  return normalize(dir.map((x, i) => x * c + kxv[i] * s + k[i] * kdv * (1 - c)));
}
