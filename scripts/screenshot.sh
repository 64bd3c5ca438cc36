#!/usr/bin/env bash
# Takes docs/screenshot.png: the real window under Xvfb (software GL), on a fresh profile so
# a saved session does not change the picture. Needs xvfb and imagemagick (Debian).
#   scripts/screenshot.sh [OUT.png] [WIDTHxHEIGHT]
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-docs/screenshot.png}"
size="${2:-1440x900}"
scripts/deps.sh xvfb imagemagick libegl1 libgl1-mesa-dri libxkbcommon-x11-0
cargo build --release --locked -q
profile="$(mktemp -d)"
Xvfb :97 -screen 0 "${size}x24" -nolisten tcp &
xvfb=$!
trap 'kill $app $xvfb 2>/dev/null || true; rm -rf "$profile"' EXIT
sleep 1
DISPLAY=:97 XDG_DATA_HOME="$profile" WAYLAND_DISPLAY= target/release/phonglab &
app=$!
sleep "${SCREENSHOT_WAIT:-6}"
DISPLAY=:97 import -window root "$out"
echo "wrote $out" >&2
