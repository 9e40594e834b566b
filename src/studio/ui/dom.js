// Small DOM helpers the widgets share: making elements, saving a file, copying text, a PNG of
// pixels.

/**
 * An element with attributes and children. `class` sets the class name; booleans toggle an
 * attribute (hidden, required, disabled); anything else is set as an attribute.
 * @template {keyof HTMLElementTagNameMap} K
 * @param {K} tag
 * @param {Record<string, string | number | boolean>} [attributes]
 * @param {Array<Node | string>} children
 * @returns {HTMLElementTagNameMap[K]}
 */
export function element(tag, attributes = {}, ...children) {
  const node = document.createElement(tag);
  for (const [key, value] of Object.entries(attributes)) {
    if (key === 'class') node.className = String(value);
    else if (typeof value === 'boolean') node.toggleAttribute(key, value);
    else node.setAttribute(key, String(value));
  }
  node.append(...children);
  return node;
}

/**
 * Puts a popover (position: fixed) just above `anchor` (the toolbar), no taller than the room
 * there: it covers none of the toolbar, the shader's name among it.
 * @param {HTMLElement} popover
 * @param {HTMLElement} anchor
 */
export function placeAbove(popover, anchor) {
  const top = anchor.getBoundingClientRect().top;
  const gap = 6;
  popover.style.bottom = `${Math.max(0, window.innerHeight - top) + gap}px`;
  popover.style.maxHeight = `${Math.max(0, top - 2 * gap)}px`;
}

/** Saves a Blob as a file, as a link with `download` does. @param {Blob} blob @param {string} fileName */
export function saveBlob(blob, fileName) {
  const url = URL.createObjectURL(blob);
  const link = document.createElement('a');
  link.href = url;
  link.download = fileName;
  link.hidden = true;
  document.body.append(link);
  link.click();
  link.remove();
  setTimeout(() => URL.revokeObjectURL(url), 60_000);
}

/** Copies text: the async Clipboard API, or the older copy command where that is refused. @param {string} text */
export async function copyText(text) {
  try {
    await navigator.clipboard.writeText(text);
    return true;
  } catch {
    const area = document.createElement('textarea');
    area.value = text;
    area.setAttribute('readonly', '');
    area.style.position = 'fixed';
    area.style.opacity = '0';
    document.body.append(area);
    area.select();
    let ok;
    try {
      ok = document.execCommand('copy');
    } catch {
      ok = false;
    }
    area.remove();
    return ok;
  }
}

/**
 * RGBA rows top to bottom → PNG Blob.
 * @param {{width: number, height: number, data: Uint8Array}} image
 * @returns {Promise<Blob>}
 */
export function pngBlob({ width, height, data }) {
  const canvas = document.createElement('canvas');
  canvas.width = width;
  canvas.height = height;
  const context = canvas.getContext('2d');
  if (!context) return Promise.reject(new Error('PNG encoding failed: no 2D canvas context'));
  const clamped = /** @type {Uint8ClampedArray<ArrayBuffer>} */ (new Uint8ClampedArray(data.buffer, data.byteOffset, data.byteLength));
  context.putImageData(new ImageData(clamped, width, height), 0, 0);
  return new Promise((resolve, reject) =>
    canvas.toBlob((blob) => (blob ? resolve(blob) : reject(new Error('PNG encoding failed'))), 'image/png'),
  );
}
