"""The shell commands of the docs (README.md, docs/*.md), as docs_test.py runs them.

A command is a line of a fenced ```sh block, with its backslash continuations joined (bash
removes a backslash-newline, inside quotes too); comment-only and blank lines are none. A command
put in the background (a line ending in a single `&`) goes with the line after it, which waits
for it or stops it (`sleep 2.5; kill -9 $!`). A block of another kind whose first line is only
`# NAME.EXT` shows a file the commands read (`# session.txt`): docs_test.py writes it first.
Standard library only.
"""
import glob
import os
import re
import shlex
from dataclasses import dataclass

FENCE = "```"
FILE_BLOCK_HEAD = re.compile(r"^# ([\w./-]+\.\w+)$")


@dataclass
class Command:
    doc: str   # the doc file, relative to the source root: README.md, docs/maze.md
    line: int  # the line its first line is on
    text: str  # what bash runs

    @property
    def where(self):
        return f"{self.doc}:{self.line}"

    @property
    def key(self):
        """The command's words, comments dropped, one space apart: what the tables match."""
        return words_of(self.text)


def words_of(text):
    try:
        return " ".join(shlex.split(text, comments=True))
    except ValueError:  # an unbalanced quote: the text as it stands
        return " ".join(text.split())


def doc_files(source):
    """README.md and docs/*.md, relative to `source`, in a fixed order."""
    docs = sorted(os.path.relpath(p, source) for p in glob.glob(os.path.join(source, "docs", "*.md")))
    return ["README.md"] + docs


def blocks(lines):
    """(language, first content line number, content lines) of each fenced block."""
    out, i = [], 0
    while i < len(lines):
        head = lines[i].strip()
        if head.startswith(FENCE):
            j = i + 1
            while j < len(lines) and lines[j].strip() != FENCE:
                j += 1
            out.append((head[len(FENCE):].strip(), i + 2, lines[i + 1:j]))
            i = j
        i += 1
    return out


def commands_of_block(doc, first_line, body):
    out, pending = [], None  # pending: a Command still being continued or put in the background
    for n, raw in enumerate(body, first_line):
        if pending is None:
            if not raw.strip() or raw.lstrip().startswith("#"):
                continue
            pending, text = Command(doc, n, ""), raw
        else:
            text = pending.text + raw
        if text.endswith("\\"):  # continued on the next line
            pending.text = text[:-1]
            continue
        background = text.rstrip().endswith("&") and not text.rstrip().endswith("&&")
        pending.text = text + ("\n" if background else "")
        if not background:
            out.append(pending)
            pending = None
    if pending is not None:
        out.append(pending)
    return out


def extract(source, doc):
    """The commands of one doc file, and the files its blocks show ({name: text})."""
    with open(os.path.join(source, doc), encoding="utf-8") as f:
        lines = f.read().split("\n")
    commands, files = [], {}
    for lang, first, body in blocks(lines):
        if lang == "sh":
            commands += commands_of_block(doc, first, body)
        elif body and FILE_BLOCK_HEAD.match(body[0].strip()):
            files[FILE_BLOCK_HEAD.match(body[0].strip()).group(1)] = "\n".join(body[1:]) + "\n"
    return commands, files


def program_words(cmd):
    """The words after the pseudoshadow executable (its subcommand first), or None."""
    words = cmd.key.split()
    for i, w in enumerate(words):
        if w in ("pseudoshadow", "./build/pseudoshadow"):
            return words[i + 1:]
    return None
