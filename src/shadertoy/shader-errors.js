// Compiler messages, mapped back to the user's shader file.
//
// The GPU compiles more than the user wrote: Shadertoy's header and its `main`, the host control
// block, then the file. A log line such as `ERROR: 0:57: 'x' : undeclared identifier` counts
// lines of all of that, so we find where the file starts in the source the GPU actually received
// and subtract.

import { countNewlines } from './header.js';

/**
 * How many lines come before the user's first line in `compiledSource` (what
 * gl.getShaderSource returns), so that `userLine = logLine - offset`.
 * @param {string} compiledSource the full text given to the GPU
 * @param {string} body the composed text (or a part of it that the compiled source holds whole)
 * @param {number} firstBodyLine 1-based line of `body` on which the user's file starts
 * @param {string} userSource the user's file, the fallback anchor
 */
export function userLineOffset(compiledSource, body, firstBodyLine, userSource) {
  const at = compiledSource.indexOf(body);
  if (at >= 0) return countNewlines(compiledSource, at) + firstBodyLine - 1;
  const userAt = userSource ? compiledSource.lastIndexOf(userSource) : -1;
  if (userAt >= 0) return countNewlines(compiledSource, userAt);
  return null;
}

const LOG_LINE = /^\s*(ERROR|WARNING)\s*:\s*\d+\s*:\s*(\d+)\s*:\s*(.*)$/i;

/**
 * Compiler messages a person cannot act on as the driver words them, in this tool's words.
 *
 * A global whose initializer is not a constant expression (`vec2 p = iResolution.xy;`, `float
 * b = a * 2.0;` with `a` a global, `float c = f();` with f the shader's own) is an error in GLSL
 * ES 3.00 (section 4.3: "Initializers may only be used in declarations of globals with no
 * storage qualifier or with a const qualifier. Such initializers must be a constant
 * expression"). Chromium's compiler, ANGLE, lets a uniform or a global through in ES 1.00 (WebGL
 * 1) with a warning, for old content, and refuses both from 3.00 on (ValidateGlobalInitializer.cpp:
 * "Implement stricter rules for ESSL 3.00"). The site compiles every pass as `#version 300 es` in the browser's
 * WebGL2, its player passing the user's text on as it is (effect.js: NewShader_Image joins
 * header, Common and the tab): such a shader fails on Shadertoy too (those in its gallery date
 * from its WebGL 1 years). A built-in function of constants (`sin(1.0)`) is a constant
 * expression and compiles in both.
 * @type {Array<[RegExp, string]>}
 */
const REWORDED = [
  [
    /global variable initializers must be constant expressions/,
    "a global's initial value must be a constant expression in GLSL ES 3.00 (this one reads a uniform, another global or a function of the shader's), so Shadertoy rejects this shader as well: declare the global without a value and assign it at the start of mainImage (or of the function that uses it)",
  ],
];

/**
 * A compiler message in this tool's words where it has some (REWORDED), else as it is.
 * @param {string} message
 */
function reword(message) {
  return REWORDED.find(([pattern]) => pattern.test(message))?.[1] ?? message;
}

/**
 * Splits a compiler log into messages: { severity, line (in the user's file, or null when the
 * message is about generated code or has no line), message }.
 */
export function parseShaderLog(log, offset, userLineCount) {
  const messages = [];
  for (const raw of log.split('\n')) {
    const text = raw.replace(/\0/g, '').trim(); // a log may end in a NUL
    if (!text || /^ERROR:\s*\d+\s+compilation errors?/i.test(text)) continue;
    const m = text.match(LOG_LINE);
    if (!m) {
      messages.push({ severity: 'error', line: null, message: text });
      continue;
    }
    const line = offset === null ? null : Number(m[2]) - offset;
    const inFile = line !== null && line >= 1 && line <= userLineCount;
    messages.push({ severity: m[1].toLowerCase(), line: inFile ? line : null, message: reword(m[3].trim()) });
  }
  return messages;
}

/** A readable report: one message a line, with the offending source line under it. */
export function formatShaderMessages(messages, userSource, fileName = 'shader') {
  const lines = userSource.split('\n');
  return messages
    .map(({ severity, line, message }) => {
      if (line === null) return `${severity}: ${message}`;
      const code = lines[line - 1]?.trim() ?? '';
      return `${fileName}:${line}: ${severity}: ${message}` + (code ? `\n    ${code}` : '');
    })
    .join('\n');
}
