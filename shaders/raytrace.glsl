// Analytic raytracer: a striped ground plane, a sphere, a cube and a cone (or, by SCENE, a
// cylinder or a torus in its place), lit by one point light, with hard shadows and mirror
// reflections. A Shadertoy Image-tab shader: paste it as it is. Drag to orbit; all tunables are
// in the control block below.
//
// Reading guide. The lecture's template is all here, in its order: the intersectors, the scene
// and its one walk (traceScene: nearest hit, and a shadow ray's any hit), the materials, the
// local shading, the bounce loop (radiance) and the camera and image (mainImage). Added to it:
// - controls: one block that Shadertoy compiles as it is and the page turns into a panel;
// - the new object (cone, cylinder or torus): one section, "the new object", behind one
//   interface, chosen by the one #if SCENE;
// - adaptive anti-aliasing: a pixel whose first sample lies near an edge takes more samples.
//   "near misses" and "edges" hold its tests, "what a path records" what they read of the path;
// - the debug views (VIEW 1 to 5), compiled only when chosen.
//
// Numerical choices, each explained where it is made:
// - every position is relative to the eye, so a scene far from the origin keeps its digits;
// - the sphere, cone and cylinder quadratics use cancellation-free discriminants and stable
//   roots; the torus is solved by root isolation on its unexpanded distance, never as a quartic;
// - no global epsilon: secondary rays skip the convex solid they leave, and a ray that starts
//   inside a solid (or leaves the torus) is pushed off its surface by a few ulps;
// - the ground texture is filtered over each sample's footprint: exactly for the eye ray (the
//   parallelogram its ray differentials span), over a ray cone's width for reflected rays;
// - a pixel whose first sample lies near an edge (a silhouette, crease, shadow boundary or
//   reflected silhouette) takes the n x n grid when ADAPTIVE_AA is on: found by its own rays'
//   near-miss tests and by derivatives over its 2x2 pixel quad.
//
// The code avoids branches: it computes both answers and picks one with a select (mix, ?:),
// joins conditions with all() and any() of a bvec rather than && and ||, and ends each loop at
// its bottom, on its last needed trip. Every object is asked for every ray.
// Why each form, and what it costs: docs/numerics.md in the repository.

// ---- controls --------------------------------------------------------------------------------
// Shadertoy compiles this block as it stands. The page defines HOST_CONTROLS and declares the
// same names itself (a #define is compile-time, a const becomes a uniform), each `// ui:` comment
// making a control of its panel.
#ifndef HOST_CONTROLS
#define SAMPLES 16                                     // ui: Samples per (edge) pixel | 1, 4, 9, 16
#define ADAPTIVE_AA 1                                  // ui: Adaptive anti-aliasing | toggle
#define VIEW 0                                         // ui: View | Picture, Normals, Depth, Object, Bounces, Extra samples
#define BOUNCES 3                                      // ui: Reflection bounce limit | 0 .. 4
#define SHADOWS 1                                      // ui: Shadows | toggle
#define TEXTURE 0                                      // ui: Ground texture | Stripes, Checkerboard
#define TEXTURE_FILTER 1                               // ui: Filter texture over pixel footprint | toggle
#define SCENE 0                                        // ui: Scene (the new object) | Cone, Cylinder, Torus
const vec3  CAMERA_TARGET = vec3(0.0, 0.6, 0.0);       // ui: Camera target | -5 .. 5
const vec2  CAMERA_ORBIT = vec2(30.0, 18.0);           // ui: Camera orbit (deg) | azimuth -180 .. 180, elevation -89 .. 90
const float CAMERA_DISTANCE = 6.5;                     // ui: Camera distance | 0.1 .. 2000
const float FIELD_OF_VIEW = 45.0;                      // ui: Vertical field of view (deg) | 0.01 .. 120
const float ORBIT_SPEED = 4.0;                         // ui: Orbit speed (deg/s) | -30 .. 30
const vec3  SCENE_ORIGIN = vec3(0.0);                  // ui: Scene origin | -1000000 .. 1000000
const vec3  SPHERE_CENTER = vec3(-1.3, 0.8, 0.3);      // ui: Sphere centre | -4 .. 4
const float SPHERE_RADIUS = 0.8;                       // ui: Sphere radius | 0.05 .. 2
const vec3  CUBE_CENTER = vec3(1.0, 0.5, -1.1);        // ui: Cube centre | -4 .. 4
const vec3  CUBE_HALF_SIZE = vec3(0.5);                // ui: Cube half size | 0.05 .. 2
const vec3  CONE_BASE = vec3(1.2, 0.0, 1.1);           // ui: Cone base centre | -4 .. 4 | when SCENE = Cone
const float CONE_RADIUS = 0.55;                        // ui: Cone base radius | 0.05 .. 2 | when SCENE = Cone
const float CONE_HEIGHT = 1.7;                         // ui: Cone height | 0.05 .. 4 | when SCENE = Cone
const vec3  CYLINDER_BASE = vec3(1.2, 0.0, 1.1);       // ui: Cylinder base centre | -4 .. 4 | when SCENE = Cylinder
const float CYLINDER_RADIUS = 0.45;                    // ui: Cylinder radius | 0.05 .. 2 | when SCENE = Cylinder
const float CYLINDER_HEIGHT = 1.3;                     // ui: Cylinder height | 0.05 .. 4 | when SCENE = Cylinder
const vec3  TORUS_CENTER = vec3(1.2, 0.545, 1.1);      // ui: Torus centre | -4 .. 4 | when SCENE = Torus
const vec3  TORUS_AXIS = vec3(0.9, 1.0, 0.2);          // ui: Torus axis (any length) | -1 .. 1 | when SCENE = Torus
const vec2  TORUS_RADII = vec2(0.55, 0.17);            // ui: Torus radii | major 0.05 .. 2, minor 0.005 .. 2 | when SCENE = Torus; minor <= major
const vec3  LIGHT_POSITION = vec3(-2.5, 6.0, 4.5);     // ui: Light position | -10 .. 10
const float GROUND_REFLECTIVITY = 0.15;                // ui: Ground reflectivity | 0 .. 1
const float SPHERE_REFLECTIVITY = 0.35;                // ui: Sphere reflectivity | 0 .. 1
const float CUBE_REFLECTIVITY = 0.25;                  // ui: Cube reflectivity | 0 .. 1
const float CONE_REFLECTIVITY = 0.2;                   // ui: Cone reflectivity | 0 .. 1 | when SCENE = Cone
const float CYLINDER_REFLECTIVITY = 0.3;               // ui: Cylinder reflectivity | 0 .. 1 | when SCENE = Cylinder
const float TORUS_REFLECTIVITY = 0.3;                  // ui: Torus reflectivity | 0 .. 1 | when SCENE = Torus
#endif

// ---- constants -------------------------------------------------------------------------------
const float PI = 3.14159265358979;
const float DEG = PI / 180.0;
// Infinity for a ray's parameter (the end of an eye ray's range), written as nearly the largest
// finite float32: GLSL ES has no infinity literal. t values at or past it (a ray parallel to a
// plane up to rounding) are misses: p = ro + t * rd would be infinite or NaN.
const float T_INFINITY = 3.0e38;
// float32 unit roundoff, 2^-24: the relative error of one correctly rounded operation.
const float EPS32 = 5.960464477539063e-8;
const vec4 MISS = vec4(-1.0, 0.0, 0.0, 0.0);

// ---- intersectors ----------------------------------------------------------------------------
// Each takes a ray origin ro, a unit direction rd and a range end tMax, and returns vec4(t, n):
// t the nearest hit with 0 < t < tMax, n the unit outward normal there; a miss (or a hit at or
// past tMax) returns t < 0. A ray that starts inside a closed solid hits its far side. tMax is
// how a scene walk passes the nearest hit so far (and a shadow ray the light's distance); 0
// rejects everything.
//
// Written without early returns: every quantity is computed and the answer chosen by selects, so
// a value that is not a number where the test fails (a division by a zero that the test rules
// out) is never returned.

// A hit at t with normal n when `hit`, else MISS. mix() with a bool picks one side exactly (no
// arithmetic), so a NaN on the side not taken does not leak.
vec4 hitOrMiss(bool hit, float t, vec3 n) {
    return mix(MISS, vec4(t, n), bvec4(hit));
}

// A direction perpendicular to the unit vector axis, for where a radial direction is 0/0 (a ray
// along an axis of revolution): (-z, 0, x), or (0, z, -y) when the axis is nearly x.
vec3 anyPerpendicular(vec3 axis) {
    return mix(vec3(-axis.z, 0.0, axis.x), vec3(0.0, axis.z, -axis.y), bvec3(abs(axis.x) < 0.9));
}

// Plane dot(plane.xyz, p) + plane.w = 0, plane.xyz unit. Substituting p = ro + t rd:
// t = -(dot(n, ro) + w) / dot(n, rd). A ray parallel to the plane (dot(n, rd) == 0, also with
// the origin on the plane) is a miss, never 0/0.
vec4 intersectPlane(vec3 ro, vec3 rd, vec4 plane, float tMax) {
    float approach = dot(plane.xyz, rd);
    float t = -(dot(plane.xyz, ro) + plane.w) / approach;
    return hitOrMiss(all(bvec3(approach != 0.0, t > 0.0, t < min(tMax, T_INFINITY))), t, plane.xyz);
}

// Sphere |p - center| = radius. With f = ro - center and b = f.rd, the roots of
// t^2 + 2 b t + c = 0 (c = f.f - r^2) are -b +- sqrt(b^2 - c). The textbook b^2 - c cancels
// catastrophically when the sphere is small or far (both terms ~ |f|^2); r^2 - |f - b rd|^2 is
// the same number computed from the ray's perpendicular offset, with no cancellation
// (Haines et al., Ray Tracing Gems ch. 7). The roots come as q = -b - sign(b) sqrt(disc) and
// c / q, so neither subtracts nearly equal numbers. q == 0 only for an origin on the surface
// and a tangent ray: both roots are 0, a miss.
vec4 intersectSphere(vec3 ro, vec3 rd, vec3 center, float radius, float tMax) {
    vec3 f = ro - center;
    float b = dot(f, rd);
    vec3 offAxis = f - b * rd;
    float disc = radius * radius - dot(offAxis, offAxis);
    float q = -b - (b >= 0.0 ? 1.0 : -1.0) * sqrt(max(disc, 0.0));
    float c = dot(f, f) - radius * radius;
    float t0 = min(c / q, q), t1 = max(c / q, q);
    float t = t0 > 0.0 ? t0 : t1;
    return hitOrMiss(all(bvec4(disc >= 0.0, q != 0.0, t > 0.0, t < tMax)), t, normalize(f + t * rd));
}

