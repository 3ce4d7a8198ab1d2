#!/usr/bin/env bash
# `study run` with a person at the window (docs/study.md, "In the window"), under xvfb-run with real
# X key events (xdotool, XTest): the instructions, the practice, the "practice over" screen and a
# few trials answered with keys, then Esc; the printed `study resume` line finishes the session
# with a simulated tail; the log holds exactly the answers sent, and `study summarize` takes it.
# Then identification: two materials named, Esc; theta and distance: two answers each, Esc, and a
# simulated tail.
# usage: study_window.sh PSEUDOSHADOW STUDIES_DIR OUT_DIR
set -euo pipefail
exe=$1 studies=$2 out=$3
source "$(dirname "$0")/../window/window_start.sh"
rm -rf "$out"; mkdir -p "$out"; cd "$out"
fail() { echo "study_window: $*" >&2; exit 1; }

# Waits (up to 60 s) for the window's title to be $1 exactly.
title_is() {
  local wid name
  for _ in $(seq 600); do
    wid=$(xdotool search --onlyvisible --name "pseudoshadow study" 2>/dev/null | head -n 1) || true
    if [ -n "$wid" ]; then
      name=$(xdotool getwindowname "$wid" 2>/dev/null) || true
      [ "$name" = "$1" ] && return 0
    fi
    kill -0 "$pid" 2>/dev/null || fail "the window ended while waiting for '$1'"
    sleep 0.1
  done
  fail "the window's title is '$name', not '$1', after 60 s"
}
press() { xdotool key --delay 0 "$1"; }

# Threshold: 4 practice trials and 3 that count, each key sent once the title says it is taken.
start_window "pseudoshadow study" console.txt "$exe" study run "$studies/lambda_threshold.toml" --participant P03 --out st
title_is "pseudoshadow study: instructions"
press space
sent=(1 2 2 1 2 1 1)
for i in 0 1 2 3 4 5 6; do
  if [ "$i" -lt 4 ]; then what="practice trial $((i + 1)) of 4"; else what="trial $((i - 3)) of 120"; fi
  [ "$i" -eq 4 ] && { title_is "pseudoshadow study: practice over"; press Return; }
  title_is "pseudoshadow study: $what, answer"
  press "${sent[$i]}"
done
title_is "pseudoshadow study: trial 4 of 120"
press Escape
wait "$pid" || fail "exit $? after Esc: $(window_tail console.txt)"
resume="pseudoshadow study resume $studies/lambda_threshold.toml --participant P03 --out st"
grep -qxF "study: stopped after 7 of 124 trials; the log is st/P03/trials.jsonl; resume with: $resume" console.txt \
  || fail "no stop line: $(window_tail console.txt)"
log=st/P03/trials.jsonl
got=$(grep '"type":"trial"' "$log" | sed -E 's/.*"response":([0-9]+).*/\1/' | tr '\n' ' ')
[ "$got" = "${sent[*]} " ] || fail "the log's answers are '$got', the keys sent '${sent[*]}'"
grep -q '"observer":{"answered_in":"window","kind":"person"}' "$log" || fail "the log does not say a person answered"
grep -q '"type":"session_end"' "$log" && fail "a stopped run wrote session_end"
# The printed line, with a simulated participant for the rest.
"$exe" ${resume#pseudoshadow } --simulate -q || fail "the printed resume line failed"
[ "$(grep -c '"type":"trial"' "$log")" -eq 124 ] || fail "the session did not finish: $(grep -c '"type":"trial"' "$log") trials"
grep -q '"type":"resumed","at_trial":8,"observer":{"kind":"simulated"' "$log" || fail "no resumed line naming the simulated tail"
tail -n 1 "$log" | grep -q '"type":"session_end"' || fail "no session_end after the tail"
"$exe" study summarize st --out st/summary --resamples 50 -q || fail "study summarize refused the mixed log"

# Identification: the material on screen named with keys 3 and 1, then Esc.
start_window "pseudoshadow study" console2.txt "$exe" study run "$studies/identification.toml" --participant P01 --out id
title_is "pseudoshadow study: instructions"
press space
title_is "pseudoshadow study: practice trial 1 of 8, answer"
press 3
title_is "pseudoshadow study: practice trial 2 of 8, answer"
press 1
title_is "pseudoshadow study: practice trial 3 of 8, answer"
press Escape
wait "$pid" || fail "identification: exit $? after Esc"
got=$(grep '"type":"trial"' id/P01/trials.jsonl | sed -E 's/.*"answered_index":([0-9]+).*/\1/' | tr '\n' ' ')
[ "$got" = "2 0 " ] || fail "identification: the log's answers are '$got', want '2 0 ' (keys 3 and 1)"
# The other two threshold experiments: two practice answers each, Esc, then a simulated tail.
for name in theta_threshold distance_threshold; do
  start_window "pseudoshadow study" "console_$name.txt" "$exe" study run "$studies/$name.toml" --participant P02 --out "$name"
  title_is "pseudoshadow study: instructions"
  press space
  title_is "pseudoshadow study: practice trial 1 of 4, answer"
  press 2
  title_is "pseudoshadow study: practice trial 2 of 4, answer"
  press 1
  title_is "pseudoshadow study: practice trial 3 of 4, answer"
  press Escape
  wait "$pid" || fail "$name: exit $? after Esc"
  got=$(grep '"type":"trial"' "$name/P02/trials.jsonl" | sed -E 's/.*"response":([0-9]+).*/\1/' | tr '\n' ' ')
  [ "$got" = "2 1 " ] || fail "$name: the log's answers are '$got', want '2 1 '"
  "$exe" study resume "$studies/$name.toml" --participant P02 --out "$name" --simulate -q || fail "$name: the simulated tail failed"
  tail -n 1 "$name/P02/trials.jsonl" | grep -q '"type":"session_end"' || fail "$name: no session_end after the tail"
done
echo "study_window: ok (lambda: 7 answers by key, then a simulated tail to 124; identification: 2 answers;" \
  "theta and distance: 2 answers each, then a simulated tail)"
