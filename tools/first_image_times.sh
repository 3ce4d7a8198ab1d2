#!/usr/bin/env bash
# Time to the first image, as a user meets it: the whole `pseudoshadow render` process (one
# frame, the scene's own size) for every shipped scene under three Gabor strategies — the
# default "auto", every textured material forced to "naive" (per-pixel sum) and forced to
# "baked" (a tile baked first). CPU seconds (user + sys, so a loaded machine skews it less than
# wall time), median of REPS alternating runs. Prints a table with auto / min(naive, baked).
# Usage: tools/first_image_times.sh [BUILD_DIR] [REPS]      (docs/benchmarks.md)
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
exe="${1:-${repo}/build}/pseudoshadow"
reps="${2:-3}"
tmp="$(mktemp -d)"
trap 'rm -rf "${tmp}"' EXIT

cpu_seconds() {  # runs the command, prints its user+sys CPU seconds
  /usr/bin/time -f "%U %S" -o "${tmp}/time" "$@" > /dev/null 2>&1
  awk '{ printf "%.3f", $1 + $2 }' "${tmp}/time"
}
median() { printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }

printf '%-30s %8s %8s %8s %8s\n' scene auto naive baked "auto/best"
for scene in "${repo}"/scenes/*.toml; do
  name="$(basename "${scene}" .toml)"
  # The textured materials, as auto's notes name them.
  "${exe}" render --scene "${scene}" --out "${tmp}/x.png" --stats "${tmp}/s.json" -q
  mapfile -t mats < <(grep -o "material '[^']*'" "${tmp}/s.json" | sed "s/material '\(.*\)'/\1/" | sort -u)
  naive=() baked=()
  for m in "${mats[@]}"; do
    naive+=(--set "materials.${m}.gabor_strategy=\"naive\"")
    baked+=(--set "materials.${m}.gabor_strategy=\"baked\"")
  done
  ta=() tn=() tb=()
  for ((i = 0; i < reps; ++i)); do
    ta+=("$(cpu_seconds "${exe}" render --scene "${scene}" --out "${tmp}/a.png" -q)")
    tn+=("$(cpu_seconds "${exe}" render --scene "${scene}" --out "${tmp}/n.png" -q "${naive[@]}")")
    tb+=("$(cpu_seconds "${exe}" render --scene "${scene}" --out "${tmp}/b.png" -q "${baked[@]}")")
  done
  a="$(median "${ta[@]}")" n="$(median "${tn[@]}")" b="$(median "${tb[@]}")"
  printf '%-30s %8s %8s %8s %8.2f\n' "${name}" "${a}" "${n}" "${b}" \
    "$(awk -v a="${a}" -v n="${n}" -v b="${b}" 'BEGIN { m = (n < b ? n : b); print (m > 0 ? a / m : 0) }')"
done
