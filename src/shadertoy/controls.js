// The control block: a shader's tunables, declared once, in the shader.
//
// A shader may hold one block of the form
//
//   #ifndef HOST_CONTROLS
//   #define BOUNCES 3                          // ui: Bounce limit | 0 .. 4
//   #define SHADOWS 1                          // ui: Shadows | toggle
//   #define TEXTURE 0                          // ui: Ground texture | Stripes, Checkerboard
//   #define SAMPLES 1                          // ui: Samples per pixel | 1, 4, 9, 16
//   const float CONE_HEIGHT = 1.8;             // ui: Cone height | 0.1 .. 4 step 0.01
//   const vec3  LIGHT_POSITION = vec3(4, 6, 3); // ui: Light position | -10 .. 10
//   #endif
//
// Shadertoy, which knows nothing of hosts, compiles the block as it stands: the values are the
// defaults. A host defines HOST_CONTROLS and declares the same names itself (composeImageShader
// in shadertoy.js): a `#define` control is compile-time (the host re-defines it and recompiles
// when it changes, so a feature switched off costs nothing), a `const` control becomes a uniform
// that changes without recompiling.
//
// After `// ui:` comes the label, then `|` and the range: `min .. max` (optionally `step s`),
// `toggle` (0 or 1), or a comma list of choices (numbers are the values themselves; words are
// labels whose values are 0, 1, 2, ...). A vector may name each component and give it a range
// of its own: `// ui: Camera orbit (deg) | azimuth -180 .. 180, elevation -89 .. 90`.
//
// A third `|` part may say when the control matters, or bound one component by another:
//   `| when SCENE = Cone`            shown only while SCENE (a control above it) is Cone;
//   `| when SCENE = Cone, Cylinder`  ... is one of these;
//   `| minor <= major`               a vector's named component kept at most another (a host
//                                    clamps it, and says so, as the shader itself would);
//   `| when SCENE = Torus; minor <= major`  both.
// Shadertoy never reads any of it: it is a comment.

import { HOST_CONTROLS_MACRO } from './header.js';

const VECTOR_SIZES = { float: 1, int: 1, bool: 1, vec2: 2, vec3: 3, vec4: 4 };
const NUMBER = String.raw`[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?`;
const DEFINE_LINE = new RegExp(String.raw`^\s*#define\s+([A-Za-z_]\w*)\s+(${NUMBER})\s*//\s*ui:\s*(.*)$`);
const CONST_LINE = new RegExp(String.raw`^\s*const\s+(float|int|bool|vec2|vec3|vec4)\s+([A-Za-z_]\w*)\s*=\s*([^;]+);\s*//\s*ui:\s*(.*)$`);

/**
 * One control of a control block, as parseControls returns it.
 * @typedef {object} Control
 * @property {string} name the GLSL name
 * @property {'define' | 'uniform'} kind `#define` (compile-time) or `const` (a uniform in a host)
 * @property {'float' | 'int' | 'bool' | 'vec2' | 'vec3' | 'vec4'} type
 * @property {any} default the value in the shader: a number, a boolean, or an array of numbers
 * @property {string} label
 * @property {number} [min]
 * @property {number} [max]
 * @property {number} [step]
 * @property {boolean} [toggle] shown as a checkbox (0 or 1)
 * @property {Array<{label: string, value: number}>} [options] a list of choices
 * @property {Array<{name: string, min: number, max: number, step?: number}>} [components] a
 *   vector's components, each named and with a range of its own
 * @property {number} [line] the 1-based line of the shader that declares it
 * @property {{name: string, choices: string[], values: number[]}} [when] shown only while the
 *   control `name` has one of these values (`| when NAME = Choice`)
 * @property {{component: number, bound: number}} [atMost] component `component` is kept at
 *   most component `bound` (`| a <= b`)
 */

export class ControlBlockError extends Error {
  constructor(message, line) {
    super(line ? `${message} (shader line ${line})` : message);
    this.name = 'ControlBlockError';
    this.line = line;
  }
}

