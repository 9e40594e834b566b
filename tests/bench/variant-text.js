// What the benchmark scripts that take the shader apart (ablation.js, apart.js) share: the paste
// form of an edited shader text, and edits that must apply, so that a renamed function fails the
// script instead of timing the project twice.

import { composeImageShader, hostControlBlock } from '../../src/shadertoy/header.js';
import { parseControls } from '../../src/shadertoy/controls.js';

/**
 * A function from (shader text, compile-time controls) to the whole fragment shader in
 * Shadertoy's header, the live controls as constants with `source`'s defaults (the paste form);
 * one sample per pixel unless the controls say otherwise.
 * @param {string} source the project's shader, whose controls the host block declares
 */
export function pasteFormOf(source) {
  return formOf(source, true);
}

/** As pasteFormOf, but the live controls uniforms: the form the page compiles while a control moves. */
export function uniformFormOf(source) {
  return formOf(source, false);
}

/** @param {string} source @param {boolean} constants */
function formOf(source, constants) {
  const controls = parseControls(source);
  const defaults = Object.fromEntries(controls.map((c) => [c.name, c.default]));
  /** @param {string} text @param {Record<string, number>} [defines] */
  return (text, defines = {}) =>
    composeImageShader(text, {
      hostBlock: hostControlBlock(controls, { SAMPLES: 1, ADAPTIVE_AA: 0, ...defines }, constants ? defaults : null),
    }).code;
}

/** `text` with `from` replaced by `to`, which must occur exactly once. */
export function edit(text, from, to) {
  const at = text.indexOf(from);
  if (at < 0 || text.indexOf(from, at + 1) >= 0) throw new Error(`benchmark: "${from}" is not in the shader exactly once`);
  return text.slice(0, at) + to + text.slice(at + from.length);
}
