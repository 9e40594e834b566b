// The site's media for the command line: `--media DIR` (a folder laid out as the site's paths,
// DIR/a/<hash>.<ext> for /media/a/<hash>.<ext>) and `--fetch-media` (what no folder has is
// downloaded once from the site into a cache folder, and read from there ever after). The page
// reads them through one URL (page-server.js mountFolders), the folders in order: DIR first,
// then the cache. Nothing here runs unless asked: without --fetch-media no request leaves the
// machine.
//
// `--channel0..3 FILE` for the kinds a channel of the page's panel cannot hold: a volume (the
// site's .bin) and a cubemap (an image whose five other faces lie beside it as the site names
// them, sky.png with sky_1.png … sky_5.png). Such a channel has to be declared samplerCube or
// sampler3D, so it is a channel of the shader itself: the shader is run as the Shadertoy JSON
// the site would hold for it, its Image pass reading the file through the media library
// (src/player/inputs/media-library.js), with the sampler the site gives a new input of that kind.
// Images, videos and music stay the page's own channels (view-options.js).

import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fromShadertoyJson, toShadertoyJson } from '../shadertoy/multipass-json.js';
import { singlePass } from '../shadertoy/multipass.js';
import {
  LIBRARY_KINDS,
  MEDIA_WORDS,
  MOVING_LIBRARY_KINDS,
  cubeFaceFiles,
  mediaFiles,
  mediaUrlPath,
  parseVolume,
} from '../shadertoy/media.js';
import { UsageError } from './view-options.js';
import { ShaderproofError } from '../headless/session.js';

/** Where the site's media is downloaded from: its own origin, or SHADERPROOF_MEDIA_ORIGIN (a mirror, a test's server). */
const mediaOrigin = () => process.env.SHADERPROOF_MEDIA_ORIGIN || 'https://www.shadertoy.com';

/** The download cache: SHADERPROOF_MEDIA_CACHE, else $XDG_CACHE_HOME/shaderproof/media, else ~/.cache/shaderproof/media. */
function mediaCacheDir() {
  if (process.env.SHADERPROOF_MEDIA_CACHE) return path.resolve(process.env.SHADERPROOF_MEDIA_CACHE);
  const cache = process.env.XDG_CACHE_HOME || path.join(os.homedir(), '.cache');
  return path.join(cache, 'shaderproof', 'media');
}

/** How long one download may take before it is given up (the site's media are at most a few MB). */
const DOWNLOAD_TIMEOUT_MS = 60_000;

/**
 * The site media files a shader's channels name (media-folder paths), for a Shadertoy JSON; none
 * for a .glsl file or a JSON that cannot be read (the page says why it cannot load it).
 * @param {string} file
 */
function namedMedia(file) {
  if (!/\.json$/i.test(file)) return [];
  let model;
  try {
    model = fromShadertoyJson(fs.readFileSync(file, 'utf8')).model;
  } catch {
    return [];
  }
  const channels = model.passes.flatMap((pass) => pass.channels);
  return [
    ...new Set(
      channels.flatMap((c) =>
        c && (LIBRARY_KINDS.includes(c.kind) || MOVING_LIBRARY_KINDS.includes(c.kind)) ? mediaFiles(/** @type {any} */ (c)) : [],
      ),
    ),
  ];
}

/**
 * The media folders to serve for a shader, in order: --media DIR, then the download cache with
 * --fetch-media, after downloading into it what neither has. A download that fails is said and
 * left: the page then says the channel went without it.
 * @param {string} file the shader
 * @param {import('./view-options.js').MediaOptions | undefined} media
 * @param {(line: string) => void} say
 * @returns {Promise<string[]>}
 */
