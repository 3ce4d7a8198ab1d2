#!/usr/bin/env bash
# The window as a new user first sees it, under Xvfb (no window manager), driven by xdotool:
# `pseudoshadow run` on the default scene with the mouse moved by xdotool, three screenshots of the whole window (overlays included):
#   window_start.png     at start: the help overlay and the readouts, the shadow under the pointer
#   window_readouts.png  pressed 1 mm into the plank (PageDown 4 times, which also hides the help),
#                        stroking at ~400 px/s: the texture shows, the readouts say "touching"
#   window_panel.png     the same stroke with the parameter panel (F1) docked beside the shadow
# then checks, on every frame of the session's `--ui-report`, that no overlay rectangle
# intersects the shadow's bounding box (measured on the frame's pixels). Screenshots are X
# window dumps (xwd) converted to PNG by tools/xwd_png.py (standard library only: zlib), cropped
# to the window. Not part of CI: GUI input timing on a loaded machine is not
# deterministic (tests/app's run_ui_report_* tests check the same rectangles in CI).
# Needs xvfb, xdotool, x11-apps (xwd), python3 and the build.
# Usage: tools/window_check_xvfb.sh [WORK_DIR] [SCENE]
#   (default: a new temporary directory, scenes/default.toml)
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
exe="${repo}/build/pseudoshadow"
work="${1:-$(mktemp -d)}"
scene="${2:-${repo}/scenes/default.toml}"
for tool in Xvfb xdotool xwd python3; do
  command -v "${tool}" >/dev/null || { echo "window_check: needs ${tool} (apt-get install xvfb xdotool x11-apps python3)" >&2; exit 2; }
done
[ -x "${exe}" ] || { echo "window_check: build first (tools/bootstrap.sh)" >&2; exit 2; }
mkdir -p "${work}"
cd "${work}"
rm -f ./*.xwd window_*.png ui_report.json

source "${repo}/tools/xvfb_display.sh"

# The mouse itself (the default device), moved by xdotool as a person would.
"${exe}" run --scene "${scene}" --no-watch --ui-report ui_report.json --quit-after 90 > run.log 2>&1 &
run_pid=$!
win="$(xdotool search --sync --name '^pseudoshadow' | head -n 1)"
eval "$(xdotool getwindowgeometry --shell "${win}")"  # X, Y, WIDTH, HEIGHT
shot() { xwd -root -silent > "$1.xwd"; python3 "${repo}/tools/xwd_png.py" png "$1.xwd" "${X}" "${Y}" "${WIDTH}" "${HEIGHT}" "$1.png"; }
# The first frame waits for the shaders' JIT and the Gabor tile bake (seconds on a loaded
# machine): poll until the window is not black, then give the probe time to come down.
for _ in $(seq 120); do
  xwd -root -silent > first.xwd
  python3 "${repo}/tools/xwd_png.py" black first.xwd "${X}" "${Y}" "${WIDTH}" "${HEIGHT}" || break
  sleep 0.5
done
# The pointer rests a little left of the window's centre: the shadow (1 mm above the plank at
# start) sits under it, with the help and the readouts beside it.
cx=$(( WIDTH * 2 / 5 )); cy=$(( HEIGHT / 2 ))
xdotool mousemove $(( X + cx )) $(( Y + cy ))
sleep 3
shot window_start
# Four PageDown presses lower the probe 4 x 0.5 mm, from 1 mm above the plank to 1 mm into it
# (any key but H/? also hides the help); then strokes along x at about 400 px/s (8 px every 20 ms), the speed the shipped
# scenes' texture peaks at, run in the background while the screenshots are taken.
for _ in 1 2 3 4; do xdotool key --window "${win}" Next; sleep 0.3; done
stroke() {
  while :; do
    for x in $(seq $(( cx - 60 )) 8 $(( cx + 60 ))) $(seq $(( cx + 60 )) -8 $(( cx - 60 ))); do
      xdotool mousemove $(( X + x )) $(( Y + cy )); sleep 0.02
    done
  done
}
stroke &
stroke_pid=$!
sleep 6
shot window_readouts
xdotool key --window "${win}" F1
sleep 6
shot window_panel
kill "${stroke_pid}" 2>/dev/null || true
xdotool key --window "${win}" q
wait "${run_pid}" || { cat run.log; echo "window_check: run failed" >&2; exit 1; }
cat run.log

python3 - <<'PY'
import json, sys
report = json.load(open("ui_report.json"))
def hit(a, b):
    return a is not None and b is not None and a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]
bad, shadowed = [], 0
for f in report["frames"]:
    if f["shadow"] is None:
        continue
    shadowed += 1
    for box in ("hud", "help", "panel"):
        if hit(f[box], f["shadow"]):
            bad.append(f"frame {f['frame']}: {box} {f[box]} covers the shadow {f['shadow']}")
print(f"window_check: {len(report['frames'])} frames, {shadowed} with a shadow, {len(bad)} with an overlay over it")
for line in bad[:10]:
    print("  " + line)
sys.exit(1 if bad or shadowed == 0 else 0)
PY
echo "window_check: screenshots window_start.png, window_readouts.png, window_panel.png in ${work}"
