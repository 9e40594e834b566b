// The pixel inspector's path probe: shaders/raytrace.glsl compiled once more, so that the path of
// one pixel's ray, bounce by bounce, comes from the shader itself and not from a second
// implementation of it. The file is included verbatim (its mainImage renamed by a macro, as the
// progressive raytracer does: progressive.js), with PROBE_PATH defined: then radiance() calls
// probeRay() after each ray it traces and probeLit() once it knows whether a hit is lit (a few
// `#ifdef PROBE_PATH` lines in the shader; without the macro they are not there, and the pasted
// shader and its frame time are what they were). This module writes the rest, host-side:
//
// - before the file (in the host block): the macro, the probe's uniforms, and prototypes of the
//   two record functions (radiance() calls them before they are defined);
// - after the file: the records (three texels a ray: (object id, t, weight), the unit normal,
//   (lit, 0, 0)), the two functions, and a mainImage with two modes:
//   - mode 0 traces the ray through the centre of pixel probePixel with the shader's own camera,
//     eyeRay and radiance (the pixel's first sample: its centre, the whole pixel its footprint),
//     and writes texel x of the records at fragCoord.x (a 1-row target PROBE_TEXELS wide; the
//     last texel is the sample's radiance, linear, not clamped);
//   - mode 1 runs the shader's own mainImage at gl_FragCoord + probeOrigin: the host block then
//     chooses the VIEW "Extra samples", so this is the shader's view of the pixels with extra
//     samples (which the adaptive anti-aliasing gave the grid: the float64 reference samples those as it did),
//     drawn over the 2×2 quad of the inspected pixel or over the whole frame.
//
// readPath() decodes what mode 0 wrote; objectNames() names the objects its rays hit, from the
// shader's own ids and SCENE's choices.

import { singlePass } from '../shadertoy/multipass.js';
import { parseConstants } from '../shadertoy/controls.js';

/** The macro radiance()'s record lines are behind. */
const PATH_PROBE_MACRO = 'PROBE_PATH';
/** Rays recorded at most: the eye ray and its reflections (the shader's BOUNCES goes to 4). */
const PROBE_RAYS = 8;
/** Texels a ray's record takes. */
const TEXELS_PER_RAY = 3;
/** The width of mode 0's target: every ray's texels, then the sample's radiance. */
export const PROBE_TEXELS = TEXELS_PER_RAY * PROBE_RAYS + 1;
/** What a record's object id is before its ray is traced. */
const NOT_TRACED = -2;

/** Before the file, after the host's control block. */
const PRELUDE = `// ---- the pixel inspector's path probe (src/raytracer/path-probe.js) ----
#define ${PATH_PROBE_MACRO}
uniform vec2 probePixel;   // mode 0: the pixel whose path is recorded (fragCoord - 0.5)
uniform vec2 probeOrigin;  // mode 1: mainImage runs at gl_FragCoord.xy + probeOrigin
uniform int probeMode;     // 0: record the path; 1: the shader's own mainImage
void probeRay(int k, int id, float t, vec3 n, float weight);
void probeLit(int k, bool lit);
`;

/** After the file. */
const PROBE_MAIN = `
#undef mainImage
// ---- the pixel inspector's path probe (src/raytracer/path-probe.js) ----
// Ray k of the path (0: the eye ray; k: the k-th reflection) in texels 3k .. 3k + 2:
// (object id, t, the weight it carries), the unit normal at its hit, (lit, 0, 0).
const int PROBE_RAYS = ${PROBE_RAYS};
vec3 probeRecords[3 * PROBE_RAYS + 1];

void probeRay(int k, int id, float t, vec3 n, float weight) {
    if (k < PROBE_RAYS) {
        probeRecords[3 * k] = vec3(float(id), t, weight);
        probeRecords[3 * k + 1] = n;
    }
}

void probeLit(int k, bool lit) {
    if (k < PROBE_RAYS) probeRecords[3 * k + 2] = vec3(lit ? 1.0 : 0.0, 0.0, 0.0);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    if (probeMode == 1) {
        raytraceMainImage(fragColor, fragCoord + probeOrigin);
        return;
    }
    for (int i = 0; i < PROBE_RAYS; i++) {
        probeRecords[3 * i] = vec3(${NOT_TRACED}.0, 0.0, 0.0);
        probeRecords[3 * i + 1] = vec3(0.0);
        probeRecords[3 * i + 2] = vec3(-1.0, 0.0, 0.0);
    }
    // The pixel's first sample as mainImage takes it: its centre, the whole pixel its footprint.
    vec3 key, keyNormal;
    probeRecords[3 * PROBE_RAYS] = sampleRadiance(frameView(), probePixel + 0.5, 1.0, key, keyNormal);
    fragColor = vec4(probeRecords[int(fragCoord.x)], 1.0);
}
`;

