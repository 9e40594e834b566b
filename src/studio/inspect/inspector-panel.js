// The inspector's readout (its state is inspector.js): a panel at the lower left of the canvas
// while Inspect is on. It says how to pin a pixel, then what the inspector read there: its
// fragCoord and frame; its colour as the shader wrote it (float, before the 8-bit rounding),
// times 255, and the byte the canvas shows; each buffer's value; for the raytracer the path of
// its ray, ray by ray, beside the float64 reference's, and the reference's colour with the
// difference in 1/255 steps.

import { element } from '../ui/dom.js';

/** @typedef {import('./inspector.js').Inspector} Inspector */
/** @typedef {import('./inspector.js').Readout} Readout */

/** A float as float32 holds it: 7 significant digits; very large or small ones in exponent form. @param {number} v */
function formatFloat(v) {
  if (!Number.isFinite(v)) return String(v);
  if (v === 0) return '0';
  const a = Math.abs(v);
  return a >= 1e5 || a < 1e-4 ? v.toExponential(6) : String(Number(v.toPrecision(7)));
}

/** A signed difference in 1/255 steps. @param {number} v */
const formatSteps = (v) => `${v >= 0 ? '+' : '−'}${Math.abs(v).toFixed(Math.abs(v) < 0.1 ? 4 : 2)}`;

/** A distance along a ray (a miss: "—"). @param {number} t */
const formatT = (t) => (Number.isFinite(t) && t < 1e30 ? formatFloat(t) : '—');

/** A unit normal, 3 decimals (the path table must fit a narrow canvas). @param {number[]} n */
const formatNormal = (n) => `(${n.map((v) => (Math.abs(v) < 5e-4 ? 0 : v).toFixed(3)).join(', ')})`;

/** A table row of cells (the first a header cell). @param {string} head @param {Array<string | Node>} cells */
const row = (head, cells, attributes = {}) =>
  element('tr', attributes, element('th', { scope: 'row' }, head), ...cells.map((c) => element('td', {}, c)));

export class InspectorPanel {
  /**
   * @param {HTMLElement} stage
   * @param {Inspector} inspector
   * @param {{compare: () => void}} actions
   */
  constructor(stage, inspector, actions) {
    this.inspector = inspector;
    this.title = element('strong', {}, 'Inspect');
    const close = element('button', { type: 'button', 'aria-label': 'Close the inspector', title: 'Leave Inspect (I)' }, '✕');
    close.addEventListener('click', () => inspector.setActive(false));
    this.unpinButton = element('button', { type: 'button', title: 'Unpin the pixel (Esc)' }, 'Unpin');
    this.unpinButton.addEventListener('click', () => inspector.unpin());
    this.compareButton = element(
      'button',
      { type: 'button', title: 'The frame against the float64 reference with the same rays: an error heat map and its figures' },
      'Compare with float64',
    );
    this.compareButton.addEventListener('click', () => actions.compare());
    this.body = element('div', { class: 'inspector-body', 'aria-live': 'polite' });
    this.root = element(
      'section',
      { class: 'inspector', 'aria-label': 'Pixel inspector', hidden: true },
      element('header', {}, this.title, element('span', { class: 'spacer' }), this.compareButton, this.unpinButton, close),
      this.body,
    );
    stage.append(this.root);
    inspector.on('mode', () => this.render());
    inspector.on('readout', () => this.render());
  }

  /** A comparison is under way (its button waits: a press would only start it again), or not. @param {boolean} on */
  setComparing(on) {
    this.compareButton.disabled = on;
  }

  render() {
    const inspector = this.inspector;
    this.root.hidden = !inspector.active;
    this.unpinButton.hidden = !inspector.pinned;
    if (!inspector.active) return;
    const readout = inspector.readout;
    const pinned = inspector.pinned;
    if (!pinned) {
      this.title.textContent = 'Inspect';
      this.body.replaceChildren(
        element(
          'p',
          { class: 'hint' },
          'Click a pixel of the canvas to pin it (Esc unpins, I leaves Inspect). The magnifier shows where you point.',
        ),
      );
      return;
    }
    this.title.textContent = `Pixel ${pinned.x}, ${pinned.y}`;
    if (inspector.problem) {
      this.body.replaceChildren(element('p', { class: 'problem' }, inspector.problem));
      return;
    }
    if (!readout) {
      // a probe waits for the frame under way (the buffers must hold a whole frame)
      const progress = inspector.app.frames.progress;
      const waiting = progress
        ? ` once the frame under way is drawn (${Math.floor((100 * progress.y) / Math.max(1, progress.height))}% so far)`
        : '';
      this.body.replaceChildren(element('p', { class: 'hint' }, `Reading the pixel${waiting}…`));
      return;
    }
    this.body.replaceChildren(...this._readout(readout));
  }

