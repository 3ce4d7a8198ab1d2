#!/usr/bin/env python3
"""The walks' checks (walk_checks.py) on frames built here with known answers: `home` and
`still` read the turn a rolling 4D surface gives the view (view_turn_deg) beside its offset, so
a view left turned, or turning on at rest, fails even where it has not moved; `free` counts the
hand's push into a surface (held_mm), not a field's (Field's charges push a hovering proxy onto
the floor). No window, no X."""
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


with tempfile.TemporaryDirectory() as d:
    path = os.path.join(d, "t.walk")
    with open(path, "w", encoding="utf-8") as f:
        f.write("wait 1.0 home\nwait 1.0 still\nsweep 0.2 0.5 0.7 0.6 0.5 free\n")
    home, still, free = walk.parse_walk(path)


def touching(pressed, held=None):
    """A sweep's frames, the fourth touching: pressed from the hand, held by the surface."""
    out = [{"frame": i, "view_offset_mm": [0.0, 0.0, 0.0], "contact": False, "state": "hovering",
            "pressed_mm": 0.0, "penetration_mm": 0.0, "buried_mm": 0.0, "force_n": 0.2,
            "scene": "field.toml"} for i in range(6)]
    out[3].update(contact=True, state="touching", pressed_mm=pressed, force_n=0.57)
    if held is not None:
        out[3]["held_mm"] = held
    return out

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
    # Field, under a repelling charge: the proxy pushed onto the floor, pressed 1.08 mm, held 0.3.
    ("free, a field's push onto the floor", free, touching(1.08, 0.3), False),
    ("free, the hand pushed 1.08 mm in", free, touching(1.08, 1.08), True),
    ("free, a log without held_mm reads pressed_mm", free, touching(1.08), True),
    ("free, grazing 0.3 mm", free, touching(0.3), False),
]
for what, step, fs, fails in cases:
    out = walk_checks.check_step(step, fs, walk_checks.new_report())
    if bool(out) != fails:
        failures.append(f"{what}: expected {'a failure' if fails else 'a pass'}, got {out or 'a pass'}")

for f in failures:
    print("FAIL", f)
print(f"walk checks: {len(cases) - len(failures)} of {len(cases)} cases as expected")
sys.exit(1 if failures else 0)
