// The face and texel coordinates a samplerCube lookup reads along a direction, computed in
// float64 from the OpenGL ES 3.0 specification's table "Selection of cube map images" (§3.8.10,
// Table 3.21: the major axis, then sc, tc): what the cube map tests hold the GPU's reads to.

/**
 * @param {number[]} direction
 * @returns {{face: number, s: number, t: number}} face 0..5 as +X, −X, +Y, −Y, +Z, −Z; (s, t) in
 *   [0, 1], t = 0 the face's first row uploaded
 */
export function cubeLookup([x, y, z]) {
  const ax = Math.abs(x);
  const ay = Math.abs(y);
  const az = Math.abs(z);
  let face, sc, tc, ma;
  if (ax >= ay && ax >= az) [face, sc, tc, ma] = x > 0 ? [0, -z, -y, ax] : [1, z, -y, ax];
  else if (ay >= az) [face, sc, tc, ma] = y > 0 ? [2, x, z, ay] : [3, x, -z, ay];
  else [face, sc, tc, ma] = z > 0 ? [4, x, -y, az] : [5, -x, -y, az];
  return { face, s: (sc / ma + 1) / 2, t: (tc / ma + 1) / 2 };
}
