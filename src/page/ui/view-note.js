// What a debug view shows when it shows nothing: the raytracer's "Extra samples" view marks the
// pixels that took adaptive anti-aliasing's extra samples, so with ADAPTIVE_AA off (uniform
// supersampling: every pixel takes the grid) or SAMPLES at 1 (no pixel takes more than one) it
// marks none, and would look like a picture with no edges found. A line at the bottom of the
// canvas says which it is, while that view is on.

import { extraSamplesValues } from '../../shadertoy/extra-samples.js';
import { element } from './dom.js';

/** @typedef {import('../app/app.js').RaytracerApp} RaytracerApp */

/**
 * Why the "Extra samples" view marks no pixel, or null (another view, or it marks them).
 * @param {Array<{name: string, label: string, options?: Array<{label: string, value: number}>}>} controls
 * @param {Record<string, any>} values
 */
export function extraSamplesViewNote(controls, values) {
  const view = extraSamplesValues(controls);
  if (!view || values.VIEW !== view.VIEW) return null;
  const label = (name, fallback) => controls.find((c) => c.name === name)?.label ?? fallback;
  const samples = values.SAMPLES;
  if (samples === undefined) return null;
  if (!(samples > 1))
    return `"Extra samples" view: ${label('SAMPLES', 'SAMPLES')} is 1, so no pixel takes extra samples and none is marked.`;
  if (values.ADAPTIVE_AA === undefined || values.ADAPTIVE_AA) return null;
  return `"Extra samples" view: ${label('ADAPTIVE_AA', 'ADAPTIVE_AA')} is off, so every pixel takes all ${samples} samples (uniform supersampling) and none is marked.`;
}

/**
 * Shows the note over the canvas while it applies.
 * @param {RaytracerApp} app
 * @param {HTMLElement} stage
 */
export function installViewNote(app, stage) {
  const note = element('p', { class: 'view-note', role: 'status', hidden: true });
  stage.append(note);
  const update = () => {
    const text = extraSamplesViewNote(app.controls, app.values);
    note.hidden = text === null;
    if (text !== null && note.textContent !== text) note.textContent = text;
  };
  app.on('state', update);
  app.on('source', update);
  update();
  return note;
}
