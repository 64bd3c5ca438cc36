#!/usr/bin/env python3
"""Runs the worksheet's own Python cells once for each of its five modelviews and writes
what they print (and the values behind the prints, at full precision) as JSON.

Usage: python3 scripts/worksheet_cells.py WORKSHEET.txt > tests/data/worksheet_cells.json

The worksheet is a Jupyter notebook exported to text: code cells start with `In [k]:` inside
``` fences; other fences hold the notebook's printed output. A fenced block is run when it
compiles as Python, except the one that shows the C call `glLightModeli(...)` (prose, not a
cell) and shell escapes (`! jupyter ...`). The only change made to the cells: the line
`mview = mview5` selects mview1..mview5 in turn. Needs numpy.
"""
import contextlib, io, json, re, sys

import numpy as np


def cells(text):
    out = []
    for block in re.findall(r"```\n(.*?)```", text, re.S):
        src = re.sub(r"^In \[[ 0-9]*\]: ?", "", block.strip("\n"))
        if not src.strip() or "glLightModeli" in src or src.lstrip().startswith("!"):
            continue
        try:
            compile(src, "<cell>", "exec")
        except SyntaxError:
            continue  # printed output, not code
        out.append(src)
    return out


def vec(v):
    return [float(x) for x in np.asarray(v, dtype=float).ravel()]


def main():
    text = open(sys.argv[1], encoding="utf-8").read()
    code = cells(text)
    assert sum("mview = mview5" in c for c in code) == 1, "the worksheet selects mview5 once"
    runs = []
    for k in range(1, 6):
        ns = {}
        buf = io.StringIO()
        with contextlib.redirect_stdout(buf):
            for c in code:
                exec(c.replace("mview = mview5", "mview = mview%d" % k), ns)
        printed = {}
        for m in re.finditer(r"^(\w+) = +(\[[^\]]*\])", buf.getvalue(), re.M):
            printed[m.group(1)] = m.group(2)
        runs.append({
            "mview": k,
            "modelview_rows": [vec(r) for r in ns["mview"]],
            "stdout": buf.getvalue(),
            "printed": printed,
            # The values behind the prints, and the steps the worksheet computes without printing.
            "values": {
                "vertexNormal": vec(ns["vertexNormal"]), "lightPos": vec(ns["lightPos"]),
                "vertexPos": vec(ns["vertexPos"]), "vlv": vec(ns["vlv"]), "vov": vec(ns["vov"]),
                "Iamb": vec(ns["Iamb"]), "cosTheta": float(ns["cosTheta"]), "Idif": vec(ns["Idif"]),
                "H": vec(ns["H"]), "cosBeta": float(ns["cosBeta"]), "Ispec": vec(ns["Ispec"]),
                "d": float(ns["d"]), "at": float(ns["at"]), "I": vec(ns["I"]),
            },
        })
    # The cells' own text too: the app's names are tested against it.
    json.dump({"source": "worksheet-vertex-colour.txt, cells In [1]..In [10] run as printed",
               "numpy": np.__version__, "cells": code, "runs": runs}, sys.stdout, indent=1)
    print()


if __name__ == "__main__":
    main()
