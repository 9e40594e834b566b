// The page's widgets around the canvas, wired to the app: the toolbar (time, the frame-time
// readout, output: actions.js), the lil-gui panel, the editor, the keys (keys.js: shortcuts and
// the shader's keyboard), dropping a .glsl file, a Shadertoy JSON export or an image on the
// page, a status line for short confirmations, and the notes (notices.js).

import { Editor } from './ui/editor.js';
import { Panel } from './ui/panel.js';
import { Toolbar } from './ui/toolbar/toolbar.js';
import { installRecordDialog } from './ui/toolbar/record-dialog.js';
import { installShortcuts, watchKeyboard } from './ui/keys.js';
import { pageActions } from './ui/actions.js';
import { channelLoaded, installViewNote, showLoadNotes } from './ui/notices.js';
import { missingNotesTitle } from '../player/words.js';
import { installSound } from './ui/sound-controls.js';
import { KeptWork } from './kept-work.js';
import { droppedKind } from '../player/io/shader-loader.js';
import { shareLink } from '../player/io/share-link.js';
import { missingLines } from '../player/io/project-files.js';
import { openShader } from '../player/io/open-shader.js';
import { installInspection } from './inspect/inspection.js';

/** @typedef {import('../player/app/app.js').ShaderApp} ShaderApp */
/** @typedef {import('./ui/toolbar/frame-readout.js').Activity} Activity */

/** A compile is said in the readout once it has taken this long (a quick one never shows). */
const COMPILE_SAID_AFTER_S = 1;

/**
 * What the page is doing, for the frame-time readout.
 * @param {ShaderApp} app
 * @returns {Activity}
 */
function activity(app) {
  const { progress, count, stillFrames } = app.frames;
  const fraction = progress ? progress.y / Math.max(1, progress.height) : null;
  // the watchdog's view first: a compile that takes a while, a band past its limit
  const band = app.gpu.band;
  if (band && app.gpu.hung === 'drawing') return { phase: 'stalled', seconds: band.seconds };
  if (band && band.compiling && band.seconds >= COMPILE_SAID_AFTER_S) return { phase: 'compiling', seconds: band.seconds };
  // no shader runs: its compile failed (the overlay says why), and nothing is drawn
  if (!app.compiles.hasProgram && app.compiles.failed) return { phase: 'failed' };
  if (count === 0) return { phase: 'first', progress: fraction };
  if (app.converge.on) return { phase: 'converging', samples: stillFrames, of: app.converge.frames };
  // a frame drawn while paused is said only when it takes more than a band (a heavy one): a
  // cheap one is on the canvas before anyone could read the line
  if (!app.inputs.playing) return { phase: 'paused', progress: progress && progress.bands > 1 ? fraction : null };
  if (app.inputs.speed === 0) return { phase: 'still' };
  return { phase: 'playing' };
}

/**
 * @param {ShaderApp} app
 * @param {{builtinSource: string, recorder: import('../player/io/recorder.js').Recorder,
 *   viewNote: Parameters<typeof installViewNote>[2]}} page the built-in raytracer's text (the
 *   float64 reference is its twin), the page's recorder, and why a debug view of the shader shows
 *   nothing (the raytracer's: main.js plugs it in)
 * @returns the page's widgets and actions, for the page's hook (hook/page-hook.js) and the tests
 */
