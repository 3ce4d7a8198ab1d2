# Sourced by the window tests written in bash (tests/maze/maze_window_*.sh,
# tests/cli/calibrate_stop_resume.sh): a program's window started under the test's X server, and
# when it ends, why (the walks' rule, tests/window/window_proc.py). Needs a `fail MESSAGE`
# function in the sourcing script.

# What the program prints when GLFW cannot open the display or create the window
# (src/gl/context_glfw.cpp: "glfwInit failed: X11: Failed to open display :99").
kWindowDisplayFailure='glfwInit failed|glfwCreateWindow\([^)]*\) failed|Failed to open display'

# The last 20 lines of file $1, indented, for a failure message.
window_tail() { tail -n 20 "$1" 2>/dev/null | sed 's/^/    /'; }

# Waits (at most 30 s) for a visible window named $1 of the background process $pid. Returns 1
# when the process ended first, its status in $window_status; fails the test after 30 s.
wait_window() {
  local end=$((SECONDS + 30))
  # Polled without --sync: a search that fails (no such window yet, or the X server refused the
  # connection for a moment) is tried again, and a program that ended is seen within 0.2 s.
  until xdotool search --onlyvisible --name "$1" >/dev/null 2>&1; do
    if ! kill -0 "$pid" 2>/dev/null; then
      window_status=0
      wait "$pid" || window_status=$?
      return 1
    fi
    ((SECONDS < end)) || { kill "$pid"; fail "no window named '$1' after 30 s; the last lines of $2:
$(window_tail "$2")"; }
    sleep 0.2
  done
}

# start_window TITLE OUTFILE CMD...: starts CMD in the background, its stdout and stderr appended
# to OUTFILE, and waits for its window; sets $pid. A program that ends first fails the test with
# its status and OUTFILE's last lines, except one that could not open its display: that one is
# started again, once, after 1 s (a busy X server can refuse a connection for a moment).
start_window() {
  local title=$1 outfile=$2 try
  shift 2
  for try in 1 2; do
    "$@" >>"$outfile" 2>&1 &
    pid=$!
    wait_window "$title" "$outfile" && return 0
    if [ "$try" -eq 2 ] || ! grep -qE "$kWindowDisplayFailure" "$outfile"; then
      fail "the window '$title' exited early (status $window_status); the last lines of $outfile:
$(window_tail "$outfile")"
    fi
    echo "start_window: '$title' could not open its display ($(grep -m1 -E "$kWindowDisplayFailure" "$outfile")); starting it again in 1 s"
    sleep 1
  done
}
