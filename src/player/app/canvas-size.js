// The canvas's drawing-buffer size, in device pixels, and when it changes.
//
// Without a fixed size the canvas fills its place in the layout, and its drawing buffer is that
// CSS size times devicePixelRatio times the resolution scale, its longer side capped (by the
// panel's cap and by the largest size the GPU draws). A fixed size (?size=WxH) is the drawing
// buffer itself: its CSS size is that over devicePixelRatio, shrunk to fit the window.

import { clampSize } from '../../shared/canvas-limits.js';

/** @typedef {{width: number, height: number}} Size */

/**
 * A size the GPU can draw: scaled down (keeping its aspect), with a warning, if a side exceeds
 * `maxSide`. A `maxSide` of 0 (the context is lost: no limit known) leaves the size as it is.
 * @param {Size} size
 * @param {number} maxSide the GPU's largest drawing-buffer or render-target side
 * @param {string} what what the size is for, in the warning
 * @returns {Size}
 */
export function fitGpu(size, maxSide, what) {
  if (!maxSide) return size;
  const fitted = clampSize(size, maxSide);
  if (fitted.width !== size.width || fitted.height !== size.height) {
    console.warn(
      `${what} ${size.width}x${size.height} is larger than this GPU draws (${maxSide} px a side): using ${fitted.width}x${fitted.height}`,
    );
  }
  return fitted;
}

export class CanvasSize {
  /**
   * @param {HTMLCanvasElement} canvas
   * @param {object} options
   * @param {() => number} options.maxSide the GPU's largest side now (0 while the context is lost)
   * @param {Size | null} [options.fixed] fixed drawing-buffer size (device px)
   * @param {number} [options.scale] resolution scale of the device pixels (without a fixed size)
   * @param {number} [options.cap] cap on the drawing buffer's longer side (device px; 0: none)
   */
  constructor(canvas, { maxSide, fixed = null, scale = 1, cap = 0 }) {
    /** @type {HTMLCanvasElement} */
    this.canvas = canvas;
    /** @type {() => number} */
    this.maxSide = maxSide;
    /** The fixed drawing-buffer size, or null when the canvas follows the layout. @type {Size | null} */
    this.fixed = fixed ? fitGpu(fixed, maxSide(), 'size') : null;
    /** @type {number} */
    this.scale = scale;
    /** @type {number} */
    this.cap = cap;
  }

  /** @param {number} scale resolution scale of the device pixels (without a fixed size) */
  setScale(scale) {
    this.scale = scale;
  }

  /** @param {number} cap cap on the drawing buffer's longer side, in device pixels (0: none) */
  setCap(cap) {
    this.cap = Math.max(0, Math.round(Number(cap) || 0));
  }

  /**
   * A fixed drawing-buffer size (device px), or null: the canvas follows the layout again.
   * @param {Size | null} size
   */
  setFixed(size) {
    this.fixed = size ? fitGpu(size, this.maxSide(), 'size') : null;
    if (!this.fixed) {
      this.canvas.style.width = '';
      this.canvas.style.height = '';
    }
    this.fitFixedSize();
  }

  /**
   * The drawing-buffer size for the current layout, in device pixels.
   * @returns {Size}
   */
  target() {
    if (this.fixed) return this.fixed;
    const dpr = window.devicePixelRatio || 1;
    let width = Math.max(1, Math.round(this.canvas.clientWidth * dpr * this.scale));
    let height = Math.max(1, Math.round(this.canvas.clientHeight * dpr * this.scale));
    const longest = Math.max(width, height);
    const cap = Math.min(this.cap || Infinity, this.maxSide() || Infinity);
    if (longest > cap) {
      width = Math.max(1, Math.round((width * cap) / longest));
      height = Math.max(1, Math.round((height * cap) / longest));
    }
    return { width, height };
  }

  /**
   * A fixed size is in device pixels: its CSS size is that over devicePixelRatio, unscaled, and
   * shrunk (keeping its aspect) when it would not fit the window.
   */
  fitFixedSize() {
    if (!this.fixed) return;
    const dpr = window.devicePixelRatio || 1;
    const css = { width: this.fixed.width / dpr, height: this.fixed.height / dpr };
    const room = this.canvas.parentElement ?? document.documentElement;
    const k = Math.min(1, (room.clientWidth || css.width) / css.width, (room.clientHeight || css.height) / css.height);
    this.canvas.style.width = `${css.width * k}px`;
    this.canvas.style.height = `${css.height * k}px`;
  }

  /**
   * Calls `onChange` whenever the layout, the window or devicePixelRatio changes the target size
   * away from the canvas's drawing buffer (the caller then draws, which resizes it).
   * @param {() => void} onChange
   */
  watch(onChange) {
    this.fitFixedSize();
    const check = () => {
      this.fitFixedSize();
      const { width, height } = this.target();
      if (width !== this.canvas.width || height !== this.canvas.height) onChange();
    };
    new ResizeObserver(check).observe(this.canvas);
    // the canvas's size in device pixels also changes with devicePixelRatio alone
    try {
      new ResizeObserver(check).observe(this.canvas, { box: 'device-pixel-content-box' });
    } catch {
      // not supported (Safari): the media query below catches ratio changes
    }
    if (this.fixed && this.canvas.parentElement) new ResizeObserver(check).observe(this.canvas.parentElement);
    window.addEventListener('resize', check);
    // A devicePixelRatio change (zoom, moving the window to another screen) need not resize
    // anything in CSS pixels: watch the ratio itself, re-arming the query for each new value.
    const watchRatio = () => {
      const query = matchMedia(`(resolution: ${window.devicePixelRatio || 1}dppx)`);
      query.addEventListener(
        'change',
        () => {
          check();
          watchRatio();
        },
        { once: true },
      );
    };
    watchRatio();
    // Not every ratio change fires those (emulated device metrics, some zoom paths): a cheap
    // check twice a second catches the rest.
    let ratio = window.devicePixelRatio;
    setInterval(() => {
      if (window.devicePixelRatio !== ratio) {
        ratio = window.devicePixelRatio;
        check();
      }
    }, 500);
  }
}
