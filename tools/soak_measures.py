"""The hour-long soak's measures and targets (issue 33 §2; docs/hardening.md, "Hours of
running"): pure functions of the samples tools/soak.py collects, so that
tests/window/soak_measures_test.py can judge series with known answers. Standard library only."""
import signal

# Targets (issue 33 §2). RSS may grow 1 % after warm-up: allocator pages settle for minutes.
RSS_GROWTH_MAX = 0.01
# "Rate unchanged": the median of the per-second rate in the last tenth no more than 1 % (10 Hz
# at 1 kHz) below the first tenth's; a loop slowed by a leak of work per tick shows well beyond
# that. A faster last tenth is no defect (a machine whose other load ended).
RATE_CHANGE_MAX = 0.01
# "p99 unchanged": the median per-second jitter p99 of the last tenth may exceed the first's by
# 50 % plus 100 us. The machine is shared: a build beside the soak moves p99 by that much, and a
# loop that degrades (work growing per tick) moves it by milliseconds.
JITTER_FACTOR, JITTER_SLACK_US = 1.5, 100.0
# RSS is compared as the median of the second tenth (warm) and of the last tenth (end): it swings
# by 5 % and more within minutes as the window draws (a panel opening a world: 270 -> 400 MiB and
# back), so two single samples cannot resolve 1 %; a leak moves the median of a tenth.
# No drift: the proxy at the same resting pointer after every loop, within 0.5 mm (the walks'
# drift tolerance: under a pixel of every shipped camera), judged as the median resting point of
# the last tenth's loops against the first tenth's. A single loop that ends away from it (a sample
# taken before the proxy settled at seconds per frame, a body resting against it, a missed press)
# is counted (`loops_off`) but is not drift: the next loops come back.
DRIFT_MAX_MM = 0.5
# A checkpoint's press is repeated at most this often (run_loop); a press that takes on none of
# the three tries is a defect of the window, not of the machine's load.
MAX_RETRIES = 2


def pct(values, q):
    if not values:
        return None
    v = sorted(values)
    return v[min(len(v) - 1, int(q * len(v)))]


def tenth_stats(frames):
    rates = [f["haptic_hz"] for f in frames if f.get("haptic_hz")]
    jit = [f["jitter_p99_us"] for f in frames if f.get("haptic_hz")]
    dt = [(b["t_s"] - a["t_s"]) * 1000.0 for a, b in zip(frames, frames[1:]) if b["scene"] == a["scene"]]
    return {"frames": len(frames), "rate_hz_p50": pct(rates, 0.5), "rate_hz_min": min(rates) if rates else None,
            "jitter_p99_us_p50": pct(jit, 0.5), "jitter_p99_us_max": max(jit) if jit else None,
            "frame_ms_p50": pct(dt, 0.5), "frame_ms_p99": pct(dt, 0.99)}


def median(values):
    v = sorted(values)
    return None if not v else (v[len(v) // 2] if len(v) % 2 else 0.5 * (v[len(v) // 2 - 1] + v[len(v) // 2]))


def rss_metrics(rss):
    """RSS after warm-up (median of the second tenth) and at the end (median of the last tenth);
    rss: (seconds from the start, MiB) samples."""
    if len(rss) < 10:
        return {}
    span = rss[-1][0]
    warm = median([m for t, m in rss if span / 10.0 < t <= span / 5.0])
    end = median([m for t, m in rss if t >= span * 0.9])
    if warm is None or end is None:
        return {}
    return {"rss_warm_mib": warm, "rss_end_mib": end, "rss_growth": (end - warm) / warm,
            "rss_range_mib": [min(m for t, m in rss if t > span / 10.0), max(m for t, m in rss if t > span / 10.0)]}


def drift_metrics(loops):
    """The median resting point of the last tenth's loops against the first tenth's (only loops
    that ended in the world's own scene), and the loops that ended over DRIFT_MAX_MM from the
    first tenth's."""
    home = [lp for lp in loops if lp["scene"] == (loops[0]["scene"] if loops else None)]
    if len(home) < 2:
        return {"drift_mm": None, "loops_off": 0}
    n = max(1, len(home) // 10)
    centre = lambda group: [median([lp["proxy_mm"][k] for lp in group]) for k in range(3)]  # noqa: E731
    first, last = centre(home[:n]), centre(home[-n:])
    dist = lambda a, b: sum((x - y) ** 2 for x, y in zip(a, b)) ** 0.5  # noqa: E731
    return {"drift_mm": dist(first, last), "loops_off": sum(dist(lp["proxy_mm"], first) > DRIFT_MAX_MM for lp in home),
            "largest_off_mm": max(dist(lp["proxy_mm"], first) for lp in home)}


def judge(r):
    bad = []
    if r["error"]:
        bad.append(r["error"])
    lost = [m for m in r.get("missed", []) if not m["recovered"]]
    if lost:
        bad.append(f"{len(lost)} press(es) did not take in {MAX_RETRIES + 1} tries (first at {lost[0]['t_s']} s, "
                   f"line {lost[0]['line']}: {lost[0]['seen']}, expected {lost[0]['expected']})")
    failed = r.get("returns_failed", [])
    if failed:
        bad.append(f"{len(failed)} of {r['return_checks']} return checks failed (first: {failed[0]})")
    if "rss_growth" not in r or "first" not in r or r["loops"] < 2:
        return bad + ["too short to judge (fewer than two loops or no RSS samples)"]
    if r["rss_growth"] > RSS_GROWTH_MAX:
        bad.append(f"RSS grew {100 * r['rss_growth']:.2f} % after warm-up (target <= {100 * RSS_GROWTH_MAX:.0f} %)")
    a, b = r["first"], r["last"]
    if a["rate_hz_p50"] and b["rate_hz_p50"] and b["rate_hz_p50"] < (1 - RATE_CHANGE_MAX) * a["rate_hz_p50"]:
        bad.append(f"haptic rate {a['rate_hz_p50']:.1f} -> {b['rate_hz_p50']:.1f} Hz")
    if a["jitter_p99_us_p50"] is not None and b["jitter_p99_us_p50"] is not None and \
            b["jitter_p99_us_p50"] > JITTER_FACTOR * a["jitter_p99_us_p50"] + JITTER_SLACK_US:
        bad.append(f"jitter p99 {a['jitter_p99_us_p50']:.0f} -> {b['jitter_p99_us_p50']:.0f} us")
    if r["drift_mm"] is not None and r["drift_mm"] > DRIFT_MAX_MM:
        bad.append(f"the proxy's resting point moved {r['drift_mm']:.2f} mm from the first tenth's loops to the last's")
    return bad


def exit_error(rc, ran_s, seconds, console):
    """None when the window ran its `seconds` and then closed cleanly (Escape, status 0); else
    what happened, with the console's last line (a crash must fail the world, not end its loops
    early and pass: glibc's "free(): corrupted ..." abort once did that)."""
    if rc == 0 and ran_s >= seconds:
        return None
    try:
        how = f"killed by {signal.Signals(-rc).name}" if rc < 0 else f"exit status {rc}"
    except ValueError:
        how = f"killed by signal {-rc}"
    when = f"after {ran_s:.0f} of {seconds:.0f} s" if ran_s < seconds else "when closed"
    last = (console.strip().splitlines() or [""])[-1][:200]
    return f"the window ended {when} ({how})" + (f": {last}" if last else "")
