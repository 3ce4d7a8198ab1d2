#!/usr/bin/env bash
# Screenshot strips of the window walks (issue 27): runs every `window` walk (tests/window) with
# WINDOW_SHOTS, so each walk's `shot` steps dump the window as the person sees it (overlays
# included, xwd), and writes one strip a walk into docs/images/walks/<walk>.png (each shot
# shrunk 4x: 128 px for the 512 px window) and docs/window_walks.md: the strip and the walk's
# numbers (largest proxy depth and drawn penetration while hovering, key presses up to each
# button's scene switch, view drift at rest, taps counted of taps sent, the deepest dent).
#   tools/walk_strips.sh [BUILD_DIR]      (default: build)
# Needs xvfb-run, xdotool and xwd (apt-get install xvfb xdotool x11-apps). About 6-8 minutes.
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$(cd "${1:-${repo}/build}" && pwd)"
for tool in xvfb-run xdotool xwd; do
  command -v "${tool}" >/dev/null || { echo "walk_strips: needs ${tool} (apt-get install xvfb xdotool x11-apps)" >&2; exit 2; }
done
shots="$(mktemp -d)"
trap 'rm -rf "${shots}"' EXIT
echo "walk_strips: running the window walks (ctest -L window -R walk_), shots in ${shots}"
WINDOW_SHOTS="${shots}" ctest --test-dir "${build}" -L window -R 'window\.walk_' --output-on-failure || \
  echo "walk_strips: some walks failed: their strips and numbers are written all the same, marked"
mkdir -p "${repo}/docs/images/walks"
python3 - "${repo}" "${build}" "${shots}" <<'PY'
import glob, json, os, sys
repo, build, shots = sys.argv[1:4]
sys.path.insert(0, os.path.join(repo, "tools"))
import xwd_png
rows = ["# The window walks, as a person sees them", "",
        "Made by `tools/walk_strips.sh` from the `window` tests (`tests/window/walk.py`, docs/window.md",
        "\"Tests\"): each walk's `shot` steps, the real window under Xvfb at 1280x800 driven by xdotool,",
        "shrunk 4x. Numbers from the walk's `--readouts-log`: the proxy's depth in the haptic geometry",
        "and the drawn probe's penetration while only the pointer moved (at rest; sweeping, the drawn",
        "probe beside a steep surface reads as inside it, docs/window.md), key presses up to each",
        "button's scene switch, the view's drift while the pointer rested, taps counted of taps sent.", ""]
for path in sorted(glob.glob(os.path.join(build, "tests", "window", "window.walk_*", "report.json"))):
    with open(path, encoding="utf-8") as f:
        r = json.load(f)
    pngs = sorted(glob.glob(os.path.join(shots, f"{r['walk']}_win_*.png")))
    test = os.path.basename(os.path.dirname(path))
    rows.append(f"## {test} ({r['scene']})")
    rows.append("")
    if pngs:
        xwd_png.strip(os.path.join(repo, "docs", "images", "walks", f"{r['walk']}.png"), 4, pngs)
        rows += [f"![{r['walk']}](images/walks/{r['walk']}.png)", ""]
    presses = r.get("presses_to_switch")
    facts = [f"{r['frames']} frames",
             f"proxy buried while hovering {r['max_hover_buried_mm']:.2f} mm",
             f"drawn penetration at rest {r['max_rest_penetration_mm']:.2f} mm",
             f"view drift at rest {r['max_rest_drift_mm']:.2f} mm",
             f"taps counted {r['taps_counted']} of {r['taps_sent']}"]
    if presses:
        facts.append("presses to switch " + ", ".join(map(str, presses)))
    if "max_dent_mm" in r:
        facts.append(f"deepest dent {r['max_dent_mm']:.2f} mm")
    if "panel_frames_checked" in r:
        facts.append(f"panel still on {r['panel_frames_checked']} frames")
    rows.append("; ".join(facts) + "." + (" **Failed:** " + "; ".join(r["failures"]) if r["failures"] else ""))
    rows.append("")
with open(os.path.join(repo, "docs", "window_walks.md"), "w", encoding="utf-8") as f:
    f.write("\n".join(rows))
print(f"walk_strips: docs/window_walks.md and docs/images/walks/ written")
PY
