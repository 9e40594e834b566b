// iq-style capped cylinder: the closed form of Inigo Quilez's article "Intersectors"
// (iquilezles.org/articles/intersectors, its capped cylinder), from pa to pb with radius ra.
// Written here from its formulas; no code is copied. With ba = pb - pa, oc = ro - pa and
// baba = ba.ba, bard = ba.rd, baoc = ba.oc, a point w = oc + t rd at axial coordinate
// y = baoc + t bard (0 to baba between the caps) is on the side when baba |w|^2 - y^2 = ra^2 baba:
//   k2 t^2 + 2 k1 t + k0 = 0,  k2 = baba - bard^2,  k1 = baba (oc.rd) - baoc bard,
//   k0 = baba (oc.oc) - baoc^2 - ra^2 baba;
// h = k1^2 - k2 k0 < 0 is a miss; the side root is t = (-k1 - sqrt(h)) / k2, a hit when
// 0 < y < baba, with the normal (w - ba y / baba) / ra. Otherwise the cap on the side y fell is
// crossed at t = ((y < 0 ? 0 : baba) - baoc) / bard, inside its disc when |k1 + k2 t| < sqrt(h)
// (the side's quadratic is negative there), with the normal ba sign(y) / sqrt(baba).
// What an author typically writes: exactly that. k2 = baba - bard^2 is |ba|^2 (1 - cos^2) and
// cancels to rounding noise for a ray nearly along the axis (0/0 for one exactly along it); the
// discriminant k1^2 - k2 k0 cancels for a far eye; the side normal is not renormalized; an origin
// inside never sees the far side.
//
// Adapted to the project's contract only: makeCylinder/intersectCylinder's names and argument
// order (the struct carries the three parameters as given, nothing precomputed); hits only for
// 0 < t < tMax; vec4(t, n), MISS on a miss. Appended after shaders/raytrace.glsl
// (tests/bench/primitive-peers.js): the #defines at the end make the test and timing mains that
// follow call these instead of the project's makeCylinder and intersectCylinder.

struct IqCylinder {
    vec3 pa, pb;
    float ra;
};

IqCylinder iqMakeCylinder(vec3 pa, vec3 pb, float ra) {
    return IqCylinder(pa, pb, ra);
}

vec4 iqCylinder(vec3 ro, vec3 rd, IqCylinder cylinder, float tMax) {
    vec3 ba = cylinder.pb - cylinder.pa;
    vec3 oc = ro - cylinder.pa;
    float baba = dot(ba, ba);
    float bard = dot(ba, rd);
    float baoc = dot(ba, oc);
    float k2 = baba - bard * bard;
    float k1 = baba * dot(oc, rd) - baoc * bard;
    float k0 = baba * dot(oc, oc) - baoc * baoc - cylinder.ra * cylinder.ra * baba;
    float h = k1 * k1 - k2 * k0;
    if (h < 0.0) return MISS;
    h = sqrt(h);
    float t = (-k1 - h) / k2;
    float y = baoc + t * bard;
    if (y > 0.0 && y < baba) {
        return t > 0.0 && t < tMax ? vec4(t, (oc + t * rd - ba * y / baba) / cylinder.ra) : MISS;
    }
    t = ((y < 0.0 ? 0.0 : baba) - baoc) / bard;
    if (abs(k1 + k2 * t) < h && t > 0.0 && t < tMax) return vec4(t, ba * sign(y) * inversesqrt(baba));
    return MISS;
}

#define makeCylinder iqMakeCylinder
#define intersectCylinder iqCylinder
