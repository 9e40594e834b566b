// The bar along the bottom of the page: play/pause, restart, the time slider, the speed, a
// frame-time graph with fps, the shader's name, and the output buttons. Every button is a real
// <button> whose accessible name is what it does ("Play", "Pause", "Restart", "Copy for
// Shadertoy", "Download .glsl", "Export JSON", "Screenshot", ...); the icons are decoration.

import { element } from '../dom.js';
import { FrameReadout } from './frame-readout.js';
import { ToolbarFit } from './toolbar-fit.js';
import './toolbar.css';

const SPEEDS = [0, 0.1, 0.25, 0.5, 1, 2, 4, 8];
const GRAPH_FRAMES = 90; // frame times kept in the graph

// 16×16 icons, drawn in the button's text colour
const ICONS = {
  play: '<path d="M4 2.5v11l9.5-5.5z"/>',
  pause: '<path d="M3.5 2.5h3v11h-3zM9.5 2.5h3v11h-3z"/>',
  restart: '<path d="M2.5 2.5h2v11h-2zM13.5 2.5v11L5.5 8z"/>',
  reset:
    '<g fill="none" stroke="currentColor" stroke-width="1.5"><circle cx="8" cy="8" r="4.5"/><path d="M8 1v3.5M8 11.5V15M1 8h3.5M11.5 8H15"/></g>',
  edit: '<path d="M11.2 1.8l3 3-8.7 8.7-3.8.8.8-3.8z"/>',
  copy: '<g fill="none" stroke="currentColor" stroke-width="1.5"><path d="M5.5 1.75h8v9.5h-8z"/><path d="M2.75 4.5v9.75h8"/></g>',
  download: '<g fill="none" stroke="currentColor" stroke-width="1.6"><path d="M8 1.5v8.5M4.3 6.6 8 10.3l3.7-3.7M2.5 14h11"/></g>',
  json: '<g fill="none" stroke="currentColor" stroke-width="1.5" stroke-linecap="round"><path d="M5.5 2C3.5 2 4 4.5 4 6S2 8 2 8s2 .5 2 2-.5 4 1.5 4M10.5 2c2 0 1.5 2.5 1.5 4s2 2 2 2-2 .5-2 2 .5 4-1.5 4"/></g>',
  camera:
    '<g fill="none" stroke="currentColor" stroke-width="1.5"><path d="M1.75 4.5h3l1.3-2h3.9l1.3 2h3v9H1.75z"/><circle cx="8" cy="8.8" r="2.6"/></g>',
  fullscreen: '<g fill="none" stroke="currentColor" stroke-width="1.6"><path d="M2 6V2h4M10 2h4v4M14 10v4h-4M6 14H2v-4"/></g>',
  link: '<g fill="none" stroke="currentColor" stroke-width="1.6" stroke-linecap="round"><path d="M6.3 9.7l3.4-3.4M7.2 4.6l1.1-1.1a2.7 2.7 0 0 1 3.8 3.8L11 8.4M8.8 11.4l-1.1 1.1a2.7 2.7 0 0 1-3.8-3.8L5 7.6"/></g>',
  inspect:
    '<g fill="none" stroke="currentColor" stroke-width="1.6"><circle cx="6.5" cy="6.5" r="4.5"/><path d="M10 10l4.5 4.5M6.5 4.5v4M4.5 6.5h4"/></g>',
  compare:
    '<g stroke="currentColor" stroke-width="1.5"><path fill="none" d="M2 13.5h12M2 13.5V2.5"/><path d="M4 11l2.5-4 2.5 2 4-6" fill="none"/></g>',
  // a speaker, with its sound waves or crossed out (the Sound tab's mute button: sound-controls.js)
  sound:
    '<path d="M1.5 5.5h3L8.5 2v12l-4-3.5h-3z"/><g fill="none" stroke="currentColor" stroke-width="1.4" stroke-linecap="round"><path d="M10.6 5.6a3.4 3.4 0 0 1 0 4.8M12.4 3.6a6.2 6.2 0 0 1 0 8.8"/></g>',
  muted:
    '<path d="M1.5 5.5h3L8.5 2v12l-4-3.5h-3z"/><path d="M10.5 5.5l4 5M14.5 5.5l-4 5" fill="none" stroke="currentColor" stroke-width="1.5" stroke-linecap="round"/>',
};

