// llvmpipe's loop limit, and the guarded form of a pass that shows where it cut a loop short.
//
// Mesa's llvmpipe (gallivm) gives each shader invocation one counter for all of its loops: every
// trip of every loop takes one from it, and a loop whose trip finds it at zero stops there, as if
// its condition had failed (LP_MAX_TGSI_LOOP_ITERATIONS, 65,535, in Mesa's lp_bld_limits.h; one
// counter for the invocation, its functions inlined). So a pass that loops more than that in all
// draws a picture that is not the shader's, and a loop that never ends draws one at all.
// SwiftShader and a GPU have no such limit.
//
// Which invocations the limit cut short cannot be read from the picture, and a bound on the
// trips cannot be proven for every loop (a `while` on a value, a bound from a uniform). So the
// pass is drawn in a guarded form that knows, per pixel, whether a loop of it ended other than
// by its own hand: each loop keeps the last value of its condition and whether it left by a
// `break`. A loop that ends with its condition last true and no break was stopped from outside:
// by the limit. (A `return` leaves the function, and the check after the loop with it; a pixel
// discarded writes nothing.) The pass writes that flag as a second output
// (LOOP_GUARD_OUTPUT, location 1) beside its colour, which the form leaves as it was: the same
// statements in the same order, plus stores to the guard's own variables.
//
// The form is built from the pass as the GPU compiles it: preprocessed by a GLSL preprocessor
// (@shaderfrog/glsl-parser's: macros expanded, #if resolved, as ANGLE's would, with GL_ES
// defined), then its statements read and each loop wrapped in place by text inserted around it,
// never moved (loop-statements.js). That library's full parser would do the reading too, but at
// 1-6 s a pass here (its PEG grammar, measured on public shaders of 1-16 KB), against a few ms
// for the statements alone; the guard must cost little beside the pass's compile. The guard's
// names start with `shaderproof_`; Shadertoy code does not use that prefix.

import { preprocess } from '@shaderfrog/glsl-parser/preprocessor/index.js';
import { readStatements, sideEffectFree } from './loop-statements.js';

/** How many trips llvmpipe lets one shader invocation make through all of its loops. */
export const LLVMPIPE_LOOP_LIMIT = 65_535;

/** The guarded form's second output: red 1 where a loop of the pixel was cut short. */
const LOOP_GUARD_OUTPUT = 'shaderproof_loopGuard';

/** The pixel's flag: set after a loop that did not end by its own hand. */
const CUT_FLAG = 'shaderproof_loopCut';

/** The pass's output as the headers declare it (header.js, sound.js): the guard's goes beside it. */
const OUTPUT_DECLARATION = /^out\s+vec4\s+(\w+)\s*;/m;

/**
 * A pass's text in its guarded form, or why it has none.
 * @typedef {{code: string, loops: number, reason?: undefined} | {code: null, loops: 0, reason: string}} GuardedPass
 */

/**
 * The guarded form of a composed pass (`#version` line first, then the header with its `out`
 * and its `main`, then the user's text). `loops` is how many loops it has: with none, nothing
 * can be cut, and the pass needs no guard. A text this cannot parse (one the GPU's compiler
 * would reject too, or one beyond the parser) has no guarded form: `reason` says why.
 * @param {string} code
 * @returns {GuardedPass}
 */
export function guardLoops(code) {
  const version = /^\s*#version[^\n]*\n/.exec(code);
  const body = version ? code.slice(version[0].length) : code;
  let expanded;
  try {
    expanded = preprocess(body, {
      preserveComments: false,
      defines: { GL_ES: '1', __VERSION__: '300' },
      preserve: { extension: () => true, pragma: () => true },
    });
  } catch (error) {
    return { code: null, loops: 0, reason: `not preprocessed: ${String(error?.message ?? error).split('\n')[0]}` };
  }
  const declared = OUTPUT_DECLARATION.exec(expanded);
  if (!declared) return { code: null, loops: 0, reason: 'no `out vec4` output declared' };
  let read;
  try {
    read = readStatements(expanded);
  } catch (error) {
    return { code: null, loops: 0, reason: `not read: ${error.message}` };
  }
  if (read.loops.length === 0) return { code: null, loops: 0, reason: 'no loops' };
  if (read.mainEnd === null) return { code: null, loops: 0, reason: 'no main()' };
  // text to insert at offsets of `expanded`; at one offset, by `order`: a closing of a deeper
  // statement before one of its parent's, an opening of a parent before its child's
  /** @type {Array<{at: number, order: number, text: string, remove?: number}>} */
  const edits = [
    { at: declared.index, order: 0, text: 'layout(location = 0) ' },
    {
      at: declared.index + declared[0].length,
      order: 0,
      text: ` layout(location = 1) out vec4 ${LOOP_GUARD_OUTPUT}; bool ${CUT_FLAG} = false;`,
    },
    { at: read.mainEnd, order: Infinity, text: `${LOOP_GUARD_OUTPUT} = vec4(${CUT_FLAG} ? 1.0 : 0.0, 0.0, 0.0, 1.0); ` },
  ];
  read.loops.forEach((loop, i) => {
    const live = `shaderproof_live${i}`;
    const broke = `shaderproof_broke${i}`;
    const { depth, init, condition } = loop;
    // a for's init goes before it, into the loop's block: the same scope for what it declares,
    // and still in scope for the check after the loop
    const hoisted = init ? `${expanded.slice(init.start, init.end)}; ` : '';
    if (init) edits.push({ at: init.start, order: depth, text: '', remove: init.end - init.start });
    edits.push({ at: loop.start, order: depth, text: `{ bool ${live} = true; bool ${broke} = false; ${hoisted}` });
    // for (;;): no condition, so `live` stays true, and only a break or a return ends it whole
    if (condition) {
      edits.push({ at: condition.start, order: depth, text: `(${live} = (` });
      edits.push({ at: condition.end, order: -depth, text: '))' });
    }
    edits.push({ at: loop.end, order: -depth, text: ` if (${live} && !${broke}${recheck(loop, expanded)}) ${CUT_FLAG} = true; }` });
    for (const at of loop.breaks) {
      edits.push({ at: at.start, order: depth + 1, text: `{ ${broke} = true; ` });
      edits.push({ at: at.end, order: -(depth + 1), text: ' }' });
    }
  });
  edits.sort((a, b) => b.at - a.at || b.order - a.order);
  // from the end, so that each offset still points where it did; at one offset the last sorted
  // (lowest order) is inserted last, and so comes first
  let guarded = expanded;
  for (const { at, text, remove = 0 } of edits) guarded = guarded.slice(0, at) + text + guarded.slice(at + remove);
  return { code: (version ? version[0] : '') + guarded, loops: read.loops.length };
}

/**
 * The test a loop stopped with its condition last true must also pass to have been cut: for a
 * `for` or a `while`, that its condition is true still. llvmpipe stops a loop at its back edge,
 * after the body (and a for's step) and before the condition is asked again, so a loop of exactly
 * the limit's trips is stopped where its own condition would have ended it (measured: 65,535
 * trips counted in full); asking the condition once more tells the two apart, where asking has no
 * side effect (else the loop is said cut, which errs on the safe side). A `do` asks its condition
 * before its back edge: true there, it was cut.
 * @param {import('./loop-statements.js').LoopStatement} loop
 * @param {string} text
 */
function recheck({ kind, condition }, text) {
  if (kind === 'do' || !condition) return '';
  const expression = text.slice(condition.start, condition.end);
  return sideEffectFree(expression) ? ` && (${expression})` : '';
}
