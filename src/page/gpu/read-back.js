// A render target's pixels read back for the page, rows top to bottom: as the page's canvas shows
// them (RGBA8, alpha 1), or as floats (RGBA32F). Reading waits for the GPU: the band scheduler
// (band-scheduler.js) reads a target once its fence has passed.

import { flipRows } from '../../shared/pixels.js';

/** @typedef {import('./renderer.js').ShaderRenderer} ShaderRenderer */

/**
 * A float target's pixels, RGBA32F, rows top to bottom.
 * @param {ShaderRenderer} renderer
 * @param {any} target
 * @param {number} width
 * @param {number} height
 */
export function readFloat(renderer, target, width, height) {
  const pixels = new Float32Array(width * height * 4);
  renderer.three.readRenderTargetPixels(target, 0, 0, width, height, pixels);
  const row = width * 4;
  const out = new Float32Array(pixels.length);
  for (let y = 0; y < height; y++) out.set(pixels.subarray((height - 1 - y) * row, (height - y) * row), y * row);
  return out;
}

/**
 * A target's pixels as the page shows them: rows top to bottom, alpha 1 (the page's canvas has none).
 * @param {ShaderRenderer} renderer
 * @param {any} target
 * @param {number} width
 * @param {number} height
 */
export function readOpaque(renderer, target, width, height) {
  const pixels = flipRows(renderer.readTarget(target), width, height);
  for (let i = 3; i < pixels.length; i += 4) pixels[i] = 255;
  return pixels;
}
