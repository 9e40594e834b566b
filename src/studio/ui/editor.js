// The editor panel: the running shader's source in CodeMirror 6 (C-family highlighting for GLSL,
// bracket matching, search with Ctrl+F, undo history, Tab indents; Esc then Tab moves focus on,
// as CodeMirror documents), one tab per pass of a multipass shader (Common, Buffer A–D, Image:
// editor-tabs.js), each tab a document of its own with its own undo history. Pasting a shader
// into it runs the whole shader at once (a paste of Shadertoy's JSON export loads that shader);
// after typing, Ctrl+Enter (⌘+Enter, Alt+Enter) or the "Compile" button runs every tab. Compile
// errors are lint diagnostics at their lines in their tab, with a marker in the gutter.

import { basicSetup } from 'codemirror';
import { cpp } from '@codemirror/lang-cpp';
import { indentWithTab } from '@codemirror/commands';
import { indentUnit } from '@codemirror/language';
import { lintGutter, setDiagnostics } from '@codemirror/lint';
import { search } from '@codemirror/search';
import { Compartment, EditorState, Prec } from '@codemirror/state';
import { EditorView, keymap } from '@codemirror/view';
import { oneDark } from '@codemirror/theme-one-dark';
import { TabBar } from './editor-tabs.js';
import { looksLikeJson, projectTabs, withTabTexts } from '../../player/io/project-files.js';
import { singlePass } from '../../shadertoy/multipass.js';

/** @typedef {{severity?: string, pass?: string | null, line: number | null, message: string}} ShaderMessage */
/** @typedef {import('../../shadertoy/multipass.js').MultipassShader} MultipassShader */

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

/** The tab a compiler message belongs to: its pass, or the Image tab for a single-pass shader. */
const tabOf = (/** @type {ShaderMessage} */ m) => m.pass ?? 'Image';

/**
 * Whether messages[i] is the first of its kind (a Common tab's error comes once from every pass
 * that includes it).
 * @param {ShaderMessage[]} messages
 * @param {number} i
 */
function firstOfItsKind(messages, i) {
  const m = messages[i];
  return messages.findIndex((o) => o.pass === m.pass && o.line === m.line && o.message === m.message) === i;
}

