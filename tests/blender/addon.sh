#!/usr/bin/env bash
# CTest (blender_addon): the add-on's zip installed into Blender and driven
# headless (addon_test.py). Skipped (exit 77) where Blender is not
# installed; scripts/blender-roundtrip installs it.
#   addon.sh ZIP MODULE_DIR SOURCE_DIR
set -euo pipefail
zip=$1 module=$2 src=$3
source "$src/tests/blender/need_blender.sh"
home=$(mktemp -d)
trap 'rm -rf "$home"' EXIT
# A scratch user folder: the add-on is installed there, not into the user's Blender.
HOME=$home BLENDER_USER_CONFIG=$home/config BLENDER_USER_SCRIPTS=$home/scripts \
  "$blender" -b --factory-startup --python-exit-code 1 --python "$src/tests/blender/addon_test.py" -- "$zip" "$module" \
  > "$home/blender.log" 2>&1 || { cat "$home/blender.log"; exit 1; }
grep "^blender addon" "$home/blender.log"
