// Shadertoy's JSON format (what its API returns and its exports hold) to the multipass model of
// multipass.js and back.
//
// The format, as the site's player reads it (https://www.shadertoy.com/js/effect.js,
// Effect.newScriptJSON) and as its exports show it: `{Shader: {ver, info, renderpass: [...]}}`;
// each render pass has `name`, `type` ("image", "buffer", "common", "sound", "cubemap"), `code`,
// `description`, `inputs[]` and `outputs[]`. An input has `channel` (0..3), `type`, `id`,
// `filepath`, `previewfilepath`, `published` and `sampler` {filter, wrap, vflip, srgb, internal}
// with every sampler value a string ("true"/"false" for the flags). The player names a buffer
// pass from its output id, not from its `name` ("Buffer " + letter). Ids are the site's asset
// ids: Buffer A–D '4dXGR8', 'XsXGR8', '4sXGR8', 'XdfGR8', the keyboard '4dXGRr', the Image
// output '4dfGRr'. Older exports (and the API before 2019) write `ctype` for `type`, `src` for
// `filepath`, and numbers for ids: buffers 257–260, the keyboard 33, the Image output 37
// (github.com/vilya/Shadertron, doc/ShaderToyJSONNotes.md and its samples). Both are read; a
// file is written back in the style it came in, a new one in the site's current style.
//
// Lossless: fromShadertoyJson(toShadertoyJson(model)).model equals model, and fields the model
// does not hold (descriptions, `published`, `srgb`, `internal`, a media input's id, unknown keys)
// ride along in `extra` and are written back. The Sound tab is a pass of kind 'sound' (sound.js
// renders it); the Cube A pass (type "cubemap", output id '4dX3Rr', or 41 in the older style) one
// of kind 'cubemap', and an input reading it (type "cubemap" with that id, its file the site's
// '/media/previz/cubemap00.png') a channel of kind 'cubebuffer' (cube-a.js).

import { BUFFER_NAMES, DEFAULT_SAMPLER, MultipassError, bufferPassName, unsupportedNote, validateModel } from './multipass.js';
import { CUBE_A_FILE, CUBE_A_ID, CUBE_A_LEGACY_ID, CUBE_A_NAME } from './cube-a.js';
import { jsonSyntaxError } from '../shared/json-syntax.js';

const SITE_IDS = { A: '4dXGR8', B: 'XsXGR8', C: '4sXGR8', D: 'XdfGR8', keyboard: '4dXGRr', image: '4dfGRr', cube: CUBE_A_ID };
const LEGACY_IDS = { A: 257, B: 258, C: 259, D: 260, keyboard: 33, image: 37, cube: CUBE_A_LEGACY_ID };
const BUFFER_FILE = (/** @type {string} */ b) => `/media/previz/buffer0${BUFFER_NAMES.indexOf(/** @type {any} */ (b))}.png`;
const KEYBOARD_FILE = '/presets/tex00.jpg';
const MEDIA_TYPES = ['texture', 'cubemap', 'volume', 'video', 'webcam', 'music', 'musicstream', 'mic'];

/**
 * How a file writes ids and keys: the site's current style or the older one.
 * @typedef {{ids: 'site' | 'legacy', typeKey: 'type' | 'ctype', srcKey: 'filepath' | 'src'}} Style
 */
const SITE_STYLE = Object.freeze({ ids: 'site', typeKey: 'type', srcKey: 'filepath' });

/**
 * Reads a shader in Shadertoy's JSON format.
 * @param {string | object} json the text or the parsed value: `{Shader: {info, renderpass}}`,
 *   `{info, renderpass}`, or an array of one of those (as the API's batch answers)
 * @returns {{model: import('./multipass.js').MultipassShader, info: Record<string, any>, notes: string[]}}
 *   notes: what the page will not do (media it cannot have)
 * @throws {MultipassError} for a file that is not a shader, naming the pass at fault
 */
