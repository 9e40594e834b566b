// A shader as the page's files hold it: its tabs (Common, Buffer A–D, Cube A, Image, Sound) as the editor shows
// them, a text that may be a plain Image-tab shader or Shadertoy's JSON export, the text kept in
// the browser's storage, and the names of the files the page saves. Pure: no DOM here.

import { BUFFER_NAMES, bufferPassName, singlePass, validateModel } from '../../shadertoy/multipass.js';
import { fromShadertoyJson, toShadertoyJson } from '../../shadertoy/multipass-json.js';

/** @typedef {import('../../shadertoy/multipass.js').MultipassShader} MultipassShader */
/** @typedef {{name: string, code: string}} Tab */
/** @typedef {{model: MultipassShader, info: Record<string, any> | null, notes: string[]}} LoadedShader */

/**
 * Whether a model is a plain single-pass shader: no Common tab, no buffer (its Image tab is all).
 * @param {MultipassShader} model
 */
function isSinglePass(model) {
  return model.common === null && model.passes.every((p) => p.kind === 'image');
}

/**
 * The model's tabs in the editor's order: Common (if any), the buffers A–D it has, Cube A (if
 * any), Image, Sound (if any).
 * @param {MultipassShader} model
 * @returns {Tab[]}
 */
export function projectTabs(model) {
  /** @type {Tab[]} */
  const tabs = [];
  if (model.common !== null) tabs.push({ name: 'Common', code: model.common });
  for (const b of BUFFER_NAMES) {
    const pass = model.passes.find((p) => p.kind === 'buffer' && p.buffer === b);
    if (pass) tabs.push({ name: bufferPassName(b), code: pass.code });
  }
  const cube = model.passes.find((p) => p.kind === 'cubemap');
  if (cube) tabs.push({ name: cube.name, code: cube.code });
  const image = model.passes.find((p) => p.kind === 'image');
  if (image) tabs.push({ name: 'Image', code: image.code });
  const sound = model.passes.find((p) => p.kind === 'sound');
  if (sound) tabs.push({ name: 'Sound', code: sound.code });
  return tabs;
}

/**
 * One tab's text ('Common', 'Buffer A', 'Image', ...), or null when the model has no such tab.
 * @param {MultipassShader} model
 * @param {string} name
 */
export function tabCode(model, name) {
  return projectTabs(model).find((t) => t.name === name)?.code ?? null;
}

/**
 * The model with its tabs' texts replaced (the editor's edits); channels and the rest are kept.
 * @param {MultipassShader} model
 * @param {Record<string, string>} texts by tab name; a tab not named keeps its text
 * @returns {MultipassShader}
 */
export function withTabTexts(model, texts) {
  const text = (name, code) => (Object.hasOwn(texts, name) ? texts[name] : code);
  return {
    ...model,
    common: model.common === null ? null : text('Common', model.common),
    passes: model.passes.map((p) => ({ ...p, code: text(p.kind === 'image' ? 'Image' : p.name, p.code) })),
  };
}

/**
 * Whether a text is meant as JSON rather than GLSL (a shader's text never starts with a brace or
 * a bracket).
 * @param {string} text
 */
export const looksLikeJson = (text) => /^\s*[[{]/.test(text);

/**
 * Reads a shader's text: Shadertoy's JSON export (when it looks like JSON, or `json` says it is
 * one, as a .json file), else a plain Image-tab shader.
 * @param {string} text
 * @param {{json?: boolean}} [options]
 * @returns {LoadedShader}
 * @throws {Error} for JSON that is not a Shadertoy shader: "not a Shadertoy shader: <why>"
 */
export function readShaderText(text, { json = false } = {}) {
  if (!json && !looksLikeJson(text)) return { model: singlePass(text), info: null, notes: [] };
  try {
    return fromShadertoyJson(text);
  } catch (error) {
    const why = /^not (JSON|a Shadertoy shader)/.test(error.message) ? error.message : `not a Shadertoy shader: ${error.message}`;
    throw new Error(why, { cause: error });
  }
}

/** Whether a file name or URL names a JSON file. @param {string} name */
export const isJsonName = (name) => /\.json([?#].*)?$/i.test(name);

/**
 * Shadertoy's JSON export of a shader, as text (the "Export JSON" file, the share link's payload).
 * @param {MultipassShader} model
 * @param {Record<string, any> | null} info the `info` it came with; null: a minimal one named `name`
 * @param {string} name
 * @param {number} [indent] spaces per level (0: all on one line, as a link carries it)
 */
export function exportJson(model, info, name, indent = 2) {
  const json = JSON.stringify(toShadertoyJson(model, info ?? { name, description: '', tags: [] }), null, indent || undefined);
  return indent ? `${json}\n` : json;
}

/**
 * What the page cannot give a shader, in the words of the JSON loader: media its channels name
 * (kept in the model, so the notes follow the shader through edits).
 * @param {MultipassShader} model
 * @returns {string[]}
 */
function shaderNotes(model) {
  if (isPlain(model)) return [];
  try {
    return fromShadertoyJson(toShadertoyJson(model)).notes;
  } catch {
    return []; // a model the JSON cannot hold has nothing the loader would say
  }
}

/**
 * The lines of the page's note on what the shader on screen goes without: what its loader said
 * (app.notes) and what its model asks for that the page cannot give, each once, less the media
 * the media library gave it (and with why for what it could not: inputs/media-library.js).
 * and the files the page's channels could not load.
 * @param {{notes: string[], project: MultipassShader, media: {adjust: (lines: string[]) => string[]},
 *   channels: {failures: Array<string | null>}}} app
 */
export const missingLines = (app) => [
  ...app.media.adjust([...new Set([...app.notes, ...shaderNotes(app.project)])]),
  ...app.channels.failures.filter((line) => line !== null),
];

/** A plain single-pass shader: one Image tab, no channels, nothing else. @param {MultipassShader} model */
const isPlain = (model) =>
  isSinglePass(model) && !model.extra && model.passes.every((p) => !p.extra && p.channels.every((c) => c === null));

/**
 * A shader as one text, for the browser's storage and comparisons: a single-pass shader is its
 * code (as the page always kept it), a multipass one its model as JSON.
 * @param {MultipassShader} model
 */
export function serializeProject(model) {
  return isPlain(model) ? model.passes[0].code : JSON.stringify(model);
}

/**
 * The inverse of serializeProject. A text that is not a model's JSON is a single-pass shader.
 * @param {string} text
 * @returns {MultipassShader}
 */
export function deserializeProject(text) {
  if (looksLikeJson(text)) {
    try {
      const model = validateModel(JSON.parse(text));
      // kept before Cube A ran here, its cubemap pass rode in `extra` as the file had it: read again
      return model.extra?.unsupportedPasses ? fromShadertoyJson(toShadertoyJson(model)).model : model;
    } catch {
      // not a model: taken as it is
    }
  }
  return singlePass(text);
}
