// The Sound tab from the command line: `render SHADER -o OUT.wav [--time T] [--duration S]`
// (a stereo 16-bit WAV at 44,100 Hz of the samples the page plays, src/shadertoy/sound.js), and
// `test`'s comparison of a case's sound with its reference WAV.

import fs from 'node:fs';
import { writeWhole } from '../headless/png.js';
import { fromShadertoyJson } from '../shadertoy/multipass-json.js';
import { soundPass } from '../shadertoy/multipass.js';
import { encodeWav } from '../shared/wav.js';
import { renderShader } from './render.js';
import { ShaderproofError } from '../headless/session.js';

/** The site's sample rate (src/shadertoy/sound.js SAMPLE_RATE: the package ships src/cli, not src/shadertoy). */
export const SOUND_SAMPLE_RATE = 44_100;
/** The default length of a WAV: the site's own WAV export's (effect.js saveScreenshot: 60 s). */
export const DEFAULT_SOUND_SECONDS = 60;
/** The longest: what the site renders and plays (sound.js PLAY_SECONDS). */
export const MAX_SOUND_SECONDS = 180;
/** The picture drawn to compile the shader before its sound: small, it is not kept. */
const SOUND_VIEW_SIZE = { width: 64, height: 36 };

/**
 * The Sound tab of `file`, seconds [time, time + duration), as interleaved 16-bit samples.
 * @param {import('../headless/session.js').Session} session
 * @param {string} file
 * @param {import('./view-options.js').ViewOptions} view
 * @param {{time: number, duration: number}} range
 * @returns {Promise<{pcm: Int16Array, sampleRate: number, notes: import('../headless/view.js').PageNote[]}>}
 */
export async function renderSound(session, file, view, { time, duration }) {
  const first = await renderShader(session, file, { ...view, size: SOUND_VIEW_SIZE, time });
  const client = /** @type {import('../headless/client.js').EngineClient} */ (session.client());
  const sound = await client.renderSound({ time, duration }).catch((error) => {
    const message = error.message.split('\n')[0];
    if (/no Sound tab/.test(message))
      throw new ShaderproofError(`${file}: has no Sound tab (mainSound), so no .wav; give a shader with one, or -o OUT.png for a picture`);
    throw new ShaderproofError(`${file}: its sound: ${message}`);
  });
  const bytes = Buffer.from(sound.data, 'base64');
  const pcm = new Int16Array(bytes.buffer, bytes.byteOffset, bytes.byteLength / 2);
  return { pcm, sampleRate: sound.sampleRate, notes: first.notes };
}

/**
 * Whether a shader file has a Sound tab: a Shadertoy JSON with one (a .glsl file is an Image tab
 * alone; a JSON that cannot be read has none the page would play).
 * @param {string} file
 */
export function hasSoundTab(file) {
  const text = fs.readFileSync(file, 'utf8');
  if (!/\.json$/i.test(file) && !/^\s*[[{]/.test(text)) return false;
  try {
    return soundPass(fromShadertoyJson(text).model) !== null;
  } catch {
    return false;
  }
}

/**
 * Writes a WAV (whole, or not at all).
 * @param {string} file
 * @param {{pcm: Int16Array, sampleRate: number}} sound
 */
export function writeWav(file, { pcm, sampleRate }) {
  writeWhole(file, Buffer.from(encodeWav(pcm, sampleRate)));
}

/** What a WAV holds, in words. @param {{pcm: Int16Array, sampleRate: number}} sound */
export const wavSummary = ({ pcm, sampleRate }) =>
  `${(pcm.length / 2 / sampleRate).toFixed(2)} s of stereo 16-bit sound at ${sampleRate} Hz`;
