// Shadertoy's Sound tab: `vec2 mainSound(int samp, float time)` rendered on the GPU as the site
// renders it, and its samples as the page plays them, the command line writes them and `test`
// compares them. Pure: no WebGL, no Web Audio here.
//
// Read in the site's own player (effect.js, as copied in github.com/DustinBrett/daedalOS,
// public/System/ShaderToy/CoastalLandscape/effect.js: EffectPass.MakeHeader_Sound, Create_Sound,
// iRenderSound, Paint_Sound, saveScreenshot):
// - the sample rate is 44,100 Hz (mSampleRate, also iSampleRate); the site renders the first
//   180 s (mPlayTime = 60*3) once, when the Sound tab compiles, and plays that buffer;
// - a block is one draw into a 512 × 512 RGBA8 target (mTextureDimensions, TEXFMT.C4I8): 262,144
//   samples, the texel at (x, y) holding sample y*512 + x of the block; block j starts at sample
//   j*262144, given to the shader as `iSampleOffset` (int) and `iTimeOffset` (that / iSampleRate,
//   a float); blocks are drawn until 180 s are covered, the last one partly;
// - the header's main computes `time = iTimeOffset + ((x-0.5) + (y-0.5)*512)/iSampleRate` and
//   `samp = iSampleOffset + int(y-0.2)*512 + int(x-0.2)` from gl_FragCoord, in float32 on the
//   GPU, so our `time` at a sample is the site's to the bit only if blocks start where the
//   site's do: soundBlocks() below always covers whole blocks from the site's grid;
// - each channel is packed as v = floor((0.5 + 0.5*y) * 65536), low byte mod(v, 256)/255 and
//   high byte floor(v/256)/255, written (Llow, Lhigh, Rlow, Rhigh). Nothing clamps y: the RGBA8
//   target clamps each byte on its own, so y ≥ 1 gives a high byte of 255 (v/256 ≥ 256) with
//   the low byte still wrapping, and y < -1 a high byte of 0 (its low byte wraps too): not a
//   plain clamp, kept as is because it is what the site plays;
// - the player unpacks u = low + 256*high and plays -1 + 2u/65535 (Paint_Sound); the site's WAV
//   export writes u - 32767 (which overflows Int16 at u = 65535); this project writes u - 32768,
//   the same 16 bits, none lost: the WAV's samples are the ones the page plays, as 16-bit words.
// - the sound pass declares iChannelTime, iTimeOffset, iSampleOffset, iDate, iSampleRate,
//   iChannelResolution and iChannel0..3, and nothing else (no iTime, iResolution, iMouse,
//   iFrame); Common is included before the tab, as in every pass.

import { SAMPLER_DECLARATIONS, SHADER_PRELUDE, countNewlines } from './header.js';

/** Samples a second (the site's mSampleRate and iSampleRate). */
export const SAMPLE_RATE = 44_100;
/** The side of the square target a block is drawn into. */
export const BLOCK_SIDE = 512;
/** Samples in one block (one draw). */
export const BLOCK_SAMPLES = BLOCK_SIDE * BLOCK_SIDE;
/** How much of the Sound tab the site renders and plays, in seconds (the page plays as much). */
export const PLAY_SECONDS = 180;
/** The uniforms the sound header adds to the site's: the block's first sample and its time. */
export const SAMPLE_OFFSET_UNIFORM = 'iSampleOffset';
export const TIME_OFFSET_UNIFORM = 'iTimeOffset';