// Axis-aligned box, by slabs. Per axis the ray is inside the slab for t between the two plane
// crossings. GLSL ES does not promise 1/0 = inf, and 0 * inf = NaN when the origin lies on a
// slab plane, so a zero direction component (+0 or -0) is handled by hand: the ray is inside
// that slab for all t, or never. The normal is the single axis that sets the entry (or, from
// inside, the exit) time, so it is exactly unit length even at an edge or corner. Written on
// whole vectors, with no per-component loop.
vec4 intersectBox(vec3 ro, vec3 rd, vec3 center, vec3 halfSize, float tMax) {
    vec3 o = ro - center;
    bvec3 parallel = equal(rd, vec3(0.0));
    bvec3 outsideSlab = greaterThan(abs(o), halfSize);
    vec3 inv = 1.0 / mix(rd, vec3(1.0), parallel);  // parallel axes get a harmless 1
    vec3 tA = (-halfSize - o) * inv;
    vec3 tB = (halfSize - o) * inv;
    vec3 tIn = mix(min(tA, tB), vec3(-T_INFINITY), parallel);
    vec3 tOut = mix(max(tA, tB), vec3(T_INFINITY), parallel);
    float tEnter = max(max(tIn.x, tIn.y), tIn.z);
    float tExit = min(min(tOut.x, tOut.y), tOut.z);
    bool outside = tEnter > 0.0;
    float t = outside ? tEnter : tExit;
    vec3 times = mix(tOut, tIn, bvec3(outside));
    // One axis only: the first whose time is t.
    bool onX = times.x == t, onY = all(bvec2(!onX, times.y == t));
    vec3 axis = vec3(onX, onY, !any(bvec2(onX, onY)));
    // Parallel to a slab and outside it: never inside that slab (both true: their ints sum to 2).
    bool neverInSlab = any(equal(ivec3(parallel) + ivec3(outsideSlab), ivec3(2)));
    return hitOrMiss(all(bvec4(!neverInSlab, tEnter <= tExit, tExit > 0.0, t < tMax)), t, (outside ? -1.0 : 1.0) * sign(rd) * axis);
}

// Closed capped cone from base (radius ra) to top (radius rb); rb = 0 is a pointed cone. What
// depends only on the cone (its axis frame and bounding sphere) is computed once, by makeCone,
// not once per ray.
struct Cone {
    vec3 base;
    vec3 axis;          // unit, from base to top
    float height;
    float ra, rb;
    float slope;        // k = (rb - ra) / height: the radius changes by k per unit of height
    vec3 boundCenter;   // the bounding sphere: the axis midpoint, reaching both rims
    float boundRadius;
};

Cone makeCone(vec3 pa, vec3 pb, float ra, float rb) {
    vec3 axisVector = pb - pa;
    float height = length(axisVector);
    return Cone(pa, axisVector / height, height, ra, rb, (rb - ra) / height, 0.5 * (pa + pb),
                length(vec2(0.5 * height, max(ra, rb))));
}

// The nearest part of a capped solid of revolution hit by a ray, in the solid's axis frame (the
// ray's axial coordinate yo + yd t, its radial offset oPerp + t dPerp): the side's two roots of
// a t^2 + 2 b t + c = 0 (disc its discriminant, which each caller computes in its own stable
// form), taken as c / q and q / a so that neither subtracts nearly equal numbers, each kept when
// nearer than tBest and between the caps y = 0 and y = height; then the caps, planes y = 0
// (radius rBase) and y = height (radius rTop; none when 0), inside their discs. A ray parallel
// to the caps (yd == 0) crosses neither. Returns (t, part): part 1 the side, 2 the base, 3 the
// top (the last test that moved t), 0 nothing nearer than tBest.
vec2 nearestCapped(float a, float b, float c, float disc, float yo, float yd, vec3 oPerp, vec3 dPerp, float height, float rBase, float rTop, float tBest) {
    float q = -(b + (b >= 0.0 ? 1.0 : -1.0) * sqrt(max(disc, 0.0)));
    // q == 0 only when b == 0 and disc == 0: a tangent ray whose root is t = 0 (or none).
    float cOverQ = c / q, qOverA = q / a;
    float t0 = q != 0.0 ? cOverQ : -1.0;
    float t1 = a != 0.0 ? qOverA : -1.0;
    float y0 = yo + t0 * yd, y1 = yo + t1 * yd;
    bool side0 = all(bvec4(disc >= 0.0, t0 > 0.0, t0 < tBest, all(bvec2(y0 >= 0.0, y0 <= height))));
    tBest = side0 ? t0 : tBest;
    bool side1 = all(bvec4(disc >= 0.0, t1 > 0.0, t1 < tBest, all(bvec2(y1 >= 0.0, y1 <= height))));
    tBest = side1 ? t1 : tBest;
    float tBase = -yo / yd;
    vec3 wBase = oPerp + tBase * dPerp;
    bool onBase = all(bvec4(yd != 0.0, tBase > 0.0, tBase < tBest, dot(wBase, wBase) <= rBase * rBase));
    tBest = onBase ? tBase : tBest;
    float tTop = (height - yo) / yd;
    vec3 wTop = oPerp + tTop * dPerp;
    bool onTop = all(bvec4(yd != 0.0, rTop > 0.0, all(bvec2(tTop > 0.0, tTop < tBest)), dot(wTop, wTop) <= rTop * rTop));
    tBest = onTop ? tTop : tBest;
    float part = onTop ? 3.0 : (onBase ? 2.0 : (any(bvec2(side0, side1)) ? 1.0 : 0.0));
    return vec2(tBest, part);
}

// With unit axis A, height H, slope k, a point w = p - base has axial coordinate y = A.w and
// radial offset w_perp = w - y A; the side is |w_perp|^2 = r(y)^2, r(y) = ra + k y, for
// 0 <= y <= H. On the ray, with o = ro - base, this is a t^2 + 2 b t + c = 0 with
//   a = |rd_perp|^2 - k^2 (A.rd)^2,  b = o_perp.rd_perp - k (A.rd) r(A.o),  c = |o_perp|^2 - r(A.o)^2.
// The squared equation also holds on the mirror nappe (r(y) < 0), which lies past the apex, so
// the test 0 <= y <= H rejects it. For a ray parallel to a generator line a -> 0: the roots are
// taken as c / q and q / a with q = -(b + sign(b) sqrt(b^2 - a c)), so the finite root c / q
// stays exact while q / a runs off (Eberly, Geometric Tools, "Intersection of a ray and a cone").
// The origin is first moved to the near side of the cone's bounding sphere (Wald, Ray Tracing
// Gems II ch. 34): the quadratic's error grows with the square of the distance, the shift's only
// linearly. A ray that misses that sphere, or whose range ends before it, misses the cone.
vec4 intersectCone(vec3 ro, vec3 rd, Cone cone, float tMax) {
    vec3 toCenter = cone.boundCenter - ro;
    float along = dot(toCenter, rd);
    vec3 offAxis = toCenter - along * rd;
    float tShift = max(0.0, along - cone.boundRadius);
    bool inBound = all(bvec3(dot(offAxis, offAxis) <= cone.boundRadius * cone.boundRadius,
                             along + cone.boundRadius > 0.0, tShift < tMax));

    vec3 o = ro + tShift * rd - cone.base;
    float yo = dot(o, cone.axis), yd = dot(rd, cone.axis);
    vec3 oPerp = o - yo * cone.axis, dPerp = rd - yd * cone.axis;
    float rOrigin = cone.ra + cone.slope * yo;

    // The side: both roots, each kept if it is nearer than the best so far and between the caps.
    float a = dot(dPerp, dPerp) - cone.slope * cone.slope * yd * yd;
    float b = dot(oPerp, dPerp) - cone.slope * yd * rOrigin;
    float c = dot(oPerp, oPerp) - rOrigin * rOrigin;
    // Every ray through the apex is a double root (the cone's radius and its gradient both
    // vanish there): b^2 - a c is 0 in exact arithmetic, and in float only the rounding of its
    // two products and their difference (within 2 ulps of the larger term, 4 EPS32). Taken as
    // is, that rounding's sign would choose between the exact root -b/a and two roots sqrt(it)
    // away (2e-4 at t = 3), and two renderers may round it to opposite signs. A discriminant
    // known no better than its rounding gives roots known no better than its square root either
    // way, so within it the double root is taken.
    float disc = b * b - a * c;
    disc = disc > 4.0 * EPS32 * (b * b + abs(a * c)) ? disc : min(disc, 0.0);
    vec2 nearest = nearestCapped(a, b, c, disc, yo, yd, oPerp, dPerp, cone.height, cone.ra, cone.rb, min(tMax - tShift, T_INFINITY));
    float tBest = nearest.x;
    bool onBase = nearest.y == 2.0, onTop = nearest.y == 3.0;

    // Side normal: the gradient of |w_perp| - r(y), i.e. (unit radial direction - k A), whose
    // length is sqrt(1 + k^2) because the two parts are orthogonal. Within the hit point's own
    // rounding error of the axis (the apex of a pointed cone, where the gradient is 0/0) the
    // radial direction is noise: the one facing the ray is used instead, and for a ray along
    // the axis itself any direction perpendicular to it.
    vec3 axis = cone.axis;
    vec3 wPerp = oPerp + tBest * dPerp;
    float radialNoise = 8.0 * EPS32 * (cone.height + max(cone.ra, cone.rb) + tBest);
    vec3 radial = mix(-dPerp, wPerp, bvec3(dot(wPerp, wPerp) > radialNoise * radialNoise));
    radial = mix(radial, anyPerpendicular(axis), bvec3(dot(radial, radial) == 0.0));
    vec3 sideNormal = (normalize(radial) - cone.slope * axis) * inversesqrt(1.0 + cone.slope * cone.slope);
    // The last test that moved tBest names the part hit.
    vec3 n = mix(mix(sideNormal, -axis, bvec3(onBase)), axis, bvec3(onTop));
    return hitOrMiss(all(bvec2(inBound, nearest.y > 0.0)), tShift + tBest, n);
}

// Wald's shift (Ray Tracing Gems II ch. 34): the distance a ray can travel before it reaches a
// bounding sphere, and whether it meets the sphere at all before tMax. A quadratic's error grows
// with the square of the distance from its origin, the shift's only linearly, so an intersector
// first moves the origin there. The shift stops short of the sphere by the rounding of `along` (a
// few roundings of |ro - centre| <= |along| + bound for a ray that meets the sphere): a sphere
// that touches the shape (the cylinder's rims, the torus's outer equator) would otherwise let a
// shifted origin round past the hit. Returns (tShift, 1 when the ray meets the sphere, else 0).
vec2 shiftToBound(vec3 ro, vec3 rd, vec3 center, float bound, float tMax) {
    vec3 toCenter = center - ro;
    float along = dot(toCenter, rd);
    vec3 offAxis = toCenter - along * rd;
    float tShift = max(0.0, along - bound - 8.0 * EPS32 * (abs(along) + bound));
    bool meets = all(bvec3(dot(offAxis, offAxis) <= bound * bound, along + bound > 0.0, tShift < tMax));
    return vec2(tShift, float(meets));
}

// Closed capped cylinder of radius r from pa to pb. What depends only on the cylinder (its axis
// frame and bounding sphere) is computed once, by makeCylinder.
struct Cylinder {
    vec3 base;
    vec3 axis;          // unit, from pa to pb
    float height;
    float radius;
    vec3 boundCenter;   // the bounding sphere: the axis midpoint, reaching both rims
    float boundRadius;
};

Cylinder makeCylinder(vec3 pa, vec3 pb, float radius) {
    vec3 axisVector = pb - pa;
    float height = length(axisVector);
    return Cylinder(pa, axisVector / height, height, radius, 0.5 * (pa + pb), length(vec2(0.5 * height, radius)));
}

