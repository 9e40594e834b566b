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

// What the header declares besides the uniforms (issue 45), read in the same copy of the site's
// player, EffectPass.MakeHeader_Image, and in the site's Image pass as compiled today (copies of it
// in public repositories, with `vec4 color = vec4(1e20)`, declare the same):
// - after each channel's sampler, a struct of that channel, `iCh0` … `iCh3`, its `sampler` (of
//   the channel's sampler type), `size` (iChannelResolution[i]), `time` (iChannelTime[i]) and
//   `loaded` (1 when the channel holds something; EffectPass.Paint_Image's texIsLoaded). That
//   player sets no texture unit for the `sampler` (so it would read unit 0, iChannel0's); the
//   page binds channel i's texture to it, with the channel's filter (channel-bindings.js);
// - `st_assert(bool)` and `st_assert(bool, int)`, declared after mainImage and defined after the
//   output: a failed assertion marks a component of the output, which `main` sets to 1 before
//   mainImage; after it, a marked x makes the pixel red, y green, z blue, w yellow (v 0, 1, 2,
//   anything else), the later test winning. Only the Image pass has them: MakeHeader_Buffer and
//   MakeHeader_Cubemap declare neither, so a buffer calling st_assert fails there as here.
// The older `struct Channel { vec3 resolution; float time; }; uniform Channel iChannel[4];` of
// copies from before is declared no more: only a leftover of it remains in that player
// (EffectPass.SetUniforms sets "iChannel[0].time", which no pass declares).
// piRenderer (piLibs.js, CreateRenderer: mShaderHeader) puts the version and the precisions
// before every pass, the precisions inside `#ifdef GL_ES`.

/** What the site's renderer puts first in every WebGL2 shader (piLibs.js: mShaderHeader). */
export const SHADER_PRELUDE = `#version 300 es
#ifdef GL_ES
precision highp float;
precision highp int;
precision mediump sampler3D;
#endif
`;

/** The Image, buffer and Cube A passes' uniforms (MakeHeader_Image, _Buffer, _Cubemap). */
const UNIFORM_DECLARATIONS = `#define HW_PERFORMANCE 1
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
`;

export const SAMPLER_DECLARATIONS = Object.freeze({ '2D': 'sampler2D', Cube: 'samplerCube', '3D': 'sampler3D' });

/**
 * The four channels' declarations: each one's sampler, and in the Image pass its struct after it.
 * @param {Array<'2D' | 'Cube' | '3D'>} types
 * @param {boolean} structs
 */
function channelDeclarations(types, structs) {
  return types
    .map((type, i) => {
      const sampler = SAMPLER_DECLARATIONS[type];
      if (!sampler) throw new Error(`composePassShader: unknown sampler type ${JSON.stringify(type)} for iChannel${i}`);
      const struct = `uniform struct {\n    ${sampler} sampler;\n    vec3 size;\n    float time;\n    int loaded;\n} iCh${i};\n`;
      return `uniform ${sampler} iChannel${i};\n${structs ? struct : ''}`;
    })
    .join('');
}

/** The entry point each pass declares before its `main` (MakeHeader_Cubemap: mainCubemap). */
const MAIN_IMAGE_DECLARATION = 'void mainImage(out vec4 c, in vec2 f);\n';
const MAIN_CUBEMAP_DECLARATION = 'void mainCubemap(out vec4 c, in vec2 f, in vec3 ro, in vec3 rd);\n';

/** The Image pass's st_assert, declared after mainImage and defined after the output. */
const ST_ASSERT_DECLARATIONS = 'void st_assert(bool cond);\nvoid st_assert(bool cond, int v);\n';
const ST_ASSERT_DEFINITIONS = `void st_assert(bool cond, int v) {
    if (!cond) {
        if (v == 0) shadertoy_out_color.x = -1.0;
        else if (v == 1) shadertoy_out_color.y = -1.0;
        else if (v == 2) shadertoy_out_color.z = -1.0;
        else shadertoy_out_color.w = -1.0;
    }
}
void st_assert(bool cond) {
    if (!cond) shadertoy_out_color.x = -1.0;
}
`;

/**
 * A pass's header up to its `main`: the prelude, the uniforms, the channels, the entry point's
 * declaration, the output; the Image pass's with its channel structs and st_assert.
 * @param {'image' | 'buffer' | 'cubemap'} kind
 * @param {Array<'2D' | 'Cube' | '3D'>} types the four channels' sampler types
 */
function passHeader(kind, types) {
  const image = kind === 'image';
  return (
    SHADER_PRELUDE +
    UNIFORM_DECLARATIONS +
    channelDeclarations(types, image) +
    (kind === 'cubemap' ? MAIN_CUBEMAP_DECLARATION : MAIN_IMAGE_DECLARATION) +
    (image ? ST_ASSERT_DECLARATIONS : '') +
    'out vec4 shadertoy_out_color;\n' +
    (image ? ST_ASSERT_DEFINITIONS : '')
  );
}

/** Shadertoy's header for a WebGL2 Image pass with four 2D channels, line for line, up to its `main`. */
export const SHADERTOY_HEADER = passHeader('image', ['2D', '2D', '2D', '2D']);

/**
 * Shadertoy's `main` for the Image pass, the header's last lines: the output starts at 1 (a
 * failed st_assert makes a component of it negative), the colour at vec4(1e20) (a shader that
 * never writes it renders white); a marked component gives the pixel its colour; alpha is 1.
 */
export const SHADERTOY_IMAGE_MAIN = `void main(void) {
    shadertoy_out_color = vec4(1.0, 1.0, 1.0, 1.0);
    vec4 color = vec4(1e20);
    mainImage(color, gl_FragCoord.xy);
    if (shadertoy_out_color.x < 0.0) color = vec4(1.0, 0.0, 0.0, 1.0);
    if (shadertoy_out_color.y < 0.0) color = vec4(0.0, 1.0, 0.0, 1.0);
    if (shadertoy_out_color.z < 0.0) color = vec4(0.0, 0.0, 1.0, 1.0);
    if (shadertoy_out_color.w < 0.0) color = vec4(1.0, 1.0, 0.0, 1.0);
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
  const types = /** @type {Array<'2D' | 'Cube' | '3D'>} */ ([0, 1, 2, 3].map((i) => channelTypes?.[i] ?? '2D'));
  const header = passHeader(kind, types);
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
    SHADER_PRELUDE.trimEnd(),
    'uniform vec4 iDate;',
    'uniform float iSampleRate;',
    'out vec4 shadertoy_out_color;',
    'void main(void) { shadertoy_out_color = vec4(0.0); }',
    '',
  ].join('\n');
  return { code: before + common + (common.endsWith('\n') ? '' : '\n'), firstSourceLine: countNewlines(before) + 1 };
}