function parseNumber(text, line) {
  const value = Number(text.trim());
  if (!Number.isFinite(value)) throw new ControlBlockError(`"${text.trim()}" is not a number`, line);
  return value;
}

function parseValue(type, text, line) {
  text = text.trim();
  if (type === 'bool') {
    if (text !== 'true' && text !== 'false') throw new ControlBlockError(`bool default must be true or false, not "${text}"`, line);
    return text === 'true';
  }
  const size = VECTOR_SIZES[type];
  if (size === 1) return parseNumber(text, line);
  const match = text.match(new RegExp(String.raw`^${type}\s*\((.*)\)$`));
  if (!match) throw new ControlBlockError(`${type} default must be written ${type}(...), not "${text}"`, line);
  const parts = match[1].split(',').map((p) => parseNumber(p, line));
  if (parts.length === 1) return Array(size).fill(parts[0]);
  if (parts.length !== size) throw new ControlBlockError(`${type} default needs ${size} components`, line);
  return parts;
}

const RANGE = String.raw`(${NUMBER})\s*\.\.\s*(${NUMBER})(?:\s+step\s+(${NUMBER}))?`;

/** A `min .. max [step s]` range, or null. */
function parseRange(spec, line) {
  const range = spec.match(new RegExp(`^${RANGE}$`));
  if (!range) return null;
  const min = Number(range[1]);
  const max = Number(range[2]);
  if (!(min < max)) throw new ControlBlockError(`range ${spec} is empty`, line);
  return { min, max, ...(range[3] !== undefined ? { step: Number(range[3]) } : {}) };
}

/**
 * Parses the `label | range | clause` annotation after `// ui:` (the clause: parseClause).
 * @param {string} text
 * @param {number} line
 * @param {number} size how many components the control has
 */
function parseAnnotation(text, line, size) {
  const [labelText, specText = '', clauseText, ...extra] = text.split('|');
  if (extra.length) throw new ControlBlockError(`more than three "|" parts in "${text.trim()}"`, line);
  const label = labelText.trim();
  const spec = specText.trim();
  if (!label) throw new ControlBlockError('control has no label after "// ui:"', line);
  const ranged = parseSpec(label, spec, line, size);
  if (clauseText === undefined) return ranged;
  return Object.assign({ ...ranged }, ...clauseText.split(';').map((clause) => parseClause(clause.trim(), ranged, line)));
}

/** The range part of an annotation. */
function parseSpec(label, spec, line, size) {
  if (spec === '') return { label };
  if (spec === 'toggle') return { label, toggle: true, min: 0, max: 1, step: 1 };
  const range = parseRange(spec, line);
  if (range) return { label, ...range };
  const items = spec.split(',').map((s) => s.trim());
  const named = items.map((item) => item.match(/^([A-Za-z]\w*)\s+(.+)$/));
  if (size > 1 && named.every((m) => m && parseRange(m[2], line))) {
    if (items.length !== size) throw new ControlBlockError(`${items.length} named ranges for ${size} components`, line);
    return { label, components: named.map((m) => ({ name: m[1], ...parseRange(m[2], line) })) };
  }
  if (items.length < 2 || items.some((s) => s === '')) throw new ControlBlockError(`cannot read range "${spec}"`, line);
  const numeric = items.every((s) => new RegExp(`^${NUMBER}$`).test(s));
  const options = items.map((s, i) => ({ label: s, value: numeric ? Number(s) : i }));
  return { label, options };
}

/**
 * The third part of an annotation: `when NAME = Choice[, Choice]` (the choices are resolved in
 * parseControls, once every control is known), or `a <= b` between two named components.
 * @param {string} clause
 * @param {{components?: Array<{name: string}>}} ranged the control so far
 * @param {number} line
 */
