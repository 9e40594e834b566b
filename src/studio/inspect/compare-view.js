// The comparison with float64 on the page (its state is compare.js): while it runs, a box at the
// upper left of the canvas says what it is doing, with a progress bar for the reference's rows and
// Cancel; after, the heat map of each pixel's error lies over the canvas (heat-map.js: 1/255
// steps, on a logarithmic scale, with its legend), with its figures: RMSE, the largest error and
// the share of pixels over 2/255, for the float32 colours and for the 8-bit pixels the canvas
// shows (`npm run accuracy`'s measure). A click on the map pins that pixel in the inspector.

import { element } from '../ui/dom.js';
import { HIGH, LOW, TICKS, heatMapPixels, scaleGradient, scalePosition } from './heat-map.js';
import { pixelAt } from './loupe.js';

/** @typedef {import('./compare.js').Comparison} Comparison */
/** @typedef {import('./compare.js').ComparisonResult} ComparisonResult */
/** @typedef {import('./compare.js').ImageError} ImageError */

const percent = (/** @type {number} */ f) => `${(100 * f).toFixed(3)}%`;
const steps = (/** @type {number} */ v) => `${(v * 255).toFixed(v * 255 < 0.1 ? 4 : 2)}/255`;

export class CompareView {
  /**
   * @param {HTMLElement} stage
   * @param {HTMLCanvasElement} canvas the page's canvas, which the map covers exactly
   * @param {Comparison} comparison
   * @param {{pin: (x: number, y: number) => void, compare: () => void}} actions
   */
  constructor(stage, canvas, comparison, actions) {
    this.stage = stage;
    this.canvas = canvas;
    this.comparison = comparison;
    /** Which error the map shows: the float32 colours or the canvas's bytes. @type {'float' | 'canvas'} */
    this.showing = 'float';
    this.map = element('canvas', { class: 'heat-map', hidden: true, title: 'Click a pixel to pin it in the inspector' });
    this.map.addEventListener('click', (event) => {
      const at = pixelAt(this.map, event.clientX, event.clientY);
      if (at) actions.pin(at.x, at.y);
    });
    this.phase = element('span', { class: 'phase' });
    this.bar = element('progress', { max: 1, value: 0 });
    this.cancel = element('button', { type: 'button' }, 'Cancel');
    this.cancel.addEventListener('click', () => comparison.cancel());
    this.progress = element('div', { class: 'compare-progress', role: 'status' }, this.phase, this.bar, this.cancel);
    this.figures = element('div', { class: 'compare-figures' });
    this.again = element('button', { type: 'button', title: 'Compare the frame on the canvas now' }, 'Compare again');
    this.again.addEventListener('click', () => actions.compare());
    this.toggle = element(
      'button',
      { type: 'button', 'aria-pressed': 'false', title: 'Show the error of the 8-bit pixels (the rounding included)' },
      '8-bit',
    );
    this.toggle.addEventListener('click', () => {
      this.showing = this.showing === 'float' ? 'canvas' : 'float';
      this.render();
    });
    this.hideMap = element('button', { type: 'button', 'aria-pressed': 'true', title: 'Show or hide the heat map over the canvas' }, 'Map');
    this.hideMap.addEventListener('click', () => {
      this.hideMap.setAttribute('aria-pressed', String(this.hideMap.getAttribute('aria-pressed') !== 'true'));
      this.render();
    });
    const close = element('button', { type: 'button', 'aria-label': 'Close the comparison' }, '✕');
    close.addEventListener('click', () => {
      comparison.cancel();
      comparison.clear();
    });
    this.root = element(
      'section',
      { class: 'compare', 'aria-label': 'Comparison with float64', hidden: true },
      element(
        'header',
        {},
        (this.title = element('strong', {}, 'Compared with float64')),
        element('span', { class: 'spacer' }),
        this.toggle,
        this.hideMap,
        this.again,
        close,
      ),
      element('div', { class: 'compare-body' }, this.progress, this.figures, (this.legend = legend())),
    );
    // on the page from the first comparison on (before, it would be one more <progress> there)
    /** The result drawn on the map, and which error. @type {[ComparisonResult, string] | null} */
    this._drawn = null;
    comparison.on('progress', () => this.render());
    comparison.on('result', () => this.render());
    // the canvas's box changes with the window, the editor beside it, the panel: before the
    // page is painted again, the map follows it or hides
    new ResizeObserver(() => this.place()).observe(canvas);
  }

  /**
   * Lays the map over the canvas's box (the canvas may be smaller than the stage: a fixed size),
   * or hides it: when there is none to show, and when it no longer matches the picture (out of
   * date, or a canvas of another shape, before the next frame says so). A map that does not
   * match is not left over the picture, dimmed or stretched.
   */
  place() {
    const { result, stale } = this.comparison;
    const mapOn = this.hideMap.getAttribute('aria-pressed') === 'true';
    const box = this.canvas.getBoundingClientRect();
    // the map's pixels over the canvas's box: within a CSS pixel of its shape, or not the picture
    const fits = result !== null && Math.abs((box.width * result.height) / result.width - box.height) <= 1;
    this.map.hidden = !result || !mapOn || stale || !fits;
    if (this.map.hidden) return;
    const stage = this.stage.getBoundingClientRect();
    Object.assign(this.map.style, {
      left: `${box.left - stage.left}px`,
      top: `${box.top - stage.top}px`,
      width: `${box.width}px`,
      height: `${box.height}px`,
    });
  }

