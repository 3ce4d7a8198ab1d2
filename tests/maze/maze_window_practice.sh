#!/usr/bin/env bash
# The practice pass in the live maze window (docs/maze.md, "Practice"), driven by real X events
# (xdotool through XTest) inside xvfb-run:
#   Space starts from the instructions into the practice; moving the mouse moves the practice's
#   hand; Space ends the practice early; the "real session" screen holds the clock (no sample of
#   the session's stream while it shows, though the mouse moves); Space starts the session, whose
#   hand starts at the probe's start (the practice's motion and the wait's do not carry over);
#   Esc quits. Then: both logs exist, the practice's ends `practice_ended` on a route of its own
#   seed, the session's ends `quit`.
# usage: maze_window_practice.sh PSEUDOSHADOW MAZE.toml OUT_DIR
set -euo pipefail
exe=$1 maze=$2 out=$3
rm -rf "$out"
mkdir -p "$out"
fail() { echo "maze_window_practice: $*" >&2; [ -f "$out/run.txt" ] && cat "$out/run.txt" >&2; exit 1; }

source "$(dirname "$0")/window_stream.sh"
source "$(dirname "$0")/../window/window_start.sh"

xdotool mousemove 640 400
start_window "pseudoshadow maze - P" "$out/run.txt" \
  "$exe" maze --maze "$maze" --participant P --seed 11 --cues on --practice --out "$out/s"
sleep 1
xdotool key space                      # instructions -> practice
wait_stream_file_past "$out/s/practice/device.log.partial" 1.5
xdotool mousemove_relative -- 60 0     # the practice's hand moves 60 x 0.15 = 9 mm
# The hand goes to a reading over the next frame (docs/window.md, "Between two frames"): under
# load the practice's first frame took 3 s and read the motion and the Space below together,
# so the practice ended before its hand set off. Wait for the hand itself.
wait_stream_x_past "$out/s/practice/device.log.partial" 5
xdotool key space                      # ends the practice
sleep 1
xdotool mousemove_relative -- 80 0     # while the "real session" screen waits
sleep 1
[ -s "$out/s/device.log.partial" ] && fail "the session's stream has samples before its Space"
xdotool key space                      # the session starts
sleep 2.5
xdotool key Escape
wait "$pid" || fail "maze exited $?"

p="$out/s/practice/session.jsonl"
[ -f "$p" ] || fail "no practice log"
grep -q '"type":"session_end","reason":"practice_ended"' "$p" || fail "the practice log does not end practice_ended: $(tail -1 "$p")"
grep -q '"seed":11,' "$p" && fail "the practice ran on the session's own seed"
grep -q '"type":"session_end","reason":"quit"' "$out/s/session.jsonl" || fail "the session does not end quit"
grep -q '"seed":11,' "$out/s/session.jsonl" || fail "the session is not on its seed"
# The practice's hand moved (60 counts); the session's first sample is the probe's start
# (x = 0, y = -91 in the shipped maze, 17 digits: exact).
awk '!/^#/ { if ($2 > m) m = $2 } END { exit !(m > 5) }' "$out/s/practice/device.log" ||
  fail "the practice's hand never moved right"
awk '!/^#/ { if (n++ == 0) { exit !($2 == 0 && $3 == -91) } }' "$out/s/device.log" ||
  fail "the session's hand does not start at the probe's start: $(grep -v '^#' "$out/s/device.log" | head -1)"
echo "maze_window_practice: practice ended early, session started at the probe's start and quit"
