// When the page plays which samples of the Sound tab: pure arithmetic the player (player.js)
// follows and the tests check. The clock's iTime is the sound's time: sample i plays when iTime
// is i / 44,100 s. So after a seek, a pause, a restart or a change of speed, playback starts
// again from the sample of the iTime it will have when the sound starts (a short lead ahead of
// the audio clock), at a rate of the clock's speed: at speed 2 the samples go by twice as fast
// (an octave up, as a tape played fast) and stay in step with iTime; at speed 0, paused, or past
// the 180 s the site renders, nothing plays.
//
// The site itself plays its one 180 s buffer from the start on Restart and only disconnects it
// on Pause (effect.js StopOutput_Sound), so its sound runs on while paused and drifts from iTime
// after a seek; this page keeps the two together.

import { BLOCK_SAMPLES, PLAY_SECONDS, SAMPLE_RATE } from '../../shadertoy/sound.js';

/** The samples the site renders and plays. */
export const PLAY_SAMPLES = PLAY_SECONDS * SAMPLE_RATE;
/** How far ahead of the audio clock a (re)start is scheduled: time to draw its block and start. */
export const LEAD_SECONDS = 0.1;
/** How far the sound may drift from iTime before it starts again at the right sample. */
export const DRIFT_SECONDS = 0.1;

/**
 * Where playback starts: sample `sample` at audio-clock time `when`, then `rate` samples of
 * sound a sample of audio (the clock's speed). Null when nothing plays.
 * @typedef {{sample: number, when: number, rate: number}} Plan
 */

/**
 * The plan for a (re)start now.
 * @param {{time: number, speed: number, playing: boolean, now: number, lead?: number}} clock iTime, the
 *   clock's speed and play state, and the audio clock's time now (AudioContext.currentTime)
 * @returns {Plan | null}
 */
export function planPlayback({ time, speed, playing, now, lead = LEAD_SECONDS }) {
  if (!playing || !(speed > 0)) return null;
  const sample = Math.round((time + lead * speed) * SAMPLE_RATE);
  if (sample >= PLAY_SAMPLES) return null;
  return { sample, when: now + lead, rate: speed };
}

/**
 * The sample that plays at audio-clock time `at` under `plan` (fractional).
 * @param {Plan} plan
 * @param {number} at
 */
export const sampleAt = (plan, at) => plan.sample + (at - plan.when) * SAMPLE_RATE * plan.rate;

/**
 * How far the sound is from iTime at audio-clock time `at`, in seconds of sound (positive: ahead).
 * @param {Plan} plan
 * @param {number} at
 * @param {number} time iTime at `at`
 */
export const driftAt = (plan, at, time) => sampleAt(plan, at) / SAMPLE_RATE - time;

/**
 * The site's blocks to play under `plan` until audio-clock time `until`: each block's index, the
 * second into its buffer to start from, and when to start it (a block follows the one before
 * with no gap).
 * @param {Plan} plan
 * @param {number} until
 * @returns {Array<{block: number, offset: number, when: number}>}
 */
export function blocksToPlay(plan, until) {
  const out = [];
  for (let block = Math.floor(plan.sample / BLOCK_SAMPLES); block * BLOCK_SAMPLES < PLAY_SAMPLES; block++) {
    const from = Math.max(plan.sample, block * BLOCK_SAMPLES);
    const when = plan.when + (from - plan.sample) / SAMPLE_RATE / plan.rate;
    if (when >= until && out.length) break;
    out.push({ block, offset: (from - block * BLOCK_SAMPLES) / SAMPLE_RATE, when });
  }
  return out;
}
