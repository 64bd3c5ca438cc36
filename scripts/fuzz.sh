#!/usr/bin/env bash
# Fuzzes the scene-file parser and evaluator, the glref case reader and the OBJ reader for a bounded time
# (not in CI). Needs a nightly toolchain (rustup toolchain install nightly) and cargo-fuzz
# (cargo install cargo-fuzz). Findings land in fuzz/artifacts/TARGET/.
#
#   scripts/fuzz.sh [SECONDS_PER_TARGET] [TARGET...]     default: 300 s, every target
set -euo pipefail
cd "$(dirname "$0")/.."
secs="${1:-300}"
shift || true
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(scene_file glref_cases obj_file)

# Seed corpora: the shipped scene files, and the public Mesa cases one per file.
mkdir -p fuzz/corpus/scene_file fuzz/corpus/glref_cases fuzz/corpus/obj_file
cp assets/scenes/*.toml assets/scenes/*/*.toml fuzz/corpus/scene_file/
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 0.5 1\nvt 0 0\nvn 0 0 1\nf 1/1/1 2/1/1 3/1/1 4/1/1\nf 1 2 5\n' > fuzz/corpus/obj_file/pyramid.obj
python3 - <<'PY'
import json, os
cases = json.load(open("tests/data/cases_public.json"))
cases = cases["cases"] if isinstance(cases, dict) else cases
for c in cases:
    c.pop("result", None)
    with open(os.path.join("fuzz/corpus/glref_cases", c["id"] + ".json"), "w") as f:
        json.dump([c], f)
PY

mkdir -p fuzz/logs
status=0
for t in "${targets[@]}"; do
  echo "== $t: ${secs}s (log: fuzz/logs/$t.log)" >&2
  if cargo +nightly fuzz run "$t" --fuzz-dir fuzz -- -max_total_time="$secs" -max_len=8192 -timeout=10 \
      -dict=fuzz/toml.dict > "fuzz/logs/$t.log" 2>&1; then
    grep -E "^Done [0-9]+ runs" "fuzz/logs/$t.log" >&2 || true
  else
    status=1
    echo "$t FOUND A FAILURE:" >&2
    grep -E "panicked at|^thread|SUMMARY|crash-" "fuzz/logs/$t.log" | head -n 8 >&2
  fi
done
exit $status
