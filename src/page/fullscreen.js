// Fullscreen for the stage (the canvas with its messages): the toolbar's "Fullscreen" button and
// the F key. The canvas follows its new size as it follows a window resize (canvas-size.js).

/**
 * Enters fullscreen with `element`, or leaves it when the page is fullscreen.
 * @param {HTMLElement} element
 * @returns {Promise<boolean>} whether the page is fullscreen afterwards
 */
export async function toggleFullscreen(element) {
  try {
    if (document.fullscreenElement) await document.exitFullscreen();
    else await element.requestFullscreen({ navigationUI: 'hide' });
  } catch (error) {
    console.warn(`Fullscreen refused: ${error.message}`);
  }
  return document.fullscreenElement !== null;
}

/**
 * Calls `onChange(isFullscreen)` whenever the page enters or leaves fullscreen (also by Esc).
 * @param {(fullscreen: boolean) => void} onChange
 */
export function watchFullscreen(onChange) {
  document.addEventListener('fullscreenchange', () => onChange(document.fullscreenElement !== null));
}
