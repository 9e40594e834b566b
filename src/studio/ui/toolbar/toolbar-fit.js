// The toolbar fitted to the window (issue 36, item 9): at most two rows, each button's label on
// one line. Measured, not guessed from a width: the buttons keep their labels where the rows
// have room for them; else they show their icons only (each keeps its accessible name and its
// tooltip); and where even the icons do not fit (a phone), the least used go into a "More" menu,
// a popover above the toolbar, where they keep their labels. Fitted again when the window's size
// or the shader's name changes; never on what the frame-time line says (style.css gives it a
// fixed room), so buttons do not move while a shader plays.

import { element, placeAbove } from '../dom.js';

/** The output buttons that go into the "More" menu first, by accessible name. */
const OVERFLOW_ORDER = [
  'Export JSON',
  'Compare with float64',
  'Copy for Shadertoy',
  'Fullscreen',
  'Copy link',
  'Download .glsl',
  'Record',
  'Screenshot',
  'Inspect',
  'Edit shader',
];

const MAX_ROWS = 2;

const shown = (/** @type {Element} */ e) => e.getClientRects().length > 0;

export class ToolbarFit {
  /**
   * @param {HTMLElement} root the toolbar
   * @param {HTMLElement} outputs its group of output buttons, where the "More" button goes
   */
  constructor(root, outputs) {
    this.root = root;
    this.outputs = outputs;
    this.moreButton = element(
      'button',
      {
        type: 'button',
        class: 'more',
        'aria-label': 'More actions',
        title: 'More actions: the buttons the toolbar has no room for here',
        'aria-expanded': 'false',
        hidden: true,
      },
      '⋯',
    );
    this.menu = element('div', { class: 'toolbar-more', role: 'group', 'aria-label': 'More actions', hidden: true });
    outputs.append(this.moreButton);
    document.body.append(this.menu);
    /** Each button in the menu, and the mark where it goes back in the toolbar. @type {Map<HTMLElement, Comment>} */
    this._places = new Map();

    this.moreButton.addEventListener('click', () => (this.menu.hidden ? this.openMenu() : this.closeMenu()));
    this.menu.addEventListener('click', (event) => {
      if (/** @type {Element} */ (event.target).closest('button')) this.closeMenu();
    });
    this.menu.addEventListener('keydown', (event) => {
      if (event.key !== 'Escape') return;
      event.preventDefault();
      this.closeMenu();
      this.moreButton.focus();
    });
    document.addEventListener('pointerdown', (event) => {
      const target = /** @type {Node} */ (event.target);
      if (!this.menu.hidden && !this.menu.contains(target) && !this.moreButton.contains(target)) this.closeMenu();
    });
    window.addEventListener('resize', () => this.fit());
  }

  openMenu() {
    this.menu.hidden = false;
    this.moreButton.setAttribute('aria-expanded', 'true');
    placeAbove(this.menu, this.root);
    /** @type {HTMLElement | null} */ (this.menu.querySelector('button'))?.focus();
  }

  closeMenu() {
    this.menu.hidden = true;
    this.moreButton.setAttribute('aria-expanded', 'false');
  }

  /** Lays the toolbar out again: labels, else icons, else icons and a "More" menu. */
  fit() {
    for (const [button, mark] of this._places) mark.replaceWith(button);
    this._places.clear();
    this.moreButton.hidden = true;
    this.root.classList.remove('icons-only');
    if (!this._fits()) this.root.classList.add('icons-only');
    if (!this._fits()) {
      this.moreButton.hidden = false;
      for (const name of OVERFLOW_ORDER) {
        const button = /** @type {HTMLElement | null} */ (this.outputs.querySelector(`:scope > button[aria-label="${name}"]`));
        if (!button) continue;
        const mark = document.createComment(name);
        button.replaceWith(mark);
        this._places.set(button, mark);
        if (this._fits()) break;
      }
    }
    // the menu lists its buttons in the toolbar's order
    const moved = [...this._places].sort(([, a], [, b]) => (a.compareDocumentPosition(b) & Node.DOCUMENT_POSITION_FOLLOWING ? -1 : 1));
    this.menu.replaceChildren(...moved.map(([button]) => button));
    if (!moved.length) this.closeMenu();
    else if (!this.menu.hidden) placeAbove(this.menu, this.root);
  }

  /** Whether the toolbar's groups lie in at most two rows, none past its right edge. */
  _fits() {
    const style = getComputedStyle(this.root);
    const box = this.root.getBoundingClientRect();
    const right = box.right - parseFloat(style.paddingRight) - parseFloat(style.borderRightWidth) + 0.5;
    const groups = [...this.root.children].filter(shown);
    // a row's groups are centred on one line (style.css: align-items: center)
    const rows = new Set(
      groups.map((g) => {
        const r = g.getBoundingClientRect();
        return Math.round((r.top + r.bottom) / 2);
      }),
    );
    const items = [...this.root.querySelectorAll('.group > *')].filter(shown);
    return rows.size <= MAX_ROWS && items.every((e) => e.getBoundingClientRect().right <= right);
  }
}
