"""Writes a notebook from (kind, text) cells: the shared part of make_*_notebook.py."""
import json
import pathlib


def write_notebook(cells, name):
    """Write the cells ("markdown" or "code", source text) to NAME.ipynb here."""
    nb = {"nbformat": 4, "nbformat_minor": 5,
          "metadata": {"kernelspec": {"name": "python3", "display_name": "Python 3", "language": "python"},
                       "language_info": {"name": "python"}},
          "cells": []}
    for i, (kind, text) in enumerate(cells):
        cell = {"cell_type": kind, "metadata": {}, "source": text, "id": f"cell-{i}"}
        if kind == "code":
            cell.update({"outputs": [], "execution_count": None})
        nb["cells"].append(cell)
    path = pathlib.Path(__file__).with_name(name + ".ipynb")
    path.write_text(json.dumps(nb, indent=1))
    print("wrote", path)
