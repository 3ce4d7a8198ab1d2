"""The window under test as a process (tests/window/walk.py, tools/soak.py): started with its
output in a console file, driven with xdotool, followed through its `--readouts-log`, and, when
it ends before its first frames, a failure that says why (the console's last lines).

A window that could not open its display is started once more after 1 s: on a busy machine an
X server can refuse a connection for a moment (a server resetting as its last client leaves),
and that is the machine's, not the program's, fault.
Standard library only.
"""
import json
import os
import re
import shutil
import subprocess
import sys
import time

# The lines the program prints when GLFW cannot open the display or create the window
# (src/gl/context_glfw.cpp: "glfwInit failed: X11: Failed to open display :99").
DISPLAY_FAILURE = re.compile(r"glfwInit failed|glfwCreateWindow\([^)]*\) failed|Failed to open display")
TAIL_LINES = 20  # of the console, in a failure's message
RETRY_WAIT_S = 1.0
SKIP = 77  # ctest's skip status


# The tests' X server wrapper: `xvfb-run -a`'s interface, the display number chosen by Xvfb
# itself, so any number of windows can start at once (tests/support/xvfb_run.sh).
XVFB_RUN = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support", "xvfb_run.sh")


def under_xvfb(script, argv, screen, who, call=subprocess.call):
    """Runs `python3 script --inner argv` under its own X server (XVFB_RUN, SCREEN as "WxHxD")
    and returns its status; SKIP, with a line saying why, where Xvfb or xdotool is not
    installed. -noreset: an X server regenerates when its last client leaves, and a connection
    made meanwhile fails ("X11: Failed to open display"): before a window connects, each
    `xdotool search` poll is that last client."""
    missing = [t for t in ("Xvfb", "xdotool") if shutil.which(t) is None]
    if missing:
        print(f"{who}: skipped, {' and '.join(missing)} not installed")
        return SKIP
    return call(["bash", XVFB_RUN, "-s", f"-screen 0 {screen} -noreset", sys.executable, os.path.abspath(script),
                 "--inner", *argv])


def console_tail(path, lines=TAIL_LINES):
    """The last `lines` lines of a console file, indented for a failure message."""
    try:
        with open(path, encoding="utf-8", errors="replace") as f:
            text = f.read().rstrip("\n").split("\n")
    except FileNotFoundError:
        return "    (no console file)"
    shown = [line for line in text[-lines:] if line] or ["(nothing printed)"]
    return "\n".join("    " + line for line in shown)


class EarlyExit(RuntimeError):
    """The window ended before it drew its first frames."""

    def __init__(self, status, console_path):
        self.status, self.tail = status, console_tail(console_path)
        self.display_failure = bool(DISPLAY_FAILURE.search(self.tail))
        super().__init__(f"the window exited early (status {status}); the last lines of {console_path}:\n{self.tail}")


def start_process(cmd, cwd, console_path):
    """Starts `cmd` with stdout and stderr appended to console_path (a file, so a chatty program
    never blocks on a full pipe; a retry's output follows the first try's)."""
    with open(console_path, "a", encoding="utf-8") as console:
        return subprocess.Popen(cmd, cwd=cwd, stdout=console, stderr=subprocess.STDOUT)


POINTER_PX = re.compile(rb'"pointer_px": ?\[(-?\d+), ?(-?\d+)\]')


class Window:
    """The running window: its X id and geometry, and xdotool to drive it."""

    def __init__(self, proc, log_path, console_path=None):
        self.proc, self.log_path, self.console_path, self.keys_sent = proc, log_path, console_path, 0
        self.wid, self.x, self.y, self.w, self.h = None, 0, 0, 1, 1
        self.offset_s = 0.0  # wall clock (time.monotonic) minus the window's session time t_s
        self.stem, self.window_shots = "", 0  # WINDOW_SHOTS: the scene's name, dumps taken
        self.torn_reads = 0  # consecutive reads that stopped at an unreadable line (frames())
        self.lines_read, self.lines_seen = 0, 0  # line_count(): bytes of the log counted, lines in them
        self.pointers, self.partial = [], b""  # line_count(): each counted line's pointer_px; a torn tail

    def xdo(self, *args):
        subprocess.run(["xdotool", *args], check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)

    def wait_ready(self, timeout_s):
        end = time.monotonic() + timeout_s
        while time.monotonic() < end:
            if self.proc.poll() is not None:
                raise EarlyExit(self.proc.returncode, self.console_path)
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

    def line_count(self):
        """Frames logged so far, counted from where the last call stopped (cheap enough to call
        between two pointer moves, unlike frames(), which parses the whole log)."""
        try:
            with open(self.log_path, "rb") as f:
                f.seek(self.lines_read)
                more = f.read()
        except FileNotFoundError:
            return 0
        self.lines_read += len(more)
        self.lines_seen += more.count(b"\n")
        *lines, self.partial = (self.partial + more).split(b"\n")
        for line in lines:  # only the pointer: a regular expression, not a whole JSON parse
            m = POINTER_PX.search(line)
            self.pointers.append((int(m.group(1)), int(m.group(2))) if m else None)
        return self.lines_seen

    def wait_point_read(self, moved_at, px, timeout_s):
        """Waits until the window has read the pointer at window pixel `px` (x, y): a frame logged
        after line `moved_at` has it as its pointer_px, or two frames were logged after that line
        (the second began after the move), or the window ended, or timeout_s passed. The frame
        drawing when the pointer moved often reads the new place already, so this is about one
        frame instead of two."""
        end = time.monotonic() + timeout_s
        while time.monotonic() < end and self.proc.poll() is None:
            count = self.line_count()
            if count >= moved_at + 2 or px in self.pointers[moved_at:]:
                return
            time.sleep(0.005)

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

    def px(self, fx, fy):
        """The window pixel at fractions (fx, fy) of the window: what its readouts call pointer_px."""
        return int(float(fx) * (self.w - 1)), int(float(fy) * (self.h - 1))

    def at(self, fx, fy):
        """The same place on the screen, as xdotool's arguments."""
        x, y = self.px(fx, fy)
        return str(self.x + x), str(self.y + y)


def open_window(win, start, timeout_s):
    """Starts the window (`start()` returns its Popen) into `win` and waits for its first frames.
    One that ended before them having failed to open its display is started again, once, after
    RETRY_WAIT_S (said on stdout); any other early end raises EarlyExit with the console's tail."""
    win.proc = start()
    try:
        win.wait_ready(timeout_s)
    except EarlyExit as e:
        if not e.display_failure or win.frames():
            raise
        first = next(line.strip() for line in e.tail.split("\n") if DISPLAY_FAILURE.search(line))
        print(f"the window could not open its display ({first}); starting it again in {RETRY_WAIT_S:g} s", flush=True)
        time.sleep(RETRY_WAIT_S)
        win.proc = start()
        win.wait_ready(timeout_s)
