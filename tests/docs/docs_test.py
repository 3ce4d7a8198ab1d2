#!/usr/bin/env python3
"""Docs that run (issue 46 §2): every shell command of README.md and docs/*.md, run.

    docs_test.py --exe PSEUDOSHADOW --build BUILD --python PYTHON3 --work DIR --group NAME [--list]

Each doc file's commands run in order in DIR/<doc>/, a copy of the source tree (so outputs, under
out/ or wherever the doc writes them, land in the copy; out/ exists, as after the README's first
command; `build` links to BUILD), from its root as the README implies. `./build/pseudoshadow` is
the built binary; `pseudoshadow` and `python3` on PATH are it and the Python the module is built
for. A plain `VAR=...` line is set for the doc's later commands. What runs short, what is skipped
and which commands run with the window are tables (doc_table.py), each entry with its reason; the
test prints every command it ran or skipped. A command that fails (a non-zero exit, or longer
than its time) fails the test, named by doc file and line with the last lines of its stderr; its
doc's copy is kept (those of docs that passed are removed), and every command's output is in
DIR/logs/. Group `window` runs itself under its own Xvfb. Exit 0 pass, 1 a command failed, 2 bad
input or a stale table, 77 skipped (group `window` without Xvfb or xdotool). Standard
library only.
"""
import argparse
import os
import shlex
import shutil
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "window"))
import doc_commands  # noqa: E402
import window_proc  # noqa: E402
import doc_plan  # noqa: E402
import doc_run  # noqa: E402

SKIP = 77
SHIPPED = ("glsl", "scenes", "textures")  # the data the binary finds beside it (top-level CMakeLists.txt)


def link_tree(src, dst):
    """dst: src's folders, each file a link to src's: a scene there reads its textures as the
    shipped data (outside a scene's folder, a scene may read only that), and a file a command
    writes there is the copy's (outputs are written beside and renamed over, never through a link)."""
    for folder, _, names in os.walk(src):
        into = os.path.join(dst, os.path.relpath(folder, src))
        os.makedirs(into, exist_ok=True)
        for n in names:
            os.symlink(os.path.join(folder, n), os.path.join(into, n))


def prepare_root(args, doc, files):
    """DIR/<doc>/: the source tree copied (its shipped data linked), an empty out/, `build` linking
    to BUILD, bin/ with pseudoshadow and python3, the files the doc shows written."""
    root = os.path.join(args.work, doc.replace("/", "_").replace(".md", ""))
    shutil.rmtree(root, ignore_errors=True)
    os.makedirs(root)
    for name in sorted(os.listdir(args.source)):
        src, dst = os.path.join(args.source, name), os.path.join(root, name)
        if name.startswith((".", "build")) or name == "out" or os.path.exists(os.path.join(src, "CMakeCache.txt")):
            continue  # git's, a build tree (this test's work folder is in one), the reader's outputs
        if name in SHIPPED:
            link_tree(src, dst)
        elif os.path.isdir(src):
            shutil.copytree(src, dst, symlinks=True)
        else:
            shutil.copy2(src, dst)
    os.makedirs(os.path.join(root, "out"))  # as after the README's first command
    os.symlink(os.path.abspath(args.build), os.path.join(root, "build"))
    os.makedirs(os.path.join(root, "bin"))
    os.symlink(os.path.abspath(args.exe), os.path.join(root, "bin", "pseudoshadow"))
    os.symlink(args.python, os.path.join(root, "bin", "python3"))
    for name, text in files.items():
        with open(os.path.join(root, name), "w", encoding="utf-8") as f:
            f.write(text)
    return root


def run_doc(args, doc, steps, files):
    """Runs one doc file's planned steps; returns failure messages."""
    root = prepare_root(args, doc, files)
    env = dict(os.environ, PATH=os.path.join(root, "bin") + os.pathsep + os.environ.get("PATH", ""))
    os.makedirs(os.path.join(args.work, "logs"), exist_ok=True)
    prelude, failures = "", []
    for step in steps:
        if step.action in ("skip", "same"):
            print(f"{step.action.upper():5} {step.cmd.where}  {step.cmd.key}\n      ({step.why})", flush=True)
            continue
        if step.action == "set":
            prelude += step.text + "\n"
            print(f"SET   {step.cmd.where}  {step.cmd.key}", flush=True)
            continue
        text = step.text.replace("./build/pseudoshadow", shlex.quote(os.path.abspath(args.exe)))
        t0 = time.monotonic()
        logs = os.path.join(args.work, "logs", f"{os.path.basename(root)}_{step.cmd.line}")
        error = doc_run.run(prelude + text, root, env, step, args.timeout, logs)
        label = {"run": "RUN", "short": "SHORT", "esc": "ESC"}[step.action]
        print(f"{label:5} {step.cmd.where}  {doc_commands.words_of(step.text)}  ({time.monotonic() - t0:.1f} s)"
              + (f"\n      ({step.why})" if step.why else ""), flush=True)
        if error:
            failures.append(f"{step.cmd.where}: `{step.cmd.key}` {error}")
            print(f"FAIL  {failures[-1]}", flush=True)
    if not failures:  # a failed doc's copy stays for a look (its frames and tables: megabytes)
        shutil.rmtree(root, ignore_errors=True)
    return failures


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--exe", required=True)
    p.add_argument("--build", required=True, help="the build tree (`build` in the commands)")
    p.add_argument("--python", default=shutil.which("python3") or "/usr/bin/python3",
                   help="the python3 the module is built for")
    p.add_argument("--source", default=os.path.normpath(os.path.join(HERE, "..", "..")))
    p.add_argument("--work", required=True, help="the folder the copies are made in (emptied first)")
    p.add_argument("--group", required=True, choices=sorted(doc_plan.GROUPS))
    p.add_argument("--timeout", type=float, default=180.0, help="seconds a command may take")
    p.add_argument("--list", action="store_true", help="print the plan, run nothing")
    p.add_argument("--inner", action="store_true", help=argparse.SUPPRESS)  # already under its X server
    args = p.parse_args()
    plan, problems = doc_plan.plan(args.source, args.group)
    if problems:
        print("\n".join(f"docs_test: {m}" for m in problems), file=sys.stderr)
        return 2
    if args.list:
        doc_plan.print_plan(plan)
        return 0
    if args.group == "window" and not args.inner:
        return window_proc.under_xvfb(__file__, sys.argv[1:], "1280x1024x24", "docs_test", call=doc_run.call)
    os.makedirs(args.work, exist_ok=True)
    t0, failures = time.monotonic(), []
    for doc, steps, files in plan:
        print(f"== {doc}", flush=True)
        failures += run_doc(args, doc, steps, files)
    ran = sum(1 for _, steps, _ in plan for s in steps if s.action in ("run", "short", "esc"))
    print(f"docs_test {args.group}: {ran} commands run, {len(failures)} failed, in {time.monotonic() - t0:.0f} s")
    for f in failures:
        print(f"FAIL {f}", file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
