// Shadertoy's Image-tab contract, in one place: the exact header the site puts before a WebGL2
// Image pass, with its `main` at the header's end, and how a host (our page, the test harness,
// the benchmark) slots its own control uniforms between the header and the user's file.
//
// Shadertoy joins header + Common + Image as plain strings and never parses the user's code, so
// a shader that compiles in `composeImageShader(source)` (no host controls) is a shader that
// pastes into Shadertoy unchanged.
//
// Where `main` goes (issue 37), read in the site's own player (effect.js and piLibs.js, as
// copied in github.com/DustinBrett/daedalOS, public/System/ShaderToy/CoastalLandscape/):
// EffectPass.MakeHeader_Image and MakeHeader_Buffer end the header with the forward declaration
// of mainImage, the output variable and `main` itself, and NewShader_Image appends each Common
// tab and "\n", then the pass's tab, with no footer (piRenderer puts `#version 300 es` and the
// precision lines first). So `main` and its call of mainImage are compiled before any user text,
// and a macro the user defines (e.g. one renaming mainImage to supersample it) never reaches
// them. The Image pass's `main` writes alpha 1; a buffer's stores the colour as it is.

import { CUBE_A_NAME, CUBE_A_UNIFORMS } from './cube-a.js';

/** Shadertoy's header for a WebGL2 Image pass, line for line. */
export const SHADERTOY_HEADER = `#version 300 es
precision highp float;
precision highp int;
precision mediump sampler3D;
#define HW_PERFORMANCE 1
uniform vec3 iResolution;
uniform float iTime;
uniform float iChannelTime[4];
uniform vec4 iMouse;
uniform vec4 iDate;
uniform float iSampleRate;
uniform vec3 iChannelResolution[4];
uniform int iFrame;
uniform float iTimeDelta;
uniform float iFrameRate;
uniform sampler2D iChannel0;
uniform sampler2D iChannel1;
uniform sampler2D iChannel2;
uniform sampler2D iChannel3;
void mainImage(out vec4 c, in vec2 f);
out vec4 shadertoy_out_color;
`;

/**
 * Shadertoy's `main` for the Image pass, the header's last lines: the colour starts at
 * vec4(1e20) (a shader that never writes it renders white), and alpha is forced to 1.
 */
export const SHADERTOY_IMAGE_MAIN = `void main(void) {
    vec4 color = vec4(1e20);
    mainImage(color, gl_FragCoord.xy);
    shadertoy_out_color = vec4(color.xyz, 1.0);
}
`;

/** The uniforms Shadertoy declares, with their GLSL types (arrays as `type[n]`). */
export const SHADERTOY_UNIFORMS = Object.freeze({
  iResolution: 'vec3',
  iTime: 'float',
  iChannelTime: 'float[4]',
  iMouse: 'vec4',
  iDate: 'vec4',
  iSampleRate: 'float',
  iChannelResolution: 'vec3[4]',
  iFrame: 'int',
  iTimeDelta: 'float',
  iFrameRate: 'float',
  iChannel0: 'sampler2D',
  iChannel1: 'sampler2D',
  iChannel2: 'sampler2D',
  iChannel3: 'sampler2D',
});

/**
 * The values of Shadertoy's uniforms on a shader's first frame, before any time has passed or
 * any input arrived: what the page writes at time 0 and what the raw test pages set. The clock
 * ticks at a nominal 60 Hz until real frames give a rate; iDate is the clock's own. Empty
 * channels are 0 × 0 (they sample black).
 */
export const FIRST_FRAME_UNIFORMS = Object.freeze({
  iTime: 0,
  iTimeDelta: 1 / 60,
  iFrameRate: 60,
  iFrame: 0,
  iMouse: Object.freeze([0, 0, 0, 0]),
  iSampleRate: 44100,
  iChannelTime: Object.freeze([0, 0, 0, 0]),
  iChannelResolution: Object.freeze(new Array(12).fill(0)),
});

