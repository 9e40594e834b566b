// The editor panel: the running shader's source in CodeMirror 6 (C-family highlighting for GLSL,
// bracket matching, search with Ctrl+F, undo history, Tab indents; Esc then Tab moves focus on,
// as CodeMirror documents). Pasting a shader into it runs that shader at once; after typing,
// Ctrl+Enter (⌘+Enter, Alt+Enter) or the "Compile" button runs it. Compile errors are lint
// diagnostics at their lines, with a marker in the gutter.

import { basicSetup } from 'codemirror';
import { cpp } from '@codemirror/lang-cpp';
import { indentWithTab } from '@codemirror/commands';
import { indentUnit } from '@codemirror/language';
import { lintGutter, setDiagnostics } from '@codemirror/lint';
import { search } from '@codemirror/search';
import { Prec } from '@codemirror/state';
import { EditorView, keymap } from '@codemirror/view';
import { oneDark } from '@codemirror/theme-one-dark';

/** @typedef {{severity?: string, line: number | null, message: string}} ShaderMessage */

/**
 * Whether a transaction replaced the whole document (a paste over everything, or into nothing).
 * @param {import('@codemirror/state').Transaction} tr
 */
function replacedAll(tr) {
  let all = false;
  tr.changes.iterChanges((fromA, toA) => {
    if (fromA === 0 && toA === tr.startState.doc.length) all = true;
  });
  return all;
}

export class Editor {
  /**
   * @param {HTMLElement} root the editor's (hidden) container
   * @param {object} actions
   * @param {(source: string, pasted: boolean) => void} actions.apply runs a source (`pasted`: a
   *   paste replaced the whole text)
   * @param {(open: boolean) => void} [actions.onToggle]
   * @param {(source: string) => void} [actions.onChange] the text changed (typed, pasted or set)
   */
  constructor(root, { apply, onToggle = () => {}, onChange = () => {} }) {
    this.root = root;
    this.onToggle = onToggle;
    root.setAttribute('aria-label', 'Shader editor');

    const header = document.createElement('div');
    header.className = 'editor-header';
    this.title = document.createElement('span');
    this.title.className = 'editor-title';
    const hint = document.createElement('span');
    hint.className = 'editor-hint';
    hint.textContent = 'Paste a shader, or edit and press Ctrl+Enter · Tab indents, Esc then Tab leaves';
    const compile = document.createElement('button');
    compile.type = 'button';
    compile.textContent = 'Compile';
    compile.title = 'Run this source (Ctrl+Enter)';
    compile.addEventListener('click', () => apply(this.text, false));
    const close = document.createElement('button');
    close.type = 'button';
    close.setAttribute('aria-label', 'Close editor');
    close.textContent = '✕';
    close.addEventListener('click', () => this.toggle(false));
    header.append(this.title, hint, compile, close);

    const body = document.createElement('div');
    body.className = 'editor-body';
    root.append(header, body);

    const run = () => {
      apply(this.text, false);
      return true;
    };
    this.view = new EditorView({
      parent: body,
      extensions: [
        Prec.highest(
          keymap.of([
            { key: 'Mod-Enter', run },
            { key: 'Alt-Enter', run },
          ]),
        ),
        basicSetup,
        lintGutter(),
        keymap.of([indentWithTab]),
        search({ top: true }),
        cpp(),
        indentUnit.of('    '), // as Shadertoy's shaders are written
        oneDark,
        EditorView.contentAttributes.of({ 'aria-label': 'Shader source', spellcheck: 'false', autocapitalize: 'off' }),
        EditorView.updateListener.of((update) => {
          if (!update.docChanged) return;
          const text = update.state.doc.toString();
          onChange(text);
          const paste = update.transactions.find((tr) => tr.isUserEvent('input.paste'));
          // a paste (of a whole shader, or any paste) runs what the editor then holds
          if (paste) setTimeout(() => apply(text, replacedAll(paste)), 0);
        }),
      ],
    });
  }

  /** The editor's text. */
  get text() {
    return this.view.state.doc.toString();
  }

  get open() {
    return !this.root.hidden;
  }

  toggle(open = !this.open) {
    this.root.hidden = !open;
    document.body.classList.toggle('editing', open);
    if (open) this.view.focus();
    this.onToggle(open);
  }

  /**
   * Shows a source (a new shader was loaded elsewhere) unless it is the one already there.
   * @param {string} source
   * @param {string} name
   */
  setSource(source, name) {
    this.title.textContent = name;
    if (this.text !== source) {
      this.view.dispatch({ changes: { from: 0, to: this.view.state.doc.length, insert: source } });
      this.setErrors([]);
    }
  }

  /**
   * Shows compile errors as diagnostics at their lines ([] clears them). Messages without a line
   * in the file (about generated code) are in the error box only.
   * @param {ShaderMessage[]} messages
   */
  setErrors(messages) {
    const doc = this.view.state.doc;
    const diagnostics = messages
      .filter((m) => m.line && m.line <= doc.lines)
      .map((m) => {
        const line = doc.line(/** @type {number} */ (m.line));
        const severity = /** @type {'error' | 'warning'} */ (m.severity === 'warning' ? 'warning' : 'error');
        return { from: line.from, to: line.to, severity, message: m.message, source: 'GLSL compiler' };
      });
    this.view.dispatch(setDiagnostics(this.view.state, diagnostics));
  }

  /**
   * Opens the editor with the cursor at the start of a line (1-based), scrolled into view.
   * @param {number} line
   */
  goToLine(line) {
    if (!this.open) this.toggle(true);
    const doc = this.view.state.doc;
    const at = doc.line(Math.min(Math.max(1, line), doc.lines)).from;
    this.view.dispatch({ selection: { anchor: at }, effects: EditorView.scrollIntoView(at, { y: 'center' }) });
    this.view.focus();
  }
}
