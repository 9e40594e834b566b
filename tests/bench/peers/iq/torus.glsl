// iq-style torus: the quartic solved in closed form through its resolvent cubic, as Inigo Quilez's
// article "Intersectors" (iquilezles.org/articles/intersectors, its torus) does. Written here from
// the algebra; no code is copied. In the torus's frame (o = ro - center, axis A, R the core
// radius, r the tube's) with m = o.o, n = o.rd, oz = o.A, dz = rd.A and k = (m - r^2 - R^2) / 2,
// the surface (|p|^2 + R^2 - r^2)^2 = 4 R^2 (|p|^2 - (p.A)^2) on the ray is the quartic
//   t^4 + 4 k3 t^3 + 4 k2 t^2 + 8 k1 t + 4 k0 = 0,
//   k3 = n, k2 = n^2 + R^2 dz^2 + k, k1 = k n + R^2 oz dz, k0 = k^2 + R^2 oz^2 - R^2 r^2.
// x = t + k3 depresses it to x^4 + 2 P x^2 + 8 Q x + S (P = 2 k2 - 3 k3^2, Q = k3 (k3^2 - k2) + k1,
// S = k3 (k3 (4 k2 - 3 k3^2) - 8 k1) + 4 k0). Ferrari: for y >= 0 a root of the resolvent cubic
// y^3 + 2 P y^2 + (P^2 - S) y - 8 Q^2 = 0 the quartic splits into x^2 -+ w x + (P + y +- e) with
// w = sqrt(2 y), e = 4 Q / w. The article takes the cubic's smallest root from the trigonometric
// form when it has three real ones (all >= 0 when the quartic has four real roots; one negative
// when it has none, which is then a miss), else its one real root by Cardano's formula (as
// -sign(b) cbrt(|b| / 2 + sqrt(D)), the form without cancellation). The article's devices are kept: a bounding-sphere test first; when |Q| is small
// (w -> 0 makes e = 4 Q / w a 0/0) the substitution t = 2 / s, whose quartic has k3 and k1
// swapped and all divided by k0; and for w near 0 the biquadratic split, e = sqrt((P + y)^2 - S).
// The normal is the gradient (|p|^2 - R^2 - r^2) p + 2 R^2 (p.A) A, normalized.
// What an author typically writes: exactly that, in float32: no origin shift, no scaling, no
// polishing of the roots, fixed thresholds in absolute units. The constant term k0 subtracts
// terms of size R^4 to leave one of size R^2 r^2 (a thin tube loses 2 log2(R / r) bits), the
// resolvent's coefficients grow as the fourth and sixth powers of the eye's distance, and a
// near-axial ray gets its small roots from differences of large ones.
//
// Adapted to the project's contract only: makeTorus/intersectTorus's names and argument order (the
// struct carries the parameters as given, the axis normalized); hits only for 0 < t < tMax;
// vec4(t, n), MISS on a miss. Appended after shaders/raytrace.glsl
// (tests/bench/primitive-peers.js): the #defines at the end make the test and timing mains that
// follow call these instead of the project's makeTorus and intersectTorus.

struct IqTorus {
    vec3 center;
    vec3 axis;  // unit
    float R, r;
};

IqTorus iqMakeTorus(vec3 center, vec3 axis, float majorRadius, float minorRadius) {
    return IqTorus(center, normalize(axis), majorRadius, minorRadius);
}

// The nearer of `best` and the root t = s (t = 2 / s for the swapped quartic), if that is past 0.
float iqTorusNearer(float best, float s, bool swapped) {
    float t = swapped ? 2.0 / s : s;
    return t > 0.0 && t < best ? t : best;
}

vec4 iqTorus(vec3 ro, vec3 rd, IqTorus torus, float tMax) {
    float R2 = torus.R * torus.R, r2 = torus.r * torus.r;
    vec3 o = ro - torus.center;
    float m = dot(o, o), n = dot(o, rd);
    float oz = dot(o, torus.axis), dz = dot(rd, torus.axis);
    float outer = torus.R + torus.r;
    if (n * n - m + outer * outer < 0.0) return MISS;

    float k = 0.5 * (m - r2 - R2);
    float k3 = n;
    float k2 = n * n + R2 * dz * dz + k;
    float k1 = k * n + R2 * oz * dz;
    float k0 = k * k + R2 * oz * oz - R2 * r2;
    bool swapped = abs(k3 * (k3 * k3 - k2) + k1) < 0.01;
    if (swapped) {
        float inverse = 1.0 / k0;
        float k3Was = k3;
        k3 = k1 * inverse;
        k2 *= inverse;
        k1 = k3Was * inverse;
        k0 = inverse;
    }
    float P = 2.0 * k2 - 3.0 * k3 * k3;
    float Q = k3 * (k3 * k3 - k2) + k1;
    float S = k3 * (k3 * (4.0 * k2 - 3.0 * k3 * k3) - 8.0 * k1) + 4.0 * k0;

    // The resolvent, depressed by y = u - 2 P / 3: u^3 + a u + b = 0.
    float a = -P * P / 3.0 - S;
    float b = -2.0 * P * P * P / 27.0 + 2.0 * P * S / 3.0 - 8.0 * Q * Q;
    float D = b * b / 4.0 + a * a * a / 27.0;
    float u;
    if (D < 0.0) {
        u = -2.0 * sqrt(-a / 3.0) * cos(acos(clamp(-1.5 * b / a * sqrt(-3.0 / a), -1.0, 1.0)) / 3.0);
    } else {
        float A = -sign(b) * pow(0.5 * abs(b) + sqrt(D), 1.0 / 3.0);
        u = A != 0.0 ? A - a / (3.0 * A) : 0.0;
    }
    float y = u - 2.0 * P / 3.0;
    float w, e;
    if (abs(y) < 1e-4) {
        float e2 = (P + y) * (P + y) - S;
        if (e2 < 0.0) return MISS;
        w = 0.0;
        e = sqrt(e2);
    } else {
        if (y < 0.0) return MISS;
        w = sqrt(2.0 * y);
        e = 4.0 * Q / w;
    }

    // The four roots x of the two quadratics.
    float t = 1e30;
    float h = w * w - 4.0 * (P + y + e);
    if (h >= 0.0) {
        h = sqrt(h);
        t = iqTorusNearer(t, 0.5 * (w + h) - k3, swapped);
        t = iqTorusNearer(t, 0.5 * (w - h) - k3, swapped);
    }
    h = w * w - 4.0 * (P + y - e);
    if (h >= 0.0) {
        h = sqrt(h);
        t = iqTorusNearer(t, 0.5 * (-w + h) - k3, swapped);
        t = iqTorusNearer(t, 0.5 * (-w - h) - k3, swapped);
    }
    if (t >= tMax || t >= 1e30) return MISS;
    vec3 p = o + t * rd;
    return vec4(t, normalize((dot(p, p) - R2 - r2) * p + 2.0 * R2 * dot(p, torus.axis) * torus.axis));
}

#define makeTorus iqMakeTorus
#define intersectTorus iqTorus
