// Compiler messages of one pass of a multipass shader, mapped back to the tab they are in: the
// Common tab or the pass's own. The same two steps as for a single file (shader-errors.js): find
// the offset of the user's text in what the GPU compiled (userLineOffset, with the composed
// code's firstSourceLine), then read the log; here the line is then placed in its section
// (composePassShader's `sections`), so "ERROR: 0:1234" becomes "Common:12" or "Buffer A:7".

import { locatePassLine } from './header.js';
import { parseShaderLog } from './shader-errors.js';

/**
 * @typedef {{severity: string, pass: string | null, line: number | null, message: string}} PassMessage
 *   pass: "Common" or the pass's name, null (with line null) for a message about generated code
 */

/**
 * Splits a compiler log of a composed pass into messages naming the tab and its line.
 * @param {string} log the compiler's info log
 * @param {number | null} offset lines before the user's first line in the compiled source
 *   (userLineOffset(compiled, body, firstSourceLine, userText)), as for parseShaderLog
 * @param {import('./header.js').PassSection[]} sections from composePassShader
 * @returns {PassMessage[]}
 */
export function parsePassShaderLog(log, offset, sections) {
  const last = sections[sections.length - 1];
  const userLines = last.firstLine + last.lineCount - 1;
  return parseShaderLog(log, offset, userLines).map(({ severity, line, message }) => {
    const at = line === null ? null : locatePassLine(sections, line);
    return { severity, pass: at ? at.name : null, line: at ? at.line : null, message };
  });
}

/**
 * A readable report: `Tab:line: severity: message`, with the offending line of that tab under it.
 * @param {PassMessage[]} messages
 * @param {Record<string, string>} sources each tab's text by name ("Common", "Image", "Buffer A", ...)
 */
export function formatPassMessages(messages, sources) {
  return messages
    .map(({ severity, pass, line, message }) => {
      if (pass === null || line === null) return `${severity}: ${message}`;
      const code = (sources[pass] ?? '').split('\n')[line - 1]?.trim() ?? '';
      return `${pass}:${line}: ${severity}: ${message}` + (code ? `\n    ${code}` : '');
    })
    .join('\n');
}
