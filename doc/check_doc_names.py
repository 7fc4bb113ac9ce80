#!/usr/bin/python3
"""Check that every repository path, class and function README.md,
doc/*.md, tutorial/*.md and the tutorial steps' pages
(tutorial/step-*/doc/*.md) name exists.

Run as `/usr/bin/python3 doc/check_doc_names.py SOURCE_DIR` (the ctest
docs/doc_names does). It reads these pages outside fenced code blocks and
checks

* paths: a link target that is not a URL (relative to the page), and an
  inline code span that starts with one of the top-level directories in
  PATH_ROOTS (relative to the repository root; on a step's page also
  relative to the step's directory, where its program runs) or is a bare
  file name ending in .cc/.h/.py/.prm/.md; `*`, `NAME`, `NNNNN` and
  `<...>` in a path match anything;
* C++ names: an inline code span that is a single CamelCase word
  (`ContactStep`, `KelvinVoigtMaterial<dim>`), a qualified name
  (`ContactStep::residual()`, `nodal::state()`) or a call (`run()`).
  A CamelCase word must occur as a word in the code (CODE_DIRS, the
  tutorial steps' programs among them); a
  function must occur followed by "("; in `A::b` the class or namespace
  A must occur, and b must occur either as `A::b` / `A<...>::b` in the
  code or in a file that declares A (class, struct or namespace A).

Names that belong to deal.II, Trilinos, the C++ standard library or other
tools are not in this repository. They are skipped by ALLOWED (exact
names) and ALLOWED_PREFIXES (anything qualified by one of these
namespaces, e.g. `TrilinosWrappers::`). To extend it, add the name or the
namespace prefix to one of the two lists below.

Exit status 0 if every name exists, 1 otherwise, with one line
"FILE:LINE: what is missing" per missing name.
"""

import glob
import os
import re
import sys

PATH_ROOTS = ("source/", "include/", "tests/", "prm/", "bench/", "doc/",
              "jupyter-notes/", ".ci/", "cmake/", "results/", "tutorial/")
CODE_DIRS = ("include", "source", "tests", "bench", "tutorial")
CODE_SUFFIXES = (".h", ".cc", ".py", ".sh", ".txt", ".cmake")

# deal.II, Trilinos, C++ and tool names the pages use (exact spans).
ALLOWED = {
    "DataOut", "DataOutFaces", "DataOutBase", "DoFHandler", "FESystem",
    "FEValues", "FEFaceValues", "ParameterHandler", "ParameterAcceptor",
    "AffineConstraints", "IndexSet", "GridIn", "GridOut", "GridGenerator",
    "GridTools", "SolutionTransfer", "SolverCG", "SolverGMRES",
    "SolverControl", "SparsityPattern", "DynamicSparsityPattern",
    "ConditionalOStream", "TimerOutput", "FunctionParser", "MappingQ",
    "MappingFE", "QGauss", "QGaussLobatto", "QGaussSimplex", "FE_Q",
    "FE_SimplexP", "FE_Nothing", "KellyErrorEstimator", "PreconditionAMG",
    "PreconditionIdentity", "SparseDirectUMFPACK", "DataPostprocessor",
    "DataPostprocessorVector", "DataPostprocessorTensor",
    "RemotePointEvaluation", "MPI_Allreduce", "MPI_Comm", "LinearOperator",
    "ArrayView", "SymmetricTensor", "Tensor", "Point", "Vector",
    "BlockVector", "FullMatrix", "ReferenceCells", "ExcMessage",
    "AssertThrow", "Assert", "DEAL_II_PICKUP_TESTS", "ParaView",
    "CMake", "GitHub", "JSON", "Gmsh", "LaTeX", "MathJax", "McCormick",
    "DataOutFilter", "XDMFEntry", "HDF5", "VTU", "PVTU", "ScaLAPACK",
    "KLU", "Amesos", "AztecOO", "Epetra_CrsMatrix", "Epetra_Vector",
    "ML", "MueLu", "Teuchos", "OpenMPI", "MPICH", "TBB", "CTest",
    "Doxygen", "Jupyter", "NumPy", "SciPy", "PyPI", "LOBPCG",
    "SIGTERM", "SIGINT", "SIGKILL", "Valgrind", "AddressSanitizer",
    "UndefinedBehaviorSanitizer", "DebugInfo", "RelWithDebInfo",
    "Release", "Debug", "CONFIGURE_DEPENDS", "JupyterLab",
}
# Names qualified by one of these (`TrilinosWrappers::MPI::Vector`).
ALLOWED_PREFIXES = (
    "dealii::", "std::", "TrilinosWrappers::", "Utilities::", "parallel::",
    "GridGenerator::", "GridTools::", "DoFTools::", "VectorTools::",
    "MatrixTools::", "MatrixCreator::", "Patterns::", "DataOutBase::",
    "LinearAlgebra::", "LinearAlgebraTrilinos::", "ReferenceCells::",
    "Triangulation", "DoFRenumbering::", "SparsityTools::",
    "LinearAlgebraPETSc::", "PETScWrappers::", "TriangulationDescription::",
    "ML_", "Epetra", "Teuchos::", "boost::", "numdiff", "MPI_", "DEAL_II_",
    "CMAKE_", "OMPI_", "HEMICONTACT_",
)

CAMEL = re.compile(r"^[A-Z][a-z0-9]+(?:[A-Z][A-Za-z0-9]*)+$")
QUALIFIED = re.compile(r"^[A-Za-z_]\w*(?:<[^<>]*>)?(?:::[A-Za-z_~]\w*)+$")
CALL = re.compile(r"^[a-z_]\w*\(\)$")
PLACEHOLDER = re.compile(r"NNNNN|NAME|CASE|TYPE|my_law|MyLaw|<[^>]*>")


