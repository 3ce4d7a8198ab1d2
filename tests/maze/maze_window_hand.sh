#!/usr/bin/env bash
# The live maze window driven by real X events (xdotool through XTest), run inside xvfb-run:
#   0. the instructions screen holds the clock: while it shows (3 s in session 3, with the mouse
#      moved meanwhile) no device sample is taken; the session's time counts from Space;
#   1. for pointers left at three places on the screen (two corners and a point outside the
#      window), the hand (device.log) stays within 1 mm of the probe's start for the first 3 s
#      without input: no jump when the window maps, takes focus and grabs the mouse;
#   2. five PageUp taps 5 ms apart raise the hand by 5 x 0.5 mm: every tap counts;
#   3. a 40-count pointer motion to the right moves the hand 40 x 0.15 mm = 6 mm to the right;
#   4. a 200-count motion to the left runs the hand 30 mm into the start corridor's wall, 12 mm
#      from the start (18 mm corridor half-width - 6 mm probe radius): the clutch puts it back
#      under the probe at the wall and logs it;
#   5. Esc ends the session, logged as quit.
# usage: maze_window_hand.sh PSEUDOSHADOW MAZE.toml OUT_DIR
set -euo pipefail
exe=$1 maze=$2 out=$3
rm -rf "$out"
mkdir -p "$out"

fail() { echo "maze_window_hand: $*" >&2; exit 1; }

source "$(dirname "$0")/../window/window_start.sh"
# Starts a mouse session into $out/$1 and waits for its window (window_start.sh).
start_session() {
  start_window "pseudoshadow maze - H$1" "$out/$1.txt" \
    "$exe" maze --maze "$maze" --participant "H$1" --seed $((6 + $1)) --cues on --out "$out/$1"
}

# The instructions screen for $2 s (the pointer moved 300 counts meanwhile), then Space.
start_from_instructions() {
  sleep "$2"
  xdotool mousemove_relative -- 300 0
  sleep 0.3
  [ -s "$out/$1/device.log.partial" ] && fail "session $1: device samples before Space (the clock ran on the instructions)"
  xdotool key space
  t_space=$(date +%s.%N)
}

source "$(dirname "$0")/window_stream.sh"
# Session seconds of session $1's newest sample; waiting for session $1 to reach $2 seconds.
stream_time() { stream_time_of "$out/$1/device.log.partial"; }
wait_stream_past() { wait_stream_file_past "$out/$1/device.log.partial" "$2"; }

quit_session() {
  xdotool key Escape
  t_quit=$(date +%s.%N)
  local status=0
  wait "$pid" || status=$?
  [ "$status" -eq 0 ] || fail "session $1 exited with status $status; the last lines of $out/$1.txt:
$(window_tail "$out/$1.txt")"
  grep -q '"type":"session_end","reason":"quit"' "$out/$1/session.jsonl" || fail "session $1: no quit logged"
}

# Session seconds the hand must stay still for without input.
kStillS=3.0

# Waits until session $1 has handled the X events sent just before, then $2 s more (of session
# time: the filter and the clutch settle): the stream's first flush after the events may hold
# frames begun before them; every sample of a later flush is from a frame begun after them.
# Counted in the session's own samples, not wall seconds: a loaded machine's frames can take
# seconds, and a fixed wait would send Esc before a slow frame read the events.
wait_handled() {
  local f="$out/$1/device.log.partial" size
  size=$(stat -c %s "$f")
  for _ in $(seq 300); do
    (($(stat -c %s "$f") > size)) && break
    sleep 0.1
  done
  wait_stream_past "$1" "$(awk -v t="$(stream_time "$1")" -v s="$2" 'BEGIN { print t + 0.001 + s }')"
}

# The hand in session $1's first kStillS s of session time, counted from the session's own first
# sample t0 (the start at Space), not from the wall clock: every sample from t0 up to and
# including the first at or after t0 + kStillS stays within 1 mm of the first, and that first
# sample is the probe's start. The mouse is read once a frame (a sample's time is its frame's),
# and on a loaded machine the first frames after Space can come seconds apart: the window then
# holds few frames, but at least the start and one past kStillS s, where a hand that jumped
# when the window mapped, took focus or grabbed the mouse still shows (nothing moves it back).
check_still() {
  awk -v name="$1" -v span="$kStillS" '
    /^#/ || done { next }
    n == 0 { t0 = $1; x0 = $2; y0 = $3; n = 1 }
    {
      d = sqrt(($2 - x0)^2 + ($3 - y0)^2); if (d > m) m = d
      if (frames == 0 || $1 != last) frames++
      last = $1
      if ($1 >= t0 + span) done = 1
    }
    END {
      printf "session %s: first sample (%.3f, %.3f) mm at %.3f s; largest move to the sample at %.3f s (%d frames): %.4f mm\n",
        name, x0, y0, t0, last, frames, m
      # The probe starts at x = 0 mid-corridor, y = -91 (the shipped maze, any seed); 1e-9: the recording
      # writes 17 digits, so the start comes back exactly.
      if (x0 < -1e-9 || x0 > 1e-9 || y0 < -91 - 1e-9 || y0 > -91 + 1e-9) exit 2
      if (!done || m > 1.0) exit 1
    }' "$out/$1/device.log"
}

