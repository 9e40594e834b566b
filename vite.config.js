// Vite serves the page from src/ (index.html lives there); the shader is imported from ../shaders
// with `?raw`, static files come from ../public, and the build goes to ../dist.
import { fileURLToPath } from 'node:url';
import { defineConfig } from 'vite';

const repo = fileURLToPath(new URL('.', import.meta.url));

export default defineConfig({
  root: `${repo}src`,
  publicDir: `${repo}public`,
  server: {
    host: '127.0.0.1',
    // the page imports ../shaders/*.glsl, outside the root: allow the whole repository
    fs: { allow: [repo] },
  },
  build: {
    outDir: `${repo}dist`,
    emptyOutDir: true,
    chunkSizeWarningLimit: 800, // three.js's WebGLRenderer is most of the bundle (~600 kB)
  },
});
