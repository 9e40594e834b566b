// The geometry every pass draws, and the scene that copies a texture texel for texel: the frame
// target to the canvas (renderer.js present), a buffer into its resized self (pass-buffers.js).

import * as THREE from 'three';
import { VERTEX_SHADER } from './pass-compiler.js';

/** Copies a texture pixel for pixel (texelFetch: no filtering, no flip). */
const COPY_SHADER = `
precision highp float;
uniform highp sampler2D frame;
out vec4 color;
void main() {
    color = texelFetch(frame, ivec2(gl_FragCoord.xy), 0);
}
`;

/** One triangle whose middle covers clip space [-1, 1]². */
export function fullscreenTriangle() {
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.Float32BufferAttribute([-1, -1, 0, 3, -1, 0, -1, 3, 0], 3));
  return geometry;
}

/**
 * A scene that draws `texture` texel for texel, and the uniform that names what it copies.
 * @param {THREE.BufferGeometry} geometry
 * @param {THREE.Texture} texture
 */
export function copyScene(geometry, texture) {
  const scene = new THREE.Scene();
  const material = new THREE.RawShaderMaterial({
    glslVersion: THREE.GLSL3,
    vertexShader: VERTEX_SHADER,
    fragmentShader: COPY_SHADER,
    uniforms: { frame: { value: texture } },
    depthTest: false,
    depthWrite: false,
  });
  const copy = new THREE.Mesh(geometry, material);
  copy.frustumCulled = false;
  scene.add(copy);
  return { scene, source: material.uniforms.frame };
}
