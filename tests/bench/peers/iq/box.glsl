// iq-style axis-aligned box: the slab method as Inigo Quilez's article "Intersectors"
// (iquilezles.org/articles/intersectors, its box) writes it, for a box centred at the origin with
// half sizes rad: m = 1 / rd, n = m ro, k = |m| rad; per axis the ray is between the slab's planes
// for t1 = -n - k <= t <= t2 = -n + k, so it is inside the box from tN, the largest component of
// t1, to tF, the smallest of t2; tN > tF or tF < 0 is a miss. The normal is the axis whose slab
// time is the hit, picked with step(). Written here from that formula; no code is copied. What an
// author typically writes: 1 / rd with no care for a zero component (it relies on 1/0 = inf, which
// GLSL ES does not promise, and an origin on a slab plane then gives 0 * inf = NaN), and the
// step() normal, which at an edge or a corner has two or three components set.
//
// Adapted to the project's contract only: a box centred at `center` (the ray moved into its
// frame); an origin inside hits the far side tF (the article returns it too), with the outward
// normal there (the article's faces the ray); hits only for 0 < t < tMax; vec4(t, n), MISS on a
// miss. Appended after shaders/raytrace.glsl (tests/bench/primitive-peers.js): the #define at the
// end makes the test and timing mains that follow call this instead of intersectBox.

vec4 iqBox(vec3 ro, vec3 rd, vec3 center, vec3 halfSize, float tMax) {
    vec3 m = 1.0 / rd;
    vec3 n = m * (ro - center);
    vec3 k = abs(m) * halfSize;
    vec3 t1 = -n - k;
    vec3 t2 = -n + k;
    float tN = max(max(t1.x, t1.y), t1.z);
    float tF = min(min(t2.x, t2.y), t2.z);
    if (tN > tF || tF < 0.0) return MISS;
    if (tN > 0.0) return tN < tMax ? vec4(tN, -sign(rd) * step(vec3(tN), t1)) : MISS;
    return tF > 0.0 && tF < tMax ? vec4(tF, sign(rd) * step(t2, vec3(tF))) : MISS;
}

#define intersectBox iqBox
