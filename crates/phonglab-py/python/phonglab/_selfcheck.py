"""The notebook's self-check, `phonglab.check(globals())`: the worksheet's values this
notebook holds, checked step by step as `phonglab check` checks the saved notebook.

The givens are read from the cells run so far (IPython's `In`; nothing is run again). The
values are read from the variables' numbers (`numpy.asarray(v, dtype=float)`), never from
their `str` or `repr`, and written as NumPy prints them with its default options (whatever
the notebook's own print options), one value a name: only the names of the steps this
scene's key prints are read, nothing else the notebook holds."""

from __future__ import annotations

import re
from typing import Any, Dict, List, Optional

import numpy as np

from . import _core
from ._core import SceneError

# NumPy's defaults: what `print("vlv = ", vlv)` writes in a fresh kernel, and so what
# `phonglab check` reads from the saved notebook.
_DEFAULT_PRINT = dict(
    precision=8,
    threshold=1000,
    edgeitems=3,
    linewidth=75,
    suppress=False,
    nanstr="nan",
    infstr="inf",
    formatter=None,
    sign="-",
    floatmode="maxprec",
    legacy=False,
)
# A step's value holds at most 16 numbers; past this it is not one (and not converted).
_MOST_NUMBERS = 64
# The self-check's call: dropped from the cells read (the rest of its cell is kept).
_CALL = re.compile(r"(phonglab\s*\.\s*)?check\s*\(\s*globals\s*\(|phonglab\s*\.\s*check\s*\(")
_STEP = re.compile(r"^([A-Za-z_][A-Za-z0-9_]*)(?:\[(\d+)\])?$")
# A given the worksheet's first cells assign: none in the cells run, none run yet.
_ASSIGNS_GIVEN = re.compile(r"^[ \t]*(vertexPos|vertexNormal|lightPos)\s*=", re.M)
_UNREAD = "?"


def _code(cells: List[Any]) -> str:
    """The cells run, in order, without the self-check's call: a line calling it (outside
    a comment) is left blank, so the lines around it (and their numbers) stay."""
    lines = []
    for cell in cells:
        if not isinstance(cell, str):
            continue
        for line in cell.split("\n"):
            code = line.split("#", 1)[0]
            lines.append("" if _CALL.search(code) else line)
    return "\n".join(lines)


def _whole(value: Any) -> bool:
    """Does Python print `value` as an integer (`1`, `[0 0 1 0]`): exact, no digits?"""
    if isinstance(value, (bool, np.bool_)):
        return False
    if isinstance(value, (int, np.integer)):
        return True
    return isinstance(value, np.ndarray) and value.dtype.kind in "iu"


def _single(value: Any) -> bool:
    """Is `value` single precision (`np.float32`), which NumPy prints with its own digits?"""
    return isinstance(value, np.float32) or (isinstance(value, np.ndarray) and value.dtype == np.float32)


def _text(value: Any) -> str:
    """`value`'s numbers as NumPy's default print writes them, on one line; `?` (a value
    that is not numbers) where it has none or too many."""
    if isinstance(value, (str, bytes, bool, np.bool_, complex, np.complexfloating)):
        return _UNREAD
    # A complex array (`Idif + 1j`) is no real value: never its real part alone.
    if isinstance(value, np.ndarray) and value.dtype.kind not in "iuf":
        return _UNREAD
    value = _own(value)
    size = value.size if isinstance(value, np.ndarray) else len(value) if isinstance(value, (list, tuple)) else 1
    if size > _MOST_NUMBERS:
        return _UNREAD
    try:
        numbers = np.asarray(value, dtype=np.float64)
    except (TypeError, ValueError, OverflowError):
        return _UNREAD
    if numbers.size == 0 or numbers.size > _MOST_NUMBERS:
        return _UNREAD
    if _whole(value) and np.all(np.isfinite(numbers)):
        numbers = numbers.astype(np.int64)
    elif _single(value):
        # Printed as float32 prints (its own shortest digits), from the numbers.
        numbers = numbers.astype(np.float32)
    if numbers.ndim == 0:
        x = numbers.item()
        if isinstance(x, int):
            return str(x)
        return str(np.float32(x)) if numbers.dtype == np.float32 else repr(float(x))
    with np.printoptions(**_DEFAULT_PRINT):
        return np.array2string(numbers, max_line_width=10**6, separator=" ").replace("\n", " ")


def _own(value: Any) -> Any:
    """A number's own value, as it prints: a float's (or int's) subclass read as the float
    (or int) it holds, never through a __float__ of its own that says another number."""
    if isinstance(value, float) and not isinstance(value, np.floating):
        return float.__float__(value)
    if isinstance(value, int) and not isinstance(value, (bool, np.integer)):
        return int.__int__(value)
    return value


def _value(namespace: Dict[str, Any], step: str) -> Optional[Any]:
    """The value the notebook holds for the key's step `step` (`vlv`, or `vlv[2]`: the
    third of the list `vlv`), or None where it holds none."""
    match = _STEP.match(step)
    if match is None or match.group(1) not in namespace:
        return None
    value = namespace[match.group(1)]
    if match.group(2) is None:
        return value
    k = int(match.group(2))
    if isinstance(value, (list, tuple, np.ndarray)) and np.ndim(value) > 0 and k < len(value):
        return value[k]
    return None


