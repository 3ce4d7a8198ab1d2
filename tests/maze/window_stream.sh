# Sourced by the maze window tests: reading the device stream a live session writes about once a
# second (DIR/device.log.partial). Needs a `fail MESSAGE` function in the sourcing script.

# Session seconds of the newest sample in stream file $1.
stream_time_of() { tail -n 1 "$1" 2>/dev/null | awk '{print $1 + 0}'; }

# Waits (at most 30 s) until stream file $1 reaches $2 session seconds.
wait_stream_file_past() {
  for _ in $(seq 300); do
    awk -v t="$(stream_time_of "$1")" -v s="$2" 'BEGIN { exit !(t + 0 >= s) }' && return 0
    sleep 0.1
  done
  fail "$1 never reached $2 s"
}

# Waits (at most 30 s) until a sample in stream file $1 has x (its second column) past $2 mm:
# the hand got to a motion sent, however long the frames that read it took.
wait_stream_x_past() {
  for _ in $(seq 300); do
    [ -f "$1" ] && awk -v x="$2" '!/^#/ && $2 + 0 > x { found = 1 } END { exit !found }' "$1" && return 0
    sleep 0.1
  done
  fail "$1: the hand never got past x = $2 mm"
}

# Session seconds of the first sample in stream file $1, once there is one (at most 30 s).
stream_first_time_of() {
  for _ in $(seq 300); do
    if [ -f "$1" ] && grep -qv '^#' "$1"; then
      grep -v '^#' "$1" | head -n 1 | awk '{print $1 + 0}'
      return 0
    fi
    sleep 0.1
  done
  fail "$1 has no sample after 30 s"
}
