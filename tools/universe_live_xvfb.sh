#!/usr/bin/env bash
# Screenshots of the five universe scenes in the live window (`pseudoshadow run`), under Xvfb,
# each driven by a short scripted device and captured with the window's own S key, then put side
# by side (oiiotool) as docs/images/universe_live.png. Not part of CI (GUI timing on a loaded
# machine is not deterministic; the replay tests cover the same worlds).
# Needs xvfb, xdotool, openimageio-tools and the build.  Usage: tools/universe_live_xvfb.sh [OUT.png]
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
exe="${repo}/build/pseudoshadow"
out="${1:-${repo}/docs/images/universe_live.png}"
for tool in Xvfb xdotool oiiotool; do
  command -v "${tool}" >/dev/null || { echo "universe_live: needs ${tool} (apt-get install xvfb xdotool openimageio-tools)" >&2; exit 2; }
done
[ -x "${exe}" ] || { echo "universe_live: build first (tools/bootstrap.sh)" >&2; exit 2; }
work="$(mktemp -d)"
trap 'kill "${xvfb_pid}" 2>/dev/null || true; rm -rf "${work}"' EXIT
display=":$(( (RANDOM % 500) + 100 ))"
Xvfb "${display}" -screen 0 1280x1024x24 >/dev/null 2>&1 &
xvfb_pid=$!
sleep 1

# One device script per world: time_s x y z buttons, held to the end.
declare -A traj=(
  [panel]="0 40 -35 14 0|30 40 -35 8.5 0"                          # over the Poly button
  [illusion]="0 -20 0 80 0|1 -20 0 54 0|30 -5 0 54 0"              # on the sphere's top
  [weight]="0 0 0 70 0|0.3 0 0 45 0|1 0 0 45 0|1.6 25 0 55 0|30 25 0 55 0"  # the ball swings
  [field]="0 0 -30 20 0|30 12 -10 20 0"                            # toward the weak spot
  [poly]="0 5 0 40 0|1 5 0 40 0|1.5 5 0 17 0|30 5 0 17 0"          # pressed into the brow
)
shots=()
for world in panel illusion weight field poly; do
  mkdir -p "${work}/${world}"
  tr '|' '\n' <<<"${traj[${world}]}" >"${work}/${world}.traj"
  (cd "${work}/${world}" &&
    DISPLAY="${display}" "${exe}" run --scene "${repo}/scenes/universe/${world}.toml" \
      --device "trajectory:${work}/${world}.traj" --quit-after 6 >run.log 2>&1) &
  pid=$!
  sleep 4.5
  DISPLAY="${display}" xdotool key s
  wait "${pid}"
  [ -f "${work}/${world}/screenshot_0000.png" ] || { echo "universe_live: no screenshot of ${world}" >&2; exit 1; }
  shots+=("${work}/${world}/screenshot_0000.png" --resize 200x200)
done
oiiotool --nosoftwareattrib "${shots[@]}" --mosaic:pad=4 5x1 -o "${out}"
echo "universe_live: ${out}"
