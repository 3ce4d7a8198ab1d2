"""Every file the docs name exists (README.md and docs/*.md).

A reference is a path that starts at the repository's top (`src/app/...`, `tests/...`,
`scenes/...`, `glsl/...`, ...) or a source file in a room of src/ (`measure/texture_aliasing.h`
means src/measure/texture_aliasing.h; `study/P01`, a command's output folder in docs/maze.md, is
the reader's, not the `study` room's). `{h,cpp}` expands to each file and `*` is a glob. Placeholders
in recipes (NAME, ROOM, X) and the files a command writes (listed in WRITTEN with the reason)
are not files of the repository. Usage: file_refs_test.py REPO_ROOT
"""
import glob
import os
import re
import sys

# Names in recipes and examples that stand for the reader's own file.
PLACEHOLDER = re.compile(r"NAME|ROOM|_X\.|/x\.|/my_")
# Files that a documented command writes, named as its output (not shipped).
WRITTEN = {
    "scenes/table4_1_a.overrides.toml": "written by the live panel's Save overrides (docs/tuning.md)",
}
TOP = ["src", "tests", "glsl", "scenes", "textures", "tools", "python", "examples", "golden_images",
       "docs", "cmake", "include", r"\.ci"]


def expand(ref):
    """`a/{b,c}.h` -> [a/b.h, a/c.h]; `a.toml,b.toml` -> both."""
    m = re.search(r"\{([^{}]*)\}", ref)
    if m:
        return [x for alt in m.group(1).split(",") for x in expand(ref[:m.start()] + alt + ref[m.end():])]
    return [part for part in ref.split(",") if part]


def exists(root, rooms, path):
    candidates = [path]
    if path.split("/")[0] in rooms:
        candidates.append("src/" + path)
    for c in candidates:
        full = os.path.join(root, c)
        if glob.glob(full) if "*" in c else os.path.exists(full):
            return True
    return False


def missing_refs(root):
    rooms = sorted(d for d in os.listdir(os.path.join(root, "src")) if os.path.isdir(os.path.join(root, "src", d)))
    pattern = re.compile(r"(?<![\w/.-])((?:" + "|".join(TOP + rooms) + r")/[\w./{},*+-]*[\w*}])")
    docs = [os.path.join(root, "README.md")] + sorted(glob.glob(os.path.join(root, "docs", "*.md")))
    top = {t.replace("\\", "") for t in TOP}
    checked, missing = 0, []
    for doc in docs:
        with open(doc, encoding="utf-8") as f:
            for n, line in enumerate(f, 1):
                for m in pattern.finditer(line):
                    for path in expand(m.group(1)):
                        if PLACEHOLDER.search(path) or path in WRITTEN:
                            continue
                        if path.split("/")[0] not in top and not path.endswith((".h", ".cpp")):
                            continue  # starts with a room's name but names no source file
                        checked += 1
                        if not exists(root, rooms, path):
                            missing.append(f"{os.path.relpath(doc, root)}:{n}: {path}")
    return checked, missing


def main():
    root = sys.argv[1]
    checked, missing = missing_refs(root)
    print(f"{checked} file references checked in README.md and docs/*.md; skipped: placeholders "
          f"({PLACEHOLDER.pattern}) and written files: " + "; ".join(f"{k} ({v})" for k, v in WRITTEN.items()))
    if checked < 200:
        print(f"only {checked} references found: the pattern no longer matches the docs")
        return 1
    for m in missing:
        print(f"{m}: no such file (moved or renamed? fix the doc)")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
