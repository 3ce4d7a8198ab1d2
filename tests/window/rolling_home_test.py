#!/usr/bin/env python3
"""Home on a rolling 4D surface, through the real window: real X pointer and key events
(xdotool under Xvfb, tools/soak.py's driver) repeat one loop on the rolling flat torus - a 4D
turn, strokes that roll the view, a press into the surface, the turn back, Home - and every loop
must come to rest where the first did (within 0.5 mm, the walks' drift tolerance). Home resets
the haptic loop's view; the picture's camera must follow it. It did not after an edit (the 4D
turn rebuilds the renderer) made while the view was rolled: the rebuilt renderer kept the rolled
camera as its own, the pose was carried onto it twice, and from then on the loops came to rest
87 to 1119 mm apart, the probe out of reach with Home no help.

    rolling_home_test.py EXE SCENE OUT_DIR      (exit 77: Xvfb or xdotool missing)"""
import json
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
TOLERANCE_MM = 0.5


def main():
    exe, scene, out = sys.argv[1:4]
    stem = os.path.splitext(os.path.basename(scene))[0]
    rc = subprocess.call([sys.executable, os.path.join(HERE, "..", "..", "tools", "soak.py"), "--exe", exe,
                          "--minutes", "0.75", "--out", out, "--loop-dir", os.path.join(HERE, "rolling_home"),
                          "--run-arg=--spare-cpu", "--run-arg=off", scene])
    if rc in (2, 77):  # a usage error, or skipped: soak.py said why
        return rc
    # soak.py's own verdict (RSS growth, rates over 45 s) is not this test's: only the rest points.
    with open(os.path.join(out, stem, "result.json"), encoding="utf-8") as f:
        result = json.load(f)
    ends = [e for e in result["loop_ends"] if e["scene"] == os.path.basename(scene)]
    if result.get("error") or len(ends) < 3:
        print(f"rolling home: {len(ends)} loops ({result.get('error')}); 3 or more are needed")
        return 1
    first = ends[0]["proxy_mm"]
    off = [math.dist(e["proxy_mm"], first) for e in ends]
    for e, d in zip(ends, off):
        print(f"  loop ended at t {e['t_s']:.1f} s: proxy {[round(x, 2) for x in e['proxy_mm']]} ({d:.2f} mm from the first)")
    if max(off) > TOLERANCE_MM:
        print(f"rolling home: a loop came to rest {max(off):.2f} mm from the first (tolerance {TOLERANCE_MM} mm)")
        return 1
    print(f"rolling home: ok, {len(ends)} loops within {max(off):.4f} mm")
    return 0


if __name__ == "__main__":
    sys.exit(main())
