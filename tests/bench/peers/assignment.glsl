// Benchmark peer 1: the assignment's own algorithm (the project's seed, the IM420 "Assignment 6 -
// Raytraced Scene" report), faithfully, in the project's scene. It shows where the project
// started. Benchmark only: it is never part of the shader users paste.
//
// COMPOSED, not standalone: this file is not a shader by itself. composePeer (compose-peer.js)
// splices the definitions listed in @replaces into shaders/raytrace.glsl, so the project's control
// block, camera and sample positions, materials and colours, reflectivities, sky, local shading
// (shadeLocal), bounce weighting and output transform are the project's own text and cannot drift
// from the scene the float64 reference renders. Only the assignment's own choices differ:
//
// - world coordinates, as the lecture template traces them: the eye at SCENE_ORIGIN + its local
//   position, every object at SCENE_ORIGIN + its local position (the project traces relative to
//   the eye). sceneRelativeTo keeps the project's name and Scene struct but fills it with world
//   positions, and leaves the eye in gEye for radiance;
// - its cone: intersectCone and normalForCone exactly as the report prints them (the first renamed
//   assignmentCone: the project's own intersectCone stays in the composed shader), called the way
//   its addCone calls them. Placement (the report's cone is elsewhere): coneCenter = the project's
//   CONE_BASE, coneHeight = CONE_HEIGHT, coneRadius = CONE_RADIUS (which assignmentCone ignores).
//   x^2 + z^2 - y^2 = 0 about coneCenter is the 45-degree double cone with its apex at
//   coneCenter; keeping 0 < y < coneHeight selects the upper nappe, so the assignment's "cone"
//   stands here as an open funnel, apex down on the project's base centre, widening to radius
//   coneHeight at the project's apex height. The wrong shape is the point;
// - its plane, t = (-d - n.o) / (n.d), kept if t > 0 (rayPlaneIntersection, the report's name);
// - its stripe texture, unfiltered: (fract(x) + 0.3) * (0.8, 0.5, 0.2) at the hit's world x (the
//   project's STRIPE_OFFSET and STRIPE_COLOR hold those numbers). The checkerboard (TEXTURE 1) is
//   the lecture's, also point-sampled. TEXTURE_FILTER is ignored: the template never filtered;
// - a textbook sphere (b^2 - c), a textbook slab box with the normal read off the hit point;
// - a miss is t = INFINITY, and a hit counts if t < the nearest so far (its addCone's test);
// - self-intersection: every secondary ray (shadow or reflection) starts EPSILON along the
//   normal from the hit, and shading is evaluated there, as such templates do; no object is
//   skipped, no hit point reprojected, no surface treated as seen from inside;
// - shadow rays are the nearest-hit trace (the same traceScene) compared with the light distance.
// Where the report says nothing (shading, reflections, camera) the project's code runs. The
// project's intersectPlane, Cone and makeCone stay in the composed shader: makeCone fills the
// Scene's cone (only its base is read here), intersectPlane is unused.
//
// @replaces intersectSphere intersectBox sceneRelativeTo traceScene radiance

// "No hit": the template's INFINITY (GLSL ES has no portable infinity literal).
const float INFINITY = 1e30;
// The template's fixed self-intersection offset, in scene units.
const float EPSILON = 1e-3;

// Textbook sphere: with oc = o - c and unit d, t^2 + 2 b t + c = 0, b = oc.d, c = oc.oc - r^2,
// t = -b -+ sqrt(b^2 - c); the nearest positive root.
float intersectSphere(vec3 ro, vec3 rd, vec3 center, float radius) {
    vec3 oc = ro - center;
    float b = dot(oc, rd);
    float c = dot(oc, oc) - radius * radius;
    float h = b * b - c;
    if (h < 0.0) return INFINITY;
    h = sqrt(h);
    float t = -b - h;
    if (t > 0.0) return t;
    t = -b + h;
    if (t > 0.0) return t;
    return INFINITY;
}

