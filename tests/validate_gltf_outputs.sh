#!/usr/bin/env bash
# CTest: what `generate` writes as glTF opens in the Khronos validator with
# no errors, for every bundled grammar and for tests/data/every_operation.grm
# (comp faces of zero thickness, colours, general rotations), as .glb and
# .gltf, plain and with --instancing, over several seeds.
#   validate_gltf_outputs.sh GENERATE_BINARY SOURCE_DIR
set -euo pipefail
generate=$1
src=$2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
files=()
for grammar in "$src"/data/grammars/*.grm "$src"/tests/data/every_operation.grm; do
  name=$(basename "$grammar" .grm)
  for seed in 1 2 3; do
    "$generate" "$grammar" -n 2 --seed "$seed" -q -o "$out/${name}_$seed.glb"
    files+=("$out/${name}_$seed.glb")
  done
  "$generate" "$grammar" -n 2 --seed 4 -q -o "$out/$name.gltf"
  "$generate" "$grammar" -n 3 --seed 5 -q --instancing -o "$out/${name}_instanced.glb"
  "$generate" "$grammar" -n 2 --seed 6 -q --instancing -o "$out/${name}_instanced.gltf"
  files+=("$out/$name.gltf" "$out/${name}_instanced.glb" "$out/${name}_instanced.gltf")
done
bash "$src/scripts/validate-gltf" "${files[@]}"
