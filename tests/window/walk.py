#!/usr/bin/env python3
"""A new user's walk through the real `pseudoshadow run` window (issue 27; docs/testing.md).

Runs the window under Xvfb at 1280x800, sends real X pointer and key events with xdotool
(XTEST, the path a person's mouse takes), follows the window's `--readouts-log` while it goes,
and checks each step's frames (walk files: tests/window/walks/*.walk, format in default.walk).

    walk.py --exe build/pseudoshadow --scene scenes/default.toml --walk default.walk --out DIR

Exit 0 pass, 1 a check failed, 2 bad input, 77 skipped (no Xvfb or xdotool). With the
environment variable WINDOW_SHOTS=FOLDER, every `shot` step saves the window's own screenshot
(S) there as <scene>_NN.png and, where xwd (x11-apps) is installed, the window as the person sees
it (overlays included) as <walk>_win_NN.png; OUT/report.json has the walk's numbers
(tools/walk_strips.sh makes both into docs/window_walks.md). Standard library only.
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import window_proc  # noqa: E402  (the window's process: started, followed, why it ended)
from walk_checks import (check_fired, check_panel, check_saves, check_step, check_switch_frames, new_report,  # noqa: E402
                         read_events)

SKIP = 77
# Frames drawn this soon after a step starts still show the step before it (the window handles
# input once a frame): not counted as the step's.
SETTLE_S = 0.3
SWEEP_POINT_WAIT_S = 3.0  # longest wait for the window to read one point of a sweep (a stall of 2.5 s was seen under load)
STATES = {"hovering", "touching", "out_of_reach"}


def fail_input(path, line_no, msg):
    print(f"{path}:{line_no}: {msg}", file=sys.stderr)
    sys.exit(2)


def include_walk(path, n, words, scene):
    """`include FILE [optional]`: FILE's steps here ({scene}: the scene's name, e.g. the scene's own
    pointing walk, walks/pointing/); `optional`: nothing where FILE does not exist."""
    if len(words) not in (2, 3) or words[2:] not in ([], ["optional"]):
        fail_input(path, n, "include takes a file and optionally the word 'optional'")
    rel = words[1].replace("{scene}", scene)
    target = os.path.join(os.path.dirname(os.path.abspath(path)), rel)
    if not os.path.exists(target):
        if words[2:] == ["optional"]:
            return []
        fail_input(path, n, f"include: {target} does not exist")
    steps = parse_walk(target, scene)
    for st in steps:
        st["line"] = f"{rel}:{st['line']}"
    return steps


def parse_walk(path, scene=""):
    steps = []
    with open(path, encoding="utf-8") as f:
        for n, raw in enumerate(f, 1):
            words = raw.split("#", 1)[0].split()
            if not words:
                continue
            if words[0] == "include":
                steps += include_walk(path, n, words, scene)
                continue
            op, args = words[0], words[1:]
            checks = {"free": False, "unburied": False, "sheets": False, "still": False, "expect": None,
                      "scene": None, "switches": None, "fired": None, "home": False,
                      "dent_min": None, "dent_max": None, "near": None, "panel_still": False, "valid": False, "edited": None,
                      "first_buttons": False}
            plain = []
            for w in args:
                if w in ("free", "unburied", "sheets", "still", "home", "panel_still", "valid", "first_buttons"):
                    checks[w] = True
                elif w.startswith("scene="):
                    checks["scene"] = w[len("scene="):]
                elif w.startswith("edited="):
                    checks["edited"] = w[len("edited="):]
                elif w.startswith("dent_min=") or w.startswith("dent_max="):
                    checks[w[:8]] = float(w[9:])
                elif w.startswith("near="):
                    checks["near"] = float(w[len("near="):])
                elif w.startswith("switches="):
                    checks["switches"] = int(w[len("switches="):])
                elif w.startswith("fired="):
                    checks["fired"] = int(w[len("fired="):])
                elif w.startswith("expect="):
                    want = set(w[len("expect="):].split("|"))
                    if not want <= STATES:
                        fail_input(path, n, f"unknown state in '{w}' (hovering, touching, out_of_reach)")
                    checks["expect"] = want
                else:
                    plain.append(w)
            arity = {"move": (2, 2), "sweep": (5, 5), "drag": (5, 5), "save": (0, 0), "wait": (1, 1), "key": (1, 3), "hold": (2, 2),
                     "scroll": (2, 2), "shot": (0, 0)}
            if op not in arity:
                fail_input(path, n, f"unknown step '{op}' ({', '.join(arity)})")
            lo, hi = arity[op]
            if not lo <= len(plain) <= hi:
                fail_input(path, n, f"'{op}' takes {lo}..{hi} values, got {len(plain)}")
            if op == "scroll" and plain[0] not in ("up", "down"):
                fail_input(path, n, "scroll takes up or down")
            steps.append({"line": n, "op": op, "args": plain, **checks})
    return steps


class Window(window_proc.Window):
    """The running window (window_proc.py) and the walk's steps sent to it."""

    def run_step(self, step, shots):
        op, a = step["op"], step["args"]
        if op == "move":
            self.xdo("mousemove", *self.at(a[0], a[1]))
        elif op in ("sweep", "drag"):
            if op == "drag":  # the left button held from the first point to the last
                self.xdo("mousemove", *self.at(a[0], a[1]))
                time.sleep(0.1)
                self.xdo("mousedown", "1")
            n = max(2, int(float(a[4]) / 0.03))
            for i in range(n + 1):
                t = i / n
                fx = float(a[0]) + t * (float(a[2]) - float(a[0]))
                fy = float(a[1]) + t * (float(a[3]) - float(a[1]))
                moved_at = self.line_count()
                self.xdo("mousemove", *self.at(fx, fy))
                time.sleep(float(a[4]) / n)
                # Every point of the sweep is read by the window: a frame logs it as its pointer,
                # or, failing that, two frames passed (the frame drawing when the pointer moved
                # may have read it before the move, the next one reads it after). Under load
                # (70 ms frames) a sweep timed by the wall clock alone left points unread: the
                # window saw a few readings 25 mm apart, not the path walked.
                self.wait_point_read(moved_at, self.px(fx, fy), SWEEP_POINT_WAIT_S)
            if op == "drag":
                time.sleep(0.1)
                self.xdo("mouseup", "1")
        elif op == "wait":
            time.sleep(float(a[0]))
        elif op == "key":
            count, gap = int(a[1]) if len(a) > 1 else 1, float(a[2]) if len(a) > 2 else 0.05
            for _ in range(count):
                self.xdo("key", "--delay", "0", a[0])  # press and release at once: the shortest tap
                self.keys_sent += 1
                time.sleep(gap)
        elif op == "hold":
            self.xdo("keydown", a[0])
            time.sleep(float(a[1]) / 1000.0)
            self.xdo("keyup", a[0])
            self.keys_sent += 1  # one press; the repeats are no new presses
        elif op == "scroll":
            for _ in range(int(a[1])):
                self.xdo("click", "4" if a[0] == "up" else "5")
                time.sleep(0.03)
        elif op == "save":  # S: screenshot_NNNN.png and its .overrides.toml in the walk's folder
            self.xdo("key", "--delay", "0", "s")
            self.keys_sent += 1
            time.sleep(0.5)
        elif op == "shot" and shots:
            self.xdo("key", "--delay", "0", "s")
            self.keys_sent += 1
            time.sleep(0.5)
            self.dump_window(shots)

    def dump_window(self, folder):
        """With xwd (x11-apps): the window as the person sees it, overlays included, as
        <folder>/<scene>_win_NN.png (tools/xwd_png.py crops the root window's dump)."""
        if shutil.which("xwd") is None:
            return
        self.window_shots += 1
        name = os.path.join(folder, f"{self.stem}_win_{self.window_shots - 1:02d}")
        os.makedirs(folder, exist_ok=True)
        with open(name + ".xwd", "wb") as f:
            subprocess.run(["xwd", "-root", "-silent"], stdout=f, check=True)
        xwd_png = tools_module("xwd_png")
        xwd_png.write_png(xwd_png.xwd_rows(name + ".xwd", self.x, self.y, self.w, self.h), self.w, self.h, name + ".png")
        os.remove(name + ".xwd")


