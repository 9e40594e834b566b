// One channel's moving input, whatever its kind: a video or music file, the webcam or the
// microphone, opened, asked for its texture at each frame's iTime, and closed. The render worker
// gets what frameAt gives in the frame's inputs (gpu/protocol.js FrameInputs.media).
//
// Why a folder of its own (src/player/inputs/): these run on the page's thread (WebCodecs, Web
// Audio, getUserMedia need it), are neither the app's state nor the page's edge, and are one
// concept, the moving channels, one module a kind; app/ and gpu/ hold twelve modules each already.

import { AudioFile } from './audio-file.js';
import { Microphone, Webcam } from './live-devices.js';
import { VideoFile } from './video-file.js';

/** @typedef {import('../gpu/protocol.js').MediaFrame} MediaFrame */
/** @typedef {'video' | 'music' | 'webcam' | 'mic'} MediaKind */

export class MediaInput {
  /**
   * @param {MediaKind} kind
   * @param {VideoFile | AudioFile | Webcam | Microphone} source
   */
  constructor(kind, source) {
    this.kind = kind;
    this.source = source;
  }

  /**
   * Opens one: a video or music file from its bytes, the webcam or the microphone by asking.
   * @param {MediaKind} kind
   * @param {Blob | null} blob the file (video, music)
   * @param {string} name the file's name, for errors
   */
  static async open(kind, blob, name) {
    if (kind === 'webcam') return new MediaInput(kind, await Webcam.open());
    if (kind === 'mic') return new MediaInput(kind, await Microphone.open());
    if (!blob) throw new Error(`${name}: no file`);
    return new MediaInput(kind, kind === 'video' ? await VideoFile.open(blob, name) : await AudioFile.decode(blob, name));
  }

  /**
   * The texture for a frame at iTime `time`, frames `delta` apart.
   * @param {number} time
   * @param {number} delta
   * @param {boolean} vflip rows flipped (images only: the site offers no flip for music and mic)
   * @returns {Promise<MediaFrame>}
   */
  async frameAt(time, delta, vflip) {
    const source = this.source;
    if (source instanceof VideoFile) return source.frameAt(time, vflip);
    if (source instanceof Webcam) return source.frameAt(vflip);
    if (source instanceof AudioFile) return source.frameAt(time, delta);
    return source.frameAt();
  }

  /**
   * The live page's clock, each frame it draws: music is heard while it plays at 1×.
   * @param {number} time
   * @param {boolean} running
   */
  follow(time, running) {
    if (this.source instanceof AudioFile) this.source.follow(time, running);
  }

  /** Stops what it plays or records. */
  close() {
    this.source.close();
  }
}
