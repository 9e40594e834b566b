// Input inspector: Shadertoy's per-frame inputs made visible, for Shadertoy's Image tab (paste it
// as it is). Driven by iMouse, iFrame and iDate:
//   - an analog clock showing iDate's local time, with a dot for each day of the month so far;
//   - iFrame as a row of eight binary lights (top left);
//   - the mouse: a crosshair through the pixel under the pointer (white while the button is
//     held, grey after release), a ring around the pixel where the button went down, and a
//     filled disc on the one frame in which it went down (iMouse.w > 0).
// Along the bottom, two strips of 10-pixel cells for a test (or a colour picker) to read back:
//   rows 0-9    data: cell k encodes one value v as the 24-bit integer round(v) + 2^23 in
//               r, g, b (high byte in r): iFrame, iMouse.xyzw, iResolution.xy, iResolution.z
//               x 1000, iDate.xyzw, iTime x 1000, iTimeDelta x 1e5, and, per pixel,
//               2 fragCoord.x and 2 fragCoord.y
//   rows 10-19  checks: cell k is green when one rule of Shadertoy's inputs holds, red when not
//               (see check() below)

const float CELL = 10.0;
const vec3 PASS = vec3(0.0, 200.0, 80.0) / 255.0;
const vec3 FAIL = vec3(230.0, 30.0, 30.0) / 255.0;

vec3 encode(float v) {
    float u = clamp(floor(v + 0.5) + 8388608.0, 0.0, 16777215.0);
    float r = floor(u / 65536.0);
    float g = floor((u - 65536.0 * r) / 256.0);
    float b = u - 65536.0 * r - 256.0 * g;
    return vec3(r, g, b) / 255.0;
}

float dataValue(int k, vec2 fragCoord) {
    if (k == 0) return float(iFrame);
    if (k == 1) return iMouse.x;
    if (k == 2) return iMouse.y;
    if (k == 3) return iMouse.z;
    if (k == 4) return iMouse.w;
    if (k == 5) return iResolution.x;
    if (k == 6) return iResolution.y;
    if (k == 7) return iResolution.z * 1000.0;
    if (k == 8) return iDate.x;
    if (k == 9) return iDate.y;
    if (k == 10) return iDate.z;
    if (k == 11) return iDate.w;
    if (k == 12) return iTime * 1000.0;
    if (k == 13) return iTimeDelta * 1e5;
    if (k == 14) return 2.0 * fragCoord.x;
    return 2.0 * fragCoord.y;
}

// Rules every frame of Shadertoy's inputs obeys; -1 for a cell with no rule.
float check(int k, vec2 fragCoord) {
    bool ok;
    if (k == 0) ok = iResolution.z == 1.0;                                  // pixel aspect 1
    else if (k == 1) ok = fract(fragCoord) == vec2(0.5);                    // pixel centres
    else if (k == 2) ok = all(greaterThan(fragCoord, vec2(0.0))) && all(lessThan(fragCoord, iResolution.xy));
    else if (k == 3) ok = iFrame >= 0;
    else if (k == 4) ok = iTimeDelta > 0.0 && iFrameRate > 0.0;
    else if (k == 5) ok = iMouse.w <= 0.0 || iMouse.z > 0.0;                // a click frame is a held frame
    else if (k == 6) ok = all(lessThanEqual(abs(iMouse.zw), iResolution.xy)); // clicks land on the canvas
    else if (k == 7) ok = iDate.x >= 2000.0 && iDate.y >= 0.0 && iDate.y <= 11.0 && iDate.z >= 1.0 &&
                          iDate.z <= 31.0 && iDate.w >= 0.0 && iDate.w < 86400.0;
    else if (k == 8) ok = texture(iChannel3, vec2(0.5)).rgb == vec3(0.0);   // an empty channel is black
    else if (k == 9) ok = iTime >= 0.0;
    else return -1.0;
    return ok ? 1.0 : 0.0;
}

float segment(vec2 p, vec2 a, vec2 b) {
    vec2 pa = p - a, ba = b - a;
    float h = clamp(dot(pa, ba) / dot(ba, ba), 0.0, 1.0);
    return length(pa - ba * h);
}

