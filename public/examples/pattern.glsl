// Hex weave: a 2D pattern for Shadertoy's Image tab (paste it as it is).
// Truchet arcs on a hexagonal grid: each cell joins the midpoints of its edges with three arcs,
// turned one way or the other by a hash of the cell, so the arcs of neighbouring cells meet in
// long winding ribbons. The grid scrolls and the colours drift with iTime.

const float SQRT3 = 1.7320508075688772;
const float ZOOM = 5.0;         // cells across the screen's height
const float RIBBON = 0.085;     // half width of a ribbon, in cell units

// Hexagonal cells of unit spacing (neighbours 1 apart along x): returns the point relative to
// its cell's centre (xy) and that centre (zw), which names the cell.
vec4 hexCell(vec2 p) {
    vec2 s = vec2(1.0, SQRT3);
    vec2 h = 0.5 * s;
    vec2 a = mod(p, s) - h;
    vec2 b = mod(p - h, s) - h;
    vec2 local = dot(a, a) < dot(b, b) ? a : b;
    return vec4(local, p - local);
}

// A hash in [0, 1) of a cell centre, with no sin() (the same on every GPU's float rounding).
float hash12(vec2 p) {
    vec3 p3 = fract(vec3(p.xyx) * 0.1031);
    p3 += dot(p3, p3.yzx + 33.33);
    return fract((p3.x + p3.y) * p3.z);
}

// Inigo Quilez's cosine palette.
vec3 palette(float t) {
    return 0.5 + 0.5 * cos(6.2831853 * (t + vec3(0.0, 0.33, 0.67)));
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = (fragCoord - 0.5 * iResolution.xy) / iResolution.y;
    vec2 p = uv * ZOOM + vec2(0.35 * iTime, 0.1 * iTime);
    vec4 cell = hexCell(p);
    // the centres lie on a lattice of (1/2, sqrt(3)/2) steps: name each cell by whole numbers, so
    // that rounding in p - local cannot give two pixels of one cell different names
    vec2 id = floor(vec2(2.0 * cell.z, 2.0 * cell.w / SQRT3) + 0.5);
    float turn = hash12(id) < 0.5 ? 0.0 : 1.0;

    // The hexagon's corners lie 1/sqrt(3) from its centre, at 30 + 60k degrees. An arc of radius
    // half an edge around every other corner joins the midpoints of that corner's two edges.
    float d = 1e9;
    for (int k = 0; k < 3; k++) {
        float angle = radians(30.0 + 60.0 * turn + 120.0 * float(k));
        vec2 corner = vec2(cos(angle), sin(angle)) / SQRT3;
        d = min(d, abs(length(cell.xy - corner) - 0.5 / SQRT3));
    }

    float px = ZOOM / iResolution.y; // one pixel in cell units
    float ribbon = smoothstep(RIBBON + px, RIBBON - px, d);
    float outline = smoothstep(RIBBON + 2.5 * px, RIBBON + px, d) - ribbon;
    float shade = 0.75 + 0.25 * cos(d / RIBBON * 1.5707963);

    vec3 background = palette(0.6 + 0.15 * hash12(id + 7.0)) * 0.14;
    vec3 colour = palette(0.08 * iTime + 0.04 * (p.x + 0.6 * p.y)) * shade;
    vec3 col = background;
    col = mix(col, vec3(0.02), max(outline, 0.0));
    col = mix(col, colour, ribbon);
    col *= 1.0 - 0.35 * dot(uv, uv); // vignette
    fragColor = vec4(pow(clamp(col, 0.0, 1.0), vec3(0.4545)), 1.0);
}
