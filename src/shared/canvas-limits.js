// The largest drawing the page makes at once, a fact that the page (src/page/app/canvas-size.js:
// ?size= is clamped to it, with a note) and the command line (--size past it is refused, and
// --tile offered) both state.

/** The largest side the page asks for, in device pixels: WebGL2 implementations allow 16384 at most in practice. */
export const MAX_SIZE = 16384;
/** Beyond 8K UHD a drawing buffer is not a view but a way to exhaust memory. */
export const MAX_PIXELS = 7680 * 4320;
