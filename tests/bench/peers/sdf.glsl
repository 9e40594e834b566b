// Benchmark peer 2: the project's scene by sphere tracing signed distance functions, the way most
// Shadertoy scenes are made. Benchmark only: it is never part of the shader users paste.
//
// COMPOSED, not standalone: this file is not a shader by itself. composePeer (compose-peer.js)
// splices the definitions listed in @replaces into shaders/raytrace.glsl, so the project's control
// block, camera and sample positions, materials and colours, reflectivities, sky, ground texture
// and its ray-cone filter (TEXTURE, TEXTURE_FILTER), local shading (shadeLocal), bounce limit and
// weighting (BOUNCES), shadows switch (SHADOWS), samples (SAMPLES) and output transform are the
// project's own text. Only the way rays find surfaces differs:
//
// - world coordinates, as SDF scenes are written: the eye at SCENE_ORIGIN + its local position,
//   the objects at SCENE_ORIGIN + theirs. sceneRelativeTo keeps the project's name and Scene
//   struct but fills it with world positions, and leaves the eye in gEye for radiance;
// - primary, reflection and shadow rays are all sphere traced through sceneDistance (the min of
//   exact SDFs of the ground plane, sphere, box and capped cone), at most MAX_STEPS steps; a
//   shadow ray (occluded) only marches, up to the light, and is cast from surfaces facing it;
// - a ray hits when the distance falls below HIT_THRESHOLD * t (t from the ray's origin). It
//   misses when t passes the far limit or the step budget runs out (as in the classic tutorial
//   loop, which returns "no hit" after MAX_STEPS): grazing rays that have not converged turn to
//   sky (or, for shadow rays, to light). The other common convention, taking wherever the ray
//   stopped as a hit, was worse here: rays just above the horizon creep along the infinite
//   ground plane and never reach the far limit, so the sky turns to ground (at 32 steps 82% of
//   the pixels off by more than 2/255, against 36%);
// - normals are the SDF's gradient by the tetrahedron of four samples;
// - secondary rays start a little off the surface along the normal (surfaceOffset), as SDF
//   scenes do; no object is skipped, no hit point reprojected, no surface treated as seen from
//   inside (a sphere-traced ray never starts inside a solid).
//
// Knobs a benchmark may define before this file (each guarded):
//   MAX_STEPS      step limit per ray (32, 64, 128, 256); default 128.
//   HIT_THRESHOLD  relative hit threshold; default 1e-4, i.e. stop within 1e-4 * t of a surface.
//     Why relative: a fixed threshold is far too coarse near the eye or far too fine (never met
//     in float32) in the distance; what matters is the error as seen from the eye, an angle.
//     Why 1e-4: about a twentieth of a pixel's footprint at 640x360 and 45 degrees
//     (2 tan(22.5 deg) / 360 = 2.3e-3 per unit distance), and over 1000 times float32's relative
//     precision of the positions (6e-8 |p|, |p| ~ 10), so the march is not chasing rounding noise.
//     Measured against the project's image at 640x360 (pixels off by more than 2/255, at 64 /
//     128 / 256 steps): 1e-3: 31 / 27 / 25% (stopping that far off the surface shifts stripe
//     and shadow edges); 3e-4: 20 / 14 / 11%; 1e-4: 18 / 9.4 / 5.4%; 3e-5: 20 / 8.9 / 4.0%;
//     1e-5: 22 / 10 / 4.8% (tighter thresholds spend the steps converging, and more grazing rays
//     run out). 1e-4 is best or within 1.5 points of the best at every limit.
// BOUNCES, SHADOWS, SAMPLES, TEXTURE, TEXTURE_FILTER are the project's controls: set them the
// project's way (hostControlBlock with #define HOST_CONTROLS, see src/shadertoy/header.js).
//
// The project's intersectors, Cone and makeCone stay in the composed shader: makeCone fills the
// Scene's cone (only its base is read here); the intersectors are unused.
//
// @replaces sceneRelativeTo traceScene radiance

#ifndef MAX_STEPS
#define MAX_STEPS 128
#endif
#ifndef HIT_THRESHOLD
#define HIT_THRESHOLD 1e-4
#endif

vec3 gEye;  // the eye in world coordinates; set by sceneRelativeTo, read by radiance

