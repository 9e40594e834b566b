// PNG files in plain Node (pngjs): the one reader and writer of the harness's goldens and the
// command line's outputs. An image is { width, height, data } with RGBA8 rows top to bottom.

import fs from 'node:fs';
import path from 'node:path';
import { PNG } from 'pngjs';

/** @param {string} file @returns {{width: number, height: number, data: Buffer}} */
export function readPng(file) {
  return decodePng(fs.readFileSync(file));
}

/** An image from a PNG file's bytes. @param {Uint8Array} bytes @returns {{width: number, height: number, data: Buffer}} */
export function decodePng(bytes) {
  const png = PNG.sync.read(Buffer.from(bytes.buffer, bytes.byteOffset, bytes.byteLength));
  return { width: png.width, height: png.height, data: png.data };
}

/** The PNG file's bytes of an image. @param {{width: number, height: number, data: Uint8Array}} image */
export function pngBytes({ width, height, data }) {
  const png = new PNG({ width, height });
  Buffer.from(data.buffer, data.byteOffset, data.byteLength).copy(png.data);
  return PNG.sync.write(png, { colorType: 6 });
}

/** Writes an image as a PNG file, making its folder. @param {string} file @param {{width: number, height: number, data: Uint8Array}} image */
export function writePng(file, image) {
  writeWhole(file, pngBytes(image));
}

/**
 * Writes `bytes` to `file` whole or not at all: into a temporary file beside it, then renamed
 * over it (a rename within a folder is atomic on POSIX file systems), so that a file already
 * there is never left half-written or replaced by a failed run's output.
 * @param {string} file
 * @param {Uint8Array} bytes
 */
export function writeWhole(file, bytes) {
  fs.mkdirSync(path.dirname(path.resolve(file)), { recursive: true });
  const temporary = path.join(path.dirname(path.resolve(file)), `.${path.basename(file)}.${process.pid}.partial`);
  try {
    fs.writeFileSync(temporary, bytes);
    fs.renameSync(temporary, file);
  } finally {
    fs.rmSync(temporary, { force: true });
  }
}
