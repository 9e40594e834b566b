// The values of a shader's controls on the page: carried over when the shader changes, changes
// read (from the panel, the URL, the hook) against the control list, and the values a
// shared link must hold.

import { choiceValue, coerceControlValue, controlDefaults, projectControls } from '../../shadertoy/controls.js';

/** @typedef {import('../../shadertoy/controls.js').Control} Control */

/**
 * A new shader's controls (its control blocks, one per tab at most) and their values, carried
 * over from the old list where they survive; `notice` says why the blocks could not be read (the
 * shader then runs with its own defaults and no controls).
 * @param {import('../../shadertoy/multipass.js').MultipassShader} project
 * @param {Control[]} oldControls
 * @param {Record<string, unknown>} oldValues
 * @returns {{controls: Control[], values: Record<string, unknown>, notice: string | null}}
 */
export function controlsOf(project, oldControls, oldValues) {
  /** @type {Control[]} */
  let controls = [];
  let notice = null;
  try {
    controls = projectControls(project);
  } catch (error) {
    notice = `${error.message}\nThe shader runs with its own defaults and no panel controls.`;
  }
  return { controls, values: carriedOverValues(controls, oldControls, oldValues), notice };
}

/**
 * The values for a new control list: the defaults, except where a control of the same name and
 * type was there before, whose value is kept (brought into the new range).
 * @param {Control[]} controls the new list
 * @param {Control[]} oldControls
 * @param {Record<string, unknown>} oldValues
 * @returns {Record<string, unknown>}
 */
function carriedOverValues(controls, oldControls, oldValues) {
  const values = controlDefaults(controls);
  for (const c of controls) {
    const old = oldControls.find((o) => o.name === c.name && o.type === c.type);
    const kept = old ? coerceControlValue(c, oldValues[c.name]) : undefined;
    if (kept !== undefined) values[c.name] = kept;
  }
  return values;
}

/**
 * Reads changes ({NAME: value}; vectors as arrays or "x,y,z") against the controls, coerced into
 * range. Unknown names and unreadable values are left out; a value written as text and brought
 * into range is kept. Each of those is said in `warnings`: what was used instead, and why.
 * @param {Control[]} controls
 * @param {Record<string, unknown>} changes
 * @param {string} from who asks, in the warnings
 * @returns {{read: Array<{control: Control, value: unknown}>, warnings: string[]}}
 */
export function readControlChanges(controls, changes, from) {
  const read = [];
  const warnings = [];
  for (const [name, raw] of Object.entries(changes)) {
    const control = controls.find((c) => c.name === name);
    if (!control) {
      warnings.push(`${from}: ${name} ignored: the shader has no control of that name.`);
      continue;
    }
    const value = coerceControlValue(control, raw);
    const shown = (v) => (Array.isArray(v) ? v.join(',') : String(v));
    if (value === undefined) {
      // a choice is named as the panel names it; anything else by the type the shader declares
      const wanted = control.options ? `one of ${control.options.map((o) => o.label).join(', ')}` : `a valid ${control.type}`;
      warnings.push(`${from}: ${name}=${shown(raw)} ignored: not ${wanted}; the shader's value ${shown(control.default)} is used.`);
      continue;
    }
    const why = typeof raw === 'string' || control.atMost ? adjusted(control, raw, value) : null;
    if (why) warnings.push(`${from}: ${name}=${shown(raw)} ${why}: using ${shown(value)}.`);
    read.push({ control, value });
  }
  return { read, warnings };
}

/**
 * Why a value as written was not used as it is ("is out of range", "is not a whole number", ...),
 * or null when it was (a choice given by its name is).
 * @param {Control} control
 * @param {unknown} raw the value as written (text from the URL, or a number or array)
 * @param {any} value what coerceControlValue made of it
 * @returns {string | null}
 */
function adjusted(control, raw, value) {
  if (typeof value === 'boolean') return null;
  if (control.options && typeof raw === 'string' && choiceValue(control, raw) !== undefined) return null;
  const parts = (Array.isArray(raw) ? raw : String(raw).split(',')).map(Number);
  const used = Array.isArray(value) ? value : [value];
  for (const [i, written] of parts.entries()) {
    if (written === used[i]) continue;
    const range = control.components?.[i] ?? control;
    const component = control.components?.[i] ? `${control.components[i].name} ` : '';
    if (control.options) return `is not one of ${control.options.map((o) => o.label).join(', ')}`;
    if (range.min !== undefined && (written < range.min || written > /** @type {number} */ (range.max)))
      return `is out of range (${component}${range.min} .. ${range.max})`;
    if (control.type === 'int') return 'is not a whole number';
    if (control.atMost?.component === i) {
      const bound = /** @type {Array<{name: string}>} */ (control.components)[control.atMost.bound].name;
      return `has ${component}${written} above ${bound} ${used[control.atMost.bound]} (${component.trim()} <= ${bound})`;
    }
  }
  return null;
}

/**
 * The values that differ from the controls' defaults (what a shared link holds).
 * @param {Control[]} controls
 * @param {Record<string, unknown>} values
 * @returns {Record<string, unknown>}
 */
function changedValues(controls, values) {
  const defaults = controlDefaults(controls);
  return Object.fromEntries(Object.entries(values).filter(([name, v]) => JSON.stringify(v) !== JSON.stringify(defaults[name])));
}

/**
 * changedValues as a link writes them: a choice that has a name by it (SCENE=Torus, VIEW=Normals),
 * which reads better than its number and which the page reads back (coerceControlValue).
 * @param {Control[]} controls
 * @param {Record<string, unknown>} values
 * @returns {Record<string, unknown>}
 */
export function linkValues(controls, values) {
  const changed = changedValues(controls, values);
  for (const control of controls) {
    const option = control.options?.find((o) => o.value === changed[control.name]);
    if (option && option.label !== String(option.value)) changed[control.name] = option.label;
  }
  return changed;
}
