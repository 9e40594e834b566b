// The site's media for the command line: `--media DIR` (a folder laid out as the site's paths,
// DIR/a/<hash>.<ext> for /media/a/<hash>.<ext>) and `--fetch-media` (what no folder has is
// downloaded once from the site into a cache folder, and read from there ever after). The page
// reads them through one URL (page-server.js mountFolders), the folders in order: DIR first,
// then the cache. Nothing here runs unless asked: without --fetch-media no request leaves the
// machine.

import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fromShadertoyJson } from '../shadertoy/multipass-json.js';
import { LIBRARY_KINDS, MOVING_LIBRARY_KINDS, mediaFiles } from '../shadertoy/media.js';

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
  if (!media.fetch) return folders;
  folders.push(cache);
  const missing = namedMedia(file).filter((rel) => !folders.some((dir) => fs.existsSync(path.join(dir, rel))));
  for (const rel of missing) {
    try {
      const bytes = await download(`${mediaOrigin()}/media/${rel}`, path.join(cache, rel));
      say(`media: downloaded /media/${rel} (${(bytes / 1024).toFixed(0)} kB) into ${cache}`);
    } catch (error) {
      say(`warning: media: /media/${rel} could not be downloaded from ${mediaOrigin()}: ${error.message}`);
    }
  }
  return folders;
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
  const data = Buffer.from(await response.arrayBuffer());
  fs.mkdirSync(path.dirname(file), { recursive: true });
  const partial = `${file}.${process.pid}.part`;
  fs.writeFileSync(partial, data);
  fs.renameSync(partial, file);
  return data.length;
}
