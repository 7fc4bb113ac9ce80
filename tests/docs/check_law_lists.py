#!/usr/bin/python3
"""Check that the law lists of README.md, doc/laws.md and doc/tutorial.md
name exactly the laws the program registers.

Run as `/usr/bin/python3 tests/docs/check_law_lists.py HEMICONTACT SOURCE_DIR`
(the ctest docs/law_lists does). The registered laws are read from the
program: the selection of `normal law/law` and `friction law/law` in
`hemicontact --print-parameters json`. In each page a law list is the text
between the lines

    <!-- law list: normal -->        (or: friction)
    <!-- end of law list -->

and the laws it names are the inline code spans in it: in a table row the
first span of the row (none in the header row), elsewhere every span. Each page must hold one list
of each kind, and each list must name every registered law of its kind and
nothing else.

Exit status 0 if every list matches, 1 otherwise, with one line
"PAGE: what is missing or extra" per mismatch.
"""

import json
import os
import re
import subprocess
import sys

PAGES = ("README.md", "doc/laws.md", "doc/tutorial.md")
KINDS = {"normal": "normal law", "friction": "friction law"}
BEGIN = re.compile(r"^<!-- law list: (\w+) -->\s*$")
END = re.compile(r"^<!-- end of law list -->\s*$")


def registered(executable):
    """{kind: set of law names} from --print-parameters json."""
    out = subprocess.run([executable, "--print-parameters", "json"],
                         check=True, capture_output=True, text=True).stdout
    parameters = json.loads(out)
    laws = {}
    for kind, subsection in KINDS.items():
        pattern = parameters[subsection]["law"]["pattern_description"]
        m = re.match(r"^\[Selection (.*) \]$", pattern)
        if not m:
            raise SystemExit("cannot read the laws of '%s' from %r"
                             % (subsection, pattern))
        laws[kind] = set(m.group(1).split("|"))
    return laws


def names_in(lines):
    """The law names of the lines of one list: the first code span of each
    table row (the header row, followed by |---|, names none), and every
    code span of the other text (a span may wrap to the next line)."""
    names, prose = set(), []
    for i, line in enumerate(lines):
        if not line.lstrip().startswith("|"):
            prose.append(line)
            continue
        if re.match(r"^\s*\|[-|: ]+$", line):
            continue
        following = lines[i + 1] if i + 1 < len(lines) else ""
        if re.match(r"^\s*\|[-|: ]+$", following):
            continue
        names.update(re.findall(r"`([^`]+)`", line)[:1])
    for span in re.findall(r"`([^`]+)`", " ".join(prose)):
        names.add(" ".join(span.split()))
    return names


def lists(text):
    """[(kind, set of names or None if unterminated, line number)] of the
    law lists of a page."""
    result = []
    kind, lines, start = None, [], 0
    for number, line in enumerate(text.split("\n"), 1):
        m = BEGIN.match(line)
        if m:
            kind, lines, start = m.group(1), [], number
        elif END.match(line) and kind is not None:
            result.append((kind, names_in(lines), start))
            kind = None
        elif kind is not None:
            lines.append(line)
    if kind is not None:
        result.append((kind, None, start))
    return result


def main():
    executable, root = sys.argv[1], sys.argv[2]
    laws = registered(executable)
    errors = []
    for page in PAGES:
        with open(os.path.join(root, page), encoding="utf-8") as f:
            found = lists(f.read())
        for kind in KINDS:
            mine = [entry for entry in found if entry[0] == kind]
            if len(mine) != 1:
                errors.append("%s: %d %s law lists (<!-- law list: %s -->), "
                              "expected one" % (page, len(mine), kind, kind))
                continue
            _, names, line = mine[0]
            if names is None:
                errors.append("%s:%d: the %s law list has no "
                              "'<!-- end of law list -->'" % (page, line, kind))
                continue
            for law in sorted(laws[kind] - names):
                errors.append("%s:%d: the %s law list lacks '%s'"
                              % (page, line, kind, law))
            for law in sorted(names - laws[kind]):
                errors.append("%s:%d: the %s law list names '%s', which is "
                              "not registered" % (page, line, kind, law))
        for kind, _, line in found:
            if kind not in KINDS:
                errors.append("%s:%d: unknown law list kind '%s'"
                              % (page, line, kind))
    for e in errors:
        print(e)
    print("%d page(s), registered: %d normal and %d friction laws; "
          "%d mismatch(es)" % (len(PAGES), len(laws["normal"]),
                               len(laws["friction"]), len(errors)))
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
