// Shadertoy's uniforms in the render worker: the three.js uniform objects every pass shares, and
// writing one frame's inputs (FrameInputs, from the page's clock, mouse and date) into them.

import * as THREE from 'three';
import { FIRST_FRAME_UNIFORMS, SHADERTOY_UNIFORMS } from '../../shadertoy/header.js';

/** @typedef {import('./protocol.js').FrameInputs} FrameInputs */

/** A 1×1 black texture: what an empty channel samples, as on Shadertoy. */
export function blackTexture() {
  const texture = new THREE.DataTexture(new Uint8Array([0, 0, 0, 255]), 1, 1);
  texture.needsUpdate = true;
  return texture;
}

/**
 * Three.js uniform objects for every uniform Shadertoy declares (SHADERTOY_UNIFORMS), holding
 * their first-frame values (FIRST_FRAME_UNIFORMS; zeros for iResolution and iDate, which every
 * frame writes before it draws). Arrays are flat (vec3[4]: 12 numbers); every channel samples
 * `black` and reports 0 × 0, as an empty one does on Shadertoy.
 * @param {THREE.Texture} black
 * @returns {Record<string, {value: any}>}
 */
export function shadertoyUniforms(black) {
  const firstFrame = /** @type {Readonly<Record<string, number | readonly number[]>>} */ (FIRST_FRAME_UNIFORMS);
  /** @type {Record<string, {value: any}>} */
  const uniforms = {};
  for (const [name, type] of Object.entries(SHADERTOY_UNIFORMS)) {
    const first = firstFrame[name];
    let value;
    if (type === 'sampler2D') value = black;
    else if (type === 'vec3') value = new THREE.Vector3().fromArray(Array.isArray(first) ? first : [0, 0, 0]);
    else if (type === 'vec4') value = new THREE.Vector4().fromArray(Array.isArray(first) ? first : [0, 0, 0, 0]);
    else if (type.endsWith(']') && Array.isArray(first))
      value = [...first]; // float[4], vec3[4] (flat)
    else if ((type === 'float' || type === 'int') && typeof first === 'number') value = first;
    else throw new Error(`no first-frame value for Shadertoy's ${type} ${name}`);
    uniforms[name] = { value };
  }
  return uniforms;
}

/**
 * Writes one frame's values into the uniforms. Used again by a screenshot, at another size:
 * then iMouse is scaled with the size, so that it points at the same place in the picture.
 * @param {Record<string, {value: any}>} uniforms
 * @param {FrameInputs} frame
 * @param {{width: number, height: number} | null} [size] another size to draw the frame at
 */
export function writeUniforms(uniforms, frame, size = null) {
  const width = size?.width ?? frame.width;
  const height = size?.height ?? frame.height;
  const sx = width / frame.width;
  const sy = height / frame.height;
  const [mx, my, mz, mw] = frame.mouse;
  uniforms.iResolution.value.set(width, height, 1);
  uniforms.iTime.value = frame.time;
  uniforms.iTimeDelta.value = frame.delta;
  uniforms.iFrameRate.value = frame.frameRate;
  uniforms.iFrame.value = frame.frame;
  uniforms.iMouse.value.set(mx * sx, my * sy, mz * sx, mw * sy);
  uniforms.iDate.value.fromArray(frame.date);
}

/**
 * Declares the live (`const`) controls as uniforms, with `values`. Entries of an older control
 * list stay: the shader still on screen may use them until its successor compiles.
 * @param {Record<string, {value: any}>} uniforms
 * @param {import('../../shadertoy/controls.js').Control[]} controls
 * @param {Record<string, unknown>} values
 */
export function setControlUniforms(uniforms, controls, values) {
  for (const c of controls) {
    if (c.kind !== 'uniform') continue;
    uniforms[c.name] ??= { value: null };
    setControlUniform(uniforms, c.name, values[c.name]);
  }
}

/**
 * One live control's value into its uniform (none: not a live control).
 * @param {Record<string, {value: any}>} uniforms
 * @param {string} name
 * @param {unknown} value
 */
export function setControlUniform(uniforms, name, value) {
  const uniform = uniforms[name];
  if (!uniform) return;
  // three.js takes plain arrays for vecN; bools go in as ints
  uniform.value = Array.isArray(value) ? value.slice() : typeof value === 'boolean' ? Number(value) : value;
}
