// The per-frame Shadertoy inputs: the clock (iTime, iTimeDelta, iFrameRate, iFrame), the mouse
// (iMouse) and the date (iDate), with the site's semantics.
//
// iMouse, in device pixels with y up (the pixel under the pointer, as fragCoord's floor):
//   xy  position while the left button (or a finger) is down; frozen after release
//   z   x of the click, positive while held, negated on release
//   w   y of the click, positive only on the frame the button went down, negative after
//
// The clock runs at `speed` times real time: iTime advances by iTimeDelta each frame, and
// iTimeDelta is that step (so a shader that integrates iTimeDelta agrees with iTime); iFrameRate
// is the real rate at which frames are drawn. iFrame counts drawn frames from 0 (restart() sets
// it and iTime back to 0, and starts a new run of the clock: a frame begun in the run before is
// not counted when it lands, so the next frame drawn is the new run's iFrame 0).
//
// A fixed schedule (setSchedule: ?date=, ?fps=, the command line's defaults) makes a frame depend
// on nothing the page measures: iDate is a given moment at iTime 0 moving on with iTime, and each
// frame advances iTime by speed / fps, with iTimeDelta and iFrameRate those of that schedule.

import { FIRST_FRAME_UNIFORMS } from '../../shadertoy/header.js';

/** iTimeDelta for the first frame and for renders while paused (a nominal 60 Hz tick). @type {number} */
const NOMINAL_DELTA = FIRST_FRAME_UNIFORMS.iTimeDelta;
/** iFrameRate until two frames give a real rate, and while paused. @type {number} */
const NOMINAL_RATE = FIRST_FRAME_UNIFORMS.iFrameRate;

/** @typedef {import('../gpu/protocol.js').FrameInputs} FrameInputs */

/**
 * Shadertoy's iDate for a moment: [year, month (0-based), day, seconds since local midnight].
 * @param {Date} date
 * @returns {number[]}
 */
export function shadertoyDate(date) {
  const midnight = new Date(date.getFullYear(), date.getMonth(), date.getDate());
  return [date.getFullYear(), date.getMonth(), date.getDate(), (date.getTime() - midnight.getTime()) / 1000];
}

export class ShadertoyInputs {
  constructor() {
    this.time = 0;
    this.speed = 1;
    this.playing = true;
    this.frame = 0;
    /** Which run of the clock this is: restart() starts another. */
    this.run = 0;
    this.delta = NOMINAL_DELTA;
    this.frameRate = NOMINAL_RATE;
    this._lastNow = null;
    /** iDate at iTime 0, ms since 1970 (null: iDate is the real date). @type {number | null} */
    this.fixedDate = null;
    /** The frame schedule, frames a second (null: iTimeDelta and iFrameRate are measured). @type {number | null} */
    this.fixedFps = null;
    this._mouse = { x: 0, y: 0, clickX: 0, clickY: 0, down: false, clicked: false, pointerId: null };
    this._fixedMouse = null; // from the URL: used as given until the user clicks
    /** @type {number[] | null} the mouse the page opened with (resetMouse) */
    this._startMouse = null;
    /** Called when pointer input changes iMouse (the page re-renders if paused). */
    this.onMouseChange = () => {};
  }

  play() {
    this.playing = true;
    this._lastNow = null; // no time jump for the pause
  }

  pause() {
    this.playing = false;
  }

  /** iTime and iFrame back to 0 (Shadertoy's rewind); the play state and the mouse stay. */
  restart() {
    this.time = 0;
    this.frame = 0;
    this.run++;
    this._lastNow = null;
  }

  setTime(seconds) {
    this.time = seconds;
  }

  setSpeed(speed) {
    this.speed = speed;
  }

  /**
   * The clock's schedule: iDate fixed at `date` (ms since 1970) at iTime 0, and `fps` frames a
   * second; null for either: the real date, the measured rate.
   * @param {{date?: number | null, fps?: number | null}} schedule
   */
  setSchedule({ date = null, fps = null }) {
    this.fixedDate = date;
    this.fixedFps = fps;
  }

  /**
   * iDate at iTime `time`: the fixed moment moved on by `time`, or the real date (`now`, ms since
   * 1970, for a recording's frames: its start moved on by their iTime).
   * @param {number} time
   * @param {number} [now]
   */
  dateAt(time, now = Date.now()) {
    return shadertoyDate(new Date(this.fixedDate !== null ? this.fixedDate + time * 1000 : now));
  }