export function installUi(app, { builtinSource, recorder, viewNote }) {
  const stage = /** @type {HTMLElement} */ (document.getElementById('stage'));
  const statusLine = /** @type {HTMLElement} */ (document.getElementById('toast'));
  /** @type {ReturnType<typeof setTimeout> | undefined} */
  let toastTimer;
  /** @param {string} text */
  const toast = (text) => {
    statusLine.textContent = text;
    statusLine.hidden = false;
    clearTimeout(toastTimer);
    toastTimer = setTimeout(() => (statusLine.hidden = true), 3000);
  };

  // ---- widgets -------------------------------------------------------------------------------

  const actions = pageActions(app, {
    stage,
    toast,
    activeTab: () => editor.activeTab,
    toggleEditor: () => editor.toggle(),
    screenshotSize: (width, height) => panel.screenshotSize(width, height),
    shipped: () => kept.shippedBase(), // (kept: below, called later)
  });
  const canvas = /** @type {HTMLCanvasElement} */ (document.getElementById('view'));
  const inspection = installInspection(app, { stage, canvas, builtinSource });
  const toolbar = new Toolbar(
    /** @type {HTMLElement} */ (document.getElementById('toolbar')),
    { ...actions, toggleInspect: () => inspection.toggle(), compare: () => inspection.compare() },
    () => activity(app),
  );
  const sound = installSound(app, { toolbar, stage }); // the Sound tab: player, mute, meter
  inspection.inspector.on('mode', () => toolbar.setInspecting(inspection.inspector.active));
  const recording = installRecordDialog(app, recorder, toolbar.root, toast);
  toolbar.fit(); // with "Record" in it
  installViewNote(app, stage, viewNote);
  const panel = new Panel({
    onConverge: (on) =>
      app.converge.set(on).catch((error) => {
        console.warn(error.message);
        toast(error.message);
        panel.setConverging(app.converge.on, app.converge.available);
      }),
    scale: app.canvasSize.scale,
    cap: app.canvasSize.cap,
    sizeFixed: Boolean(app.canvasSize.fixed),
    onScale: (s) => app.setScale(s),
    onCap: (c) => app.setCap(c),
    onControl: (name, value) => app.setControls({ [name]: value }, 'panel'),
    onChannel: (i, file) =>
      app.setChannel(i, file).then(
        () => toast(channelLoaded(i, file)),
        (error) => {
          console.warn(error.message);
          toast(error.message);
        },
      ),
  });
  // work is never lost: what is kept of the editor's text, and its name
  const kept = new KeptWork(app, builtinSource);
  const editor = new Editor(/** @type {HTMLElement} */ (document.getElementById('editor')), {
    apply: (project, pasted) =>
      app
        // an edit goes on with the shader's clock; a paste over everything is a new shader
        .setProject(project, {
          origin: 'editor',
          name: kept.nameFor(project, pasted),
          info: app.projectInfo,
          continues: !pasted,
        })
        .catch(() => {}),
    pasteJson: (text) => {
      // a Shadertoy export pasted in: that shader, by its own name
      pastedShader = true;
      open(text, 'the pasted text', { origin: 'editor', json: true }, (loaded) =>
        kept.loadedFile(String(loaded.from.name), loaded.project),
      );
    },
    onToggle: (open) => toolbar.setEditorOpen(open),
    onChange: (project, typed, pastedOver = false) => kept.edited(project, typed, pastedOver),
  });

  // ---- notes on what a loaded shader cannot have ----------------------------------------------

  /** What the note says now ('' for nothing). */
  let notesShown = '';
  /** A shader pasted into the editor is a new one: its notes show even if the last one had the same. */
  let pastedShader = false;
  const showNotes = () => {
    const lines = missingLines(app);
    const key = lines.join('\n');
    // an edit of the same shader: said already (and maybe closed)
    if (key === notesShown && app.origin === 'editor' && !pastedShader) return;
    notesShown = key;
    pastedShader = false;
    showLoadNotes(stage, missingNotesTitle(app.fileName), lines);
  };

  /**
   * Opens a shader's text (io/open-shader.js); a text that cannot be read is said in a note. A
   * compile error is the overlay's.
   * @param {string} text
   * @param {string} what what it is, in the message
   * @param {import('../player/io/open-shader.js').ShaderFrom} from
   * @param {(loaded: ReturnType<typeof import('../player/io/open-shader.js').readShader>) => void} [onRead] called before it runs
   */
  const open = (text, what, from, onRead = () => {}) => {
    let opened;
    try {
      opened = openShader(app, text, from, onRead);
    } catch (error) {
      console.warn(`${what}: ${error.message}`);
      notesShown = '\u0000error'; // goes with the next shader loaded
      showLoadNotes(stage, `Could not load ${what}`, [error.message], 'error');
      toast(`Could not load ${what}`);
      return false;
    }
    opened.running.catch(() => {}); // a compile error: the overlay says it
    return true;
  };

  const showState = () => {
    toolbar.update({ playing: app.inputs.playing, time: app.inputs.time, speed: app.inputs.speed, name: app.fileName });
  };
  let shownAt = 0;
  app.on('state', () => {
    panel.setConverging(app.converge.on, app.converge.available);
    panel.sync(app.values);
    panel.setChannelSizes(app.channels.sizes());
    showState();
  });
  app.on('drawn', (_, frame) => {
    toolbar.readout.drawn(frame);
    const now = performance.now();
    if (now - shownAt > 100) {
      shownAt = now;
      showState();
    }
  });
  app.on('source', () => {
    panel.setControls(app.controls, app.values);
    panel.setConverging(app.converge.on, app.converge.available);
    editor.setProject(app.project, app.fileName);
    showNotes();
    document.title = `${app.fileName} · Shadertoy runner`;
    showState();
  });
  app.on('notes', showNotes);
  app.on('compile', () => {
    editor.setErrors(app.compiles.errors);
    showState(); // a paused restart or time change shows once drawn
  });
  showState();

  // ---- keys ----------------------------------------------------------------------------------

  installShortcuts({
    Space: () => app.togglePlay(),
    KeyR: () => app.restart(),
    KeyF: () => actions.toggleFullscreen(),
    KeyI: () => inspection.toggle(),
  });
  // a key redraws only a shader that reads the keyboard (any other has nothing new to show)
  watchKeyboard(app.keyboard, () => app.readsKeyboard && app.frames.request());
  document.addEventListener('fullscreenchange', () => toolbar.setFullscreen(document.fullscreenElement !== null));

  // ---- drag and drop -------------------------------------------------------------------------

  const dropHint = /** @type {HTMLElement} */ (document.getElementById('drop-hint'));
  let dragDepth = 0;
  /** @type {(event: DragEvent) => event is DragEvent & {dataTransfer: DataTransfer}} */
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
    if (kind === 'image' || kind === 'video' || kind === 'music') {
      await app.setChannel(0, file).then(
        () => toast(channelLoaded(0, file)),
        (error) => toast(error.message),
      );
    } else if (kind === 'shader' || kind === 'json') {
      if (open(await file.text(), file.name, { fileName: file.name, origin: 'file', json: kind === 'json' })) toast(`Running ${file.name}`);
    } else {
      toast(`${file.name} is neither a shader (.glsl, Shadertoy's .json) nor an image`);
    }
  });

  /** The link that reproduces this view (share-link.js). */
  const shareUrl = async () => (await shareLink(app, kept.shippedBase())).url;
  return { toast, toolbar, panel, editor, kept, actions, shareUrl, recording, open, inspection, sound };
}
