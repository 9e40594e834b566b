// The editor panel: the running shader's source in a text area with line numbers. Pasting a
// shader into it runs that shader at once; after typing, Ctrl+Enter (⌘+Enter, Alt+Enter) or the
// "Compile" button runs it. Lines with compile errors are marked in the gutter.

export class Editor {
  /**
   * @param {HTMLElement} root the editor's (hidden) container
   * @param {{apply: (source: string) => void, onToggle?: (open: boolean) => void}} actions
   */
  constructor(root, { apply, onToggle = () => {} }) {
    this.root = root;
    this.onToggle = onToggle;
    root.setAttribute('aria-label', 'Shader editor');

    const header = document.createElement('div');
    header.className = 'editor-header';
    this.title = document.createElement('span');
    this.title.className = 'editor-title';
    const hint = document.createElement('span');
    hint.className = 'editor-hint';
    hint.textContent = 'Paste a shader, or edit and press Ctrl+Enter';
    const compile = document.createElement('button');
    compile.type = 'button';
    compile.textContent = 'Compile';
    compile.title = 'Run this source (Ctrl+Enter)';
    compile.addEventListener('click', () => apply(this.text.value));
    const close = document.createElement('button');
    close.type = 'button';
    close.setAttribute('aria-label', 'Close editor');
    close.textContent = '✕';
    close.addEventListener('click', () => this.toggle(false));
    header.append(this.title, hint, compile, close);

    const body = document.createElement('div');
    body.className = 'editor-body';
    this.gutter = document.createElement('div');
    this.gutter.className = 'editor-gutter';
    this.gutter.setAttribute('aria-hidden', 'true');
    this.text = document.createElement('textarea');
    this.text.setAttribute('aria-label', 'Shader source');
    this.text.spellcheck = false;
    this.text.wrap = 'off';
    this.text.autocapitalize = 'off';
    this.text.setAttribute('autocomplete', 'off');
    body.append(this.gutter, this.text);
    root.append(header, body);

    this._errorLines = new Set();
    this.text.addEventListener('input', () => this._renderGutter());
    this.text.addEventListener('scroll', () => (this.gutter.scrollTop = this.text.scrollTop));
    this.text.addEventListener('keydown', (event) => {
      if (event.key === 'Enter' && (event.ctrlKey || event.metaKey || event.altKey)) {
        event.preventDefault();
        apply(this.text.value);
      } else if (event.key === 'Escape') {
        this.toggle(false);
      }
    });
    // a paste of a whole shader (or any paste) runs it once the text area has it
    this.text.addEventListener('paste', () => setTimeout(() => apply(this.text.value), 0));
  }

  get open() {
    return !this.root.hidden;
  }

  toggle(open = !this.open) {
    this.root.hidden = !open;
    document.body.classList.toggle('editing', open);
    if (open) this.text.focus({ preventScroll: true });
    this.onToggle(open);
  }

  /** Shows a source (a new shader was loaded elsewhere) unless it is the one already there. */
  setSource(source, name) {
    this.title.textContent = name;
    if (this.text.value !== source) {
      this.text.value = source;
      this._errorLines.clear();
      this._renderGutter();
    }
  }

  /** Marks the lines of compile errors ([] clears them). */
  setErrors(messages) {
    this._errorLines = new Set(messages.filter((m) => m.line).map((m) => m.line));
    this._renderGutter();
  }

  _renderGutter() {
    const count = this.text.value.split('\n').length;
    const lines = [];
    for (let i = 1; i <= count; i++) {
      lines.push(this._errorLines.has(i) ? `<span class="error">${i}</span>` : String(i));
    }
    this.gutter.innerHTML = lines.join('\n') + '\n';
    this.gutter.scrollTop = this.text.scrollTop;
  }
}