# Session $1's longest frame, s: the largest step between the times of two successive frames'
# samples in its device stream.
longest_frame() {
  awk '/^#/ { next } n++ && $1 > t && $1 - t > g { g = $1 - t } { t = $1 } END { printf "%.3f", g }' "$out/$1/device.log"
}

i=0
for pos in "0 0" "1279 1023" "900 700"; do
  i=$((i + 1))
  xdotool mousemove $pos
  start_session $i
  start_from_instructions $i "$([ $i -eq 3 ] && echo 3 || echo 0.5)"
  t0=$(stream_first_time_of "$out/$i/device.log.partial")
  wait_stream_past $i "$(awk -v t="$t0" -v s="$kStillS" 'BEGIN { print t + s + 0.5 }')"
  if [ $i -eq 1 ]; then
    # Taps and a motion after the still phase (check_still reads the first kStillS s only).
    xdotool key --delay 5 Page_Up Page_Up Page_Up Page_Up Page_Up
    xdotool mousemove_relative -- 40 0
    wait_handled $i 1.0
  elif [ $i -eq 2 ]; then
    xdotool mousemove_relative -- -200 0
    wait_handled $i 1.0
  fi
  quit_session $i
  # Session time ends at most at the wall time from Space to Esc plus the Esc's way: 0.5 s through
  # the X server, and the frame under way when it came (the session's longest; the instructions'
  # seconds, 0.8 s or 3.3 s, are not in it).
  frame_s=$(longest_frame $i)
  awk -v a="$t_space" -v b="$t_quit" -v f="$frame_s" -v log_end="$(grep '"session_end"' "$out/$i/session.jsonl" | sed 's/.*"time_s":\([0-9.e]*\).*/\1/')" \
    'BEGIN { printf "session '$i': %.3f s of session, %.3f s from Space to Esc, longest frame %.3f s\n", log_end, b - a, f
             exit !(log_end <= b - a + 0.5 + f) }' ||
    fail "session $i: the session's clock ran before Space"
  check_still $i || fail "session $i (pointer at $pos): the hand moved without input, or did not start at the probe"
done

# Session 1's last sample: 6 mm right of the start (40 counts x 0.15 mm; 0.3 mm: two counts lost
# to a rebase at most), 2.5 mm higher (5 taps x 0.5 mm, exact: taps are events).
awk '
  /^#/ { next }
  n == 0 { x0 = $2; z0 = $4; n = 1 }
  { x = $2; z = $4 }
  END {
    printf "session 1: hand moved %.4f mm right and %.4f mm up\n", x - x0, z - z0
    if (x - x0 < 5.7 || x - x0 > 6.3) exit 1
    if (z - z0 < 2.5 - 1e-9 || z - z0 > 2.5 + 1e-9) exit 1
  }' "$out/1/device.log" || fail "session 1: the taps or the motion did not reach the hand as given"
# Session 2: one clutch, 30 - 12 = 18 mm of overshoot (1 mm: the proxy rests on the wall within
# the god-object's tolerance, and the motion may come in two events); the hand then back at the
# wall, x = -12 mm (0.5 mm, the same reason).
grep '"type":"clutch"' "$out/2/session.jsonl" | head -1 | tee "$out/2/clutch.txt"
[ "$(grep -c '"type":"clutch"' "$out/2/session.jsonl")" -ge 1 ] || fail "session 2: no clutch logged"
sed 's/.*"overshoot_mm":\([-0-9.e]*\).*/\1/' "$out/2/clutch.txt" | awk '{ if ($1 < 6 || $1 > 19) exit 1 }' ||
  fail "session 2: overshoot not in (6, 19] mm"
awk '/^#/ { next } { x = $2 } END { printf "session 2: hand after the clutch at x = %.4f mm\n", x; if (x < -12.5 || x > -11.5) exit 1 }' \
  "$out/2/device.log" || fail "session 2: the hand is not back under the probe at the wall"
echo "maze_window_hand: ok"