// Despite the project's name: the scene relative to the world origin (the usual SDF frame).
Scene sceneRelativeTo(vec3 eyeLocal) {
    gEye = SCENE_ORIGIN + eyeLocal;
    Scene s;
    s.ground = vec4(0.0, 1.0, 0.0, -SCENE_ORIGIN.y);  // n.x + d = 0 with n = +y, d = -origin.y
    s.sphereCenter = SCENE_ORIGIN + SPHERE_CENTER;
    s.cubeCenter = SCENE_ORIGIN + CUBE_CENTER;
    s.sphereRadius = SPHERE_RADIUS;
    s.cubeHalfSize = CUBE_HALF_SIZE;
    vec3 coneBase = SCENE_ORIGIN + CONE_BASE;
    s.object = makeCone(coneBase, coneBase + vec3(0.0, CONE_HEIGHT, 0.0), CONE_RADIUS, 0.0);
    s.light = SCENE_ORIGIN + LIGHT_POSITION;
    s.reflectivity = vec4(GROUND_REFLECTIVITY, SPHERE_REFLECTIVITY, CUBE_REFLECTIVITY, CONE_REFLECTIVITY);
    s.textureOrigin = vec2(0.0);  // unused: the texture is read at world xz
    return s;
}

// ---- signed distance functions (negative inside) ----------------------------------------------

// Plane n.x + w = 0, n unit: the signed distance is n.p + w.
float sdPlane(vec3 p, vec4 plane) {
    return dot(plane.xyz, p) + plane.w;
}

float sdSphere(vec3 p, vec3 center, float radius) {
    return length(p - center) - radius;
}

// Axis-aligned box. With q = |p - c| - h (per axis, by symmetry one octant suffices): outside,
// the nearest box point clamps each positive q component to the face, so the distance is
// |max(q, 0)|; inside (all q < 0) it is the distance to the nearest face, -max(q) (the form in
// Quilez, "Distance functions", iquilezles.org/articles/distfunctions). The two terms combine
// since one of them is always zero.
float sdBox(vec3 p, vec3 center, vec3 halfSize) {
    vec3 q = abs(p - center) - halfSize;
    return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0);
}

// Solid pointed cone: base disc of radius R centred at pa, apex pb. The solid is the revolution
// of the triangle (0,0), (R,0), (0,H) in meridian coordinates (r, y) = (distance from the axis,
// height above the base); its surface there is the base segment (0,0)-(R,0) and the side
// segment (R,0)-(0,H) (the axis is interior). The nearest surface point of a point lies in the
// point's own meridian half-plane, so the 3D distance is the 2D distance to those two segments:
// base, |(max(r - R, 0), y)|; side, with e = (-R, H) and v = (r, y) - (R, 0),
// |v - e clamp(v.e / e.e, 0, 1)|. Negative inside: 0 < y and r H < R (H - y).
float sdCone(vec3 p, vec3 pa, vec3 pb, float radius) {
    vec3 axisVector = pb - pa;
    float height = length(axisVector);
    vec3 axis = axisVector / height;
    vec3 w = p - pa;
    float y = dot(w, axis);
    float r = length(w - y * axis);
    vec2 toBase = vec2(max(r - radius, 0.0), y);
    vec2 e = vec2(-radius, height);
    vec2 v = vec2(r - radius, y);
    vec2 toSide = v - e * clamp(dot(v, e) / dot(e, e), 0.0, 1.0);
    float d = sqrt(min(dot(toBase, toBase), dot(toSide, toSide)));
    return (y > 0.0 && r * height < radius * (height - y)) ? -d : d;
}

// The scene: the nearest object's distance, and its id in `id`.
float sceneDistance(Scene s, vec3 p, out int id) {
    float d = sdPlane(p, s.ground);
    id = ID_GROUND;
    float dSphere = sdSphere(p, s.sphereCenter, s.sphereRadius);
    if (dSphere < d) { d = dSphere; id = ID_SPHERE; }
    float dCube = sdBox(p, s.cubeCenter, s.cubeHalfSize);
    if (dCube < d) { d = dCube; id = ID_CUBE; }
    float dCone = sdCone(p, s.object.base, s.object.base + vec3(0.0, CONE_HEIGHT, 0.0), CONE_RADIUS);
    if (dCone < d) { d = dCone; id = ID_OBJECT; }
    return d;
}

// The far limit of a march. SDF scenes bound t; here 1000 units (the scene is ~5 across) past
// the camera distance, so that no view within the controls' ranges loses an object. Ground
// farther than that is grazed so shallowly that even 256 steps cannot converge on it.
float farLimit() {
    return CAMERA_DISTANCE + 1000.0;
}

// Sphere tracing (Hart, "Sphere tracing", The Visual Computer 12, 1996): step by the distance
// bound until within HIT_THRESHOLD * t of a surface. Returns the hit id (ID_NONE on a miss: past
// tMax, or out of steps) and t.
int march(Scene s, vec3 ro, vec3 rd, float tMax, out float t) {
    t = 0.0;
    for (int i = 0; i < MAX_STEPS; i++) {
        int id;
        float d = sceneDistance(s, ro + t * rd, id);
        if (d < HIT_THRESHOLD * t) return id;
        t += d;
        if (t > tMax) return ID_NONE;
    }
    return ID_NONE;
}

