// Standalone plain peer: a whole Shadertoy Image-tab shader, for the benchmark only.
//
// A plain analytic raytracer of the project's default scene, written from scratch the way a
// Shadertoy author would write one: closed-form intersectors (after Inigo Quilez's
// "intersectors" article) with early returns, world coordinates, a fixed 1e-3 offset along the
// normal for secondary rays, point-sampled stripes, one straight bounce loop, and shadow rays
// that stop at the first blocker. It shares no code with the project (shaders/raytrace.glsl) and
// is not composed with it: only the scene's numbers are the same (read from the project's
// control and constant blocks: the cone scene, stripes, shadows on, bounce limit 3, one sample
// per pixel), so that the benchmark can set the project's frame time beside that of an
// independent shader drawing the same picture with the same rays: per pixel the eye ray and up
// to three reflections, each with a shadow ray (none where the surface faces away from the
// light). Its stripes are point-sampled, so its picture is the project's with TEXTURE_FILTER 0.
// Nothing here is used by the page or by the renderer's tests; if the project's scene changes,
// change the numbers below by hand.

// ---- the scene -------------------------------------------------------------------------------
const vec3  CAM_TARGET  = vec3(0.0, 0.6, 0.0);
const float CAM_DIST    = 6.5;
const float CAM_AZIMUTH = 30.0;     // degrees, turning at CAM_SPIN degrees a second
const float CAM_SPIN    = 4.0;
const float CAM_ELEV    = 18.0;     // degrees
const float CAM_FOV     = 45.0;     // vertical, degrees

const vec3  SPH_C = vec3(-1.3, 0.8, 0.3);
const float SPH_R = 0.8;
const vec3  BOX_C = vec3(1.0, 0.5, -1.1);
const vec3  BOX_H = vec3(0.5);
const vec3  CONE_A = vec3(1.2, 0.0, 1.1);   // base centre
const vec3  CONE_B = vec3(1.2, 1.7, 1.1);   // apex
const float CONE_R = 0.55;                  // base radius

const vec3  LIGHT = vec3(-2.5, 6.0, 4.5);

const vec3  SPH_COL  = vec3(0.85, 0.18, 0.12);
const vec3  BOX_COL  = vec3(0.15, 0.35, 0.85);
const vec3  CONE_COL = vec3(0.85, 0.2, 0.75);
const vec3  STRIPE_COL = vec3(0.8, 0.5, 0.2);
const vec3  SKY_LOW  = vec3(0.78, 0.86, 0.95);
const vec3  SKY_HIGH = vec3(0.32, 0.52, 0.85);
// mirror reflectivity of ground, sphere, box, cone
const vec4  MIRROR = vec4(0.15, 0.35, 0.25, 0.2);

const float AMB = 0.15;
const float SPEC = 0.5;
const float SHINE = 40.0;
const int   MAX_BOUNCES = 3;
const float EPS = 1e-3;

// ---- intersectors: distance along rd (unit), or -1.0 for a miss --------------------------------

// ground plane y = 0
float planeHit(vec3 ro, vec3 rd) {
    return -ro.y / rd.y;
}

float sphereHit(vec3 ro, vec3 rd, vec3 c, float r) {
    vec3 oc = ro - c;
    float b = dot(oc, rd);
    float h = b * b - dot(oc, oc) + r * r;
    if (h < 0.0) return -1.0;
    h = sqrt(h);
    float t = -b - h;
    return t > 0.0 ? t : -b + h;
}

// axis-aligned box (centre c, half size h) by slabs; nor gets the face normal
float boxHit(vec3 ro, vec3 rd, vec3 c, vec3 h, out vec3 nor) {
    vec3 inv = 1.0 / rd;
    vec3 mid = -(ro - c) * inv;
    vec3 halfSpan = abs(inv) * h;
    vec3 tNear = mid - halfSpan;
    vec3 tFar = mid + halfSpan;
    float tn = max(max(tNear.x, tNear.y), tNear.z);
    float tf = min(min(tFar.x, tFar.y), tFar.z);
    if (tn > tf || tf < 0.0) return -1.0;
    nor = -sign(rd) * step(tNear.yzx, tNear) * step(tNear.zxy, tNear);
    return tn;
}

// Pointed cone, base disc at a (radius r), apex at b. With axis unit u, height H and k = r / H,
// a point at height y = dot(p - a, u) is inside when its distance from the axis is below
// r - k y. On the ray, with q = ro - a: |q_perp + t rd_perp|^2 = (r - k (yo + t yd))^2, i.e.
// A t^2 + 2 B t + C = 0. nor gets the outward normal.
float coneHit(vec3 ro, vec3 rd, vec3 a, vec3 b, float r, out vec3 nor) {
    vec3 axis = b - a;
    float height = length(axis);
    vec3 u = axis / height;
    float k = r / height;
    vec3 q = ro - a;
    float yo = dot(q, u);
    float yd = dot(rd, u);
    // below the base plane: the base disc is the way in, if the ray meets it
    if (yo < 0.0) {
        float t = -yo / yd;
        vec3 w = q + t * rd;
        if (t > 0.0 && dot(w, w) < r * r) {
            nor = -u;
            return t;
        }
    }
    float rAtOrigin = r - k * yo;                          // the cone's radius at the origin's height
    float A = 1.0 - yd * yd - k * k * yd * yd;
    float B = dot(q, rd) - yo * yd + k * yd * rAtOrigin;
    float C = dot(q, q) - yo * yo - rAtOrigin * rAtOrigin;
    float h = B * B - A * C;
    if (h < 0.0) return -1.0;
    h = sqrt(h);
    float t0 = (-B - h) / A;
    float t1 = (-B + h) / A;
    float tA = min(t0, t1), tB = max(t0, t1);
    float y = yo + tA * yd;
    float t = tA;
    if (tA < 0.0 || y < 0.0 || y > height) {
        t = tB;
        y = yo + tB * yd;
        if (tB < 0.0 || y < 0.0 || y > height) return -1.0;
    }
    vec3 w = q + t * rd - y * u;                     // radial offset of the hit from the axis
    nor = normalize(normalize(w) + k * u);
    return t;
}

