#!/usr/bin/python3
"""Check that the source map of doc/tutorial.md names every C++ file of
source/ and include/hemicontact/, and no file that does not exist.

Run as `/usr/bin/python3 doc/check_source_map.py SOURCE_DIR` (the ctest
docs/source_map does). The source map is the text of doc/tutorial.md
between the lines

    <!-- source map -->
    <!-- end of source map -->

and the files it names are its inline code spans that start with
`source/` or `include/hemicontact/` (read as check_doc_names.py reads the
pages: outside fenced code blocks). Every file under source/ and
include/hemicontact/ whose name ends in one of CPP_SUFFIXES must be named
by its full path, once; a span naming a directory (`source/problem/`)
names no file.

Exit status 0 if the map and the directories agree, 1 otherwise, with one
line "doc/tutorial.md:LINE: what is wrong and what to do" per mismatch: a
file missing from the map (with the row of the map that names another
file of its directory, where it belongs), a listed file that does not
exist, or a file listed twice.
"""

import os
import re
import sys

sys.dont_write_bytecode = True  # no doc/__pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_doc_names import spans  # noqa: E402  (the pages' span reader)

PAGE = "doc/tutorial.md"
DIRECTORIES = ("source", "include/hemicontact")
CPP_SUFFIXES = (".h", ".hh", ".hpp", ".cc", ".cpp", ".cxx", ".inl", ".ipp",
                ".tpp")
BEGIN = re.compile(r"^<!-- source map -->\s*$")
END = re.compile(r"^<!-- end of source map -->\s*$")


def files_on_disk(root):
    """The repository-relative paths of the C++ files of DIRECTORIES."""
    found = set()
    for directory in DIRECTORIES:
        for dirpath, _, names in os.walk(os.path.join(root, directory)):
            for name in names:
                if name.endswith(CPP_SUFFIXES):
                    found.add(os.path.relpath(os.path.join(dirpath, name),
                                              root).replace(os.sep, "/"))
    return found


def source_map(text):
    """(first line, last line, {path: [line numbers]}) of the source map of
    @p text; raises ValueError if there is not exactly one, terminated."""
    lines = text.split("\n")
    begins = [i + 1 for i, l in enumerate(lines) if BEGIN.match(l)]
    ends = [i + 1 for i, l in enumerate(lines) if END.match(l)]
    if len(begins) != 1 or len(ends) != 1 or ends[0] < begins[0]:
        raise ValueError(
            "%s: %d '<!-- source map -->' and %d '<!-- end of source map -->' "
            "lines, expected one of each, in this order"
            % (PAGE, len(begins), len(ends)))
    first, last = begins[0], ends[0]
    listed = {}
    for number, kind, span in spans(text):
        if kind != "code" or not first < number < last:
            continue
        path = span.split()[0] if span.split() else span
        if path.startswith(tuple(d + "/" for d in DIRECTORIES)) and \
                not path.endswith("/"):
            listed.setdefault(path, []).append(number)
    return first, last, listed


def row_of_directory(listed, directory):
    """The line of the map that names a file of @p directory, if any."""
    lines = [min(n) for p, n in listed.items()
             if os.path.dirname(p) == directory]
    return min(lines) if lines else None


def main():
    root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else
                           os.path.join(os.path.dirname(__file__), ".."))
    with open(os.path.join(root, PAGE), encoding="utf-8") as f:
        text = f.read()
    try:
        first, last, listed = source_map(text)
    except ValueError as e:
        print(e)
        return 1
    on_disk = files_on_disk(root)
    errors = []
    for path in sorted(on_disk - set(listed)):
        directory = os.path.dirname(path)
        row = row_of_directory(listed, directory)
        where = ("next to line %d, the first row that names a file of %s/"
                 % (row, directory)) if row else \
            ("in a new row for %s/" % directory)
        errors.append(
            "%s:%d: %s is not in the source map: add `%s` with what it does "
            "to the table between '<!-- source map -->' (line %d) and "
            "'<!-- end of source map -->' (line %d), %s"
            % (PAGE, first, path, path, first, last, where))
    for path in sorted(set(listed) - on_disk):
        errors.append("%s:%d: the source map names %s, which does not exist: "
                      "correct the path or remove it"
                      % (PAGE, listed[path][0], path))
    for path in sorted(p for p in listed if len(listed[p]) > 1):
        errors.append("%s:%d: the source map names %s more than once "
                      "(lines %s): name it in one row"
                      % (PAGE, listed[path][1], path,
                         ", ".join(str(n) for n in listed[path])))
    for e in errors:
        print(e)
    print("%s: the source map names %d files; %s/ and %s/ hold %d; "
          "%d mismatch(es)" % (PAGE, len(listed), DIRECTORIES[0],
                               DIRECTORIES[1], len(on_disk), len(errors)))
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
