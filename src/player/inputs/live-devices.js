// The webcam and the microphone, in the page only (getUserMedia: the command line's headless
// browser has neither, and says so). As on the site (effect.js, NewTexture "webcam" and "mic"):
// the webcam is a <video> of the camera's stream uploaded each frame (its resolution the video's,
// flipped as its sampler says, iChannelTime 0); the microphone goes into an AnalyserNode with
// every default, read each frame into 512 bytes of spectrum (row 0) and 512 of waveform (row 1) of
// the 512 × 2 texture, iChannelTime 0.

export class Webcam {
  /** @param {HTMLVideoElement} video @param {MediaStream} stream */
  constructor(video, stream) {
    this.video = video;
    this.stream = stream;
    /** The pictures of the last two frames: the frame before may still be drawn again (a capture). @type {ImageBitmap[]} */
    this._recent = [];
  }

  static async open() {
    const stream = await openStream({ video: { width: { ideal: 1280 }, height: { ideal: 720 } }, audio: false }, 'webcam');
    const video = document.createElement('video');
    video.muted = true;
    video.playsInline = true;
    video.srcObject = stream;
    await video.play();
    return new Webcam(video, stream);
  }

  /** The camera's picture now. @param {boolean} vflip */
  async frameAt(vflip) {
    const image = await createImageBitmap(this.video, { imageOrientation: vflip ? 'flipY' : 'from-image', premultiplyAlpha: 'none' });
    this._recent.push(image);
    if (this._recent.length > 2) this._recent.shift()?.close(); // a camera picture a frame, not kept for ever
    return { kind: /** @type {const} */ ('video'), image, width: image.width, height: image.height, time: 0 };
  }

  close() {
    for (const track of this.stream.getTracks()) track.stop();
    this.video.srcObject = null;
  }
}

export class Microphone {
  /** @param {AudioContext} context @param {AnalyserNode} analyser @param {MediaStream} stream */
  constructor(context, analyser, stream) {
    this.context = context;
    this.analyser = analyser;
    this.stream = stream;
  }

  static async open() {
    const stream = await openStream({ audio: true, video: false }, 'microphone');
    const context = new AudioContext();
    const analyser = context.createAnalyser(); // the site's: every default
    context.createMediaStreamSource(stream).connect(analyser);
    context.resume().catch(() => {});
    return new Microphone(context, analyser, stream);
  }

  /** The texture now: the analyser read as the site reads it. */
  frameAt() {
    const bytes = new Uint8Array(1024);
    this.analyser.getByteFrequencyData(bytes.subarray(0, 512));
    this.analyser.getByteTimeDomainData(bytes.subarray(512));
    return { kind: /** @type {const} */ ('audio'), bytes, width: 512, height: 2, time: 0 };
  }

  close() {
    for (const track of this.stream.getTracks()) track.stop();
    this.context.close().catch(() => {});
  }
}

/** @param {MediaStreamConstraints} constraints @param {string} what */
async function openStream(constraints, what) {
  if (!navigator.mediaDevices?.getUserMedia) throw new Error(`this browser gives no ${what} here (it needs https or localhost)`);
  try {
    return await navigator.mediaDevices.getUserMedia(constraints);
  } catch (error) {
    throw new Error(
      `no ${what}: ${error?.name === 'NotAllowedError' ? 'allow it in the browser and try again' : 'plug one in and try again'}`,
      {
        cause: error,
      },
    );
  }
}
