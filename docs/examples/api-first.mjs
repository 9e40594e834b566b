// A first test with shaderproof's Node API: run it with `node api-first.mjs` in a folder where
// `npm install shaderproof` was run. The first run writes the reference (so does UPDATE=1).
import fs from 'node:fs';
import assert from 'node:assert/strict';
import { compare, render } from 'shaderproof';

const shader = {
  name: 'gradient.glsl',
  source: `void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(fragCoord.x / iResolution.x, 0.5, 0.0, 1.0);
}`,
};

const image = await render(shader, { size: '64x32' });

// the top-left pixel: red close to 0, green one half, opaque
const [r, g, b, a] = image.data.subarray(0, 4);
assert.ok(r < 8 && Math.abs(g - 128) <= 1 && b === 0 && a === 255, `top-left pixel is ${[r, g, b, a]}`);

const reference = 'gradient.png';
if (process.env.UPDATE || !fs.existsSync(reference)) {
  fs.writeFileSync(reference, image.png());
  console.log(`wrote ${reference}`);
}
const result = compare(image, reference, { threshold: 0, maxDiffPixels: 0 });
assert.ok(result.ok, result.failure ?? '');
console.log(`${reference}: the same pixels, drawn by ${image.renderer}`);
