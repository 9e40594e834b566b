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
    messages.push({ severity: m[1].toLowerCase(), line: inFile ? line : null, message: m[3].trim() });
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
