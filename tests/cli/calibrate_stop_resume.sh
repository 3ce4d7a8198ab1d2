#!/usr/bin/env bash
# `calibrate` stopped early and resumed, in the window under xvfb-run with real X key events
# (xdotool): a log cut where the first staircase has just finished is resumed by a person at the
# window; two Left presses (spaced past the blank between trials) are two more answers; Esc keeps
# every answer, says how to continue, and writes the table from the one finished staircase.
# usage: calibrate_stop_resume.sh PSEUDOSHADOW OUT_DIR
set -euo pipefail
exe=$1 out=$2
source "$(dirname "$0")/../window/window_start.sh"
rm -rf "$out"; mkdir -p "$out"; cd "$out"
fail() { echo "calibrate_stop_resume: $*" >&2; exit 1; }
args=(calibrate --curve speed --references 10,20 --reversals 8 --average-last 4 --seed 5 -q)
"$exe" "${args[@]}" --observer simulated --out full.lut
# The row at which one staircase has its 8th reversal (columns: trial,curve,point,...,reversal).
k=$(awk -F, 'NR > 1 && $10 == 1 { if (++rev[$3] == 8) { print NR - 1; exit } }' full.trials.csv)
[ -n "$k" ] || fail "no staircase finished in the full run"
head -n $((k + 1)) full.trials.csv > part.csv
start_window "pseudoshadow calibrate" stop.txt "$exe" "${args[@]}" --resume part.csv --out stop.lut
# A press answers the pair on screen: none before the first stimuli are drawn (seconds on
# software GL), none in the 0.3 s blank after an answer. So: press, and wait (up to 5 s: a
# frame's time) for the log, rewritten after every answer, to grow before pressing again.
logged() { [ -f stop.trials.csv ] && echo $(($(wc -l < stop.trials.csv) - 1)) || echo 0; }
for want in $((k + 1)) $((k + 2)); do
  for _ in $(seq 12); do
    [ "$(logged)" -ge "$want" ] && break
    xdotool key Left
    for _ in $(seq 50); do [ "$(logged)" -ge "$want" ] && break; sleep 0.1; done
  done
  [ "$(logged)" -ge "$want" ] || fail "no answer reached the log after 12 presses"
done
xdotool key Escape
wait $pid || fail "exit $?: $(cat stop.txt)"
cat stop.txt
rows=$(($(wc -l < stop.trials.csv) - 1))
[ "$rows" -eq $((k + 2)) ] || fail "the log has $rows trials, want $k replayed + 2 answered"
head -n $((k + 1)) stop.trials.csv | cmp - part.csv || fail "the replayed trials differ from the log resumed"
grep -q "stopped after $((k + 2)) trials (1 of 2 staircases finished).*--resume" stop.txt || fail "no stop message"
grep -q "not finished: not used" stop.lut || fail "the table does not say which staircase it left out"
echo "calibrate_stop_resume: ok ($k trials replayed, 2 answered, table from 1 staircase)"