// Textbook slab test (Kay and Kajiya): entry time = the latest slab entry, exit = the earliest
// slab exit, with 1 / d as the GPU computes it (inf for a zero component).
float intersectBox(vec3 ro, vec3 rd, vec3 center, vec3 halfSize) {
    vec3 inv = 1.0 / rd;
    vec3 tA = (center - halfSize - ro) * inv;
    vec3 tB = (center + halfSize - ro) * inv;
    vec3 tMin = min(tA, tB), tMax = max(tA, tB);
    float tNear = max(max(tMin.x, tMin.y), tMin.z);
    float tFar = min(min(tMax.x, tMax.y), tMax.z);
    if (tNear > tFar || tFar < 0.0) return INFINITY;
    return tNear > 0.0 ? tNear : tFar;
}

// ---- the seed's cone, as printed in the report (the PDF's line breaks joined) ----
float assignmentCone(vec3 origin, vec3 ray, vec3 coneCenter, float coneRadius, float coneHeight) {
    float yMin = 0.0;
    float yMax = coneHeight;
    vec3 toCone = origin - coneCenter;

    float a = ray.x* ray.x + ray.z * ray.z - ray.y * ray.y;
    float b = 2.0 * toCone.x * ray.x + 2.0 * toCone.z * ray.z - 2.0 * toCone.y * ray.y ;
    float c = toCone.x * toCone.x + toCone.z * toCone.z - toCone.y * toCone.y ;

    float discriminant = b*b - 4.0 * (a*c);

    if(discriminant > 0.0) {
        float t1 = (-b + sqrt(discriminant)) / (2.0 * a);
        float t2 = (-b - sqrt(discriminant)) / (2.0 * a);
        float t;
        float y1 = toCone.y + t1 * ray.y;
        float y2 = toCone.y + t2 * ray.y;
        //front of cone
        if(y2 < yMax && y2 > yMin && t2 > 0.0) {
            return t2;
        }
        // back of cone
        if(y1 < yMax && y1 > yMin && t1 > 0.0) {
            return t1;
        }
    }
    return INFINITY ;
}

// ---- the scene, in world coordinates ----
vec3 gEye;  // the eye in world coordinates; set by sceneRelativeTo, read by radiance

// Despite the project's name: the scene relative to the world origin (the template's frame).
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
    s.textureOrigin = vec2(0.0);  // unused: the texture is read at world x
    return s;
}

// The report's plane: n.x + d = 0, t = (-d - n.o) / (n.d); a parallel ray has no intersection,
// and t must be > 0.
void rayPlaneIntersection(vec3 ro, vec3 rd, vec3 n, float d, int id,
                          inout float hitDist, inout int hitId, inout vec3 hitNormal) {
    float denom = dot(n, rd);
    if (denom == 0.0) return;
    float t = (-d - dot(n, ro)) / denom;
    if (t > 0.0 && t < hitDist) { hitDist = t; hitNormal = n; hitId = id; }
}

// The report's sphere normal n = (x - c) / r.
void addSphere(vec3 ro, vec3 rd, vec3 center, float radius, int id,
               inout float hitDist, inout int hitId, inout vec3 hitNormal) {
    float dist = intersectSphere(ro, rd, center, radius);
    if (dist < hitDist) {
        hitNormal = (ro + dist * rd - center) / radius;
        hitId = id;
        hitDist = dist;
    }
}

// Box normal: the axis along which the hit point lies farthest out, relative to the half size.
void addBox(vec3 ro, vec3 rd, vec3 center, vec3 halfSize, int id,
            inout float hitDist, inout int hitId, inout vec3 hitNormal) {
    float dist = intersectBox(ro, rd, center, halfSize);
    if (dist < hitDist) {
        vec3 q = (ro + dist * rd - center) / halfSize;
        vec3 a = abs(q);
        hitNormal = a.x > a.y && a.x > a.z ? vec3(sign(q.x), 0.0, 0.0)
                  : a.y > a.z ? vec3(0.0, sign(q.y), 0.0) : vec3(0.0, 0.0, sign(q.z));
        hitId = id;
        hitDist = dist;
    }
}

// The seed's normalForCone, as printed. (unitVector * v) * unitVector is a component-wise
// product, which for this axis happens to equal the projection (0, v.y, 0): the normal is the
// unnormalised horizontal offset from the axis, tilted down by a fixed 0.8 rad term.
vec3 normalForCone(vec3 hit, vec3 coneCenter, float coneRadius, float coneHeight) {
vec3 unitVector = vec3(0.0, -1.0, 0.0);
vec3 bottomCylinder = vec3(coneCenter.x, coneCenter.y - coneHeight/2.0, coneCenter.z);
vec3 normal = hit - bottomCylinder - (unitVector * (hit - bottomCylinder)) * unitVector;
normal = normal * cos(0.8) + unitVector * sin(0.8);
normal = normalize(normal);
return normal;
}