  /**
   * Fixes iMouse to these four numbers (device pixels) until the next click.
   * @param {number[]} mouse [x, y, z, w]
   * @param {{start?: boolean}} [options] start: the page opens with it (resetMouse comes back to it)
   */
  setMouse([x, y, z, w], { start = false } = {}) {
    this._fixedMouse = [x, y, z, w];
    if (start) this._startMouse = [x, y, z, w];
  }

  /**
   * The mouse the page opens with (null: all 0), and iMouse set to it.
   * @param {number[] | null} mouse [x, y, z, w]
   */
  setStartMouse(mouse) {
    this._startMouse = mouse ? mouse.slice() : null;
    this.resetMouse();
  }

  /**
   * iMouse as the page opened with it (all 0, or the link's mouse=): a click or a drag on the
   * canvas sets iMouse as Shadertoy does, and for many a shader that turns the camera; this
   * puts it back.
   */
  resetMouse() {
    this._mouse = { x: 0, y: 0, clickX: 0, clickY: 0, down: false, clicked: false, pointerId: null };
    this._fixedMouse = this._startMouse ? this._startMouse.slice() : null;
  }

  /**
   * Tracks the left button, or one finger, on `canvas`: a drag orbits on a phone as it does with
   * a mouse. Extra fingers are ignored.
   */
  attach(canvas) {
    const toDevice = (event) => {
      const rect = canvas.getBoundingClientRect();
      return [
        Math.floor(((event.clientX - rect.left) / rect.width) * canvas.width),
        Math.floor(canvas.height - ((event.clientY - rect.top) / rect.height) * canvas.height),
      ];
    };
    const m = this._mouse;
    canvas.addEventListener('pointerdown', (event) => {
      if (event.button !== 0 || !event.isPrimary || m.down) return;
      event.preventDefault(); // no text selection, no emulated mouse events after a touch
      canvas.setPointerCapture?.(event.pointerId);
      [m.x, m.y] = toDevice(event);
      [m.clickX, m.clickY] = [m.x, m.y];
      m.down = true;
      m.clicked = true;
      m.pointerId = event.pointerId;
      this._fixedMouse = null;
      this.onMouseChange();
    });
    canvas.addEventListener('pointermove', (event) => {
      if (!m.down || event.pointerId !== m.pointerId) return;
      [m.x, m.y] = toDevice(event);
      this.onMouseChange();
    });
    const release = (event) => {
      if (!m.down || event.pointerId !== m.pointerId) return;
      m.down = false;
      m.pointerId = null;
      this.onMouseChange();
    };
    canvas.addEventListener('pointerup', release);
    canvas.addEventListener('pointercancel', release);
  }

  /**
   * The current iMouse.
   * @returns {number[]} [x, y, z, w]
   */
  mouse() {
    if (this._fixedMouse) return this._fixedMouse.slice();
    const m = this._mouse;
    return [m.x, m.y, m.down ? m.clickX : -m.clickX, m.clicked ? m.clickY : -m.clickY];
  }

  /**
   * Advances the clock to `now` (ms, performance.now()) and returns the inputs of a frame of
   * width × height (the render worker writes them into the uniforms: gpu/uniforms.js). Call
   * endFrame() once it is drawn.
   * @param {number} width
   * @param {number} height
   * @param {number} now
   * @returns {FrameInputs}
   */
  beginFrame(width, height, now) {
    const scheduled = this.fixedFps;
    if (scheduled !== null) {
      // the schedule's step, whatever the frame cost: the same frames on every machine
      this.delta = this.playing ? this.speed / scheduled : 1 / scheduled;
      this.frameRate = scheduled;
      if (this.playing && this._lastNow !== null) this.time += this.delta;
      this._lastNow = now;
    } else if (this.playing) {
      if (this._lastNow !== null) {
        const real = Math.max(0, (now - this._lastNow) / 1000);
        this.delta = real * this.speed;
        this.frameRate = real > 0 ? 1 / real : 0;
        this.time += this.delta;
      } else {
        this.delta = NOMINAL_DELTA * this.speed;
        this.frameRate = NOMINAL_RATE;
      }
      this._lastNow = now;
    } else {
      this.delta = NOMINAL_DELTA;
      this.frameRate = NOMINAL_RATE;
    }

    return {
      width,
      height,
      time: this.time,
      delta: this.delta,
      frameRate: this.frameRate,
      frame: this.frame,
      mouse: this.mouse(),
      date: this.dateAt(this.time),
    };
  }

  /**
   * A frame begun in run `run` of the clock is drawn: the next one is the frame after it, unless
   * the clock was restarted meanwhile.
   * @param {number} [run]
   */
  endFrame(run = this.run) {
    if (run !== this.run) return;
    this.frame++;
    this._mouse.clicked = false;
  }
}
