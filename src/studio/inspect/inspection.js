// The pixel inspector and the comparison with float64, put on the page: their state (the
// inspector, the comparison, the path probe they share, the float64 reference's workers), their
// widgets (the readout, the magnifier, the heat map), and what the canvas, the keys and the
// toolbar do for them. In Inspect mode a click on the canvas pins a pixel instead of moving
// iMouse (the stage hears it first); Esc unpins; I (the toolbar's binding) turns Inspect on and off.

import { Inspector } from './inspector.js';
import { Comparison } from './compare.js';
import { ProbeProgram } from './probe-program.js';
import { ReferenceCancelled, ReferenceClient } from './reference-client.js';
import { InspectorPanel } from './inspector-panel.js';
import { CompareView } from './compare-view.js';
import { Loupe, pixelAt } from './loupe.js';
import { BoxLayout } from './box-layout.js';
import { isTyping } from '../ui/keys.js';
import './inspect.css';

/** @typedef {import('../../player/app/app.js').ShaderApp} ShaderApp */

/** The page's notes over the canvas (ui/notices.js: the column of the toast and the notes, the view's note; the overlay), which the boxes keep clear of where they can. */
const notes = () => [...document.querySelectorAll('#messages, .view-note, #overlay')];

/**
 * @param {ShaderApp} app
 * @param {{stage: HTMLElement, canvas: HTMLCanvasElement, builtinSource: string}} page
 */
export function installInspection(app, { stage, canvas, builtinSource }) {
  const program = new ProbeProgram(app);
  const reference = new ReferenceClient();
  const inspector = new Inspector(app, program, reference);
  const comparison = new Comparison(app, program, reference, builtinSource);
  /** The boxes the magnifier keeps clear of (set below). @type {HTMLElement[]} */
  const boxes = [];
  const loupe = new Loupe(stage, canvas, { boxes: () => boxes, notes });

  /**
   * Runs the comparison (a press while one runs does nothing: it would only start again); why
   * it stops is said in its box (a cancel is not).
   */
  const compare = () => {
    if (comparison.running) return Promise.resolve(null);
    return comparison.run().catch((error) => {
      if (error instanceof ReferenceCancelled) return null;
      console.warn(`Compare with float64: ${error.message}`);
      return null;
    });
  };
  /** @param {boolean} [on] */
  const toggle = (on = !inspector.active) => inspector.setActive(on);
  /** Pins a pixel (y from the bottom), turning Inspect on. @param {number} x @param {number} y */
  const pin = (x, y) => {
    inspector.setActive(true);
    inspector.pin(x, y);
  };

  const panel = new InspectorPanel(stage, inspector, { compare });
  const compareView = new CompareView(stage, canvas, comparison, { pin, compare });
  boxes.push(panel.root, compareView.root);
  const boxLayout = new BoxLayout(stage, canvas, { readout: panel.root, compare: compareView.root, pin: loupe.marker, avoid: notes });
  /** Lays the boxes out, and the magnifier around them (a box that moved may lie where it was). */
  const layout = () => {
    boxLayout.layout();
    loupe.place();
  };
  comparison.on('progress', () => {
    panel.setComparing(Boolean(comparison.running));
    layout();
  });
  comparison.on('result', layout);

  // In Inspect mode the canvas's clicks pin pixels: the stage hears them first (capture), and
  // iMouse (app/shadertoy-inputs.js, on the canvas) never does.
  stage.addEventListener(
    'pointerdown',
    (event) => {
      if (!inspector.active || event.target !== canvas || event.button !== 0) return;
      event.stopPropagation();
      event.preventDefault();
      const at = pixelAt(canvas, event.clientX, event.clientY);
      if (at) inspector.pin(at.x, at.y);
    },
    { capture: true },
  );
  stage.addEventListener('pointermove', (event) => {
    const over = [canvas, compareView.map].find((target) => target === event.target);
    loupe.follow(inspector.active && over ? event : null, over);
  });
  stage.addEventListener('pointerleave', () => loupe.follow(null));
  /** Frames the pinned pixel, and lays the boxes out around it. */
  const mark = () => {
    loupe.mark(inspector.active ? (inspector.pinned ?? null) : null);
    layout();
  };
  inspector.on('mode', () => {
    stage.classList.toggle('inspecting', inspector.active);
    if (!inspector.active) loupe.follow(null);
    mark();
  });
  inspector.on('readout', layout); // the readout's size changes with its text
  app.on('drawn', () => {
    mark();
    compareView.place();
  });
  app.on('state', layout); // a note over the canvas may have come or gone
  window.addEventListener('resize', mark);
  new ResizeObserver(mark).observe(canvas); // the editor or the panel beside it changed its size
  window.addEventListener('keydown', (event) => {
    if (event.key !== 'Escape' || !inspector.active || !inspector.pinned || isTyping(event)) return;
    inspector.unpin();
  });

  /** Inspect off, no pixel pinned, no comparison: as on a page just opened (open-view.js). */
  const reset = () => {
    comparison.cancel();
    comparison.clear();
    inspector.unpin();
    inspector.setActive(false);
  };

  return { inspector, comparison, program, compare, toggle, pin, reset };
}