export async function mediaFolders(file, media, say) {
  if (!media || (!media.dir && !media.fetch)) return [];
  const cache = mediaCacheDir();
  const folders = media.dir ? [media.dir] : [];
  const named = namedMedia(file);
  if (media.dir) sayLayout(media.dir, named, say);
  if (!media.fetch) return folders;
  folders.push(cache);
  // what failed is tried once a run: a test case renders its shader up to five times
  const missing = named.filter((rel) => !failedDownloads.has(rel) && !folders.some((dir) => fs.existsSync(path.join(dir, rel))));
  /** @type {Map<string, string[]>} why → the files it stopped */
  const failed = new Map();
  await Promise.all(
    missing.map(async (rel) => {
      try {
        const bytes = await download(`${mediaOrigin()}/media/${mediaUrlPath(rel)}`, path.join(cache, rel));
        say(`media: downloaded /media/${rel} (${(bytes / 1024).toFixed(0)} kB) into ${cache}`);
      } catch (error) {
        failedDownloads.add(rel);
        failed.set(error.message, [...(failed.get(error.message) ?? []), `/media/${rel}`]);
      }
    }),
  );
  // one line a reason (no network fails every file alike), naming the files
  for (const [why, files] of failed)
    say(
      `warning: media: ${files.length === 1 ? files[0] : `${files.length} files (${files.join(', ')})`} could not be downloaded from ${mediaOrigin()}: ${why}`,
    );
  return folders;
}

/**
 * Says once when --media DIR holds a shader's files but not where the site's paths put them
 * (DIR/x.png, or DIR/media/a/x.png, for /media/a/x.png): the likeliest first mistake.
 * @param {string} dir
 * @param {string[]} files media-folder paths the shader names
 * @param {(line: string) => void} say
 */
function sayLayout(dir, files, say) {
  for (const rel of files) {
    if (fs.existsSync(path.join(dir, rel))) continue;
    const near = [path.join(dir, path.basename(rel)), path.join(dir, 'media', rel), path.join(dir, '..', rel)].find((f) =>
      fs.existsSync(f),
    );
    if (!near) continue;
    say(
      `warning: --media ${dir}: ${rel} is not there, but ${near} is: the folder is laid out as the site's paths, ${path.join(dir, rel)} for /media/${rel}`,
    );
    return;
  }
}

/** The media paths whose download failed in this process. */
const failedDownloads = new Set();

/**
 * A line of the page's "went without" note in the command line's words: the page asks for a
 * media folder by both its ways (shaderproof --media DIR, the page's ?media=URL) and calls the
 * folders it was given "the media folder"; here the flags are named, and a file whose download
 * failed is said to be that, not to be missing from a folder the person never gave.
 * @param {string} line
 * @param {import('./view-options.js').MediaOptions | undefined} media what the run was given
 */
export function commandLineWords(line, media) {
  if (line.includes(MEDIA_WORDS.noFolder))
    return line.replace(
      MEDIA_WORDS.noFolder,
      "needs the site's media: give --media DIR (a folder laid out as the site's paths) or --fetch-media",
    );
  const notIn = new RegExp(`(\\S+) ${MEDIA_WORDS.notInFolder}`).exec(line);
  if (!notIn) return line;
  const file = notIn[1];
  const where = failedDownloads.has(file)
    ? `${file} could not be downloaded (the warning above says why)`
    : media?.dir && media.fetch
      ? `${file} is neither in --media ${media.dir} nor in the download cache`
      : media?.dir
        ? `${file} is not in --media ${media.dir} (--fetch-media downloads what it lacks)`
        : `${file} is not in the download cache`;
  return line.replace(notIn[0], where);
}

/**
 * Downloads `url` into `file` whole: written beside it, then renamed, so that the cache never
 * holds half a file. Resolves with its size.
 * @param {string} url
 * @param {string} file
 */