/** The macro a host defines to switch off a shader's own control defaults (see controls.js). */
export const HOST_CONTROLS_MACRO = 'HOST_CONTROLS';

/**
 * The number of line breaks in `text` before `end`: the 0-based line on which `end` falls.
 * @param {string} text
 * @param {number} [end]
 */
export function countNewlines(text, end = text.length) {
  let n = 0;
  for (let i = 0; i < end; i++) if (text.charCodeAt(i) === 10) n++;
  return n;
}

/**
 * A GLSL float literal: keeps a decimal point (`2` would be an int in GLSL).
 * @param {number} x
 */
const floatLiteral = (x) => (Number.isInteger(x) ? x.toFixed(1) : String(x));

/**
 * A compile-time control's value in a `#define`: bools as 1 or 0, floats as float literals.
 * @param {unknown} value
 * @param {string} type
 */
function formatDefineValue(value, type) {
  if (typeof value === 'boolean') return value ? '1' : '0';
  if (type === 'float' && typeof value === 'number') return floatLiteral(value);
  return String(value);
}

/**
 * A GLSL literal of a control's type: floats keep a decimal point, vectors their constructor.
 * @param {any} value a number, a boolean, or an array of numbers
 * @param {string} type
 */
function glslLiteral(value, type) {
  if (type === 'bool') return value ? 'true' : 'false';
  if (type === 'int') return String(Math.round(value));
  if (type === 'float') return floatLiteral(value);
  return `${type}(${value.map(floatLiteral).join(', ')})`;
}

/**
 * Builds the host block that replaces a shader's control defaults: compile-time controls become
 * `#define`s with their current values, live controls become uniforms — or, given
 * `liveValues`, constants with those values: the shader exactly as it would be pasted with
 * them, which the compiler can fold (the page compiles this form while the controls are still).
 * @param {import('./controls.js').Control[]} controls from parseControls
 * @param {Record<string, unknown>} defineValues current values of the compile-time controls (other names are ignored)
 * @param {Record<string, unknown> | null} [liveValues] values to compile the live controls as constants
 */
export function hostControlBlock(controls, defineValues = {}, liveValues = null) {
  const lines = [`#define ${HOST_CONTROLS_MACRO}`];
  for (const c of controls) {
    if (c.kind === 'define') {
      const value = c.name in defineValues ? defineValues[c.name] : c.default;
      lines.push(`#define ${c.name} ${formatDefineValue(value, c.type)}`);
    } else if (liveValues) {
      const value = c.name in liveValues ? liveValues[c.name] : c.default;
      lines.push(`const ${c.type} ${c.name} = ${glslLiteral(value, c.type)};`);
    } else {
      lines.push(`uniform ${c.type} ${c.name};`);
    }
  }
  return lines.join('\n') + '\n';
}

/**
 * The full fragment shader a WebGL2 Image pass compiles.
 * @param {string} source the Image-tab text (what a user pastes into Shadertoy)
 * @param {{hostBlock?: string}} [options] text a host puts between header and file (controls)
 * @returns {{code: string, firstSourceLine: number}} the code, and the 1-based line of `code` on
 *   which the user's first line lands (to map compiler messages back to the user's file)
 */
export function composeImageShader(source, { hostBlock = '' } = {}) {
  const before = SHADERTOY_HEADER + SHADERTOY_IMAGE_MAIN + hostBlock;
  return { code: before + source, firstSourceLine: countNewlines(before) + 1 };
}

// ---- multipass (issue 13) -------------------------------------------------------------------
// The site compiles every pass as header (its `main` included) + Common + "\n" + the pass's
// tab, joined as plain strings (https://www.shadertoy.com/js/effect.js, EffectPass.NewShader:
// `fsSource += commonShaderCodes[i] + '\n'`). A buffer pass's main stores the colour as it is, alpha
// included (EffectPass.MakeHeader_Buffer: `outColor = color`, no `color.w = 1.0`): buffers hold
// data. A channel bound to a cubemap is declared `samplerCube`, a volume `sampler3D`
// (MakeHeader_Image/Buffer).

