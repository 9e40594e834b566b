// The statements of a preprocessed GLSL ES 3.00 fragment shader, read as far as the loop guard
// needs (loop-guard.js): where each loop starts and ends, where its condition is, which `break`
// leaves it, and where `main`'s body closes. Expressions and declarations are read as runs of
// balanced tokens up to their `;`: their inside does not matter here. The text must have been
// preprocessed (no macros, no comments; `#extension` and `#pragma` lines are skipped).

/** A span of the text, as offsets [start, end). @typedef {{start: number, end: number}} Span */

/**
 * One loop: its keyword, the span of the whole statement (from `for`, `while` or `do` to the end
 * of its body, or of a `do`'s `;`), a `for`'s init statement (without its `;`; null when empty),
 * its condition (null: `for (;;)`), the `break` statements that leave it, and how many loops and
 * switches it is inside.
 * @typedef {Span & {kind: 'for' | 'while' | 'do', init: Span | null, condition: Span | null, breaks: Span[], depth: number}} LoopStatement
 */

/** @typedef {{text: string, start: number, end: number}} Token */

const TOKEN =
  /\s+|#[^\n]*|0[xX][0-9a-fA-F]+[uU]?|(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?[uUfF]?|[A-Za-z_]\w*|\+\+|--|<<=?|>>=?|&&|\|\||[-+*/%<>=!&|^]=?|./gs;

/** @param {string} text @returns {Token[]} */
function tokenize(text) {
  /** @type {Token[]} */
  const tokens = [];
  for (const match of text.matchAll(TOKEN)) {
    const [word] = match;
    if (/^\s/.test(word) || word.startsWith('#')) continue;
    tokens.push({ text: word, start: /** @type {number} */ (match.index), end: /** @type {number} */ (match.index) + word.length });
  }
  return tokens;
}

const CLOSERS = /** @type {Record<string, string>} */ ({ '(': ')', '[': ']', '{': '}' });

/**
 * The loops of `text` and the offset of the `}` that closes `main` (null: no `main`).
 * Throws where the text is not statements as GLSL has them (an unbalanced bracket, a loop
 * without its parts).
 * @param {string} text
 * @returns {{loops: LoopStatement[], mainEnd: number | null}}
 */
