// The project's shader with its run-time savings switched off, for the benchmark's "savings off"
// variant. Benchmark only: never part of the shader users paste.
//
// COMPOSED, not standalone: composePeer (compose-peer.js) splices the definitions this file
// replaces (the list below) into shaders/raytrace.glsl; everything else is the project's text. What it
// undoes is the structure the project uses to do only the work a pixel needs:
// - the bounce loop tests its condition at the top (SwiftShader then runs its body once more
//   with every lane masked off), traces at the top of every bounce (so the bounce that only
//   finds the sky runs the shading and the shadow ray too), and has no 1/255 cut-off: every
//   path runs to the bounce limit or the sky;
// - the shadow ray is behind a short-circuit `&&`, as usually written;
// - the samples are taken in a nested loop even at one sample per pixel.
// The image is the same (a path cut off at 1/255 changes no 8-bit value by more than one level).
//
// @replaces radiance mainImage

vec3 radiance(Scene s, EyeRay eye, float coneSpread, out vec3 key, out vec3 keyNormal) {
    key = vec3(0.0);  // (only adaptive anti-aliasing reads it; this variant is timed at one sample)
    keyNormal = vec3(0.0);
    vec3 rd = eye.dir;
    vec3 ro = vec3(0.0);
    vec3 color = vec3(0.0);
    float throughput = 1.0;
    float coneWidth = 0.0;
    int skipId = ID_NONE;
    for (int bounce = 0; bounce <= BOUNCES; bounce++) {
        Hit hit = traceScene(s, ro, rd, skipId, T_INFINITY);
        if (hit.id == ID_NONE) return color + throughput * skyColor(rd);
        vec3 n = hit.n;
        int id = hit.id;
        bool inside = dot(rd, n) > 0.0;
        vec3 p = reprojectOnSurface(s, ro + hit.t * rd, n, id);
        coneWidth += coneSpread * hit.t;
        vec3 dpdx = hit.t * (eye.dirDx - rd * (eye.dirDx.y / rd.y));
        vec3 dpdy = hit.t * (eye.dirDy - rd * (eye.dirDy.y / rd.y));
        vec4 footprint = bounce == 0 ? abs(vec4(dpdx.x, dpdy.x, dpdx.z, dpdy.z)) : groundFootprint(rd, coneWidth).xxyy * vec4(1.0, 0.0, 1.0, 0.0);
        vec3 albedo = id == ID_GROUND
            ? groundColor(mod(s.textureOrigin + p.xz, 2.0), footprint)
            : objectColor(id);
        vec3 toLight = s.light - p;
        float lightDist = length(toLight);
        vec3 l = toLight / lightDist;
        float facing = dot(n, l);
        bool lit = !inside && facing > 0.0;
#if SHADOWS
        lit = lit && traceScene(s, p, l, id, lightDist).id == ID_NONE;
#endif
        vec3 local = shadeLocal(l, n, rd, albedo, facing, lit);
        float mirror = s.reflectivity[id];
        if (bounce == BOUNCES) return color + throughput * local;
        color += throughput * (1.0 - mirror) * local;
        throughput *= mirror;
        if (id == ID_SPHERE) coneSpread += 2.0 * coneWidth / s.sphereRadius;
        if (id == ID_OBJECT) coneSpread += 2.0 * coneWidth / max(objectMirrorRadius(s.object, p), coneWidth);
        rd = reflect(rd, n);
        ro = inside ? offsetAlong(p, -n) : p;
        skipId = inside ? ID_NONE : id;
    }
    return color;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    Camera camera = orbitCamera();
    Scene s = sceneRelativeTo(camera.eyeLocal);
    float coneSpread = 2.0 * camera.tanHalfFov / (iResolution.y * float(SAMPLES_PER_AXIS));
    vec3 key, keyNormal;
    vec3 sum = vec3(0.0);
    for (int sy = 0; sy < SAMPLES_PER_AXIS; sy++) {
        for (int sx = 0; sx < SAMPLES_PER_AXIS; sx++) {
            vec2 offset = (vec2(sx, sy) + 0.5) / float(SAMPLES_PER_AXIS) - 0.5;
            sum += radiance(s, eyeRay(camera, fragCoord + offset, 1.0 / float(SAMPLES_PER_AXIS)), coneSpread, key, keyNormal);
        }
    }
    fragColor = vec4(clamp(sum / float(SAMPLES_PER_AXIS * SAMPLES_PER_AXIS), 0.0, 1.0), 1.0);
}
