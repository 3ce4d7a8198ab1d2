#!/usr/bin/env python3
"""Hours of running (issue 33 §2): each world live in the real window under Xvfb, explored by a
scripted person for a chosen time, and what drifts or grows over that time.

    soak.py --exe build/pseudoshadow --minutes 60 --out soak_out scenes/default.toml ...

For each scene `run` opens at 1280x800 under its own Xvfb; xdotool sends real X pointer, wheel and
key events (the path of tests/window/walk.py), repeating one closed loop of steps (tools/soak/
<scene>.loop, else the loop its kind names, else default.loop; the walk format) until the time is
up. Every loop ends with the pointer resting at the window's centre, where the proxy is read.
Measured per world (docs/hardening.md, "Hours of running"):
  - RSS (VmRSS, every 5 s): after warm-up (the median of the second tenth) and at the end (the
    median of the last tenth);
  - the haptic loop's rate and per-second jitter p99 (from `--readouts-log`) in the first and
    the last tenth;
  - frame times (the time between the states two frames drew) in the first and the last tenth;
  - after each loop, the proxy at the resting pointer: where the last tenth's loops leave it (their
    median) against where the first tenth's do, and how many single loops ended away from that;
  - the window's end: a window that ends before its time (a crash), draws no frame for a whole
    loop (hung) or does not exit with status 0 when closed fails its world.
The measures and targets are tools/soak_measures.py.
Writes OUT/<scene>/{readouts.jsonl, rss.csv, result.json, soak.svg} and OUT/soak.md (one table).
Exit 0 when every world meets the targets, 1 when one misses, 2 bad input, 77 skipped (no
Xvfb or xdotool). Standard library only.
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import threading
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "tests", "window"))
import walk  # noqa: E402  (the window driver the window tests use)
import walk_checks  # noqa: E402
import window_proc  # noqa: E402
from soak_measures import MAX_RETRIES, drift_metrics, exit_error, judge, rss_metrics, tenth_stats  # noqa: E402

SKIP = 77
LOOP_KIND = {"flat_torus": "fourd", "flat_torus_rolling": "fourd", "roman": "fourd", "spun_trefoil": "fourd",
             "twist_spun_trefoil": "fourd"}


class Follow(walk.Window):
    """The walk's window, reading the readouts log incrementally (an hour is ~50 000 lines)."""

    def __init__(self, proc, log_path, console_path=None):
        super().__init__(proc, log_path, console_path)
        self._frames, self._pos, self._partial = [], 0, ""

    def frames(self):
        try:
            with open(self.log_path, encoding="utf-8") as f:
                f.seek(self._pos)
                chunk = f.read()
                self._pos = f.tell()
        except FileNotFoundError:
            return self._frames
        text = self._partial + chunk
        lines = text.split("\n")
        self._partial = lines.pop()  # an unfinished last line waits for its end
        self._frames += [json.loads(line) for line in lines if line]
        return self._frames


def rss_sampler(pid, out, stop):
    """Appends (monotonic s, RSS MiB) every 5 s until `stop` is set or the process is gone."""
    while not stop.wait(5.0):
        try:
            with open(f"/proc/{pid}/status", encoding="ascii") as f:
                kb = next(int(line.split()[1]) for line in f if line.startswith("VmRSS:"))
        except (OSError, StopIteration):
            return
        out.append((time.monotonic(), kb / 1024.0))


def loop_file(args, stem):
    if args.loop:
        return args.loop
    for name in (stem, LOOP_KIND.get(stem, ""), "default"):
        path = os.path.join(args.loop_dir, name + ".loop")
        if name and os.path.exists(path):
            return path
    raise FileNotFoundError(os.path.join(args.loop_dir, "default.loop"))


