// How a count of pixels and where they differ are said, the same in every report (the dot line,
// junit.xml, index.html): "1 pixel differs from the reference (at most 0 may) at (12, 7):
// reference 255,0,0,255, actual 254,0,0,255", "4,800 pixels differ … in x 10–90, y 5–60".

/** "1 pixel", "4,800 pixels". @param {number} count */
export const pixelCount = (count) => `${count.toLocaleString('en-US')} pixel${count === 1 ? '' : 's'}`;

/** The verb after a count: "differs" for one, "differ" else. @param {number} count @param {string} one @param {string} many */
export const verb = (count, one, many) => (count === 1 ? one : many);

/** "255,0,0,255". @param {ArrayLike<number>} value */
const rgba = (value) => Array.from(value).join(',');

/** "10–90", or "10" when both ends are one. @param {number} from @param {number} to */
const span = (from, to) => (from === to ? `${from}` : `${from}–${to}`);

/** A pixel and both images' values there: "(12, 7): reference 255,0,0,255, actual 254,0,0,255". @param {import('../headless/compare.js').Where['first'][number]} pixel */
export const pixelText = ({ x, y, reference, actual }) => `(${x}, ${y}): reference ${rgba(reference)}, actual ${rgba(actual)}`;

/**
 * Where `count` pixels differ: the one pixel and its values, or the box they lie in.
 * @param {number} count
 * @param {import('../headless/compare.js').Where} where
 */
export function whereText(count, { box, first }) {
  if (count === 1 && first.length) return `at ${pixelText(first[0])}`;
  return `in x ${span(box.left, box.right)}, y ${span(box.top, box.bottom)}`;
}

/**
 * A failed comparison's line.
 * @param {number} count
 * @param {number} allowed
 * @param {import('../headless/compare.js').Where | null} where
 */
export function differLine(count, allowed, where) {
  const said = `${pixelCount(count)} ${verb(count, 'differs', 'differ')} from the reference (at most ${allowed.toLocaleString('en-US')} may)`;
  return where ? `${said} ${whereText(count, where)}` : said;
}
