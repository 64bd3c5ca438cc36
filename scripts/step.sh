# Sourced by scripts/test, test-python and test-web: `step NAME COMMAND...` runs the command
# and prints one line to stderr with its wall seconds and its CPU seconds (user + system of
# every process it waited for), e.g. `scripts/test: clippy 142 s wall, 251 s CPU`, so each
# CI log says where the minutes go. CPU seconds stay comparable on a machine shared with
# other builds, where wall seconds do not.
step_cpu_ticks() {
  # Shell $1's reaped children's user + system time in clock ticks (Linux's /proc).
  awk '{ print $16 + $17 }' "/proc/$1/stat" 2>/dev/null || echo 0
}
step() {
  # $BASHPID, not $$: a step run in a background subshell counts that subshell's children.
  local name=$1 start=$SECONDS cpu0 cpu1 me=$BASHPID
  shift
  cpu0=$(step_cpu_ticks "$me")
  "$@"
  cpu1=$(step_cpu_ticks "$me")
  echo "${STEP_PREFIX:-$0}: $name $((SECONDS - start)) s wall, $(((cpu1 - cpu0) / $(getconf CLK_TCK))) s CPU" >&2
}

# `lint_while_building COMMAND...`: runs a cargo build with clippy as the compiler of the
# workspace's own crates (RUSTC_WORKSPACE_WRAPPER, as `cargo clippy` does itself; warnings are
# errors), so a cross build is linted as it is compiled, and the ~400 dependencies are compiled
# once for it instead of checked once for `cargo clippy` and compiled again for the build
# (docs/performance.md, "Build and CI time"). The dependencies are compiled by rustc alone.
lint_while_building() {
  local driver
  driver=$( (command -v rustup >/dev/null && rustup which clippy-driver 2>/dev/null) || command -v clippy-driver)
  RUSTC_WORKSPACE_WRAPPER="$driver" CLIPPY_ARGS="-D__CLIPPY_HACKERY__warnings__CLIPPY_HACKERY__" "$@"
}

# `lint_from_now_on`: the same for every cargo command the calling script runs after it, so
# that they all build phonglab's crates with the same compiler and reuse what the first
# built (cargo builds a crate again when its compiler changes: a `cargo run` or `cargo
# build` without the wrapper after a build with it compiled phonglab's crates anew).
lint_from_now_on() {
  RUSTC_WORKSPACE_WRAPPER=$( (command -v rustup >/dev/null && rustup which clippy-driver 2>/dev/null) || command -v clippy-driver)
  CLIPPY_ARGS="-D__CLIPPY_HACKERY__warnings__CLIPPY_HACKERY__"
  export RUSTC_WORKSPACE_WRAPPER CLIPPY_ARGS
}