def soak_one(args, scene):
    scene_stem = os.path.splitext(os.path.basename(scene))[0]
    # A loop given by --loop names the soak (the tour's loop is a walk of the panel's scene).
    stem = os.path.splitext(os.path.basename(args.loop))[0] if args.loop else scene_stem
    out = os.path.join(args.out, stem)
    os.makedirs(out, exist_ok=True)
    log = os.path.join(out, "readouts.jsonl")
    if os.path.exists(log):
        os.remove(log)
    steps = walk.parse_walk(loop_file(args, scene_stem))
    seconds = args.minutes * 60.0
    cmd = [os.path.abspath(args.exe), "run", "--scene", os.path.abspath(scene), "--readouts-log", log, "--mute",
           "--quit-after", str(seconds + 120.0), *args.run_arg]
    if any(step["first_buttons"] for step in steps):  # the buttons' places, judged after the window closed
        cmd += ["--ui-report", os.path.join(out, "ui.json")]
    console = os.path.join(out, "console.txt")
    open(console, "w").close()  # this soak's output only (a retry's follows the first try's)
    win, rss, stop = Follow(None, log, console), [], threading.Event()
    loops, misses, error = [], [], None
    checks = {"count": 0, "failed": [], "buttons": []}  # the loop's return checks (run_loop)
    try:
        window_proc.open_window(win, lambda: window_proc.start_process(cmd, out, console), args.start_timeout)
        proc = win.proc
        threading.Thread(target=rss_sampler, args=(proc.pid, rss, stop), daemon=True).start()
        t_start = time.monotonic()
        while time.monotonic() - t_start < seconds:
            run_loop(win, steps, misses, t_start, checks)
            if proc.poll() is not None:
                break  # the window ended mid-loop: the loop did not close
            win.wait_frames_after(win.now_t())
            last = win.frames()[-1]
            if loops and last["t_s"] == loops[-1]["t_s"]:  # alive, but no frame for a whole loop
                raise RuntimeError(f"the window drew no frame during loop {len(loops) + 1} (hung)")
            loops.append({"t_s": last["t_s"], "scene": last["scene"], "proxy_mm": last["proxy_mm"],
                          "view_offset_mm": last["view_offset_mm"]})
            if args.progress:
                print(f"soak {stem}: loop {len(loops)}, {time.monotonic() - t_start:.0f} of {seconds:.0f} s, "
                      f"RSS {rss[-1][1] if rss else 0:.1f} MiB, {last['haptic_hz']:.0f} Hz", flush=True)
        ran_s = time.monotonic() - t_start
        if proc.poll() is None:
            win.xdo("key", "--delay", "0", "Escape")
            proc.wait(timeout=20)
        with open(console, encoding="utf-8", errors="replace") as f:
            error = exit_error(proc.returncode, ran_s, seconds, f.read())
    except (RuntimeError, subprocess.CalledProcessError, subprocess.TimeoutExpired) as e:
        error = str(e)
    finally:
        stop.set()
        if win.proc is not None and win.proc.poll() is None:
            win.proc.kill()
            win.proc.wait()
    if checks["buttons"] and os.path.exists(os.path.join(out, "ui.json")):
        checks["failed"] += walk_checks.check_panel(out, checks["buttons"], {})
    return summarize(stem, out, win.frames(), rss, loops, error, misses, checks)


def current_scene(win):
    win.wait_frames_after(win.now_t())
    frames = win.frames()
    return os.path.basename(frames[-1]["scene"]) if frames else None


# The checks a soak's loop keeps from the walk format: where the loop returns (home: the view
# at its start; near=PX: the shadow under the pointer; first_buttons: the buttons of the first
# frame at their places, judged from --ui-report after the window closed). The others (free,
# still, switches, ...) judge a single walk; an hour of them on a loaded machine says more about
# the machine (scene= is the press's checkpoint, run_loop).
RETURN_CHECKS = ("home", "near", "first_buttons")


def check_return(win, step, t0, t1, checks, t_start):
    """A step's return checks on its frames, into `checks`: the count, each failure with its time."""
    if not any(step[k] for k in RETURN_CHECKS):
        return
    kept = {k: v for k, v in step.items()}
    for k in ("free", "unburied", "sheets", "still", "panel_still", "valid"):
        kept[k] = False
    for k in ("expect", "scene", "switches", "fired", "dent_min", "dent_max", "edited"):
        kept[k] = None
    checks["count"] += 1
    win.wait_frames_after(t1)  # the state the step ended in
    when = round(time.monotonic() - t_start, 1)
    checks["failed"] += [f"at {when} s: {m}" for m in walk_checks.check_step(kept, walk.step_span(win, kept, t0, t1), {})]
    if step["first_buttons"]:
        checks["buttons"].append((kept, [f["frame"] for f in win.frames() if f["t_s"] > t1][:1]))


