#!/usr/bin/env bash
# Fuzzes the scene-file parser and evaluator and the glref case reader for a bounded time
# (not in CI). Needs a nightly toolchain (rustup toolchain install nightly) and cargo-fuzz
# (cargo install cargo-fuzz). Findings land in fuzz/artifacts/TARGET/.
#
#   scripts/fuzz.sh [SECONDS_PER_TARGET] [TARGET...]     default: 300 s, both targets
set -euo pipefail
cd "$(dirname "$0")/.."
secs="${1:-300}"
shift || true
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(scene_file glref_cases)

# Seed corpora: the shipped scene files, and the public Mesa cases one per file.
mkdir -p fuzz/corpus/scene_file fuzz/corpus/glref_cases
cp assets/scenes/*.toml assets/scenes/*/*.toml fuzz/corpus/scene_file/
python3 - <<'PY'
import json, os
cases = json.load(open("tests/data/cases_public.json"))
cases = cases["cases"] if isinstance(cases, dict) else cases
for c in cases:
    c.pop("result", None)
    with open(os.path.join("fuzz/corpus/glref_cases", c["id"] + ".json"), "w") as f:
        json.dump([c], f)
PY

for t in "${targets[@]}"; do
  echo "== $t: ${secs}s" >&2
  cargo +nightly fuzz run "$t" --fuzz-dir fuzz -- -max_total_time="$secs" -max_len=8192 -timeout=10 \
    -dict=fuzz/toml.dict 2>&1 | tail -n 25
done