// In the axis frame (as for the cone) the side is |w_perp| = r for 0 <= y <= H; on the ray, with
// o = ro - base, a t^2 + 2 b t + c = 0 with a = |rd_perp|^2, b = o_perp.rd_perp, c = |o_perp|^2 - r^2.
// a comes from rd_perp itself, never as 1 - (A.rd)^2, which cancels to rounding noise for a ray
// nearly along the axis (pbrt-v4's Cylinder works in the axis frame for this reason). The
// discriminant b^2 - a c is a (r^2 - |v|^2), v = o_perp - (b / a) rd_perp the point of the
// projected ray nearest the axis, computed as a (r + |v|)(r - |v|) (pbrt-v4's form; the sphere's
// perpendicular offset): b^2 and a c, both ~ |o|^2 a, never cancel. Stable roots c / q and q / a
// as for the cone. A ray along the axis has a = b = 0: neither root is taken (b / a, c / q and
// q / a are all guarded) and only the caps can be hit; a ray perpendicular to the axis (A.rd = 0)
// crosses neither cap plane. The origin is moved to the bounding sphere first, as for the cone.
vec4 intersectCylinder(vec3 ro, vec3 rd, Cylinder cylinder, float tMax) {
    vec2 shift = shiftToBound(ro, rd, cylinder.boundCenter, cylinder.boundRadius, tMax);
    float tShift = shift.x;
    bool inBound = shift.y > 0.0;

    vec3 axis = cylinder.axis;
    float r = cylinder.radius;
    // ro - base first: both may be far from the origin (1e3 and more), their difference is small.
    vec3 o = (ro - cylinder.base) + tShift * rd;
    float yo = dot(o, axis), yd = dot(rd, axis);
    vec3 oPerp = o - yo * axis, dPerp = rd - yd * axis;

    float a = dot(dPerp, dPerp), b = dot(oPerp, dPerp);
    float c = dot(oPerp, oPerp) - r * r;
    float closest = length(oPerp - (a > 0.0 ? b / a : 0.0) * dPerp);
    float disc = a * (r + closest) * (r - closest);
    vec2 nearest = nearestCapped(a, b, c, disc, yo, yd, oPerp, dPerp, cylinder.height, r, r, min(tMax - tShift, T_INFINITY));
    float tBest = nearest.x;
    bool onBase = nearest.y == 2.0, onTop = nearest.y == 3.0;

    // The side normal is the radial direction; a side hit lies at |w_perp| = r > 0, so it is never
    // 0/0. The last test that moved tBest names the part hit.
    vec3 sideNormal = normalize(oPerp + tBest * dPerp);
    vec3 n = mix(mix(sideNormal, -axis, bvec3(onBase)), axis, bvec3(onTop));
    return hitOrMiss(all(bvec2(inBound, nearest.y > 0.0)), tShift + tBest, n);
}

// Closed torus: the solid within r of its core circle, radius R about the axis through the
// centre; r <= R (r = R is the horn torus, its hole closed to a point). What depends only on the
// torus is computed once, by makeTorus.
struct Torus {
    vec3 center;
    vec3 axis;          // unit (makeTorus normalizes it)
    float majorRadius;  // R
    float tubeRatio;    // r / R: the solve runs in units of R
    float boundRadius;  // R + r: the bounding sphere about the centre
};

Torus makeTorus(vec3 center, vec3 axis, float majorRadius, float minorRadius) {
    return Torus(center, normalize(axis), majorRadius, minorRadius / majorRadius, majorRadius + minorRadius);
}

// A ray in a torus's frame, in units of R: y(t) = yo + yd t along the axis, and across it
// rho(t)^2 = m2 + a (t - tc)^2 (a = |rd_perp|^2, tc the parameter of the closest approach to the
// axis, m2 its square distance there). This centred form has no cancellation: m2 is the squared
// length of that closest offset itself (the sphere's trick), and a (t - tc)^2 adds a positive term.
struct TorusRay {
    float yo, yd, a, tc, m2;
    float k;            // the tube radius r / R
};

// g(t) = |(rho - 1, y)| - k: the signed distance of the ray's point to the tube's surface, and its
// slope along the ray, at two parameters at once. This is the surface function unexpanded: near
// a root rho - 1 and y carry the rounding of numbers of size 1 and nothing cancels, so g is good
// to a few EPS32 for any tube radius; the expanded quartic's constant term subtracts two terms of
// size R^4 to leave one of size R^2 r^2 (about 2 log2(R / r) bits lost: 20 of 24 at r = 1e-3 R).
// Its gradient is unit, so Newton's method on it is well conditioned. At the axis (rho = 0) and
// at the core circle g has a kink: its slope is taken as 0 there, and the solver bisects.
vec2 torusDistance(TorusRay ray, vec2 t, out vec2 slope) {
    vec2 u = t - ray.tc;
    vec2 rho = sqrt(ray.m2 + ray.a * u * u);
    vec2 y = ray.yo + ray.yd * t;
    vec2 core = sqrt((rho - 1.0) * (rho - 1.0) + y * y);
    vec2 dRho = ray.a * u / mix(rho, vec2(1.0), equal(rho, vec2(0.0)));
    slope = ((rho - 1.0) * dRho + y * ray.yd) / mix(core, vec2(1.0), equal(core, vec2(0.0)));
    return core - ray.k;
}

// F(t) = (rho - 1)^2 + y^2 - k^2 = g (g + 2k) has the roots, critical points and monotone
// pieces of g. Half its first and second derivatives, at three parameters (|rd| = 1, u = t - tc):
//   F'/2 = yd y + a u (1 - 1 / rho),    F''/2 = 1 - a m2 / rho^3,
// both from one inversesqrt (they only place the critical points: a few ulps do not matter).
// rho = 0 only where m2 = 0 and u = 0: there F'/2 = yd y and F''/2 = 1.
void torusBend(TorusRay ray, vec3 t, out vec3 dF, out vec3 ddF) {
    vec3 u = t - ray.tc;
    vec3 rho2 = ray.m2 + ray.a * u * u;
    vec3 inv = mix(inversesqrt(rho2), vec3(0.0), equal(rho2, vec3(0.0)));
    dF = ray.yd * (ray.yo + ray.yd * t) + ray.a * u * (1.0 - inv);
    ddF = 1.0 - ray.a * ray.m2 * inv * inv * inv;
}