/**
 * One of the toolbar's icons, drawn in the text's colour (no font needed: an emoji shows as an
 * empty box where the browser has no emoji font).
 * @param {keyof typeof ICONS} name
 */
export function icon(name) {
  const span = element('span', { class: 'icon', 'aria-hidden': 'true' });
  span.innerHTML = `<svg viewBox="0 0 16 16" width="14" height="14" fill="currentColor">${ICONS[name]}</svg>`;
  return span;
}

export class Toolbar {
  /**
   * @param {HTMLElement} root the (empty) toolbar element
   * @param {object} actions callbacks: togglePlay, restart, resetView, setTime(s), setSpeed(s), toggleEditor,
   *   copyForShadertoy, download, exportJson, screenshot, toggleFullscreen, copyLink, toggleInspect, compare
   * @param {() => import('./frame-readout.js').Activity} activity what the page is doing, for the readout
   */
  constructor(root, actions, activity) {
    this.root = root;
    root.setAttribute('role', 'toolbar');
    root.setAttribute('aria-label', 'Playback and output');

    this.playButton = element('button', { type: 'button', class: 'play' });
    this.playButton.addEventListener('click', () => actions.togglePlay());
    const restart = element(
      'button',
      { type: 'button', 'aria-label': 'Restart', title: 'Restart: time and frame back to 0 (R)' },
      icon('restart'),
    );
    restart.addEventListener('click', () => actions.restart());
    const resetView = element(
      'button',
      {
        type: 'button',
        'aria-label': 'Reset view',
        title: 'Reset view: iMouse back to how the page opened (a click or drag on the canvas sets it)',
      },
      icon('reset'),
    );
    resetView.addEventListener('click', () => actions.resetView());

    this.timeSlider = element('input', {
      type: 'range',
      min: 0,
      max: 60,
      step: 0.01,
      value: 0,
      'aria-label': 'Time',
      title: 'Time (iTime, seconds)',
    });
    this._dragging = false;
    this.timeSlider.addEventListener('input', () => {
      this._dragging = true;
      actions.setTime(Number(this.timeSlider.value));
    });
    this.timeSlider.addEventListener('change', () => (this._dragging = false));
    this.timeText = element('output', { class: 'time', 'aria-live': 'off', title: 'iTime' }, '0.00 s');

    this.speedSelect = element('select', { 'aria-label': 'Speed', title: 'Time speed' });
    for (const s of SPEEDS) this.speedSelect.append(element('option', { value: String(s) }, `${s}×`));
    this.speedSelect.value = '1';
    this.speedSelect.addEventListener('change', () => actions.setSpeed(Number(this.speedSelect.value)));

    this.graph = element('canvas', { class: 'graph', width: GRAPH_FRAMES, height: 24, 'aria-hidden': 'true' });
    this.fpsText = element('span', {
      class: 'fps',
      title:
        'What the page is doing: drawing the first frame, playing (GPU time per frame where the browser measures it, else the time between frames; and the frames per second reached), paused, converging',
    });
    /** The graph and the line beside it (frame-readout.js). */
    this.readout = new FrameReadout(this.graph, this.fpsText, activity);

    this.nameText = element('span', { class: 'name', title: '' }); // its title: the whole name
    const editButton = element(
      'button',
      {
        type: 'button',
        'aria-label': 'Edit shader',
        'aria-expanded': 'false',
        title: 'Show the shader source (paste a shader there, or drop a .glsl file on the page)',
      },
      icon('edit'),
      element('span', { class: 'label' }, ' Edit'),
    );
    editButton.addEventListener('click', () => actions.toggleEditor());
    this.editButton = editButton;
    const button = (label, title, glyph, action) => {
      const b = element(
        'button',
        { type: 'button', title, 'aria-label': label },
        icon(glyph),
        element('span', { class: 'label' }, ` ${label}`),
      );
      b.addEventListener('click', () => action());
      return b;
    };

    /** A button that stays pressed while what it turns on is on. */
    const toggle = (label, title, glyph, action) => {
      const b = button(label, title, glyph, action);
      b.setAttribute('aria-pressed', 'false');
      return b;
    };
    this.fullscreenButton = toggle(
      'Fullscreen',
      'The canvas alone, on the whole screen (F; Esc leaves)',
      'fullscreen',
      actions.toggleFullscreen,
    );
    this.inspectButton = toggle(
      'Inspect',
      'Inspect a pixel: click one on the canvas to pin it and read its colour in float, its buffers and, for the raytracer, its ray path (I; Esc unpins)',
      'inspect',
      actions.toggleInspect,
    );

    const outputs = element(
      'div',
      { class: 'group outputs' },
      editButton,
      button(
        'Copy for Shadertoy',
        "Copies the shader's text (the editor's tab of a multipass shader), ready to paste into that tab on Shadertoy",
        'copy',
        actions.copyForShadertoy,
      ),
      button('Download .glsl', "Saves the shader as a .glsl file (the editor's tab of a multipass shader)", 'download', actions.download),
      button(
        'Export JSON',
        "Saves the whole shader, every tab and channel, in Shadertoy's JSON format (drop it on the page to load it back)",
        'json',
        actions.exportJson,
      ),
      button('Screenshot', 'Saves the current frame as a PNG (size: Controls → View)', 'camera', actions.screenshot),
      this.inspectButton,
      button(
        'Compare with float64',
        'The frame against the float64 reference with the same rays (the built-in raytracer): an error heat map, its RMSE, maximum and pixels over 2/255',
        'compare',
        actions.compare,
      ),
      this.fullscreenButton,
      button('Copy link', 'Copies a link that reproduces this view: shader URL, controls, mouse, time and size', 'link', actions.copyLink),
    );
    /** The graph and the frame-time line; the Sound tab's widgets go before it (sound-controls.js). */
    this.meterGroup = element('div', { class: 'group meter' }, this.graph, this.fpsText);
    root.append(
      element('div', { class: 'group transport' }, this.playButton, restart, resetView, this.timeSlider, this.timeText, this.speedSelect),
      this.meterGroup,
      element('div', { class: 'group grow' }, this.nameText),
      outputs,
    );
    /** Two rows at most: labels, else icons, else a "More" menu (toolbar-fit.js). */
    this.layout = new ToolbarFit(root, outputs); // fitted once every button is in (ui.js)
  }

