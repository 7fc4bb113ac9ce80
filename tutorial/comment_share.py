#!/usr/bin/env python3
"""The comment share of the tutorial programs, as deal.II's tutorial counts it.

    tutorial/comment_share.py [--min PERCENT] [FILE.cc ...]

Without arguments it counts every tutorial/step-*/step-*.cc beside this
script. A line counts as a comment line when its first non-blank
characters are // or when it lies inside a /* ... */ block (the opening
and closing lines included); the share is the comment lines over all
non-blank lines. The code lines are the non-blank lines that are not
comment lines (what a diff with comments stripped compares).

With --min PERCENT the exit status is 1 if a file's share is below
PERCENT (the test tutorial/comment_share runs it with 33, the share of
deal.II's step-41, on the steps it names).
"""
import pathlib
import sys


def count(path):
    comment = blank = total = 0
    inside = False
    for line in pathlib.Path(path).read_text().splitlines():
        text = line.strip()
        if not text:
            blank += 1
            continue
        total += 1
        if inside:
            comment += 1
            inside = "*/" not in text
        elif text.startswith("//"):
            comment += 1
        elif text.startswith("/*"):
            comment += 1
            inside = "*/" not in text[2:]
    return comment, total


def main():
    here = pathlib.Path(__file__).resolve().parent
    arguments = sys.argv[1:]
    minimum = None
    if arguments[:1] == ["--min"]:
        minimum = float(arguments[1])
        arguments = arguments[2:]
    files = arguments or sorted(str(p) for p in here.glob("step-*/step-*.cc"))
    below = []
    print(f"{'file':<28} {'non-blank':>9} {'comment':>8} {'code':>6} {'share':>6}")
    for name in files:
        comment, total = count(name)
        share = 100.0 * comment / total if total else 0.0
        label = str(pathlib.Path(name).resolve().relative_to(here.parent)) \
            if str(pathlib.Path(name).resolve()).startswith(str(here.parent)) else name
        print(f"{label:<28} {total:>9} {comment:>8} {total - comment:>6} {share:>5.1f}%")
        if minimum is not None and share < minimum:
            below.append(f"{label}: {share:.1f} % < {minimum:g} %")
    for line in below:
        print("FAIL:", line)
    return 1 if below else 0


if __name__ == "__main__":
    sys.exit(main())
