#!/usr/bin/env bash
# The tuning panel as a person uses it, driven by xdotool under Xvfb: open the wood scene in
# `pseudoshadow run --panel` with the probe sliding to and fro 0.5 mm above the sample, save a
# window screenshot (S: the image without the panel, plus the state that drew it), drag
# lambda_min and theta_max, save the overrides, save a second screenshot, quit; then render
# both states headless with `render --overrides` and compare them with the window's images. Not part of CI: GUI input timing on a loaded
# machine is not deterministic. Needs xvfb, xdotool, x11-apps (xwd) and the build.
# Usage: tools/panel_check_xvfb.sh [WORK_DIR]   (default: a new temporary directory)
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
exe="${repo}/build/pseudoshadow"
work="${1:-$(mktemp -d)}"
for tool in Xvfb xdotool xwd; do
  command -v "${tool}" >/dev/null || { echo "panel_check: needs ${tool} (apt-get install xvfb xdotool x11-apps)" >&2; exit 2; }
done
[ -x "${exe}" ] || { echo "panel_check: build first (tools/bootstrap.sh)" >&2; exit 2; }

mkdir -p "${work}/scenes" "${work}/textures"
cp "${repo}/scenes/table5_1_wood.toml" "${work}/scenes/wood.toml"
cp "${repo}/textures/wood.png" "${work}/textures/"
rm -f "${work}/scenes/wood.overrides.toml" "${work}"/screenshot_*.png
# The probe slides along y at 56 mm/s, 0.5 mm above the sample: the texture's amplitude
# follows speed, so a still probe would show almost none. Along y, the shadow moves up and down
# on screen and the docked panel has no reason to change sides (docs/window.md).
awk 'BEGIN { for (i = 0; i <= 600; ++i) printf "%.2f 0 %d 8.5 0\n", i * 0.25, (i % 2 ? 7 : -7) }' \
  > "${work}/stroke.traj"

source "${repo}/tools/xvfb_display.sh"

cd "${work}"
"${exe}" run --scene scenes/wood.toml --panel --no-watch --device trajectory:stroke.traj \
  --quit-after 120 > run.log 2>&1 &
run_pid=$!
sleep 6
shot() { xwd -root -silent > "$1.xwd"; }
shot before
xdotool mousemove 600 50 key s  # screenshot_0000: before the edits
sleep 1.5
# The panel docks along the right edge of the 640x480 window (x 448..640; docs/window.md), each
# slider on the line under its label: lambda_min's at y = 155, theta_max's at y = 275; handles
# dragged right in small steps, one step per frame or so.
drag() {  # x0 x1 y
  xdotool mousemove "$1" "$3" mousedown 1
  for x in $(seq "$1" 8 "$2"); do xdotool mousemove "${x}" "$3"; sleep 0.05; done
  # An edit rebuilds the renderer (and re-bakes the Gabor tile: seconds on a loaded machine);
  # ImGui 1.86 has no input queue, so input sent during that frame would be lost.
  sleep 0.3; xdotool mouseup 1; sleep 6
}
drag 476 512 155
drag 553 599 275
# Scroll the panel to its end (must not zoom the camera) and press "Save overrides".
xdotool mousemove 540 300
for _ in $(seq 10); do xdotool click 5; sleep 0.1; done
sleep 1
shot panel
xdotool mousemove 508 433 click 1
sleep 1
xdotool mousemove 600 50 key F1   # hide the panel, then S: a screenshot of the image alone
sleep 3
xdotool key s
sleep 3  # Q in the same frame as S would quit before the screenshot is taken
shot after
xdotool key q
wait "${run_pid}" || { cat run.log; echo "panel_check: run failed" >&2; exit 1; }
cat run.log
[ -f scenes/wood.overrides.toml ] || { echo "panel_check: no overrides saved" >&2; exit 1; }
echo "--- scenes/wood.overrides.toml"; cat scenes/wood.overrides.toml
grep -q lambda_min scenes/wood.overrides.toml && grep -q theta_max scenes/wood.overrides.toml ||
  { echo "panel_check: the drags did not reach the overrides" >&2; exit 1; }
status=0
for n in 0000 0001; do
  "${exe}" render --scene scenes/wood.toml --overrides "screenshot_${n}.overrides.toml" \
    --out "headless_${n}.png" -q
  echo "--- window screenshot_${n}.png vs render --overrides screenshot_${n}.overrides.toml"
  "${exe}" compare "screenshot_${n}.png" "headless_${n}.png" || status=1
done
echo "--- before vs after the edits (must differ)"
if "${exe}" compare screenshot_0000.png screenshot_0001.png; then status=1; fi
"${exe}" render --scene scenes/wood.toml --overrides scenes/wood.overrides.toml \
  --probe 0,0,8.5 --velocity 60,0,0 --out edited.png -q
"${exe}" render --scene scenes/wood.toml --probe 0,0,8.5 --velocity 60,0,0 --out unedited.png -q
echo "panel_check: images in ${work} (screenshot_0000/0001: window before/after; unedited/edited:"
echo "  render at 60 mm/s without/with the saved overrides)"
exit "${status}"
