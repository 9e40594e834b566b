// The project's shader with ONE trace site: a single loop whose iterations alternate between a
// shadow ray and the next reflection ray, the primary ray going through the same call. For the
// benchmark's "one trace site" variant (the speed issue asked for this design to be measured);
// benchmark only, never part of the shader users paste.
//
// COMPOSED, not standalone: composePeer (compose-peer.js) splices the definitions this file
// replaces (the list below) into shaders/raytrace.glsl; everything else is the project's text.
// The image is the project's, bit for bit. The cost model says why it is slower on SwiftShader:
// a loop costs its whole body on every trip its slowest pixel needs, and this body holds the
// trace and the shading of a new surface, so a pixel that sees the ground and then the sky pays
// three traces and three shadings (primary, shadow, reflection) where the project's structure
// pays three traces and one shading. On a GPU, one copy of the trace is less code and fewer
// registers; no GPU was available to measure whether that wins there (npm run bench -- --gpu).
//
// @replaces radiance

vec3 radiance(Scene s, EyeRay eye, float coneSpread, out vec3 key, out vec3 keyNormal) {
    key = vec3(0.0);  // (only adaptive anti-aliasing reads it; this variant is timed at one sample)
    keyNormal = vec3(0.0);
    vec3 rd = eye.dir;
    vec3 ro = vec3(0.0);
    vec3 color = vec3(0.0);
    float throughput = 1.0;
    float coneWidth = 0.0;
    int skipId = ID_NONE;
    float tMax = T_INFINITY;
    bool shadowRay = false;     // the ray in flight is the shadow ray of the pending surface
    int bounce = 0;
    // the pending surface: its light with and without the light visible, and what follows it
    vec3 litLocal = vec3(0.0), unlitLocal = vec3(0.0);
    float mirror = 0.0;
    bool last = false;
    vec3 nextRo = vec3(0.0), nextRd = vec3(0.0);
    int nextSkip = ID_NONE;
    for (int i = 0;; i++) {
        Hit hit = traceScene(s, ro, rd, skipId, tMax);
        bool missed = hit.id == ID_NONE;
        bool newSurface = all(bvec2(!shadowRay, !missed));

        // A new surface (garbage when there is none: nothing below takes it then).
        vec3 n = hit.n;
        int id = hit.id;
        bool inside = dot(rd, n) > 0.0;
        vec3 p = reprojectOnSurface(s, ro + hit.t * rd, n, id);
        float width = coneWidth + coneSpread * hit.t;
        vec3 dpdx = hit.t * (eye.dirDx - rd * (eye.dirDx.y / rd.y));
        vec3 dpdy = hit.t * (eye.dirDy - rd * (eye.dirDy.y / rd.y));
        vec4 footprint = bounce == 0 ? abs(vec4(dpdx.x, dpdy.x, dpdx.z, dpdy.z)) : groundFootprint(rd, width).xxyy * vec4(1.0, 0.0, 1.0, 0.0);
        vec3 ground = groundColor(mod(s.textureOrigin + p.xz, 2.0), footprint);
        vec3 albedo = mix(objectColor(id), ground, bvec3(id == ID_GROUND));
        vec3 toLight = s.light - p;
        float lightDist = length(toLight);
        vec3 l = toLight / lightDist;
        float facing = dot(n, l);
        bool canBeLit = all(bvec2(!inside, facing > 0.0));
        float m = s.reflectivity[id];
        float sphereSpread = 2.0 * width / s.sphereRadius;
        float coneSideSpread = 2.0 * width / max(objectMirrorRadius(s.object, p), width);
        float spread = id == ID_SPHERE ? sphereSpread : (id == ID_OBJECT ? coneSideSpread : 0.0);
        bool needShadow = all(bvec3(newSurface, canBeLit, SHADOWS != 0));

        litLocal = mix(litLocal, shadeLocal(l, n, rd, albedo, facing, true), bvec3(newSurface));
        unlitLocal = mix(unlitLocal, AMBIENT * albedo, bvec3(newSurface));
        mirror = newSurface ? m : mirror;
        last = newSurface ? any(bvec2(bounce == BOUNCES, throughput * m < 1.0 / 255.0)) : last;
        vec3 offsetP = mix(p, offsetAlong(p, -n), bvec3(inside));
        vec3 reflected = reflect(rd, n);
        nextRo = mix(nextRo, offsetP, bvec3(newSurface));
        nextRd = mix(nextRd, reflected, bvec3(newSurface));
        nextSkip = newSurface ? (inside ? ID_NONE : id) : nextSkip;
        coneWidth = newSurface ? width : coneWidth;
        coneSpread = newSurface ? coneSpread + spread : coneSpread;

        if (all(bvec2(!shadowRay, missed))) {
            color += throughput * skyColor(rd);
            break;
        }
        // Resolve the pending surface: its shadow ray came back, or it needs none.
        bool lit = shadowRay ? missed : all(bvec2(canBeLit, SHADOWS == 0));
        vec3 local = mix(unlitLocal, litLocal, bvec3(lit));
        bool resolve = !needShadow;
        if (all(bvec2(resolve, last))) {
            color += throughput * local;
            break;
        }
        vec3 added = throughput * (1.0 - mirror) * local;
        color = mix(color, color + added, bvec3(resolve));
        throughput = resolve ? throughput * mirror : throughput;
        bounce = resolve ? bounce + 1 : bounce;
        ro = mix(nextRo, p, bvec3(needShadow));
        rd = mix(nextRd, l, bvec3(needShadow));
        skipId = needShadow ? id : nextSkip;
        tMax = needShadow ? lightDist : T_INFINITY;
        shadowRay = needShadow;
    }
    return color;
}
