// The toolbar's frame-time readout: a graph of the times between frames and a line that says
// what the page is doing, measured honestly.
//
// - Frames that follow one another (playing, or converging a still view) go into the graph and
//   the frame rate: frames drawn per second of the page's own clock (performance.now() when each
//   was drawn, not the animation frame's timestamp, which is when it was due: on a slow GPU those
//   run ahead of the drawing), over the last RATE_WINDOW_MS. A rate is never computed from a
//   GPU time: the page cannot draw faster than its frames actually come.
// - GPU time, where the browser measures it (gpu/gpu-timer.js), comes with each drawn frame. It
//   is shown only when it fits the frames it came with: one frame's GPU time cannot exceed the
//   time between frames (the first frames of a new shader carry its compile, and would say "GPU
//   480 ms" beside "2.7 fps").
// - The line says what is happening: drawing the first frame (how far it has got), playing,
//   paused, converging (the samples so far), or time standing still at speed 0; compiling, and
//   for how long, once a compile has taken a second; "no frame for N s · may never finish" once
//   a band has outlasted the watchdog (app/render-client.js). Figures are of frames drawn: once
//   the next frame is late (twice the time between the last ones, and at least LATE_MS), the
//   line says a frame is being drawn, and for how long, instead of the rate it no longer has.

import { median } from '../../../shared/stats.js';

const RATE_WINDOW_MS = 2000;
const GRAPH_MAX_MS = 50; // the graph's top (20 fps); slower frames are clipped there
/** How often the line is written again (a heavy first frame's progress moves between frames). */
const REFRESH_MS = 250;
/** A frame this late (or twice the time between the last ones, when longer) ends the figures. */
const LATE_MS = 500;

/**
 * What the page is doing, as the readout tells it.
 * @typedef {{phase: 'first', progress: number | null}
 *   | {phase: 'playing'}
 *   | {phase: 'still'}
 *   | {phase: 'paused', progress: number | null}
 *   | {phase: 'converging', samples: number, of: number}
 *   | {phase: 'compiling', seconds: number}
 *   | {phase: 'stalled', seconds: number}
 *   | {phase: 'failed'}} Activity
 */

/** Frames drawn per second of the page's clock, over the last RATE_WINDOW_MS. */
class FrameRate {
  constructor() {
    /** @type {number[]} */
    this._times = [];
  }

  /** @param {number} now performance.now() when a frame was drawn */
  add(now) {
    this._times.push(now);
    while (this._times.length > 2 && now - this._times[0] > RATE_WINDOW_MS) this._times.shift();
  }

  reset() {
    this._times.length = 0;
  }

  /** Frames per second, or null until two frames are in. */
  get fps() {
    const t = this._times;
    return t.length < 2 ? null : ((t.length - 1) * 1000) / (t[t.length - 1] - t[0]);
  }

  /**
   * How long the next frame is overdue at `now`, in ms (0: it is not late): past twice the time
   * between the last frames, and at least LATE_MS, after the last one.
   * @param {number} now
   */
  late(now) {
    const t = this._times;
    if (!t.length) return 0;
    const since = now - t[t.length - 1];
    const fps = this.fps;
    return since > Math.max(LATE_MS, fps ? 2000 / fps : 0) ? since : 0;
  }
}

/** A rate, rounded down: never a speed the page did not reach. @param {number} fps */
const formatRate = (fps) => (fps < 10 ? `${(Math.floor(fps * 10 + 1e-6) / 10).toFixed(1)} fps` : `${Math.floor(fps + 1e-6)} fps`);

export class FrameReadout {
  /**
   * @param {HTMLCanvasElement} graph
   * @param {HTMLElement} text
   * @param {() => Activity} activity what the page is doing now
   */
  constructor(graph, text, activity) {
    this.graph = graph;
    this.text = text;
    this.activity = activity;
    /** Times between frames (ms), oldest first, as many as the graph is wide. @type {number[]} */
    this.intervals = [];
    /** GPU times (ms) of the frames in the graph. @type {number[]} */
    this._gpu = [];
    this._rate = new FrameRate();
    /** The phase the graph's frames belong to: another starts the graph again. */
    this._phase = '';
    setInterval(() => this.refresh(), REFRESH_MS);
    this.refresh();
  }

