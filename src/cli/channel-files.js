// `--channel0..3 FILE` for the kinds a channel of the page's panel cannot hold: a volume (the
// site's .bin) and a cubemap (an image whose five other faces lie beside it as the site names
// them, sky.png with sky_1.png … sky_5.png). Such a channel has to be declared samplerCube or
// sampler3D, so it is a channel of the shader itself: the shader is run as the Shadertoy JSON
// the site would hold for it, its Image pass reading the file through the media library
// (src/page/inputs/media-library.js), with the sampler the site gives a new input of that kind.
// Images, videos and music stay the page's own channels (view-options.js).

import fs from 'node:fs';
import path from 'node:path';
import { fromShadertoyJson, toShadertoyJson } from '../shadertoy/multipass-json.js';
import { singlePass } from '../shadertoy/multipass.js';
import { mediaFiles } from '../shadertoy/media.js';
import { UsageError } from './view-options.js';

/**
 * The sampler the site's channel picker gives a new input of each kind: cubemaps unflipped and
 * clamped, volumes repeating, both mipmapped.
 */
/** @type {Record<'cubemap' | 'volume', import('../shadertoy/multipass.js').Sampler>} */
const NEW_INPUT_SAMPLER = {
  cubemap: { filter: 'mipmap', wrap: 'clamp', vflip: false },
  volume: { filter: 'mipmap', wrap: 'repeat', vflip: false },
};

/**
 * What a channel's file on disk is, when it is a volume or a cubemap; null for anything else.
 * @param {string} file
 * @returns {'volume' | 'cubemap' | null}
 */
function libraryKindOnDisk(file) {
  if (/\.bin$/i.test(file)) return 'volume';
  if (!/\.(png|jpe?g|webp|gif)$/i.test(file)) return null;
  const [, ...faces] = mediaFiles({ kind: 'cubemap', src: `/media/${path.basename(file)}` });
  return faces.every((face) => fs.existsSync(path.join(path.dirname(file), face))) ? 'cubemap' : null;
}

/**
 * The shader as a Shadertoy JSON whose Image pass reads each volume and cubemap given by
 * --channelN, and the folders its media is served from; null when no channel is one.
 * @param {string} file the shader (.glsl or a Shadertoy JSON)
 * @param {(string | null)[]} channels --channel0..3
 * @returns {{json: string, folders: string[], rest: (string | null)[]} | null} rest: the channels
 *   left to the page (images, videos, music)
 */
export function withLibraryChannels(file, channels) {
  const kinds = channels.map((f) => (f ? libraryKindOnDisk(f) : null));
  if (!kinds.some(Boolean)) return null;
  const text = fs.readFileSync(file, 'utf8');
  const loaded = /\.json$/i.test(file) || /^\s*[[{]/.test(text) ? fromShadertoyJson(text) : { model: singlePass(text), info: undefined };
  const image = /** @type {import('../shadertoy/multipass.js').Pass} */ (loaded.model.passes.find((p) => p.kind === 'image'));
  const folders = [];
  kinds.forEach((kind, i) => {
    if (!kind) return;
    if (image.channels[i])
      throw new UsageError(`--channel${i} ${channels[i]}: ${path.basename(file)}'s Image pass reads iChannel${i} already`);
    const dir = path.dirname(path.resolve(/** @type {string} */ (channels[i])));
    if (!folders.includes(dir)) folders.push(dir);
    // a folder of its own for each file's folder: the media path is the file's name in it
    image.channels[i] = {
      kind,
      src: `/media/${path.basename(/** @type {string} */ (channels[i]))}`,
      supported: false,
      sampler: NEW_INPUT_SAMPLER[kind],
    };
  });
  const json = JSON.stringify(toShadertoyJson(loaded.model, loaded.info));
  return { json, folders, rest: channels.map((f, i) => (kinds[i] ? null : f)) };
}
