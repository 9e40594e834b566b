// An Ogg Theora video (the site's `.ogv` files) for video-file.js, decoded in WebAssembly on the
// page's thread (theora-stream.js: ogv.js's builds of liboggz and libtheora), since Chromium no
// longer decodes Theora. video-file.js imports this module only when a file is Ogg, so the page
// loads it, and its two WebAssembly files from the build's assets, only then: no network.

import OGVDemuxerOgg from 'ogv/dist/ogv-demuxer-ogg-wasm.js';
import OGVDecoderTheora from 'ogv/dist/ogv-decoder-video-theora-wasm.js';
import demuxerWasmUrl from 'ogv/dist/ogv-demuxer-ogg-wasm.wasm?url';
import decoderWasmUrl from 'ogv/dist/ogv-decoder-video-theora-wasm.wasm?url';
import { theoraToRgba } from './theora-colour.js';
import { TheoraStream } from './theora-stream.js';

/** @typedef {import('./video-file.js').FrameSource} FrameSource */

/** The WebAssembly files' bytes, fetched once for the page. @type {Map<string, Promise<ArrayBuffer>>} */
const binaries = new Map();

/** @param {string} url */
function binary(url) {
  let bytes = binaries.get(url);
  if (!bytes) {
    bytes = fetch(url).then((response) => {
      if (!response.ok) throw new Error(`${url}: HTTP ${response.status}`);
      return response.arrayBuffer();
    });
    bytes.catch(() => binaries.delete(url)); // a later file tries again
    binaries.set(url, bytes);
  }
  return bytes;
}

/** Fetches the decoder's WebAssembly (once): rejects with why the page could not. */
export async function loadDecoder() {
  await Promise.all([binary(demuxerWasmUrl), binary(decoderWasmUrl)]);
}

/**
 * A module of ogv.js, instantiated on the given WebAssembly (a new instance each time: the
 * modules keep one stream's state). What it would print goes nowhere: a failure rejects.
 * @param {(options: object) => Promise<any>} factory
 * @param {string} url
 */
const instance = async (factory, url) => factory({ wasmBinary: await binary(url), print: () => {}, printErr: () => {} });

/**
 * The frames of an Ogg file's Theora video.
 * @param {Blob} blob
 * @returns {Promise<FrameSource>}
 */
export async function openTheora(blob) {
  const stream = await TheoraStream.open(await blob.arrayBuffer(), {
    demuxer: () => instance(OGVDemuxerOgg, demuxerWasmUrl),
    decoder: () => instance(OGVDecoderTheora, decoderWasmUrl),
  });
  return {
    duration: stream.duration,
    async sampleAt(seconds) {
      const index = stream.indexAt(seconds);
      return {
        timestamp: stream.timeOf(index),
        async image(vflip) {
          const frame = stream.decode(index);
          const { cropWidth: width, cropHeight: height, displayWidth, displayHeight } = frame.format;
          const pixels = new ImageData(theoraToRgba(frame), width, height);
          // a file whose pixels are not square is shown at its display size, as a <video> is
          const resize = displayWidth !== width || displayHeight !== height;
          return createImageBitmap(pixels, {
            imageOrientation: vflip ? 'flipY' : 'from-image',
            colorSpaceConversion: 'none',
            premultiplyAlpha: 'none',
            ...(resize ? { resizeWidth: displayWidth, resizeHeight: displayHeight, resizeQuality: 'medium' } : {}),
          });
        },
        close() {},
      };
    },
  };
}
