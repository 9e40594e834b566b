// The Sound tab heard through Web Audio, in step with the clock (schedule.js says which sample
// plays when): each of the site's blocks is drawn by the render worker when it is first needed
// (sound-pass.js) and played as an AudioBuffer, the next one scheduled to follow it with no gap.
// Play, Pause, Restart, the time slider and the speed move the sound with iTime; a drift past
// DRIFT_SECONDS (the clock's iTime moves a frame at a time) starts it again at the right sample.
//
// Browsers start no sound before the person has interacted with the page (the autoplay rule):
// the AudioContext is made on the first click or key (unlock()), and until then the page says
// so (ui/notices.js soundNote). A gain node mutes; an analyser feeds the level meter.

import { BLOCK_SAMPLES, SAMPLE_RATE, toPlayed } from '../../shadertoy/sound.js';
import { runsSound, soundSamples } from './samples.js';
import { DRIFT_SECONDS, PLAY_SAMPLES, blocksToPlay, driftAt, planPlayback } from './schedule.js';

/** How far ahead of the audio clock blocks are scheduled, in seconds. */
const AHEAD_SECONDS = 2;
/** Blocks kept as AudioBuffers (6 s each). */
const BUFFERS_KEPT = 4;

/** @typedef {import('../app/app.js').ShaderApp} ShaderApp */
/** @typedef {import('./schedule.js').Plan} Plan */

export class SoundPlayer {
  /** @param {ShaderApp} app */
  constructor(app) {
    this.app = app;
    /** @type {AudioContext | null} made on the first interaction (unlock) */
    this.context = null;
    /** @type {GainNode | null} */
    this.gain = null;
    /** @type {AnalyserNode | null} */
    this.analyser = null;
    this.muted = false;
    /** What plays now, and the iTime it was planned at. @type {(Plan & {time: number}) | null} */
    this.plan = null;
    /** @type {Set<AudioBufferSourceNode>} */
    this._sources = new Set();
    /** Blocks scheduled under the plan. @type {Set<number>} */
    this._scheduled = new Set();
    /** @type {Map<number, Promise<AudioBuffer>>} */
    this._buffers = new Map();
    /** iDate for the Sound tab: the page's at iTime 0 when it compiled (the site's: at its compile). */
    this._date = app.inputs.dateAt(0);
    this._clock = { playing: app.inputs.playing, speed: app.inputs.speed, run: app.inputs.run };
    /** Called when what the page should say about sound changes. */
    this.onChange = () => {};
    app.on('compile', (_, error) => {
      if (error) return;
      this._buffers.clear();
      this._date = app.inputs.dateAt(0);
      this.sync();
    });
    app.on('state', () => {
      const { playing, speed, run } = app.inputs;
      const moved = playing !== this._clock.playing || speed !== this._clock.speed || run !== this._clock.run;
      this._clock = { playing, speed, run };
      if (moved) this.sync();
      else this.tick();
    });
    app.on('drawn', () => this.tick());
  }

  /** How many blocks are playing or scheduled to. */
  get sourceCount() {
    return this._sources.size;
  }

  /** Whether the shader that runs has a Sound tab (one that did not compile plays nothing). */
  get available() {
    return runsSound(this.app);
  }

  /** Whether it has one the browser will not let play yet (no interaction so far). */
  get waiting() {
    return this.available && this.context?.state !== 'running';
  }

  /** The first click or key: sound may start (the autoplay rule). */
  unlock() {
    if (!this.context) {
      const context = new AudioContext({ sampleRate: SAMPLE_RATE });
      this.gain = context.createGain();
      this.analyser = context.createAnalyser();
      this.analyser.fftSize = 1024;
      this.gain.connect(this.analyser).connect(context.destination);
      this.gain.gain.value = this.muted ? 0 : 1;
      context.addEventListener('statechange', () => this.onChange());
      this.context = context;
    }
    this.context.resume().then(
      () => this.sync(),
      () => {},
    );
  }

  /** @param {boolean} muted */
  setMuted(muted) {
    this.muted = muted;
    if (this.gain) this.gain.gain.value = muted ? 0 : 1;
    this.onChange();
  }

  /** Playback starts again from the clock as it is now (or stops). */
  sync() {
    for (const source of this._sources) source.stop();
    this._sources.clear();
    this._scheduled.clear();
    this.plan = null;
    const context = this.context;
    if (context && context.state === 'running' && this.available) {
      const { time, speed, playing } = this.app.inputs;
      const plan = planPlayback({ time, speed, playing, now: context.currentTime });
      this.plan = plan && { ...plan, time };
    }
    this.tick();
    this.onChange();
  }

  /** Schedules the blocks that come next; starts again if the sound has drifted from iTime. */
  tick() {
    const plan = this.plan;
    const context = this.context;
    if (!plan || !context) return;
    const now = context.currentTime;
    if (now > plan.when && Math.abs(driftAt(plan, now, this.app.inputs.time)) > DRIFT_SECONDS) {
      this.sync();
      return;
    }
    for (const { block, offset, when } of blocksToPlay(plan, now + AHEAD_SECONDS)) {
      if (this._scheduled.has(block)) continue;
      this._scheduled.add(block);
      this._start(plan, block, offset, when).catch(() => this._scheduled.delete(block));
    }
  }

  /** The sound's level now: the RMS of what the analyser last heard, 0..1. */
  level() {
    if (!this.analyser || !this.plan) return 0;
    const data = new Float32Array(this.analyser.fftSize);
    this.analyser.getFloatTimeDomainData(data);
    let sum = 0;
    for (const v of data) sum += v * v;
    return Math.sqrt(sum / data.length);
  }

  /** Plays block `block` from `offset` s into it at `when` (or now, that much further in, if late). */
  async _start(plan, block, offset, when) {
    const buffer = await this._buffer(block);
    const context = /** @type {AudioContext} */ (this.context);
    if (plan !== this.plan || !this.gain) return;
    const late = context.currentTime - when;
    const source = context.createBufferSource();
    source.buffer = buffer;
    source.playbackRate.value = plan.rate;
    source.connect(this.gain);
    source.addEventListener('ended', () => this._sources.delete(source));
    this._sources.add(source);
    source.start(Math.max(when, context.currentTime), offset + Math.max(0, late) * plan.rate);
  }

  /** Block `block` as an AudioBuffer, drawn by the render worker once. @returns {Promise<AudioBuffer>} */
  _buffer(block) {
    let buffer = this._buffers.get(block);
    if (!buffer) {
      const first = block * BLOCK_SAMPLES;
      const count = Math.min(BLOCK_SAMPLES, PLAY_SAMPLES - first);
      buffer = soundSamples(this.app, first, count, this._date).then((words) => {
        const audio = new AudioBuffer({ numberOfChannels: 2, length: count, sampleRate: SAMPLE_RATE });
        toPlayed(words).forEach((data, channel) => audio.copyToChannel(data, channel));
        return audio;
      });
      buffer.catch(() => this._buffers.delete(block));
      this._buffers.set(block, buffer);
      for (const old of this._buffers.keys()) if (this._buffers.size > BUFFERS_KEPT && old !== block) this._buffers.delete(old);
    }
    return buffer;
  }
}
