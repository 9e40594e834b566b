// The lil-gui panel: the view (resolution scale, size cap, screenshot size), images for the four
// channels, and one widget per shader control (built from parseControls): floats → slider,
// ints → integer slider, toggles → checkbox, choices → dropdown, vec2/3/4 → a folder with one
// slider per component. A shader without a control block gets no "Shader controls" folder.

import GUI from 'lil-gui';
import { MAX_SCALE, MIN_SCALE } from '../../shared/canvas-limits.js';
import { controlApplies } from '../../shadertoy/controls.js';

const COMPONENTS = ['x', 'y', 'z', 'w'];

/** Longer side of the drawing buffer, in device pixels (0: no cap). */
const CAP_CHOICES = {
  'No cap': 0,
  '3840 px': 3840,
  '2560 px': 2560,
  '1920 px': 1920,
  '1280 px': 1280,
  '960 px': 960,
  '640 px': 640,
  '320 px': 320,
};
const SCREENSHOT_CHOICES = {
  'Canvas size': 'current',
  '2× canvas': 'double',
  '1280×720': '1280x720',
  '1920×1080': '1920x1080',
  '3840×2160': '3840x2160',
};

/** The screenshot size a SCREENSHOT_CHOICES value means for a canvas of width × height, or null for the canvas size. */
function screenshotSize(choice, width, height) {
  if (choice === 'double') return { width: width * 2, height: height * 2 };
  const m = /^(\d+)x(\d+)$/.exec(choice);
  return m ? { width: Number(m[1]), height: Number(m[2]) } : null;
}

export class Panel {
  /**
   * Shows whether the shader converges, and whether it can (the raytracer can: app.canConverge).
   * @param {boolean} on
   * @param {boolean} available
   */
  /**
   * The View folder as a page opened with these gives it (io/open-view.js).
   * @param {{scale: number, cap: number, sizeFixed: boolean}} view
   */
  setView({ scale, cap, sizeFixed }) {
    this._state.scale = scale;
    this._state.cap = Object.values(CAP_CHOICES).includes(cap) ? cap : 0;
    this._scale
      .name(sizeFixed ? 'Scale (size fixed)' : 'Resolution scale')
      .enable(!sizeFixed)
      .updateDisplay();
    this._cap
      .name(sizeFixed ? 'Max size (size fixed)' : 'Max canvas size')
      .enable(!sizeFixed)
      .updateDisplay();
  }

  setConverging(on, available) {
    this._state.converge = on;
    this._converge.updateDisplay();
    this._converge.enable(available || on);
  }

  /**
   * @param {object} options
   * @param {number} options.scale
   * @param {number} options.cap
   * @param {boolean} options.sizeFixed true when the URL fixed the size (scale and cap are moot)
   * @param {(scale: number) => void} options.onScale
   * @param {(cap: number) => void} options.onCap
   * @param {(name: string, value: unknown) => void} options.onControl
   * @param {(index: number, source: File | 'webcam:' | 'mic:' | null) => void} options.onChannel
   * @param {(on: boolean) => void} [options.onConverge] "Converge when still" switched
   */
  constructor({ scale, cap, sizeFixed, onScale, onCap, onControl, onChannel, onConverge = () => {} }) {
    // docked beside the canvas (below it on a phone: style.css), never over the scene
    this.gui = new GUI({ title: 'Controls', container: document.getElementById('panel-dock') ?? document.body });
    if (window.innerWidth < 640) this.gui.close(); // a phone: the picture first, the panel one tap away
    this.onControl = onControl;

    this._state = { scale, cap: Object.values(CAP_CHOICES).includes(cap) ? cap : 0, screenshot: 'current', converge: false };
    const view = this.gui.addFolder('View');
    const scaleController = view.add(this._state, 'scale', MIN_SCALE, MAX_SCALE, 0.05).name('Resolution scale').onChange(onScale);
    const capController = view
      .add(this._state, 'cap', CAP_CHOICES)
      .name('Max canvas size')
      .onChange((v) => onCap(Number(v)));
    this._scale = scaleController;
    this._cap = capController;
    this.setView({ scale, cap, sizeFixed });
    view.add(this._state, 'screenshot', SCREENSHOT_CHOICES).name('Screenshot size');
    // a single-pass shader's progressive form: one more sample per pixel each still frame
    this._converge = view.add(this._state, 'converge').name('Converge when still').onChange(onConverge);

    // one hidden file input serves the four channels
    this._file = Object.assign(document.createElement('input'), { type: 'file', accept: 'image/*,video/*,audio/*', hidden: true });
    this._file.setAttribute('aria-label', 'Image, video or music file for a channel');
    document.body.append(this._file);
    this._file.addEventListener('change', () => {
      const file = this._file.files?.[0];
      if (file) onChannel(this._fileChannel, file);
      this._file.value = '';
    });
    const channels = this.gui.addFolder('Channels').close();
    this._channelNames = [];
    for (let i = 0; i < 4; i++) {
      const actions = {
        load: () => {
          this._fileChannel = i;
          this._file.click();
        },
        webcam: () => onChannel(i, 'webcam:'),
        mic: () => onChannel(i, 'mic:'),
        clear: () => onChannel(i, null),
      };
      this._channelNames.push(channels.add(actions, 'load').name(`Load file into iChannel${i}…`));
      channels.add(actions, 'webcam').name(`Webcam into iChannel${i}`);
      channels.add(actions, 'mic').name(`Microphone into iChannel${i}`);
      channels.add(actions, 'clear').name(`Clear iChannel${i}`);
    }

    this._controlsFolder = null;
    this._view = {}; // what the widgets edit: scalars by name, vectors as {x, y, z, w}
    this._controls = [];
    /** Each control's widget (a vector's: its folder), by name: hidden while the control does not apply. @type {Record<string, {show: (shown?: boolean) => unknown}>} */
    this._widgets = {};
  }