async function download(url, file) {
  const response = await fetch(url, { signal: AbortSignal.timeout(DOWNLOAD_TIMEOUT_MS) }).catch((error) => {
    throw new Error(
      error.name === 'TimeoutError' ? `no answer within ${DOWNLOAD_TIMEOUT_MS / 1000} s` : (error.cause?.message ?? error.message),
    );
  });
  if (!response.ok) throw new Error(`HTTP ${response.status}${response.statusText ? ` ${response.statusText}` : ''}`);
  // a web page in a file's place (a login or a challenge page) is no media, and would stay cached
  if (/text\/html/i.test(response.headers.get('content-type') ?? '')) throw new Error('the server answered with a web page, not the file');
  const data = Buffer.from(await response.arrayBuffer());
  fs.mkdirSync(path.dirname(file), { recursive: true });
  const partial = `${file}.${process.pid}.part`;
  fs.writeFileSync(partial, data);
  fs.renameSync(partial, file);
  return data.length;
}

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
 * What a channel's file on disk is, when it is a volume or a cubemap (with its faces' names);
 * null for anything else (an image, a video, music: the page's own channels).
 * @param {string} file
 * @param {number} index the channel, for messages
 * @returns {{kind: 'volume' | 'cubemap', files: string[]} | null} files: the names the channel reads, in its folder
 */
function libraryKindOnDisk(file, index) {
  const name = path.basename(file);
  if (/\.bin$/i.test(file)) {
    if (!fs.existsSync(file)) throw new ShaderproofError(`${file}: no such file`);
    try {
      const bytes = fs.readFileSync(file);
      parseVolume(bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength));
    } catch (error) {
      throw new ShaderproofError(`${file}: ${error.message} (a volume is the site's .bin format)`);
    }
    return { kind: 'volume', files: [name] };
  }
  if (!/\.(png|jpe?g|webp|gif)$/i.test(file)) return null;
  const face = /^(.*)_([1-5])(\.[^.]+)$/.exec(name);
  const first = face ? `${face[1]}${face[3]}` : null;
  if (first && fs.existsSync(path.join(path.dirname(file), first)))
    throw new UsageError(
      `--channel${index} ${file}: face ${face?.[2]} of a cubemap; give its first face, ${path.join(path.dirname(file), first)}`,
    );
  const [, ...faces] = cubeFaceFiles(name);
  const present = faces.filter((face) => fs.existsSync(path.join(path.dirname(file), face)));
  if (present.length === 0) return null;
  if (present.length < faces.length)
    throw new UsageError(
      `--channel${index} ${file}: a cubemap's first face, with ${present.length} of its other five beside it; ${faces.filter((f) => !present.includes(f)).join(', ')} missing`,
    );
  return { kind: 'cubemap', files: [name, ...faces] };
}

/**
 * The shader as a Shadertoy JSON whose Image pass reads each volume and cubemap given by
 * --channelN, and what to mount for them: each channel's own files under a folder of its own
 * (`channel<i>/`), so that two files of one name, or a --media folder's, cannot stand in for
 * each other; null when no channel is one.
 * @param {string} file the shader (.glsl or a Shadertoy JSON)
 * @param {(string | null)[]} channels --channel0..3
 * @returns {{json: string, mounts: import('../headless/page-server.js').FolderMount[], rest: (string | null)[]} | null}
 *   rest: the channels left to the page (images, videos, music)
 */
export function withLibraryChannels(file, channels) {
  if (!channels.some(Boolean)) return null;
  const found = channels.map((f, i) => (f ? libraryKindOnDisk(f, i) : null));
  const text = fs.readFileSync(file, 'utf8');
  const json = /\.json$/i.test(file) || /^\s*[[{]/.test(text);
  if (!json && !found.some(Boolean)) return null;
  let loaded;
  try {
    loaded = json ? fromShadertoyJson(text) : { model: singlePass(text), info: null };
  } catch (error) {
    throw new ShaderproofError(`${file}: ${error.message}`);
  }
  const image = /** @type {import('../shadertoy/multipass.js').Pass} */ (loaded.model.passes.find((p) => p.kind === 'image'));
  // a channel the shader's JSON fills already: the file given would go unread
  channels.forEach((given, i) => {
    if (given && image.channels[i])
      throw new UsageError(
        `--channel${i} ${given}: ${path.basename(file)}'s Image pass reads iChannel${i} already (its ${image.channels[i]?.kind})`,
      );
  });
  if (!found.some(Boolean)) return null;
  /** @type {import('../headless/page-server.js').FolderMount[]} */
  const mounts = [];
  found.forEach((disk, i) => {
    if (!disk) return;
    const given = /** @type {string} */ (channels[i]);
    mounts.push({ prefix: `channel${i}`, dir: path.dirname(path.resolve(given)), files: disk.files });
    image.channels[i] = {
      kind: disk.kind,
      src: `/media/channel${i}/${encodeURIComponent(disk.files[0])}`,
      supported: false,
      sampler: NEW_INPUT_SAMPLER[disk.kind],
    };
  });
  // named as the file is, so that the page's notes and messages name it
  const info = loaded.info ?? { name: path.basename(file), description: '', tags: [] };
  return { json: JSON.stringify(toShadertoyJson(loaded.model, info)), mounts, rest: channels.map((f, i) => (found[i] ? null : f)) };
}