export function readStatements(text) {
  const tokens = tokenize(text);
  /** @type {LoopStatement[]} */
  const loops = [];
  let mainEnd = null;
  let at = 0;

  const peek = (offset = 0) => tokens[at + offset]?.text;
  const fail = (/** @type {string} */ what) => {
    const token = tokens[at];
    const line = token ? text.slice(0, token.start).split('\n').length : 'end';
    throw new Error(`${what} at line ${line} of the preprocessed text`);
  };
  const expect = (/** @type {string} */ word) => {
    if (peek() !== word) fail(`expected "${word}", found "${peek() ?? 'the end'}"`);
    return tokens[at++];
  };
  /** Skips a balanced bracket from its opener; returns the closer's token. */
  const skipBalanced = () => {
    const stack = [CLOSERS[tokens[at].text]];
    at++;
    while (stack.length) {
      const word = peek();
      if (word === undefined) fail('an unclosed bracket');
      if (word in CLOSERS) stack.push(CLOSERS[word]);
      else if (word === ')' || word === ']' || word === '}') {
        if (stack.pop() !== word) fail(`an unbalanced "${word}"`);
      }
      at++;
    }
    return tokens[at - 1];
  };
  /** Skips to (and past) the `;` that ends a simple statement; returns it. */
  const skipToSemicolon = () => {
    for (;;) {
      const word = peek();
      if (word === undefined) fail('a statement without its ";"');
      if (word === ';') return tokens[at++];
      if (word in CLOSERS) skipBalanced();
      else if (word === '}' || word === ')' || word === ']') fail(`an unbalanced "${word}"`);
      else at++;
    }
  };
  /** Skips a parenthesis from its `(`; returns the span of what is inside (null: nothing). */
  const parenthesised = () => {
    if (peek() !== '(') fail(`expected "(", found "${peek() ?? 'the end'}"`);
    const first = at + 1;
    skipBalanced();
    const last = at - 2;
    return last >= first ? { start: tokens[first].start, end: tokens[last].end } : null;
  };

  /**
   * One statement from `at`; returns the offset where it ends.
   * @param {Array<LoopStatement | null>} targets what a `break` leaves, innermost last (null: a switch)
   * @returns {number}
   */
  function statement(targets) {
    const token = tokens[at];
    if (!token) fail('a missing statement');
    const depth = targets.length;
    switch (token.text) {
      case '{':
        at++;
        while (peek() !== '}') {
          if (peek() === undefined) fail('an unclosed "{"');
          statement(targets);
        }
        return tokens[at++].end;
      case 'if': {
        at++;
        parenthesised();
        let end = statement(targets);
        if (peek() === 'else') {
          at++;
          end = statement(targets);
        }
        return end;
      }
      case 'switch': {
        at++;
        parenthesised();
        expect('{');
        const inner = [...targets, null];
        while (peek() !== '}') {
          if (peek() === undefined) fail('an unclosed switch');
          if (peek() === 'case' || peek() === 'default') {
            while (peek() !== ':') {
              if (peek() === undefined) fail('a case without its ":"');
              if (peek() in CLOSERS) skipBalanced();
              else at++;
            }
            at++;
          } else statement(inner);
        }
        return tokens[at++].end;
      }
      case 'break': {
        at++;
        const semi = expect(';');
        const target = targets[targets.length - 1];
        if (target) target.breaks.push({ start: token.start, end: semi.end });
        return semi.end;
      }
      case 'for':
      case 'while': {
        /** @type {LoopStatement} */
        const loop = {
          kind: token.text === 'for' ? 'for' : 'while',
          start: token.start,
          end: 0,
          init: null,
          condition: null,
          breaks: [],
          depth,
        };
        at++;
        if (token.text === 'for') {
          expect('(');
          /** @type {Token[][]} */
          const parts = [[]];
          let level = 0;
          for (;;) {
            const part = tokens[at];
            if (!part) fail('an unclosed for (');
            if (part.text in CLOSERS) level++;
            else if (part.text === ')' || part.text === ']' || part.text === '}') {
              if (level === 0) break;
              level--;
            }
            if (level === 0 && part.text === ';') parts.push([]);
            else parts[parts.length - 1].push(part);
            at++;
          }
          if (parts.length !== 3) fail(`a for ( with ${parts.length - 1} ";" where it takes 2`);
          expect(')');
          const span = (/** @type {Token[]} */ part) => (part.length ? { start: part[0].start, end: part[part.length - 1].end } : null);
          loop.init = span(parts[0]);
          loop.condition = span(parts[1]);
        } else loop.condition = parenthesised();
        loop.end = statement([...targets, loop]);
        loops.push(loop);
        return loop.end;
      }
      case 'do': {
        /** @type {LoopStatement} */
        const loop = { kind: 'do', start: token.start, end: 0, init: null, condition: null, breaks: [], depth };
        at++;
        statement([...targets, loop]);
        expect('while');
        loop.condition = parenthesised();
        loop.end = expect(';').end;
        loops.push(loop);
        return loop.end;
      }
      default:
        return skipToSemicolon().end;
    }
  }

  // the top level: declarations (structs and interface blocks among them) and functions, whose
  // body is the `{` after a parameter list
  while (at < tokens.length) {
    const word = peek();
    if (word === '(') {
      const name = tokens[at - 1]?.text;
      skipBalanced();
      if (peek() === '{') {
        statement([]);
        if (name === 'main') mainEnd = tokens[at - 1].start;
      }
    } else if (word in CLOSERS) skipBalanced();
    else at++;
  }
  return { loops, mainEnd };
}

/** GLSL's built-in functions and constructors that a condition may call and stay free of side effects. */
const PURE_CALLS = new Set(
  (
    'float int uint bool vec2 vec3 vec4 ivec2 ivec3 ivec4 uvec2 uvec3 uvec4 bvec2 bvec3 bvec4 mat2 mat3 mat4 ' +
    'mat2x2 mat2x3 mat2x4 mat3x2 mat3x3 mat3x4 mat4x2 mat4x3 mat4x4 radians degrees sin cos tan asin acos atan ' +
    'sinh cosh tanh asinh acosh atanh pow exp log exp2 log2 sqrt inversesqrt abs sign floor trunc round roundEven ' +
    'ceil fract mod min max clamp mix step smoothstep isnan isinf floatBitsToInt floatBitsToUint intBitsToFloat ' +
    'uintBitsToFloat length distance dot cross normalize faceforward reflect refract matrixCompMult outerProduct ' +
    'transpose determinant inverse lessThan lessThanEqual greaterThan greaterThanEqual equal notEqual any all not ' +
    'textureSize texture textureProj textureLod textureOffset texelFetch texelFetchOffset textureProjOffset ' +
    'textureLodOffset textureProjLod textureProjLodOffset textureGrad textureGradOffset textureProjGrad ' +
    'textureProjGradOffset'
  ).split(' '),
);

/**
 * Whether an expression has no side effects: no assignment, increment or decrement, and no call
 * but of GLSL's built-ins (a function of the shader's own may write a global).
 * @param {string} expression
 */
export function sideEffectFree(expression) {
  const tokens = tokenize(expression);
  return tokens.every(({ text }, i) => {
    if (/^(?:[-+*/%&|^]|<<|>>)?=$/.test(text) || text === '++' || text === '--') return false;
    return !(tokens[i + 1]?.text === '(' && /^[A-Za-z_]/.test(text) && !PURE_CALLS.has(text));
  });
}