def run_loop(win, steps, misses, t_start, checks):
    """One pass of the loop. A step with `scene=NAME` (the wait after a button press or a
    Backspace) is a checkpoint: when the window shows another scene there, the press did not take
    (a tap lost on a loaded machine, a probe resting on a button's rim), and the loop would go on
    pressed into the wrong world. So the key step before it is repeated - after Home, which puts
    the hand back at its start height - up to MAX_RETRIES times. Every miss is recorded
    (result.json `missed`, with its retries and whether one took); one that never took fails the
    world, and the drift is measured only between loops that ended in the loop's own scene."""
    last_key = None
    for step in steps:
        t0 = win.now_t()
        win.run_step(step, shots=False)
        check_return(win, step, t0, win.now_t(), checks, t_start)
        if step["op"] == "key":
            last_key = step
        if step["scene"] is None or last_key is None:
            continue
        seen = current_scene(win)
        if seen == step["scene"]:
            continue
        miss = {"t_s": round(time.monotonic() - t_start, 1), "line": step["line"], "expected": step["scene"],
                "seen": seen, "retries": 0, "recovered": False}
        misses.append(miss)
        while miss["retries"] < MAX_RETRIES and not miss["recovered"]:
            # Home first: the view home and the hand back at its start height over the surface
            # under the pointer (docs/window.md), where the loop's height keys count from.
            win.run_step({"op": "key", "args": ["Home", "1", "0.05"]}, shots=False)
            time.sleep(0.5)
            win.run_step(last_key, shots=False)
            win.run_step(step, shots=False)
            miss["retries"] += 1
            miss["recovered"] = current_scene(win) == step["scene"]


def summarize(stem, out, frames, rss, loops, error, misses=(), checks=None):
    with open(os.path.join(out, "rss.csv"), "w", encoding="ascii") as f:
        f.write("t_s,rss_mib\n")
        for t, m in rss:
            f.write(f"{t - rss[0][0]:.1f},{m:.2f}\n")
    r = {"scene": stem, "error": error, "loops": len(loops), "frames": len(frames), "missed": list(misses)}
    if checks is not None and checks["count"]:
        r["return_checks"] = checks["count"] + len(checks["buttons"])
        r["returns_failed"] = checks["failed"]
    if frames:
        t0, t1 = frames[0]["t_s"], frames[-1]["t_s"]
        tenth = (t1 - t0) / 10.0
        r["minutes"] = (t1 - t0) / 60.0
        r["first"] = tenth_stats([f for f in frames if f["t_s"] <= t0 + tenth])
        r["last"] = tenth_stats([f for f in frames if f["t_s"] >= t1 - tenth])
    r.update(rss_metrics([(t - rss[0][0], m) for t, m in rss]))
    r["loop_scenes"] = sorted({lp["scene"] for lp in loops})
    r.update(drift_metrics(loops))
    r["failures"] = judge(r)
    with open(os.path.join(out, "result.json"), "w", encoding="utf-8") as f:
        json.dump({**r, "loop_ends": loops}, f, indent=1)
    write_svg(os.path.join(out, "soak.svg"), stem, rss, frames)
    return r


def write_svg(path, stem, rss, frames):
    """RSS and haptic rate over the run, one small picture a person can look at."""
    w, h, m = 640, 260, 40

    def poly(points, y_lo, y_hi, top, height, colour):
        if len(points) < 2:
            return ""
        x0, x1 = points[0][0], points[-1][0]
        span, yspan = max(x1 - x0, 1e-9), max(y_hi - y_lo, 1e-9)
        pts = " ".join(f"{m + (x - x0) / span * (w - 2 * m):.1f},{top + height - (y - y_lo) / yspan * height:.1f}"
                       for x, y in points)
        return f'<polyline fill="none" stroke="{colour}" stroke-width="1.2" points="{pts}"/>'

    rss_pts = [(t, v) for t, v in rss]
    rate_pts = [(f["t_s"], f["haptic_hz"]) for f in frames if f.get("haptic_hz")]
    lo = min((v for _, v in rss_pts), default=0.0)
    hi = max((v for _, v in rss_pts), default=1.0)
    body = [f'<text x="{m}" y="16" font-size="12">{stem}: RSS {lo:.1f}-{hi:.1f} MiB (blue), haptic rate 900-1100 Hz (red), over the run</text>',
            poly(rss_pts, lo - 0.5, hi + 0.5, 25, 100, "#1f5fbf"), poly(rate_pts, 900.0, 1100.0, 140, 100, "#bf1f1f")]
    with open(path, "w", encoding="utf-8") as f:
        f.write(f'<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}">'
                f'<rect width="{w}" height="{h}" fill="white"/>{"".join(body)}</svg>\n')


def fmt(v, spec):
    return "-" if v is None else format(v, spec)


