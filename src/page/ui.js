// The page's widgets around the canvas, wired to the app: the toolbar (time and output), the
// lil-gui panel, the editor, keyboard shortcuts (shortcuts.js: Space, R, F), dropping a
// .glsl file, a Shadertoy JSON export or an image on the page, a status line for short
// confirmations, and the note that says what a loaded shader cannot have (load-notes.js).

import { Editor } from './editor.js';
import { KeptSource, fileStem } from './kept-source.js';
import { Panel } from './panel.js';
import { Toolbar } from './toolbar.js';
import { installRecordDialog } from './record-dialog.js';
import { droppedKind } from './shader-loader.js';
import { installShortcuts } from './shortcuts.js';
import { toggleFullscreen, watchFullscreen } from './fullscreen.js';
import { MAX_LINK_LENGTH, shareLink } from './share-link.js';
import { exportJson, projectTabs, readShaderText, serializeProject, shaderNotes, tabCode, tabFileName } from './project-files.js';
import { showLoadNotes } from './load-notes.js';

/** Saves a Blob as a file, as a link with `download` does. */
function saveBlob(blob, fileName) {
  const url = URL.createObjectURL(blob);
  const link = document.createElement('a');
  link.href = url;
  link.download = fileName;
  link.hidden = true;
  document.body.append(link);
  link.click();
  link.remove();
  setTimeout(() => URL.revokeObjectURL(url), 60_000);
}

/** Copies text: the async Clipboard API, or the older copy command where that is refused. */
async function copyText(text) {
  try {
    await navigator.clipboard.writeText(text);
    return true;
  } catch {
    const area = document.createElement('textarea');
    area.value = text;
    area.setAttribute('readonly', '');
    area.style.position = 'fixed';
    area.style.opacity = '0';
    document.body.append(area);
    area.select();
    let ok;
    try {
      ok = document.execCommand('copy');
    } catch {
      ok = false;
    }
    area.remove();
    return ok;
  }
}

/** RGBA rows top to bottom → PNG Blob. */
export function pngBlob({ width, height, data }) {
  const canvas = document.createElement('canvas');
  canvas.width = width;
  canvas.height = height;
  const context = canvas.getContext('2d');
  context.putImageData(new ImageData(new Uint8ClampedArray(data.buffer, data.byteOffset, data.byteLength), width, height), 0, 0);
  return new Promise((resolve, reject) =>
    canvas.toBlob((blob) => (blob ? resolve(blob) : reject(new Error('PNG encoding failed'))), 'image/png'),
  );
}

/** A file name without its folders and extension ("raytrace-edited" for an edited shader). */
const stem = fileStem;

/**
 * @param {import('./app.js').RaytracerApp} app
 * @returns the page's output actions, for the automation hook and the tests
 */