  /**
   * A frame was drawn.
   * @param {{interval: number | null, gpuTimes: number[]}} frame
   * @param {number} [now] performance.now()
   */
  drawn({ interval, gpuTimes }, now = performance.now()) {
    this._follow();
    if (interval === null) {
      this._rate.reset();
      this._rate.add(now);
      this._gpu.length = 0;
    } else {
      this.intervals.push(interval);
      if (this.intervals.length > this.graph.width) this.intervals.shift();
      this._rate.add(now);
      this._gpu.push(...gpuTimes);
      if (this._gpu.length > this.graph.width) this._gpu.splice(0, this._gpu.length - this.graph.width);
    }
    this._drawGraph();
  }

  /** A new phase (playing, converging, paused...) starts the graph and the rate again. */
  _follow() {
    const phase = this.activity().phase;
    if (phase === this._phase) return;
    this._phase = phase;
    this.intervals.length = 0;
    this._gpu.length = 0;
    this._rate.reset();
    this._drawGraph();
  }

  /** Writes the line for what the page is doing now. */
  refresh() {
    this._follow();
    const now = this.activity();
    const percent = (/** @type {number | null} */ p) => (p === null ? '' : ` · ${Math.floor(p * 100)}%`);
    let line;
    const s = (/** @type {number} */ seconds) => `${Math.floor(seconds)} s`;
    if (now.phase === 'compiling') line = `Compiling · ${s(now.seconds)}`;
    else if (now.phase === 'stalled') line = `No frame for ${s(now.seconds)} · may never finish`;
    else if (now.phase === 'failed') line = 'Not running · did not compile';
    else if (now.phase === 'first') line = `Drawing the first frame${percent(now.progress)}`;
    else if (now.phase === 'paused') line = now.progress === null ? 'Paused' : `Paused · drawing a frame${percent(now.progress)}`;
    else if (now.phase === 'still') line = 'Speed 0× · time stands still';
    else if (now.phase === 'converging')
      line = now.samples >= now.of ? `Converged · ${now.samples} samples` : `Converging · ${now.samples} samples${this._speed(' · ')}`;
    else line = this._speed('') || 'Playing';
    if (this.text.textContent !== line) this.text.textContent = line;
  }

  /** The frame time and rate of the frames in the graph ('' until two are in). @param {string} lead */
  _speed(lead) {
    const fps = this._rate.fps;
    if (fps === null || !this.intervals.length) return '';
    // no figure from frames that were not drawn: a late frame is said as late
    const late = this._rate.late(performance.now());
    if (late) return `${lead}${lead ? 'drawing' : 'Drawing'} a frame · ${Math.floor(late / 1000)} s`;
    const between = 1000 / fps;
    const gpu = this._gpu.length ? median(this._gpu.slice(-10)) : null;
    // a GPU time longer than the time between frames is not this run's (a compile, a first frame)
    const time = gpu !== null && gpu <= between ? `GPU ${gpu.toFixed(1)} ms` : `${between.toFixed(1)} ms between frames`;
    return `${lead}${time} · ${formatRate(fps)}`;
  }

  _drawGraph() {
    const g = this.graph.getContext('2d');
    if (!g) return;
    const { width, height } = this.graph;
    this.graph.dataset.frames = String(this.intervals.length);
    g.clearRect(0, 0, width, height);
    // guides at 60 fps and 30 fps
    g.fillStyle = 'rgba(255,255,255,0.18)';
    for (const ms of [1000 / 60, 1000 / 30]) g.fillRect(0, Math.round(height - (ms / GRAPH_MAX_MS) * height), width, 1);
    const times = this.intervals;
    for (let i = 0; i < times.length; i++) {
      const ms = times[i];
      const h = Math.max(1, Math.min(height, Math.round((ms / GRAPH_MAX_MS) * height)));
      g.fillStyle = ms <= 1000 / 55 ? '#46a758' : ms <= 1000 / 28 ? '#f5d90a' : '#e5484d';
      g.fillRect(width - times.length + i, height - h, 1, h);
    }
  }
}