export function fromShadertoyJson(json) {
  let value = json;
  if (typeof value === 'string') {
    try {
      value = JSON.parse(value);
    } catch (error) {
      throw new MultipassError(`not JSON: ${jsonSyntaxError(value) ?? String(error.message).replace(/\s*\n\s*/g, ' ')}`);
    }
  }
  if (Array.isArray(value)) {
    if (value.length !== 1) throw new MultipassError(`expected one shader, the file holds ${value.length}`);
    value = value[0];
  }
  const shader = value && typeof value === 'object' && 'Shader' in value ? value.Shader : value;
  if (!shader || typeof shader !== 'object' || !Array.isArray(shader.renderpass)) {
    throw new MultipassError('not a Shadertoy shader: no "renderpass" list (expected {"Shader": {"info": ..., "renderpass": [...]}})');
  }
  const style = detectStyle(shader.renderpass);
  const notes = [];
  /** @type {import('./multipass.js').MultipassShader} */
  const model = { common: null, passes: [] };
  const extra = {};
  shader.renderpass.forEach((raw, index) => {
    const where = typeof raw?.name === 'string' && raw.name ? raw.name : `render pass ${index + 1}`;
    if (!raw || typeof raw !== 'object') throw new MultipassError(`${where}: not an object`);
    if (typeof raw.code !== 'string') throw new MultipassError(`${where}: has no code`);
    if (raw.type === 'common') {
      if (model.common !== null) throw new MultipassError(`${where}: a second Common tab`);
      model.common = raw.code;
      const commonExtra = leftover(raw, { name: 'Common', type: 'common', code: raw.code, description: '', inputs: [], outputs: [] });
      if (Object.keys(commonExtra).length) extra.commonPass = commonExtra;
      return;
    }
    if (!['image', 'buffer', 'sound', 'cubemap'].includes(raw.type))
      throw new MultipassError(`${where}: unknown pass type ${JSON.stringify(raw.type)}`);
    const buffer = raw.type === 'buffer' ? bufferWritten(raw, where) : null;
    const name = buffer ? bufferPassName(buffer) : ({ sound: 'Sound', cubemap: CUBE_A_NAME }[raw.type] ?? 'Image');
    const channels = readInputs(raw.inputs, name, style, notes);
    /** @type {import('./multipass.js').Pass} */
    const pass = /** @type {import('./multipass.js').Pass} */ ({ name, kind: raw.type, buffer, code: raw.code, channels });
    const passExtra = leftover(raw, { ...writePass({ ...pass, channels: [null, null, null, null] }, style), inputs: raw.inputs });
    if (Object.keys(passExtra).length) pass.extra = passExtra;
    model.passes.push(pass);
  });
  if (style.ids !== SITE_STYLE.ids || style.typeKey !== SITE_STYLE.typeKey || style.srcKey !== SITE_STYLE.srcKey) extra.style = style;
  const shaderExtra = leftover(shader, { ver: '0.1', info: shader.info, renderpass: shader.renderpass });
  if (Object.keys(shaderExtra).length) extra.shader = shaderExtra;
  if (Object.keys(extra).length) model.extra = extra;
  validateModel(model);
  return { model, info: shader.info && typeof shader.info === 'object' ? shader.info : {}, notes };
}

/**
 * Writes a model in Shadertoy's JSON format (the inverse of fromShadertoyJson).
 * @param {import('./multipass.js').MultipassShader} model
 * @param {Record<string, any>} [info] the shader's `info` (name, description, ...); default a minimal one
 * @returns {{Shader: {ver: string, info: Record<string, any>, renderpass: object[]}}}
 */
export function toShadertoyJson(model, info = { name: 'untitled', description: '', tags: [] }) {
  validateModel(model);
  /** @type {Style} */
  const style = model.extra?.style ?? SITE_STYLE;
  const renderpass = model.passes.map((pass) => {
    const written = writePass(pass, style);
    return { ...written, ...(pass.extra ?? {}) };
  });
  if (model.common !== null) {
    renderpass.push({
      inputs: [],
      outputs: [],
      code: model.common,
      name: 'Common',
      description: '',
      type: 'common',
      ...(model.extra?.commonPass ?? {}),
    });
  }
  // a model kept before Cube A ran here holds its cubemap pass as the file had it
  for (const raw of model.extra?.unsupportedPasses ?? []) renderpass.push(raw);
  return { Shader: { ver: '0.1', info, renderpass, ...(model.extra?.shader ?? {}) } };
}

