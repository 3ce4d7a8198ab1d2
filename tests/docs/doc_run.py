"""Running one doc command for docs_test.py: bash from the copy's root, output in files (no pipe
to fill), a time limit, and what went wrong said with the last lines of its stderr. Standard
library only."""
import os
import signal
import subprocess
import time

TAIL_LINES = 15  # of stderr, in a failure's message
WINDOW_WAIT_S = 60.0  # for an Esc-closed command's window to show (a first frame on a loaded machine)
CLOSE_WAIT_S = 30.0  # for it to end after Esc
TITLE = "^pseudoshadow"  # every window's title (src/gl/context.h, the maze's and calibrate's own)


def call(argv):
    return subprocess.call(argv)


def tail(path, lines=TAIL_LINES):
    with open(path, encoding="utf-8", errors="replace") as f:
        text = [line for line in f.read().rstrip("\n").split("\n") if line]
    return "\n".join("    " + line for line in (text[-lines:] or ["(nothing on stderr)"]))


def start(script, root, env, logs):
    """bash -c script in its own process group (a timeout stops all it started)."""
    with open(logs + ".out", "w") as out, open(logs + ".err", "w") as err:
        return subprocess.Popen(["bash", "-c", script], cwd=root, env=env, stdin=subprocess.DEVNULL, stdout=out,
                                stderr=err, start_new_session=True)


def stop(proc):
    if proc.poll() is None:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.wait()


def ended(proc, logs, timeout_s):
    """None when the command ended with status 0 within timeout_s; else what happened."""
    try:
        rc = proc.wait(timeout=timeout_s)
    except subprocess.TimeoutExpired:
        stop(proc)
        return f"did not finish in {timeout_s:g} s; the last lines of its stderr:\n{tail(logs + '.err')}"
    return None if rc == 0 else f"exited with status {rc}; the last lines of its stderr:\n{tail(logs + '.err')}"


def window_id():
    found = subprocess.run(["xdotool", "search", "--onlyvisible", "--name", TITLE], capture_output=True, text=True)
    ids = found.stdout.split()
    return ids[-1] if ids else None


def run_closed_with_esc(proc, logs):
    """Waits for the window, gives it 1 s, taps Esc (again once, if the first was lost)."""
    end = time.monotonic() + WINDOW_WAIT_S
    wid = None
    while wid is None:
        if proc.poll() is not None:
            return ended(proc, logs, 0) or "ended before its window showed"
        if time.monotonic() > end:
            stop(proc)
            return f"no window after {WINDOW_WAIT_S:g} s; the last lines of its stderr:\n{tail(logs + '.err')}"
        time.sleep(0.2)
        wid = window_id()
    time.sleep(1.0)
    for _ in range(2):
        subprocess.run(["xdotool", "windowfocus", wid], capture_output=True)
        subprocess.run(["xdotool", "key", "Escape"], capture_output=True)
        try:
            proc.wait(timeout=CLOSE_WAIT_S)
            break
        except subprocess.TimeoutExpired:
            pass
    if proc.poll() is None:
        stop(proc)
        return f"did not close on Esc within {2 * CLOSE_WAIT_S:g} s"
    return ended(proc, logs, 0)


def run(script, root, env, step, timeout_s, logs):
    """Runs a step's script; None on success, else what went wrong."""
    proc = start(script, root, env, logs)
    try:
        return run_closed_with_esc(proc, logs) if step.action == "esc" else ended(proc, logs, timeout_s)
    finally:
        stop(proc)
