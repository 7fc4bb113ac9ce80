#!/usr/bin/python3
"""Check that ContactProblem stays the mathematics of a step: at most
LIMIT member functions (public and private, the constructors included) in
include/hemicontact/problem/contact_problem.h. What reads the state and
not the members is a free function of ProblemState
(include/hemicontact/problem/problem_state.h; doc/extending.md).

    /usr/bin/python3 tests/layout/contact_problem_size.py SOURCE_DIR

Prints the count and the names; exit status 1 above LIMIT.
"""

import os
import re
import sys

LIMIT = 30


def main():
    path = os.path.join(sys.argv[1], "include", "hemicontact", "problem",
                        "contact_problem.h")
    text = open(path).read()
    body = text[text.index("class ContactProblem"):]
    # strip the comments, then the bodies of inline definitions
    body = re.sub(r"/\*.*?\*/", "", body, flags=re.S)
    body = re.sub(r"//[^\n]*", "", body)
    names = re.findall(r"^\s{4}~?([A-Za-z_]\w*)\s*\(", body, re.M)
    print("ContactProblem: %d member functions (at most %d): %s" %
          (len(names), LIMIT, ", ".join(names)))
    if len(names) > LIMIT:
        print("%s: %d member functions, more than %d; make what reads the "
              "state a free function of ProblemState" %
              (path, len(names), LIMIT))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