/**
 * The path probe of a raytracer's file, as a single-pass shader (its Image tab: the file with
 * its mainImage renamed, then the probe's own).
 * @param {string} source the raytracer's text (shaders/raytrace.glsl or an edit that keeps its functions)
 * @returns {import('../shadertoy/multipass.js').MultipassShader}
 */
export function pathProbeProject(source) {
  return singlePass(`#define mainImage raytraceMainImage\n${source}${source.endsWith('\n') ? '' : '\n'}${PROBE_MAIN}`);
}

/**
 * The host block of the path probe: the page's own (its control values) and the probe's prelude.
 * @param {string} hostBlock from hostControlBlock (header.js), with the "Extra samples" VIEW chosen for mode 1 (extra-samples.js)
 */
export function pathProbeHostBlock(hostBlock) {
  return hostBlock + PRELUDE;
}

/**
 * One ray of a path.
 * @typedef {object} PathRay
 * @property {number} id the object hit (the shader's ID_*: 0 ground, 1 sphere, 2 cube, 3 the
 *   scene's new object), -1 for the sky
 * @property {number} t the distance along the ray to its hit (the ray's range end for the sky)
 * @property {number[]} normal the unit outward normal at the hit
 * @property {boolean | null} lit whether the light reaches the hit (null: not shaded, the sky)
 * @property {number} weight the share of the pixel's colour this ray carries (1 for the eye ray)
 */

/**
 * The names of the objects a path's rays hit, read from the shader: its `const int ID_NAME`
 * lines name the ids (ID_NONE, no hit, is the sky), and ID_OBJECT, the scene's new object, is
 * named by the label of SCENE's choice (its `// ui:` choices). An id the shader does not name is
 * `object N`.
 * @param {string} source the raytracer's text
 * @param {import('../shadertoy/controls.js').Control[]} controls its controls (SCENE's choices)
 * @returns {(id: number, values: Record<string, any>) => string} the name of `id` with these control values
 */
export function objectNames(source, controls) {
  /** @type {Map<number, string>} */
  const ids = new Map();
  for (const [name, value] of Object.entries(parseConstants(source)))
    if (name.startsWith('ID_') && typeof value === 'number' && !ids.has(value)) ids.set(value, name.slice(3).toLowerCase());
  const scenes = controls.find((control) => control.name === 'SCENE')?.options?.map((option) => option.label.toLowerCase()) ?? [];
  return (id, values) => {
    const name = ids.get(id);
    if (name === 'none') return 'sky';
    if (name === 'object') return scenes[values.SCENE ?? 0] ?? `object ${id}`;
    return name ?? `object ${id}`;
  };
}

/**
 * The path mode 0 wrote: its rays in order, and the sample's radiance.
 * @param {ArrayLike<number>} rgba PROBE_TEXELS texels, RGBA
 * @returns {{rays: PathRay[], radiance: number[]}}
 */
export function readPath(rgba) {
  const texel = (i) => [rgba[4 * i], rgba[4 * i + 1], rgba[4 * i + 2]];
  /** @type {PathRay[]} */
  const rays = [];
  for (let k = 0; k < PROBE_RAYS; k++) {
    const [id, t, weight] = texel(TEXELS_PER_RAY * k);
    if (id === NOT_TRACED) break;
    const lit = texel(TEXELS_PER_RAY * k + 2)[0];
    rays.push({ id, t, normal: texel(TEXELS_PER_RAY * k + 1), lit: lit < 0 ? null : lit === 1, weight });
  }
  return { rays, radiance: texel(TEXELS_PER_RAY * PROBE_RAYS) };
}
