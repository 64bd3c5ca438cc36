#!/usr/bin/env bash
# Compares the "Phong demo" preset with the demo's own shaders under Mesa at many frames of
# the spin. Needs the glref harness set up (its setup.sh: Mesa, Xvfb, a venv with numpy)
# (docs/lighting.md) in the folder GLREF names.
# Usage: scripts/seed_demo_sweep.sh [FRAME...]   (default: 1 37 90 120 180 250 333 360 444 500 575 640 719)
set -euo pipefail
cd "$(dirname "$0")/.."
GLREF=${GLREF:?set GLREF to the glref harness folder (docs/lighting.md)}
PY="$GLREF/.venv/bin/python"
OUT=${OUT:-/tmp/phonglab-seed-sweep}
mkdir -p "$OUT"
cargo build --release --locked -q
frames=("$@")
[ ${#frames[@]} -eq 0 ] && frames=(1 37 90 120 180 250 333 360 444 500 575 640 719)
for f in "${frames[@]}"; do
  "$PY" "$GLREF/seed_demo.py" "$OUT" "$f" > /dev/null
  for o in sphere teapot cylinder; do
    for s in gouraud phong flat; do
      target/release/phonglab render --preset phong-demo --object "$o" --shading "$s" --frame "$f" \
        -o "$OUT/ours_${f}_${o}_${s}.png" 2> /dev/null
      echo "frame $f $o $s $("$PY" scripts/compare_png.py "$OUT/ours_${f}_${o}_${s}.png" "$OUT/seed_${f}_${o}_${s}.png")"
    done
  done
done
