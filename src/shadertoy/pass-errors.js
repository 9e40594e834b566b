// Compiler messages of one pass of a multipass shader, mapped back to the tab they are in: the
// Common tab or the pass's own. The same two steps as for a single file (shader-errors.js): find
// the offset of the user's text in what the GPU compiled (userLineOffset, with the composed
// code's firstSourceLine), then read the log; here the line is then placed in its section
// (composePassShader's `sections`), so "ERROR: 0:1234" becomes "Common:12" or "Buffer A:7".

import { locatePassLine } from './header.js';
import { formatShaderMessages, parseShaderLog } from './shader-errors.js';

/**
 * @typedef {{severity: string, pass: string | null, line: number | null, message: string}} PassMessage
 *   pass: "Common" or the pass's name, null (with line null) for a message about generated code
 */

/**
 * Whether a shader's compile messages name their tab ("Image:3", "Sound:7") rather than its file
 * ("wave.json:3"): whenever it has more than one tab. A Sound tab is no part of a frame, but it is
 * a tab of its own: beside it, "wave.json:3" would not say which of the two line 3 is in.
 * @param {import('./multipass.js').MultipassShader} model
 */
const namesTabs = (model) => model.common !== null || model.passes.length > 1;

/**
 * What a pass's compiler log is read against: the user's text the GPU compiled after the header
 * (Common and a line break, then the tab), and where each of them lies (null: a plain file's
 * lines, counted in the file).
 * @param {import('./multipass.js').MultipassShader} model
 * @param {import('./multipass.js').Pass} pass
 * @param {{sections: import('./header.js').PassSection[]}} composed composePassShader's or composeSoundShader's
 * @returns {{userText: string, sections: import('./header.js').PassSection[] | null}}
 */
export function passCheck(model, pass, composed) {
  return {
    userText: (model.common === null ? '' : model.common + '\n') + pass.code,
    sections: namesTabs(model) ? composed.sections : null,
  };
}

/**
 * The messages of a pass's compiler log, each with its tab (null: a plain file's, or generated
 * code's) and its line in that tab or file.
 * @param {string} log the compiler's info log
 * @param {number | null} offset lines before the user's first line in the compiled source (userLineOffset)
 * @param {{userText: string, sections: import('./header.js').PassSection[] | null}} check passCheck's
 * @returns {PassMessage[]}
 */
export function passMessages(log, offset, { userText, sections }) {
  if (sections) return parsePassShaderLog(log, offset, sections);
  return parseShaderLog(log, offset, userText.split('\n').length).map((m) => ({ ...m, pass: null }));
}

/**
 * A shader's compile messages as the page's note and the command line say them: "Tab:line:" with
 * that tab's line under it where the shader has tabs (namesTabs), "NAME:line:" with the Image
 * tab's line where it is one file; a message about no line of the user's, as it is.
 * @param {Array<{severity: string, pass?: string | null, line: number | null, message: string}>} messages
 * @param {import('./multipass.js').MultipassShader} model
 * @param {string} fileName the shader's name
 */
export function formatCompileMessages(messages, model, fileName) {
  const tabs = Object.fromEntries([['Common', model.common ?? ''], ...model.passes.map((pass) => [pass.name, pass.code])]);
  const image = model.passes.find((pass) => pass.kind === 'image')?.code ?? '';
  return messages
    .map((m) => (m.pass ? formatPassMessages([{ ...m, pass: m.pass }], tabs) : formatShaderMessages([m], image, fileName)))
    .join('\n');
}

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
