"""Writes a notebook from (kind, text) cells through nbformat: the shared part of make_*_notebook.py."""
import pathlib

import nbformat
from nbformat import v4


def write_notebook(cells, name):
    """Write the cells ("markdown" or "code", source text) to NAME.ipynb here."""
    make = {"markdown": v4.new_markdown_cell, "code": v4.new_code_cell}
    nb = v4.new_notebook(
        metadata={"kernelspec": {"name": "python3", "display_name": "Python 3", "language": "python"},
                  "language_info": {"name": "python"}},
        cells=[make[kind](text, id=f"cell-{i}") for i, (kind, text) in enumerate(cells)])
    nbformat.validate(nb)
    path = pathlib.Path(__file__).with_name(name + ".ipynb")
    nbformat.write(nb, str(path))
    print("wrote", path)
