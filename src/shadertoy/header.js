// Shadertoy's Image-tab contract, in one place: the exact header the site puts before a WebGL2
// Image pass, the `main` it puts after it, and how a host (our page, the test harness, the
// benchmark) slots its own control uniforms between the header and the user's file.
//
// Shadertoy joins header + Common + Image as plain strings and never parses the user's code, so
// a shader that compiles in `composeImageShader(source)` (no host controls) is a shader that
// pastes into Shadertoy unchanged.

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
 * Shadertoy's `main`: the colour starts at vec4(1e20) (a shader that never writes it renders
 * white), and alpha is forced to 1.
 */
export const SHADERTOY_FOOTER = `
void main(void) {
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
export function glslLiteral(value, type) {
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
  const before = SHADERTOY_HEADER + hostBlock;
  return {
    code: before + source + (source.endsWith('\n') ? '' : '\n') + SHADERTOY_FOOTER,
    firstSourceLine: countNewlines(before) + 1,
  };
}