def tools_module(name):
    """A module of the repository's tools/ folder, imported once (only where screenshots are
    asked for: the walks themselves need the standard library only)."""
    if name not in sys.modules:
        tools = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools")
        if tools not in sys.path:
            sys.path.insert(0, tools)
    return __import__(name)


def win_scene_stem(args):
    return os.path.splitext(os.path.basename(args.scene))[0]


def keys_handled_at(win, step, t0, t1):
    """When the window had handled a key step's taps (the t_s of the frame that handled its last
    one; frames of 1-2 s under load handle several at once), at least t1; t1 for other steps."""
    if step["op"] != "key":
        return t1
    taps = int(step["args"][1]) if len(step["args"]) > 1 else 1
    end = time.monotonic() + 15.0
    while time.monotonic() < end:
        handled = 0
        for f in win.frames():
            handled += f["keys"] if f["t_s"] >= t0 else 0
            if handled >= taps:
                return max(t1, f["t_s"])
        if win.proc.poll() is not None:
            break
        time.sleep(0.05)
    return t1


def step_span(win, step, t0, t1):
    """A step's frames: the states drawn from its start (plus SETTLE_S: the keys or motion before
    it are still being handled) to its end."""
    span = [f for f in win.frames() if t0 + SETTLE_S <= f["t_s"] <= t1]
    if step["switches"] is not None:  # a switch the step causes may come before SETTLE_S, or after it
        span = [f for f in win.frames() if f["t_s"] < t0][-1:] + [f for f in win.frames() if t0 <= f["t_s"] <= t1]
        end = keys_handled_at(win, step, t0, t1) + 1.0
        win.wait_frames_after(end)
        after = [f for f in win.frames() if f["t_s"] > t1]
        within = [f for f in after if f["t_s"] <= end]
        # and the frame begun within that second: a switch's frame loads the new world (1-3 s under
        # load) and draws the state of the tick that adopted it, so its time is the load's end.
        span += within + after[len(within):len(within) + 1]
    if (step["expect"] or step["scene"] or step["home"] or step["dent_max"] is not None or step["near"] is not None
            or not span):  # the state the step ended in
        span += [f for f in win.frames() if f["t_s"] > t1][:1]
    return span


