#!/usr/bin/env python3
"""The hour-long soak's judgements (tools/soak.py, docs/hardening.md "Hours of running") on
series built here with known answers: RSS that swings by 5 % every few minutes around a flat
level is no growth, the same swings on a 2 % climb are; single loops that end away and come back
are counted but are not drift, a resting point that moves for good is; a window that ends early or
crashes fails its world. No window, no X."""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
import soak_measures as soak  # noqa: E402

failures = []


def check(name, ok, detail):
    if not ok:
        failures.append(f"{name}: {detail}")


# An hour of RSS every 5 s: 150 MiB with a +-5 % square swing of a 4-minute period (a window that
# opens and closes a world), flat or climbing 2 % over the hour.
def series(climb):
    out = []
    for i in range(720):
        t = 5.0 * i
        swing = 7.5 if (i // 24) % 2 else -7.5
        out.append((t, 150.0 * (1.0 + climb * t / 3600.0) + swing))
    return out


# A world that meets every other target, to judge one measure at a time.
base = {"error": None, "missed": [], "loops": 10, "drift_mm": 0.0,
        "first": {"rate_hz_p50": 1000, "jitter_p99_us_p50": 30}, "last": {"rate_hz_p50": 1000, "jitter_p99_us_p50": 30}}
flat = soak.rss_metrics(series(0.0))
check("flat RSS", abs(flat["rss_growth"]) < 0.002, f"growth {flat['rss_growth']:.4f}, expected ~0")
check("flat RSS judged", not soak.judge({**base, **flat}), f"a flat series failed: {soak.judge({**base, **flat})}")
climb = soak.rss_metrics(series(0.02))
# Medians of the second tenth (6-12 min) and the last (54-60 min): 150 * 0.02 * (57 - 9) / 60.
expected = 0.02 * (57.0 - 9.0) / 60.0 / (1.0 + 0.02 * 9.0 / 60.0)
check("climbing RSS", abs(climb["rss_growth"] - expected) < 0.003, f"growth {climb['rss_growth']:.4f}, expected {expected:.4f}")
check("climbing RSS judged", any("RSS grew" in f for f in soak.judge({**base, **climb})), "a 2 %/h climb passed")
# Two single samples at a swing's top and bottom would have read 7 % of growth: the medians do not.
check("two samples would mislead", abs((150 + 7.5) / (150 - 7.5) - 1.0) > 0.05, "the swing is too small to test")

# 100 loops resting at one point, three of which end 30 mm away once each (transients).
home = [0.0, 0.0, 10.0]
loops = [{"scene": "x.toml", "proxy_mm": list(home), "t_s": 20.0 * i} for i in range(100)]
for i in (5, 50, 97):
    loops[i]["proxy_mm"] = [30.0, 0.0, 10.0]
d = soak.drift_metrics(loops)
check("transients", d["drift_mm"] == 0.0 and d["loops_off"] == 3 and math.isclose(d["largest_off_mm"], 30.0),
      f"got {d}")
# The same loops, the last third resting 1 mm further along x: drift.
for lp in loops[67:]:
    lp["proxy_mm"] = [lp["proxy_mm"][0] + 1.0, 0.0, 10.0]
d = soak.drift_metrics(loops)
check("drift", math.isclose(d["drift_mm"], 1.0), f"got {d}")
check("drift judged", any("resting point moved" in f for f in soak.judge({**base, "drift_mm": d["drift_mm"], **flat})),
      "a 1 mm move passed")
# Loops that ended in another scene (a panel's world) are not compared.
other = [{"scene": "a.toml", "proxy_mm": [0.0, 0.0, 0.0]}] + [{"scene": "b.toml", "proxy_mm": [99.0, 0.0, 0.0]}] * 5
check("other scenes", soak.drift_metrics(other)["drift_mm"] is None, "loops in another scene were compared")

# The window's end: closed by the soak after its time with status 0 is the only clean end. A glibc
# abort 14 s before the end (as once seen, and passed, when the soak read only the readouts) fails.
check("clean end", soak.exit_error(0, 2400.3, 2400.0, "frames 100 ...\n") is None, "a clean end was judged")
crash = soak.exit_error(-6, 2386.0, 2400.0, "warning: sound is off\nfree(): corrupted unsorted chunks\n")
check("crash", crash is not None and "after 2386 of 2400 s" in crash and "SIGABRT" in crash
      and crash.endswith("free(): corrupted unsorted chunks"), f"got {crash!r}")
check("crash judged", crash in soak.judge({**base, **flat, "error": crash}), "a crashed window passed")
early = soak.exit_error(0, 600.0, 2400.0, "")
check("early quit", early == "the window ended after 600 of 2400 s (exit status 0)", f"got {early!r}")
late = soak.exit_error(1, 2401.0, 2400.0, "error: x")
check("failed close", late == "the window ended when closed (exit status 1): error: x", f"got {late!r}")

for f in failures:
    print("FAIL", f)
print("soak measures:", "ok" if not failures else f"{len(failures)} failed")
sys.exit(1 if failures else 0)
