#!/usr/bin/env python3
"""A new user's walk through the real `pseudoshadow run` window (issue 27; docs/testing.md).

Runs the window under Xvfb at 1280x800, sends real X pointer and key events with xdotool
(XTEST, the path a person's mouse takes), follows the window's `--readouts-log` while it goes,
and checks each step's frames (walk files: tests/window/walks/*.walk, format in default.walk).

    walk.py --exe build/pseudoshadow --scene scenes/default.toml --walk default.walk --out DIR

Exit 0 pass, 1 a check failed, 2 bad input, 77 skipped (no xvfb-run or xdotool). With the
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

SKIP = 77
# Penetration a hovering frame may show, mm: the frame's largest penetration is measured on the
# render mesh while the hand hovers 1 mm over the haptic geometry (the same triangles for meshes,
# tessellated analytic shapes otherwise: a sphere's 64-segment mesh lies up to ~0.2 mm inside
# the true sphere of the larger scenes), so 0.25 mm, a quarter of the hover height.
PENETRATION_TOL_MM = 0.25
# View drift allowed while the pointer rests, mm: a resting view does not move at all; 0.5 mm
# is under one pixel of every shipped scene's camera.
DRIFT_TOL_MM = 0.5
# Depth a hovering hand may graze a surface, mm: the mouse is read once a frame (4-30 frames a
# second on llvmpipe) and the hand's filter coasts between readings, on a straight line that cuts
# under a curved surface the pointer sweeps over; half the 1 mm hover height.
CONTACT_TOL_MM = 0.5
# The proxy's depth inside the haptic geometry, mm: the god-object keeps it out up to its contact
# epsilon (1e-3 mm); 0.05 mm leaves room for the float read-back of the log's 4 decimals.
BURIED_TOL_MM = 0.05
# Frames drawn this soon after a step starts still show the step before it (the window handles
# input once a frame): not counted as the step's.
SETTLE_S = 0.3
STATES = {"hovering", "touching", "out_of_reach"}


def fail_input(path, line_no, msg):
    print(f"{path}:{line_no}: {msg}", file=sys.stderr)
    sys.exit(2)


def parse_walk(path):
    steps = []
    with open(path, encoding="utf-8") as f:
        for n, raw in enumerate(f, 1):
            words = raw.split("#", 1)[0].split()
            if not words:
                continue
            op, args = words[0], words[1:]
            checks = {"free": False, "unburied": False, "sheets": False, "still": False, "expect": None,
                      "scene": None, "switches": None, "home": False,
                      "dent_min": None, "dent_max": None, "near": None, "panel_still": False, "valid": False, "edited": None}
            plain = []
            for w in args:
                if w in ("free", "unburied", "sheets", "still", "home", "panel_still", "valid"):
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


class Window:
    """The running window: its X id and geometry, and xdotool to drive it."""

    def __init__(self, proc, log_path):
        self.proc, self.log_path, self.keys_sent = proc, log_path, 0
        self.wid, self.x, self.y, self.w, self.h = None, 0, 0, 1, 1
        self.offset_s = 0.0  # wall clock (time.monotonic) minus the window's session time t_s
        self.stem, self.window_shots = "", 0  # WINDOW_SHOTS: the scene's name, dumps taken
        self.torn_reads = 0  # consecutive reads that stopped at an unreadable line (frames())

    def xdo(self, *args):
        subprocess.run(["xdotool", *args], check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)

    def wait_ready(self, timeout_s):
        end = time.monotonic() + timeout_s
        while time.monotonic() < end:
            if self.proc.poll() is not None:
                raise RuntimeError(f"the window exited early (status {self.proc.returncode})")
            found = subprocess.run(["xdotool", "search", "--pid", str(self.proc.pid)], capture_output=True, text=True)
            ids = found.stdout.split()
            if ids and len(self.frames()) >= 2:
                self.wid = ids[-1]
                geo = subprocess.run(["xdotool", "getwindowgeometry", "--shell", self.wid], capture_output=True,
                                     text=True).stdout
                g = dict(line.split("=", 1) for line in geo.split())
                self.x, self.y, self.w, self.h = int(g["X"]), int(g["Y"]), int(g["WIDTH"]), int(g["HEIGHT"])
                self.sync_clock()
                return
            time.sleep(0.1)
        raise RuntimeError(f"no window with two frames after {timeout_s} s")

    def sync_clock(self):
        """Session time <-> wall clock: a frame's line is written a little after the state it drew
        (the frame's own time), so over a second of frames the smallest wall - t_s is the offset."""
        best, end, seen = None, time.monotonic() + 1.0, 0
        while time.monotonic() < end or best is None:
            frames = self.frames()
            if len(frames) > seen:
                seen = len(frames)
                d = time.monotonic() - frames[-1]["t_s"]
                best = d if best is None else min(best, d)
            time.sleep(0.01)
        self.offset_s = best

    def now_t(self):
        return time.monotonic() - self.offset_s

    def wait_frames_after(self, t, count=2, timeout_s=15.0):
        """Waits until `count` frames drew states from session time t on (a slow scene's frames
        take a few hundred ms on llvmpipe)."""
        end = time.monotonic() + timeout_s
        while time.monotonic() < end:
            if sum(1 for f in self.frames() if f["t_s"] >= t) >= count or self.proc.poll() is not None:
                return
            time.sleep(0.05)

    def frames(self):
        try:
            with open(self.log_path, encoding="utf-8", errors="replace") as f:
                lines = f.read().split("\n")[:-1]  # complete lines only
        except FileNotFoundError:
            return []
        out = []
        for line in lines:
            try:
                out.append(json.loads(line))
            except json.JSONDecodeError:
                # Most likely a torn read, a line read while its write was still landing (seen once
                # in CI: a JSONDecodeError at the first character of a complete line, not
                # reproduced). Stop before it for now and read it again next time; a line that
                # stays unreadable for ~200 reads is an error.
                self.torn_reads += 1
                if self.torn_reads > 200:
                    raise RuntimeError(f"{self.log_path}: line {len(out) + 1} is not JSON: {line[:80]!r}")
                return out
        self.torn_reads = 0
        return out

    def at(self, fx, fy):
        return str(self.x + int(float(fx) * (self.w - 1))), str(self.y + int(float(fy) * (self.h - 1)))

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
                self.xdo("mousemove", *self.at(fx, fy))
                time.sleep(float(a[4]) / n)
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


def check_near(step, frame, where, report):
    """near=PX: on the step's last frame the pseudo-shadow's centre (shadow_px, the --ui-report
    measure) is within PX window pixels of the pointer (pointer_px)."""
    pointer, shadow = frame.get("pointer_px"), frame.get("shadow_px")
    if pointer is None or shadow is None:
        return [f"{where}: frame {frame['frame']} has no {'pointer' if pointer is None else 'shadow'} on screen"]
    d = ((pointer[0] - shadow[0]) ** 2 + (pointer[1] - shadow[1]) ** 2) ** 0.5
    report["max_pointer_shadow_px"] = max(report.get("max_pointer_shadow_px", 0.0), d)
    if d > step["near"]:
        return [f"{where}: the shadow's centre {shadow} is {d:.1f} px from the pointer {pointer} at frame "
                f"{frame['frame']} (at most {step['near']:g})"]
    return []


def check_step(step, frames, report):
    """The step's checks on its frames; returns failure messages."""
    where = f"walk line {step['line']} ({step['op']})"
    out = []
    if not frames:
        return [f"{where}: no frame drawn during the step"] if (step["free"] or step["still"] or step["expect"]) else []
    if step["free"] or step["unburied"] or step["sheets"]:
        for f in frames:
            key = "max_rest_penetration_mm" if step["still"] else "max_sweep_penetration_mm"
            if not f["contact"]:
                report[key] = max(report[key], f["penetration_mm"])
            report["max_hover_buried_mm"] = max(report["max_hover_buried_mm"], f["buried_mm"])
            if f["contact"]:
                report["max_hover_pressed_mm"] = max(report["max_hover_pressed_mm"], f["pressed_mm"])
            touching = step["free"] and f["contact"] and f["pressed_mm"] > CONTACT_TOL_MM
            # The drawn probe's penetration counts while the pointer rests and the proxy touches
            # nothing. It is measured per pixel along the renderer's reference normal, which
            # converges away from the pointer's plane after the start: a probe passing beside a steep
            # surface (materials_demo's ball) reads as up to ~27 mm inside it for a frame. The
            # proxy's own depth (buried_mm) counts on every frame.
            drawn_in = step["still"] and not f["contact"] and f["penetration_mm"] > PENETRATION_TOL_MM
            # A surface embedded in 4D is touched sheet by sheet: the proxy passes through the others
            # by design (docs/fourd.md), so its overlap with them is no burial.
            buried = not step["sheets"] and f["buried_mm"] > BURIED_TOL_MM
            if touching or drawn_in or buried:
                out.append(f"{where}: frame {f['frame']} buried or in contact while only the pointer moved: "
                           f"state {f['state']}, pressed {f['pressed_mm']} mm, penetration {f['penetration_mm']} mm, "
                           f"proxy buried {f['buried_mm']} mm, force {f['force_n']} N")
                break
    if step["still"]:
        rest = frames[len(frames) // 3:]  # the first third: the view settles after the last motion
        a, b = rest[0]["view_offset_mm"], rest[-1]["view_offset_mm"]
        drift = sum((x - y) ** 2 for x, y in zip(a, b)) ** 0.5
        report["max_rest_drift_mm"] = max(report["max_rest_drift_mm"], drift)
        if drift > DRIFT_TOL_MM:
            out.append(f"{where}: the view drifted {drift:.2f} mm while the pointer rested")
    if step["scene"] is not None and os.path.basename(frames[-1]["scene"]) != step["scene"]:
        out.append(f"{where}: scene {frames[-1]['scene']} at frame {frames[-1]['frame']}, expected {step['scene']}")
    if step["switches"] is not None:
        names = [f["scene"] for f in frames]
        switches = sum(1 for a, b in zip(names, names[1:]) if a != b)
        report["switches"] = report.get("switches", 0) + switches
        if switches and step["op"] == "key":  # key presses the window handled up to the switch
            first = next(i for i in range(1, len(names)) if names[i] != names[i - 1])
            report.setdefault("presses_to_switch", []).append(sum(f["keys"] for f in frames[1:first + 1]))
        if switches != step["switches"]:
            out.append(f"{where}: {switches} scene switches ({' -> '.join(dict.fromkeys(names))}), expected {step['switches']}")
    if step["home"]:
        off = sum(x * x for x in frames[-1]["view_offset_mm"]) ** 0.5
        if off > DRIFT_TOL_MM:
            out.append(f"{where}: the view is {off:.2f} mm from home at frame {frames[-1]['frame']}")
    if step["dent_min"] is not None:
        deepest = max((f.get("dent_mm") or 0.0) for f in frames)
        report["max_dent_mm"] = max(report.get("max_dent_mm", 0.0), deepest)
        if deepest < step["dent_min"]:
            out.append(f"{where}: the deepest dent was {deepest:.2f} mm, expected at least {step['dent_min']} mm")
    if step["dent_max"] is not None and (frames[-1].get("dent_mm") or 0.0) > step["dent_max"]:
        out.append(f"{where}: still dented {frames[-1]['dent_mm']:.2f} mm at frame {frames[-1]['frame']}, "
                   f"expected at most {step['dent_max']} mm")
    if step["near"] is not None:
        out += check_near(step, frames[-1], where, report)
    if step["expect"]:
        state = frames[-1]["state"].replace(" ", "_")
        if state not in step["expect"]:
            out.append(f"{where}: state {state} at frame {frames[-1]['frame']}, expected {'|'.join(sorted(step['expect']))}")
    return out


def check_panel(out_dir, still_steps, report):
    """After the window closed: the panel's rectangle (--ui-report, by frame) on every frame of
    each panel_still step is shown and the same - it does not jump away from the pointer."""
    if not still_steps:
        return []
    with open(os.path.join(out_dir, "ui.json"), encoding="utf-8") as f:
        ui = {fr["frame"]: fr for fr in json.load(f)["frames"]}
    out = []
    for step, frames in still_steps:
        rects = [ui[n]["panel"] for n in frames if n in ui]
        where = f"walk line {step['line']} ({step['op']})"
        report["panel_frames_checked"] = report.get("panel_frames_checked", 0) + len(rects)
        if not rects or any(r is None for r in rects):
            out.append(f"{where}: the panel is not shown on every frame of the step")
        elif len({tuple(r) for r in rects}) > 1:
            out.append(f"{where}: the panel moved while the pointer came to it: {rects[0]} -> "
                       f"{next(r for r in rects if r != rects[0])}")
    return out


def check_saves(out_dir, saves):
    """After the window closed: each checked `save` step's override file (the panel's edits as
    `run` saved them beside the screenshot) keeps every min <= max pair and holds the edited key."""
    out = []
    for step, index in saves:
        where = f"walk line {step['line']} (save)"
        path = os.path.join(out_dir, f"screenshot_{index:04d}.overrides.toml")
        if not os.path.exists(path):
            out.append(f"{where}: no {os.path.basename(path)}: the S tap saved nothing")
            continue
        values = {}
        with open(path, encoding="utf-8") as f:
            for line in f:
                if "=" in line and not line.lstrip().startswith("#"):
                    k, v = (x.strip() for x in line.split("=", 1))
                    values[k] = v
        if step["edited"] and not any(k.endswith(step["edited"]) for k in values):
            out.append(f"{where}: the panel's edit of {step['edited']} is not in {os.path.basename(path)}")
        for k, v in values.items():
            if step["valid"] and k.endswith("_min") and k[:-4] + "_max" in values:
                lo, hi = float(v), float(values[k[:-4] + "_max"])
                if lo > hi:
                    out.append(f"{where}: {k} = {lo} > {k[:-4]}_max = {hi}: the panel broke an invariant")
    return out


def win_scene_stem(args):
    return os.path.splitext(os.path.basename(args.scene))[0]


def walk(args):
    steps = parse_walk(args.walk)
    os.makedirs(args.out, exist_ok=True)
    log = os.path.join(args.out, "readouts.jsonl")
    for name in os.listdir(args.out):  # a rerun's files only
        if name in ("readouts.jsonl", "ui.json", "events.jsonl") or name.startswith("screenshot_"):
            os.remove(os.path.join(args.out, name))
    shots = os.environ.get("WINDOW_SHOTS", "")
    cmd = [os.path.abspath(args.exe), "run", "--scene", os.path.abspath(args.scene), "--readouts-log", log,
           "--ui-report", os.path.join(args.out, "ui.json"), "--events", os.path.join(args.out, "events.jsonl"),
           "--mute", "--quit-after", str(args.limit)]
    console = open(os.path.join(args.out, "console.txt"), "w")
    proc = subprocess.Popen(cmd, cwd=args.out, stdout=console, stderr=subprocess.STDOUT)
    win = Window(proc, log)
    walk_name = os.path.splitext(os.path.basename(args.walk))[0]
    win.stem = walk_name if walk_name not in ("default", win_scene_stem(args)) else win_scene_stem(args)
    report = {"max_rest_penetration_mm": 0.0, "max_sweep_penetration_mm": 0.0, "max_hover_pressed_mm": 0.0,
              "max_hover_buried_mm": 0.0, "max_rest_drift_mm": 0.0}
    failures, panel_steps, save_steps, saved = [], [], [], 0
    try:
        win.wait_ready(args.start_timeout)
        for step in steps:
            t0 = win.now_t()
            win.run_step(step, shots)
            t1 = win.now_t()
            win.wait_frames_after(t1)
            # A step's frames: the states drawn from its start (plus SETTLE_S: the keys or motion
            # before it are still being handled) to its end.
            span = [f for f in win.frames() if t0 + SETTLE_S <= f["t_s"] <= t1]
            if step["switches"] is not None:  # a switch the step causes may come before SETTLE_S, or after it
                span = [f for f in win.frames() if f["t_s"] < t0][-1:] + [f for f in win.frames() if t0 <= f["t_s"] <= t1]
                win.wait_frames_after(t1 + 1.0)
                span += [f for f in win.frames() if t1 < f["t_s"] <= t1 + 1.0]
            if (step["expect"] or step["scene"] or step["home"] or step["dent_max"] is not None or step["near"] is not None
                    or not span):  # the state the step ended in
                span += [f for f in win.frames() if f["t_s"] > t1][:1]
            failures += check_step(step, span, report)
            if step["panel_still"]:  # every frame from the step's start (a flick's are few) to the one after it
                during = [f for f in win.frames() if t0 <= f["t_s"] <= t1] + [f for f in win.frames() if f["t_s"] > t1][:1]
                panel_steps.append((step, [f["frame"] for f in during]))
            if step["op"] == "save" or (step["op"] == "shot" and shots):
                saved += 1
                if step["op"] == "save" and (step["valid"] or step["edited"]):
                    save_steps.append((step, saved - 1))
        win.wait_frames_after(win.now_t())  # every key sent handled before the count
        keys_counted = sum(f["keys"] for f in win.frames())
        win.xdo("key", "--delay", "0", "Escape")  # the closing tap: it must close the window
        try:
            rc = proc.wait(timeout=10)
            if rc != 0:
                failures.append(f"the window exited with status {rc} (console.txt)")
        except subprocess.TimeoutExpired:
            failures.append("the closing Esc tap was lost: the window is still open 10 s later")
    except (RuntimeError, subprocess.CalledProcessError) as e:
        failures.append(str(e))
        keys_counted = sum(f["keys"] for f in win.frames())
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
        console.close()
    if proc.returncode == 0:
        failures += check_panel(args.out, panel_steps, report) + check_saves(args.out, save_steps)
    if keys_counted != win.keys_sent:
        failures.append(f"taps counted {keys_counted} of {win.keys_sent} sent")
    if shots:
        os.makedirs(shots, exist_ok=True)
        stem = os.path.splitext(os.path.basename(args.scene))[0]
        for i, name in enumerate(sorted(n for n in os.listdir(args.out) if n.startswith("screenshot_") and n.endswith(".png"))):
            shutil.copy(os.path.join(args.out, name), os.path.join(shots, f"{stem}_{i:02d}.png"))
    frames = win.frames()
    print(f"walk {os.path.basename(args.scene)}: {len(frames)} frames; while hovering: proxy buried "
          f"{report['max_hover_buried_mm']:.2f} mm, grazing {report['max_hover_pressed_mm']:.2f} mm, drawn penetration "
          f"{report['max_rest_penetration_mm']:.2f} mm at rest ({report['max_sweep_penetration_mm']:.2f} sweeping); taps counted {keys_counted} of {win.keys_sent}, "
          f"view drift at rest {report['max_rest_drift_mm']:.2f} mm"
          + (f", deepest dent {report['max_dent_mm']:.2f} mm" if "max_dent_mm" in report else "")
          + (f", shadow at most {report['max_pointer_shadow_px']:.1f} px from the pointer at rest"
             if "max_pointer_shadow_px" in report else "")
          + (f", panel still on {report['panel_frames_checked']} frames" if "panel_frames_checked" in report else ""))
    for f in failures:
        print(f"FAIL {f}")
    with open(os.path.join(args.out, "report.json"), "w", encoding="utf-8") as f:  # tools/walk_strips.sh
        json.dump({"walk": win.stem, "scene": os.path.basename(args.scene), "frames": len(frames), **report,
                   "taps_counted": keys_counted, "taps_sent": win.keys_sent, "failures": failures}, f, indent=1)
    return 1 if failures else 0


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--exe", required=True)
    p.add_argument("--scene", required=True)
    p.add_argument("--walk", help="the walk file (default: WALK_DIR/<scene>.walk, else WALK_DIR/default.walk)")
    p.add_argument("--walk-dir", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "walks"))
    p.add_argument("--out", required=True)
    p.add_argument("--limit", type=float, default=90.0, help="the window quits after this many seconds regardless")
    p.add_argument("--start-timeout", type=float, default=60.0)
    p.add_argument("--inner", action="store_true", help=argparse.SUPPRESS)  # already under xvfb-run
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
    missing = [t for t in ("xvfb-run", "xdotool") if shutil.which(t) is None]
    if missing:
        print(f"walk.py: skipped, {' and '.join(missing)} not installed")
        return SKIP
    # One X server per walk, the size of the screen; the window opens at its top left.
    return subprocess.call(["xvfb-run", "-a", "-s", "-screen 0 1280x800x24", sys.executable, os.path.abspath(__file__),
                            "--inner", *sys.argv[1:]])


if __name__ == "__main__":
    sys.exit(main())