// The torus by root isolation, never by a closed-form quartic (a resolvent cubic's small root
// loses most of its digits in float32, and gives fake hits in the hole). Every root is a sign change of the unexpanded g, found in a bracket where g is
// monotone, so a hit off the surface cannot be returned. The brackets come from the shape of F:
// F'' = 2 - 2 a m2 / rho^3 is negative only where rho^3 < a m2, an interval tc +- s about the
// closest approach to the axis (empty when m2 >= a^2). So F' rises on the outer pieces and falls
// on the middle one: one root of F' at most in each, F has at most three critical points
// c1 <= c2 <= c3, and g is monotone between them: one root at most in each of the four gaps.
// Each F' root is found by Newton's method from the end of its piece where Fourier's condition
// holds (F' and F''' of one sign; F''' has the sign of t - tc), so its iterates move
// monotonically and never leave the piece; each g root by Newton's method on g, bisecting
// whenever a step would leave the bracket (a safeguarded Newton, as Numerical Recipes' rtsafe).
// The two roots that can be the first past the origin are solved as one vec2. The origin is
// first moved to the bounding sphere (Wald, Ray Tracing Gems II ch. 34), then everything runs in
// units of R.
vec4 intersectTorus(vec3 ro, vec3 rd, Torus torus, float tMax) {
    // (the sphere touches the torus all along its outer equator, where a radial ray's entry root
    // is the sphere's point: shiftToBound stops short of it)
    vec2 shift = shiftToBound(ro, rd, torus.center, torus.boundRadius, tMax);
    float tShift = shift.x;
    bool inBound = shift.y > 0.0;

    vec3 axis = torus.axis;
    vec3 o = ((ro - torus.center) + tShift * rd) / torus.majorRadius;
    TorusRay ray;
    ray.k = torus.tubeRatio;
    ray.yo = dot(o, axis);
    ray.yd = dot(rd, axis);
    vec3 oPerp = o - ray.yo * axis, dPerp = rd - ray.yd * axis;
    ray.a = dot(dPerp, dPerp);
    ray.tc = ray.a > 0.0 ? -dot(oPerp, dPerp) / ray.a : 0.0;
    vec3 closest = oPerp + ray.tc * dPerp;
    ray.m2 = dot(closest, closest);

    // Roots can lie only inside the bounding sphere (radius 1 + k here) and the slab |y| <= k.
    // Both touch the torus (along the outer equator, and the top and bottom circles), so both are
    // widened past the rounding of their chord (a few roundings of numbers of size 1 + k, and of
    // |yo| + k): an end of the range is then outside the torus whenever the origin is.
    float bo = dot(o, rd);
    vec3 off = o - bo * rd;
    float bound = (1.0 + ray.k) * (1.0 + 16.0 * EPS32);
    float h2 = bound * bound - dot(off, off);
    float h = sqrt(max(h2, 0.0));
    float slab = ray.k + 8.0 * EPS32 * (abs(ray.yo) + ray.k);
    float slabA = (-slab - ray.yo) / ray.yd, slabB = (slab - ray.yo) / ray.yd;
    bool level = ray.yd == 0.0;  // parallel to the slab: inside it for all t, or never
    float lo = max(max(-bo - h, 0.0), level ? 0.0 : min(slabA, slabB));
    float hi = min(-bo + h, level ? T_INFINITY : max(slabA, slabB));
    bool inRange = all(bvec3(h2 >= 0.0, lo < hi, any(bvec2(!level, abs(ray.yo) <= slab))));
    // A ray with no range gets the empty one, [lo, lo]: both loops below end on their first trip
    // (and clamp() never sees its ends crossed, which GLSL leaves undefined).
    hi = all(bvec2(inBound, inRange)) ? hi : lo;

    // The pieces of F': [lo, tc - s], [tc - s, tc + s], [tc + s, hi], clipped to the range. The
    // cube root rho_b = (a m2)^(1/3) from pow, then one Newton step (pow is held to no accuracy).
    float bendCube = ray.a * ray.m2;
    float rhoBend = pow(bendCube, 1.0 / 3.0);
    rhoBend = rhoBend > 0.0 ? rhoBend - (rhoBend - bendCube / (rhoBend * rhoBend)) / 3.0 : 0.0;
    float spread = ray.a > 0.0 ? sqrt(max(rhoBend * rhoBend - ray.m2, 0.0) / ray.a) : 0.0;
    vec3 lower = clamp(vec3(lo, ray.tc - spread, ray.tc + spread), lo, hi);
    vec3 upper = clamp(vec3(ray.tc - spread, ray.tc + spread, hi), lo, hi);
    // Fourier's starts: lo (F' concave, rising), tc (the middle piece falls, concave before tc and
    // convex after it: Newton from tc moves away from it either way), hi (convex, rising).
    const vec3 FALLS = vec3(1.0, -1.0, 1.0);
    vec3 crit = vec3(lo, clamp(ray.tc, lower.y, upper.y), hi);
    // t is at most hi, and g or F' at it costs a few roundings of numbers of size |o| + hi: steps
    // below tNoise are rounding noise. g itself is good to about gNoise (rho from rho^2 and its
    // sqrt, then |(rho - 1, y)|, each a rounding or two of numbers up to 1 + hi): below it, even
    // its sign says nothing more.
    float tNoise = 8.0 * EPS32 * (hi + 1.0);
    float gNoise = 2.0 * EPS32 * (hi + 1.0);
    // Newton takes a few trips; a triple zero of F' (a ray whose closest approach to the axis is
    // also an inflection, m2 = a^2) it approaches only linearly, and the cap of 12 stops it.
    for (int trip = 1;; trip++) {
        vec3 dF, ddF;
        torusBend(ray, crit, dF, ddF);
        // A step that would leave the piece means no root in it: F' keeps one sign there, and the
        // critical point is the end it points to (also where F'' = 0, at an end of the middle piece).
        bvec3 leaves = greaterThan(abs(dF), abs(ddF) * (upper - lower));
        vec3 end = mix(lower, upper, lessThan(FALLS * dF, vec3(0.0)));
        vec3 newton = crit - FALLS * dF / mix(abs(ddF), vec3(1.0), equal(ddF, vec3(0.0)));
        vec3 next = clamp(mix(newton, end, leaves), lower, upper);
        bool done = all(lessThanEqual(abs(next - crit), vec3(tNoise)));
        crit = next;
        if (any(bvec2(done, trip == 12))) break;
    }

    // The four gaps between lo <= c1 <= c2 <= c3 <= hi; a root where g changes sign across one.
    // g(hi) is not evaluated: hi ends the widened range, outside the torus, so g(hi) > 0, and
    // g(c3) + (hi - c3) bounds it (g changes by at most 1 per unit of t), which is all the chord
    // start below needs (it is g(hi) for a ray leaving the tube square on).
    vec4 left = vec4(lo, crit), right = vec4(crit, hi);
    vec2 slope;
    vec4 gLeft = vec4(torusDistance(ray, left.xy, slope), torusDistance(ray, left.zw, slope));
    vec4 gRight = vec4(gLeft.yzw, max(gLeft.w + (hi - crit.z), gNoise));
    bvec4 insideLeft = lessThan(gLeft, vec4(0.0));
    bvec4 crosses = notEqual(insideLeft, lessThan(gRight, vec4(0.0)));
    // Only the first root past the origin is wanted: a gap after the first one that crosses and
    // starts past 0 (its root is at least its start) is dropped, so the loop does not wait for
    // roots nobody uses. (A crossing gap that starts at 0 may hold the root t = 0 of an origin on
    // the surface, not a hit: the next one is kept too.) Products of 0/1 vectors are ANDs.
    const vec4 GAP = vec4(0.0, 1.0, 2.0, 3.0);
    vec4 firstGaps = mix(vec4(4.0), GAP, bvec4(vec4(crosses) * vec4(greaterThan(left, vec4(0.0)))));
    float first = min(min(firstGaps.x, firstGaps.y), min(firstGaps.z, firstGaps.w));
    // So at most two gaps are solved: that first one, and before it one that crosses from t = 0
    // (the ends only grow, and a gap of no width cannot cross: g is the same at both of its ends,
    // so at most one crossing gap starts at 0). The loop below solves the two as one vec2.
    vec4 zeroGaps = mix(vec4(4.0), GAP, bvec4(vec4(crosses) * vec4(lessThanEqual(left, vec4(0.0))) * vec4(lessThan(GAP, vec4(first)))));
    float fromZero = min(min(zeroGaps.x, zeroGaps.y), min(zeroGaps.z, zeroGaps.w));
    bvec2 solved = lessThan(vec2(fromZero, first), vec2(4.0));
    ivec2 gap = ivec2(min(vec2(fromZero, first), vec2(3.0)));
    vec2 lo2 = vec2(left[gap.x], left[gap.y]), hi2 = vec2(right[gap.x], right[gap.y]);
    vec2 gLo = vec2(gLeft[gap.x], gLeft[gap.y]), gHi = vec2(gRight[gap.x], gRight[gap.y]);
    bvec2 insideLo = lessThan(gLo, vec2(0.0));
    // Start where the chord across the gap crosses 0: g is a distance, close to linear. Newton
    // converges only linearly on near-tangent rays; the cap of 16 trips is past their need.
    vec2 root = mix(0.5 * (lo2 + hi2), lo2 + (hi2 - lo2) * gLo / (gLo - gHi), solved);
    for (int trip = 1;; trip++) {
        vec2 g = torusDistance(ray, root, slope);
        bvec2 likeLo = equal(lessThan(g, vec2(0.0)), insideLo);
        lo2 = mix(lo2, root, likeLo);
        hi2 = mix(root, hi2, likeLo);
        // Newton's step where it stays in the bracket, else bisection. A step that leaves it by
        // no more than rounding is clamped to the end, not rejected: a root can sit within
        // rounding of an end, and bisection would then creep to it one halving a trip.
        vec2 newton = root - g / mix(slope, vec2(1.0), equal(slope, vec2(0.0)));
        vec2 kept = clamp(newton, lo2, hi2);
        vec2 next = mix(0.5 * (lo2 + hi2), kept, lessThanEqual(abs(newton - kept), vec2(tNoise)));
        // A gap without a root stays put, and so does a point on the surface to rounding (|g| at
        // most gNoise): a step from there would be noise over g', a jump where g' is near 0.
        next = mix(root, next, solved);
        bvec2 onSurface = lessThanEqual(abs(g), vec2(gNoise));
        next = mix(next, root, onSurface);
        // Done: on the surface, or a step or bracket below rounding, in every gap.
        vec2 unsettled = mix(min(abs(next - root), hi2 - lo2), vec2(0.0), onSurface);
        bool done = all(lessThanEqual(unsettled, vec2(tNoise)));
        root = next;
        if (any(bvec2(done, trip == 16))) break;
    }

    // The first root past the origin (the gaps are in order along the ray).
    vec2 found = mix(vec2(T_INFINITY), root, solved);
    found = mix(vec2(T_INFINITY), found, greaterThan(found, vec2(0.0)));
    float t = min(found.x, found.y);

    // Normal: the gradient of g, (rho - 1) times the radial unit vector plus y times the axis.
    // rho > 1 - k at every hit, so the radial direction is 0/0 only for the horn torus (k = 1) at
    // its centre: there (within rounding) the direction facing the ray is used, as at the cone's apex.
    vec3 pPerp = oPerp + t * dPerp;
    float y = ray.yo + t * ray.yd;
    float u = t - ray.tc;
    float rho = sqrt(ray.m2 + ray.a * u * u);
    vec3 radial = mix(-dPerp, pPerp, bvec3(rho > tNoise));
    radial = mix(radial, anyPerpendicular(axis), bvec3(dot(radial, radial) == 0.0));
    vec3 n = normalize((rho - 1.0) * normalize(radial) + y * axis);
    float tHit = tShift + t * torus.majorRadius;
    return hitOrMiss(all(bvec4(inBound, inRange, t < T_INFINITY, tHit < tMax)), tHit, n);
}

// ---- near misses: how close a ray cone passes to each primitive's outline --------------------
// The adaptive anti-aliasing's edge tests (below, EDGE_TESTS) ask these of a pixel's own rays:
// closed forms per primitive, no extra trace.

// A ray standing for a cone: its width at distance t is w0 + w1 t (w1 < 0: one that narrows to a
// point at the end, as a shadow ray's towards a point light), tested for outlines up to tEnd.
struct RayCone {
    vec3 ro, rd;
    float w0, w1, tEnd;
};

float widthAt(RayCone c, float t) {
    return max(c.w0 + c.w1 * t, 0.0);
}

// The sphere's outline: the ray passes at |offAxis| from the centre; the outline is within the
// cone when |offAxis| - r is within its width there, and in front of where the cone ends.
bool nearSphere(RayCone c, vec3 center, float radius) {
    vec3 f = center - c.ro;
    float along = dot(f, c.rd);
    float off = length(f - along * c.rd);
    return all(bvec3(abs(off - radius) < widthAt(c, along), along + radius > 0.0, along - radius < c.tEnd));
}

// A box's outline: the ray hits the box grown by the cone's width (half-sizes + w: each slab's
// interval wider by w / |rd_i|) and misses it shrunk by w. One slab computation, as intersectBox's.
bool nearBox(RayCone c, vec3 center, vec3 halfSize) {
    vec3 o = c.ro - center;
    float w = widthAt(c, max(-dot(o, c.rd), 0.0));
    bvec3 parallel = equal(c.rd, vec3(0.0));
    vec3 inv = 1.0 / mix(c.rd, vec3(1.0), parallel);
    vec3 tA = (-halfSize - o) * inv, tB = (halfSize - o) * inv;
    vec3 grow = mix(w * abs(inv), vec3(0.0), parallel);
    vec3 tIn = mix(min(tA, tB), vec3(-T_INFINITY), parallel), tOut = mix(max(tA, tB), vec3(T_INFINITY), parallel);
    vec3 margin = halfSize - abs(o);  // a parallel axis: how far inside its slab the ray runs
    vec3 inGrown = tIn - grow, outGrown = tOut + grow, inShrunk = tIn + grow, outShrunk = tOut - grow;
    float enterGrown = max(max(inGrown.x, inGrown.y), inGrown.z), exitGrown = min(min(outGrown.x, outGrown.y), outGrown.z);
    float enterShrunk = max(max(inShrunk.x, inShrunk.y), inShrunk.z), exitShrunk = min(min(outShrunk.x, outShrunk.y), outShrunk.z);
    bool grown = all(bvec4(enterGrown <= exitGrown, exitGrown > 0.0, enterGrown < c.tEnd, !any(lessThan(mix(vec3(1.0), margin + w, parallel), vec3(0.0)))));
    bool shrunk = all(bvec3(enterShrunk <= exitShrunk, exitShrunk > 0.0, !any(lessThan(mix(vec3(1.0), margin - w, parallel), vec3(0.0)))));
    return all(bvec2(grown, !shrunk));
}

// The outline of a capped solid of revolution about the unit axis from base, radius ra + k y at
// height y in [0, H] (the cone, and the cylinder with k = 0). Along the ray (axial coordinate
// y(t), distance rho(t) from the axis, rho^2 = m2 + a (t - tc)^2 as for the torus), the distance
// to the side's generator line is D(t) = (rho - ra - k y) / sqrt(1 + k^2); its extremum is where
// rho' = k y', at t = tc + u, u = k yd sqrt(m2 / (a (a - k^2 yd^2))) (none for a ray steeper than
// the side). There the side's outline is within the cone if |D| is. The rims: where the ray
// crosses a cap's plane at rho, the rim is |rho - r| away in that plane, |rho - r| |yd| across the
// ray. (The apex is the top rim of radius 0.)
bool nearRevolution(RayCone c, vec3 base, vec3 axis, float height, float ra, float k, float bound) {
    vec3 o = c.ro - base;
    float yo = dot(o, axis), yd = dot(c.rd, axis);
    vec3 oPerp = o - yo * axis, dPerp = c.rd - yd * axis;
    float a = dot(dPerp, dPerp);
    float tc = a > 0.0 ? -dot(oPerp, dPerp) / a : 0.0;
    vec3 closest = oPerp + tc * dPerp;
    float m2 = dot(closest, closest);
    float steep = a * (a - k * k * yd * yd);
    float u = steep > 0.0 ? k * yd * sqrt(m2 / steep) : 0.0;
    float tSide = tc + u;
    float ySide = yo + yd * tSide;
    float side = abs(sqrt(m2 + a * u * u) - ra - k * ySide) * inversesqrt(1.0 + k * k);
    float wSide = widthAt(c, tSide);
    bool nearSide = all(bvec4(steep > 0.0, side < wSide, ySide > -wSide, ySide < height + wSide));
    vec2 tCap = (vec2(0.0, height) - yo) / yd;
    vec2 rhoCap = vec2(length(oPerp + tCap.x * dPerp), length(oPerp + tCap.y * dPerp));
    vec2 rim = abs(rhoCap - vec2(ra, ra + k * height)) * abs(yd);
    vec2 wCap = vec2(widthAt(c, tCap.x), widthAt(c, tCap.y));
    // A rim crossed behind where the ray ends, by more than the cone's width across it, is hidden
    // (the back half of the base ellipse, behind the solid's own body): (tCap - tEnd) |yd| is how
    // far the ray's end lies from the cap's plane, as |rho - r| |yd| is how far from the rim.
    bvec2 inView = lessThan((tCap - c.tEnd) * abs(yd), wCap);
    bvec2 nearRim = bvec2(vec2(lessThan(rim, wCap)) * vec2(inView));
    bool inFront = all(bvec2(tc + bound > 0.0, tc - bound < c.tEnd));
    bool rims = all(bvec2(yd != 0.0, any(nearRim)));  // a ray parallel to the caps crosses no rim
    return all(bvec2(inFront, any(bvec2(nearSide, rims))));
}

