// The message box over the canvas: compile errors and fatal problems (role="alert", so screen
// readers announce it and tests can find it).

export class Overlay {
  /** @param {HTMLElement} element */
  constructor(element) {
    this.element = element;
    this.element.setAttribute('role', 'alert');
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

  hide() {
    this.element.hidden = true;
    this.element.replaceChildren();
  }
}
