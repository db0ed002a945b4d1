#!/usr/bin/env bash
# Runs a command with its own X server: Xvfb picks a free display number
# itself (-displayfd), so parallel runs and a developer's X never collide.
# CI has no DISPLAY and no terminal; everything started here is stopped here.
#   tests/run_with_xvfb.sh COMMAND [ARGS...]
set -euo pipefail

runtime_dir=$(mktemp -d)
chmod 700 "$runtime_dir"
display_file="$runtime_dir/display"
xvfb_pid=""
cleanup() {
  if [[ -n "$xvfb_pid" ]]; then
    kill "$xvfb_pid" 2>/dev/null || true
    wait "$xvfb_pid" 2>/dev/null || true
  fi
  rm -rf "$runtime_dir"
}
trap cleanup EXIT

Xvfb -displayfd 3 -screen 0 1280x720x24 -nolisten tcp 3>"$display_file" \
  >"$runtime_dir/xvfb.log" 2>&1 &
xvfb_pid=$!
# Should this script be killed outright (a ctest timeout), the trap does not
# run: a watcher stops Xvfb once this shell is gone.
wrapper_pid=$$
( while kill -0 "$wrapper_pid" 2>/dev/null; do sleep 1; done; kill "$xvfb_pid" 2>/dev/null ) \
  </dev/null >/dev/null 2>&1 &
for _ in $(seq 100); do
  [[ -s "$display_file" ]] && break
  if ! kill -0 "$xvfb_pid" 2>/dev/null; then
    echo "run_with_xvfb: Xvfb failed to start:" >&2
    cat "$runtime_dir/xvfb.log" >&2
    exit 1
  fi
  sleep 0.05
done
if [[ ! -s "$display_file" ]]; then
  echo "run_with_xvfb: Xvfb did not report a display within 5 s" >&2
  exit 1
fi

export DISPLAY=":$(tr -d '[:space:]' <"$display_file")"
export XDG_RUNTIME_DIR="$runtime_dir"
"$@"
