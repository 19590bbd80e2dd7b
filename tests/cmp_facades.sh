#!/usr/bin/env bash
# scripts/cmp_facades.py on facades written by hand in the CMP Facade
# Database's XML form (tests/data/cmp/): windows and doors become thin
# labelled boxes that infer takes and check derives; every rectangle,
# overlaps and all, becomes examples that infer takes with the set's stack
# order (sills painted over windows' lower edges, everything on the
# facade), and without it names an overlap and --stack. Each facade is one
# example, though a background rectangle stands apart from it (hand_b), and
# the set's <x> runs down the image (doors at the bottom).
# usage: cmp_facades.sh INFER CHECK SOURCE_DIR
set -euo pipefail
infer=$1 check=$2 src=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir "$work/wd" "$work/all"
python3 "$src/scripts/cmp_facades.py" "$src/tests/data/cmp" "$work/wd" --labels window,door
python3 "$src/scripts/cmp_facades.py" "$src/tests/data/cmp" "$work/all"
[ "$(ls "$work/wd" | wc -l)" -eq 3 ] || { echo "expected 3 examples"; exit 1; }
grep -q "^o window.001$" "$work/wd/hand_a.obj" || { echo "no window.001 in hand_a.obj"; exit 1; }
! grep -q "^o facade" "$work/wd/hand_a.obj" || { echo "facade kept though only windows and doors asked"; exit 1; }
# The set's <x> runs down the image: each hand facade's door (annotated at
# the bottom) stands on the ground, below every window.
for f in "$work"/wd/*.obj; do
  python3 - "$f" <<'PY' || { echo "door not at the bottom of $f"; exit 1; }
import sys
low = {}
name = None
for line in open(sys.argv[1]):
    if line.startswith("o "):
        name = line.split()[1]
    elif line.startswith("v ") and name:
        z = float(line.split()[3])
        low[name] = min(low.get(name, z), z)
doors = [z for n, z in low.items() if n.startswith("door")]
windows = [z for n, z in low.items() if n.startswith("window")]
sys.exit(0 if doors and min(doors) < 1e-9 and min(doors) < min(windows) else 1)
PY
done
"$infer" "$work"/wd/*.obj -o "$work/style.grm" -q
"$check" "$work/style.grm" "$work"/wd/*.obj > "$work/checked"
grep -q "^3 of 3 examples derivable" "$work/checked" || { cat "$work/checked"; exit 1; }
# As annotated, sills overlap the windows' lower edges: without an order
# infer refuses, names the pair and says how to give one.
if "$infer" "$work"/all/*.obj -o "$work/all.grm" -q 2> "$work/err"; then echo "overlapping annotations inferred"; exit 1; fi
grep -q "overlap" "$work/err" || { cat "$work/err"; exit 1; }
grep -q -- "--stack" "$work/err" || { cat "$work/err"; exit 1; }
# With the set's own order each part keeps what is visible of it.
stack=background,facade,sill,balcony,door,blind,molding,deco,shop,window,cornice,pillar
"$infer" "$work"/all/*.obj -o "$work/all.grm" -q --stack "$stack"
"$check" "$work/all.grm" "$work"/all/*.obj --stack "$stack" > "$work/checked_all"
grep -q "^3 of 3 examples derivable" "$work/checked_all" || { cat "$work/checked_all"; exit 1; }
grep -q "I(facade)" "$work/all.grm" || { echo "no facade left around the windows"; cat "$work/all.grm"; exit 1; }
echo "cmp_facades: ok"