// The ground's outline is the horizon: a ray cone that meets it within its own spread of parallel.
bool nearHorizon(RayCone c, vec4 plane) {
    return abs(dot(plane.xyz, c.rd)) < c.w1;
}

// ---- the new object --------------------------------------------------------------------------
// The assignment's new object, chosen by SCENE at compile time: the cone, the cylinder or the
// torus. Each offers the scene the same interface, so that nothing else in the file depends on
// which it is:
//   Object                       its type (the intersector's own struct)
//   OBJECT_COLOR, _REFLECTIVITY  its material (from the control block)
//   placeObject(eyeLocal)        the object relative to the eye (see Scene)
//   intersectObject(...)         its intersector, as the others: vec4(t, n)
//   objectSurfacePoint(o, p, n)  a hit point put back on its surface, where that is cheap
//   objectMirrorRadius(o, p)     its radius of curvature at p as a mirror (its most curved direction)
//   reenters(id)                 whether a ray leaving the surface of `id` can meet it again: not
//                                the ground and the convex solids (the scene walk then skips
//                                them); the torus can (its hole, its inner wall), so such a ray
//                                starts a few ulps off the surface, outside, and the torus stays
//                                in the walk
//   nearObject(cone, o)          whether a ray cone passes near its outline (the edge tests)
const int ID_NONE = -1;
const int ID_GROUND = 0;
const int ID_SPHERE = 1;
const int ID_CUBE = 2;
const int ID_OBJECT = 3;  // the new object

#if SCENE == 0
#define Object Cone
#define OBJECT_COLOR CONE_COLOR
#define OBJECT_REFLECTIVITY CONE_REFLECTIVITY

Object placeObject(vec3 eyeLocal) {
    return makeCone(CONE_BASE - eyeLocal, CONE_BASE + vec3(0.0, CONE_HEIGHT, 0.0) - eyeLocal, CONE_RADIUS, 0.0);
}

vec4 intersectObject(vec3 ro, vec3 rd, Object cone, float tMax) {
    return intersectCone(ro, rd, cone, tMax);
}

vec3 objectSurfacePoint(Object cone, vec3 p, vec3 n) {
    return p;
}

// The side curves with radius r(y) across its axis: 0 at the apex.
float objectMirrorRadius(Object cone, vec3 p) {
    return CONE_RADIUS * max(1.0 - (p.y - cone.base.y) / CONE_HEIGHT, 0.0);
}

bool reenters(int id) {
    return false;
}

bool nearObject(RayCone c, Object cone) {
    return nearRevolution(c, cone.base, cone.axis, cone.height, cone.ra, cone.slope, cone.boundRadius);
}

#elif SCENE == 1
#define Object Cylinder
#define OBJECT_COLOR CYLINDER_COLOR
#define OBJECT_REFLECTIVITY CYLINDER_REFLECTIVITY

Object placeObject(vec3 eyeLocal) {
    return makeCylinder(CYLINDER_BASE - eyeLocal, CYLINDER_BASE + vec3(0.0, CYLINDER_HEIGHT, 0.0) - eyeLocal, CYLINDER_RADIUS);
}

vec4 intersectObject(vec3 ro, vec3 rd, Object cylinder, float tMax) {
    return intersectCylinder(ro, rd, cylinder, tMax);
}

vec3 objectSurfacePoint(Object cylinder, vec3 p, vec3 n) {
    return p;
}

float objectMirrorRadius(Object cylinder, vec3 p) {
    return CYLINDER_RADIUS;
}

bool reenters(int id) {
    return false;
}

bool nearObject(RayCone c, Object cylinder) {
    return nearRevolution(c, cylinder.base, cylinder.axis, cylinder.height, cylinder.radius, 0.0, cylinder.boundRadius);
}

#else
#define Object Torus
#define OBJECT_COLOR TORUS_COLOR
#define OBJECT_REFLECTIVITY TORUS_REFLECTIVITY

// An axis of length 0 means none: upright. The tube is no wider than the hole's radius.
Object placeObject(vec3 eyeLocal) {
    vec3 axis = dot(TORUS_AXIS, TORUS_AXIS) > 0.0 ? TORUS_AXIS : vec3(0.0, 1.0, 0.0);
    return makeTorus(TORUS_CENTER - eyeLocal, axis, TORUS_RADII.x, min(TORUS_RADII.y, TORUS_RADII.x));
}

vec4 intersectObject(vec3 ro, vec3 rd, Object torus, float tMax) {
    return intersectTorus(ro, rd, torus, tMax);
}

// The point from the torus's core circle: the nearest point of the core, then the tube's radius
// along the normal. Rays leave the torus from here, and may meet it again (reenters), so the
// start must be off the surface by more than the point's error: this puts that error at a few
// roundings of the point's coordinates, where the intersector's t leaves up to K u S (S the
// distance the ray came), and the step off it can be small (leaveTorus). On the axis (no
// nearest point of the core) the point stays as it is.
vec3 objectSurfacePoint(Object torus, vec3 p, vec3 n) {
    vec3 q = p - torus.center;
    vec3 radial = q - dot(q, torus.axis) * torus.axis;
    vec3 core = torus.center + torus.majorRadius * normalize(radial);
    return mix(p, core + (torus.tubeRatio * torus.majorRadius) * n, bvec3(dot(radial, radial) > 0.0));
}

// Across its tube, with the tube's radius.
float objectMirrorRadius(Object torus, vec3 p) {
    return torus.tubeRatio * torus.majorRadius;
}

bool reenters(int id) {
    return id == ID_OBJECT;
}

// The torus's outline has no cheap closed form (its distance from a line is a quartic's root
// again). By its definition, the cone hitting the torus with its tube grown by the cone's width
// and missing it shrunk, it takes two more torus solves per ray, far too slow. So the torus's
// edges are left to the quad's derivative test (mainImage).
bool nearObject(RayCone c, Object torus) {
    return false;
}
#endif

// ---- the scene -------------------------------------------------------------------------------

// Everything is traced relative to the eye: positions near the eye keep all their digits even
// when the scene (and the camera with it) sits far from the origin.
struct Scene {
    vec4 ground;        // plane y_world = 0, as a plane equation in eye-relative coordinates
    vec3 sphereCenter;
    vec3 cubeCenter;
    float sphereRadius;
    vec3 cubeHalfSize;
    Object object;      // the new object (SCENE)
    vec3 light;
    vec4 reflectivity;  // ground, sphere, cube, the new object
    vec2 textureOrigin; // world xz of the eye, reduced modulo the texture period (2)
};

Scene sceneRelativeTo(vec3 eyeLocal) {
    Scene s;
    s.ground = vec4(0.0, 1.0, 0.0, eyeLocal.y);
    s.sphereCenter = SPHERE_CENTER - eyeLocal;
    s.cubeCenter = CUBE_CENTER - eyeLocal;
    s.sphereRadius = SPHERE_RADIUS;
    s.cubeHalfSize = CUBE_HALF_SIZE;
    s.reflectivity = vec4(GROUND_REFLECTIVITY, SPHERE_REFLECTIVITY, CUBE_REFLECTIVITY, OBJECT_REFLECTIVITY);
    s.object = placeObject(eyeLocal);
    s.light = LIGHT_POSITION - eyeLocal;
    // mod() of each term separately keeps the sum small: SCENE_ORIGIN may be ~1e4 or more.
    s.textureOrigin = mod(SCENE_ORIGIN.xz, 2.0) + mod(eyeLocal.xz, 2.0);
    return s;
}

struct Hit {
    float t;    // tMax for a miss
    vec3 n;     // unit outward normal
    int id;     // ID_NONE for a miss
};

// The nearer of a hit so far and an intersector's answer h for object id.
Hit nearer(Hit hit, vec4 h, int id) {
    bool take = h.x > 0.0;
    return Hit(take ? h.x : hit.t, mix(hit.n, h.yzw, bvec3(take)), take ? id : hit.id);
}

// The largest of a vector's components in magnitude: the scale of the rounding in a position.
float maxAbs(vec3 v) {
    return max(max(abs(v.x), abs(v.y)), abs(v.z));
}

// How far from the ground's plane (in units of float32's unit roundoff times the size of the
// numbers involved) a hit point may lie and still be in that plane. An intersector puts its hit
// within about K u S of its surface, S the distance from the ray's origin plus the object's
// size (K = 32 is what the intersectors are tested to; the height of a point on a face is off
// by that however grazing the ray, as the error in t runs along the ray); the plane's own height
// is off by u |w|. Twice that, so that both sides of a tie land in the band.
const float GROUND_BAND_ULPS = 64.0;

// The one scene walk, for every ray: the nearest hit with 0 < t < tMax. An eye or reflection
// ray passes tMax = T_INFINITY; a shadow ray passes the light's distance, and is blocked when the
// walk finds anything ("any hit before the light" is "a nearest hit before the light": the
// same answer, and one copy of the intersector code). Each object is asked only for hits
// nearer than the best so far. skipId is the convex solid the ray is leaving: it cannot be hit
// again, so its range is empty (tMax 0).
//
// A surface that lies in the ground's own plane (the cone's base and the cube's bottom, at the
// default controls) is the ground, whatever the rounding: otherwise the nearer of the two is
// decided by the last bits of two different computations, and from below the ground (the eye
// under it) the cone's and the cube's colours show through in speckles. So a hit whose point is
// within the rounding band of the ground's plane, on a ray that meets the ground, is the
// ground's.
//
// Every object is asked, whatever the ray: no bounding-sphere skip.
Hit traceScene(Scene s, vec3 ro, vec3 rd, int skipId, float tMax) {
    vec4 ground = intersectPlane(ro, rd, s.ground, skipId == ID_GROUND ? 0.0 : tMax);
    // The objects are asked only for hits nearer than the ground's by more than the band: along
    // the ray a point's height above the plane is |n.rd| (tGround - t), so "within the band of
    // the plane" is "within band / |n.rd| of the ground's t". Same test as checking the height
    // of the nearest object's point afterwards, and only a float kept across the walk.
    float band = GROUND_BAND_ULPS * EPS32 * (ground.x + maxAbs(ro) + abs(s.ground.w));
    float tGround = ground.x;
    Hit hit = Hit(tGround > 0.0 ? tGround - band / abs(dot(s.ground.xyz, rd)) : tMax, vec3(0.0), ID_NONE);
    hit = nearer(hit, intersectSphere(ro, rd, s.sphereCenter, s.sphereRadius, skipId == ID_SPHERE ? 0.0 : hit.t), ID_SPHERE);
    hit = nearer(hit, intersectBox(ro, rd, s.cubeCenter, s.cubeHalfSize, skipId == ID_CUBE ? 0.0 : hit.t), ID_CUBE);
    hit = nearer(hit, intersectObject(ro, rd, s.object, skipId == ID_OBJECT ? 0.0 : hit.t), ID_OBJECT);
    bool groundNearest = all(bvec2(hit.id == ID_NONE, tGround > 0.0));
    return Hit(groundNearest ? tGround : hit.t, mix(hit.n, s.ground.xyz, bvec3(groundNearest)), groundNearest ? ID_GROUND : hit.id);
}

