#!/usr/bin/python3
"""diff_lines.py [OLD NEW ...]: how far one tutorial step is from another,
measured in code lines.

Each file is reduced to its code lines: comments (// to the end of the
line, /* ... */ blocks) and blank lines are removed, and leading and
trailing blanks of every line are kept as they are except at the end.
The two reductions are compared with `diff` (GNU diffutils), and the
program prints the code lines of both, the lines of OLD that diff removes
and the lines of NEW that it adds. Removed + added is the distance the
tutorial's "a chain" rule measures (issue 73).

It also prints, for NEW, the comment share: the lines whose first
non-blank characters are // or that lie inside a /* */ block, over all
non-blank lines.

Without arguments it compares the consecutive steps of this directory
that exist (step-1 -> step-2, step-2 -> step-3, ...) and step-1 with every
later step. Run it from anywhere:

    tutorial/diff_lines.py
    tutorial/diff_lines.py tutorial/step-1/step-1.cc tutorial/step-2/step-2.cc
"""
import os
import re
import subprocess
import sys
import tempfile


def code_lines(path):
    """The lines of PATH without comments and blank lines."""
    text = open(path, encoding="utf-8").read()
    out, i, n = [], 0, len(text)
    in_string = None
    while i < n:
        c = text[i]
        if in_string:
            out.append(c)
            if c == "\\" and i + 1 < n:
                out.append(text[i + 1])
                i += 2
                continue
            if c == in_string:
                in_string = None
            i += 1
        elif text.startswith("//", i):
            j = text.find("\n", i)
            i = n if j < 0 else j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            # keep the line breaks of the block, so that lines stay lines
            block = text[i:n if j < 0 else j + 2]
            out.append("\n" * block.count("\n"))
            i = n if j < 0 else j + 2
        else:
            if c in "\"'":
                in_string = c
            out.append(c)
            i += 1
    lines = [l.rstrip() for l in "".join(out).split("\n")]
    return [l for l in lines if l.strip()]


def comment_share(path):
    """(comment lines, non-blank lines) of PATH."""
    comment = total = 0
    in_block = False
    for line in open(path, encoding="utf-8"):
        s = line.strip()
        if not s:
            continue
        total += 1
        if in_block:
            comment += 1
            if "*/" in s:
                in_block = False
        elif s.startswith("//"):
            comment += 1
        elif s.startswith("/*"):
            comment += 1
            in_block = "*/" not in s[2:]
    return comment, total


def distance(old, new):
    """(code lines of old, of new, removed, added)."""
    a, b = code_lines(old), code_lines(new)
    with tempfile.TemporaryDirectory() as tmp:
        pa, pb = os.path.join(tmp, "old"), os.path.join(tmp, "new")
        open(pa, "w").write("\n".join(a) + "\n")
        open(pb, "w").write("\n".join(b) + "\n")
        diff = subprocess.run(["diff", pa, pb], capture_output=True,
                              text=True).stdout
    removed = sum(1 for l in diff.splitlines() if l.startswith("< "))
    added = sum(1 for l in diff.splitlines() if l.startswith("> "))
    return len(a), len(b), removed, added


def report(old, new):
    n_old, n_new, removed, added = distance(old, new)
    comments, total = comment_share(new)
    print(f"{os.path.basename(old)} -> {os.path.basename(new)}: code lines "
          f"{n_old} -> {n_new}, removed {removed} + added {added} = "
          f"{removed + added}; {os.path.basename(new)} comment share "
          f"{comments}/{total} = {100 * comments / total:.1f} %")


if __name__ == "__main__":
    args = sys.argv[1:]
    if args:
        if len(args) % 2:
            sys.exit(__doc__)
        for old, new in zip(args[::2], args[1::2]):
            report(old, new)
    else:
        here = os.path.dirname(os.path.abspath(__file__))
        steps = []
        for k in range(1, 100):
            path = os.path.join(here, f"step-{k}", f"step-{k}.cc")
            if os.path.exists(path):
                steps.append(path)
        for old, new in zip(steps, steps[1:]):
            report(old, new)
        for new in steps[2:]:
            report(steps[0], new)
        comments, total = comment_share(steps[0])
        print(f"step-1.cc comment share {comments}/{total} = "
              f"{100 * comments / total:.1f} %")
