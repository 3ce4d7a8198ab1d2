#!/usr/bin/env bash
# `study run --simulate` killed with SIGKILL while it writes, then `study resume`: the log holds
# exactly the trials of an unbroken run (each once, in order), and `study summarize` accepts its
# checksum chain. usage: study_kill_resume.sh PSEUDOSHADOW EXPERIMENT OUT_DIR
set -euo pipefail
exe=$1 experiment=$2 out=$3
rm -rf "$out"; mkdir -p "$out"
fail() { echo "study_kill_resume: $*" >&2; exit 1; }
run() { "$exe" study "$1" "$experiment" --participant P01 --simulate --out "$2" -q; }
# The trial lines without their checksums (the resumed log's chain holds a `resumed` line).
trials() { grep '"type":"trial"' "$1" | sed 's/,"sha256":"[0-9a-f]*"}$/}/'; }
run run "$out/whole"
log="$out/broken/P01/trials.jsonl"
"$exe" study run "$experiment" --participant P01 --simulate --out "$out/broken" -q & pid=$!  # the process itself, not a subshell
for _ in $(seq 200); do
  [ -f "$log" ] && [ "$(wc -l < "$log")" -ge 50 ] && break
  sleep 0.02
done
kill -9 "$pid" 2>/dev/null || fail "the run ended before it was killed: give the experiment more trials"
wait "$pid" 2>/dev/null || true
killed_at=$(wc -l < "$log")
grep -q '"type":"session_end"' "$log" && fail "the killed run had finished"
run resume "$out/broken"
cmp <(trials "$out/whole/P01/trials.jsonl") <(trials "$log") || fail "the resumed log's trials differ from the unbroken run's"
"$exe" study summarize "$out/broken" --out "$out/summary" --resamples 20 -q || fail "summarize refused the resumed log"
echo "study_kill_resume: ok (killed at line $killed_at of $(wc -l < "$out/whole/P01/trials.jsonl"); resumed log equals the unbroken run)"
