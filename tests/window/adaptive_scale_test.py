#!/usr/bin/env python3
"""Adaptive resolution in the real window (docs/adaptive.md): Field's view travels (the recorded
navigation walk, tests/haptics/data/universe_field_navigate.traj, played as the device), then
rests. From the window's --readouts-log: every frame whose view moved, after the first two (the
controller has measured no redraw before them), is drawn below scale 1, and the first whole
frame after the last move draws a haptic state at most 100 ms newer than that move's (the
issue's rest requirement). --frame-budget 1 makes every machine reduce, a GPU's too.

    adaptive_scale_test.py EXE SOURCE_ROOT OUT_DIR      (exit 77: Xvfb missing)"""
import json
import os
import shutil
import subprocess
import sys

import window_proc

REST_LIMIT_S = 0.100


def main():
    exe, root, out = sys.argv[1:4]
    if shutil.which("Xvfb") is None:
        print("adaptive scale: Xvfb missing, skipped")
        return 77
    os.makedirs(out, exist_ok=True)
    log = os.path.join(out, "readouts.jsonl")
    cmd = ["bash", window_proc.XVFB_RUN, exe, "run", "--scene", os.path.join(root, "scenes/universe/field.toml"),
           "--device", "trajectory:" + os.path.join(root, "tests/haptics/data/universe_field_navigate.traj"),
           "--size", "640x360", "--frame-budget", "1", "--quit-after", "6", "--readouts-log", log,
           "--mute", "--no-watch", "-q"]
    if subprocess.call(cmd) != 0:
        print("adaptive scale: run failed: " + " ".join(cmd))
        return 1
    with open(log, encoding="utf-8") as f:
        rows = [json.loads(line) for line in f if line.strip()]
    moved = [i for i, r in enumerate(rows) if r["view_moved"]]
    if len(moved) < 5:
        print(f"adaptive scale: only {len(moved)} frames moved the view; the walk should travel")
        return 1
    full = [i for i in moved[2:] if rows[i]["surface_scale"] >= 1.0]
    if full:
        print(f"adaptive scale: moving frames drawn whole: {full}")
        return 1
    last = moved[-1]
    whole = next((i for i in range(last + 1, len(rows)) if rows[i]["surface_scale"] >= 1.0), None)
    if whole is None:
        print("adaptive scale: no whole frame after the view came to rest")
        return 1
    rest_s = rows[whole]["t_s"] - rows[last]["t_s"]
    print(f"adaptive scale: {len(moved)} moving frames, scales {sorted({rows[i]['surface_scale'] for i in moved})}; "
          f"whole again {rest_s * 1e3:.0f} ms after the last move (limit {REST_LIMIT_S * 1e3:.0f} ms)")
    return 0 if rest_s <= REST_LIMIT_S else 1


if __name__ == "__main__":
    sys.exit(main())
