#!/usr/bin/env bash
# Runs the exported PyOpenGL programs under Mesa (llvmpipe, freeglut, GLU; the glref
# harness's Python with PyOpenGL) in a virtual X display, for tests/pyopengl_mesa.rs:
#   scripts/pyopengl_mesa.sh PROGRAMS_DIR OUT_DIR [SIZE]
# writes OUT_DIR/NAME.png (SIZE x SIZE, default 128) for each PROGRAMS_DIR/NAME.py and
# OUT_DIR/programs.txt (each program's CRC-32 and name). Needs GLREF (default
# ../shared/glref) set up by its setup.sh (or PYTHON: a Python with PyOpenGL and NumPy), and Xvfb.
set -euo pipefail
src=$1
out=$2
size=${3:-128}
glref=${GLREF:-$(cd "$(dirname "$0")/../.." && pwd)/shared/glref}
python=${PYTHON:-$glref/.venv/bin/python}
display=:$((90 + RANDOM % 9))
Xvfb "$display" -screen 0 1024x768x24 >/dev/null 2>&1 &
xvfb=$!
trap 'kill $xvfb' EXIT
sleep 1
mkdir -p "$out"
: > "$out/programs.txt.new"
for program in "$src"/*.py; do
  name=$(basename "$program" .py)
  DISPLAY=$display LIBGL_ALWAYS_SOFTWARE=1 "$python" "$program" --png "$out/$name.png" --size "$size"
  crc=$("$python" -c 'import sys, zlib; print("%08x" % (zlib.crc32(open(sys.argv[1], "rb").read()) & 0xffffffff))' "$program")
  echo "$crc $name.py" >> "$out/programs.txt.new"
done
sort -k2 "$out/programs.txt.new" > "$out/programs.txt"
rm "$out/programs.txt.new"
echo "$(ls "$out"/*.png | wc -l) pictures in $out"