function parseClause(clause, ranged, line) {
  const when = clause.match(/^when\s+([A-Za-z_]\w*)\s*=\s*(.+)$/);
  if (when) return { when: { name: when[1], choices: when[2].split(',').map((c) => c.trim()), values: [] } };
  const bound = clause.match(/^([A-Za-z]\w*)\s*<=\s*([A-Za-z]\w*)$/);
  if (bound) {
    const index = (name) => {
      const i = ranged.components?.findIndex((c) => c.name === name) ?? -1;
      if (i < 0) throw new ControlBlockError(`"${clause}": ${name} is not a named component of this control`, line);
      return i;
    };
    return { atMost: { component: index(bound[1]), bound: index(bound[2]) } };
  }
  throw new ControlBlockError(`cannot read "${clause}"; expected "when NAME = Choice" or "a <= b"`, line);
}

/**
 * Resolves each `when` to the values of the control it names (declared before it).
 * @param {Control[]} controls
 */
function resolveWhen(controls) {
  controls.forEach((control, i) => {
    if (!control.when) return;
    const { name, choices } = control.when;
    const other = controls.slice(0, i).find((c) => c.name === name);
    if (!other) throw new ControlBlockError(`"when ${name} = ...": no control ${name} is declared above ${control.name}`, control.line);
    control.when.values = choices.map((choice) => {
      const value = choiceValue(other, choice);
      if (value === undefined) throw new ControlBlockError(`"when ${name} = ${choice}": ${name} has no choice ${choice}`, control.line);
      return value;
    });
  });
}

/**
 * The value of one of a control's choices, by its label (any case) or by its number; undefined
 * when it has no such choice.
 * @param {Control} control
 * @param {string} text
 */
export function choiceValue(control, text) {
  const wanted = text.trim().toLowerCase();
  const option = control.options?.find((o) => o.label.toLowerCase() === wanted);
  if (option) return option.value;
  const n = Number(wanted);
  return wanted !== '' && control.options?.some((o) => o.value === n) ? n : undefined;
}

/**
 * Whether a control matters with these values (its `when`, if any, holds).
 * @param {Control} control
 * @param {Record<string, unknown>} values
 */
export function controlApplies(control, values) {
  return !control.when || control.when.values.includes(/** @type {number} */ (values[control.when.name]));
}

/**
 * Finds the control block (the `#ifndef HOST_CONTROLS` ... `#endif` section) and returns one
 * descriptor per control, in order:
 *   { name, kind: 'define'|'uniform', type, default, label, min?, max?, step?, toggle?, options?, line }
 * A shader without a block has no controls. Lines in the block without `// ui:` are left alone
 * (helper macros, comments).
 * @param {string} source
 * @returns {Control[]}
 */
