#!/usr/bin/python3
"""Check the include arrows between the folders of the library
(doc/development.md, "Layout"): the mathematics (problem/ and everything
below it) includes nothing of the run's output or of its driver, the
output nothing of the driver, the state types nothing of the problem, the
coupled fields (coupling/, thermal/, fields/) nothing of the problem, the
parameters nothing of the solver or the model, the laws nothing of the
model. So no circle runs through output/, simulation/, problem/, the
coupled fields, solver/ or laws/.

    /usr/bin/python3 tests/layout/include_arrows.py SOURCE_DIR

Exit status 0 if every arrow is allowed, 1 otherwise, with one line
"FILE: includes FOLDER/HEADER, which FOLDER of it must not" per arrow.
"""

import os
import re
import sys

BELOW_OUTPUT = {"base", "coupling", "expressions", "fields", "laws", "model", "memory", "mesh", "thermal",
                "solver", "state", "problem"}
FORBIDDEN = {folder: {"output", "simulation"} for folder in BELOW_OUTPUT}
FORBIDDEN["output"] = {"simulation"}
FORBIDDEN["state"] = {"output", "simulation", "problem"}
# a coupled field sees the mechanical step through its MechanicalView, not
# through the problem; the registry sits above the fields it lists
FORBIDDEN["coupling"] = {"output", "simulation", "problem", "fields", "thermal"}
FORBIDDEN["thermal"] = {"output", "simulation", "problem", "fields"}
FORBIDDEN["fields"] = {"output", "simulation", "problem"}
# the parameters hold their types (input/solver_tuning.h); the laws read
# their constants from expressions/, not from model/
FORBIDDEN["input"] = {"output", "simulation", "problem", "solver", "model"}
FORBIDDEN["laws"] = {"output", "simulation", "problem", "model"}


def main():
    root = sys.argv[1]
    bad = []
    for base in ("source", os.path.join("include", "hemicontact")):
        top = os.path.join(root, base)
        for dirpath, _, names in os.walk(top):
            for name in sorted(names):
                if not name.endswith((".h", ".cc")):
                    continue
                path = os.path.join(dirpath, name)
                rel = os.path.relpath(path, top)
                folder = rel.split(os.sep)[0] if os.sep in rel else ""
                with open(path, encoding="utf-8") as f:
                    text = f.read()
                for m in re.finditer(r"#include <hemicontact/([a-z_]+)/([^>]+)>",
                                     text):
                    if m.group(1) in FORBIDDEN.get(folder, ()):
                        bad.append("%s: includes %s/%s, which %s/ must not" %
                                   (os.path.relpath(path, root), m.group(1),
                                    m.group(2), folder))
    for line in bad:
        print(line)
    print("%d forbidden include arrows" % len(bad))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