  /** The screenshot size chosen in the panel, for a canvas of width × height (null: canvas size). */
  screenshotSize(width, height) {
    return screenshotSize(this._state.screenshot, width, height);
  }

  /** Shows each channel's image size next to its button. */
  setChannelSizes(sizes) {
    sizes.forEach(([w, h], i) => this._channelNames[i].name(`Load file into iChannel${i}…${w ? ` (${w}×${h})` : ''}`));
  }

  /** (Re)builds the shader-control widgets; none (and no folder) for a shader without controls. */
  setControls(controls, values) {
    this._controlsFolder?.destroy();
    this._controls = controls;
    this._view = {};
    this._widgets = {};
    if (controls.length === 0) {
      this._controlsFolder = null;
      return;
    }
    const folder = this.gui.addFolder('Shader controls');
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
    // a control of another scene's object changes nothing: it is not shown (`| when`, controls.js)
    for (const c of this._controls) this._widgets[c.name]?.show(controlApplies(c, values));
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
      this._widgets[c.name] = sub;
      this._view[c.name] = {};
      COMPONENTS.slice(0, size).forEach((axis, i) => {
        // a component with a name and range of its own (controls.js), else x, y, z, w in the vector's range
        const component = c.components?.[i];
        this._view[c.name][axis] = 0;
        listen(this._numberWidget(sub, this._view[c.name], axis, component ?? c).name(component?.name ?? axis), () =>
          COMPONENTS.slice(0, size).map((a) => this._view[c.name][a]),
        );
      });
      return;
    }
    if (c.options) {
      this._view[c.name] = c.default;
      const choices = Object.fromEntries(c.options.map((o) => [o.label, o.value]));
      this._widgets[c.name] = listen(folder.add(this._view, c.name, choices).name(c.label), () => this._view[c.name]);
    } else if (isCheckbox(c)) {
      this._view[c.name] = false;
      // a bool stays a bool; a toggle on an int or float is 0 or 1
      const read = () => (c.type === 'bool' ? this._view[c.name] : Number(this._view[c.name]));
      this._widgets[c.name] = listen(folder.add(this._view, c.name).name(c.label), read);
    } else {
      this._view[c.name] = 0;
      this._widgets[c.name] = listen(this._numberWidget(folder, this._view, c.name, c).name(c.label), () => this._view[c.name]);
    }
  }

  /**
   * A slider (or a number field, without a range) for one number.
   * @param {{min?: number, max?: number, step?: number, type?: string}} range the control's, or its component's
   */
  _numberWidget(gui, object, property, range) {
    const controller = range.min !== undefined ? gui.add(object, property, range.min, range.max, range.step) : gui.add(object, property);
    if (range.type === 'int') controller.step(1);
    else if (range.step !== undefined) controller.step(range.step);
    return controller;
  }
}

function isCheckbox(c) {
  return c.toggle === true || c.type === 'bool';
}