// ---- materials and texture -------------------------------------------------------------------
// Plain `const` lines, one value each: the project's float64 reference reads them from this file.
const vec3  SPHERE_COLOR = vec3(0.85, 0.18, 0.12);
const vec3  CUBE_COLOR = vec3(0.15, 0.35, 0.85);
const vec3  CONE_COLOR = vec3(0.85, 0.2, 0.75);        // magenta, as in the assignment
const vec3  CYLINDER_COLOR = vec3(0.2, 0.7, 0.35);
const vec3  TORUS_COLOR = vec3(0.95, 0.7, 0.15);
const vec3  STRIPE_COLOR = vec3(0.8, 0.5, 0.2);        // the assignment's (fract(x) + 0.3) * colour
const float STRIPE_OFFSET = 0.3;
const vec3  CHECKER_LIGHT = vec3(0.9);
const vec3  CHECKER_DARK = vec3(0.25);
const vec3  SKY_HORIZON = vec3(0.78, 0.86, 0.95);
const vec3  SKY_ZENITH = vec3(0.32, 0.52, 0.85);
const float AMBIENT = 0.15;
const float SPECULAR = 0.5;
const float SHININESS = 40.0;

vec3 objectColor(int id) {
    return id == ID_SPHERE ? SPHERE_COLOR : (id == ID_CUBE ? CUBE_COLOR : OBJECT_COLOR);
}

// The two ground patterns, each with its first and second integrals (P1' = P, P2' = P1), both
// continuous, so that a filtered pattern costs the same for a footprint of any width:
//   stripes, fract:  P1(x) = floor(x)/2 + r^2/2,  P2(x) = x^2/4 - floor(x)/12 - r^2/4 + r^3/6,  r = fract(x)
//   checkers, the square wave s(x) = floor(x) mod 2, with k = floor(x/2), y = x - 2k:
//                    P1(x) = k + max(y - 1, 0),  P2(x) = k(k - 1) + k/2 + k y + max(y - 1, 0)^2 / 2
// (One definition each, the pattern chosen inside: TEXTURE is fixed at compile time.)
float pattern(float x) {
#if TEXTURE == 0
    return fract(x);
#else
    return mod(floor(x), 2.0);
#endif
}

float patternIntegral(float x) {
#if TEXTURE == 0
    float r = fract(x);
    return 0.5 * floor(x) + 0.5 * r * r;
#else
    return floor(0.5 * x) + max(2.0 * fract(0.5 * x) - 1.0, 0.0);
#endif
}

float patternIntegral2(float x) {
#if TEXTURE == 0
    float r = fract(x);
    return 0.25 * x * x - floor(x) / 12.0 - 0.25 * r * r + r * r * r / 6.0;
#else
    float k = floor(0.5 * x), over = max(x - 2.0 * k - 1.0, 0.0);
    return k * (k - 1.0) + 0.5 * k + k * (x - 2.0 * k) + 0.5 * over * over;
#endif
}

// The pattern averaged over x + U, U the sum of two independent uniform offsets of widths wa and
// wb: a footprint spanned by two vectors (a pixel's parallelogram on the ground), projected on
// one world axis, is exactly that; a ray cone's width is wb = 0. Its density is a trapezoid, so
// the average is the second difference of P2 over 4ab (a, b the half-widths, a >= b); for
// b < a/64 it is within 1e-4 of the box of width 2a, (P1(x + a) - P1(x - a)) / 2a, which is used
// instead there: the second difference would lose about a/b of float32's digits to cancellation.
// Inside one linear piece of the pattern the average is the pattern at the centre, exactly.
// Both patterns repeat every 2, so x moves by a multiple of 2 next to 0 first: P2 then takes
// small arguments (its second differences do not change: P2 gains a linear term per period).
float filteredPattern(float x, float wa, float wb) {
    float a = 0.5 * max(wa, wb), b = 0.5 * min(wa, wb);
    float x0 = x - 2.0 * floor(0.5 * x + 0.5);
    float box = (patternIntegral(x0 + a) - patternIntegral(x0 - a)) / (2.0 * a);
    float trapezoid = (patternIntegral2(x0 + a + b) - patternIntegral2(x0 + a - b)
                     - patternIntegral2(x0 - a + b) + patternIntegral2(x0 - a - b)) / (4.0 * a * b);
    float filtered = 64.0 * b < a ? box : trapezoid;
    return floor(x0 - a - b) == floor(x0 + a + b) ? pattern(x) : filtered;
}

// Ground albedo at texture coordinate uv (world xz reduced modulo 2) for a footprint whose two
// spanning vectors have the extents footprint.xy along x and footprint.zw along z.
vec3 groundColor(vec2 uv, vec4 footprint) {
#if TEXTURE == 0
    // The assignment's stripes: (fract(x) + 0.3) * vec3(0.8, 0.5, 0.2).
#if TEXTURE_FILTER
    float stripe = filteredPattern(uv.x, footprint.x, footprint.y);
#else
    float stripe = pattern(uv.x);
#endif
    return (stripe + STRIPE_OFFSET) * STRIPE_COLOR;
#else
    // The lecture's checkerboard; the filtered XOR of two square waves filtered one by one is
    // sx + sz - 2 sx sz (exact for footprints along the axes, close for the others).
#if TEXTURE_FILTER
    float sx = filteredPattern(uv.x, footprint.x, footprint.y), sz = filteredPattern(uv.y, footprint.z, footprint.w);
#else
    float sx = pattern(uv.x), sz = pattern(uv.y);
#endif
    return mix(CHECKER_LIGHT, CHECKER_DARK, sx + sz - 2.0 * sx * sz);
#endif
}

// Extent along world x and z of a ray cone of width coneWidth meeting the ground with unit
// direction rd: an ellipse with semi-axes coneWidth / |rd.y| along the ray's horizontal heading
// and coneWidth across it, projected on the two axes. Straight down (no heading) it is a
// circle, where the projection formula would be 0/0.
vec2 groundFootprint(vec3 rd, float coneWidth) {
    float h2 = rd.x * rd.x + rd.z * rd.z;
    float dy2 = rd.y * rd.y;
    vec2 projected = coneWidth * sqrt(vec2(rd.x * rd.x + rd.z * rd.z * dy2, rd.z * rd.z + rd.x * rd.x * dy2) / (dy2 * h2));
    return mix(projected, vec2(coneWidth), bvec2(h2 == 0.0));
}

vec3 skyColor(vec3 rd) {
    return mix(SKY_HORIZON, SKY_ZENITH, clamp(rd.y, 0.0, 1.0));
}

// ---- shading ---------------------------------------------------------------------------------
// The light leaving a surface towards the viewer (ray direction rd), with outward normal n,
// direction l to the light and facing = n.l: the ambient term that every surface gets, plus,
// where the light is visible (lit), a diffuse term and a Phong highlight.
vec3 shadeLocal(vec3 l, vec3 n, vec3 rd, vec3 albedo, float facing, bool lit) {
    vec3 ambient = AMBIENT * albedo;
    float highlight = pow(max(dot(reflect(-l, n), -rd), 0.0), SHININESS);
    return mix(ambient, ambient + facing * albedo + SPECULAR * highlight, bvec3(lit));
}

// Puts a hit point exactly back on its surface where that is cheap: rounding in ro + t rd
// leaves it slightly off, which shows as acne and speckle in shadows and reflections.
vec3 reprojectOnSurface(Scene s, vec3 p, vec3 n, int id) {
    vec3 onGround = vec3(p.x, -s.ground.w, p.z);
    vec3 onSphere = s.sphereCenter + s.sphereRadius * n;
    vec3 onSurface = mix(mix(p, onSphere, bvec3(id == ID_SPHERE)), onGround, bvec3(id == ID_GROUND));
    // The new object's own (the torus's), where it has one.
    onSurface = mix(onSurface, objectSurfacePoint(s.object, p, n), bvec3(id == ID_OBJECT));
    return onSurface;
}

// Moves p off its surface along n by `ulps` ulps of its largest coordinate, and by at least 2^-16
// near the origin: a float form of the integer-ulp offset of Waechter and Binder (Ray Tracing
// Gems ch. 6, whose constants these are). An ulp of x is 2 EPS32 |x| or less. Only used for rays
// that may hit the surface they start on again: from inside a solid, or leaving a solid that is
// not convex (the torus).
vec3 offsetByUlps(vec3 p, vec3 n, float ulps) {
    return p + n * max(1.0 / 65536.0, ulps * 2.0 * EPS32 * maxAbs(p));
}

// From inside a solid: the hit point carries the intersector's error, up to K u S.
vec3 offsetAlong(vec3 p, vec3 n) {
    return offsetByUlps(p, n, 256.0);
}

// A point on the torus's surface (re-projected: its error a few roundings of its coordinates)
// moved outward by 16 ulps: past that error, and 16 times less than offsetAlong's step, which
// seen from 1e3 away is 3e-2, two pixels of a telephoto view.
vec3 leaveTorus(vec3 p, vec3 n) {
    return offsetByUlps(p, n, 16.0);
}

// ---- what a path records ---------------------------------------------------------------------
// radiance (below) is the lecture's loop. It tells these four functions what its path did, at
// four moments; each keeps only what is compiled in, and with none of it they are empty:
// - EDGE_TESTS: the eye ray's hit, which the adaptive anti-aliasing's edge tests read;
// - VIEW 4: the number of bounces, for the Bounces view;
// - PROBE_PATH: never defined on Shadertoy. The page's pixel inspector defines it, with probeRay
//   and probeLit, to record one pixel's path ray by ray.
#ifndef EDGE_TESTS
#define EDGE_TESTS (ADAPTIVE_AA == 1 && SAMPLES > 1)
#endif

#if EDGE_TESTS
// The eye ray's hit: all the edge tests read of a sample's path (one record a sample; the shadow
// and reflected cones start from it as radiance's rays do).
Hit eyeHit;
#endif

#if VIEW == 4
// The reflections the pixel's first sample traced: set once, by its path (-1 until then).
int pathBounces = -1;
#endif

// The eye ray met `hit` (the sky for ID_NONE).
void recordEyeRay(Hit hit) {
#ifdef PROBE_PATH
    probeRay(0, hit.id, hit.t, hit.n, 1.0);
#endif
#if EDGE_TESTS
    eyeHit = hit;
#endif
}

// The surface at `bounce` was shaded; `lit`: the light reaches it.
void recordSurface(int bounce, bool lit) {
#ifdef PROBE_PATH
    probeLit(bounce, lit);
#endif
}