export function parseControls(source) {
  const lines = source.split('\n');
  const start = lines.findIndex((l) => new RegExp(String.raw`^\s*#ifndef\s+${HOST_CONTROLS_MACRO}\b`).test(l));
  if (start < 0) return [];
  const controls = [];
  const names = new Set();
  let depth = 1;
  for (let i = start + 1; i < lines.length; i++) {
    const text = lines[i];
    const lineNo = i + 1;
    if (/^\s*#\s*if/.test(text)) depth++;
    if (/^\s*#\s*endif/.test(text) && --depth === 0) {
      resolveWhen(controls);
      return controls;
    }
    if (!/\/\/\s*ui:/.test(text)) continue;
    /** @type {Control} */
    let control;
    const define = text.match(DEFINE_LINE);
    const constant = text.match(CONST_LINE);
    if (define) {
      const value = Number(define[2]);
      const isInt = /^[-+]?\d+$/.test(define[2]);
      control = {
        name: define[1],
        kind: 'define',
        type: isInt ? 'int' : 'float',
        default: value,
        ...parseAnnotation(define[3], lineNo, 1),
      };
    } else if (constant) {
      const [, type, name, value, annotation] = constant;
      control = {
        name,
        kind: 'uniform',
        type: /** @type {Control['type']} */ (type),
        default: parseValue(type, value, lineNo),
        ...parseAnnotation(annotation, lineNo, VECTOR_SIZES[type]),
      };
    } else {
      throw new ControlBlockError(
        `cannot read control line "${text.trim()}"; expected "#define NAME number // ui: ..." or "const TYPE NAME = value; // ui: ..."`,
        lineNo,
      );
    }
    if (names.has(control.name)) throw new ControlBlockError(`control ${control.name} is declared twice`, lineNo);
    if (control.type === 'int' && control.step === undefined && !control.options) control.step = 1;
    names.add(control.name);
    controls.push({ ...control, line: lineNo });
  }
  throw new ControlBlockError(`#ifndef ${HOST_CONTROLS_MACRO} has no matching #endif`, start + 1);
}

/**
 * The defaults of a control list, as { name: value }.
 * @param {Control[]} controls
 * @returns {Record<string, any>}
 */
export function controlDefaults(controls) {
  return Object.fromEntries(controls.map((c) => [c.name, c.default]));
}

/**
 * Brings a value for a control into its type and range: numbers are clamped, ints rounded,
 * choices snapped to a listed value. Returns undefined for a value that cannot be read
 * (the caller keeps the default and warns).
 * @param {Control} control
 * @param {unknown} value
 * @returns {any} a number, a boolean, an array of numbers, or undefined
 */
export function coerceControlValue(control, value) {
  const size = VECTOR_SIZES[control.type];
  /** @param {unknown} v @param {{min?: number, max?: number}} range */
  const one = (v, range = control) => {
    if (control.type === 'bool') {
      if (v === true || v === 'true' || v === 1 || v === '1') return true;
      if (v === false || v === 'false' || v === 0 || v === '0') return false;
      return undefined;
    }
    if (control.options && typeof v === 'string') {
      const chosen = choiceValue(control, v);
      if (chosen !== undefined) return chosen;
    }
    let n = typeof v === 'number' ? v : Number(String(v).trim());
    if (String(v).trim() === '' || !Number.isFinite(n)) return undefined;
    if (control.options) {
      const values = control.options.map((o) => o.value);
      return values.reduce((best, x) => (Math.abs(x - n) < Math.abs(best - n) ? x : best), values[0]);
    }
    // a range has both ends or neither (parseRange)
    if (range.min !== undefined && range.max !== undefined) n = Math.min(range.max, Math.max(range.min, n));
    if (control.type === 'int') n = Math.round(n);
    return n;
  };
  if (size === 1) return one(Array.isArray(value) ? value[0] : value);
  const parts = Array.isArray(value) ? value : String(value).split(',');
  if (parts.length !== size) return undefined;
  const out = parts.map((v, i) => one(v, control.components?.[i] ?? control));
  if (out.some((v) => v === undefined)) return undefined;
  const { atMost } = control;
  if (atMost) out[atMost.component] = Math.min(Number(out[atMost.component]), Number(out[atMost.bound]));
  return out;
}

const PLAIN_CONST_LINE = /^const\s+(float|int|vec2|vec3|vec4)\s+([A-Za-z_]\w*)\s*=\s*([^;]+);/;

/**
 * The shader's other named values: every top-level `const TYPE NAME = literal;` line outside the
 * control block (materials, shading constants). Lets a port of the shader (the float64
 * reference) read them instead of keeping copies. Lines whose value is an expression rather
 * than a literal are skipped.
 * @param {string} source
 * @returns {Record<string, number | number[]>}
 */
export function parseConstants(source) {
  /** @type {Record<string, number | number[]>} */
  const constants = {};
  source.split('\n').forEach((text, i) => {
    const match = text.match(PLAIN_CONST_LINE);
    if (!match || /\/\/\s*ui:/.test(text)) return;
    try {
      constants[match[2]] = parseValue(match[1], match[3], i + 1);
    } catch {
      // an expression such as PI / 180.0: not a literal, not needed by ports
    }
  });
  return constants;
}

/**
 * A shader's controls: those of its Common tab and of each pass, the first of each name. Throws
 * when a control block cannot be read.
 * @param {import('./multipass.js').MultipassShader} project
 * @returns {Control[]}
 */
export function projectControls(project) {
  /** @type {Control[]} */
  const controls = [];
  for (const text of [project.common ?? '', ...project.passes.map((pass) => pass.code)])
    for (const control of parseControls(text)) if (!controls.some((c) => c.name === control.name)) controls.push(control);
  return controls;
}