vec3 clockFace(vec2 fragCoord, vec3 col) {
    vec2 centre = vec2(0.5 * iResolution.x, 0.5 * (iResolution.y + 2.0 * CELL));
    float radius = 0.4 * (iResolution.y - 2.0 * CELL);
    vec2 p = fragCoord - centre;
    float r = length(p);
    float aa = 1.0;
    col = mix(col, vec3(0.09, 0.1, 0.14), smoothstep(radius + aa, radius, r));
    col = mix(col, vec3(0.75), smoothstep(aa, 0.0, abs(r - radius) - 0.6));
    // hour ticks
    float angle = atan(p.x, p.y);
    float tick = abs(fract(angle / 6.2831853 * 12.0 + 0.5) - 0.5) * 6.2831853 / 12.0 * r;
    col = mix(col, vec3(0.75), step(r, radius) * step(radius * 0.86, r) * smoothstep(aa, 0.0, tick - 0.5));
    // day-of-month dots around the inside
    float day = floor((angle / 6.2831853 + 0.5) * 31.0);
    float dotDistance = length(p - (radius * 0.72) * vec2(sin(((day + 0.5) / 31.0 - 0.5) * 6.2831853), cos(((day + 0.5) / 31.0 - 0.5) * 6.2831853)));
    if (day < iDate.z) col = mix(col, vec3(0.35, 0.55, 0.95), smoothstep(1.6 + aa, 1.6, dotDistance));
    // hands: hours, minutes, seconds
    float seconds = iDate.w;
    vec3 hands = vec3(mod(seconds / 43200.0, 1.0), mod(seconds / 3600.0, 1.0), mod(floor(seconds) / 60.0, 1.0)) * 6.2831853;
    float lengths[3] = float[3](0.5, 0.78, 0.88);
    float widths[3] = float[3](1.8, 1.2, 0.5);
    vec3 colours[3] = vec3[3](vec3(0.95), vec3(0.95), vec3(0.95, 0.35, 0.25));
    for (int i = 0; i < 3; i++) {
        vec2 tip = radius * lengths[i] * vec2(sin(hands[i]), cos(hands[i]));
        float d = segment(p, vec2(0.0), tip) - widths[i];
        col = mix(col, colours[i], smoothstep(aa, 0.0, d));
    }
    return col;
}

vec3 frameLights(vec2 fragCoord, vec3 col) {
    vec2 origin = vec2(6.0, iResolution.y - 12.0);
    vec2 q = fragCoord - origin;
    int bit = int(floor(q.x / 9.0));
    if (q.y >= 0.0 && q.y < 7.0 && q.x >= 0.0 && bit < 8 && mod(q.x, 9.0) < 7.0) {
        bool on = ((iFrame >> (7 - bit)) & 1) == 1;
        col = on ? vec3(1.0, 0.8, 0.2) : vec3(0.2, 0.18, 0.12);
    }
    return col;
}

vec3 mouse(vec2 fragCoord, vec3 col) {
    if (iMouse == vec4(0.0)) return col;
    vec2 pixel = floor(fragCoord);
    bool held = iMouse.z > 0.0;
    vec3 lineColour = held ? vec3(1.0) : vec3(0.5);
    if (pixel.x == floor(iMouse.x) || pixel.y == floor(iMouse.y)) col = mix(col, lineColour, 0.85);
    vec2 click = abs(iMouse.zw) + 0.5;
    float d = length(fragCoord - click);
    col = mix(col, vec3(0.2, 0.9, 1.0), smoothstep(1.0, 0.0, abs(d - 6.0) - 0.75));
    if (iMouse.w > 0.0) col = mix(col, vec3(0.2, 0.9, 1.0), smoothstep(5.0, 4.0, d));
    return col;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    if (fragCoord.y < CELL) {
        int k = int(fragCoord.x / CELL);
        fragColor = vec4(k < 16 ? encode(dataValue(k, fragCoord)) : vec3(0.05), 1.0);
        return;
    }
    if (fragCoord.y < 2.0 * CELL) {
        float ok = check(int(fragCoord.x / CELL), fragCoord);
        fragColor = vec4(ok < 0.0 ? vec3(0.05) : ok > 0.5 ? PASS : FAIL, 1.0);
        return;
    }
    vec2 uv = fragCoord / iResolution.xy;
    vec3 col = mix(vec3(0.03, 0.04, 0.07), vec3(0.1, 0.08, 0.16), uv.y);
    col = clockFace(fragCoord, col);
    col = frameLights(fragCoord, col);
    col = mouse(fragCoord, col);
    fragColor = vec4(col, 1.0);
}