// The surface at `bounce` reflected: the reflected ray met `hit`, carrying `weight` of the pixel.
void recordReflection(int bounce, Hit hit, float weight) {
#ifdef PROBE_PATH
    probeRay(bounce + 1, hit.id, hit.t, hit.n, weight);
#endif
}

// The path ended after `bounces` reflections.
void recordPathEnd(int bounces) {
#if VIEW == 4
    pathBounces = pathBounces < 0 ? bounces : pathBounces;
#endif
}

// ---- the bounce loop: radiance ---------------------------------------------------------------
// An eye ray, and how its direction changes across the footprint of its sample along image x and
// y: ray differentials (Igehy, "Tracing ray differentials", 1999). They give the exact
// footprint of the sample where the eye ray meets the ground.
struct EyeRay {
    vec3 dir;
    vec3 dirDx, dirDy;
};

// Radiance along one eye ray. coneSpread is the angle one sample subtends: the ray cone that
// sizes the texture filter of reflected rays (Akenine-Moeller et al., Ray Tracing Gems ch. 20);
// the eye ray's own ground hit is filtered over its exact footprint, from its differentials.
// key returns what the eye ray saw, for the adaptive anti-aliasing's edge test (mainImage):
// the object it hit, whether that point is lit, and the object its reflection hit; and the
// normal there.
//
// Branch-free as the rest: the loop ends at its bottom, on its last needed trip; the ground
// colour is computed for every hit and chosen by a select; every hit traces its shadow ray.
vec3 radiance(Scene s, EyeRay eye, float coneSpread, out vec3 key, out vec3 keyNormal) {
    vec3 rd = eye.dir;
    vec3 ro = vec3(0.0);
    vec3 color = vec3(0.0);
    float throughput = 1.0;
    float coneWidth = 0.0;
    Hit hit = traceScene(s, ro, rd, ID_NONE, T_INFINITY);
    recordEyeRay(hit);
    key = vec3(float(hit.id), 0.0, float(ID_NONE));
    keyNormal = hit.n;
    if (hit.id == ID_NONE) {
        recordPathEnd(0);
        return skyColor(rd);
    }
    // Where the eye ray meets the ground, the parallelogram its differentials span on the plane:
    // dp = t (dd - d (n.dd) / (n.d)) with n = +y. Once, before the loop: only the first hit uses it.
    vec3 dpdx = hit.t * (eye.dirDx - rd * (eye.dirDx.y / rd.y));
    vec3 dpdy = hit.t * (eye.dirDy - rd * (eye.dirDy.y / rd.y));
    vec4 eyeFootprint = abs(vec4(dpdx.x, dpdy.x, dpdx.z, dpdy.z));
    for (int bounce = 0;; bounce++) {
        vec3 n = hit.n;
        int id = hit.id;
        bool inside = dot(rd, n) > 0.0;
        vec3 p = reprojectOnSurface(s, ro + hit.t * rd, n, id);
        coneWidth += coneSpread * hit.t;
        // The ground's footprint: the eye ray's own (above), or for a reflected ray its cone's.
        vec2 cone = groundFootprint(rd, coneWidth);
        vec4 footprint = bounce == 0 ? eyeFootprint : vec4(cone.x, 0.0, cone.y, 0.0);
        vec3 ground = groundColor(mod(s.textureOrigin + p.xz, 2.0), footprint);
        vec3 albedo = mix(objectColor(id), ground, bvec3(id == ID_GROUND));

        // A surface seen from inside its closed solid gets no direct light: the solid itself
        // stands between it and the light. One facing away from the light needs no shadow ray.
        vec3 toLight = s.light - p;
        float lightDist = length(toLight);
        vec3 l = toLight / lightDist;
        float facing = dot(n, l);
        bool lit = all(bvec2(!inside, facing > 0.0));
#if SHADOWS
        bool meetsAgain = reenters(id);
        bool blocked = traceScene(s, mix(p, leaveTorus(p, n), bvec3(meetsAgain)), l, meetsAgain ? ID_NONE : id, lightDist).id != ID_NONE;
        lit = all(bvec2(lit, !blocked));
#endif
        recordSurface(bounce, lit);
        vec3 local = shadeLocal(l, n, rd, albedo, facing, lit);
        key.y = bounce == 0 ? float(lit) : key.y;

        float mirror = s.reflectivity[id];
        // At the bounce limit the surface keeps all its weight as local colour, so lowering the
        // limit removes reflected detail without darkening the mirrors. Below 1/255 of weight
        // left, a reflection cannot change the 8-bit output: the path ends there.
        if (any(bvec2(bounce == BOUNCES, throughput * mirror < 1.0 / 255.0))) {
            color += throughput * local;
            recordPathEnd(bounce);
            break;
        }
        color += throughput * (1.0 - mirror) * local;
        throughput *= mirror;

        // A curved mirror widens the ray cone: 2 * width * curvature (flat faces add nothing).
        // Where the new object's radius of curvature -> 0 (the cone's apex), the curvature is
        // capped at that of a mirror as small as the cone's own footprint.
        float sphereSpread = 2.0 * coneWidth / s.sphereRadius;
        float objectSpread = 2.0 * coneWidth / max(objectMirrorRadius(s.object, p), coneWidth);
        coneSpread += id == ID_SPHERE ? sphereSpread : (id == ID_OBJECT ? objectSpread : 0.0);
        rd = reflect(rd, n);
        // Leaving a convex solid: it cannot be hit again, so skip it. From inside, or leaving a
        // solid it may meet again: stay eligible, and start a few ulps off the surface on the
        // side the ray goes.
        bool again = any(bvec2(inside, reenters(id)));
        ro = mix(p, inside ? offsetAlong(p, -n) : leaveTorus(p, n), bvec3(again));
        hit = traceScene(s, ro, rd, again ? ID_NONE : id, T_INFINITY);
        recordReflection(bounce, hit, throughput);
        key.z = bounce == 0 ? float(hit.id) : key.z;
        if (hit.id == ID_NONE) {
            color += throughput * skyColor(rd);
            recordPathEnd(bounce + 1);
            break;
        }
    }
    return color;
}

// ---- edges: the centre ray's own near-miss tests ---------------------------------------------
// With adaptive anti-aliasing a pixel takes the n x n grid of samples when its centre lies near
// an edge it cannot resolve. Each pixel tests its own rays: the eye ray stands for a cone as wide
// as the pixel's footprint (the ray cone the texture filter uses), and the pixel is near a
// silhouette when an object's outline passes within that width of the ray, in front of what the
// ray hit; near a shadow boundary when the shadow ray's cone (from the footprint on the surface
// to a point at the light) grazes an occluder; near a reflected silhouette when the reflected
// ray's cone grazes an outline. Closed forms per primitive, from the eye ray's hit alone.

#if EDGE_TESTS
// What the tests read of the centre ray's first surface: the shadow ray's and the reflected
// ray's cones start there as radiance would start them (from the point as traced, not
// re-projected: the cones are far wider than its rounding).
struct FirstHit {
    float t;            // the eye ray's hit (T_INFINITY for the sky)
    int id;
    vec3 p, l;          // the hit point, the direction to the light
    float lightDist;
    bool facesLight;    // n.l > 0: only then can a shadow boundary cross it
    float width;        // the eye ray's cone width at p
    vec3 reflected;     // the reflected ray's direction
    float spread;       // its cone's widening per unit of distance (radiance's, curvature included)
    bool reflects;      // radiance reflects there: weight of at least 1/255 and a bounce left
};

FirstHit firstHitOf(Scene s, vec3 dir, Hit hit, float pixelSpread) {
    FirstHit f;
    f.t = hit.t;
    f.id = hit.id;
    bool sky = hit.id == ID_NONE;
    f.p = sky ? vec3(0.0) : hit.t * dir;
    vec3 toLight = s.light - f.p;
    f.lightDist = length(toLight);
    f.l = toLight / f.lightDist;
    f.facesLight = all(bvec2(!sky, dot(hit.n, f.l) > 0.0));
    f.width = pixelSpread * hit.t;
    f.reflected = reflect(dir, hit.n);
    float sphereSpread = 2.0 * f.width / s.sphereRadius;
    float objectSpread = 2.0 * f.width / max(objectMirrorRadius(s.object, f.p), f.width);
    f.spread = pixelSpread + (hit.id == ID_SPHERE ? sphereSpread : (hit.id == ID_OBJECT ? objectSpread : 0.0));
    f.reflects = all(bvec3(!sky, BOUNCES > 0, s.reflectivity[clamp(hit.id, 0, 3)] >= 1.0 / 255.0));
    return f;
}

// Whether the cone passes near an outline of the scene: every object but `skipId` (the convex
// solid a secondary ray leaves, whose own outline is not in its way).
bool nearOutline(Scene s, RayCone c, int skipId) {
    bool sphere = all(bvec2(skipId != ID_SPHERE, nearSphere(c, s.sphereCenter, s.sphereRadius)));
    bool cube = all(bvec2(skipId != ID_CUBE, nearBox(c, s.cubeCenter, s.cubeHalfSize)));
    bool object = all(bvec2(skipId != ID_OBJECT, nearObject(c, s.object)));
    return any(bvec4(sphere, cube, object, nearHorizon(c, s.ground)));
}

// How near an outline must pass, in units of the cone's width (a sample's footprint, 1 pixel for
// the first sample): an outline that crosses the pixel passes within 0.5 of its centre across it
// (0.71 at its corners). The quad's sharing (mainImage) gives back what 0.5 leaves at the corners.
const float EDGE_REACH = 0.5;

// The centre ray's edge tests, from its hit: (silhouette, shadow boundary, reflected silhouette),
// each 1 when its cone grazes an outline. pixelSpread is the angle the pixel subtends. The
// reflected ray's hit is not recorded: its cone runs on past it, which marks at least the pixels
// a test that stopped there would.
vec3 centreEdges(Scene s, vec3 eyeDir, Hit hit, float pixelSpread) {
    FirstHit f = firstHitOf(s, eyeDir, hit, pixelSpread);
    float w = EDGE_REACH * f.width;
    bool silhouette = nearOutline(s, RayCone(vec3(0.0), eyeDir, 0.0, EDGE_REACH * pixelSpread, f.t), ID_NONE);
    int leaving = reenters(f.id) ? ID_NONE : f.id;  // the torus may shade and mirror itself
    bool shadow = all(bvec2(f.facesLight, nearOutline(s, RayCone(f.p, f.l, w, -w / f.lightDist, f.lightDist), leaving)));
    bool reflection = all(bvec2(f.reflects, nearOutline(s, RayCone(f.p, f.reflected, w, EDGE_REACH * f.spread, T_INFINITY), leaving)));
    return vec3(silhouette, shadow, reflection);
}
#endif

// ---- camera ----------------------------------------------------------------------------------
// sin and cos of an angle in radians, to float32 accuracy. The built-ins are not held to any
// accuracy by GLSL ES; some are off by ~1e-4 relative, which turns the camera by half a pixel.
// Reduce to |r| <= pi/4 with a two-part pi/2 (Cody and Waite), then Taylor series to r^9 and
// r^10: the first omitted terms are below 2e-9 there.
vec2 sinCos(float angle) {
    float quadrant = floor(angle / (0.5 * PI) + 0.5);
    float r = (angle - quadrant * 1.5707963705062866) + quadrant * 4.3711388286737929e-8;
    float r2 = r * r;
    float sinR = r * (1.0 - r2 / 6.0 * (1.0 - r2 / 20.0 * (1.0 - r2 / 42.0 * (1.0 - r2 / 72.0))));
    float cosR = 1.0 - r2 / 2.0 * (1.0 - r2 / 12.0 * (1.0 - r2 / 30.0 * (1.0 - r2 / 56.0 * (1.0 - r2 / 90.0))));
    // Each quarter turn maps (sin, cos) to (cos, -sin); two of them negate both.
    float q = mod(quadrant, 4.0);
    vec2 turned = mod(q, 2.0) == 1.0 ? vec2(cosR, -sinR) : vec2(sinR, cosR);
    return q >= 2.0 ? -turned : turned;
}

