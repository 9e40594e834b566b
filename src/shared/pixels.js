// Pixel buffers between GL and the rest of the world: GL reads RGBA8 rows bottom to top, images
// and PNG files run top to bottom; the page's hook hands them over as base64. Used by the
// page (hook/engine-hook.js, app.js) and the test harness alike.

/** The rows of a width × height RGBA8 buffer in the opposite order (a new buffer). */
export function flipRows(pixels, width, height) {
  const row = width * 4;
  const out = new Uint8Array(pixels.length);
  for (let y = 0; y < height; y++) out.set(pixels.subarray((height - 1 - y) * row, (height - y) * row), y * row);
  return out;
}

/** Base64 of bytes, in chunks (String.fromCharCode takes a bounded number of arguments). */
export function toBase64(bytes) {
  let binary = '';
  for (let i = 0; i < bytes.length; i += 0x8000) binary += String.fromCharCode.apply(null, Array.from(bytes.subarray(i, i + 0x8000)));
  return btoa(binary);
}

/** The bytes of a base64 string. */
export function fromBase64(text) {
  const binary = atob(text);
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; i++) bytes[i] = binary.charCodeAt(i);
  return bytes;
}
