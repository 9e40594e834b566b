// The editor's tab bar: one tab per pass of a multipass shader (Common, Buffer A–D, Image), as an
// ARIA tab list (the arrow keys move between tabs). A tab whose pass has compile errors is
// marked. Hidden for a single-pass shader, which looks as it always did.

export class TabBar {
  /**
   * @param {HTMLElement} parent where the bar goes
   * @param {(name: string) => void} onSelect a tab was chosen
   */
  constructor(parent, onSelect) {
    this.onSelect = onSelect;
    this.root = document.createElement('div');
    this.root.className = 'editor-tabs';
    this.root.setAttribute('role', 'tablist');
    this.root.setAttribute('aria-label', 'Shader passes');
    this.root.hidden = true;
    this.root.addEventListener('keydown', (event) => this._onKey(event));
    parent.append(this.root);
    /** @type {HTMLButtonElement[]} */
    this.buttons = [];
  }

  /**
   * Shows these tabs (hidden when there is only one), `active` selected.
   * @param {string[]} names
   * @param {string} active
   */
  setTabs(names, active) {
    this.root.hidden = names.length < 2;
    if (this.buttons.map((b) => b.dataset.tab).join('\n') !== names.join('\n')) {
      this.buttons = names.map((name) => {
        const button = document.createElement('button');
        button.type = 'button';
        button.setAttribute('role', 'tab');
        button.dataset.tab = name;
        button.textContent = name;
        button.addEventListener('click', () => this.onSelect(name));
        return button;
      });
      this.root.replaceChildren(...this.buttons);
    }
    this.select(active);
  }

  /** Marks `name` as the selected tab. @param {string} name */
  select(name) {
    for (const b of this.buttons) {
      const selected = b.dataset.tab === name;
      b.setAttribute('aria-selected', String(selected));
      b.tabIndex = selected ? 0 : -1;
    }
  }

  /**
   * Marks the tabs that have compile errors.
   * @param {Set<string>} names
   */
  markErrors(names) {
    for (const b of this.buttons) {
      const bad = names.has(/** @type {string} */ (b.dataset.tab));
      b.classList.toggle('has-errors', bad);
      b.title = bad ? `${b.dataset.tab}: has compile errors` : '';
    }
  }

  /** Left and right arrows (Home, End) move between tabs, as an ARIA tab list does. */
  _onKey(event) {
    const at = this.buttons.indexOf(/** @type {HTMLButtonElement} */ (event.target));
    if (at < 0) return;
    const last = this.buttons.length - 1;
    const to = { ArrowLeft: at - 1, ArrowRight: at + 1, Home: 0, End: last }[event.key];
    if (to === undefined) return;
    event.preventDefault();
    const next = this.buttons[(to + this.buttons.length) % this.buttons.length];
    this.onSelect(/** @type {string} */ (next.dataset.tab));
    next.focus();
  }
}
