#!/usr/bin/env bash
# SIGTERM to the window commands (docs/maze.md "A signal", docs/calibrate.md, docs/haptics.md),
# under xvfb-run: each ends through its normal end and says so in one line on stderr, exit 143.
#   run --record:       the recording closed (renamed from .partial, whole samples);
#   calibrate --window: the trial log holds every answer; the printed resume command, run
#                       headless, ends with the uninterrupted run's log and table byte for byte;
#   maze --window:      the log ends with session_end `terminated`; --resume goes on from it.
# usage: stop_signal_window.sh PSEUDOSHADOW MAZE_TOML STROKE_TRAJ OUT_DIR
set -euo pipefail
exe=$1 maze=$2 stroke=$3 out=$4
rm -rf "$out"; mkdir -p "$out"; cd "$out"
fail() { echo "stop_signal_window: $*" >&2; exit 1; }
# Waits (up to 60 s) until the command in $1 is true.
await() { for _ in $(seq 600); do eval "$1" && return 0; sleep 0.1; done; fail "timed out waiting for: $1"; }
# Sends SIGTERM to $1 and checks its exit status is 143 (128 + 15). (bash's `wait` says 143 for a
# process the signal killed, too: the checks after each call tell the two apart.)
term() { kill -TERM "$1"; set +e; wait "$1"; local rc=$?; set -e; [ "$rc" -eq 143 ] || fail "$2: exit $rc, want 143: $(cat "$2.err")"; }
lines() { [ -f "$1" ] && wc -l < "$1" || echo 0; }

# run --record: SIGTERM once a second of samples is on disk.
"$exe" run --device "trajectory:$stroke" --set "render.size=[128,128]" --quit-after 120 --record rec.log -q \
  > run.out 2> run.err &
pid=$!
await '[ "$(lines rec.log.partial)" -gt 100 ]'
term $pid run
[ ! -e rec.log.partial ] || fail "run: rec.log.partial left: the recording was not closed"
head -n 1 rec.log | grep -q "^# pseudoshadow device log" || fail "run: rec.log has no header"
tail -n 1 rec.log | grep -Eq "^[0-9.e+-]+ [0-9.e+-]+ [0-9.e+-]+ [0-9.e+-]+ [0-9]+$" || fail "run: the last sample is not whole"
grep -qx "run: terminated by SIGTERM; recording flushed to rec.log; replay with: pseudoshadow replay --log rec.log --out DIR" run.err \
  || fail "run: message: $(cat run.err)"

# calibrate --window with the simulated observer: SIGTERM after 3 answers, then the printed resume.
args=(calibrate --curve speed --references 10,20 --reversals 8 --average-last 4 --observer simulated --seed 5 -q)
"$exe" "${args[@]}" --out full.lut
"$exe" "${args[@]}" --window --out cut.lut > cal.out 2> cal.err &
pid=$!
await '[ "$(lines cut.trials.csv)" -ge 4 ]'
term $pid cal
answered=$(($(lines cut.trials.csv) - 1))
head -n $((answered + 1)) full.trials.csv | cmp -s - cut.trials.csv || fail "calibrate: the cut log is not the full run's start"
line=$(cat cal.err)
want="calibrate: terminated by SIGTERM; trial log flushed to cut.trials.csv; resume with: pseudoshadow ${args[*]} --window --out cut.lut --resume cut.trials.csv"
[ "$line" = "$want" ] || fail "calibrate: message: $line"
resume=${line#*resume with: pseudoshadow }
# shellcheck disable=SC2086  # the printed command's words, as a person would paste them
"$exe" ${resume/--window /} || fail "calibrate: the printed resume command failed"
cmp full.trials.csv cut.trials.csv || fail "calibrate: resumed log differs from the uninterrupted one"
cmp full.lut cut.lut || fail "calibrate: resumed table differs from the uninterrupted one"

# maze --window with a scripted participant: SIGTERM once rooms are logged, then --resume.
"$exe" maze script --maze "$maze" --seed 7 --errors 1 --out m.traj
"$exe" maze --maze "$maze" --participant W --seed 7 --cues on --device trajectory:m.traj --window --out w \
  > maze.out 2> maze.err &
pid=$!
await '[ "$(lines w/session.jsonl)" -ge 4 ]'
term $pid maze
tail -n 1 w/session.jsonl | grep -q '"type":"session_end","reason":"terminated"' || fail "maze: last line $(tail -n 1 w/session.jsonl)"
grep -qx "maze: terminated by SIGTERM; log flushed to w/session.jsonl; resume with: pseudoshadow maze --resume w" maze.err \
  || fail "maze: message: $(cat maze.err)"
"$exe" maze --resume w -q || fail "maze: --resume failed"
tail -n 1 w/session.jsonl | grep -q '"reason":"criterion"' || fail "maze: resumed session did not reach the criterion"
echo "stop_signal_window: ok (run, calibrate after $answered answers, maze)"
