#!/usr/bin/env bash
# Runs a command on an X server of its own (Xvfb, 1280×1024×24). The server picks a free display
# number itself (-displayfd), so that window tests run side by side without racing for one, as
# `xvfb-run -a` does. -noreset: the server outlives each window the command closes.
#   with_xvfb.sh COMMAND [ARGS...]
set -uo pipefail
ready=$(mktemp)
Xvfb -displayfd 3 -screen 0 1280x1024x24 -noreset -nolisten tcp 3>"$ready" 2>/dev/null &
server=$!
for _ in $(seq 200); do
  [ -s "$ready" ] && break
  if ! kill -0 "$server" 2>/dev/null; then
    echo "with_xvfb.sh: Xvfb did not start" >&2
    rm -f "$ready"
    exit 1
  fi
  sleep 0.05
done
display=$(head -n 1 "$ready")
rm -f "$ready"
if [ -z "$display" ]; then
  echo "with_xvfb.sh: Xvfb named no display within 10 s" >&2
  kill "$server" 2>/dev/null
  exit 1
fi
# A program of ours that crashes writes its stack first (app/crash_stack.h).
DISPLAY=":$display" GPSURF_CRASH_STACK=1 "$@"
status=$?
kill "$server" 2>/dev/null
wait "$server" 2>/dev/null
exit "$status"
