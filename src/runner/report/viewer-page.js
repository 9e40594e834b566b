// The HTML report's image viewer, in the page (viewer.js writes its HTML): one zoom and one
// centre a case, shared by its views (reference, actual, diff, comparison), each image placed in
// its viewport by a translate; drag pans, Ctrl+wheel zooms about the pointer, the arrow keys and
// + / - do both from the keyboard. The difference's box is outlined a few CSS pixels wide at any
// zoom. The pixel under the pointer is marked in every view and read in every image, from the
// case's -pixels.js (data: URLs, which a canvas may read) loaded when the pointer first comes.

export const VIEWER_STYLE = `
.tools { display: flex; flex-wrap: wrap; gap: 6px; align-items: center; margin: 8px 0; }
.tools > span { color: var(--skip); margin-left: 8px; }
.tools label { display: inline-flex; gap: 4px; align-items: center; }
.images, .statics { display: flex; flex-wrap: wrap; gap: 12px; align-items: flex-start; }
figure { margin: 0; }
figcaption { font-size: 12px; color: var(--skip); }
.view { position: relative; width: var(--vw); height: var(--vh); overflow: hidden; cursor: grab; touch-action: none; background: repeating-conic-gradient(#8883 0% 25%, transparent 0% 50%) 0 0 / 16px 16px; outline-offset: 2px; }
.view.panning { cursor: grabbing; }
.images img, .statics img { display: block; image-rendering: pixelated; }
.view img { position: absolute; left: 0; top: 0; max-width: none; transform-origin: 0 0; user-select: none; }
.view .top { position: absolute; inset: 0; clip-path: inset(0 0 0 var(--cut, 50%)); }
.compare[data-mode="reference"] .top { visibility: hidden; }
.compare[data-mode="actual"] .top { clip-path: none; }
.compare:not([data-mode="slider"]) input[type="range"] { visibility: hidden; }
.compare input[type="range"] { display: block; width: var(--vw); margin: 4px 0 0; }
.mark, .cursor { position: absolute; pointer-events: none; display: none; }
.mark { border: 2px solid #fff; box-shadow: 0 0 0 1px #000, inset 0 0 0 1px #000; }
.mark i { display: none; position: absolute; background: #fff; box-shadow: 0 0 0 1px #000; }
.mark.small i { display: block; }
.mark i:nth-child(-n + 2) { left: calc(50% - 1px); width: 2px; height: 10px; }
.mark i:nth-child(n + 3) { top: calc(50% - 1px); width: 10px; height: 2px; }
.mark i:nth-child(1) { bottom: calc(100% + 6px); }
.mark i:nth-child(2) { top: calc(100% + 6px); }
.mark i:nth-child(3) { right: calc(100% + 6px); }
.mark i:nth-child(4) { left: calc(100% + 6px); }
.images:not(.unmarked) .mark.on, .cursor.on { display: block; }
.cursor { border: 1px solid #fff; box-shadow: 0 0 0 1px #000; }
.readout { margin: 6px 0; font: 12px/1.5 ui-monospace, monospace; color: var(--skip); min-height: 1.5em; white-space: pre-wrap; }
`;