  /** Fits the toolbar again (after a button is added to it). */
  fit() {
    this.layout.fit();
  }

  /** Play state, time, speed and shader name from the app. */
  update({ playing, time, speed, name }) {
    const label = playing ? 'Pause' : 'Play';
    if (this.playButton.getAttribute('aria-label') !== label) {
      this.playButton.setAttribute('aria-label', label);
      this.playButton.title = `${label} (Space)`;
      this.playButton.replaceChildren(icon(playing ? 'pause' : 'play'));
    }
    if (!this._dragging) {
      const max = Math.max(60, Math.ceil((time + 1) / 60) * 60);
      if (Number(this.timeSlider.max) !== max) this.timeSlider.max = String(max);
      this.timeSlider.value = String(time);
    }
    this.timeText.value = `${time.toFixed(2)} s`;
    if (Number(this.speedSelect.value) !== speed) {
      let option = [...this.speedSelect.options].find((o) => Number(o.value) === speed);
      if (!option) {
        option = element('option', { value: String(speed) }, `${speed}×`);
        this.speedSelect.append(option);
      }
      this.speedSelect.value = option.value;
    }
    if (this.nameText.title !== name) {
      // the folders in their own span, which a phone's toolbar leaves out (style.css)
      const cut = name.lastIndexOf('/') + 1;
      this.nameText.title = name;
      this.nameText.replaceChildren(element('span', { class: 'folder' }, name.slice(0, cut)), name.slice(cut));
      this.layout.fit(); // a phone's toolbar gives the name its own width
    }
    this.readout.refresh();
  }

  /** @param {boolean} on whether the page is fullscreen */
  setFullscreen(on) {
    this.fullscreenButton.setAttribute('aria-pressed', String(on));
  }

  /** @param {boolean} on whether Inspect is on */
  setInspecting(on) {
    this.inspectButton.setAttribute('aria-pressed', String(on));
  }

  setEditorOpen(open) {
    this.editButton.setAttribute('aria-expanded', String(open));
  }
}