def nominal_s(step):
    """How long a step takes by the walk file's own numbers (the sleeps walk.py does), before any
    wait for the window's frames."""
    op, a = step["op"], step["args"]
    if op in ("wait", "sweep", "drag"):
        return float(a[0] if op == "wait" else a[4]) + (0.2 if op == "drag" else 0.0)
    if op == "key":
        return (int(a[1]) if len(a) > 1 else 1) * (float(a[2]) if len(a) > 2 else 0.05)
    if op == "hold":
        return float(a[1]) / 1000.0
    if op == "scroll":
        return int(a[1]) * 0.03
    return 0.5 if op == "save" else 0.0


def add_time(report, op, took_s, nominal):
    """report["time_s"]: per step kind, the wall time it took and its nominal time (nominal_s),
    so a slow walk shows whether its steps waited on frames or its checks took the time."""
    t = report.setdefault("time_s", {}).setdefault(op, [0.0, 0.0])
    t[0] += took_s
    t[1] += nominal


def walk_steps(win, steps, shots, report, failures, panel_steps, save_steps, fired_steps):
    """Runs the steps with their checks: adds to the failures, and to the panel_still, checked
    save and fired= steps, judged after the window closed (what a step that raised left is kept)."""
    saved = 0
    for step in steps:
        started = time.monotonic()
        if win.proc.poll() is not None:  # one failure that says why, not one per step left
            raise RuntimeError(f"the window ended (status {win.proc.returncode}) before walk line {step['line']}, "
                               f"{win.now_t():.0f} s into the session; it quits by itself after --limit "
                               f"{win.limit_s:g} s")
        t0 = win.now_t()
        win.run_step(step, shots)
        t1 = win.now_t()
        stepped = time.monotonic()
        add_time(report, step["op"], stepped - started, nominal_s(step))
        win.wait_frames_after(t1)
        failures.extend(check_step(step, step_span(win, step, t0, t1), report))
        add_time(report, "checks", time.monotonic() - stepped, 0.0)
        if step["fired"] is not None:
            fired_steps.append((step, t0, t1))
        if step["panel_still"]:  # every frame from the step's start (a flick's are few) to the one after it
            during = [f for f in win.frames() if t0 <= f["t_s"] <= t1] + [f for f in win.frames() if f["t_s"] > t1][:1]
            panel_steps.append((step, [f["frame"] for f in during]))
        if step["first_buttons"]:  # the frame after the step, against the first frame
            panel_steps.append((step, [f["frame"] for f in win.frames() if f["t_s"] > t1][:1]))
        if step["op"] == "save" or (step["op"] == "shot" and shots):
            saved += 1
            if step["op"] == "save" and (step["valid"] or step["edited"]):
                save_steps.append((step, saved - 1))