def _printing_order(cells: List[str], steps: List[str]) -> List[str]:
    """`steps` in the order the cells print them, as `phonglab check` reads them from the
    saved notebook: by the cell that prints the step's label (`"vlv = "`, `f"vlv[{i}] = "`),
    a light's label by the loop it is printed in (`for`), then the light (the loop prints
    each light's values together), then the label's place in its cell; a step no cell
    prints after them, in the key's order."""
    found: Dict[str, Any] = {}

    def where(step: str) -> Any:
        match = _STEP.match(step)
        base, light = (match.group(1), match.group(2)) if match else (step, None)
        if base not in found:
            label = re.compile(r"[\"']" + re.escape(base) + r"(\[[^\]]*\])?\s*=")
            found[base] = next(
                ((k, cell, m.start()) for k, cell in enumerate(cells) for m in [label.search(cell)] if m), None
            )
        if found[base] is None:
            return (1, 0, 0, 0, 0)
        k, cell, at = found[base]
        loop = cell.rfind("for ", 0, at) if light is not None else -1
        return (0, k, loop if loop >= 0 else at, int(light or 0), at)

    return sorted(steps, key=where)


def printed(namespace: Dict[str, Any], steps: List[str]) -> str:
    """The notebook's values of the key's `steps`, as `name =  value` lines in the order
    given, one a step."""
    lines = []
    for step in steps:
        value = _value(namespace, step)
        if value is not None:
            lines.append(f"{step} =  {_text(value)}")
    return "\n".join(lines)


def _missing(code: str, namespace: Dict[str, Any], key: List[str]) -> List[str]:
    """The key's steps (in its order) whose name the notebook does not hold though its cells
    name them (outside comments: `I = (Iamb + ...)` names Iamb), or the key's last, the colour:
    a cell skipped, or stopped by an error. A step the cells never name (`Ilight`, which
    the worksheet does not print) is not asked."""
    named = set(re.findall(r"[A-Za-z_][A-Za-z0-9_]*", "\n".join(line.split("#", 1)[0] for line in code.split("\n"))))
    return [
        step
        for k, step in enumerate(key)
        if _STEP.sub(r"\1", step) not in namespace and (_STEP.sub(r"\1", step) in named or k == len(key) - 1)
    ]


def check(namespace: Dict[str, Any], lang: Optional[str] = None) -> bool:
    """The self-check cell: checks the worksheet's values this notebook holds step by step,
    as `phonglab check` checks a saved notebook, and prints the table (each step, the
    first wrong one and its likely cause) in lang (default: the language set_language
    chose). Call it as phonglab.check(globals()).

    The givens are read from the cells run so far (IPython's `In`; nothing is run again),
    the values from the numbers of the notebook's variables (never from how they print).
    A step of the key the notebook holds no value for (a cell skipped, or stopped by an
    error) makes it "not checked", as `phonglab check` says of the saved notebook.
    Returns True when every step is right. Raises SceneError given anything but
    globals(), outside Jupyter (use `phonglab check --printed` for a script's output) and
    before the worksheet's cells have run in this kernel."""
    lang = _core.language() if lang is None else lang
    if not isinstance(namespace, dict):
        why = "not-globals" if namespace is globals or isinstance(namespace, str) else "no-cells"
        raise SceneError(_core.check_refusal(why, lang))
    cells = namespace.get("In")
    if not isinstance(cells, list):
        cells = namespace.get("_ih")
    if not isinstance(cells, list):
        raise SceneError(_core.check_refusal("no-cells", lang))
    code = _code(cells)
    if not _ASSIGNS_GIVEN.search(code):
        raise SceneError(_core.check_refusal("run-first", lang))
    run = [c for c in cells if isinstance(c, str)]
    steps = _printing_order(run, _core.check_steps(code, lang))
    missing = _missing(code, namespace, _core.check_steps(code, lang))
    text, right = _core.check_work(code, printed(namespace, steps), missing, lang)
    print(text, end="")
    for name in _reassigned(run, steps):
        print(_core.check_note("reassigned", name, lang))
    return right


def _reassigned(cells: List[str], steps: List[str]) -> List[str]:
    """The steps' names assigned again (`I = …`, `for I in …`) in a cell run after the last
    cell that prints them: the value read now is not the one printed, which is what
    `phonglab check` reads from the saved notebook."""
    names = []
    for step in steps:
        match = _STEP.match(step)
        base = match.group(1) if match else step
        if base in names:
            continue
        label = re.compile(r"[\"']" + re.escape(base) + r"(\[[^\]]*\])?\s*=")
        printing = [k for k, cell in enumerate(cells) if label.search(cell)]
        if not printing:
            continue
        name = re.escape(base)
        again = re.compile(
            r"^[ \t]*(?:for\s+(?:[\w\s,()]*?\b)?" + name + r"\b[\w\s,()]*?\bin\b|"
            + name + r"\s*(?:\[[^\]]*\])?\s*(?:[-+*/@]|\*\*)?=(?!=))",
            re.M,
        )
        later = _code(cells[printing[-1] + 1 :])
        if again.search("\n".join(line.split("#", 1)[0] for line in later.split("\n"))):
            names.append(base)
    return names