  render() {
    const { comparison } = this;
    const { running, result, error } = comparison;
    this.root.hidden = !running && !result && !error;
    if (!this.root.hidden && !this.root.isConnected) this.stage.append(this.map, this.root);
    this.progress.hidden = !running;
    // a refusal (or a failure) with nothing measured is not a comparison: no map, no map controls
    const refused = !running && !result && Boolean(error);
    this.title.textContent = running ? 'Comparing with float64…' : refused ? 'Cannot compare with float64' : 'Compared with float64';
    this.toggle.hidden = !result;
    this.hideMap.hidden = !result;
    this.legend.hidden = !result;
    // one comparison at a time: another press would only start it again
    this.again.disabled = Boolean(running);
    this.again.title = running ? 'A comparison is under way (Cancel stops it)' : 'Compare the frame on the canvas now';
    if (running) {
      this.phase.textContent = running.of ? `${running.phase}: ${running.rows} of ${running.of} rows` : `${running.phase}…`;
      if (running.of) this.bar.value = running.rows / running.of;
      else this.bar.removeAttribute('value'); // indeterminate
    }
    this.toggle.setAttribute('aria-pressed', String(this.showing === 'canvas'));
    // an out-of-date map is hidden (place): its buttons would change nothing on the page
    this.toggle.disabled = this.hideMap.disabled = comparison.stale;
    if (result && (this._drawn?.[0] !== result || this._drawn[1] !== this.showing)) this._draw(result);
    this.place();
    this.figures.replaceChildren(...this._figures());
  }

  /** @param {ComparisonResult} result */
  _draw(result) {
    this.map.width = result.width;
    this.map.height = result.height;
    const error = this.showing === 'float' ? result.floatError : result.canvasError;
    const context = /** @type {CanvasRenderingContext2D} */ (this.map.getContext('2d'));
    context.putImageData(new ImageData(heatMapPixels(error, result.picture), result.width, result.height), 0, 0);
    this._drawn = [result, this.showing];
  }

  _figures() {
    const { result, error, stale } = this.comparison;
    const parts = [];
    if (error) parts.push(element('p', { class: 'problem' }, error));
    if (!result) return parts;
    const line = (/** @type {string} */ name, /** @type {ImageError} */ e, /** @type {string} */ title) =>
      element(
        'tr',
        { title },
        element('th', { scope: 'row' }, name),
        element('td', {}, e.rmse.toExponential(2)),
        element('td', {}, steps(e.maxAbs)),
        element('td', {}, percent(e.over2)),
        element('td', {}, String(e.nonFinite)),
      );
    const { figures } = result;
    parts.push(
      element(
        'table',
        { class: 'figures' },
        element('tr', {}, ...['', 'RMSE', 'max', '> 2/255', 'NaN/Inf'].map((h) => element('th', { scope: 'col' }, h))),
        line('float32', figures.float, 'The shader’s colours before the 8-bit rounding (the Image pass drawn again in RGBA32F)'),
        line('canvas', figures.canvas, 'The 8-bit pixels the canvas shows: what npm run accuracy measures (the rounding is most of it)'),
      ),
    );
    const notes = [
      `${result.width}×${result.height}, iTime ${result.frame.time.toFixed(3)} s, same rays as the shader`,
      result.extraSampleShare === null ? '' : `extra samples in ${percent(result.extraSampleShare)} of the pixels, as the shader took them`,
      `reference ${(result.ms.reference / 1000).toFixed(1)} s`,
    ].filter(Boolean);
    parts.push(element('p', { class: 'note' }, notes.join(' · ') + '. Click the map to inspect a pixel.'));
    if (result.caveat) parts.push(element('p', { class: 'note' }, result.caveat));
    if (stale)
      parts.push(
        element('p', { class: 'problem' }, 'Out of date: the view has changed since, so its map is hidden. Compare again to measure it.'),
      );
    return parts;
  }
}

/** The colour scale, in 1/255 steps. */
function legend() {
  const bar = element('div', { class: 'scale', style: `background: ${scaleGradient()}` });
  const ticks = element('div', { class: 'ticks' });
  for (const tick of TICKS) {
    const label = element('span', { style: `left: ${100 * scalePosition(tick)}%` }, `${tick}${tick === HIGH ? '+' : ''}`);
    ticks.append(label);
  }
  return element(
    'div',
    { class: 'legend', title: `Each pixel's largest channel error; below ${LOW}/255 the picture shows, dimmed` },
    bar,
    ticks,
    element('span', { class: 'unit' }, `|error| in 1/255 steps (log scale); below ${LOW}, the picture in grey`),
  );
}
