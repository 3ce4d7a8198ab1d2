"""Which doc commands a docs_test.py group runs, how, and in which order (the tables:
doc_table.py). Standard library only."""
import re
import shlex
from dataclasses import dataclass

import doc_commands
from doc_commands import Command, program_words
from doc_table import AFTER, GROUPS, SHORT, SKIPPED, WINDOW_SHORT, WITH_WINDOW, lookup, matches, needs_window

ASSIGNMENT = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*=")
TABLES = {"SKIPPED": SKIPPED, "SHORT": SHORT, "WINDOW_SHORT": WINDOW_SHORT, "WITH_WINDOW": WITH_WINDOW,
          "AFTER": AFTER}


@dataclass
class Step:
    cmd: Command
    action: str      # run, short, esc (opened under Xvfb and closed with Esc), skip, set (a VAR=... line),
                     # same (a repeat of an earlier command: not run again)
    text: str        # what bash runs
    why: str = ""    # a skip's or a short form's reason
    window: bool = False  # it runs in group `window`


def replaced(text, pairs):
    for old, new in pairs:
        text = text.replace(old, new, 1)
    return text


def is_assignment(cmd):
    try:
        return bool(ASSIGNMENT.match(cmd.text.strip())) and len(shlex.split(cmd.text, comments=True)) == 1
    except ValueError:
        return False


def step_of(cmd):
    skip = lookup(SKIPPED, cmd)
    window = needs_window(cmd)
    with_window = bool(window) or lookup(WITH_WINDOW, cmd) is not None
    if skip is not None:
        return Step(cmd, "skip", cmd.text, SKIPPED[skip], with_window)
    if is_assignment(cmd):
        return Step(cmd, "set", cmd.text)
    table = WINDOW_SHORT if window == "esc" else SHORT
    short = lookup(table, cmd)
    if short is not None and table[short][1]:
        pairs, why = table[short]
        return Step(cmd, "short", replaced(cmd.text, pairs), why, with_window)
    if window == "esc":
        return Step(cmd, "esc", cmd.text, "opened under Xvfb, closed with Esc once its window shows", True)
    why = WITH_WINDOW.get(lookup(WITH_WINDOW, cmd), "") if with_window and not window else ""
    return Step(cmd, "run", cmd.text, why, with_window)


def steps_of(cmd):
    """A command whose first part (before &&) is skipped runs its second part on its own."""
    first, sep, rest = cmd.text.partition(" && ")
    head = Command(cmd.doc, cmd.line, first)
    if sep and "&&" in cmd.key.split() and lookup(SKIPPED, head) is not None:  # not an && in a comment
        return [step_of(head)] + steps_of(Command(cmd.doc, cmd.line, rest))
    return [step_of(cmd)]


def ordered(steps):
    """AFTER: a step that reads what a later one writes moves to right after it."""
    out = list(steps)
    for step in steps:
        after = lookup(AFTER, step.cmd)
        if after is None:
            continue
        maker = next((s for s in out if s.cmd.key.startswith(AFTER[after])), None)
        if maker is not None:
            out.remove(step)
            out.insert(out.index(maker) + 1, step)
    return out


def stale_entries(all_cmds):
    out = []
    for name, table in TABLES.items():
        for prefix in table:
            if not any(matches(prefix, c) for c in all_cmds):
                out.append(f"doc_table.py {name}: '{prefix}' matches no doc command; remove it or fix it")
    for prefix in AFTER.values():
        if not any(c.key.startswith(prefix) for c in all_cmds):
            out.append(f"doc_table.py AFTER: '{prefix}' matches no doc command")
    return out


def everywhere(step):
    """A `VAR=...` line, or a `mkdir` of a folder that later commands write into: run by every
    group that runs commands of its doc."""
    return step.action == "set" or step.cmd.key.startswith("mkdir ")


def group_of(doc, step):
    return "window" if step.window else next((g for g, docs in GROUPS.items() if doc in docs), None)


def same_key(cmd):
    return cmd.key.replace("./build/pseudoshadow", "pseudoshadow")


def mark_repeats(doc, steps, seen):
    """A command that an earlier doc (or line) has word for word runs once, where it comes first
    (the README's and a doc's own copy): the repeat says where that is."""
    for step in steps:
        if step.action in ("skip", "set") or program_words(step.cmd) is None or everywhere(step):
            continue  # only the program's commands: a shell command may make what a later one needs
        first = seen.setdefault(same_key(step.cmd), (step.cmd.where, group_of(doc, step)))
        if first[0] != step.cmd.where:
            step.action, step.why = "same", f"the same command as {first[0]}, run by docs.{first[1]}"


def plan(source, group):
    """[(doc, steps, files)] of `group`, and the problems that stop the test: a doc file with
    commands in no group, a table entry that matches no command."""
    grouped = {doc for docs in GROUPS.values() for doc in docs}
    out, problems, all_cmds, seen = [], [], [], {}
    for doc in doc_commands.doc_files(source):
        cmds, files = doc_commands.extract(source, doc)
        if cmds and doc not in grouped:
            problems.append(f"{doc} has shell commands but no group: add it to GROUPS in tests/docs/doc_table.py")
        steps = ordered([s for c in cmds for s in steps_of(c)])
        all_cmds += [s.cmd for s in steps]
        mark_repeats(doc, steps, seen)
        mine = [s for s in steps if everywhere(s) or
                (s.window if group == "window" else doc in GROUPS[group] and not s.window)]
        if any(not everywhere(s) for s in mine):
            out.append((doc, mine, files))
    return out, problems + stale_entries(all_cmds)


def print_plan(plan_):
    for doc, steps, _ in plan_:
        print(f"== {doc}")
        for s in steps:
            shown = s.cmd.key if s.action in ("skip", "same") else doc_commands.words_of(s.text)
            print(f"{s.action.upper():5} {s.cmd.where}  {shown}" + (f"\n      ({s.why})" if s.why else ""))