  /** @param {Readout} r */
  _readout(r) {
    const { frame } = r;
    const where = element(
      'p',
      { class: 'where' },
      `fragCoord (${r.fragCoord.join(', ')}) of ${frame.width}×${frame.height} · iFrame ${frame.frame} · iTime ${frame.time.toFixed(3)} s`,
    );
    const swatch = element('span', { class: 'swatch', style: `background: rgb(${r.canvas.slice(0, 3).join(', ')})` });
    const channels = ['R', 'G', 'B', 'A'];
    const rows = [
      element('tr', {}, element('th', {}, swatch), ...channels.map((c) => element('th', { scope: 'col' }, c))),
      row('float', r.color.map(formatFloat), {
        class: 'float',
        title: 'The colour as the shader wrote it (the Image pass drawn again in RGBA32F; its alpha is forced to 1, as on Shadertoy)',
      }),
      row(
        '× 255',
        r.color.map((v) => (v * 255).toFixed(2)),
        { title: 'The float in 1/255 steps: the canvas rounds it to the nearest' },
      ),
      row('canvas', r.canvas.map(String), { class: 'bytes', title: 'The 8-bit value the canvas shows' }),
    ];
    if (r.reference) {
      const ref = r.reference;
      rows.push(
        row('float64', [...ref.rgb.map(formatFloat), ''], {
          class: 'reference',
          title: 'The float64 reference, same rays (src/reference/render.js)',
        }),
        row('Δ /255', [...ref.difference.map(formatSteps), ''], {
          class: 'difference',
          title: 'The shader (clamped) minus float64, in 1/255 steps',
        }),
      );
    }
    for (const { name, value } of r.buffers)
      rows.push(row(name, value.map(formatFloat), { class: 'buffer', title: `${name} at this pixel (RGBA32F)` }));
    const parts = [where, element('table', { class: 'values' }, ...rows)];
    if (r.referenceNote) parts.push(element('p', { class: 'note' }, r.referenceNote));
    if (r.path) parts.push(...this._path(r));
    else if (r.pathNote) parts.push(element('p', { class: 'note' }, r.pathNote));
    return parts;
  }

  /** The path table: the shader's rays beside the reference's. @param {Readout} r */
  _path(r) {
    const path = /** @type {NonNullable<Readout['path']>} */ (r.path);
    const reference = r.reference?.path ?? [];
    const head = element(
      'tr',
      {},
      ...['ray', 'hit', 't', 't float64', 'normal', 'light', 'weight'].map((h) => element('th', { scope: 'col' }, h)),
    );
    const rows = path.rays.map((ray, k) => {
      const twin = reference[k];
      const differs = twin && twin.id !== ray.id;
      return element(
        'tr',
        { class: differs ? 'differs' : '' },
        element('th', { scope: 'row' }, k === 0 ? 'eye' : `${k}`),
        element('td', {}, ray.object + (differs ? ` (float64: ${twin.object})` : '')),
        element('td', {}, formatT(ray.t)),
        element('td', {}, twin ? formatT(twin.t) : ''),
        element('td', {}, ray.id >= 0 ? formatNormal(ray.normal) : ''),
        element('td', {}, ray.lit === null ? '' : ray.lit ? 'lit' : 'shadow'),
        element('td', {}, formatFloat(ray.weight)),
      );
    });
    const last = path.rays[path.rays.length - 1];
    const bounces = this.inspector.app.values.BOUNCES;
    const end = !last
      ? ''
      : last.id < 0
        ? 'The path ends in the sky.'
        : path.rays.length - 1 === bounces
          ? `The path ends at the bounce limit (${bounces}).`
          : 'The path ends here: a reflection would carry less than 1/255.';
    const samples =
      path.extraSamples === null
        ? ''
        : path.extraSamples
          ? ' The adaptive anti-aliasing gave this pixel its grid of extra samples; the path is its centre ray.'
          : '';
    return [
      element('h3', {}, 'The ray through the pixel’s centre, from the shader’s path probe'),
      element('table', { class: 'path' }, head, ...rows),
      element('p', { class: 'note' }, end + samples),
    ];
  }
}
