#!/usr/bin/env bash
# CTest (blender_roundtrip): Vernacular's files in Blender and Blender's in
# Vernacular, with Blender's default import and export settings.
#  - Buildings `generate` writes (GLB, one and four side by side; OBJ)
#    import standing: their height along Blender's z, names kept.
#  - Houses modelled in Blender and exported as OBJ and GLB give `infer`
#    their height on z and exact numbers (2.7 to 1.2 is 9 to 4, not 2.7000000476837 to 1.2000000476837),
#    the same grammar from either format, and `check` derives them.
#  - A scene of three houses, windows set into their walls, one turned 30
#    degrees, exported whole: an example per house, the turned one in its
#    own frame, one grammar from the OBJ and the GLB, `check` derives all.
# Blender is large: where it is not installed the test is skipped (exit 77);
# scripts/blender-roundtrip installs it and runs this test.
#   roundtrip.sh GENERATE INFER CHECK SOURCE_DIR
set -euo pipefail
generate=$1 infer=$2 check=$3 src=$4
source "$src/tests/blender/need_blender.sh"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
run_blender() {
  "$blender" -b --factory-startup --python-exit-code 1 --python "$src/tests/blender/roundtrip.py" -- "$@" \
    > "$out/blender.log" 2>&1 || { cat "$out/blender.log"; exit 1; }
  grep -E "^blender roundtrip|mesh objects|exported" "$out/blender.log"
}

# The house of the README: a 12 x 8 plot, 9 high at the roof's ridge.
cat > "$out/house.grm" <<'GRAMMAR'
@scope 12, 8, 9
plot --> split(x){ ~2 : house | ~1 : garage } : 0.7
plot --> split(x){ ~1 : garage | ~2 : house } : 0.3
house --> split(z){ ~2 : walls | ~1 : I(roof) }
walls --> repeat(x, 2.5){ split(z){ ~1 : I(rect) | 1.2 : I(window) | ~1 : I(rect) } }
garage --> split(z){ ~rand(0.8, 1.2) : I(rect) | ~2 : nil }
GRAMMAR
"$generate" "$out/house.grm" -q -o "$out/house.glb"
"$generate" "$out/house.grm" -q -o "$out/house.obj"
"$generate" "$out/house.grm" -q -n 4 --spacing 2 -o "$out/street.glb"
run_blender import "$out/house.glb" 12 8 9 rect,roof,window
run_blender import "$out/house.obj" 12 8 9 rect,roof,window
# Four plots on a 2 x 2 grid, 2 m apart: side by side, not stacked.
run_blender import "$out/street.glb" 26 18 9 rect,roof,window

mkdir "$out/blender"
run_blender build "$out/blender"
grammar_body() { grep -v -e '^#' -e '^@primitives' "$1"; }
for format in obj glb; do
  "$infer" -q "$out"/blender/house_6.$format "$out"/blender/house_8.$format -o "$out/$format.grm"
  cat "$out/$format.grm"
  # Widths 6 and 8 (a distribution), 4 deep, 3.9 high; walls 2.7 and
  # roofs 1.2 high: exactly 9 to 4, which float noise would not give.
  grep -q '^@scope .*, 4, 3.9$' "$out/$format.grm" || { echo "FAIL: $format: the height is not on z"; exit 1; }
  grep -q 'split(z){ ~9 : I(wall) | ~4 : I(roof) }' "$out/$format.grm" ||
    { echo "FAIL: $format: the heights are not exactly 2.7 and 1.2"; exit 1; }
  "$check" "$out/$format.grm" "$out"/blender/house_6.$format "$out"/blender/house_8.$format
done
diff <(grammar_body "$out/obj.grm") <(grammar_body "$out/glb.grm") ||
  { echo "FAIL: Blender's OBJ and GLB of the same houses give different grammars"; exit 1; }

# A scene of three houses standing apart, windows set into their walls,
# one turned 30 degrees: each house is an example, the turned one read in
# its own frame, from the OBJ and the GLB alike.
mkdir "$out/scene"
run_blender scene "$out/scene"
for format in obj glb; do
  "$infer" "$out/scene/street.$format" -o "$out/scene_$format.grm" 2> "$out/infer.log" || { cat "$out/infer.log"; exit 1; }
  cat "$out/infer.log"
  grep -q "holds 3 buildings standing apart" "$out/infer.log" || { echo "FAIL: $format: not read as 3 houses"; exit 1; }
  grep -q "stands turned 30 degrees" "$out/infer.log" || { echo "FAIL: $format: the turned house not found"; exit 1; }
  "$check" "$out/scene_$format.grm" "$out/scene/street.$format" | tail -1 | grep -q "3 of 3 examples derivable" ||
    { echo "FAIL: $format: check does not derive the 3 houses"; exit 1; }
done
diff <(grammar_body "$out/scene_obj.grm") <(grammar_body "$out/scene_glb.grm") ||
  { echo "FAIL: Blender's OBJ and GLB of one scene give different grammars"; exit 1; }
echo "blender roundtrip: all passed"
