// The values of a shader's controls on the page: carried over when the shader changes, changes
// read (from the panel, the URL, the automation hook) against the control list, and the values a
// shared link must hold.

import { coerceControlValue, controlDefaults } from '../../shadertoy/controls.js';

/** @typedef {import('../../shadertoy/controls.js').Control} Control */

/**
 * The values for a new control list: the defaults, except where a control of the same name and
 * type was there before, whose value is kept (brought into the new range).
 * @param {Control[]} controls the new list
 * @param {Control[]} oldControls
 * @param {Record<string, unknown>} oldValues
 * @returns {Record<string, unknown>}
 */
export function carriedOverValues(controls, oldControls, oldValues) {
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
      warnings.push(
        `${from}: ${name}=${shown(raw)} ignored: not a valid ${control.type}; the shader's value ${shown(control.default)} is used.`,
      );
      continue;
    }
    if (typeof raw === 'string' && typeof value !== 'boolean') {
      const written = Array.isArray(value) ? raw.split(',').map(Number) : Number(raw);
      if (JSON.stringify(written) !== JSON.stringify(value))
        warnings.push(`${from}: ${name}=${raw} is out of range: using ${shown(value)}.`);
    }
    read.push({ control, value });
  }
  return { read, warnings };
}

/**
 * The values that differ from the controls' defaults (what a shared link holds).
 * @param {Control[]} controls
 * @param {Record<string, unknown>} values
 * @returns {Record<string, unknown>}
 */
export function changedValues(controls, values) {
  const defaults = controlDefaults(controls);
  return Object.fromEntries(Object.entries(values).filter(([name, v]) => JSON.stringify(v) !== JSON.stringify(defaults[name])));
}