def table(results):
    rows = ["| world | min | loops | RSS warm -> end MiB (growth) | rate Hz first / last | jitter p99 us first / last "
            "(median of seconds) | frame ms p50 first / last | drift mm (loops off / largest mm) | presses retried | result |",
            "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for r in results:
        a, b = r.get("first", {}), r.get("last", {})
        rows.append(f"| {r['scene']} | {fmt(r.get('minutes'), '.0f')} | {r['loops']} | "
                    f"{fmt(r.get('rss_warm_mib'), '.1f')} -> {fmt(r.get('rss_end_mib'), '.1f')} "
                    f"({fmt(100 * r['rss_growth'] if 'rss_growth' in r else None, '+.2f')} %) | "
                    f"{fmt(a.get('rate_hz_p50'), '.0f')} / {fmt(b.get('rate_hz_p50'), '.0f')} | "
                    f"{fmt(a.get('jitter_p99_us_p50'), '.0f')} / {fmt(b.get('jitter_p99_us_p50'), '.0f')} | "
                    f"{fmt(a.get('frame_ms_p50'), '.0f')} / {fmt(b.get('frame_ms_p50'), '.0f')} | "
                    f"{fmt(r.get('drift_mm'), '.2f')} ({r.get('loops_off', 0)} / {fmt(r.get('largest_off_mm'), '.2f')}) | "
                    f"{len(r.get('missed', []))} | {'pass' if not r['failures'] else '; '.join(r['failures'])} |")
    return "\n".join(rows) + "\n"


def write_table(out, scenes, loop=None):
    results = []
    for scene in scenes:
        stem = os.path.splitext(os.path.basename(loop or scene))[0]  # soak_one's name for it
        path = os.path.join(out, stem, "result.json")
        if os.path.exists(path):
            with open(path, encoding="utf-8") as f:
                r = json.load(f)
            # The measures and targets as this tool states them now, from the saved samples.
            rss_csv = os.path.join(os.path.dirname(path), "rss.csv")
            if os.path.exists(rss_csv):
                with open(rss_csv, encoding="ascii") as f:
                    r.update(rss_metrics([tuple(map(float, line.split(","))) for line in f.read().split()[1:]]))
            r.update(drift_metrics(r.get("loop_ends", [])))
            r["failures"] = judge(r)
            results.append(r)
    with open(os.path.join(out, "soak.md"), "w", encoding="utf-8") as f:
        f.write(table(results))
    print(table(results), end="")
    print(f"soak: table in {os.path.join(out, 'soak.md')}")
    return 1 if any(r["failures"] for r in results) else 0


def wait_for_display(timeout_s):
    """Returns once the X display accepts a connection: twelve soaks starting at once on two
    cores once had a window fail with "X11: Failed to open display" before its Xvfb served."""
    deadline = time.monotonic() + timeout_s
    while subprocess.call(["xdotool", "getdisplaygeometry"], stdout=subprocess.DEVNULL,
                          stderr=subprocess.DEVNULL) != 0:
        if time.monotonic() > deadline:
            raise SystemExit(f"soak.py: the display {os.environ.get('DISPLAY')} did not open in {timeout_s:g} s")
        time.sleep(0.5)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("scenes", nargs="+", help="scene files, one soak each")
    p.add_argument("--exe", default="build/pseudoshadow")
    p.add_argument("--minutes", type=float, default=60.0, help="time per world (default 60)")
    p.add_argument("--out", default="soak_out")
    p.add_argument("--loop-dir", default=os.path.join(HERE, "soak"))
    p.add_argument("--loop", help="this loop (the walk format) for every scene, naming the soak (soak.sh --tour)")
    p.add_argument("--start-timeout", type=float, default=60.0)
    p.add_argument("--progress", action="store_true", help="a line after every loop")
    p.add_argument("--run-arg", action="append", default=[], metavar="ARG",
                   help="one more argument for `pseudoshadow run` (repeatable; e.g. --run-arg=--spare-cpu --run-arg=off)")
    p.add_argument("--table", metavar="OUT", help="only write OUT/soak.md from the scenes' OUT/<scene>/result.json")
    p.add_argument("--inner", action="store_true", help=argparse.SUPPRESS)  # already under its X server
    args = p.parse_args()
    if args.table:
        return write_table(args.table, args.scenes, args.loop)
    for path in [args.exe, *args.scenes]:
        if not os.path.exists(path):
            print(f"soak.py: no such file: {path}", file=sys.stderr)
            return 2
    if not args.inner:
        return window_proc.under_xvfb(__file__, sys.argv[1:], "1280x800x24", "soak.py")
    os.makedirs(args.out, exist_ok=True)
    wait_for_display(args.start_timeout)
    results = []
    for scene in args.scenes:
        print(f"soak {scene}: {args.minutes:g} min ...", flush=True)
        results.append(soak_one(args, scene))
        print(table(results[-1:]).splitlines()[-1], flush=True)
    with open(os.path.join(args.out, "soak.md"), "w", encoding="utf-8") as f:
        f.write(table(results))
    print(f"soak: table in {os.path.join(args.out, 'soak.md')}")
    return 1 if any(r["failures"] for r in results) else 0


if __name__ == "__main__":
    sys.exit(main())
