// Shadertoy's Cube A pass (`void mainCubemap(out vec4 fragColor, in vec2 fragCoord, in vec3
// rayOri, in vec3 rayDir)`), the facts a renderer needs, pure: no WebGL here.
//
// Read in the site's own player, effect.js and piLibs.js, as copied whole in
// github.com/DustinBrett/daedalOS (public/System/ShaderToy/CoastalLandscape/), and checked
// against a CoffeeScript port of the same player in a public code index (Pass.paint_Cubemap:
// the same corners, size and order):
// - EffectPass.Paint (type "cubemap"): Effect.ResizeCubemapBuffer(0, 1024, 1024), so every face
//   is 1024 × 1024 whatever the canvas, and the pass's iResolution is (1024, 1024, 1); two cube
//   textures used in turn, as the buffers are (mLastRenderDone), so a reader sees the one painted
//   last: the pass itself its previous frame;
// - Effect.ResizeCubemapBuffer: TEXTYPE.CUBEMAP, TEXFMT.C4F16 (piRenderer: RGBA16F), FILTER.LINEAR,
//   TEXWRP.CLAMP; a reader's filter is set on the texture (EffectPass.Paint_Image, "cubemap"
//   with a buffer id), and "mipmap" makes Effect.Paint regenerate its mipmaps after it paints;
// - the six faces in the order 0…5, each drawn into TEXTURE_CUBE_MAP_POSITIVE_X + face
//   (piRenderer.SetRenderTargetCubeMap) with the viewport [0, 0, 1024, 1024] and the uniforms
//   unCorners (the face's four corners A, B, C, D and the apex, EffectPass.Paint_Cubemap) and
//   unViewport; MakeHeader_Cubemap's main: ro = unCorners[4], uv = (gl_FragCoord.xy −
//   unViewport.xy) / unViewport.zw, rd = normalize(mix(mix(A, B, uv.x), mix(D, C, uv.x), uv.y) − ro),
//   fragCoord = gl_FragCoord.xy − unViewport.xy, and the colour stored as it is (no alpha forced);
// - Effect.Paint: buffers first, then the Cube A pass, then Image; on frame 0 (also after
//   Restart) both cube textures are cleared to vec4(0) on every face;
// - a channel reading the pass: type "cubemap", id "4dX3Rr" (assetID_to_cubemapBuferID), its
//   preview file "/media/previz/cubemap00.png"; iChannelResolution (1024, 1024, 1).
// The corners put the texel at (s, t) of face f on the direction a samplerCube lookup takes to
// that texel (the OpenGL ES 3.0 specification's table "Cube Map Texture Selection"), so texture(iChannel, d) reads
// back what mainCubemap wrote for d (tests/browser/cube-a.test.js computes it).

/** The side of every face, in texels (EffectPass.Paint: ResizeCubemapBuffer(…, 1024, 1024)). */
export const CUBE_A_SIZE = 1024;

/** The pass's name, as the site names it (Effect.Load: "Cube A"). */
export const CUBE_A_NAME = 'Cube A';

/** The site's asset id of the Cube A output, and of an input reading it. */
export const CUBE_A_ID = '4dX3Rr';

/** The numeric id older exports write for it (their buffers are 257–260, the Image output 37). */
export const CUBE_A_LEGACY_ID = 41;

/** The file an input reading Cube A names (the site's preview picture of it). */
export const CUBE_A_FILE = '/media/previz/cubemap00.png';

/**
 * Each face's corners A, B, C, D (uv (0,0), (1,0), (1,1), (0,1)), in the face order +X, −X, +Y,
 * −Y, +Z, −Z (EffectPass.Paint_Cubemap's corA…corD).
 * @type {ReadonlyArray<ReadonlyArray<readonly [number, number, number]>>}
 */
// prettier-ignore
const FACE_CORNERS = Object.freeze([
  [[1, 1, 1], [1, 1, -1], [1, -1, -1], [1, -1, 1]],
  [[-1, 1, -1], [-1, 1, 1], [-1, -1, 1], [-1, -1, -1]],
  [[-1, 1, -1], [1, 1, -1], [1, 1, 1], [-1, 1, 1]],
  [[-1, -1, 1], [1, -1, 1], [1, -1, -1], [-1, -1, -1]],
  [[-1, 1, 1], [1, 1, 1], [1, -1, 1], [-1, -1, 1]],
  [[1, 1, -1], [-1, 1, -1], [-1, -1, -1], [1, -1, -1]],
]);

/**
 * The unCorners uniform of face `face` (0…5): its four corners, then the apex (the origin), as
 * 15 floats.
 * @param {number} face
 * @returns {number[]}
 */
export function faceCorners(face) {
  const corners = FACE_CORNERS[face];
  if (!corners) throw new Error(`a cube has faces 0 to 5, not ${face}`);
  return [...corners.flat(), 0, 0, 0];
}

/**
 * The direction mainCubemap gets at fragCoord (x, y) of face `face` (what the header's main
 * computes), before normalizing.
 * @param {number} face
 * @param {number} x
 * @param {number} y
 * @returns {[number, number, number]}
 */
export function faceDirection(face, x, y) {
  const [a, b, c, d] = FACE_CORNERS[face];
  const u = x / CUBE_A_SIZE;
  const v = y / CUBE_A_SIZE;
  const mix = (p, q, t) => p.map((value, i) => value + (q[i] - value) * t);
  return /** @type {[number, number, number]} */ (mix(mix(a, b, u), mix(d, c, u), v));
}

/** The uniforms the Cube A pass's main reads beside Shadertoy's (MakeHeader_Cubemap). */
export const CUBE_A_UNIFORMS = Object.freeze({ viewport: 'unViewport', corners: 'unCorners' });