/** Shadertoy's `main` for a buffer pass: the colour stored as mainImage left it, alpha included. */
const SHADERTOY_BUFFER_MAIN = `void main(void) {
    vec4 color = vec4(1e20);
    mainImage(color, gl_FragCoord.xy);
    shadertoy_out_color = color;
}
`;

/**
 * Shadertoy's `main` for the Cube A pass (cube-a.js: EffectPass.MakeHeader_Cubemap): the ray of
 * the texel from the face's corners, mainCubemap called with it, the colour stored as it is. Its
 * colour starts at vec4(1e20) as the buffer's does here (the copy of effect.js read starts all
 * three at vec4(0, 0, 0, 1); the site's current Image header starts at 1e20).
 */
const SHADERTOY_CUBEMAP_MAIN = `uniform vec4 ${CUBE_A_UNIFORMS.viewport};
uniform vec3 ${CUBE_A_UNIFORMS.corners}[5];
void main(void) {
    vec4 color = vec4(1e20);
    vec3 ro = ${CUBE_A_UNIFORMS.corners}[4];
    vec2 uv = (gl_FragCoord.xy - ${CUBE_A_UNIFORMS.viewport}.xy) / ${CUBE_A_UNIFORMS.viewport}.zw;
    vec3 rd = normalize(mix(mix(${CUBE_A_UNIFORMS.corners}[0], ${CUBE_A_UNIFORMS.corners}[1], uv.x),
                            mix(${CUBE_A_UNIFORMS.corners}[3], ${CUBE_A_UNIFORMS.corners}[2], uv.x), uv.y) - ro);
    mainCubemap(color, gl_FragCoord.xy - ${CUBE_A_UNIFORMS.viewport}.xy, ro, rd);
    shadertoy_out_color = color;
}
`;

/** The Cube A pass declares mainCubemap where the others declare mainImage (MakeHeader_Cubemap). */
const MAIN_IMAGE_DECLARATION = 'void mainImage(out vec4 c, in vec2 f);';
const MAIN_CUBEMAP_DECLARATION = 'void mainCubemap(out vec4 c, in vec2 f, in vec3 ro, in vec3 rd);';

export const SAMPLER_DECLARATIONS = Object.freeze({ '2D': 'sampler2D', Cube: 'samplerCube', '3D': 'sampler3D' });

/**
 * A tiled still (the command line's --tile: a picture larger than one draw may be) draws each
 * tile with iResolution the whole picture's and fragCoord moved by the tile's place in it: the
 * host's own uniform, in the host's own `main`, never in what pastes into Shadertoy. An offset
 * of even whole pixels keeps every 2×2 quad, and so every screen-space derivative, the whole
 * picture's (the command line's tiles start at multiples of an even tile size).
 */
export const TILE_OFFSET_UNIFORM = 'shadertoy_tileOffset';

/** The Image pass's `main` for a tile: Shadertoy's, with fragCoord moved by the tile's offset. */
const TILED_IMAGE_MAIN = SHADERTOY_IMAGE_MAIN.replace('gl_FragCoord.xy', `gl_FragCoord.xy + ${TILE_OFFSET_UNIFORM}`);

/**
 * One part of a composed pass, in lines counted from the first line of user text (1 = the
 * composed shader's line `firstSourceLine`).
 * @typedef {{name: string, firstLine: number, lineCount: number}} PassSection
 */

