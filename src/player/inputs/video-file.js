// A video input from a file, decoded frame by frame at the frame's iTime: the frame shown at
// iTime is the last one whose timestamp is at or before it, never whatever a <video> element had
// ready, so a recording or the command line gets the same picture on every run. WebM and MP4 are
// decoded by the browser (mediabunny's VideoSampleSink over WebCodecs); Ogg Theora, which
// Chromium no longer decodes, by ogv.js's WebAssembly (theora-video.js, loaded only for one).
//
// On the site a video input is a <video loop> element started when it can play; each frame its
// current picture is uploaded with UNPACK_FLIP_Y = the sampler's vflip, mipmaps made again when the
// filter is "mipmap"; iChannelTime is its currentTime and iChannelResolution (videoWidth,
// videoHeight, 1) (effect.js: NewTexture "video", Paint_Image; piLibs.js UpdateTextureFromImage).
// Here the video's clock is iTime, looped: iChannelTime = iTime mod its duration.
//
// Its sound is not read: the site plays a video's sound aloud but gives a shader only its
// picture, and the page plays no video's sound (docs/compatibility.md).

/** @typedef {{kind: 'video', image: ImageBitmap, width: number, height: number, time: number}} VideoFrameInput */
/**
 * A decoder's frame: its timestamp (seconds from the video's start), its picture on demand.
 * @typedef {{timestamp: number, image: (vflip: boolean) => Promise<ImageBitmap>, close: () => void}} DecodedFrame
 */
/**
 * A video's frames, whatever decodes them: the one shown `seconds` after its start (from 0 to
 * its duration), or null if it has none there.
 * @typedef {{duration: number, sampleAt: (seconds: number) => Promise<DecodedFrame | null>}} FrameSource
 */

/** An Ogg file starts with its first page's capture pattern. */
async function isOgg(/** @type {Blob} */ blob) {
  const head = new Uint8Array(await blob.slice(0, 4).arrayBuffer());
  return String.fromCharCode(...head) === 'OggS';
}

/**
 * The frames of a WebM or MP4 file the browser's WebCodecs decodes.
 * @param {Blob} blob
 * @param {(why: string, cause: unknown) => Error} fail
 * @returns {Promise<FrameSource>}
 */
async function openWebCodecs(blob, fail) {
  const { ALL_FORMATS, BlobSource, Input, VideoSampleSink } = await import('mediabunny');
  let track;
  try {
    const input = new Input({ source: new BlobSource(blob), formats: ALL_FORMATS });
    track = await input.getPrimaryVideoTrack();
  } catch (error) {
    throw fail('not a video file', error);
  }
  if (!track) throw fail('it has no video track', null);
  if (!(await track.canDecode())) throw fail('this browser cannot decode its codec', null);
  const start = await track.getFirstTimestamp();
  const duration = (await track.computeDuration()) - start;
  const sink = new VideoSampleSink(track);
  return {
    duration,
    async sampleAt(seconds) {
      const sample = (await sink.getSample(start + seconds)) ?? (await sink.getSample(start));
      if (!sample) return null;
      return {
        timestamp: sample.timestamp,
        async image(vflip) {
          const videoFrame = sample.toVideoFrame();
          try {
            return await createImageBitmap(videoFrame, {
              imageOrientation: vflip ? 'flipY' : 'from-image',
              colorSpaceConversion: 'none',
              premultiplyAlpha: 'none',
            });
          } finally {
            videoFrame.close();
          }
        },
        close: () => sample.close(),
      };
    },
  };
}

export class VideoFile {
  /**
   * @param {FrameSource} source
   */
  constructor(source) {
    this.source = source;
    this.duration = source.duration;
    /** The last frame made, by its timestamp and flip, to give again while it is the one shown. @type {{key: string, frame: VideoFrameInput} | null} */
    this._last = null;
  }

  /**
   * Opens a video file: WebM or MP4 the browser's WebCodecs decodes, or Ogg Theora.
   * @param {Blob} blob
   * @param {string} name for the error
   */
  static async open(blob, name) {
    const fail = (/** @type {string} */ why, /** @type {unknown} */ cause) =>
      new Error(`cannot play ${name} as a video: ${why}; use a WebM (VP8, VP9, AV1), MP4 (H.264) or Ogg (Theora) file`, { cause });
    if (!(await isOgg(blob))) return new VideoFile(await openWebCodecs(blob, fail));
    let theora;
    try {
      theora = await import('./theora-video.js');
      await theora.loadDecoder();
    } catch (error) {
      // the page's own files, not the video: a build served without its assets
      throw new Error(
        `cannot play ${name} as a video: the page could not load its Theora decoder (${error.message}); build the page again (npm run build)`,
        { cause: error },
      );
    }
    try {
      return new VideoFile(await theora.openTheora(blob));
    } catch (error) {
      throw fail(error.message, error);
    }
  }

  /**
   * The picture at iTime `time` (looped), its rows flipped when `vflip` (as the site uploads it).
   * @param {number} time
   * @param {boolean} vflip
   * @returns {Promise<VideoFrameInput>}
   */
  async frameAt(time, vflip) {
    const local = this.duration > 0 ? time % this.duration : 0;
    const sample = await this.source.sampleAt(local);
    if (!sample) throw new Error('the video has no frame');
    try {
      const key = `${sample.timestamp} ${vflip}`;
      if (this._last?.key === key) return { ...this._last.frame, time: local };
      const image = await sample.image(vflip);
      /** @type {VideoFrameInput} */
      const frame = { kind: 'video', image, width: image.width, height: image.height, time: local };
      this._last = { key, frame };
      return frame;
    } finally {
      sample.close();
    }
  }

  close() {
    this._last = null;
  }
}
