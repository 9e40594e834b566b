// The lil-gui panel: play/pause, a frame-time readout, the resolution scale, and one widget per
// shader control (built from parseControls): floats → slider, ints → integer slider,
// toggles → checkbox, choices → dropdown, vec2/3/4 → a folder with one slider per component.

import GUI from 'lil-gui';
import { MAX_SCALE, MIN_SCALE } from './url-params.js';

const COMPONENTS = ['x', 'y', 'z', 'w'];

export class Panel {
  /**
   * @param {object} options
   * @param {boolean} options.playing
   * @param {number} options.scale
   * @param {boolean} options.scaleLocked true when the URL fixed the size (the scale is moot)
   * @param {(playing: boolean) => void} options.onPlay
   * @param {(scale: number) => void} options.onScale
   * @param {(name: string, value: unknown) => void} options.onControl
   */
  constructor({ playing, scale, scaleLocked, onPlay, onScale, onControl }) {
    this.gui = new GUI({ title: 'Raytracer' });
    this.onControl = onControl;

    this._state = { playing, frameTime: '–', scale };
    this._actions = { togglePlay: () => onPlay(!this._state.playing) };
    this._play = this.gui.add(this._actions, 'togglePlay');
    this.setPlaying(playing);
    this._frameTime = this.gui.add(this._state, 'frameTime').name('Frame time').disable();
    const scaleController = this.gui.add(this._state, 'scale', MIN_SCALE, MAX_SCALE, 0.05).name('Resolution scale').onChange(onScale);
    if (scaleLocked) scaleController.name('Resolution scale (size fixed by URL)').disable();

    this._controlsFolder = null;
    this._view = {}; // what the widgets edit: scalars by name, vectors as {x, y, z, w}
    this._controls = [];
  }

  setPlaying(playing) {
    this._state.playing = playing;
    this._play.name(playing ? '❚❚ Pause' : '▶ Play');
  }

  /** Shows a frame time in milliseconds (or a word such as "paused"). */
  setFrameTime(ms) {
    this._state.frameTime = typeof ms === 'number' ? `${ms.toFixed(1)} ms (${(1000 / ms).toFixed(0)} fps)` : ms;
    this._frameTime.updateDisplay();
  }

  /** (Re)builds the shader-control widgets. */
  setControls(controls, values) {
    this._controlsFolder?.destroy();
    this._controls = controls;
    this._view = {};
    if (controls.length === 0) {
      this._controlsFolder = null;
      return;
    }
    const folder = this.gui.addFolder('Shader');
    this._controlsFolder = folder;
    for (const control of controls) this._addControl(folder, control);
    this.sync(values);
  }

  /** Brings the widgets in line with `values` (after a change from the URL or the API). */
  sync(values) {
    for (const c of this._controls) {
      const value = values[c.name];
      if (value === undefined) continue;
      if (Array.isArray(value)) value.forEach((v, i) => (this._view[c.name][COMPONENTS[i]] = v));
      else this._view[c.name] = isCheckbox(c) ? Boolean(value) : value;
    }
    this._controlsFolder?.controllersRecursive().forEach((controller) => controller.updateDisplay());
  }

  _addControl(folder, c) {
    // compile-time controls rebuild the shader: only once a drag ends, not on every step
    const listen = (controller, read) => {
      const emit = () => this.onControl(c.name, read());
      return c.kind === 'define' ? controller.onFinishChange(emit) : controller.onChange(emit);
    };
    const size = { vec2: 2, vec3: 3, vec4: 4 }[c.type];
    if (size) {
      const sub = folder.addFolder(c.label).close(); // keeps the panel short; click to open
      this._view[c.name] = {};
      for (const axis of COMPONENTS.slice(0, size)) {
        this._view[c.name][axis] = 0;
        listen(this._numberWidget(sub, this._view[c.name], axis, c).name(axis), () =>
          COMPONENTS.slice(0, size).map((a) => this._view[c.name][a]),
        );
      }
      return;
    }
    if (c.options) {
      this._view[c.name] = c.default;
      const choices = Object.fromEntries(c.options.map((o) => [o.label, o.value]));
      listen(folder.add(this._view, c.name, choices).name(c.label), () => this._view[c.name]);
    } else if (isCheckbox(c)) {
      this._view[c.name] = false;
      // a bool stays a bool; a toggle on an int or float is 0 or 1
      const read = () => (c.type === 'bool' ? this._view[c.name] : Number(this._view[c.name]));
      listen(folder.add(this._view, c.name).name(c.label), read);
    } else {
      this._view[c.name] = 0;
      listen(this._numberWidget(folder, this._view, c.name, c).name(c.label), () => this._view[c.name]);
    }
  }

  _numberWidget(gui, object, property, c) {
    const controller = c.min !== undefined ? gui.add(object, property, c.min, c.max, c.step) : gui.add(object, property);
    if (c.type === 'int') controller.step(1);
    else if (c.step !== undefined) controller.step(c.step);
    return controller;
  }
}

function isCheckbox(c) {
  return c.toggle === true || c.type === 'bool';
}