/** The style of a file, from the first id and keys it uses. */
function detectStyle(renderpass) {
  const inputs = renderpass.flatMap((p) => (Array.isArray(p?.inputs) ? p.inputs : []));
  const outputs = renderpass.flatMap((p) => (Array.isArray(p?.outputs) ? p.outputs : []));
  const firstId = [...outputs, ...inputs].map((x) => x?.id).find((id) => id !== undefined);
  const first = inputs[0];
  const ids = typeof firstId === 'number' || /^\d+$/.test(String(firstId ?? 'x')) ? 'legacy' : 'site';
  // With no input to tell, a legacy file is taken to use the legacy keys.
  if (!first) return ids === 'legacy' ? { ids, typeKey: 'ctype', srcKey: 'src' } : { ...SITE_STYLE };
  return {
    ids,
    typeKey: !('type' in first) && 'ctype' in first ? 'ctype' : 'type',
    srcKey: !('filepath' in first) && 'src' in first ? 'src' : 'filepath',
  };
}

/** The buffer a buffer pass writes: from its output id (either style), else its name. */
function bufferWritten(raw, where) {
  const id = Array.isArray(raw.outputs) && raw.outputs.length ? raw.outputs[0]?.id : undefined;
  const fromId = bufferOfId(id);
  if (fromId) return fromId;
  const fromName = String(raw.name ?? '').match(/^Buf(?:fer)?\s*([A-D])$/i);
  if (id === undefined && fromName) return /** @type {any} */ (fromName[1].toUpperCase());
  throw new MultipassError(`${where}: a buffer pass whose output ${JSON.stringify(id)} is none of Buffer A–D`);
}

/** @returns {import('./multipass.js').BufferName | null} */
function bufferOfId(id) {
  for (const b of BUFFER_NAMES) if (id === SITE_IDS[b] || Number(id) === LEGACY_IDS[b]) return b;
  return null;
}

/** A sampler flag: the site writes "true"/"false" strings. */
function readFlag(value, where) {
  if (value === true || value === 'true') return true;
  if (value === false || value === 'false' || value === undefined) return false;
  throw new MultipassError(`${where}: vflip must be "true" or "false", not ${JSON.stringify(value)}`);
}

function readSampler(raw, where) {
  const s = raw && typeof raw === 'object' ? raw : {};
  const filter = s.filter ?? DEFAULT_SAMPLER.filter;
  const wrap = s.wrap ?? DEFAULT_SAMPLER.wrap;
  if (!['nearest', 'linear', 'mipmap'].includes(filter)) throw new MultipassError(`${where}: unknown filter ${JSON.stringify(filter)}`);
  if (!['clamp', 'repeat'].includes(wrap)) throw new MultipassError(`${where}: unknown wrap ${JSON.stringify(wrap)}`);
  return { filter, wrap, vflip: s.vflip === undefined ? DEFAULT_SAMPLER.vflip : readFlag(s.vflip, where) };
}

/** A pass's `inputs` as four channels (null where nothing is bound). */
function readInputs(inputs, passName, style, notes) {
  if (inputs !== undefined && !Array.isArray(inputs)) throw new MultipassError(`${passName}: "inputs" is not a list`);
  /** @type {Array<import('./multipass.js').Channel | null>} */
  const channels = [null, null, null, null];
  for (const raw of inputs ?? []) {
    const index = raw?.channel;
    if (!Number.isInteger(index) || index < 0 || index > 3)
      throw new MultipassError(`${passName}: an input on channel ${JSON.stringify(index)} (channels are 0 to 3)`);
    const where = `${passName}, iChannel${index}`;
    if (channels[index]) throw new MultipassError(`${where}: two inputs on one channel`);
    const type = raw.type ?? raw.ctype;
    const sampler = readSampler(raw.sampler, where);
    /** @type {import('./multipass.js').Channel} */
    let channel;
    if (type === 'buffer') {
      const buffer = bufferOfId(raw.id) ?? bufferOfFile(raw.filepath ?? raw.src);
      if (!buffer) throw new MultipassError(`${where}: a buffer input with id ${JSON.stringify(raw.id)}, none of Buffer A–D`);
      channel = { kind: 'buffer', buffer, sampler };
    } else if (type === 'keyboard') {
      channel = { kind: 'keyboard', sampler };
    } else if (type === 'cubemap' && readsCubeA(raw)) {
      channel = { kind: 'cubebuffer', sampler };
    } else if (MEDIA_TYPES.includes(type)) {
      channel = { kind: type, src: String(raw.filepath ?? raw.src ?? ''), supported: false, sampler };
      notes.push(unsupportedNote(passName, index, channel));
    } else {
      throw new MultipassError(`${where}: unknown input type ${JSON.stringify(type)}`);
    }
    const channelExtra = leftover(raw, writeChannel(channel, index, style));
    if (Object.keys(channelExtra).length) channel.extra = channelExtra;
    channels[index] = channel;
  }
  return channels;
}

