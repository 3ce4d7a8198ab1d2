#!/usr/bin/env python3
"""`run --max-fps` (docs/window.md, "Frame rate"): the window's frames start at least one period
apart. A scripted window session of 10 frames at --max-fps 4 must show, in its --readouts-log,
states drawn a median 200 ms or more apart and 2.2 s or more from the first to the last (9
periods of 250 ms, less 50 ms: a frame draws the state of the last 1 kHz tick, which a loaded
machine can delay; the times logged are the states', not the frames'). Uncapped, these 64x48
frames came a median 45 ms apart with the whole suite running beside them (the first ones bake
the Gabor tile between frames, 40 ms a frame), a few ms with nothing beside them. Only this
lower bound is asserted: how fast an uncapped window draws is the machine's business
(benchmarks, not tests), so --max-fps 0 need only run. A negative rate is refused with exit 2.
Run under an X server.

    run_max_fps.py EXE TRAJ OUT_DIR          Standard library only."""
import json
import os
import subprocess
import sys

FPS, FRAMES = 4, 10
MEDIAN_GAP_S = 0.200
MIN_SPAN_S = (FRAMES - 1) / FPS - 0.050


def session(exe, traj, log, fps, frames):
    cmd = [exe, "run", "--device", "trajectory:" + traj, "--frames", str(frames), "--size", "64x48",
           "--max-fps", str(fps), "--readouts-log", log, "--mute", "--no-watch", "-q"]
    done = subprocess.run(cmd, capture_output=True, text=True)
    return done.returncode, done.stdout + done.stderr, cmd


def main():
    exe, traj, out = sys.argv[1:4]
    os.makedirs(out, exist_ok=True)
    failures = []
    capped = os.path.join(out, "capped.jsonl")
    rc, text, cmd = session(exe, traj, capped, FPS, FRAMES)
    if rc != 0:
        print(f"FAIL: {' '.join(cmd)} exited {rc}:\n{text}")
        return 1
    with open(capped, encoding="utf-8") as f:
        t = [json.loads(line)["t_s"] for line in f if line.strip()]
    gaps = [b - a for a, b in zip(t, t[1:])]
    print(f"--max-fps {FPS}: {len(t)} frames, gaps {min(gaps) * 1e3:.1f}-{max(gaps) * 1e3:.1f} ms, "
          f"first to last {(t[-1] - t[0]) * 1e3:.0f} ms")
    if len(t) != FRAMES:
        failures.append(f"{len(t)} frames logged, not {FRAMES}")
    median = sorted(gaps)[len(gaps) // 2]
    if median < MEDIAN_GAP_S or t[-1] - t[0] < MIN_SPAN_S:
        failures.append(f"states drawn a median {median * 1e3:.1f} ms apart, {(t[-1] - t[0]) * 1e3:.0f} ms from the first "
                        f"to the last (at most {FPS} frames a second: >= {MEDIAN_GAP_S * 1e3:.0f} ms and >= {MIN_SPAN_S * 1e3:.0f} ms)")
    rc, text, cmd = session(exe, traj, os.path.join(out, "uncapped.jsonl"), 0, 12)
    if rc != 0:
        failures.append(f"{' '.join(cmd)} exited {rc}:\n{text}")
    rc, text, cmd = session(exe, traj, os.path.join(out, "refused.jsonl"), -3, 2)
    if rc != 2 or "--max-fps" not in text:
        failures.append(f"--max-fps -3: exit {rc} (expected 2, naming the option):\n{text}")
    for f in failures:
        print("FAIL: " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
