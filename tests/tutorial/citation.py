"""citation.py SOURCE_DIR: the tutorial cites the paper as CITATION.cff does.

From the reference in CITATION.cff (family-names, given-names, title,
journal, year) it builds the authors as "D. Han and W. Han" and checks
that
* every author pair written with initials ("X. Han and Y. Han",
  "X. Han, Y. Han", "X. Han & Y. Han") in the tutorial's pages and
  programs (tutorial/**/*.md, tutorial/**/*.cc, the lines of
  doc/tutorial.md and README.md) is that one;
* step-2's introduction and program, which solve the paper's problem,
  and step-3's introduction, which relates step-3 to it, give the full
  reference: the authors, the title and the year.
It prints what it checked and exits 1 with FILE:LINE for each mismatch."""
import glob
import os
import re
import sys

source = sys.argv[1]
cff = open(os.path.join(source, "CITATION.cff")).read()
reference = cff[cff.index("references:"):]
family = re.findall(r"family-names:\s*(.+)", reference)
given = re.findall(r"given-names:\s*(.+)", reference)
assert len(family) == len(given) >= 1, (family, given)
names = [f"{g.strip()[0]}. {f.strip()}" for f, g in zip(family, given)]
authors = " and ".join(names)
title = " ".join(re.search(r"title:\s*>-\s*\n((?:\s{6,}.+\n)+)",
                           reference).group(1).split())
year = re.search(r"year:\s*(\d{4})", reference).group(1)

files = sorted(glob.glob(os.path.join(source, "tutorial", "**", "*.md"),
                         recursive=True) +
               glob.glob(os.path.join(source, "tutorial", "**", "*.cc"),
                         recursive=True) +
               [os.path.join(source, "doc", "tutorial.md"),
                os.path.join(source, "README.md")])
pair = re.compile(r"\b[A-Z]\.\s+Han(?:\s*,|\s+and|\s+&)\s+[A-Z]\.\s+Han\b")
errors, seen = [], 0
for path in files:
    text = open(path, encoding="utf-8").read()
    for match in pair.finditer(text):
        seen += 1
        written = " ".join(match.group(0).split())
        if written != authors:
            line = text.count("\n", 0, match.start()) + 1
            errors.append(f"{os.path.relpath(path, source)}:{line}: "
                          f"'{written}', CITATION.cff has '{authors}'")

for page in ("tutorial/step-2/doc/intro.md", "tutorial/step-2/step-2.cc",
             "tutorial/step-3/doc/intro.md"):
    text = " ".join(open(os.path.join(source, page)).read().split())
    text = re.sub(r"\s*\*\s*", " ", text)  # a C comment's leading stars
    for part in (authors, title, year):
        if part not in " ".join(text.split()):
            errors.append(f"{page}: the reference lacks '{part}'")

print(f"CITATION.cff: {authors}, \"{title}\", {year}; {seen} author pairs "
      f"in {len(files)} files")
for e in errors:
    print("FAIL:", e)
sys.exit(1 if errors else 0)
