# Sourced by scripts/test, test-python and test-web: `step NAME COMMAND...` runs the command
# and prints one line to stderr with its wall seconds and its CPU seconds (user + system of
# every process it waited for), e.g. `scripts/test: clippy 142 s wall, 251 s CPU`, so each
# CI log says where the minutes go. CPU seconds stay comparable on a machine shared with
# other builds, where wall seconds do not.
step_cpu_ticks() {
  # The shell's reaped children's user + system time in clock ticks (Linux's /proc).
  awk '{ print $16 + $17 }' "/proc/$$/stat" 2>/dev/null || echo 0
}
step() {
  local name=$1 start=$SECONDS cpu0 cpu1
  shift
  cpu0=$(step_cpu_ticks)
  "$@"
  cpu1=$(step_cpu_ticks)
  echo "${STEP_PREFIX:-$0}: $name $((SECONDS - start)) s wall, $(((cpu1 - cpu0) / $(getconf CLK_TCK))) s CPU" >&2
}
