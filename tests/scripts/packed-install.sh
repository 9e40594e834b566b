#!/usr/bin/env bash
# The install recipe of docs/ci.md and docs/api.md, proved on the packed tarball (.ci/run runs it
# after npm test): npm pack (prepack builds the page and the API's types), the tarball installed
# into an empty folder (its dependencies from npm's cache, which npm ci filled), then there:
# npx shaderproof --version, docs/api.md's first example with node, a TypeScript file that uses
# the API's types, and a small folder through npx shaderproof test (--update, then a run).
# Each must exit 0. KEEP=1 keeps the folder and says where it is.
set -euo pipefail
repo="$(cd "$(dirname "$0")/../.." && pwd)"
work="$(mktemp -d "${TMPDIR:-/tmp}/shaderproof-packed-XXXXXX")"
if [ -z "${KEEP:-}" ]; then trap 'rm -rf "$work"' EXIT; else echo "packed-install: in $work"; fi
step() { echo "packed-install: $*"; }

step "npm pack"
tarball="$(cd "$repo" && npm pack --silent --pack-destination "$work" | tail -n 1)"
version="$(node -p "require('$repo/package.json').version")"

app="$work/app"
mkdir "$app"
cd "$app"
step "npm install $tarball, in an empty folder"
npm init -y >/dev/null
npm install --prefer-offline --no-audit --no-fund "$work/$tarball" >/dev/null

step "npx shaderproof --version"
said="$(npx --no-install shaderproof --version)"
[ "$said" = "$version" ] || { echo "packed-install: --version said '$said', package.json has $version" >&2; exit 1; }

step "docs/api.md's first example (docs/examples/api-first.mjs), twice: the reference, then the check"
cp "$repo/docs/examples/api-first.mjs" .
node api-first.mjs
node api-first.mjs

step "a TypeScript file resolves the API's types"
cat >consumer.mts <<'TS'
import { compare, openSession, render, ShaderproofError, type Rendered } from 'shaderproof';
const still: Rendered = await render({ source: 'void mainImage(out vec4 c, in vec2 p) { c = vec4(1.0); }' }, { size: '8x8' });
const width: number = still.width;
const same: boolean = compare(still.png(), still).ok;
const session = await openSession({ renderer: 'swiftshader' });
await session.close();
export { width, same, ShaderproofError };
TS
node "$repo/node_modules/typescript/bin/tsc" --noEmit --strict --module nodenext --moduleResolution nodenext --target es2022 \
  --types node --typeRoots "$repo/node_modules/@types" --skipLibCheck consumer.mts

step "npx shaderproof test on a small folder: --update, then a run against its references"
mkdir shaders
cat >shaders/rings.glsl <<'GLSL'
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 p = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    fragColor = vec4(0.5 + 0.5 * cos(12.0 * length(p) + vec3(0.0, 2.0, 4.0)), 1.0);
}
GLSL
npx --no-install shaderproof test shaders --update --reporter dot
npx --no-install shaderproof test shaders --reporter dot,junit
step "done"