// The seed's addCone; its `vec3 color` / `hitColor` pair is the project's material id here, so
// that the project's colour and reflectivity tables apply.
void addCone( vec3 ro, vec3 rd, vec3 center, float radius, float height, int id, inout float hitDist, inout int hitId, inout vec3 hitNormal ){

    float dist = assignmentCone(ro, rd, center, radius, height);

    if (dist < hitDist) {
        vec3 yMin = center-height;
        vec3 hit = ro + dist * rd;
        hitNormal = normalForCone(hit, center, radius, height);
        hitId = id;
        hitDist = dist;
    }
}

// The template's rayTraceScene: nearest hit over all objects; ID_NONE when nothing is hit. (Its
// own signature, not the project's: nothing else calls it.)
int traceScene(Scene s, vec3 ro, vec3 rd, out float hitDist, out vec3 hitNormal) {
    hitDist = INFINITY;
    hitNormal = vec3(0.0);
    int hitId = ID_NONE;
    rayPlaneIntersection(ro, rd, s.ground.xyz, s.ground.w, ID_GROUND, hitDist, hitId, hitNormal);
    addSphere(ro, rd, s.sphereCenter, s.sphereRadius, ID_SPHERE, hitDist, hitId, hitNormal);
    addBox(ro, rd, s.cubeCenter, s.cubeHalfSize, ID_CUBE, hitDist, hitId, hitNormal);
    addCone(ro, rd, s.object.base, CONE_RADIUS, CONE_HEIGHT, ID_OBJECT, hitDist, hitId, hitNormal);
    return hitId;
}

// The project's radiance loop (sky, bounce limit, reflectivity weighting, local shading by
// shadeLocal) with the template's hit handling: world coordinates from gEye, unfiltered texture
// at the hit, secondary rays and shading from EPSILON along the normal, and a shadow ray (the
// nearest hit towards the light, blocking if nearer than the light) from surfaces facing it.
vec3 radiance(Scene s, EyeRay eye, float coneSpread, out vec3 key, out vec3 keyNormal) {
    // One sample per pixel: nothing for the adaptive anti-aliasing's edge test.
    key = vec3(0.0);
    keyNormal = vec3(0.0);
    vec3 rd = eye.dir;
    vec3 ro = gEye;
    vec3 color = vec3(0.0);
    float throughput = 1.0;
    for (int bounce = 0; bounce <= BOUNCES; bounce++) {
        float t;
        vec3 n;
        int id = traceScene(s, ro, rd, t, n);
        if (id == ID_NONE) return color + throughput * skyColor(rd);

        vec3 hitPos = ro + t * rd;
        vec3 albedo = objectColor(id);
        if (id == ID_GROUND) {
#if TEXTURE == 0
            float b = fract(1.0 * hitPos.x);
            albedo = (b + STRIPE_OFFSET) * STRIPE_COLOR;
#else
            albedo = groundColor(mod(hitPos.xz, 2.0), vec4(0.0));  // zero footprint: unfiltered
#endif
        }
        vec3 p = hitPos + EPSILON * n;
        vec3 toLight = s.light - p;
        float lightDist = length(toLight);
        vec3 l = toLight / lightDist;
        float facing = dot(n, l);
        bool lit = facing > 0.0;
#if SHADOWS
        if (lit) {
            float shadowDist;
            vec3 shadowNormal;
            lit = !(traceScene(s, p, l, shadowDist, shadowNormal) != ID_NONE && shadowDist < lightDist);
        }
#endif
        vec3 local = shadeLocal(l, n, rd, albedo, facing, lit);

        float mirror = s.reflectivity[id];
        if (bounce == BOUNCES || throughput * mirror < 1.0 / 255.0) return color + throughput * local;
        color += throughput * (1.0 - mirror) * local;
        throughput *= mirror;
        rd = reflect(rd, n);
        ro = p;
    }
    return color;
}
