// Text into the HTML report: escaped, and a file of the output folder as a relative URL.

/** @param {unknown} text */
export const escape = (text) =>
  String(text).replace(/[<>&"']/g, (c) => ({ '<': '&lt;', '>': '&gt;', '&': '&amp;', '"': '&quot;', "'": '&#39;' })[c] ?? c);

/** A file of the output folder as a relative URL (a case's name may hold folders). @param {string} name */
export const href = (name) => name.split('/').map(encodeURIComponent).join('/');