def close_window(win):
    """The closing Esc tap: it must close the window, with status 0."""
    win.xdo("key", "--delay", "0", "Escape")
    try:
        rc = win.proc.wait(timeout=10)
    except subprocess.TimeoutExpired:
        return ["the closing Esc tap was lost: the window is still open 10 s later"]
    if rc != 0:
        return [f"the window exited with status {rc}; the last lines of {win.console_path}:\n"
                f"{window_proc.console_tail(win.console_path)}"]
    return []


def drive(args, win, cmd, steps, report):
    """Opens the window, walks, closes it; returns (failures, panel steps, save steps, fired= steps,
    taps counted)."""
    failures, panel_steps, save_steps, fired_steps = [], [], [], []
    shots = os.environ.get("WINDOW_SHOTS", "")
    try:
        started = time.monotonic()
        window_proc.open_window(win, lambda: window_proc.start_process(cmd, args.out, win.console_path),
                                args.start_timeout)
        add_time(report, "start", time.monotonic() - started, 0.0)
        walk_steps(win, steps, shots, report, failures, panel_steps, save_steps, fired_steps)
        win.wait_frames_after(win.now_t())  # every key sent handled before the count
        keys_counted = sum(f["keys"] for f in win.frames())
        failures.extend(close_window(win))
    except (RuntimeError, subprocess.CalledProcessError) as e:
        failures.append(str(e))
        if not isinstance(e, window_proc.EarlyExit) and win.proc is not None and win.proc.poll() is not None:
            failures.append(f"the window had ended (status {win.proc.returncode}); the last lines of "
                            f"{win.console_path}:\n{window_proc.console_tail(win.console_path)}")
        keys_counted = sum(f["keys"] for f in win.frames())
    finally:
        if win.proc is not None and win.proc.poll() is None:
            win.proc.kill()
            win.proc.wait()
    return failures, panel_steps, save_steps, fired_steps, keys_counted


def copy_shots(args, shots):
    os.makedirs(shots, exist_ok=True)
    stem = os.path.splitext(os.path.basename(args.scene))[0]
    for i, name in enumerate(sorted(n for n in os.listdir(args.out) if n.startswith("screenshot_") and n.endswith(".png"))):
        shutil.copy(os.path.join(args.out, name), os.path.join(shots, f"{stem}_{i:02d}.png"))


def print_report(args, win, report, keys_counted, failures):
    frames = win.frames()
    print(f"walk {os.path.basename(args.scene)}: {len(frames)} frames; while hovering: proxy buried "
          f"{report['max_hover_buried_mm']:.2f} mm, grazing {report['max_hover_pressed_mm']:.2f} mm, drawn penetration "
          f"{report['max_rest_penetration_mm']:.2f} mm at rest ({report['max_sweep_penetration_mm']:.2f} sweeping); taps counted {keys_counted} of {win.keys_sent}, "
          f"view drift at rest {report['max_rest_drift_mm']:.2f} mm"
          + (f", deepest dent {report['max_dent_mm']:.2f} mm" if "max_dent_mm" in report else "")
          + (f", shadow at most {report['max_pointer_shadow_px']:.1f} px from the pointer at rest"
             if "max_pointer_shadow_px" in report else "")
          + (f", panel still on {report['panel_frames_checked']} frames" if "panel_frames_checked" in report else ""))
    if "time_s" in report:  # where the walk's time went: steps against their nominal time
        print("time: " + ", ".join(f"{op} {t[0]:.1f} s" + (f" (nominal {t[1]:.1f})" if t[1] else "")
                                   for op, t in sorted(report["time_s"].items(), key=lambda kv: -kv[1][0])))
    for f in failures:
        print(f"FAIL {f}")
    with open(os.path.join(args.out, "report.json"), "w", encoding="utf-8") as f:  # tools/walk_strips.sh
        json.dump({"walk": win.stem, "scene": os.path.basename(args.scene), "frames": len(frames), **report,
                   "taps_counted": keys_counted, "taps_sent": win.keys_sent, "failures": failures}, f, indent=1)


