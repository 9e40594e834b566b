// The per-frame Shadertoy inputs: the clock (iTime, iTimeDelta, iFrameRate, iFrame), the mouse
// (iMouse) and the date (iDate), with the site's semantics.
//
// iMouse, in device pixels with y up:
//   xy  position while the left button is held; frozen after release
//   z   x of the click, positive while held, negated on release
//   w   y of the click, positive only on the frame the button went down, negative after

const NOMINAL_DELTA = 1 / 60; // iTimeDelta for the first frame and for renders while paused

export class ShadertoyInputs {
  constructor() {
    this.time = 0;
    this.playing = true;
    this.frame = 0;
    this.delta = NOMINAL_DELTA;
    this._lastNow = null;
    this._mouse = { x: 0, y: 0, clickX: 0, clickY: 0, down: false, clicked: false };
    this._fixedMouse = null; // from the URL: used as given until the user clicks
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

  setTime(seconds) {
    this.time = seconds;
  }

  /** Fixes iMouse to these four numbers (device pixels) until the next click. */
  setMouse([x, y, z, w]) {
    this._fixedMouse = [x, y, z, w];
  }

  /** Tracks the left button on `canvas`. */
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
      if (event.button !== 0) return;
      canvas.setPointerCapture(event.pointerId);
      [m.x, m.y] = toDevice(event);
      [m.clickX, m.clickY] = [m.x, m.y];
      m.down = true;
      m.clicked = true;
      this._fixedMouse = null;
      this.onMouseChange();
    });
    canvas.addEventListener('pointermove', (event) => {
      if (!m.down) return;
      [m.x, m.y] = toDevice(event);
      this.onMouseChange();
    });
    const release = () => {
      if (!m.down) return;
      m.down = false;
      this.onMouseChange();
    };
    canvas.addEventListener('pointerup', release);
    canvas.addEventListener('pointercancel', release);
  }

  /** The current iMouse as [x, y, z, w]. */
  mouse() {
    if (this._fixedMouse) return this._fixedMouse;
    const m = this._mouse;
    return [m.x, m.y, m.down ? m.clickX : -m.clickX, m.clicked ? m.clickY : -m.clickY];
  }

  /**
   * Advances the clock to `now` (ms, performance.now()) and writes every Shadertoy uniform for a
   * drawing buffer of width × height. Call endFrame() after drawing.
   */
  beginFrame(uniforms, width, height, now) {
    if (this.playing) {
      if (this._lastNow !== null) {
        this.delta = Math.max(0, (now - this._lastNow) / 1000);
        this.time += this.delta;
      } else {
        this.delta = NOMINAL_DELTA;
      }
      this._lastNow = now;
    } else {
      this.delta = NOMINAL_DELTA;
    }

    const date = new Date();
    const midnight = new Date(date.getFullYear(), date.getMonth(), date.getDate());
    uniforms.iResolution.value.set(width, height, 1);
    uniforms.iTime.value = this.time;
    uniforms.iTimeDelta.value = this.delta;
    uniforms.iFrameRate.value = this.delta > 0 ? 1 / this.delta : 0;
    uniforms.iFrame.value = this.frame;
    uniforms.iMouse.value.fromArray(this.mouse());
    uniforms.iDate.value.set(date.getFullYear(), date.getMonth(), date.getDate(), (date - midnight) / 1000);
  }

  endFrame() {
    this.frame++;
    this._mouse.clicked = false;
  }
}
