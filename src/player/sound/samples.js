// The Sound tab's samples as the page asks the render worker for them (sound-pass.js draws
// them): what the player schedules, the recorder encodes and window.shaderEngine hands the command
// line.

import { soundPass } from '../../shadertoy/multipass.js';
import { SAMPLE_RATE } from '../../shadertoy/sound.js';

/** @typedef {import('../app/app.js').ShaderApp} ShaderApp */

/** Whether the shader in the app has a Sound tab. @param {ShaderApp} app */
export const hasSound = (app) => soundPass(app.project) !== null;

/**
 * Whether the shader that runs (the last one that compiled) has a Sound tab: a shader that did
 * not compile plays nothing, and the one before it, if any, plays on.
 * @param {ShaderApp} app
 */
export const runsSound = (app) => app.compiles.running !== null && soundPass(app.compiles.running.project) !== null;

/**
 * Samples [first, first + count) of the Sound tab: two 16-bit words a sample (sound.js).
 * @param {ShaderApp} app
 * @param {number} first
 * @param {number} count
 * @param {number[]} [date] iDate (default: the page's at iTime 0)
 * @returns {Promise<Uint16Array>}
 */
export function soundSamples(app, first, count, date = app.inputs.dateAt(0)) {
  return app.gpu.ask('sound', { first, count, date });
}

/**
 * The samples of seconds [time, time + duration), as whole samples (sample i at i / 44,100 s).
 * @param {number} time
 * @param {number} duration
 */
export function sampleRange(time, duration) {
  const first = Math.max(0, Math.round(time * SAMPLE_RATE));
  return { first, count: Math.max(0, Math.round((time + duration) * SAMPLE_RATE) - first) };
}
