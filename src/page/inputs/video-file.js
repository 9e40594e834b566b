// A video input from a file, decoded frame by frame at the frame's iTime: the frame shown at
// iTime is the last one whose timestamp is at or before it (mediabunny's VideoSampleSink.getSample
// over WebCodecs), never whatever a <video> element had ready, so a recording or the command line
// gets the same picture on every run.
//
// On the site a video input is a <video loop> element started when it can play; each frame its
// current picture is uploaded with UNPACK_FLIP_Y = the sampler's vflip, mipmaps made again when the
// filter is "mipmap"; iChannelTime is its currentTime and iChannelResolution (videoWidth,
// videoHeight, 1) (effect.js: NewTexture "video", Paint_Image; piLibs.js UpdateTextureFromImage).
// Here the video's clock is iTime, looped: iChannelTime = iTime mod its duration.

/** @typedef {{kind: 'video', image: ImageBitmap, width: number, height: number, time: number}} VideoFrameInput */

export class VideoFile {
  /**
   * @param {any} sink mediabunny's VideoSampleSink on the file's video track
   * @param {number} start the first frame's timestamp
   * @param {number} duration seconds
   */
  constructor(sink, start, duration) {
    this.sink = sink;
    this.start = start;
    this.duration = duration;
    /** The last frame made, by its timestamp and flip, to give again while it is the one shown. @type {{key: string, frame: VideoFrameInput} | null} */
    this._last = null;
  }

  /**
   * Opens a video file (WebM or MP4 the browser's WebCodecs decodes).
   * @param {Blob} blob
   * @param {string} name for the error
   */
  static async open(blob, name) {
    const { ALL_FORMATS, BlobSource, Input, VideoSampleSink } = await import('mediabunny');
    const fail = (/** @type {string} */ why, /** @type {unknown} */ cause) =>
      new Error(`cannot play ${name} as a video: ${why}; use a WebM (VP8, VP9, AV1) or MP4 (H.264) file`, { cause });
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
    return new VideoFile(new VideoSampleSink(track), start, duration);
  }

  /**
   * The picture at iTime `time` (looped), its rows flipped when `vflip` (as the site uploads it).
   * @param {number} time
   * @param {boolean} vflip
   * @returns {Promise<VideoFrameInput>}
   */
  async frameAt(time, vflip) {
    const local = this.duration > 0 ? time % this.duration : 0;
    const sample = (await this.sink.getSample(this.start + local)) ?? (await this.sink.getSample(this.start));
    if (!sample) throw new Error('the video has no frame');
    try {
      const key = `${sample.timestamp} ${vflip}`;
      if (this._last?.key === key) return { ...this._last.frame, time: local };
      const videoFrame = sample.toVideoFrame();
      const image = await createImageBitmap(videoFrame, {
        imageOrientation: vflip ? 'flipY' : 'from-image',
        colorSpaceConversion: 'none',
        premultiplyAlpha: 'none',
      });
      videoFrame.close();
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