export class Editor {
  /**
   * @param {HTMLElement} root the editor's (hidden) container
   * @param {object} actions
   * @param {(project: MultipassShader, pasted: boolean) => void} actions.apply runs the edited
   *   shader, every tab (`pasted`: a paste replaced the whole of a single-pass shader)
   * @param {(text: string) => void} [actions.pasteJson] a paste left a tab holding JSON (a
   *   Shadertoy export): load it
   * @param {(open: boolean) => void} [actions.onToggle]
   * @param {(project: MultipassShader, typed: boolean, pastedOver?: boolean) => void} [actions.onChange] a tab's
   *   text changed: typed or pasted by the user (`typed`; `pastedOver`: a paste replaced the whole
   *   of a single-pass shader), or set with a new shader
   */
  constructor(root, { apply, pasteJson = () => {}, onToggle = () => {}, onChange = () => {} }) {
    this.root = root;
    this.onToggle = onToggle;
    this.onChange = onChange;
    /** Set while setProject puts a new shader in the tabs. */
    this._settingProject = false;
    root.setAttribute('aria-label', 'Shader editor');
    /** The shader the tabs were made from (its channels ride along with the edits). */
    this.model = singlePass('');
    /** Each tab's document, with its undo history; the shown one's is in the view. @type {Array<{name: string, state: EditorState}>} */
    this.tabs = [];
    this.active = 'Image';

    const header = document.createElement('div');
    header.className = 'editor-header';
    this.title = document.createElement('span');
    this.title.className = 'editor-title';
    const hint = document.createElement('span');
    hint.className = 'editor-hint';
    hint.textContent = 'Paste a shader (or Shadertoy JSON), or edit and press Ctrl+Enter · Tab indents, Esc then Tab leaves';
    const compile = document.createElement('button');
    compile.type = 'button';
    compile.textContent = 'Compile';
    compile.title = 'Run this source, every tab (Ctrl+Enter)';
    compile.addEventListener('click', () => apply(this.project(), false));
    const close = document.createElement('button');
    close.type = 'button';
    close.setAttribute('aria-label', 'Close editor');
    close.textContent = '✕';
    close.addEventListener('click', () => this.toggle(false));
    // long lines wrap by default: the editor beside the canvas is narrower than many shaders' lines
    this.wrapping = new Compartment();
    this.wrapButton = document.createElement('button');
    this.wrapButton.type = 'button';
    this.wrapButton.textContent = 'Wrap';
    this.wrapButton.title = 'Wrap long lines (the editor can also be made wider: drag its lower right corner)';
    this.wrapButton.setAttribute('aria-pressed', 'true');
    this.wrapButton.addEventListener('click', () => this.setWrap(this.wrapButton.getAttribute('aria-pressed') !== 'true'));
    header.append(this.title, hint, this.wrapButton, compile, close);
    root.append(header);
    this.tabBar = new TabBar(root, (name) => this.showTab(name));

    const body = document.createElement('div');
    body.className = 'editor-body';
    root.append(body);

    const run = () => {
      apply(this.project(), false);
      return true;
    };
    this.extensions = [
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
      this.wrapping.of(EditorView.lineWrapping),
      EditorView.contentAttributes.of({ 'aria-label': 'Shader source', spellcheck: 'false', autocapitalize: 'off' }),
      EditorView.updateListener.of((update) => {
        if (!update.docChanged || this._settingProject) return;
        const project = this.project();
        const paste = update.transactions.find((tr) => tr.isUserEvent('input.paste'));
        const whole = paste !== undefined && replacedAll(paste);
        // kept under its new name at once: a paste over a whole single-pass shader is a new one
        this.onChange(project, true, whole && this.tabs.length === 1);
        if (!paste) return;
        // a paste (of a whole shader, or any paste) runs what the editor then holds; JSON pasted
        // over a whole tab is a Shadertoy export
        const text = update.state.doc.toString();
        if (whole && looksLikeJson(text)) setTimeout(() => pasteJson(text), 0);
        // a paste over a whole single-pass shader is a new shader ("untitled"); over one tab of a
        // multipass one, an edit of that shader
        else setTimeout(() => apply(project, whole && this.tabs.length === 1), 0);
      }),
    ];
    this.view = new EditorView({ parent: body, state: this._newState('') });
    this.tabs = [{ name: 'Image', state: this.view.state }];
  }

  /**
   * Wraps long lines, or not, in every tab.
   * @param {boolean} on
   */
  setWrap(on) {
    this.wrapButton.setAttribute('aria-pressed', String(on));
    const effects = this.wrapping.reconfigure(on ? EditorView.lineWrapping : []);
    this.view.dispatch({ effects });
    for (const tab of this.tabs) if (tab.name !== this.active) tab.state = tab.state.update({ effects }).state;
    this._wrap = on;
  }

  /** @param {string} doc */
  _newState(doc) {
    if (this._wrap === false)
      return EditorState.create({ doc, extensions: this.extensions }).update({ effects: this.wrapping.reconfigure([]) }).state;
    return EditorState.create({ doc, extensions: this.extensions });
  }

  /** The shown tab's text. */
  get text() {
    return this.view.state.doc.toString();
  }

  /** The name of the shown tab ('Image' for a single-pass shader). */
  get activeTab() {
    return this.active;
  }

  /** Every tab's text, by name. @returns {Record<string, string>} */
  texts() {
    return Object.fromEntries(this.tabs.map((t) => [t.name, (t.name === this.active ? this.view.state : t.state).doc.toString()]));
  }

