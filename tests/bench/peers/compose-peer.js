// Builds a benchmark peer shader from the project's shader and a peer file.
//
// A peer (tests/bench/peers/*.glsl) holds only what differs from the project: replacement
// definitions for some of the project's top-level functions (or structs), plus helpers of its own.
// Everything else (control block, camera and sample positions, materials, sky, shading, output
// transform) is the project's own text, so a peer cannot drift from the project's scene when the
// project changes its colours or camera.
//
// The peer says which definitions it replaces, in one or more comment lines:
//
//   // @replaces sceneRelativeTo traceScene radiance
//
// and composePeer checks, failing loudly:
// - each listed name is defined exactly once in the project and exactly once in the peer;
// - the peer defines no other name that the project also defines (an accidental collision, or a
//   replacement whose project function was renamed: it would silently stay the project's);
// - the peer's replacements come in the project's order (so that each helper can be placed
//   before the replacement it precedes in the peer, and still precede every later one);
// - every piece that is moved has balanced #if/#endif and braces.
//
// Placement: each replacement goes exactly where the project's definition was; the peer's text
// between the previous replacement and this one (comments, #defines, constants, helper
// functions) goes immediately before it. Text after the peer's last replacement goes right after
// it. A helper therefore lands inside any preprocessor conditional that surrounds the project
// definition it precedes (e.g. an `#if SHADOWS` around a shadow-ray function): put helpers that
// other code needs before an earlier replacement.

import { countNewlines } from '../../../src/shadertoy/header.js';

const DIRECTIVE = /^[ \t]*\/\/[ \t]*@replaces\b(.*)$/gm;
const IDENT = /^[A-Za-z_]\w*$/;

export class ComposePeerError extends Error {
  constructor(message) {
    super(`composePeer: ${message}`);
    this.name = 'ComposePeerError';
  }
}

/**
 * The top-level declarations of a GLSL source, skipping comments and preprocessor lines:
 *   { kind: 'function'|'struct'|'other', name, start, end }
 * start is the declaration's first code character, end the index after its closing `}` (a
 * function) or `;` (anything else). `name` is the function's or struct's name (null otherwise).
 * Function prototypes (`float f(float x);`) are kind 'other'.
 */
export function scanTopLevel(source, label = 'source') {
  const items = [];
  let depth = 0;
  let start = -1;
  let header = ''; // code text of the current declaration up to its first `{` (comments dropped)
  let lineStart = true;
  const lineOf = (index) => countNewlines(source, index) + 1;
  for (let i = 0; i < source.length;) {
    const c = source[i];
    if (c === '/' && source[i + 1] === '/') {
      while (i < source.length && source[i] !== '\n') i++;
      continue;
    }
    if (c === '/' && source[i + 1] === '*') {
      const close = source.indexOf('*/', i + 2);
      if (close < 0) throw new ComposePeerError(`${label}: unterminated /* comment at line ${lineOf(i)}`);
      i = close + 2;
      continue;
    }
    if (c === '\n') {
      lineStart = true;
      if (depth === 0 && start >= 0) header += ' ';
      i++;
      continue;
    }
    if (c === ' ' || c === '\t' || c === '\r' || c === '\f' || c === '\v') {
      if (depth === 0 && start >= 0) header += ' ';
      i++;
      continue;
    }
    if (c === '#' && lineStart) {
      // A preprocessor line, with backslash continuations; it holds no declaration boundaries.
      while (i < source.length && source[i] !== '\n') {
        if (source[i] === '\\' && source[i + 1] === '\n') i++;
        i++;
      }
      continue;
    }
    lineStart = false;
    if (depth === 0 && start < 0) {
      start = i;
      header = '';
    }
    if (c === '{') {
      depth++;
    } else if (c === '}') {
      depth--;
      if (depth < 0) throw new ComposePeerError(`${label}: unbalanced "}" at line ${lineOf(i)}`);
      if (depth === 0 && isFunctionHeader(header)) {
        items.push({ kind: 'function', name: functionName(header), start, end: i + 1 });
        start = -1;
      }
    } else if (c === ';' && depth === 0) {
      const struct = header.match(/^\s*struct\s+([A-Za-z_]\w*)/);
      items.push({ kind: struct ? 'struct' : 'other', name: struct ? struct[1] : null, start, end: i + 1 });
      start = -1;
    } else if (depth === 0) {
      header += c;
    }
    i++;
  }
  if (depth !== 0) throw new ComposePeerError(`${label}: ${depth} unclosed "{" at the end`);
  if (start >= 0) throw new ComposePeerError(`${label}: unterminated declaration at line ${lineOf(start)}`);
  return items;
}

function isFunctionHeader(header) {
  return header.includes('(') && !/^\s*struct\b/.test(header) && !/=/.test(header.slice(0, header.indexOf('(')));
}

