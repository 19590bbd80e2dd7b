#!/usr/bin/env bash
# Installs the build into a scratch prefix, builds tests/consumer against it
# with find_package(Vernacular) and runs it on the bundled garage.
# Usage: run.sh BUILD_DIR SOURCE_DIR [CXX_FLAGS]  (the build's sanitizer flags, if any)
set -euo pipefail
build=$1
source=$2
flags=${3:-}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cmake --install "$build" --prefix "$scratch/prefix" > "$scratch/install.log"
test -f "$scratch/prefix/include/vernacular/vernacular.hpp"
test -x "$scratch/prefix/bin/infer"
# No installed header may include one of the library's private ones.
if grep -rn '#include "' "$scratch/prefix/include/vernacular" | grep -v '"vernacular/'; then
  echo "an installed header includes a private one" >&2
  exit 1
fi
cmake -S "$source/tests/consumer" -B "$scratch/build" -DCMAKE_PREFIX_PATH="$scratch/prefix" \
  -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS=$flags" "-DCMAKE_EXE_LINKER_FLAGS=$flags" > "$scratch/configure.log"
cmake --build "$scratch/build" > "$scratch/build.log"
mkdir -p "$scratch/out"
"$scratch/build/consumer" "$source/data/examples/garage" "$scratch/out"
test -s "$scratch/out/garage.grm"
test -s "$scratch/out/garage.prims.obj"
test -s "$scratch/out/variants.glb"
"$scratch/prefix/bin/infer" --version