  /** The shader as edited: the loaded one with every tab's text as the editor holds it. */
  project() {
    return withTabTexts(this.model, this.texts());
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
   * Shows another tab (its own document, undo history and diagnostics).
   * @param {string} name
   */
  showTab(name) {
    const tab = this.tabs.find((t) => t.name === name);
    if (!tab || name === this.active) return;
    const current = this.tabs.find((t) => t.name === this.active);
    if (current) current.state = this.view.state;
    this.active = name;
    this.view.setState(tab.state);
    this.tabBar.select(name);
    this.root.dataset.tab = name;
  }

  /**
   * Shows a shader (a new one was loaded elsewhere): one tab per pass. A tab whose text is already
   * there is left alone (with its undo history); one whose text differs gets the new text as an
   * edit (Ctrl+Z brings the old back).
   * @param {MultipassShader} model
   * @param {string} name
   */
  setProject(model, name) {
    this.title.textContent = name;
    this.model = model;
    this._settingProject = true; // one onChange after, with every tab's new text
    const current = this.tabs.find((t) => t.name === this.active);
    if (current) current.state = this.view.state;
    let changed = false;
    this.tabs = projectTabs(model).map(({ name: tab, code }) => {
      const old = this.tabs.find((t) => t.name === tab);
      if (!old) {
        changed = true;
        return { name: tab, state: this._newState(code) };
      }
      if (old.state.doc.toString() === code) return old;
      changed = true;
      if (tab === this.active) {
        this.view.dispatch({ changes: { from: 0, to: this.view.state.doc.length, insert: code } });
        return { name: tab, state: this.view.state };
      }
      return { name: tab, state: old.state.update({ changes: { from: 0, to: old.state.doc.length, insert: code } }).state };
    });
    const names = this.tabs.map((t) => t.name);
    if (!names.includes(this.active)) {
      this.active = 'Image';
      this.view.setState(/** @type {{state: EditorState}} */ (this.tabs.find((t) => t.name === 'Image')).state);
    }
    this.tabBar.setTabs(names, this.active);
    this.root.dataset.tab = this.active;
    this._settingProject = false;
    if (changed) {
      this.setErrors([]);
      this.onChange(this.project(), false);
    }
  }

  /**
   * Shows compile errors as diagnostics at their lines, in their tabs ([] clears them). Messages
   * without a line in a tab (about generated code) are in the error box only.
   * @param {ShaderMessage[]} messages
   */
  setErrors(messages) {
    const withErrors = new Set();
    for (const tab of this.tabs) {
      const shown = tab.name === this.active;
      const state = shown ? this.view.state : tab.state;
      const doc = state.doc;
      const diagnostics = messages
        .filter((m, i) => tabOf(m) === tab.name && m.line && m.line <= doc.lines && firstOfItsKind(messages, i))
        .map((m) => {
          const line = doc.line(/** @type {number} */ (m.line));
          const severity = /** @type {'error' | 'warning'} */ (m.severity === 'warning' ? 'warning' : 'error');
          if (severity === 'error') withErrors.add(tab.name);
          return { from: line.from, to: line.to, severity, message: m.message, source: 'GLSL compiler' };
        });
      const spec = setDiagnostics(state, diagnostics);
      if (shown) this.view.dispatch(spec);
      else tab.state = state.update(spec).state;
    }
    this.tabBar.markErrors(withErrors);
  }

  /**
   * Opens the editor on a tab with the cursor at the start of a line (1-based), scrolled into view.
   * @param {number} line
   * @param {string | null} [pass] the tab (null or absent: the Image tab, a single-pass shader's)
   */
  goToLine(line, pass = null) {
    if (!this.open) this.toggle(true);
    this.showTab(pass ?? 'Image');
    const doc = this.view.state.doc;
    const at = doc.line(Math.min(Math.max(1, line), doc.lines)).from;
    this.view.dispatch({ selection: { anchor: at }, effects: EditorView.scrollIntoView(at, { y: 'center' }) });
    this.view.focus();
  }
}