function functionName(header) {
  const match = header.slice(0, header.indexOf('(')).match(/([A-Za-z_]\w*)\s*$/);
  return match ? match[1] : null;
}

/** The names listed in the peer's `// @replaces` lines, in the order written. */
export function replacedNames(peerSource) {
  const names = [];
  for (const match of peerSource.matchAll(DIRECTIVE)) {
    for (const name of match[1]
      .trim()
      .split(/[\s,]+/)
      .filter(Boolean)) {
      if (!IDENT.test(name)) throw new ComposePeerError(`"${name}" in an @replaces line is not a GLSL name`);
      if (names.includes(name)) throw new ComposePeerError(`${name} is listed twice in @replaces`);
      names.push(name);
    }
  }
  return names;
}

/** Throws unless #if/#ifdef/#ifndef and #endif balance in `text`, and never go below zero. */
function checkConditionals(text, what) {
  let depth = 0;
  for (const line of text.split('\n')) {
    if (/^\s*#\s*if(n?def)?\b/.test(line)) depth++;
    else if (/^\s*#\s*endif\b/.test(line)) depth--;
    if (depth < 0) throw new ComposePeerError(`${what} has an #endif without its #if`);
  }
  if (depth !== 0) throw new ComposePeerError(`${what} has an #if without its #endif`);
}

function definitionsByName(items) {
  const byName = new Map();
  for (const item of items) {
    if (item.kind === 'other' || !item.name) continue;
    if (!byName.has(item.name)) byName.set(item.name, []);
    byName.get(item.name).push(item);
  }
  return byName;
}

/**
 * The project's shader with the peer's replacements spliced in (see the file comment).
 * @param {string} projectSource shaders/raytrace.glsl
 * @param {string} peerSource a peer file
 * @param {{peerName?: string}} [options] name used in messages and in the banner comments
 * @returns {string} an Image-tab source, for composeImageShader
 */
export function composePeer(projectSource, peerSource, { peerName = 'peer' } = {}) {
  const names = replacedNames(peerSource);
  if (names.length === 0) throw new ComposePeerError(`${peerName} has no "// @replaces name ..." line`);
  const projectDefs = definitionsByName(scanTopLevel(projectSource, 'project'));
  const peerDefs = definitionsByName(scanTopLevel(peerSource, peerName));

  for (const name of names) {
    const inProject = projectDefs.get(name) ?? [];
    const inPeer = peerDefs.get(name) ?? [];
    if (inProject.length === 0) throw new ComposePeerError(`${peerName} replaces ${name}, which the project does not define (renamed?)`);
    if (inProject.length > 1)
      throw new ComposePeerError(`the project defines ${name} ${inProject.length} times (overloads); cannot tell which to replace`);
    if (inPeer.length === 0) throw new ComposePeerError(`${peerName} lists ${name} in @replaces but does not define it`);
    if (inPeer.length > 1) throw new ComposePeerError(`${peerName} defines ${name} ${inPeer.length} times`);
  }
  for (const [name, defs] of peerDefs) {
    if (names.includes(name)) continue;
    if (defs.length > 1) throw new ComposePeerError(`${peerName} defines ${name} ${defs.length} times`);
    if (projectDefs.has(name)) {
      throw new ComposePeerError(`${peerName} defines ${name}, which the project also defines; list it in @replaces or rename it`);
    }
  }

  const replacements = names
    .map((name) => ({ name, project: projectDefs.get(name)[0], peer: peerDefs.get(name)[0] }))
    .sort((a, b) => a.project.start - b.project.start);
  for (let k = 1; k < replacements.length; k++) {
    if (replacements[k].peer.start < replacements[k - 1].peer.start) {
      throw new ComposePeerError(
        `${peerName} defines ${replacements[k].name} before ${replacements[k - 1].name}; ` +
          `the project has them the other way round (keep the project's order)`,
      );
    }
  }

  let out = '';
  let projectPos = 0;
  let peerPos = 0;
  replacements.forEach(({ name, project, peer }, k) => {
    const replaced = projectSource.slice(project.start, project.end);
    checkConditionals(replaced, `the project's ${name}`);
    const helpers = peerSource.slice(peerPos, peer.start);
    checkConditionals(helpers, `${peerName}'s text before ${name}`);
    const definition = peerSource.slice(peer.start, peer.end);
    checkConditionals(definition, `${peerName}'s ${name}`);
    out += projectSource.slice(projectPos, project.start);
    out += `// ---- ${peerName}: replaces the project's ${name} ----\n`;
    out += helpers.replace(/^\s*\n/, '');
    out += definition;
    peerPos = peer.end;
    projectPos = project.end;
    if (k === replacements.length - 1) {
      const trailing = peerSource.slice(peerPos);
      checkConditionals(trailing, `${peerName}'s text after ${name}`);
      if (trailing.trim() !== '') out += '\n' + trailing.replace(/\s+$/, '');
    }
  });
  out += projectSource.slice(projectPos);
  return out;
}
