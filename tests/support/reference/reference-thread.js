// Renders rows of the float64 reference in a worker thread (reference-threads.js splits an image
// over the machine's cores).
import { parentPort, workerData } from 'node:worker_threads';
import { renderReference } from '../../../src/reference/render.js';

if (!parentPort) throw new Error('reference-thread.js runs in a worker thread: reference-threads.js starts it');
const { source, view, options } = workerData;
const { rgb } = renderReference(source, view, options);
// (rgb is a new Float64Array: its buffer is an ArrayBuffer, never a SharedArrayBuffer)
parentPort.postMessage(rgb, [/** @type {ArrayBuffer} */ (rgb.buffer)]);
