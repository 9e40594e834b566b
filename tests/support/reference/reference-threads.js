// The float64 reference (src/reference/render.js) split by rows over worker threads (one per
// core, reference-thread.js): the benchmark's converged reference (at 640x360 and 64 samples per
// pixel, ~15 million paths) and the accuracy report's converged references.
import os from 'node:os';
import { Worker } from 'node:worker_threads';

export async function renderReferenceParallel(
  source,
  view,
  options,
  threads = Math.max(1, os.availableParallelism?.() ?? os.cpus().length),
) {
  const { width, height } = view;
  const bands = [];
  for (let i = 0; i < threads; i++) {
    const first = Math.floor((i * height) / threads);
    const end = Math.floor(((i + 1) * height) / threads);
    if (end > first) bands.push([first, end]);
  }
  const parts = await Promise.all(
    bands.map(
      (rows) =>
        new Promise((resolve, reject) => {
          const worker = new Worker(new URL('./reference-thread.js', import.meta.url), {
            workerData: { source, view, options: { ...options, rows } },
          });
          worker.once('message', resolve);
          worker.once('error', reject);
          worker.once('exit', (code) => code !== 0 && reject(new Error(`reference worker exited with ${code}`)));
        }),
    ),
  );
  const rgb = new Float64Array(width * height * 3);
  let offset = 0;
  for (const part of parts) {
    rgb.set(part, offset);
    offset += part.length;
  }
  return { width, height, rgb };
}