// ---- the scene walk --------------------------------------------------------------------------

// nearest hit: distance (-1.0 for none), normal, material (0 ground, 1 sphere, 2 box, 3 cone)
float castRay(vec3 ro, vec3 rd, out vec3 nor, out int mat) {
    float tmin = 1e20;
    mat = -1;
    vec3 n;
    float t = planeHit(ro, rd);
    if (t > 0.0) { tmin = t; nor = vec3(0.0, 1.0, 0.0); mat = 0; }
    t = sphereHit(ro, rd, SPH_C, SPH_R);
    if (t > 0.0 && t < tmin) { tmin = t; nor = (ro + t * rd - SPH_C) / SPH_R; mat = 1; }
    t = boxHit(ro, rd, BOX_C, BOX_H, n);
    if (t > 0.0 && t < tmin) { tmin = t; nor = n; mat = 2; }
    t = coneHit(ro, rd, CONE_A, CONE_B, CONE_R, n);
    if (t > 0.0 && t < tmin) { tmin = t; nor = n; mat = 3; }
    return mat < 0 ? -1.0 : tmin;
}

// any hit before maxT
bool occluded(vec3 ro, vec3 rd, float maxT) {
    vec3 n;
    float t = sphereHit(ro, rd, SPH_C, SPH_R);
    if (t > 0.0 && t < maxT) return true;
    t = boxHit(ro, rd, BOX_C, BOX_H, n);
    if (t > 0.0 && t < maxT) return true;
    t = coneHit(ro, rd, CONE_A, CONE_B, CONE_R, n);
    if (t > 0.0 && t < maxT) return true;
    t = planeHit(ro, rd);
    return t > 0.0 && t < maxT;
}

vec3 sky(vec3 rd) {
    return mix(SKY_LOW, SKY_HIGH, clamp(rd.y, 0.0, 1.0));
}

vec3 albedo(int mat, vec3 p) {
    if (mat == 0) return (fract(p.x) + 0.3) * STRIPE_COL;
    if (mat == 1) return SPH_COL;
    if (mat == 2) return BOX_COL;
    return CONE_COL;
}

// ambient everywhere; diffuse and a Phong highlight where the light is seen
vec3 shade(vec3 p, vec3 n, vec3 rd, vec3 alb) {
    vec3 col = AMB * alb;
    vec3 toLight = LIGHT - p;
    float dist = length(toLight);
    vec3 l = toLight / dist;
    float dif = dot(n, l);
    if (dif <= 0.0) return col;
    if (occluded(p + EPS * n, l, dist)) return col;
    float spe = pow(max(dot(reflect(-l, n), -rd), 0.0), SHINE);
    return col + dif * alb + SPEC * spe;
}

vec3 render(vec3 ro, vec3 rd) {
    vec3 col = vec3(0.0);
    float weight = 1.0;
    for (int bounce = 0; bounce <= MAX_BOUNCES; bounce++) {
        vec3 n;
        int mat;
        float t = castRay(ro, rd, n, mat);
        if (t < 0.0) {
            col += weight * sky(rd);
            break;
        }
        vec3 p = ro + t * rd;
        vec3 local = shade(p, n, rd, albedo(mat, p));
        float m = MIRROR[mat];
        // the last bounce, or too little weight left to show in 8 bits: keep it all as local
        if (bounce == MAX_BOUNCES || weight * m < 1.0 / 255.0) {
            col += weight * local;
            break;
        }
        col += weight * (1.0 - m) * local;
        weight *= m;
        ro = p + EPS * n;
        rd = reflect(rd, n);
    }
    return col;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float az = radians(CAM_AZIMUTH + CAM_SPIN * iTime);
    float el = radians(CAM_ELEV);
    vec3 ro = CAM_TARGET + CAM_DIST * vec3(cos(el) * sin(az), sin(el), cos(el) * cos(az));
    vec3 fw = normalize(CAM_TARGET - ro);
    vec3 right = normalize(cross(fw, vec3(0.0, 1.0, 0.0)));
    vec3 up = cross(right, fw);
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    vec3 rd = normalize(fw + tan(radians(0.5 * CAM_FOV)) * (uv.x * right + uv.y * up));
    fragColor = vec4(clamp(render(ro, rd), 0.0, 1.0), 1.0);
}
