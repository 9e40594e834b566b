// The message box over the canvas: compile errors and fatal problems (role="alert", so screen
// readers announce it and tests can find it).

export class Overlay {
  /** @param {HTMLElement} element */
  constructor(element) {
    this.element = element;
    this.element.setAttribute('role', 'alert');
    /**
     * Shows a line of the shader, in a tab of a multipass one (pass null: a single-pass shader's
     * file); set by the page once the editor exists.
     * @type {((line: number, pass: string | null) => void) | null}
     */
    this.onLine = null;
    this.hide();
  }

  show(title, detail = '') {
    this.element.replaceChildren();
    const heading = document.createElement('strong');
    heading.textContent = title;
    this.element.append(heading);
    if (detail) {
      const pre = document.createElement('pre');
      pre.textContent = detail;
      this.element.append(pre);
    }
    this.element.hidden = false;
  }

  /** Writes the shown message's detail again (its buttons and focus stay). @param {string} detail */
  setDetail(detail) {
    const pre = this.element.querySelector('pre');
    if (pre && pre.textContent !== detail) pre.textContent = detail;
  }

  /**
   * A message with buttons under it.
   * @param {string} title
   * @param {string} detail
   * @param {Array<{label: string, run: () => void}>} actions
   */
  showActions(title, detail, actions) {
    this.show(title, detail);
    const row = document.createElement('p');
    for (const { label, run } of actions) {
      const button = document.createElement('button');
      button.type = 'button';
      button.textContent = label;
      button.addEventListener('click', run);
      row.append(button);
    }
    this.element.append(row);
  }

  /**
   * Compile errors: one entry a message; a message at a line of the file (or of a tab: `pass`) is
   * a button that calls `this.onLine(line, pass)` (the page opens the editor there).
   * @param {string} title
   * @param {Array<{line: number | null, pass?: string | null}>} messages
   * @param {(message: any) => string} format a message's text
   */
  showMessages(title, messages, format) {
    const onLine = this.onLine;
    this.show(title);
    const list = document.createElement('pre');
    const said = new Set(); // a Common tab's error comes once from every pass that includes it
    for (const message of messages) {
      const text = format(message);
      if (said.has(text)) continue;
      said.add(text);
      if (message.line === null || !onLine) {
        list.append(text, '\n');
        continue;
      }
      const link = document.createElement('button');
      link.type = 'button';
      link.className = 'error-line';
      const line = message.line;
      const pass = message.pass ?? null;
      link.title = pass ? `Show line ${line} of ${pass} in the editor` : `Show line ${line} in the editor`;
      link.textContent = text;
      link.addEventListener('click', () => onLine(line, pass));
      list.append(link, '\n');
    }
    this.element.append(list);
  }

  hide() {
    this.element.hidden = true;
    this.element.replaceChildren();
  }
}