/** The viewer's script: written into index.html as `(source)()`. It runs in the report's page. */
export function viewerScript() {
  /** How far outside the difference's box its outline is drawn, in CSS pixels. */
  const PAD = 5;
  /** Below this size (CSS pixels) the outline also gets a crosshair's arms. */
  const SMALL = 24;
  /** @param {string | undefined} text */
  const nums = (text) => (text ?? '').split(' ').filter(Boolean).map(Number);
  /** @typedef {{images: Record<string, {width: number, data: Uint8ClampedArray}>} | 'loading' | 'missing'} Pixels */
  /** @type {WeakMap<HTMLElement, Pixels>} */
  const pixels = new WeakMap();
  /** @type {WeakMap<Element, HTMLElement>} */
  const loading = new WeakMap();

  /** Places every view of a viewer at its zoom and centre (the centre kept so the image covers the viewport). @param {HTMLElement} viewer */
  const layout = (viewer) => {
    const zoom = Number(viewer.dataset.zoom);
    const [width, height] = nums(viewer.dataset.size);
    const [vw, vh] = nums(viewer.dataset.view);
    const [cx, cy] = nums(viewer.dataset.center);
    const place = (/** @type {number} */ size, /** @type {number} */ c, /** @type {number} */ port) =>
      Math.round(size * zoom <= port ? (port - size * zoom) / 2 : Math.min(0, Math.max(port - size * zoom, port / 2 - c * zoom)));
    const [tx, ty] = [place(width, cx, vw), place(height, cy, vh)];
    viewer.dataset.at = `${tx} ${ty}`;
    const box = nums(viewer.dataset.box);
    for (const view of viewer.querySelectorAll('.view')) {
      for (const img of view.querySelectorAll('img'))
        Object.assign(/** @type {HTMLElement} */ (img).style, {
          width: `${width * zoom}px`,
          height: `${height * zoom}px`,
          transform: `translate(${tx}px, ${ty}px)`,
        });
      const mark = /** @type {HTMLElement} */ (view.querySelector('.mark'));
      if (box.length === 4) {
        const [w, h] = [(box[2] - box[0] + 1) * zoom, (box[3] - box[1] + 1) * zoom];
        Object.assign(mark.style, {
          left: `${tx + box[0] * zoom - PAD}px`,
          top: `${ty + box[1] * zoom - PAD}px`,
          width: `${w + 2 * PAD}px`,
          height: `${h + 2 * PAD}px`,
        });
        mark.classList.add('on');
        mark.classList.toggle('small', Math.max(w, h) < SMALL);
      }
    }
    for (const button of viewer.parentElement?.querySelectorAll('[data-zoom]') ?? [])
      button.setAttribute('aria-pressed', String(Math.abs(Number(/** @type {HTMLElement} */ (button).dataset.zoom) - zoom) < 1e-3));
  };

  /**
   * Sets a viewer's zoom and centre, and places its views. The centre kept is the one shown: the
   * image's middle where it fits the viewport, else no nearer its edge than half the viewport.
   * @param {HTMLElement} viewer @param {number} zoom @param {number} cx @param {number} cy
   */
  const show = (viewer, zoom, cx, cy) => {
    const [width, height] = nums(viewer.dataset.size);
    const [vw, vh] = nums(viewer.dataset.view);
    const keep = (/** @type {number} */ c, /** @type {number} */ size, /** @type {number} */ port) =>
      size * zoom <= port ? size / 2 : Math.min(size - port / 2 / zoom, Math.max(port / 2 / zoom, c));
    viewer.dataset.zoom = String(zoom);
    viewer.dataset.center = `${keep(cx, width, vw)} ${keep(cy, height, vh)}`;
    layout(viewer);
  };

  /** The zooms the viewer's buttons offer, smallest first. @param {HTMLElement} viewer */
  const zoomsOf = (viewer) =>
    [...(viewer.parentElement?.querySelectorAll('[data-zoom]') ?? [])].map((b) => Number(/** @type {HTMLElement} */ (b).dataset.zoom));

  /** The next zoom up (step 1) or down (-1), keeping the image point (px, py) where it is. @param {HTMLElement} viewer @param {number} step @param {number} [px] @param {number} [py] */
  const zoomBy = (viewer, step, px, py) => {
    const zoom = Number(viewer.dataset.zoom);
    const zooms = zoomsOf(viewer);
    const next = step > 0 ? zooms.find((z) => z > zoom + 1e-3) : zooms.filter((z) => z < zoom - 1e-3).at(-1);
    if (next === undefined) return;
    const [cx, cy] = nums(viewer.dataset.center);
    const [x, y] = [px ?? cx, py ?? cy];
    show(viewer, next, x - ((x - cx) * zoom) / next, y - ((y - cy) * zoom) / next);
  };

  /** The image pixel under a pointer event in a view, as floats. @param {HTMLElement} viewer @param {Element} view @param {MouseEvent} event */
  const pointAt = (viewer, view, event) => {
    const rect = view.getBoundingClientRect();
    const [tx, ty] = nums(viewer.dataset.at);
    const zoom = Number(viewer.dataset.zoom);
    return [(event.clientX - rect.left - tx) / zoom, (event.clientY - rect.top - ty) / zoom];
  };

  /** Loads the viewer's -pixels.js once. @param {HTMLElement} viewer */
  const load = (viewer) => {
    if (pixels.has(viewer) || !viewer.dataset.pixels) return;
    pixels.set(viewer, 'loading');
    const script = document.createElement('script');
    script.src = viewer.dataset.pixels;
    loading.set(script, viewer);
    script.onerror = () => pixels.set(viewer, 'missing');
    document.head.append(script);
  };

  /** What a -pixels.js calls: decodes its images into pixel arrays. @param {Record<string, string>} urls */
  /** @type {any} */ (window).shaderproofPixels = (urls) => {
    const viewer = document.currentScript && loading.get(document.currentScript);
    if (!viewer) return;
    Promise.all(
      Object.entries(urls).map(async ([kind, url]) => {
        const img = new Image();
        img.src = url;
        await img.decode();
        const canvas = document.createElement('canvas');
        [canvas.width, canvas.height] = [img.naturalWidth, img.naturalHeight];
        const context = /** @type {CanvasRenderingContext2D} */ (canvas.getContext('2d', { willReadFrequently: true }));
        context.drawImage(img, 0, 0);
        return [kind, { width: img.naturalWidth, data: context.getImageData(0, 0, img.naturalWidth, img.naturalHeight).data }];
      }),
    ).then(
      (images) => pixels.set(viewer, { images: Object.fromEntries(images) }),
      () => pixels.set(viewer, 'missing'),
    );
  };

  /** Marks pixel (x, y) in every view and reads it in every image, or clears both. @param {HTMLElement} viewer @param {number[] | null} at */
  const readout = (viewer, at) => {
    const line = /** @type {HTMLElement | null} */ (viewer.nextElementSibling);
    const [width, height] = nums(viewer.dataset.size);
    const inside = at && at[0] >= 0 && at[1] >= 0 && at[0] < width && at[1] < height;
    const [tx, ty] = nums(viewer.dataset.at);
    const zoom = Number(viewer.dataset.zoom);
    for (const cursor of viewer.querySelectorAll('.cursor')) {
      const style = /** @type {HTMLElement} */ (cursor).style;
      cursor.classList.toggle('on', Boolean(inside));
      if (!inside || !at) continue;
      const size = Math.max(zoom, 7);
      Object.assign(style, {
        left: `${tx + (at[0] + 0.5) * zoom - size / 2 - 1}px`,
        top: `${ty + (at[1] + 0.5) * zoom - size / 2 - 1}px`,
        width: `${size + 2}px`,
        height: `${size + 2}px`,
      });
    }
    if (!line) return;
    if (!inside || !at) {
      line.textContent = line.dataset.hintText ?? line.textContent;
      return;
    }
    line.dataset.hintText ??= line.textContent ?? '';
    const [x, y] = at;
    const got = pixels.get(viewer);
    const values =
      got === 'missing'
        ? ["the values need this case's -pixels.js beside index.html"]
        : !got || got === 'loading'
          ? ['reading the values…']
          : Object.entries(got.images).map(([kind, { width: w, data }]) => {
              const i = (y * w + x) * 4;
              return `${kind} ${[...data.subarray(i, i + 4)].join(',')}`;
            });
    line.textContent = [`(${x}, ${y})`, ...values].join(' · ');
    delete line.dataset.hint;
  };

  /** @param {Event} event */
  const viewOf = (event) => {
    const view = /** @type {Element} */ (event.target).closest?.('.view');
    const viewer = /** @type {HTMLElement | null} */ (view?.closest('.images') ?? null);
    return view && viewer ? { view, viewer } : null;
  };

  /** @type {{viewer: HTMLElement, view: Element, x: number, y: number, center: number[]} | null} */
  let drag = null;
  document.addEventListener('pointerdown', (event) => {
    const found = viewOf(event);
    if (!found || event.button !== 0) return;
    drag = { ...found, x: event.clientX, y: event.clientY, center: nums(found.viewer.dataset.center) };
    found.view.classList.add('panning');
    /** @type {HTMLElement} */ (found.view).setPointerCapture(event.pointerId);
    event.preventDefault();
  });
  document.addEventListener('pointermove', (event) => {
    if (drag) {
      const zoom = Number(drag.viewer.dataset.zoom);
      show(drag.viewer, zoom, drag.center[0] - (event.clientX - drag.x) / zoom, drag.center[1] - (event.clientY - drag.y) / zoom);
    }
    const found = drag ?? viewOf(event);
    if (!found) return;
    load(found.viewer);
    const [px, py] = pointAt(found.viewer, found.view, event);
    readout(found.viewer, [Math.floor(px), Math.floor(py)]);
  });
  const release = () => {
    drag?.view.classList.remove('panning');
    drag = null;
  };
  document.addEventListener('pointerup', release);
  document.addEventListener('pointercancel', release);
  document.addEventListener(
    'pointerout',
    (event) => {
      const found = viewOf(event);
      if (found && !drag && !found.view.contains(/** @type {Node | null} */ (event.relatedTarget))) readout(found.viewer, null);
    },
    true,
  );
  document.addEventListener(
    'wheel',
    (event) => {
      const found = viewOf(event);
      if (!found || !(event.ctrlKey || event.metaKey)) return;
      event.preventDefault();
      const [px, py] = pointAt(found.viewer, found.view, event);
      zoomBy(found.viewer, event.deltaY < 0 ? 1 : -1, px, py);
    },
    { passive: false },
  );
  document.addEventListener('keydown', (event) => {
    const found = viewOf(event);
    if (!found || event.ctrlKey || event.metaKey || event.altKey) return;
    const { viewer } = found;
    const zoom = Number(viewer.dataset.zoom);
    const [vw, vh] = nums(viewer.dataset.view);
    const [cx, cy] = nums(viewer.dataset.center);
    const steps = { ArrowLeft: [-vw / 4, 0], ArrowRight: [vw / 4, 0], ArrowUp: [0, -vh / 4], ArrowDown: [0, vh / 4] };
    const step = /** @type {Record<string, number[]>} */ (steps)[event.key];
    if (step) show(viewer, zoom, cx + step[0] / zoom, cy + step[1] / zoom);
    else if (event.key === '+' || event.key === '=') zoomBy(viewer, 1);
    else if (event.key === '-') zoomBy(viewer, -1);
    else return;
    event.preventDefault();
  });
  document.addEventListener('click', (event) => {
    const target = /** @type {HTMLElement} */ (event.target);
    const viewer = /** @type {HTMLElement | null} */ (target.closest('.body')?.querySelector('.images') ?? null);
    if (!viewer) return;
    const button = /** @type {HTMLElement | null} */ (target.closest('button'));
    const [cx, cy] = nums(viewer.dataset.center);
    if (button?.dataset.zoom) show(viewer, Number(button.dataset.zoom), cx, cy);
    else if (button?.hasAttribute('data-goto')) {
      const [zoom, x, y] = nums(viewer.dataset.opening);
      show(viewer, zoom, x, y);
    } else if (target.matches('[data-outline]')) viewer.classList.toggle('unmarked', !(/** @type {HTMLInputElement} */ (target).checked));
  });
  document.addEventListener('input', (event) => {
    const slider = /** @type {HTMLInputElement} */ (event.target);
    if (slider.type !== 'range') return;
    /** @type {HTMLElement | null} */ (slider.closest('.compare'))?.style.setProperty('--cut', `${slider.value}%`);
  });
  for (const viewer of document.querySelectorAll('.images[data-zoom]')) {
    const [zoom, cx, cy] = nums(/** @type {HTMLElement} */ (viewer).dataset.opening);
    show(/** @type {HTMLElement} */ (viewer), zoom, cx, cy);
  }
}
