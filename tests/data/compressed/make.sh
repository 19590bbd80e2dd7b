#!/usr/bin/env bash
# Remakes this folder's GLB files: house.glb as generate writes it from
# house.grm, and the same file compressed as web pipelines compress
# glTF, by glTF-Transform (npm package @gltf-transform/cli, installed into
# .tools/ at the repository's top on first use): house_draco.glb
# (KHR_draco_mesh_compression) and house_meshopt.glb
# (EXT_meshopt_compression), positions quantized to 16 bits.
#   tests/data/compressed/make.sh [BUILD_DIR]   (default build/)
# The files are committed: the tests read them without npm.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
top="$here/../../.."
build="${1:-$top/build}"
tools="${VERN_TOOLS:-$top/.tools}"
if [ ! -x "$tools/node_modules/.bin/gltf-transform" ]; then
  mkdir -p "$tools"
  npm install --prefix "$tools" --no-audit --no-fund --loglevel=error @gltf-transform/cli@4.5.1 >&2
fi
"$build/bin/generate" "$here/house.grm" -n 1 -o "$here/house.glb" -q
"$tools/node_modules/.bin/gltf-transform" draco "$here/house.glb" "$here/house_draco.glb" --quantize-position 16
"$tools/node_modules/.bin/gltf-transform" meshopt "$here/house.glb" "$here/house_meshopt.glb" --quantize-position 16
