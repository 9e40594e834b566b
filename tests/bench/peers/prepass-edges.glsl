// The project's adaptive anti-aliasing with its edge tests moved out of the sample loop: a design
// tried for issue 28 and measured by `npm run bench:apart`. Benchmark only: never part of the
// shader users paste.
//
// COMPOSED, not standalone: composePeer (compose-peer.js) splices the definition this file
// replaces (the list below) into shaders/raytrace.glsl; everything else is the project's text.
// Only the adaptive path (ADAPTIVE_AA 1, SAMPLES > 1, VIEW 0) is written here: it is the only
// form the benchmark times.
//
// In the project the edge tests run in the sample loop's trip 0, and SwiftShader runs that
// `if (i == 0)` body on every trip of a marked quad. Here the pixel first traces its centre ray
// alone, fills the record the tests read from that hit (the reflected ray's cone then runs to
// infinity: its hit is not traced, so the test marks at least what the project's marks), and
// runs the three cone tests before the loop; the loop's trip 0 keeps only the quad's derivative
// test, which needs the first sample's whole path (lit or not, the first reflection's object).
// What it costs in exchange: the centre ray is traced twice.
//
// @replaces mainImage

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    View view = frameView();
    Camera camera = view.camera;
    Scene s = view.scene;
    const int N = SAMPLES_PER_AXIS;
    float pixelSpread = view.pixelSpread;
    vec3 key, keyNormal;
    bool edge = false;

    // The cone tests, from the centre ray's hit alone (as radiance's records would fill them).
    EyeRay centre = eyeRay(camera, fragCoord, 1.0);
    Hit first = traceScene(s, vec3(0.0), centre.dir, ID_NONE, T_INFINITY);
    bool sky = first.id == ID_NONE;
    vec3 p = sky ? vec3(0.0) : first.t * centre.dir;
    vec3 toLight = s.light - p;
    float width = pixelSpread * first.t;
    float objectSpread = 2.0 * width / max(objectMirrorRadius(s.object, p), width);
    firstPath.t = first.t;
    firstPath.id = first.id;
    firstPath.p = p;
    firstPath.lightDist = length(toLight);
    firstPath.l = toLight / firstPath.lightDist;
    firstPath.facing = dot(centre.dir, first.n) < 0.0 ? dot(first.n, firstPath.l) : 0.0;
    firstPath.width = width;
    firstPath.reflected = reflect(centre.dir, first.n);
    firstPath.reflectedT = T_INFINITY;
    firstPath.spread = pixelSpread + (first.id == ID_SPHERE ? 2.0 * width / s.sphereRadius : (first.id == ID_OBJECT ? objectSpread : 0.0));
    firstPath.reflects = float(!sky);
    vec3 coneEdges = firstSampleEdges(s, centre.dir, pixelSpread);

    vec3 pixelColor = vec3(0.0);
    for (int i = 0;; i++) {
        int cell = max(i - 1, 0);
        vec2 offset = (vec2(cell % N, cell / N) + 0.5) / float(N) - 0.5;
        float footprint = i == 0 ? 1.0 : 1.0 / float(N);
        EyeRay ray = eyeRay(camera, fragCoord + (i == 0 ? vec2(0.0) : offset), footprint);
        vec3 c = radiance(s, ray, pixelSpread * footprint, key, keyNormal);
        if (i == 0) {
            // the project's quad test and quad sharing, unchanged
            vec3 keyStep = abs(dFdx(key)) + abs(dFdy(key));
            float normalStep = dot(abs(dFdx(keyNormal)) + abs(dFdy(keyNormal)), vec3(1.0));
            bool quad = any(bvec2(any(greaterThan(keyStep, vec3(0.0))), normalStep > 0.5));
            float own = float(any(bvec2(any(greaterThan(coneEdges, vec3(0.0))), quad)));
            float marked = max(own, abs(dFdx(own)));
            marked = max(marked, abs(dFdy(marked)));
            edge = marked > 0.0;
        }
        pixelColor = i <= 1 ? c : pixelColor + c;
        if (any(bvec2(!edge, i == N * N))) break;
    }
    pixelColor = edge ? pixelColor / float(N * N) : pixelColor;
    fragColor = vec4(clamp(pixelColor, 0.0, 1.0), 1.0);
}
