"""What docs_test.py does with each doc command that it does not simply run: the tables.

Every entry is matched as a prefix of a command's words (doc_commands.Command.key); an entry that
matches no command fails the test (a stale entry hides nothing). Standard library only.
"""
from doc_commands import program_words

# The tests (ctest docs.<group>), each a set of doc files run in its own copy of the source tree,
# in the doc's order. `window` is the commands of every file that need a window (needs_window),
# with the ones that read what those wrote (WITH_WINDOW), under one Xvfb. A doc file with
# commands that no group names fails every group.
GROUPS = {
    "readme": ["README.md", "docs/api.md", "docs/testing.md", "docs/vibration.md", "docs/hardening.md"],
    "scenes": ["docs/fourd.md", "docs/universe.md", "docs/calibrate.md", "docs/web.md"],
    "studies": ["docs/maze.md", "docs/tuning.md", "docs/study.md"],
    "window": [],  # every file's window commands
}

# Not run, and why.
SKIPPED = {
    "bash tools/bootstrap.sh": "installs packages and builds build/: the build this test runs in (the command after && runs)",
    "ctest ": "the test suite itself, of which this test is one",
    "cmake --install build": "installs into the reader's prefix (api.install_consumer installs into a temporary one and builds against it)",
    "bash tools/sanitize.sh": "sanitizer builds of everything with fuzz runs: hours on 2 cores (CI runs it)",
    "PS_FUZZ_SECONDS=1800 bash tools/sanitize.sh": "the same with 30-minute fuzz runs",
    "cmake -S . -B build-asan": "a clang ASan + libFuzzer build of its own (tools/sanitize.sh makes it)",
    "cmake --build build-asan": "builds the ASan tree of the command before it",
    "LSAN_OPTIONS=suppressions=tests/fuzz/lsan.supp build-asan/": "a 30-minute fuzz run in the ASan build (tools/sanitize.sh runs it short)",
    "./build/pseudoshadow compare a.png b.png": "a.png and b.png stand for the reader's images (docs/testing.md's compare runs)",
    "./build/pseudoshadow bench$": "the whole sweep: 1.5 minutes on 2 cores even at 64x64 (app.bench_plot_only tests its plots)",
    "./build/pseudoshadow bench --first-image": "about 10 minutes on 2 cores (every scene's render and replay, three ways, three times)",
    "parallel --sshloginfile hosts.txt": "needs machines reachable over ssh (hosts.txt)",
    "./build/pseudoshadow tune $SWEEP --shard ${SLURM_ARRAY_TASK_ID}/32": "the body of a Slurm job file, run by sbatch",
    "jobid=$(sbatch": "needs a Slurm cluster",
    "sbatch --dependency": "needs a Slurm cluster",
    "pseudoshadow run --vibration-out sound:NAME": "NAME stands for the reader's OpenAL device",
    "sudo apt-get install emscripten": "installs a package (about 400 MB) that the suite does not use",
    "bash tools/web_core_probe.sh": "needs Emscripten, which the suite does not install (docs/web.md)",
    "npm ci --prefix web": "fetches puppeteer-core and pngjs from the npm registry; the suite installs nothing",
    "cmake --build build --target web_page": "needs Emscripten, which the suite does not install (browser.golden builds it where it is)",
    "python3 -m http.server -d build/web 8000": "a server that runs until it is stopped (browser.golden serves the page itself)",
}

SMALL_REPLAY = [("replay", "replay --size 128")]

# Run shorter: (text replaced, its replacement) pairs on the command, and why. The short form
# still goes through every step of the long one (same command, options and outputs).
SHORT = {
    "./build/pseudoshadow bench --texture-filter --size 256": ([("--size 256", "--size 64")], "64x64 (its reference 512x512)"),
    "./build/pseudoshadow bench-haptics": ([("bench-haptics", "bench-haptics --seconds 1")], "1 s, not 5"),
    # Replays at 128x128: the same frames, a quarter of the pixels or less.
    "./build/pseudoshadow replay --scene scenes/default.toml --log out/session.log": (SMALL_REPLAY, "128x128"),
    "./build/pseudoshadow replay --scene scenes/fourd/flat_torus_rolling.toml": (SMALL_REPLAY, "128x128"),
    "./build/pseudoshadow replay --log tests/haptics/data/stroke.traj": (SMALL_REPLAY, "128x128"),
    "pseudoshadow replay --scene scenes/fourd/": (SMALL_REPLAY, "128x128"),
    # One staircase of 2 reversals, not one per default reference of 16 (tests/cli's
    # calibrate_window.cmake runs two of 3).
    "xvfb-run -a ./build/pseudoshadow calibrate --curve speed --observer simulated --window": (
        [("--observer", "--references 20 --reversals 2 --average-last 2 --observer")], "one staircase of 2 reversals"),
}

# Window commands that wait for a person: opened under Xvfb, and once the window shows, closed
# with Esc (run: closes; calibrate: stops, keeping the trials; maze: quits at the instructions).
# Those listed here instead run a short form with nobody at the window, and why.
WINDOW_SHORT = {
    "./build/pseudoshadow calibrate --curve distance --out textures/my_intensity.lut": (
        [("--out", "--references 2 --reversals 2 --average-last 2 --observer simulated --window --out")],
        "the simulated observer answers in the window, one staircase of 2 reversals: the table the render after it reads"),
}

# Commands that need no window themselves but read what a window command wrote: they run with
# the window commands, after them, and why.
WITH_WINDOW = {
    "./build/pseudoshadow replay --scene scenes/default.toml --log out/session.log": "replays the `run` window's recording",
    "./build/pseudoshadow render --set materials.wood.intensity_lut=textures/my_intensity.lut": "reads the window calibration's table",
    "pseudoshadow maze summarize study/P01/session.jsonl study/P02/session.jsonl": "summarizes the two window sessions",
    "pseudoshadow maze plan --participants 12 --conditions on,off --out study/plan.csv": "the plan the window sessions read",
    "pseudoshadow maze script --plan study/plan.csv --participant P03": "reads that plan, beside the window sessions",
}

# Commands that read a file a later command of their doc writes: each runs right after that
# command (the doc shows the file's making later).
AFTER = {
    "./build/pseudoshadow render --scene scenes/table4_1_a.toml --overrides scenes/table4_1_a.overrides.toml":
        "./build/pseudoshadow tune --console",
}


def matches(entry, cmd):
    """An entry is a prefix of the command's words; one ending in `$` is all of them."""
    return cmd.key == entry[:-1] if entry.endswith("$") else cmd.key.startswith(entry)


def lookup(table, cmd):
    """The longest entry of `table` that matches the command, or None."""
    hits = [k for k in table if matches(k, cmd)]
    return max(hits, key=len) if hits else None


def needs_window(cmd):
    """None: headless. "xvfb": runs as written (it starts its own X server). "esc": opens a
    window and waits for a person (run; calibrate without --observer; maze with the mouse;
    study run or resume without --simulate)."""
    if cmd.key.startswith("xvfb-run"):
        return "xvfb"
    words = program_words(cmd)
    if not words:
        return None
    sub, rest = words[0], words[1:]
    if sub == "run":
        return "esc"
    if sub == "calibrate" and "--observer" not in rest:
        return "esc"
    if sub == "study" and rest and rest[0] in ("run", "resume") and "--simulate" not in rest:
        return "esc"
    if sub == "maze" and not (rest and rest[0] in ("script", "plan", "summarize")) and \
            not any(w.startswith("--device") or w == "--resume" for w in rest):
        return "esc"
    return None
