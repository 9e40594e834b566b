// Twisted column: a raymarched 3D scene for Shadertoy's Image tab (paste it as it is).
// A rounded box twisted about its axis, a ring and a bobbing sphere on a checkered floor,
// sphere-traced through a signed distance field, with soft shadows, ambient occlusion and fog.
// Drag to orbit the camera. The control block holds the tunables (a host such as this project's
// page turns them into panel controls; Shadertoy compiles them as they stand).

#ifndef HOST_CONTROLS
#define MAX_STEPS 96                              // ui: March steps | 16 .. 256
const float TWIST = 1.2;                          // ui: Twist (radians per unit) | 0 .. 4 step 0.01
const vec3  ALBEDO = vec3(0.85, 0.42, 0.18);      // ui: Column colour | 0 .. 1
const float ORBIT_SPEED = 0.15;                   // ui: Orbit speed (rad/s) | -1 .. 1
#endif

const float FAR = 30.0;

mat2 rotation(float a) {
    float c = cos(a), s = sin(a);
    return mat2(c, -s, s, c);
}

float sdRoundBox(vec3 p, vec3 halfSize, float r) {
    vec3 q = abs(p) - halfSize + r;
    return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0) - r;
}

float sdTorus(vec3 p, vec2 t) {
    vec2 q = vec2(length(p.xz) - t.x, p.y);
    return length(q) - t.y;
}

// The scene: x = distance, y = material (0 floor, 1 column, 2 ring, 3 sphere).
vec2 map(vec3 p) {
    vec2 hit = vec2(p.y, 0.0);
    vec3 q = p - vec3(0.0, 1.05, 0.0);
    q.xz = rotation(TWIST * q.y) * q.xz;
    // twisting stretches distances by up to sqrt(1 + (TWIST r)^2): scale so the march never overshoots
    float column = sdRoundBox(q, vec3(0.42, 1.0, 0.42), 0.08) / sqrt(1.0 + 0.36 * TWIST * TWIST);
    if (column < hit.x) hit = vec2(column, 1.0);
    float ring = sdTorus(p - vec3(0.0, 0.25, 0.0), vec2(1.45, 0.16));
    if (ring < hit.x) hit = vec2(ring, 2.0);
    vec3 c = vec3(2.3 * cos(0.6 * iTime), 0.55 + 0.25 * sin(1.7 * iTime), 2.3 * sin(0.6 * iTime));
    float sphere = length(p - c) - 0.4;
    if (sphere < hit.x) hit = vec2(sphere, 3.0);
    return hit;
}

vec2 march(vec3 ro, vec3 rd) {
    float t = 0.0;
    for (int i = 0; i < MAX_STEPS; i++) {
        vec2 h = map(ro + t * rd);
        if (abs(h.x) < 0.0005 * t) return vec2(t, h.y);
        t += h.x;
        if (t > FAR) break;
    }
    return vec2(FAR, -1.0);
}

vec3 normalAt(vec3 p) {
    const vec2 e = vec2(1.0, -1.0) * 0.0007;
    return normalize(e.xyy * map(p + e.xyy).x + e.yyx * map(p + e.yyx).x +
                     e.yxy * map(p + e.yxy).x + e.xxx * map(p + e.xxx).x);
}

float softShadow(vec3 ro, vec3 rd) {
    float light = 1.0;
    float t = 0.02;
    for (int i = 0; i < 48; i++) {
        float h = map(ro + t * rd).x;
        light = min(light, 10.0 * h / t);
        t += clamp(h, 0.02, 0.3);
        if (light < 0.002 || t > 8.0) break;
    }
    return clamp(light, 0.0, 1.0);
}

float occlusion(vec3 p, vec3 n) {
    float occ = 0.0;
    float weight = 1.0;
    for (int i = 1; i <= 5; i++) {
        float h = 0.03 + 0.12 * float(i);
        occ += (h - map(p + h * n).x) * weight;
        weight *= 0.7;
    }
    return clamp(1.0 - 1.5 * occ, 0.0, 1.0);
}

vec3 sky(vec3 rd) {
    return mix(vec3(0.55, 0.65, 0.8), vec3(0.16, 0.27, 0.5), clamp(rd.y * 1.5, 0.0, 1.0));
}

vec3 shade(vec3 ro, vec3 rd) {
    vec2 hit = march(ro, rd);
    if (hit.y < 0.0) return sky(rd);
    vec3 p = ro + hit.x * rd;
    vec3 n = normalAt(p);
    vec3 albedo = ALBEDO;
    if (hit.y == 0.0) {
        vec2 cell = floor(p.xz * 1.25);
        albedo = mix(vec3(0.18), vec3(0.55), mod(cell.x + cell.y, 2.0));
    } else if (hit.y == 2.0) {
        albedo = vec3(0.2, 0.45, 0.75);
    } else if (hit.y == 3.0) {
        albedo = vec3(0.85);
    }
    vec3 sun = normalize(vec3(0.6, 0.7, 0.35));
    float diffuse = max(dot(n, sun), 0.0) * softShadow(p + 0.002 * n, sun);
    float ambient = 0.5 + 0.5 * n.y;
    float ao = occlusion(p, n);
    vec3 h = normalize(sun - rd);
    float specular = pow(max(dot(n, h), 0.0), 48.0) * diffuse * (hit.y == 0.0 ? 0.15 : 0.6);
    vec3 col = albedo * (vec3(1.25, 1.1, 0.95) * diffuse + vec3(0.25, 0.3, 0.4) * ambient * ao) + specular;
    return mix(col, sky(rd), 1.0 - exp(-0.004 * hit.x * hit.x));
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    float yaw = ORBIT_SPEED * iTime + 0.6;
    float pitch = 0.32;
    if (iMouse.x != 0.0 || iMouse.y != 0.0) {
        vec2 m = iMouse.xy / iResolution.xy;
        yaw += 6.2831853 * (m.x - 0.5);
        pitch = mix(0.05, 1.3, m.y);
    }
    vec3 target = vec3(0.0, 0.8, 0.0);
    vec3 ro = target + 5.2 * vec3(cos(pitch) * cos(yaw), sin(pitch), cos(pitch) * sin(yaw));
    vec3 forward = normalize(target - ro);
    vec3 right = normalize(cross(forward, vec3(0.0, 1.0, 0.0)));
    vec3 up = cross(right, forward);
    vec3 rd = normalize(uv.x * right + uv.y * up + 1.8 * forward);
    vec3 col = shade(ro, rd);
    col = pow(clamp(col, 0.0, 1.0), vec3(0.4545));
    fragColor = vec4(col, 1.0);
}
