#!/usr/bin/env bash
# The window as a new user first sees it, under Xvfb (no window manager), driven by xdotool:
# `pseudoshadow run` on the default scene with a scripted probe hovering and sliding over the
# plank, three screenshots of the whole window (overlays included):
#   window_start.png     at start: the help overlay and the readouts, beside the shadow
#   window_readouts.png  after a key press has hidden the help: the readouts alone
#   window_panel.png     with the parameter panel (F1) docked beside the shadow
# then checks, on every frame of the session's `--ui-report`, that no overlay rectangle
# intersects the shadow's bounding box (measured on the frame's pixels). Screenshots are X
# window dumps (xwd) converted to PNG by the few lines of Python below (standard library only:
# zlib), cropped to the window. Not part of CI: GUI input timing on a loaded machine is not
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
cat > xwd.py <<'PY'
"""xwd.py png|black FILE.xwd X Y W H [OUT.png]: crop an X window dump to the window and write
it as PNG, or exit 0 if that region is all black (the window has not drawn its first frame)."""
import struct, sys, zlib


def xwd_rows(src, x0, y0, w, h):
    """The RGB rows (each led by PNG filter byte 0) of the window at x0, y0, w x h in a
    TrueColor ZPixmap X window dump of depth 24 (Xvfb: 3 bytes a pixel, lines padded)."""
    d = open(src, "rb").read()
    hdr = struct.unpack(">25I", d[:100])
    header_size, fmt, depth, width, height = hdr[0], hdr[2], hdr[3], hdr[4], hdr[5]
    byte_order, bpp, line_bytes, ncolors = hdr[7], hdr[11], hdr[12], hdr[19]
    stride = bpp // 8
    if fmt != 2 or depth != 24 or stride not in (3, 4):
        sys.exit(f"window_check: {src}: expected a depth-24 ZPixmap dump (format {fmt}, depth {depth}, {bpp} bpp)")
    red_mask = hdr[14]
    pix = d[header_size + 12 * ncolors:]
    rows = []
    for y in range(y0, y0 + h):
        line = pix[y * line_bytes:(y + 1) * line_bytes]
        row = bytearray(b"\0")  # PNG filter type 0
        for x in range(x0, x0 + w):
            p = int.from_bytes(line[stride * x:stride * x + stride], "little" if byte_order == 0 else "big")
            r, g, b = (p >> 16) & 255, (p >> 8) & 255, p & 255
            row += bytes((r, g, b) if red_mask == 0xFF0000 else (b, g, r))
        rows.append(bytes(row))
    return rows

def write_png(rows, w, h, dst):
    def chunk(t, c):
        return struct.pack(">I", len(c)) + t + c + struct.pack(">I", zlib.crc32(t + c) & 0xFFFFFFFF)
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(b"".join(rows), 9)) + chunk(b"IEND", b"")
    open(dst, "wb").write(png)


mode, src = sys.argv[1], sys.argv[2]
x0, y0, w, h = map(int, sys.argv[3:7])
rows = xwd_rows(src, x0, y0, w, h)
if mode == "black":
    sys.exit(0 if all(not any(r[1:]) for r in rows) else 1)
write_png(rows, w, h, sys.argv[7])
PY

# The probe comes down to 1.5 mm above the plank (the default scene's sphere has an 8 mm
# radius) and slides +-6 mm along x at 60 mm/s, so the shadow is dark and moves a little.
awk 'BEGIN { print "0.0 0 0 14 0"; print "0.5 0 0 9.5 0";
             for (i = 1; i <= 120; ++i) printf "%.2f %d 0 9.5 0\n", 0.5 + i * 0.2, (i % 2 ? 6 : -6) }' \
  > hover.traj

display=":$(( 90 + RANDOM % 100 ))"
Xvfb "${display}" -screen 0 1024x768x24 >/dev/null 2>&1 &
xvfb_pid=$!
trap 'kill ${xvfb_pid} 2>/dev/null || true' EXIT
export DISPLAY="${display}"
sleep 1

"${exe}" run --scene "${scene}" --no-watch --device trajectory:hover.traj --ui-report ui_report.json \
  --quit-after 60 > run.log 2>&1 &
run_pid=$!
win="$(xdotool search --sync --name '^pseudoshadow' | head -n 1)"
eval "$(xdotool getwindowgeometry --shell "${win}")"  # X, Y, WIDTH, HEIGHT
shot() { xwd -root -silent > "$1.xwd"; python3 xwd.py png "$1.xwd" "${X}" "${Y}" "${WIDTH}" "${HEIGHT}" "$1.png"; }
# The first frame waits for the shaders' JIT and the Gabor tile bake (seconds on a loaded
# machine): poll until the window is not black, then give the probe time to come down.
for _ in $(seq 120); do
  xwd -root -silent > first.xwd
  python3 xwd.py black first.xwd "${X}" "${Y}" "${WIDTH}" "${HEIGHT}" || break
  sleep 0.5
done
sleep 2
shot window_start
xdotool key --window "${win}" Right   # any key but H/? hides the help (Right does nothing else)
sleep 1.5
shot window_readouts
xdotool key --window "${win}" F1
sleep 2
shot window_panel
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