export function installUi(app) {
  const stage = /** @type {HTMLElement} */ (document.getElementById('stage'));
  const statusLine = document.getElementById('toast');
  /** @type {ReturnType<typeof setTimeout> | undefined} */
  let toastTimer;
  const toast = (text) => {
    statusLine.textContent = text;
    statusLine.hidden = false;
    clearTimeout(toastTimer);
    toastTimer = setTimeout(() => (statusLine.hidden = true), 3000);
  };

  // ---- output --------------------------------------------------------------------------------

  /** The link that reproduces this view (share-link.js). */
  const shareUrl = async () => (await shareLink(app)).url;

  const actions = {
    togglePlay: () => app.togglePlay(),
    restart: () => app.restart(),
    setTime: (t) => app.setTime(t),
    setSpeed: (s) => app.setSpeed(s),
    toggleEditor: () => editor.toggle(),
    toggleFullscreen: () => toggleFullscreen(stage),

    /**
     * Exactly the text Shadertoy's tab takes: the shader file, or the editor's tab of a multipass
     * shader (Shadertoy adds the header).
     */
    async copyForShadertoy() {
      const { tab, code, multipass } = shownTab();
      const ok = await copyText(code);
      const what = multipass ? `${tab} of ${app.fileName}` : app.fileName;
      toast(
        ok
          ? `Copied ${what} (${code.split('\n').length} lines): paste it into Shadertoy's ${tab} tab`
          : 'The browser refused to copy; use Download .glsl instead',
      );
      return ok;
    },

    /** Saves the shader file, or the editor's tab of a multipass shader ("NAME - Buffer A.glsl"). */
    download() {
      const { tab, code, multipass } = shownTab();
      const name = tabFileName(stem(app.fileName), tab, multipass);
      saveBlob(new Blob([code], { type: 'text/plain;charset=utf-8' }), name);
      toast(`Saved ${name}`);
      return name;
    },

    /** Saves the whole shader, every tab and channel, as Shadertoy's JSON export ("NAME.json"). */
    exportJson() {
      const name = `${stem(app.fileName)}.json`;
      saveBlob(new Blob([exportJson(app.project, app.projectInfo, stem(app.fileName))], { type: 'application/json' }), name);
      toast(`Saved ${name} (Shadertoy's JSON format, ${projectTabs(app.project).length} tabs)`);
      return name;
    },

    /** A PNG of the current frame, at the size chosen in the panel (canvas size by default). */
    async screenshot(size = null) {
      try {
        const image = await app.capture(size ?? panel.screenshotSize(app.renderer.width, app.renderer.height));
        const name = `${stem(app.fileName)}-t${app.inputs.last.time.toFixed(2)}-${image.width}x${image.height}.png`;
        saveBlob(await pngBlob(image), name);
        toast(`Saved ${name}`);
        return { name, width: image.width, height: image.height };
      } catch (error) {
        console.warn(`Screenshot failed: ${error.message}`);
        toast(`Screenshot failed: ${error.message}`);
        return null;
      }
    },

    /** Copies the view's link, saying what it leaves out; a link too long to travel is not copied. */
    async copyLink() {
      const { url, omitted, tooLong } = await shareLink(app);
      if (tooLong) {
        toast(
          `Not copied: the link would be ${url.length} characters, too long for many browsers and apps (over ${MAX_LINK_LENGTH}); share the shader with Download .glsl`,
        );
        return null;
      }
      const ok = await copyText(url);
      const caveat = omitted.length ? ` (${omitted.join(', ')} ${omitted.length > 1 ? 'are' : 'is'} not in the link)` : '';
      toast(ok ? `Copied a link to this view${caveat}` : 'The browser refused to copy the link');
      return url;
    },
  };

  // ---- widgets -------------------------------------------------------------------------------

  const toolbar = new Toolbar(document.getElementById('toolbar'), actions);
  const recording = installRecordDialog(app, toolbar.root, { saveBlob, toast });
  const panel = new Panel({
    onConverge: (on) =>
      app.setConverging(on).catch((error) => {
        console.warn(error.message);
        toast(error.message);
        panel.setConverging(app.converging, app.canConverge);
      }),
    scale: app.canvasSize.scale,
    cap: app.canvasSize.cap,
    sizeFixed: Boolean(app.canvasSize.fixed),
    onScale: (s) => app.setScale(s),
    onCap: (c) => app.setCap(c),
    onControl: (name, value) => app.setControls({ [name]: value }, 'panel'),
    onChannel: (i, file) =>
      app.setChannel(i, file).then(
        () => toast(file ? `Loaded ${file.name} into iChannel${i}` : `Emptied iChannel${i}`),
        (error) => {
          console.warn(error.message);
          toast(error.message);
        },
      ),
  });
  // an edited shader's name: "untitled" after a paste over everything, else "NAME (edited)"
  const kept = new KeptSource();
  const editor = new Editor(document.getElementById('editor'), {
    apply: (project, pasted) =>
      app
        .setProject(project, { origin: 'editor', name: kept.nameFor(serializeProject(project), pasted), info: app.projectInfo })
        .catch(() => {}),
    pasteJson: (text) => {
      // a Shadertoy export pasted in: that shader, by its own name
      const loaded = readText(text, 'the pasted text', { json: true });
      if (!loaded) return;
      const name = String(loaded.info?.name || 'untitled');
      kept.loadedFile({ name, source: serializeProject(loaded.model) });
      pastedShader = true;
      app.setProject(loaded.model, { origin: 'editor', name, info: loaded.info }).catch(() => {});
    },
    onToggle: (open) => toolbar.setEditorOpen(open),
    onChange: (project) => kept.save(serializeProject(project)),
  });

  /** The editor's tab and its text as the page runs it (the whole file for a single-pass shader). */
  const shownTab = () => {
    const multipass = projectTabs(app.project).length > 1;
    const tab = multipass ? editor.activeTab : 'Image';
    return { tab, multipass, code: tabCode(app.project, tab) ?? app.source };
  };

  // ---- notes on what a loaded shader cannot have ----------------------------------------------

  /** What the note says now ('' for nothing). */
  let notesShown = '';
  /** A shader pasted into the editor is a new one: its notes show even if the last one had the same. */
  let pastedShader = false;
  const showNotes = () => {
    const lines = [...new Set([...app.notes, ...shaderNotes(app.project)])];
    const key = lines.join('\n');
    // an edit of the same shader: said already (and maybe closed)
    if (key === notesShown && app.origin === 'editor' && !pastedShader) return;
    notesShown = key;
    pastedShader = false;
    showLoadNotes(stage, `${app.fileName} runs without some of what it asks for`, lines);
  };

  /**
   * Reads a shader's text (a Shadertoy export or GLSL); a text that cannot be read is said in a
   * note, and null returned.
   * @param {string} text
   * @param {string} name what it is, in the message
   * @param {{json?: boolean}} [options]
   */
  const readText = (text, name, options) => {
    try {
      return readShaderText(text, options);
    } catch (error) {
      console.warn(`${name}: ${error.message}`);
      notesShown = '\u0000error'; // goes with the next shader loaded
      showLoadNotes(stage, `Could not load ${name}`, [error.message], 'error');
      toast(`Could not load ${name}`);
      return null;
    }
  };

  const showState = () => {
    toolbar.update({ playing: app.inputs.playing, time: app.inputs.time, speed: app.inputs.speed, name: app.fileName });
  };
  let shownAt = 0;
  app.on('state', () => {
    panel.setConverging(app.converging, app.canConverge);
    panel.sync(app.values);
    panel.setChannelSizes(app.renderer.channelSizes());
    showState();
  });
  app.on('frame', (_, ms) => {
    toolbar.addGpuTimes(app.renderer.gpuTimer.poll());
    toolbar.addFrameTime(ms);
    const now = performance.now();
    if (now - shownAt > 100) {
      shownAt = now;
      showState();
    }
  });
  app.on('source', () => {
    if (app.origin !== 'editor') kept.loadedFile({ name: app.fileName, source: serializeProject(app.project) });
    panel.setControls(app.controls, app.values);
    panel.setConverging(app.converging, app.canConverge);
    editor.setProject(app.project, app.fileName);
    showNotes();
    document.title = `${app.fileName} · Shadertoy runner`;
    showState();
  });
  app.on('compile', () => {
    editor.setErrors(app.compileErrors);
    showState(); // a paused restart or time change shows once drawn
  });
  showState();

  // ---- keyboard ------------------------------------------------------------------------------

  installShortcuts({ Space: () => app.togglePlay(), KeyR: () => app.restart(), KeyF: () => actions.toggleFullscreen() });
  watchFullscreen((on) => toolbar.setFullscreen(on));

  // ---- drag and drop -------------------------------------------------------------------------

  const dropHint = document.getElementById('drop-hint');
  let dragDepth = 0;
  const hasFiles = (event) => [...(event.dataTransfer?.types ?? [])].includes('Files');
  document.addEventListener('dragenter', (event) => {
    if (!hasFiles(event)) return;
    event.preventDefault();
    dragDepth++;
    dropHint.hidden = false;
  });
  document.addEventListener('dragover', (event) => {
    if (!hasFiles(event)) return;
    event.preventDefault();
    event.dataTransfer.dropEffect = 'copy';
  });
  document.addEventListener('dragleave', () => {
    if (--dragDepth <= 0) {
      dragDepth = 0;
      dropHint.hidden = true;
    }
  });
  document.addEventListener('drop', async (event) => {
    if (!hasFiles(event)) return;
    event.preventDefault();
    dragDepth = 0;
    dropHint.hidden = true;
    const file = event.dataTransfer.files[0];
    if (!file) return;
    const kind = droppedKind(file);
    if (kind === 'image') {
      await app.setChannel(0, file).then(
        () => toast(`Loaded ${file.name} into iChannel0`),
        (error) => toast(error.message),
      );
    } else if (kind === 'shader' || kind === 'json') {
      const loaded = readText(await file.text(), file.name, { json: kind === 'json' });
      if (!loaded) return;
      app.setProject(loaded.model, { name: file.name, origin: 'file', info: loaded.info }).catch(() => {});
      toast(`Running ${file.name}`);
    } else {
      toast(`${file.name} is neither a shader (.glsl, Shadertoy's .json) nor an image`);
    }
  });

  return { toast, toolbar, panel, editor, kept, actions, shareUrl, recording };
}