const SOUND_HEADER = `${SHADER_PRELUDE}#define HW_PERFORMANCE 1
uniform float iChannelTime[4];
uniform float ${TIME_OFFSET_UNIFORM};
uniform int ${SAMPLE_OFFSET_UNIFORM};
uniform vec4 iDate;
uniform float iSampleRate;
uniform vec3 iChannelResolution[4];
uniform sampler2D iChannel0;
uniform sampler2D iChannel1;
uniform sampler2D iChannel2;
uniform sampler2D iChannel3;

vec2 mainSound(in int samp, float time);
out vec4 outColor;
void main() {
    float t = ${TIME_OFFSET_UNIFORM} + ((gl_FragCoord.x - 0.5) + (gl_FragCoord.y - 0.5) * ${BLOCK_SIDE}.0) / iSampleRate;
    int s = ${SAMPLE_OFFSET_UNIFORM} + int(gl_FragCoord.y - 0.2) * ${BLOCK_SIDE} + int(gl_FragCoord.x - 0.2);
    vec2 y = mainSound(s, t);
    vec2 v = floor((0.5 + 0.5 * y) * 65536.0);
    vec2 vl = mod(v, 256.0) / 255.0;
    vec2 vh = floor(v / 256.0) / 255.0;
    outColor = vec4(vl.x, vh.x, vl.y, vh.y);
}
`;

/**
 * The fragment shader of a Sound tab: the site's sound header and main, Common and "\n", the tab.
 * @param {string} code the Sound tab's text
 * @param {{common?: string | null, channelTypes?: Array<'2D' | 'Cube' | '3D'>}} [options]
 * @returns {{code: string, firstSourceLine: number, sections: import('./header.js').PassSection[]}}
 */
export function composeSoundShader(code, { common = null, channelTypes } = {}) {
  let header = SOUND_HEADER;
  (channelTypes ?? []).forEach((type, i) => {
    header = header.replace(`uniform sampler2D iChannel${i};`, `uniform ${SAMPLER_DECLARATIONS[type]} iChannel${i};`);
  });
  const commonText = common === null ? '' : common + '\n';
  const sections = [];
  if (common !== null) sections.push({ name: 'Common', firstLine: 1, lineCount: countNewlines(common) + 1 });
  sections.push({ name: 'Sound', firstLine: countNewlines(commonText) + 1, lineCount: countNewlines(code) + 1 });
  return { code: header + commonText + code, firstSourceLine: countNewlines(header) + 1, sections };
}

/**
 * The site's blocks that cover samples [first, first + count): their indices.
 * @param {number} first
 * @param {number} count
 */
export function soundBlocks(first, count) {
  const from = Math.floor(first / BLOCK_SAMPLES);
  const to = Math.ceil((first + count) / BLOCK_SAMPLES);
  return Array.from({ length: Math.max(0, to - from) }, (_, i) => from + i);
}

/**
 * A block's texels (RGBA8, row y = 0 first, as readPixels gives them) as 16-bit words, two a
 * sample (left, right), `count` samples from the block's first.
 * @param {Uint8Array} texels
 * @param {number} [count]
 * @returns {Uint16Array}
 */
export function unpackBlock(texels, count = BLOCK_SAMPLES) {
  const words = new Uint16Array(count * 2);
  for (let i = 0; i < count; i++) {
    words[2 * i] = texels[4 * i] + 256 * texels[4 * i + 1];
    words[2 * i + 1] = texels[4 * i + 2] + 256 * texels[4 * i + 3];
  }
  return words;
}

/**
 * The words as signed 16-bit PCM (u - 32768), interleaved as they come.
 * @param {Uint16Array} words
 */
export function toPcm16(words) {
  const pcm = new Int16Array(words.length);
  for (let i = 0; i < words.length; i++) pcm[i] = words[i] - 32768;
  return pcm;
}

/**
 * Interleaved words as the site plays them: -1 + 2u/65535 (Paint_Sound), one Float32Array a channel.
 * @param {Uint16Array} words
 * @returns {[Float32Array<ArrayBuffer>, Float32Array<ArrayBuffer>]}
 */
export function toPlayed(words) {
  const n = words.length / 2;
  const left = new Float32Array(n);
  const right = new Float32Array(n);
  for (let i = 0; i < n; i++) {
    left[i] = -1 + (2 * words[2 * i]) / 65535;
    right[i] = -1 + (2 * words[2 * i + 1]) / 65535;
  }
  return [left, right];
}
