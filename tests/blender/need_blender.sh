# Sourced by the Blender tests: sets $blender, or skips the test (exit 77,
# CTest's SKIP_RETURN_CODE) with a message where Blender is not installed.
blender=${BLENDER:-blender}
if ! command -v "$blender" > /dev/null; then
  echo "SKIPPED: Blender is not installed; scripts/blender-roundtrip installs it (apt) and runs this test"
  exit 77
fi
