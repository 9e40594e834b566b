// The "Record" toolbar button and its popover: format (WebM video or a .zip of PNGs), duration
// and frames, frames per second, size (the canvas's by default); "Start" records (recorder.js)
// with a progress bar, "Cancel" stops the recording (nothing is saved) or closes the popover.

import { MAX_FPS, MAX_FRAMES, RecordingCancelled } from '../../../player/io/recorder.js';

/** @typedef {import('../../../player/io/recorder.js').Recorder} Recorder */
import { recordingFileName } from '../../../player/io/file-names.js';
import { element, placeAbove, saveBlob } from '../dom.js';

/** @typedef {import('../../../player/app/app.js').ShaderApp} ShaderApp */

const RECORD_ICON = '<svg viewBox="0 0 16 16" width="14" height="14" fill="currentColor"><circle cx="8" cy="8" r="5"/></svg>';

/** A labelled field: `<label>Text <input></label>`. @param {string} label @param {HTMLElement} input */
function field(label, input) {
  return element('label', {}, `${label} `, input);
}

/**
 * Adds "Record" to the toolbar's output buttons (after "Screenshot"), a view on the page's
 * recorder (main.js owns it, and gives it to window.shaderEngine too).
 * @param {ShaderApp} app
 * @param {Recorder} recorder
 * @param {HTMLElement} toolbarRoot
 * @param {(text: string) => void} toast a short confirmation
 * @returns {{recorder: Recorder, open: () => void, close: () => void}}
 */
export function installRecordDialog(app, recorder, toolbarRoot, toast) {
  const openButton = element(
    'button',
    {
      type: 'button',
      'aria-label': 'Record',
      'aria-expanded': 'false',
      'aria-haspopup': 'dialog',
      title: 'Record a video or PNG sequence, frame by frame',
    },
    element('span', { class: 'icon', 'aria-hidden': 'true' }),
    element('span', { class: 'label' }, ' Record'),
  );
  /** @type {HTMLElement} */ (openButton.firstChild).innerHTML = RECORD_ICON;
  const screenshot = toolbarRoot.querySelector('button[aria-label="Screenshot"]');
  if (screenshot) screenshot.after(openButton);
  else (toolbarRoot.querySelector('.group:last-child') ?? toolbarRoot).append(openButton);

  const format = /** @type {HTMLSelectElement} */ (
    element(
      'select',
      { 'aria-label': 'Format' },
      element('option', { value: 'webm' }, 'WebM video'),
      element('option', { value: 'png' }, 'PNG sequence (.zip)'),
    )
  );
  const number = (label, attributes) =>
    /** @type {HTMLInputElement} */ (element('input', { type: 'number', 'aria-label': label, required: true, ...attributes }));
  // any duration: frames / fps has as many decimals as it has (100 frames at 30 fps is 3.333 s)
  const duration = number('Duration (s)', { min: 0.001, step: 'any', value: 2 });
  const frames = number('Frames', { min: 1, max: MAX_FRAMES, step: 1, value: 60 });
  const fps = number('Frames per second', { min: 1, max: MAX_FPS, step: 1, value: 30 });
  const width = number('Width', { min: 1, step: 1 });
  const height = number('Height', { min: 1, step: 1 });
  const progress = /** @type {HTMLProgressElement} */ (element('progress', { max: 1, value: 0, 'aria-label': 'Recording progress' }));
  const status = element('output', { class: 'record-status', 'aria-live': 'polite' });
  const start = /** @type {HTMLButtonElement} */ (element('button', { type: 'button' }, 'Start'));
  const cancel = element('button', { type: 'button' }, 'Cancel');

  const dialog = element(
    'div',
    { class: 'record-dialog', role: 'dialog', 'aria-label': 'Record', hidden: true },
    element('div', { class: 'record-fields' }, field('Format', format), field('Duration (s)', duration), field('Frames', frames)),
    element('div', { class: 'record-fields' }, field('FPS', fps), field('Width', width), field('Height', height)),
    element('div', { class: 'record-progress' }, progress, status),
    element('div', { class: 'record-buttons' }, start, cancel),
  );
  document.body.append(dialog);

  // duration, frames and fps agree: frames = round(duration × fps)
  const value = (input) => Number(input.value);
  duration.addEventListener('input', () => {
    if (value(duration) > 0 && value(fps) > 0) frames.value = String(Math.max(1, Math.round(value(duration) * value(fps))));
  });
  fps.addEventListener('input', () => {
    if (value(duration) > 0 && value(fps) > 0) frames.value = String(Math.max(1, Math.round(value(duration) * value(fps))));
  });
  frames.addEventListener('input', () => {
    if (value(frames) > 0 && value(fps) > 0) duration.value = String(+(value(frames) / value(fps)).toFixed(3));
  });

  const setRecording = (recording) => {
    for (const input of [format, duration, frames, fps, width, height, start]) input.disabled = recording;
    cancel.title = recording ? 'Stop recording; nothing is saved' : 'Close';
  };

  const open = () => {
    if (!recorder.busy) {
      width.value = String(app.frames.size.width);
      height.value = String(app.frames.size.height);
      progress.value = 0;
      status.textContent = '';
    }
    dialog.hidden = false;
    placeAbove(dialog, toolbarRoot); // above the toolbar: off the shader's name and the buttons
    openButton.setAttribute('aria-expanded', 'true');
    (recorder.busy ? cancel : start).focus();
  };
  const close = () => {
    dialog.hidden = true;
    openButton.setAttribute('aria-expanded', 'false');
  };

  window.addEventListener('resize', () => dialog.hidden || placeAbove(dialog, toolbarRoot));
  openButton.addEventListener('click', () => (dialog.hidden ? open() : !recorder.busy && close()));
  cancel.addEventListener('click', () => (recorder.busy ? recorder.cancel() : close()));
  dialog.addEventListener('keydown', (event) => {
    if (event.key === 'Escape' && !recorder.busy) {
      event.preventDefault();
      close();
      openButton.focus();
    }
  });

  start.addEventListener('click', async () => {
    if (recorder.busy) return;
    if (![duration, frames, fps, width, height].every((input) => input.checkValidity() && value(input) > 0)) {
      status.textContent = 'Every field needs a positive number';
      return;
    }
    const request = {
      format: /** @type {'webm' | 'png'} */ (format.value),
      frames: value(frames),
      fps: value(fps),
      width: value(width),
      height: value(height),
    };
    setRecording(true);
    progress.value = 0;
    status.textContent = 'Starting…';
    try {
      const result = await recorder.record(request, (done, total) => {
        progress.value = done / total;
        status.textContent = `Frame ${done} of ${total}`;
      });
      const name = recordingFileName(app.fileName, result);
      saveBlob(new Blob([/** @type {Uint8Array<ArrayBuffer>} */ (result.bytes)], { type: result.mimeType }), name);
      status.textContent = `Saved ${name}`;
      toast(`Saved ${name} (${result.frames} frames)`);
      close();
    } catch (error) {
      if (error instanceof RecordingCancelled) {
        status.textContent = 'Cancelled: nothing saved';
        toast('Recording cancelled');
      } else {
        console.warn(`Recording failed: ${error.message}`);
        status.textContent = `Recording failed: ${error.message}`;
        toast(`Recording failed: ${error.message}`);
      }
      progress.value = 0;
    } finally {
      setRecording(false);
    }
  });

  return { recorder, open, close };
}