def code_files(root):
    files = []
    for d in CODE_DIRS:
        for dirpath, _, names in os.walk(os.path.join(root, d)):
            files += [os.path.join(dirpath, n) for n in names
                      if n.endswith(CODE_SUFFIXES)]
    return files


def read(path):
    with open(path, encoding="utf-8", errors="replace") as f:
        return f.read()


class Code:
    """The text of the code files, searched by regular expressions."""

    def __init__(self, root):
        self.files = {p: read(p) for p in code_files(root)}
        self.all = "\n".join(self.files.values())
        self.names = set()
        for dirpath, _, names in os.walk(root):
            if "/build" in dirpath or "/.git" in dirpath:
                continue
            self.names.update(names)
        # ctest names (`doc/doxygen`, `tests/active_set_newton`)
        self.tests = set()
        for p in glob.glob(os.path.join(root, "**", "CMakeLists.txt"),
                           recursive=True):
            if "/build" not in p:
                self.tests.update(re.findall(r"add_test\(NAME\s+([^\s)]+)",
                                             read(p)))

    def has(self, pattern):
        return re.search(pattern, self.all) is not None

    def declaring(self, scope):
        decl = re.compile(r"\b(?:class|struct|namespace|enum class)\s+"
                          + re.escape(scope) + r"\b")
        return [t for t in self.files.values() if decl.search(t)]


def path_exists(root, path, tests=()):
    path = path.split("#")[0].rstrip("/") or "."
    if path in tests or any(os.path.exists(os.path.join(root, path + s))
                            for s in (".cc", ".prm")):
        return True                               # a ctest name
    if PLACEHOLDER.search(path) or "*" in path:
        pattern = PLACEHOLDER.sub("*", path)
        return bool(glob.glob(os.path.join(root, pattern)))
    return os.path.exists(os.path.join(root, path))


def check_identifier(code, span):
    """None if @p span names nothing checked or exists, else what is missing."""
    name = re.sub(r"<[^<>]*>", "", span)          # ContactProblem<dim>
    if name in ALLOWED or span in ALLOWED or \
            any(name.startswith(p) for p in ALLOWED_PREFIXES):
        return None
    if CALL.match(name):
        function = name[:-2]
        ok = code.has(r"\b" + re.escape(function) + r"\s*\(")
        return None if ok else "function " + span
    bare = name[:-2] if name.endswith("()") else name
    if QUALIFIED.match(bare):
        parts = bare.split("::")
        scope, member = parts[-2], parts[-1]
        if scope in ALLOWED:
            return None
        if not code.has(r"\b" + re.escape(scope) + r"\b"):
            return "class or namespace " + scope + " (in " + span + ")"
        if code.has(r"\b" + re.escape(scope) + r"(?:<[^<>;{}]*>)?::"
                    + re.escape(member) + r"\b"):
            return None
        word = re.compile(r"\b" + re.escape(member) + r"\b")
        if any(word.search(t) for t in code.declaring(scope)):
            return None
        return "member " + span
    if CAMEL.match(bare):
        return None if code.has(r"\b" + re.escape(bare) + r"\b") \
            else "class " + span
    return None


def spans(text):
    """(line number, kind, text) of inline code spans and link targets
    outside fenced code blocks."""
    fenced = False
    for number, line in enumerate(text.split("\n"), 1):
        if line.lstrip().startswith("```"):
            fenced = not fenced
            continue
        if fenced:
            continue
        for m in re.finditer(r"`([^`]+)`", line):
            yield number, "code", m.group(1).strip()
        for m in re.finditer(r"\]\(([^)\s]+)\)", line):
            yield number, "link", m.group(1)


def check_page(root, code, page):
    errors = []
    rel_page = os.path.relpath(page, root)
    page_dir = os.path.dirname(rel_page)
    # a step's page (tutorial/step-N/doc/) names files of its step too
    step_dir = os.path.dirname(page_dir) \
        if re.match(r"^tutorial/step-[^/]+/doc$", page_dir) else None
    for number, kind, span in spans(read(page)):
        where = "%s:%d: " % (rel_page, number)
        if kind == "link":
            if re.match(r"^[a-z]+:", span) or span.startswith("#"):
                continue
            target = os.path.normpath(os.path.join(page_dir, span))
            if not path_exists(root, target):
                errors.append(where + "no file " + span)
            continue
        first = span.split()[0] if span.split() else span
        first = first.rstrip(",;:.")
        if first.startswith(PATH_ROOTS):
            if not path_exists(root, first, code.tests) and not (
                    step_dir and path_exists(os.path.join(root, step_dir),
                                             first)):
                errors.append(where + "no file " + first)
            continue
        if re.match(r"^\w[\w.-]*\.(cc|h|py|prm|md|ipynb)$", span):
            if not PLACEHOLDER.search(span) and span not in code.names:
                errors.append(where + "no file named " + span)
            continue
        if " " in span:
            continue
        missing = check_identifier(code, span)
        if missing:
            errors.append(where + "no " + missing)
    return errors


def main():
    root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else
                           os.path.join(os.path.dirname(__file__), ".."))
    code = Code(root)
    pages = [os.path.join(root, "README.md")] + \
        sorted(glob.glob(os.path.join(root, "doc", "*.md"))) + \
        sorted(glob.glob(os.path.join(root, "tutorial", "*.md"))) + \
        sorted(glob.glob(os.path.join(root, "tutorial", "step-*", "doc",
                                      "*.md")))
    errors = []
    for page in pages:
        errors += check_page(root, code, page)
    for e in errors:
        print(e)
    print("%d page(s) checked, %d missing name(s)" % (len(pages),
                                                     len(errors)))
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
