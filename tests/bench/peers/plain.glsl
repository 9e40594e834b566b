// Benchmark peer 3: "plain analytic": the project's scene ray traced the way a competent Shadertoy
// author writes it, with the closed-form intersectors of Inigo Quilez's article "Intersectors"
// (iquilezles.org/articles/intersectors; the code here is written from its formulas). It is the
// project's algorithm without the project's numerical care, so it shows what that care costs and
// what it buys. Benchmark only: it is never part of the shader users paste.
//
// COMPOSED, not standalone: this file is not a shader by itself. composePeer (compose-peer.js)
// splices the definitions listed in @replaces into shaders/raytrace.glsl, so the project's control
// block, camera basis and sample positions, materials and colours, reflectivities, sky, local
// shading (shadeLocal), bounce limit and weighting (BOUNCES, with the project's 1/255 cut-off,
// which the float64 reference has too), shadows switch (SHADOWS), samples (SAMPLES) and output
// transform are the project's own text. What differs is what a plain analytic tracer does:
//
// - world coordinates: the eye at SCENE_ORIGIN + its local position, the objects at SCENE_ORIGIN
//   + theirs (the project traces relative to the eye). sceneRelativeTo keeps the project's name
//   and Scene struct but fills it with world positions, and leaves the eye in gEye for radiance;
// - the intersectors, with early returns, each returning vec4(t, normal), t < 0 for a miss:
//   plane, t = -(n.ro + w) / n.rd; sphere, the textbook roots -b -+ sqrt(b^2 - c), normal
//   (p - c) / r; box, slabs with 1 / rd, the normal from the axis of the entry time; capped cone,
//   the article's quadratic in the axis frame with its two caps;
// - one trace function, traceScene, for every ray: the nearest hit below tMax, FAR for eye and
//   reflection rays, the light's distance for shadow rays (cast from surfaces facing the light);
// - self-intersection: every secondary ray starts EPSILON = 1e-3 along the normal from the hit
//   point; no object is skipped, no hit point reprojected, no surface treated as seen from inside;
// - the ground texture point-sampled at the hit's world xz: groundColor is the plain fract
//   stripes (or floor checkerboard, TEXTURE 1); TEXTURE_FILTER is ignored, and so no ray cone;
// - the camera's sin and cos are the built-ins (sinCos).
// The project's Cone, makeCone and intersectCone stay in the composed shader (the scene's new
// object calls intersectCone; this file's cone is intersectCappedCone): makeCone fills the Scene's object,
// whose base is read here.
//
// @replaces intersectPlane intersectSphere intersectBox sceneRelativeTo traceScene
// @replaces groundColor radiance sinCos

// The fixed offset of secondary rays off the surface, in scene units.
const float EPSILON = 1e-3;
// Range of eye and reflection rays.
const float FAR = 1e20;

// Plane n.p + w = 0, n unit.
vec4 intersectPlane(vec3 ro, vec3 rd, vec4 plane) {
    float t = -(dot(plane.xyz, ro) + plane.w) / dot(plane.xyz, rd);
    if (t <= 0.0) return vec4(-1.0);
    return vec4(t, plane.xyz);
}

// Sphere: with oc = ro - center, t^2 + 2 b t + c = 0 for b = oc.rd, c = oc.oc - r^2.
vec4 intersectSphere(vec3 ro, vec3 rd, vec3 center, float radius) {
    vec3 oc = ro - center;
    float b = dot(oc, rd);
    float c = dot(oc, oc) - radius * radius;
    float h = b * b - c;
    if (h < 0.0) return vec4(-1.0);
    h = sqrt(h);
    float t = -b - h;
    if (t < 0.0) t = -b + h;  // from inside: the far side
    if (t < 0.0) return vec4(-1.0);
    return vec4(t, (ro + t * rd - center) / radius);
}

// Axis-aligned box by slabs: per axis the ray is between the two planes for t from -n - k to
// -n + k; it is in the box between the last entry and the first exit. The normal is the axis
// whose entry time is the hit, facing the ray.
vec4 intersectBox(vec3 ro, vec3 rd, vec3 center, vec3 halfSize) {
    vec3 m = 1.0 / rd;
    vec3 n = m * (ro - center);
    vec3 k = abs(m) * halfSize;
    vec3 t1 = -n - k;
    vec3 t2 = -n + k;
    float tN = max(max(t1.x, t1.y), t1.z);
    float tF = min(min(t2.x, t2.y), t2.z);
    if (tN > tF || tF < 0.0) return vec4(-1.0);
    if (tN > 0.0) return vec4(tN, -sign(rd) * step(vec3(tN), t1));
    return vec4(tF, -sign(rd) * step(t2, vec3(tF)));  // from inside: the exit face
}

