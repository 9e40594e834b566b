// A compile error as the HTML report shows it: the page's report ("FILE:LINE: error: text", the
// source line under it; a Shadertoy JSON's tab in place of FILE: "Image:2: error: …") read into
// its errors, and the lines of the source around them, numbered as the user numbers them.

import fs from 'node:fs';

/**
 * @typedef {{where: string, errors: {line: number, text: string}[],
 *   excerpt: {number: number, text: string, error: boolean}[]}} CompileDetail
 *   where: the file or the JSON's tab; excerpt: empty when the source cannot be read
 */

/** Lines shown before the first error and after the last. */
const CONTEXT = 3;
/** The most lines an excerpt shows (errors far apart: the first ones). */
const MAX_LINES = 24;

/** "WHERE:LINE: error: text" (ANGLE's "ERROR: 0:LINE:" is rewritten by the page). */
const ERROR_LINE = /^(.+?):(\d+): (?:error|ERROR): (.*)$/;

/**
 * @param {string} message the ShaderproofError's message
 * @param {{file: string, kind: 'glsl' | 'json'}} testCase
 * @returns {CompileDetail | null} null when the message names no line
 */
export function compileDetail(message, { file, kind }) {
  const found = message
    .split('\n')
    .map((line) => ERROR_LINE.exec(line))
    .filter((match) => match !== null);
  if (!found.length) return null;
  const where = found[0][1];
  const errors = found.filter((match) => match[1] === where).map((match) => ({ line: Number(match[2]), text: match[3] }));
  const lines = sourceOf(file, kind, where)?.replace(/\n$/, '').split('\n') ?? [];
  const marked = new Set(errors.map((e) => e.line));
  const first = Math.max(1, Math.min(...marked) - CONTEXT);
  const last = Math.min(lines.length, Math.max(...marked) + CONTEXT, first + MAX_LINES - 1);
  const excerpt = [];
  for (let number = first; number <= last; number++) excerpt.push({ number, text: lines[number - 1], error: marked.has(number) });
  return { where, errors, excerpt };
}

/**
 * The text the error's lines count in: the .glsl file, or the JSON's tab named `where`.
 * @param {string} file
 * @param {'glsl' | 'json'} kind
 * @param {string} where
 */
function sourceOf(file, kind, where) {
  try {
    const text = fs.readFileSync(file, 'utf8');
    if (kind === 'glsl') return text;
    // Shadertoy's shapes (src/shadertoy/multipass-json.js): {Shader: {…}}, {…}, or [one of those]
    const value = [JSON.parse(text)].flat()[0];
    const passes = (value?.Shader ?? value)?.renderpass ?? [];
    const pass = passes.find((p) => String(p?.name ?? '').toLowerCase() === where.toLowerCase());
    return typeof pass?.code === 'string' ? pass.code : null;
  } catch {
    return null;
  }
}
