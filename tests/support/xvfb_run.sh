#!/usr/bin/env bash
# The tests' X server: runs a command under its own Xvfb, as `xvfb-run -a` does, but with the
# display number chosen by the server itself (Xvfb -displayfd). Two `xvfb-run -a` started together
# can both pick the lowest free number from /tmp/.X*-lock before either server has made its lock
# file; one then fails or connects to the other's server. Xvfb -displayfd takes the lock itself and
# writes the number only once it listens, so any number of these can start at once, and the window
# tests can run side by side (docs/testing.md, "The window tests").
#
#   xvfb_run.sh [-a] [-s "SERVER ARGS"] [--] COMMAND [ARGS...]
#
# -a is accepted and ignored (the number is always chosen by the server); -s/--server-args as in
# xvfb-run (default "-screen 0 1280x1024x24", xvfb-run's). Exit status: the command's; 1 with the
# server's own lines when Xvfb does not start. Access: none asked (no -auth), so only local clients
# of this machine can connect, as to any Xvfb started by hand.
set -uo pipefail
server_args="-screen 0 1280x1024x24"
while [[ $# -gt 0 ]]; do
  case "$1" in
    -a|--auto-servernum) shift ;;
    -s|--server-args) server_args="$2"; shift 2 ;;
    --server-args=*) server_args="${1#*=}"; shift ;;
    --) shift; break ;;
    -*) echo "xvfb_run.sh: unknown option $1 (usage: xvfb_run.sh [-a] [-s \"SERVER ARGS\"] COMMAND...)" >&2; exit 2 ;;
    *) break ;;
  esac
done
if [[ $# -eq 0 ]]; then
  echo "xvfb_run.sh: no command to run (usage: xvfb_run.sh [-a] [-s \"SERVER ARGS\"] COMMAND...)" >&2
  exit 2
fi
if ! command -v Xvfb >/dev/null; then
  echo "xvfb_run.sh: Xvfb is not installed (Debian package xvfb)" >&2
  exit 1
fi

tmp=$(mktemp -d -t ps-xvfb.XXXXXX)
xpid=""
clean_up() {
  if [[ -n "$xpid" ]]; then
    kill "$xpid" 2>/dev/null
    wait "$xpid" 2>/dev/null
  fi
  rm -rf "$tmp"
}
trap clean_up EXIT
trap 'exit 143' TERM
trap 'exit 130' INT
trap 'exit 129' HUP

# The server ends with this script even when the script is killed outright (ctest's timeout, a
# SIGKILL): setpriv (util-linux) asks the kernel to send it SIGTERM when its parent dies.
pdeath=()
if setpriv --help 2>/dev/null | grep -q -- --pdeathsig; then pdeath=(setpriv --pdeathsig TERM --); fi
# shellcheck disable=SC2086  # the server's arguments are words, as in xvfb-run
"${pdeath[@]}" Xvfb -displayfd 3 $server_args 3>"$tmp/display" >"$tmp/server.log" 2>&1 &
xpid=$!
display=""
for _ in $(seq 1 600); do  # up to 30 s: a loaded 2-core machine can take seconds
  if [[ -s "$tmp/display" ]] && display=$(head -n 1 "$tmp/display") && [[ -n "$display" ]]; then
    break
  fi
  if ! kill -0 "$xpid" 2>/dev/null; then
    echo "xvfb_run.sh: Xvfb exited before it listened; its last lines:" >&2
    tail -n 20 "$tmp/server.log" >&2
    xpid=""
    exit 1
  fi
  sleep 0.05
done
if [[ -z "$display" ]]; then
  echo "xvfb_run.sh: Xvfb did not say its display number within 30 s; its last lines:" >&2
  tail -n 20 "$tmp/server.log" >&2
  exit 1
fi

DISPLAY=":$display" "$@"
status=$?
exit "$status"
