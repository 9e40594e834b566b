// The ground's texture in float64, as groundColor in shaders/raytrace.glsl computes it: the two
// patterns with their first and second integrals, the filter over a footprint spanned by two
// vectors, and a ray cone's footprint on the ground. The same formulas and the same choices as
// the shader, so that a same-ray comparison isolates arithmetic error.

const fract = (x) => x - Math.floor(x);

/** Each pattern with P1' = pattern and P2' = P1 (derived in the shader's comment). */
export const PATTERNS = Object.freeze({
  stripes: {
    at: fract,
    integral: (x) => 0.5 * Math.floor(x) + 0.5 * fract(x) ** 2,
    integral2: (x) => {
      const r = fract(x);
      return 0.25 * x * x - Math.floor(x) / 12 - 0.25 * r * r + (r * r * r) / 6;
    },
  },
  checkers: {
    at: (x) => Math.floor(x) - 2 * Math.floor(0.5 * x),
    integral: (x) => Math.floor(0.5 * x) + Math.max(2 * fract(0.5 * x) - 1, 0),
    integral2: (x) => {
      const k = Math.floor(0.5 * x);
      const over = Math.max(x - 2 * k - 1, 0);
      return k * (k - 1) + 0.5 * k + k * (x - 2 * k) + 0.5 * over * over;
    },
  },
});

/**
 * The pattern averaged over x + U, U the sum of two independent uniform offsets of widths wa and
 * wb (filteredPattern in the shader): a trapezoid, or the box of the wider one where the narrower
 * is under 1/64 of it, or the pattern itself inside one linear piece.
 * @param {{at: (x: number) => number, integral: (x: number) => number, integral2: (x: number) => number}} pattern
 */
export function filteredPattern(pattern, x, wa, wb) {
  const a = 0.5 * Math.max(wa, wb);
  const b = 0.5 * Math.min(wa, wb);
  const x0 = x - 2 * Math.floor(0.5 * x + 0.5); // both patterns repeat every 2
  if (Math.floor(x0 - a - b) === Math.floor(x0 + a + b)) return pattern.at(x);
  if (64 * b < a) return (pattern.integral(x0 + a) - pattern.integral(x0 - a)) / (2 * a);
  const P2 = pattern.integral2;
  return (P2(x0 + a + b) - P2(x0 + a - b) - P2(x0 - a + b) + P2(x0 - a - b)) / (4 * a * b);
}

/** Extents along world x and z of a ray cone of width coneWidth meeting the ground along rd. */
export function groundFootprint(rd, coneWidth) {
  const h2 = rd[0] * rd[0] + rd[2] * rd[2];
  if (h2 === 0) return [coneWidth, coneWidth];
  const dy2 = rd[1] * rd[1];
  return [
    coneWidth * Math.sqrt((rd[0] * rd[0] + rd[2] * rd[2] * dy2) / (dy2 * h2)),
    coneWidth * Math.sqrt((rd[2] * rd[2] + rd[0] * rd[0] * dy2) / (dy2 * h2)),
  ];
}