/**
 * The full fragment shader of one pass of a multipass shader: Shadertoy's header (with each
 * channel's sampler type) ending in the Image or buffer `main`, the host block, the Common tab, a
 * line break, and the pass's tab. With no Common, no channel types and kind 'image' it is exactly
 * composeImageShader(code, {hostBlock}).
 * @param {string} code the pass's tab text
 * @param {{common?: string | null, hostBlock?: string, kind?: 'image' | 'buffer' | 'cubemap', name?: string,
 *   channelTypes?: Array<'2D' | 'Cube' | '3D'>, tiled?: boolean}} [options] name: the pass's name
 *   in error messages (default "Image", or "Buffer" for a buffer); tiled: an Image pass drawn as
 *   a tile of a larger picture (TILE_OFFSET_UNIFORM)
 * @returns {{code: string, firstSourceLine: number, sections: PassSection[]}} the code; the
 *   1-based line of `code` where the user's text (Common, or the tab when there is none) starts;
 *   and where Common and the tab lie, for mapping compiler messages (pass-errors.js)
 */
export function composePassShader(code, { common = null, hostBlock = '', kind = 'image', name, channelTypes, tiled = false } = {}) {
  if (tiled && kind !== 'image') throw new Error('composePassShader: only the Image pass is drawn in tiles');
  let header = SHADERTOY_HEADER;
  (channelTypes ?? []).forEach((type, i) => {
    const declaration = SAMPLER_DECLARATIONS[type];
    if (!declaration) throw new Error(`composePassShader: unknown sampler type ${JSON.stringify(type)} for iChannel${i}`);
    header = header.replace(`uniform sampler2D iChannel${i};`, `uniform ${declaration} iChannel${i};`);
  });
  if (kind === 'cubemap') header = header.replace(MAIN_IMAGE_DECLARATION, MAIN_CUBEMAP_DECLARATION);
  const main =
    { buffer: SHADERTOY_BUFFER_MAIN, cubemap: SHADERTOY_CUBEMAP_MAIN }[kind] ?? (tiled ? TILED_IMAGE_MAIN : SHADERTOY_IMAGE_MAIN);
  // the tile's uniform is declared before the `main` that reads it
  const before = header + (tiled ? `uniform vec2 ${TILE_OFFSET_UNIFORM};\n` : '') + main + hostBlock;
  const commonText = common === null ? '' : common + '\n';
  const passName = name ?? { buffer: 'Buffer', cubemap: CUBE_A_NAME }[kind] ?? 'Image';
  /** @type {PassSection[]} */
  const sections = [];
  if (common !== null) sections.push({ name: 'Common', firstLine: 1, lineCount: countNewlines(common) + 1 });
  sections.push({ name: passName, firstLine: countNewlines(commonText) + 1, lineCount: countNewlines(code) + 1 });
  return {
    code: before + commonText + code,
    firstSourceLine: countNewlines(before) + 1,
    sections,
  };
}

/**
 * The section and the line in it of a line of user text (1-based, counted as PassSection's), or
 * null for a line outside every section.
 * @param {PassSection[]} sections
 * @param {number} line
 * @returns {{name: string, line: number} | null}
 */
export function locatePassLine(sections, line) {
  const section = sections.find((s) => line >= s.firstLine && line < s.firstLine + s.lineCount);
  return section ? { name: section.name, line: line - section.firstLine + 1 } : null;
}

/**
 * The Common tab as the site also compiles it on its own, to report its errors: only iDate and
 * iSampleRate are declared there (EffectPass.MakeHeader_Common), so a Common tab that reads any
 * other uniform (iTime, iResolution, iMouse, iChannel0, ...) fails on the site even though every
 * pass that includes it would compile.
 * @param {string} common
 * @returns {{code: string, firstSourceLine: number}}
 */
export function composeCommonShader(common) {
  const before = [
    ...SHADERTOY_HEADER.split('\n').slice(0, 4),
    'uniform vec4 iDate;',
    'uniform float iSampleRate;',
    'out vec4 shadertoy_out_color;',
    'void main(void) { shadertoy_out_color = vec4(0.0); }',
    '',
  ].join('\n');
  return { code: before + common + (common.endsWith('\n') ? '' : '\n'), firstSourceLine: countNewlines(before) + 1 };
}
