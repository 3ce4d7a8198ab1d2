#!/bin/bash
# The haptic loop beside CPU-bound competitors (docs/haptics.md, "Under load"): runs
# `pseudoshadow bench-haptics` idle and then beside N busy loops at the same nice level, for each
# of a few settings, and prints one Markdown table row per run (period p50 / p99 / p99.9 / max,
# stalls, frame p50). Usage:
#   tools/haptics_under_load.sh [SECONDS [COMPETITORS]]      (default 10 s, 2 competitors)
# PS_BIN names the pseudoshadow binary (default: build/pseudoshadow of this checkout).
set -euo pipefail
seconds="${1:-10}"
competitors="${2:-2}"
repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bin="${PS_BIN:-${repo_root}/build/pseudoshadow}"
[ -x "${bin}" ] || { echo "haptics_under_load: no ${bin}; build first (tools/bootstrap.sh)" >&2; exit 1; }

busy_pids=()
start_competitors() {
  for _ in $(seq "${competitors}"); do
    (while :; do :; done) &
    busy_pids+=($!)
  done
}
stop_competitors() {
  [ ${#busy_pids[@]} -eq 0 ] || kill "${busy_pids[@]}" 2> /dev/null || true
  busy_pids=()
}
trap stop_competitors EXIT

row() {  # row LABEL LOADED OPTIONS...
  local label="$1" loaded="$2"
  shift 2
  [ "${loaded}" = yes ] && start_competitors
  local out
  out="$("${bin}" bench-haptics --seconds "${seconds}" "$@" 2>&1)" || { stop_competitors; echo "${out}" >&2; exit 1; }
  stop_competitors
  local period frames stalls granted
  period="$(grep '^period us:' <<< "${out}" | awk '{print $4" / "$6" / "$8" / "$10}')"
  frames="$(grep '^frames:' <<< "${out}" | awk '{print $5}')"
  stalls="$(grep -o 'stalls [0-9]*' <<< "${out}" | awk '{print $2}')"
  granted="$(grep -o 'haptic thread [^,;]*' <<< "${out}" | head -1 | sed 's/haptic thread //')"
  echo "| ${label} | ${granted} | ${period} | ${stalls:-?} | ${frames} ms |"
}

echo "bench-haptics ${seconds} s; competitors: ${competitors} busy loops at nice $(nice); $(nproc) CPUs"
echo
echo "| run | haptic thread | period p50 / p99 / p99.9 / max (us) | stalls | frame p50 |"
echo "| --- | --- | --- | --- | --- |"
row "idle" no
row "loaded" yes
row "loaded, --spare-cpu off" yes --spare-cpu off
row "loaded, --realtime 20" yes --realtime 20
row "loaded, --realtime 20 --spare-cpu off" yes --realtime 20 --spare-cpu off