// Capped cone from pa (radius ra) to pb (radius rb). With ba = pb - pa, a point w = p - pa is at
// axial coordinate y = w.ba (0 to |ba|^2 between the caps), and on the side when
// |ba|^2 |w|^2 - y^2 = (ra |ba|^2 - (ra - rb) y)^2 / |ba|^2; on the ray this is the quadratic
// k2 t^2 + 2 k1 t + k0 = 0 below. A ray that starts below the base (or above the top) is
// first tested against that cap's disc.
vec4 intersectCappedCone(vec3 ro, vec3 rd, vec3 pa, vec3 pb, float ra, float rb) {
    vec3 ba = pb - pa;
    vec3 oa = ro - pa;
    vec3 ob = ro - pb;
    float m0 = dot(ba, ba);
    float m1 = dot(oa, ba);
    float m2 = dot(ob, ba);
    float m3 = dot(rd, ba);

    if (m1 < 0.0) {
        vec3 q = oa * m3 - rd * m1;  // m3 times the base-plane crossing, relative to pa
        if (dot(q, q) < ra * ra * m3 * m3) return vec4(-m1 / m3, -ba * inversesqrt(m0));
    } else if (m2 > 0.0) {
        vec3 q = ob * m3 - rd * m2;
        if (dot(q, q) < rb * rb * m3 * m3) return vec4(-m2 / m3, ba * inversesqrt(m0));
    }

    float m4 = dot(rd, oa);
    float m5 = dot(oa, oa);
    float rr = ra - rb;
    float hy = m0 + rr * rr;
    float k2 = m0 * m0 - m3 * m3 * hy;
    float k1 = m0 * m0 * m4 - m1 * m3 * hy + m0 * ra * rr * m3;
    float k0 = m0 * m0 * m5 - m1 * m1 * hy + m0 * ra * (2.0 * rr * m1 - m0 * ra);
    float h = k1 * k1 - k2 * k0;
    if (h < 0.0) return vec4(-1.0);
    float t = (-k1 - sqrt(h)) / k2;
    float y = m1 + t * m3;
    if (t < 0.0 || y < 0.0 || y > m0) return vec4(-1.0);
    // The gradient of the side's implicit function.
    return vec4(t, normalize(m0 * (m0 * (oa + t * rd) + rr * ra * ba) - hy * y * ba));
}

vec3 gEye;  // the eye in world coordinates; set by sceneRelativeTo, read by radiance

// Despite the project's name: the scene relative to the world origin (the usual Shadertoy frame).
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

// The nearest hit with 0 < t < tMax; id ID_NONE for a miss. (Its own signature, not the
// project's: nothing else calls it.)
Hit traceScene(Scene s, vec3 ro, vec3 rd, float tMax) {
    Hit hit = Hit(tMax, vec3(0.0), ID_NONE);
    vec4 h = intersectPlane(ro, rd, s.ground);
    if (h.x > 0.0 && h.x < hit.t) hit = Hit(h.x, h.yzw, ID_GROUND);
    h = intersectSphere(ro, rd, s.sphereCenter, s.sphereRadius);
    if (h.x > 0.0 && h.x < hit.t) hit = Hit(h.x, h.yzw, ID_SPHERE);
    h = intersectBox(ro, rd, s.cubeCenter, s.cubeHalfSize);
    if (h.x > 0.0 && h.x < hit.t) hit = Hit(h.x, h.yzw, ID_CUBE);
    h = intersectCappedCone(ro, rd, s.object.base, s.object.base + vec3(0.0, CONE_HEIGHT, 0.0), CONE_RADIUS, 0.0);
    if (h.x > 0.0 && h.x < hit.t) hit = Hit(h.x, h.yzw, ID_OBJECT);
    return hit;
}

// Ground albedo at world xz, point-sampled; the footprint is ignored (the project's signature).
vec3 groundColor(vec2 uv, vec4 footprint) {
#if TEXTURE == 0
    return (fract(uv.x) + STRIPE_OFFSET) * STRIPE_COLOR;
#else
    return mix(CHECKER_LIGHT, CHECKER_DARK, mod(floor(uv.x) + floor(uv.y), 2.0));
#endif
}

// The project's bounce loop and weighting, traced the plain way. coneSpread is unused: nothing
// is filtered.
vec3 radiance(Scene s, EyeRay eye, float coneSpread, out vec3 key, out vec3 keyNormal) {
    // One sample per pixel: nothing for the adaptive anti-aliasing's edge test.
    key = vec3(0.0);
    keyNormal = vec3(0.0);
    vec3 rd = eye.dir;
    vec3 ro = gEye;
    vec3 color = vec3(0.0);
    float throughput = 1.0;
    for (int bounce = 0; bounce <= BOUNCES; bounce++) {
        Hit hit = traceScene(s, ro, rd, FAR);
        if (hit.id == ID_NONE) return color + throughput * skyColor(rd);

        vec3 p = ro + hit.t * rd;
        vec3 n = hit.n;
        vec3 albedo = hit.id == ID_GROUND ? groundColor(p.xz, vec4(0.0)) : objectColor(hit.id);

        vec3 toLight = s.light - p;
        float lightDist = length(toLight);
        vec3 l = toLight / lightDist;
        float facing = dot(n, l);
        bool lit = facing > 0.0;
#if SHADOWS
        if (lit) lit = traceScene(s, p + EPSILON * n, l, lightDist).id == ID_NONE;
#endif
        vec3 local = shadeLocal(l, n, rd, albedo, facing, lit);

        float mirror = s.reflectivity[hit.id];
        if (bounce == BOUNCES || throughput * mirror < 1.0 / 255.0) return color + throughput * local;
        color += throughput * (1.0 - mirror) * local;
        throughput *= mirror;
        rd = reflect(rd, n);
        ro = p + EPSILON * n;
    }
    return color;
}

// The built-in sin and cos.
vec2 sinCos(float angle) {
    return vec2(sin(angle), cos(angle));
}