/** Whether a "cubemap" input reads the Cube A pass: its id, else its file (the site's preview of it). */
function readsCubeA(raw) {
  if (raw.id !== undefined) return raw.id === CUBE_A_ID || Number(raw.id) === CUBE_A_LEGACY_ID;
  return String(raw.filepath ?? raw.src ?? '').endsWith(CUBE_A_FILE);
}

function bufferOfFile(file) {
  const m = String(file ?? '').match(/buffer0([0-3])\.png$/);
  return m ? BUFFER_NAMES[Number(m[1])] : null;
}

/** One channel as the site writes it (before the channel's extra fields). */
function writeChannel(channel, index, style) {
  const ids = style.ids === 'legacy' ? LEGACY_IDS : SITE_IDS;
  const file =
    { buffer: () => BUFFER_FILE(channel.buffer), keyboard: () => KEYBOARD_FILE, cubebuffer: () => CUBE_A_FILE }[channel.kind]?.() ??
    channel.src;
  const out = {
    id: { buffer: () => ids[channel.buffer], keyboard: () => ids.keyboard, cubebuffer: () => ids.cube }[channel.kind]?.(),
    [style.srcKey]: file,
    ...(style.srcKey === 'filepath' ? { previewfilepath: file } : {}),
    [style.typeKey]: channel.kind === 'cubebuffer' ? 'cubemap' : channel.kind,
    channel: index,
    sampler: {
      filter: channel.sampler.filter,
      wrap: channel.sampler.wrap,
      vflip: String(channel.sampler.vflip),
      srgb: 'false',
      internal: 'byte',
    },
    published: 1,
  };
  if (out.id === undefined) delete out.id;
  return out;
}

function writePass(pass, style) {
  const ids = style.ids === 'legacy' ? LEGACY_IDS : SITE_IDS;
  const inputs = [];
  pass.channels.forEach((channel, index) => {
    if (!channel) return;
    const written = writeChannel(channel, index, style);
    const extra = channel.extra ?? {};
    inputs.push({ ...written, ...extra, sampler: { ...written.sampler, ...(extra.sampler ?? {}) } });
  });
  return {
    inputs,
    // the Sound tab writes no texture: its outputs, if a file has any, ride in its extra
    outputs: pass.kind === 'sound' ? [] : [{ id: { image: ids.image, cubemap: ids.cube }[pass.kind] ?? ids[pass.buffer], channel: 0 }],
    code: pass.code,
    name: pass.name,
    description: '',
    type: pass.kind,
  };
}

/**
 * The fields of `raw` that `expected` (what the writer produces without extras) does not
 * reproduce: the extras that make the round trip lossless. A sampler is compared field by field.
 */
function leftover(raw, expected) {
  const extra = {};
  for (const [key, value] of Object.entries(raw)) {
    if (key === 'sampler' && value && typeof value === 'object' && expected.sampler) {
      const samplerExtra = {};
      for (const [k, v] of Object.entries(value)) {
        if (['filter', 'wrap', 'vflip'].includes(k)) continue;
        if (JSON.stringify(v) !== JSON.stringify(expected.sampler[k])) samplerExtra[k] = v;
      }
      if (Object.keys(samplerExtra).length) extra.sampler = samplerExtra;
      continue;
    }
    if (['channel', 'type', 'ctype', 'inputs', 'code'].includes(key) && key in expected) continue;
    if (JSON.stringify(value) !== JSON.stringify(expected[key])) extra[key] = value;
  }
  return extra;
}
