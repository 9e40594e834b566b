// Textbook forms of two intersectors, spliced into the shader in place of the real ones to show
// that the tests can fail: the checks that pass the shader's forms must catch these.

/** The shader source with the function that starts with `signature` replaced by `replacement`. */
export function replaceFunction(source, signature, replacement) {
  const start = source.indexOf(signature);
  if (start < 0) throw new Error(`no ${signature} in the shader`);
  const end = source.indexOf('\n}\n', start) + 3;
  return source.slice(0, start) + replacement + source.slice(end);
}

/** The sphere with the textbook discriminant b^2 - c. */
export const TEXTBOOK_SPHERE = `vec4 intersectSphere(vec3 ro, vec3 rd, vec3 center, float radius, float tMax) {
    vec3 f = ro - center;
    float b = dot(f, rd);
    float disc = b * b - (dot(f, f) - radius * radius);
    if (disc < 0.0) return MISS;
    float t = -b - sqrt(disc);
    if (t <= 0.0) t = -b + sqrt(disc);
    return t > 0.0 && t < tMax ? vec4(t, normalize(f + t * rd)) : MISS;
}
`;

// The torus as the textbook solves it: the expanded quartic (|p|^2 + R^2 - r^2)^2 = 4 R^2 rho^2,
// with m = |o|^2, n = o.d, k = (m + R^2 - r^2) / 2:
//   t^4 + 4 n t^3 + 4 (n^2 + k - R^2 |d_perp|^2) t^2 + 8 (n k - R^2 o_perp.d_perp) t + 4 (k^2 - R^2 |o_perp|^2),
// depressed by t = x - n, then Ferrari's method: a positive root z of the resolvent cubic
// z^3 + 2 p z^2 + (p^2 - 4 s) z - q^2 (Cardano, or the trigonometric form for three real roots)
// splits the quartic into two quadratics x^2 -+ w x + (p + z +- q / w) / 2, w = sqrt(z). No origin
// shift, no scaling, no polishing: the closed form as written.
export const NAIVE_TORUS = `vec4 intersectTorus(vec3 ro, vec3 rd, Torus torus, float tMax) {
    float R = torus.majorRadius, r = torus.tubeRatio * torus.majorRadius;
    vec3 o = ro - torus.center;
    vec3 oPerp = o - dot(o, torus.axis) * torus.axis, dPerp = rd - dot(rd, torus.axis) * torus.axis;
    float n = dot(o, rd), k = 0.5 * (dot(o, o) + R * R - r * r);
    float A = 4.0 * n;
    float B = 4.0 * (n * n + k - R * R * dot(dPerp, dPerp));
    float C = 8.0 * (n * k - R * R * dot(oPerp, dPerp));
    float D = 4.0 * (k * k - R * R * dot(oPerp, oPerp));
    float p = B - 3.0 * A * A / 8.0;
    float q = C - A * B / 2.0 + A * A * A / 8.0;
    float s = D - A * C / 4.0 + A * A * B / 16.0 - 3.0 * A * A * A * A / 256.0;
    // The resolvent cubic z^3 + a2 z^2 + a1 z + a0, depressed by z = u - a2 / 3.
    float a2 = 2.0 * p, a1 = p * p - 4.0 * s, a0 = -q * q;
    float P = a1 - a2 * a2 / 3.0, Q = 2.0 * a2 * a2 * a2 / 27.0 - a2 * a1 / 3.0 + a0;
    float delta = Q * Q / 4.0 + P * P * P / 27.0;
    float u;
    if (delta > 0.0) {
        float sq = sqrt(delta);
        float m1 = -Q / 2.0 + sq, m2 = -Q / 2.0 - sq;
        u = sign(m1) * pow(abs(m1), 1.0 / 3.0) + sign(m2) * pow(abs(m2), 1.0 / 3.0);
    } else {
        float rr = sqrt(-P / 3.0);
        u = 2.0 * rr * cos(acos(clamp(-Q / (2.0 * rr * rr * rr), -1.0, 1.0)) / 3.0);
    }
    float z = u - a2 / 3.0;
    float roots[4];
    if (z <= 0.0) {  // q = 0: biquadratic, x^2 = (-p +- sqrt(p^2 - 4 s)) / 2
        float d = p * p - 4.0 * s;
        float x2a = d >= 0.0 ? (-p + sqrt(d)) / 2.0 : -1.0, x2b = d >= 0.0 ? (-p - sqrt(d)) / 2.0 : -1.0;
        roots[0] = x2a >= 0.0 ? sqrt(x2a) : -1e30; roots[1] = x2a >= 0.0 ? -sqrt(x2a) : -1e30;
        roots[2] = x2b >= 0.0 ? sqrt(x2b) : -1e30; roots[3] = x2b >= 0.0 ? -sqrt(x2b) : -1e30;
    } else {
        float w = sqrt(z);
        float c1 = (p + z - q / w) / 2.0, c2 = (p + z + q / w) / 2.0;
        float d1 = z - 4.0 * c1, d2 = z - 4.0 * c2;
        roots[0] = d1 >= 0.0 ? (-w + sqrt(d1)) / 2.0 : -1e30; roots[1] = d1 >= 0.0 ? (-w - sqrt(d1)) / 2.0 : -1e30;
        roots[2] = d2 >= 0.0 ? (w + sqrt(d2)) / 2.0 : -1e30; roots[3] = d2 >= 0.0 ? (w - sqrt(d2)) / 2.0 : -1e30;
    }
    float t = 1e30;
    for (int i = 0; i < 4; i++) {
        float ti = roots[i] - n;
        if (roots[i] > -1e29 && ti > 0.0 && ti < t) t = ti;
    }
    if (t >= tMax || t >= 1e30) return MISS;
    vec3 hp = o + t * rd;
    vec3 hPerp = hp - dot(hp, torus.axis) * torus.axis;
    return vec4(t, normalize(hp - R * normalize(hPerp)));
}
`;
