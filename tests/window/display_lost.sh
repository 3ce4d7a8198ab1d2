#!/usr/bin/env bash
# The X display lost mid-session (docs/hardening.md, "Faults"): the X server is killed under
# `run`, `maze` and `calibrate` windows. Each ends its session as on a stop signal: every log
# flushed and closed (the recording renamed from .partial, the maze log's session_end with reason
# display_lost, calibrate's trial log), one line saying the display went away and how to go on,
# exit 1; the maze session then resumes to its end. Before the change Xlib exit()ed the process
# ("X connection to :N broken"): the recording stayed .partial and the maze log had no end.
# Usage: display_lost.sh PSEUDOSHADOW WORKDIR
set -u
exe=$1 work=$2
rm -rf "${work}" && mkdir -p "${work}" && cd "${work}" || exit 1
fail() { echo "FAIL: $*"; exit 1; }
for tool in Xvfb xdotool; do
  command -v "${tool}" > /dev/null || { echo "skipped: ${tool} is not installed"; exit 77; }
done

# One X server per command, on a display number Xvfb picks; killed after `after` seconds.
xvfb_pid=""
start_x() {
  exec 3> >(cat > display.txt)
  Xvfb -displayfd 3 -screen 0 1024x768x24 -nolisten tcp > /dev/null 2>&1 &
  xvfb_pid=$!
  exec 3>&-
  for _ in $(seq 50); do [ -s display.txt ] && break; sleep 0.1; done
  [ -s display.txt ] || fail "Xvfb did not start"
  export DISPLAY=":$(head -n 1 display.txt)"
  rm -f display.txt
}
# run_and_lose SECONDS KEY COMMAND...: the command in the window, KEY pressed once its window is
# up (and 2 s more for its first frames on a loaded machine) and again every 0.5 s for 2 s (none:
# -; a frame late still gets one), the X server killed SECONDS after the first; with `until_file`
# set, not before that file has 2 lines (the key pressed again each 0.5 s meanwhile, up to 30 s).
# The command's exit status in `rc`, its output in out.txt.
until_file=""
run_and_lose() {
  local after=$1 key=$2
  shift 2
  local pid attempt
  # A command that cannot open its display is retried once on a new X server, not failed
  # (seen once in CI with two window tests beside it: "X11: Failed to open display :1").
  for attempt in 1 2; do
    start_x
    timeout 90 "$@" > out.txt 2>&1 &
    pid=$!
    # Any window with a name: this X server is the command's own.
    for _ in $(seq 300); do
      xdotool search --name . > /dev/null 2>&1 && break
      kill -0 "${pid}" 2> /dev/null || break
      sleep 0.1
    done
    if [ "${attempt}" -eq 1 ] && ! kill -0 "${pid}" 2> /dev/null && grep -q "Failed to open display" out.txt; then
      wait "${pid}"
      echo "retrying once: $(grep -m1 "Failed to open display" out.txt)"
      kill "${xvfb_pid}"
      wait "${xvfb_pid}" 2> /dev/null
      continue
    fi
    break
  done
  sleep 2
  [ "${key}" = "-" ] || xdotool key --delay 500 "${key}" "${key}" "${key}" "${key}"
  sleep "${after}"
  if [ -n "${until_file}" ]; then
    for _ in $(seq 60); do
      [ -f "${until_file}" ] && [ "$(wc -l < "${until_file}")" -ge 2 ] && break
      xdotool key "${key}"
      sleep 0.5
    done
  fi
  kill "${xvfb_pid}"
  wait "${pid}"
  rc=$?
  wait "${xvfb_pid}" 2> /dev/null
  cat out.txt
}

# run: the recording and the event log closed (renamed from .partial).
run_and_lose 2 - "${exe}" run --record rec.log --events events.jsonl --mute
[ "${rc}" -eq 1 ] || fail "run: exit ${rc}, expected 1"
grep -q "^run: the display went away .*; recording and event log flushed to rec.log, events.jsonl" out.txt ||
  fail "run: no line saying the display went away"
[ -s rec.log ] && [ ! -e rec.log.partial ] || fail "run: the recording was not closed"
[ -e events.jsonl ] && [ ! -e events.jsonl.partial ] || fail "run: the event log was not closed"
"${exe}" replay --log rec.log --every 30 --size 64 --out replayed -q || fail "run: its recording does not replay"

# maze: session_end display_lost after the participant started (Space), then resumed headless.
"${exe}" maze script --seed 3 --out p.traj > /dev/null || fail "maze script"
run_and_lose 3 space "${exe}" maze --participant D1 --seed 3 --cues on --out m
[ "${rc}" -eq 1 ] || fail "maze: exit ${rc}, expected 1"
grep -q "^maze: the display went away .*; log flushed to m/session.jsonl; resume with: pseudoshadow maze --resume m" out.txt ||
  fail "maze: no line saying the display went away"
tail -n 1 m/session.jsonl | grep -q '"type":"session_end","reason":"display_lost"' || fail "maze: no session_end display_lost"
"${exe}" maze --resume m --device trajectory:p.traj -q || fail "maze: --resume after the display was lost"
grep -q '"type":"resumed"' m/session.jsonl || fail "maze: no resumed line"

# calibrate: two answers given, the trial log written, the resume line printed.
until_file=c.trials.csv run_and_lose 3 Left "${exe}" calibrate --curve distance --out c.lut
[ "${rc}" -eq 1 ] || fail "calibrate: exit ${rc}, expected 1"
grep -q "^calibrate: the display went away .*; trial log flushed to c.trials.csv; resume with: pseudoshadow calibrate" out.txt ||
  fail "calibrate: no line saying the display went away"
[ "$(wc -l < c.trials.csv)" -ge 2 ] || fail "calibrate: no trial in its log"
echo "ok: run, maze and calibrate each ended their session when the display went away"
