#!/usr/bin/env python3
"""docs.layers: the layer table of docs/architecture.md is the include graph of src/, and tests/
mirrors src/ as docs/testing.md says.

    layers_test.py REPO_ROOT

The table lists the rooms of src/ from the bottom of the house up: "each room includes only rooms
above it in this table". This reads the table's order and every `#include "ROOM/..."` in
src/ROOM, and fails naming each include that points at a room lower in the table (or at a room
the table does not list), with its file and line. A second check keeps the table whole: every
folder of src/ is a row.
"""
import os
import re
import sys


def table_rooms(architecture_md):
    """The rooms in the layer table's order: its rows' `src/ROOM` directories, and the public
    headers a row names beside its room (`include/NAME/`, as {NAME: ROOM})."""
    rooms, public = [], {}
    in_table = False
    with open(architecture_md, encoding="utf-8") as f:
        for line in f:
            if line.startswith("| layer | directory |"):
                in_table = True
                continue
            if in_table:
                if not line.startswith("|"):
                    break
                m = re.match(r"\|\s*([a-z0-9_]+)\s*\|\s*`src/([a-z0-9_]+)`", line)
                if m:
                    rooms.append(m.group(2))
                    for name in re.findall(r"`include/([a-z0-9_]+)/`", line):
                        public[name] = m.group(2)
    return rooms, public


def include_arrows(src, room):
    """(file, line number, included room) for each quoted include in src/room."""
    for dirpath, _, files in os.walk(os.path.join(src, room)):
        for name in sorted(files):
            if not name.endswith((".h", ".cpp")):
                continue
            path = os.path.join(dirpath, name)
            with open(path, encoding="utf-8") as f:
                for n, line in enumerate(f, 1):
                    m = re.match(r'\s*#include "([a-z0-9_]+)/', line)
                    if m:
                        yield os.path.relpath(path, os.path.dirname(src)), n, m.group(1)


def mirror_problems(root, rooms):
    """Every room of src/ has tests/ROOM or is named in docs/testing.md's "Where a room's tests
    are." paragraph; every folder of tests/ is a room or named there."""
    with open(os.path.join(root, "docs", "testing.md"), encoding="utf-8") as f:
        text = f.read()
    start = text.find("**Where a room's tests are.**")
    if start < 0:
        return ["docs/testing.md has no \"Where a room's tests are.\" paragraph"]
    named = set(re.findall(r"`([a-z0-9_]+)`", text[start:text.find("\n\n", start)]))
    tests = os.path.join(root, "tests")
    folders = {d for d in os.listdir(tests) if os.path.isdir(os.path.join(tests, d))}
    out = [f"src/{r}/ has no tests/{r}/ and docs/testing.md does not say where its tests are"
           for r in rooms if r not in folders and r not in named]
    out += [f"tests/{d}/ is no room of src/ and docs/testing.md does not name it"
            for d in sorted(folders) if d not in rooms and d not in named]
    return out


def main():
    root = sys.argv[1]
    src = os.path.join(root, "src")
    rooms, public = table_rooms(os.path.join(root, "docs", "architecture.md"))
    if len(rooms) < 5:
        sys.exit(f"docs.layers: the layer table of docs/architecture.md was not found ({rooms})")
    rank = {r: i for i, r in enumerate(rooms)}
    folders = sorted(d for d in os.listdir(src) if os.path.isdir(os.path.join(src, d)))
    problems = [f"src/{d}/ is not a row of the layer table" for d in folders if d not in rank]
    arrows = 0
    for room in rooms:
        for path, line, target in include_arrows(src, room):
            arrows += 1
            target = public.get(target, target)
            if target not in rank:
                problems.append(f"{path}:{line}: includes {target}/, which the layer table does not list")
            elif rank[target] > rank[room]:
                problems.append(f"{path}:{line}: {room} includes {target}/, a room below it in the layer table")
    problems += mirror_problems(root, rooms)
    for p in problems:
        print(p)
    print(f"docs.layers: {len(rooms)} rooms, {arrows} includes checked, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
