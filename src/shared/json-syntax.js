// Where a text stops being JSON, and what is there, in one line of this project's words: the
// browser's and Node's JSON.parse say it in words of their own, some with a quote of the text
// around the fault that runs over several lines, some with no place at all. The command line
// (a shader file that is not JSON) and the page (a Shadertoy export that is not JSON) both say
// it so. A scan of JSON's grammar (RFC 8259), nothing parsed into values.

/**
 * The first place `text` breaks JSON's grammar, as "line L, column C: what is there", or null
 * when it is JSON.
 * @param {string} text
 * @returns {string | null}
 */
export function jsonSyntaxError(text) {
  let at = 0;
  const n = text.length;
  /** @param {string} what */
  const fail = (what) => {
    throw new JsonFault(at, what);
  };
  const found = () => (at >= n ? 'the text ends' : JSON.stringify(text.slice(at, at + 12).split('\n')[0]));
  const space = () => {
    while (at < n && ' \t\n\r'.includes(text[at])) at++;
  };
  /** @param {RegExp} pattern sticky */
  const match = (pattern) => {
    pattern.lastIndex = at;
    const m = pattern.exec(text);
    if (m) at += m[0].length;
    return Boolean(m);
  };
  const string = () => {
    at++; // the opening quote
    for (;;) {
      if (at >= n) fail('the text ends inside a string');
      const c = text[at];
      if (c === '"') return void at++;
      if (c === '\\') {
        at++;
        if (!match(/["\\/bfnrt]|u[0-9a-fA-F]{4}/y)) fail(`${found()} where an escape (\\n, \\", \\u0041, …) belongs`);
      } else if (text.charCodeAt(at) < 0x20) fail('a line break or a control character inside a string (write it as \\n)');
      else at++;
    }
  };
  const value = () => {
    space();
    const c = text[at];
    if (c === '{' || c === '[') {
      const close = c === '{' ? '}' : ']';
      at++;
      space();
      if (text[at] === close) return void at++;
      for (;;) {
        if (close === '}') {
          space();
          if (text[at] !== '"') fail(`${found()} where a property name in double quotes belongs`);
          string();
          space();
          if (text[at] !== ':') fail(`${found()} where ':' belongs`);
          at++;
        }
        value();
        space();
        if (text[at] === ',') {
          at++;
          continue;
        }
        if (text[at] === close) return void at++;
        fail(`${found()} where ',' or '${close}' belongs`);
      }
    }
    if (c === '"') return string();
    if (match(/-?(?:0|[1-9]\d*)(?:\.\d+)?(?:[eE][+-]?\d+)?|true\b|false\b|null\b/y)) return;
    fail(`${found()} where a value belongs`);
  };
  try {
    value();
    space();
    if (at < n) fail(`${found()} after the end of the JSON value`);
    return null;
  } catch (error) {
    if (!(error instanceof JsonFault)) throw error;
    const before = text.slice(0, error.at).split('\n');
    return `line ${before.length}, column ${before[before.length - 1].length + 1}: ${error.what}`;
  }
}

class JsonFault {
  /** @param {number} at @param {string} what */
  constructor(at, what) {
    this.at = at;
    this.what = what;
  }
}