// Step of the normal estimate. The gradient by differences is exact for planes and O(h^2 / R)
// off for curved faces; it blurs edges over a width h, and its rounding error is ~ulp(|p|) / h.
// 1e-3 keeps both well under what 8-bit shading shows at |p| ~ 10.
const float NORMAL_STEP = 1e-3;

// Gradient by the tetrahedron technique (four samples at the corners (+-1, +-1, +-1) with an
// even number of minus signs; their weighted sum is 4 h grad f + O(h^3); Quilez, "Normals for
// an SDF", iquilezles.org/articles/normalsSDF).
vec3 sdfNormal(Scene s, vec3 p) {
    const vec2 k = vec2(1.0, -1.0);
    int id;
    return normalize(k.xyy * sceneDistance(s, p + NORMAL_STEP * k.xyy, id) +
                     k.yyx * sceneDistance(s, p + NORMAL_STEP * k.yyx, id) +
                     k.yxy * sceneDistance(s, p + NORMAL_STEP * k.yxy, id) +
                     k.xxx * sceneDistance(s, p + NORMAL_STEP * k.xxx, id));
}

// How far a secondary ray starts off the surface it leaves, along the normal: twice the hit
// threshold at that distance (the hit point is within HIT_THRESHOLD * t of the surface, and the
// normal is only that good), at least twice the threshold at one unit.
float surfaceOffset(float t) {
    return 2.0 * HIT_THRESHOLD * max(t, 1.0);
}

// Nearest hit along the ray, sphere traced; ID_NONE for a miss. (Its own signature, not the
// project's: nothing else calls it.)
int traceScene(Scene s, vec3 ro, vec3 rd, out float hitDist, out vec3 hitNormal) {
    int id = march(s, ro, rd, farLimit(), hitDist);
    hitNormal = id == ID_NONE ? vec3(0.0) : sdfNormal(s, ro + hitDist * rd);
    return id;
}

// Shadow ray, sphere traced up to the light (no normal needed). ro is already off the surface
// (radiance offsets it); sphere tracing skips no object.
bool occluded(Scene s, vec3 ro, vec3 rd, float lightDist) {
    float t;
    return march(s, ro, rd, lightDist, t) != ID_NONE && t < lightDist;
}

// The project's radiance loop (sky, texture and its ray cone, local shading by shadeLocal, bounce
// limit, reflectivity weighting, the ray cone's widening on curved mirrors) with sphere-traced
// hits: world coordinates from gEye, secondary rays and shading from surfaceOffset along the
// normal.
vec3 radiance(Scene s, EyeRay eye, float coneSpread, out vec3 key, out vec3 keyNormal) {
    // One sample per pixel: nothing for the adaptive anti-aliasing's edge test.
    key = vec3(0.0);
    keyNormal = vec3(0.0);
    vec3 rd = eye.dir;
    vec3 ro = gEye;
    vec3 color = vec3(0.0);
    float throughput = 1.0;
    float coneWidth = 0.0;
    for (int bounce = 0; bounce <= BOUNCES; bounce++) {
        float t;
        vec3 n;
        int id = traceScene(s, ro, rd, t, n);
        if (id == ID_NONE) return color + throughput * skyColor(rd);

        vec3 hit = ro + t * rd;
        coneWidth += coneSpread * t;
        vec3 albedo = id == ID_GROUND
            ? groundColor(mod(hit.xz, 2.0), groundFootprint(rd, coneWidth).xxyy * vec4(1.0, 0.0, 1.0, 0.0))
            : objectColor(id);
        vec3 p = hit + surfaceOffset(t) * n;
        vec3 toLight = s.light - p;
        float lightDist = length(toLight);
        vec3 l = toLight / lightDist;
        float facing = dot(n, l);
        bool lit = facing > 0.0;
#if SHADOWS
        lit = lit && !occluded(s, p, l, lightDist);
#endif
        vec3 local = shadeLocal(l, n, rd, albedo, facing, lit);

        float mirror = s.reflectivity[id];
        if (bounce == BOUNCES || throughput * mirror < 1.0 / 255.0) return color + throughput * local;
        color += throughput * (1.0 - mirror) * local;
        throughput *= mirror;

        // The project's widening of the ray cone on curved mirrors (see its radiance): the cone's
        // side has radius CONE_RADIUS (1 - height / CONE_HEIGHT) across its axis.
        if (id == ID_SPHERE) coneSpread += 2.0 * coneWidth / s.sphereRadius;
        if (id == ID_OBJECT) {
            float radiusHere = CONE_RADIUS * max(1.0 - (hit.y - s.object.base.y) / CONE_HEIGHT, 0.0);
            coneSpread += 2.0 * coneWidth / max(radiusHere, coneWidth);
        }
        rd = reflect(rd, n);
        ro = p;
    }
    return color;
}