def walk(args):
    steps = parse_walk(args.walk, win_scene_stem(args))
    os.makedirs(args.out, exist_ok=True)
    log = os.path.join(args.out, "readouts.jsonl")
    for name in os.listdir(args.out):  # a rerun's files only
        if name in ("readouts.jsonl", "ui.json", "events.jsonl") or name.startswith("screenshot_"):
            os.remove(os.path.join(args.out, name))
    cmd = [os.path.abspath(args.exe), "run", "--scene", os.path.abspath(args.scene), "--readouts-log", log,
           "--ui-report", os.path.join(args.out, "ui.json"), "--events", os.path.join(args.out, "events.jsonl"),
           "--mute", "--quit-after", str(args.limit)] + args.run_arg
    console = os.path.join(args.out, "console.txt")
    open(console, "w").close()  # this run's output only (a retry's follows the first try's)
    win = Window(None, log, console)
    win.limit_s = args.limit
    walk_name = os.path.splitext(os.path.basename(args.walk))[0]
    win.stem = walk_name if walk_name not in ("default", win_scene_stem(args)) else win_scene_stem(args)
    report = new_report()
    failures, panel_steps, save_steps, fired_steps, keys_counted = drive(args, win, cmd, steps, report)
    if win.proc is not None and win.proc.returncode == 0:
        failures += check_panel(args.out, panel_steps, report) + check_saves(args.out, save_steps)
        events = read_events(args.out)
        failures += check_fired(events, fired_steps, report) + check_switch_frames(win.frames(), events, report)
    if keys_counted != win.keys_sent:
        failures.append(f"taps counted {keys_counted} of {win.keys_sent} sent")
    if os.environ.get("WINDOW_SHOTS", ""):
        copy_shots(args, os.environ["WINDOW_SHOTS"])
    print_report(args, win, report, keys_counted, failures)
    return 1 if failures else 0


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--exe", required=True)
    p.add_argument("--scene", required=True)
    p.add_argument("--walk", help="the walk file (default: WALK_DIR/<scene>.walk, else WALK_DIR/default.walk)")
    p.add_argument("--walk-dir", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "walks"))
    p.add_argument("--out", required=True)
    # 400 s: a walk's steps wait for frames, and a heavy scene's frames take 120-400 ms on 2 cores
    # with llvmpipe (Table 4.1 b: 410 ms), so its walk takes about 100 s alone and two to three
    # times that on a machine that is busy with other work. The limit only ends a walk that hangs
    # (ctest's TIMEOUT is above it); a walk that finishes sooner ends sooner.
    p.add_argument("--limit", type=float, default=400.0, help="the window quits after this many seconds regardless")
    p.add_argument("--start-timeout", type=float, default=60.0)
    # A slow machine on demand: `--run-arg=--max-fps --run-arg=8` draws 8 frames a second, so the
    # mouse is read 8 times a second, as on a loaded 2-core machine drawing a heavy scene.
    p.add_argument("--run-arg", action="append", default=[], help="one more argument for `run` (repeat it)")
    p.add_argument("--inner", action="store_true", help=argparse.SUPPRESS)  # already under its X server
    args = p.parse_args()
    if not args.walk:
        own = os.path.join(args.walk_dir, os.path.splitext(os.path.basename(args.scene))[0] + ".walk")
        args.walk = own if os.path.exists(own) else os.path.join(args.walk_dir, "default.walk")
    for path in (args.exe, args.scene, args.walk):
        if not os.path.exists(path):
            print(f"walk.py: no such file: {path}", file=sys.stderr)
            return 2
    if args.inner:
        return walk(args)
    # One X server per walk, the size of the screen; the window opens at its top left.
    return window_proc.under_xvfb(__file__, sys.argv[1:], "1280x800x24", "walk.py")


if __name__ == "__main__":
    sys.exit(main())
