#!/usr/bin/env python3
"""The walks' view checks (walk_checks.py) on frames built here with known answers: `home` and
`still` read the turn a rolling 4D surface gives the view (view_turn_deg) beside its offset, so
a view left turned, or turning on at rest, fails even where it has not moved. No window, no X."""
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import walk  # noqa: E402
import walk_checks  # noqa: E402

failures = []


def frames(turns, offset=(0.0, 0.0, 0.0)):
    return [{"frame": i, "view_offset_mm": list(offset), "view_turn_deg": t, "contact": False,
             "state": "hovering", "scene": "flat_torus_rolling.toml"} for i, t in enumerate(turns)]


def report():
    return {"max_rest_drift_mm": 0.0}


with tempfile.TemporaryDirectory() as d:
    path = os.path.join(d, "t.walk")
    with open(path, "w", encoding="utf-8") as f:
        f.write("wait 1.0 home\nwait 1.0 still\n")
    home, still = walk.parse_walk(path)

cases = [
    # (what, step, frames, fails)
    ("home, unturned", home, frames([0.0] * 6), False),
    ("home, turned 0.05 degree (under the tolerance)", home, frames([0.05] * 6), False),
    ("home, left turned 0.5 degree at offset 0", home, frames([0.5] * 6), True),
    ("home, moved 2 mm", home, frames([0.0] * 6, (2.0, 0.0, 0.0)), True),
    ("home, a log without the field", home, [{k: v for k, v in f.items() if k != "view_turn_deg"}
                                              for f in frames([0.0] * 6)], False),
    ("still, turned and holding", still, frames([20.0] * 9), False),
    ("still, turning on at rest", still, frames([20.0 + 0.1 * i for i in range(9)]), True),
]
for what, step, fs, fails in cases:
    out = walk_checks.check_step(step, fs, report())
    if bool(out) != fails:
        failures.append(f"{what}: expected {'a failure' if fails else 'a pass'}, got {out or 'a pass'}")

for f in failures:
    print("FAIL", f)
print(f"walk checks: {len(cases) - len(failures)} of {len(cases)} cases as expected")
sys.exit(1 if failures else 0)
