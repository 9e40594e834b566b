// iq-style sphere: the closed form a Shadertoy author writes, from Inigo Quilez's article
// "Intersectors" (iquilezles.org/articles/intersectors, its sphere): with oc = ro - center,
// b = oc.rd and c = oc.oc - r^2, the roots of t^2 + 2 b t + c = 0 are -b -+ sqrt(h), h = b^2 - c;
// h < 0 is a miss. Written here from that formula; no code is copied. What an author typically
// writes: the discriminant b^2 - c (both terms ~ |oc|^2, so it cancels for a small or far sphere),
// the near root -b - sqrt(h), and the normal normalize(p - center).
//
// Adapted to the project's contract only: the article returns both roots, and an origin inside
// takes the second one (-b + sqrt(h), the far side); hits only for 0 < t < tMax; vec4(t, n), MISS
// on a miss. Appended after shaders/raytrace.glsl (tests/bench/primitive-peers.js): the #define at
// the end makes the test and timing mains that follow call this instead of intersectSphere.

vec4 iqSphere(vec3 ro, vec3 rd, vec3 center, float radius, float tMax) {
    vec3 oc = ro - center;
    float b = dot(oc, rd);
    float c = dot(oc, oc) - radius * radius;
    float h = b * b - c;
    if (h < 0.0) return MISS;
    h = sqrt(h);
    float t = -b - h;
    if (t <= 0.0) t = -b + h;
    if (t <= 0.0 || t >= tMax) return MISS;
    return vec4(t, normalize(oc + t * rd));
}

#define intersectSphere iqSphere
