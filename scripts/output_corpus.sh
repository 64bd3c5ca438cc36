#!/usr/bin/env bash
# Writes everything phonglab outputs for the shipped scenes into one folder, so two builds
# can be compared byte for byte (a refactoring must leave every file the same):
#   scripts/output_corpus.sh BINARY OUT
#   diff -r OUT_BEFORE OUT_AFTER
# For each scene of assets/scenes (the 24 Red Book teapots included): explain (text and
# Markdown, front and back, en and pt-PT), the GLSL and WGSL shaders (Gouraud and Phong),
# the four exports, the glref case, a 128x128 render with each shading and object; and an
# exercise set (sheets, keys, PDFs) at each level, with the worksheet's set, in both
# languages; and eval of the public cases.
set -euo pipefail
BIN=${1:?usage: output_corpus.sh BINARY OUT}
OUT=${2:?usage: output_corpus.sh BINARY OUT}
cd "$(dirname "$0")/.."
rm -rf "$OUT"
mkdir -p "$OUT"
scenes=(assets/scenes/*.toml assets/scenes/redbook-teapots/*.toml)
for s in "${scenes[@]}"; do
  b=$(basename "$s" .toml)
  d="$OUT/$b"
  mkdir -p "$d"
  for lang in en pt-PT; do
    "$BIN" --lang "$lang" explain "$s" > "$d/explain-$lang.txt" 2>&1 || true
    "$BIN" --lang "$lang" explain --markdown --back "$s" > "$d/explain-back-$lang.md" 2>&1 || true
    for to in notebook pyopengl glsl; do
      "$BIN" --lang "$lang" export --scene "$s" --to "$to" > "$d/export-$to-$lang.txt" 2>&1 || true
    done
    "$BIN" --lang "$lang" export --scene "$s" --to openframeworks -o "$d/of-$lang" > /dev/null 2>&1 || true
  done
  for target in glsl wgsl; do
    for shading in gouraud phong; do
      "$BIN" shader --scene "$s" --target "$target" --shading "$shading" > "$d/shader-$shading.$target" 2>&1 || true
    done
  done
  "$BIN" case "$s" > "$d/case.json" 2>&1 || true
done
# Pictures: the first scenes with every object and shading (a render is the slow part).
for s in assets/scenes/worksheet-mview5.toml assets/scenes/phong-demo.toml assets/scenes/spotlight.toml \
  assets/scenes/three-lights.toml assets/scenes/redbook-teapots/08-bronze.toml; do
  b=$(basename "$s" .toml)
  for o in sphere teapot cylinder; do
    for sh in gouraud phong flat; do
      "$BIN" render --scene "$s" --object "$o" --shading "$sh" --size 128 -o "$OUT/$b/render-$o-$sh.png" \
        > /dev/null 2>&1 || true
    done
  done
done
for lang in en pt-PT; do
  for level in 1 2 3 4; do
    "$BIN" --lang "$lang" exercise --seed 3 --count 2 --level "$level" --out "$OUT/exercise-$lang-$level" \
      > /dev/null 2>&1 || true
  done
  "$BIN" --lang "$lang" exercise --seed 7 --count 1 --level 3 --worksheet --out "$OUT/exercise-$lang-worksheet" \
    > /dev/null 2>&1 || true
done
"$BIN" eval tests/data/cases_public.json > "$OUT/eval.json" 2>&1 || true
"$BIN" eval --precision f64 --clamp tests/data/cases_public.json > "$OUT/eval-f64.json" 2>&1 || true
echo "$(find "$OUT" -type f | wc -l) files in $OUT"
