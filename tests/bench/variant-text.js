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

/**
 * `text` with every all(bvecN(a, b, ...)) written (a && b && ...) and every any(bvecN(...)) as
 * (a || b || ...): the short-circuit forms the shader avoids (SwiftShader turns them into
 * branches). Nested ones are rewritten too.
 * @param {string} text
 */
export function branchyConditions(text) {
  const opening = /\b(all|any)\(bvec[234]\(/g;
  let out = '';
  let from = 0;
  for (let match = opening.exec(text); match; match = opening.exec(text)) {
    if (match.index < from) continue;
    const argsStart = match.index + match[0].length;
    const args = [];
    let depth = 0;
    let start = argsStart;
    let i = argsStart;
    for (; i < text.length; i++) {
      const ch = text[i];
      if (ch === '(') depth++;
      else if (ch === ')' && depth > 0) depth--;
      else if (ch === ')' || (ch === ',' && depth === 0)) {
        args.push(text.slice(start, i).trim());
        start = i + 1;
        if (ch === ')') break;
      }
    }
    if (text[i + 1] !== ')') throw new Error(`benchmark: ${match[0]} at ${match.index} is not closed as all(bvecN(...))`);
    const joined = args.map((arg) => branchyConditions(arg)).join(match[1] === 'all' ? ' && ' : ' || ');
    out += `${text.slice(from, match.index)}(${joined})`;
    from = i + 2;
  }
  return out + text.slice(from);
}