// The orbit camera: CAMERA_ORBIT at rest, turning slowly with time; a mouse drag sets the
// angles, the screen centre being the rest view. Its basis comes straight from the angles, so
// looking straight down is as well defined as any other view (no cross product with a world up
// vector).
struct Camera {
    vec3 eyeLocal;      // the eye, relative to SCENE_ORIGIN
    vec3 back, right, up;
    float tanHalfFov;
};

Camera orbitCamera() {
    vec2 angles = CAMERA_ORBIT + vec2(ORBIT_SPEED * iTime, 0.0);
    if (any(notEqual(iMouse.xy, vec2(0.0)))) {
        vec2 m = iMouse.xy / iResolution.xy - 0.5;
        angles += vec2(-360.0 * m.x, 180.0 * m.y);
    }
    vec2 az = sinCos(angles.x * DEG);
    vec2 el = sinCos(clamp(angles.y, -89.0, 90.0) * DEG);
    vec2 halfFov = sinCos(0.5 * FIELD_OF_VIEW * DEG);
    Camera c;
    c.back = vec3(el.y * az.x, el.x, el.y * az.y);
    c.right = vec3(az.y, 0.0, -az.x);
    c.up = vec3(-el.x * az.x, el.y, -el.x * az.y);
    c.eyeLocal = CAMERA_TARGET + CAMERA_DISTANCE * c.back;
    c.tanHalfFov = halfFov.x / halfFov.y;
    return c;
}

// The eye ray through a point of the image, in pixels, for a sample that stands for a square of
// footprint pixels on a side. The derivative of normalize(v) along dv is (dv - d (d.dv)) / |v|.
EyeRay eyeRay(Camera c, vec2 pixel, float footprint) {
    vec2 uv = (2.0 * pixel - iResolution.xy) / iResolution.y;
    vec3 v = -c.back + c.tanHalfFov * (uv.x * c.right + uv.y * c.up);
    EyeRay ray;
    ray.dir = normalize(v);
    float step = 2.0 * c.tanHalfFov * footprint / iResolution.y;  // |dv| across the footprint
    float invLength = inversesqrt(dot(v, v));
    ray.dirDx = step * (c.right - ray.dir * dot(ray.dir, c.right)) * invLength;
    ray.dirDy = step * (c.up - ray.dir * dot(ray.dir, c.up)) * invLength;
    return ray;
}

// What every sample of a frame shares: the camera, the scene relative to its eye, and the angle
// one pixel subtends.
struct View {
    Camera camera;
    Scene scene;
    float pixelSpread;
};

View frameView() {
    View v;
    v.camera = orbitCamera();
    v.scene = sceneRelativeTo(v.camera.eyeLocal);
    v.pixelSpread = 2.0 * v.camera.tanHalfFov / iResolution.y;
    return v;
}

// The radiance of one sample through image point `pixel` (in pixels), standing for a square
// `footprint` pixels on a side (1: the whole pixel; 0: a point). mainImage's one-sample form
// takes it, and so do the page's pixel inspector and progressive form (the page's hooks, below).
vec3 sampleRadiance(View v, vec2 pixel, float footprint, out vec3 key, out vec3 keyNormal) {
    return radiance(v.scene, eyeRay(v.camera, pixel, footprint), v.pixelSpread * footprint, key, keyNormal);
}

// ---- debug views, and the page's hooks (not needed for the picture) --------------------------
// VIEW 1 to 5 show what the picture is made of (they paste into Shadertoy too); only the chosen
// view's code is compiled, and VIEW 0, the picture, has none of it. mainImage draws them.
// The studio page compiles this file in ways of its own. What it relies on (Shadertoy defines
// none of these macros, and needs none of it but the two functions, which mainImage calls):
// - HOST_CONTROLS (controls): the page declares the controls itself, from its panel;
// - PROBE_PATH (what a path records): its pixel inspector records one pixel's path;
// - EDGE_TESTS 0 (what a path records): its progressive form, whose samples are points;
// - frameView and sampleRadiance (camera): its inspector and progressive form trace one sample;
// - VIEW 5, "Extra samples": its inspector shows the pixels that took extra samples.
#if VIEW >= 1 && VIEW <= 3
// A debug view's colour for the first surface the pixel centre's ray meets (the Normals, Depth
// and Object views): its outward normal as a colour, its distance on a scale that shows the
// whole scene (t / (t + the camera's distance): half grey at the camera's distance, white the
// sky), or each object's own flat colour (the ground a sand colour, the sky pale blue).
vec3 firstHitView(Scene s, vec3 dir) {
    Hit hit = traceScene(s, vec3(0.0), dir, ID_NONE, T_INFINITY);
    bool sky = hit.id == ID_NONE;
#if VIEW == 1
    return sky ? vec3(0.0) : 0.5 + 0.5 * hit.n;
#elif VIEW == 2
    return vec3(sky ? 1.0 : hit.t / (hit.t + CAMERA_DISTANCE));
#else
    vec3 own = hit.id == ID_GROUND ? vec3(0.76, 0.6, 0.42) : objectColor(hit.id);
    return sky ? vec3(0.75, 0.85, 1.0) : own;
#endif
}
#endif

#if VIEW == 4
// The Bounces view's colour for a path that traced `bounces` reflections (0: the eye ray's surface
// alone, or the sky): dark blue, blue, green, yellow, red for 0 to 4.
vec3 bouncesView(int bounces) {
    const vec3 STEPS[5] = vec3[5](vec3(0.1, 0.1, 0.35), vec3(0.1, 0.4, 0.9), vec3(0.1, 0.75, 0.3), vec3(0.95, 0.85, 0.1), vec3(0.9, 0.15, 0.1));
    return STEPS[min(bounces, 4)];
}
#endif

// ---- image -----------------------------------------------------------------------------------
#if SAMPLES == 1
#define SAMPLES_PER_AXIS 1
#elif SAMPLES == 4
#define SAMPLES_PER_AXIS 2
#elif SAMPLES == 9
#define SAMPLES_PER_AXIS 3
#else
#define SAMPLES_PER_AXIS 4
#endif

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    View view = frameView();
    Camera camera = view.camera;
    Scene s = view.scene;
#if VIEW >= 1 && VIEW <= 3
    fragColor = vec4(firstHitView(s, eyeRay(camera, fragCoord, 1.0).dir), 1.0);
    return;
#endif
    const int N = SAMPLES_PER_AXIS;
    float pixelSpread = view.pixelSpread;
    vec3 key, keyNormal;
    bool edge = false;
    // Which test gave the pixel its extra samples: (silhouette, shadow boundary, reflected
    // silhouette, the quad's derivatives), for the debug view.
    vec4 edges = vec4(0.0);
#if SAMPLES_PER_AXIS == 1
    // One sample at the pixel centre, the whole pixel its footprint, and no loop around it.
    vec3 pixelColor = sampleRadiance(view, fragCoord, 1.0, key, keyNormal);
#elif ADAPTIVE_AA
    vec3 pixelColor = vec3(0.0);
    for (int i = 0;; i++) {
        // Trip 0: the pixel centre, the whole pixel its footprint. Then, for a pixel near an edge,
        // the n x n grid of sub-pixel centres, each a 1/n-pixel footprint (the centre sample is
        // dropped: an edge pixel gets exactly what uniform supersampling gives it).
        int cell = max(i - 1, 0);  // (GLSL leaves % of a negative number undefined)
        vec2 offset = (vec2(cell % N, cell / N) + 0.5) / float(N) - 0.5;
        float footprint = i == 0 ? 1.0 : 1.0 / float(N);
        EyeRay ray = eyeRay(camera, fragCoord + (i == 0 ? vec2(0.0) : offset), footprint);
        vec3 c = radiance(s, ray, pixelSpread * footprint, key, keyNormal);
        if (i == 0) {
            // Near an edge the first sample cannot resolve? The pixel's own rays test for
            // silhouettes, shadow boundaries and reflected silhouettes (centreEdges); the 2x2
            // quad's derivatives of key add a change of object, of lit, or of reflected object.
            // Derivatives are defined here: no pixel leaves the loop before its bottom.
            vec3 keyStep = abs(dFdx(key)) + abs(dFdy(key));
            // A crease: the normal turns by more than 0.5 over the quad (a curved face, ~0.1).
            float normalStep = dot(abs(dFdx(keyNormal)) + abs(dFdy(keyNormal)), vec3(1.0));
            bool quad = any(bvec2(any(greaterThan(keyStep, vec3(0.0))), normalStep > 0.5));
#if EDGE_TESTS
            edges = vec4(centreEdges(s, ray.dir, eyeHit, pixelSpread), float(quad));
#else
            edges = vec4(0.0, 0.0, 0.0, float(quad));
#endif
            // A quad shares its mark: an edge found in one pixel often runs into its neighbours.
            float own = float(any(greaterThan(edges, vec4(0.0))));
            float marked = max(own, abs(dFdx(own)));
            marked = max(marked, abs(dFdy(marked)));
            edge = marked > 0.0;
        }
        pixelColor = i <= 1 ? c : pixelColor + c;
        if (any(bvec2(!edge, i == N * N))) break;
    }
    pixelColor = edge ? pixelColor / float(N * N) : pixelColor;
#else
    // Uniform supersampling: the n x n grid of sub-pixel centres, row by row.
    vec3 pixelColor = vec3(0.0);
    for (int i = 0;; i++) {
        vec2 offset = (vec2(i % N, i / N) + 0.5) / float(N) - 0.5;
        pixelColor += radiance(s, eyeRay(camera, fragCoord + offset, 1.0 / float(N)), pixelSpread / float(N), key, keyNormal);
        if (i == N * N - 1) break;
    }
    pixelColor /= float(N * N);
#endif
#if VIEW == 4
    // (the first sample's path: the pixel centre's)
    pixelColor = bouncesView(pathBounces);
#elif VIEW == 5
    // The pixels that took extra samples, over the picture in grey, coloured by the first test
    // that marked them: magenta a silhouette, yellow a shadow boundary, cyan a reflected
    // silhouette, green only the quad's derivatives (a crease, two surfaces meeting), blue none
    // of its own: a pixel of a quad another pixel marked.
    vec3 marked = edges.x > 0.0 ? vec3(1.0, 0.0, 1.0) : (edges.y > 0.0 ? vec3(1.0, 1.0, 0.0) : (edges.z > 0.0 ? vec3(0.0, 1.0, 1.0) : vec3(0.0, 1.0, 0.0)));
    marked = any(greaterThan(edges, vec4(0.0))) ? marked : vec3(0.0, 0.0, 1.0);
    pixelColor = edge ? marked : vec3(0.25 + 0.5 * dot(pixelColor, vec3(0.299, 0.587, 0.114)));
#endif
    fragColor = vec4(clamp(pixelColor, 0.0, 1.0), 1.0);
}
