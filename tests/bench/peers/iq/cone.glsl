// iq-style capped cone: the closed form of Inigo Quilez's article "Intersectors"
// (iquilezles.org/articles/intersectors, its capped cone), from pa (radius ra) to pb (radius rb).
// Written here from its formulas; no code is copied. With ba = pb - pa, oa = ro - pa, ob = ro - pb
// and the dot products m0 = ba.ba, m1 = oa.ba, m2 = rd.ba, m3 = rd.oa, m5 = oa.oa, m9 = ob.ba:
// - the caps first, and only the one the origin is beyond: below the base (m1 < 0) the base plane
//   is crossed at t = -m1 / m2, inside its disc when |oa m2 - rd m1|^2 < ra^2 m2^2 (the division
//   delayed); above the top (m9 > 0) at t = -m9 / m2, inside when |ob + t rd|^2 < rb^2;
// - the side: a point w = oa + t rd at axial coordinate y = w.ba (0 to m0 between the caps) is on
//   it when m0^2 |w|^2 - hy y^2 + 2 m0 ra rr y - m0^2 ra^2 = 0 (rr = ra - rb, hy = m0 + rr^2), i.e.
//   k2 t^2 + 2 k1 t + k0 = 0 with k2 = m0^2 - hy m2^2, k1 = m0^2 m3 - hy m1 m2 + m0 ra rr m2,
//   k0 = m0^2 m5 - hy m1^2 + m0 ra (2 rr m1 - m0 ra); h = k1^2 - k2 k0 < 0 is a miss; the root is
//   t = (-k1 - sqrt(h)) / k2, kept if 0 <= y <= m0; the normal is the gradient
//   m0 (m0 w + rr ra ba) - hy y ba, normalized.
// What an author typically writes: exactly that. The textbook root (-k1 - sqrt(h)) / k2 loses its
// digits as k2 -> 0 (a ray parallel to a generator line); one root only, so the mirror nappe
// (y > m0 past a pointed cone's apex) hides the real cone behind it, and an origin inside never
// sees the far side (the article: "most of these functions only work for a ray with origin
// outside of the primitive").
//
// Adapted to the project's contract only: makeCone/intersectCone's names and argument order (the
// struct carries the four parameters as given, nothing precomputed); hits only for 0 < t < tMax;
// vec4(t, n), MISS on a miss. Appended after shaders/raytrace.glsl
// (tests/bench/primitive-peers.js): the #defines at the end make the test and timing mains that
// follow call these instead of the project's makeCone and intersectCone.

struct IqCone {
    vec3 pa, pb;
    float ra, rb;
};

IqCone iqMakeCone(vec3 pa, vec3 pb, float ra, float rb) {
    return IqCone(pa, pb, ra, rb);
}

vec4 iqCone(vec3 ro, vec3 rd, IqCone cone, float tMax) {
    vec3 ba = cone.pb - cone.pa;
    vec3 oa = ro - cone.pa;
    vec3 ob = ro - cone.pb;
    float m0 = dot(ba, ba);
    float m1 = dot(oa, ba);
    float m2 = dot(rd, ba);
    float m3 = dot(rd, oa);
    float m5 = dot(oa, oa);
    float m9 = dot(ob, ba);

    if (m1 < 0.0) {
        vec3 q = oa * m2 - rd * m1;
        if (dot(q, q) < cone.ra * cone.ra * m2 * m2) {
            float t = -m1 / m2;
            return t > 0.0 && t < tMax ? vec4(t, -ba * inversesqrt(m0)) : MISS;
        }
    } else if (m9 > 0.0) {
        float t = -m9 / m2;
        vec3 q = ob + t * rd;
        if (dot(q, q) < cone.rb * cone.rb) return t > 0.0 && t < tMax ? vec4(t, ba * inversesqrt(m0)) : MISS;
    }

    float rr = cone.ra - cone.rb;
    float hy = m0 + rr * rr;
    float k2 = m0 * m0 - hy * m2 * m2;
    float k1 = m0 * m0 * m3 - hy * m1 * m2 + m0 * cone.ra * rr * m2;
    float k0 = m0 * m0 * m5 - hy * m1 * m1 + m0 * cone.ra * (2.0 * rr * m1 - m0 * cone.ra);
    float h = k1 * k1 - k2 * k0;
    if (h < 0.0) return MISS;
    float t = (-k1 - sqrt(h)) / k2;
    float y = m1 + t * m2;
    if (y < 0.0 || y > m0 || t <= 0.0 || t >= tMax) return MISS;
    return vec4(t, normalize(m0 * (m0 * (oa + t * rd) + rr * cone.ra * ba) - hy * y * ba));
}

#define makeCone iqMakeCone
#define intersectCone iqCone
