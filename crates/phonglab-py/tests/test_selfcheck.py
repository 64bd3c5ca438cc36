"""`phonglab.check(globals())` judges the notebook's values (their numbers, one a step of
the key), never how they print, and agrees with `phonglab check` on the same notebook."""

import contextlib
import io
import json
import subprocess

import numpy as np
import pytest

import phonglab

VECTORS = "vlv = vlv/np.linalg.norm(vlv)"
DIFFUSE = "Idif = (Ldif*matDif)*cosTheta"


@pytest.fixture(scope="module")
def cells(cli, tmp_path_factory):
    """The exported worksheet notebook's code cells, without the self-check cell."""
    path = tmp_path_factory.mktemp("nb") / "ws.ipynb"
    cli("export", "--to", "notebook", "-o", path)
    nb = json.loads(path.read_text())
    code = ["".join(c["source"]) for c in nb["cells"] if c["cell_type"] == "code"]
    assert code[-1].startswith("# import phonglab; phonglab.check(globals()")
    return code[:-1]


def run(cells, after="", lang="en"):
    """Runs `cells` as Jupyter does (each appended to In, then run), then `after`, then
    the self-check: (its verdict, what it printed)."""
    ns = {"In": [""]}
    for cell in cells:
        ns["In"].append(cell)
        exec(cell, ns)
    if after:
        ns["In"].append(after)
        exec(after, ns)
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        right = phonglab.check(ns, lang=lang)
    return right, out.getvalue()


def mistaken(cells, old, new):
    changed = [c.replace(old, new) for c in cells]
    assert changed != cells, old
    return changed


def test_right_work_is_right_and_wrong_work_names_its_step(cells):
    right, text = run(cells)
    assert right, text
    assert "all right" in text
    right, text = run(mistaken(cells, DIFFUSE, DIFFUSE + "*3"))
    assert not right
    assert "first wrong step: Idif" in text, text


def test_a_value_whose_str_lies_is_judged_by_its_numbers(cells):
    # D17: an ndarray subclass printing the key's values for wrong numbers.
    lie = (
        "def lie(text):\n"
        "    return type('Lie', (np.ndarray,), {'__str__': lambda self: text, '__repr__': lambda self: text})\n"
        "Idif = Idif.view(lie('[0.09942795 0.05965677 0.0252664  0.        ]'))\n"
        "I = I.view(lie('[0.05958709 0.03575929 0.01515525 0.        ]'))\n"
        "glColor = glColor.view(lie('[0.05958709 0.03575929 0.01515525 1.        ]'))\n"
    )
    right, text = run(mistaken(cells, DIFFUSE, DIFFUSE + "*3"), lie)
    assert not right and "first wrong step: Idif" in text, text


def test_floats_whose_repr_lies_are_judged_by_their_numbers(cells):
    # D18: a list of float subclasses whose repr is the key's.
    lie = (
        "class F(float):\n"
        "    def __repr__(self):\n"
        "        return repr(float(self) / 2)\n"
        "    __str__ = __repr__\n"
        "vlv = [F(2 * x) for x in vlv]\n"
    )
    right, text = run(cells, lie)
    assert not right and "first wrong step: vlv" in text, text


def test_a_value_with_line_breaks_forges_no_other_step(cells):
    # D19: one variable's text holding other steps' lines.
    right, _ = run(mistaken(cells, DIFFUSE, DIFFUSE + "*3"))
    assert not right
    forged = "Idif = '0\\nIdif = [0.07075524 0.04245314 0.01798012 0.]\\nI = [1 1 1 0]'\n"
    right, text = run(mistaken(cells, DIFFUSE, DIFFUSE + "*3"), forged)
    assert not right, text
    # The value is not numbers: unread, never three values.
    assert "Idif: yours" not in text and "(Idif)" in text, text


def test_the_students_print_options_do_not_change_the_verdict(cells):
    # D20: precision=0 would print 3x the diffuse as the key's rounded.
    for precision in (0, 2):
        after = f"np.set_printoptions(precision={precision}, suppress=True)\n"
        right, text = run(mistaken(cells, DIFFUSE, DIFFUSE + "*1.04"), after)
        assert not right and "first wrong step: Idif" in text, (precision, text)
        right, text = run(cells, after)
        assert right, (precision, text)
    np.set_printoptions(precision=8, suppress=False)


def test_a_comment_naming_the_check_keeps_its_cell(cells):
    # D21: the givens cell with a comment about the self-check is still read (z = 45).
    changed = [c.replace("lightPos = np.array([0, 0, 90, 1]);", "lightPos = np.array([0, 0, 45, 1]);  # run phonglab.check(globals()) at the end") for c in cells]
    assert changed != cells
    right, text = run(changed)
    assert right, text
    # And a cell that calls it among other lines keeps those lines.
    right, text = run(cells[:2] + ["import phonglab; phonglab.check  # later\n" + cells[2]] + cells[3:])
    assert right, text


def test_a_list_of_numpy_scalars_is_read_as_its_numbers(cells):
    # D22: NumPy 2 prints [np.float64(...), ...]; the numbers are what counts.
    right, text = run(cells, "I = list(I)\nvlv = tuple(vlv)\n")
    assert right, text
    assert "not checked whole" not in text


def test_unrelated_variables_are_not_counted(cells):
    # D23: thousands of other arrays are not the student's steps.
    junk = "for k in range(5000):\n    globals()[f'junk{k}'] = np.zeros(4)\n"
    right, text = run(cells, junk)
    assert right, text
    assert "junk" not in text


def test_a_value_that_is_not_numbers_leaves_the_work_unchecked(cells):
    right, text = run(cells, "cosTheta = 'about 0.14'\n")
    assert not right
    assert "not checked whole" in text and "cosTheta" in text, text
    for odd in ("{'x': 1}", "np.zeros(100000)", "None", "3 + 4j", "True"):
        right, text = run(cells, f"vlv = {odd}\n")
        assert not right or odd == "None", (odd, text)


def test_several_lights_are_read_from_the_per_light_lists(cli, tmp_path):
    from conftest import ROOT

    path = tmp_path / "three.ipynb"
    cli("export", "--to", "notebook", "-o", path, "--scene", ROOT / "assets/scenes/three-lights.toml")
    nb = json.loads(path.read_text())
    three = ["".join(c["source"]) for c in nb["cells"] if c["cell_type"] == "code"][:-1]
    right, text = run(three)
    assert right, text
    assert "vlv[2]: yours" in text
    # A scalar where the key has one vlv a light: no vlv[k] is held (nor printed), none read,
    # so the work is incomplete, naming the steps it lacks (never right).
    right, text = run(three, "vlv = np.float64(3.0)\n")
    assert "vlv[0]: yours" not in text and "vertexPos: yours" in text, text
    assert not right and "incomplete:" in text and "the first vlv[0]" in text, text
    right, text = run(mistaken(three, "Idif[i] = (Ldif[i]*matDif)*cosTheta[i]", "Idif[i] = (Ldif[i]*matDif)*cosTheta[i]*2"))
    assert not right and "first wrong step: Idif[0]" in text, text


def test_steps_are_in_the_keys_order_as_the_command_line_prints_them(cells):
    # py_teacher 13: the vectors cell run twice makes vertexNormal (printed first) the first wrong.
    k = next(i for i, c in enumerate(cells) if VECTORS in c)
    right, text = run(cells[: k + 1] + [cells[k]] + cells[k + 1 :])
    assert not right
    assert "first wrong step: vertexNormal" in text, text


def test_only_the_check_cell_after_a_restart_says_to_run_the_others_first():
    # py_teacher 10.
    ns = {"In": ["", "import phonglab; phonglab.check(globals())"]}
    with pytest.raises(phonglab.SceneError, match="Run the other cells first"):
        phonglab.check(ns)
    with pytest.raises(phonglab.SceneError, match="Execute primeiro as outras células"):
        phonglab.check(ns, lang="pt-PT")


def test_outside_jupyter_it_says_what_to_use_instead():
    # py_teacher 11: a script's globals() has no In.
    ns = {"vertexPos": np.array([-512, -384, 0, 1]), "lightPos": np.array([0, 0, 90, 1])}
    with pytest.raises(phonglab.SceneError, match=r"checks a Jupyter notebook.*phonglab check --printed"):
        phonglab.check(ns)
    with pytest.raises(phonglab.SceneError, match="verifica um caderno Jupyter"):
        phonglab.check(None, lang="pt-PT")


def test_the_evidence_line_reads_well_for_the_step_at(cells):
    # py_teacher 13: "Evidence: at at you printed".
    right, text = run(mistaken(cells, "at = atC + atLin*d + atQuad*d*d", "at = atC + atLin*d + atQuad*d"))
    assert not right
    assert "at at" not in text
    assert "Evidence: for at, you printed 1.07" in text, text


@pytest.mark.parametrize(
    "scene, old, new, first",
    [
        # py_teacher 9: vlv reversed.
        (None, "vlv = (lightPos - vertexPos)", "vlv = (vertexPos - lightPos)", "vlv"),
        # Several lights: the loop prints each light's steps together, vov after them.
        ("assets/scenes/three-lights.toml", "vov = np.array([0, 0, 1, 0])", "vov = np.array([0, 0.6, 0.8, 0])", "vov"),
    ],
)
def test_the_self_check_and_the_command_line_agree_on_the_saved_notebook(cli, tmp_path, scene, old, new, first):
    # The check cell uncommented, run all, saved, checked by the command line.
    from conftest import ROOT

    nbclient = pytest.importorskip("nbclient")
    nbformat = pytest.importorskip("nbformat")
    path = tmp_path / "hw.ipynb"
    cli("export", "--to", "notebook", "-o", path, *(["--scene", ROOT / scene] if scene else []))
    nb = json.loads(path.read_text())
    changed = 0
    for cell in nb["cells"]:
        source = "".join(cell["source"])
        if old in source:
            cell["source"] = source.replace(old, new)
            changed += 1
    assert changed == 1
    last = nb["cells"][-1]
    last["source"] = "".join(last["source"])[2:]
    notebook = nbformat.reads(json.dumps(nb), as_version=4)
    nbclient.NotebookClient(notebook, timeout=120, kernel_name="python3").execute()
    own = "".join(o.get("text", "") for o in notebook.cells[-1].outputs if o.get("output_type") == "stream")
    path.write_text(nbformat.writes(notebook))
    try:
        cli("check", path)
        said = None
    except subprocess.CalledProcessError as e:
        said = e.stdout
    assert said is not None, "phonglab check found the mistake right"
    assert "not checked whole" not in said, said
    assert f"first wrong step: {first} " in own and f"first wrong step: {first} " in said, (own, said)
    # The same table, line for line, after the command line's scene line.
    assert said.split("\n", 1)[1] == own, (said, own)


def run_skipping(cells, skipped):
    """Runs `cells` as Jupyter does, except the cell that starts with `skipped`: a cell
    that then stops with an error (a NameError) is in In, as Jupyter keeps it."""
    ns = {"In": [""]}
    left = [c for c in cells if not c.startswith(skipped)]
    assert len(left) == len(cells) - 1, skipped
    for cell in left:
        ns["In"].append(cell)
        try:
            exec(cell, ns)
        except NameError:
            pass
    return ns


def test_a_skipped_cell_is_not_checked_and_names_what_is_missing(cells):
    # N7: the Iamb cell skipped; the I cell stops with NameError: never "all right".
    ns = run_skipping(cells, "Iamb = ")
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        right = phonglab.check(ns, lang="en")
    text = out.getvalue()
    assert right is False, text
    assert "all right" not in text, text
    assert "not checked: the notebook holds no value for Iamb, I, glColor" in text, text
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        assert phonglab.check(ns, lang="pt-PT") is False
    assert "não verificado: o caderno não tem valor para Iamb, I, glColor" in out.getvalue()


def test_the_self_check_speaks_the_language_set(cells):
    # N3: set_language is the default of check() and of its refusals.
    try:
        phonglab.set_language("pt-BR")
        ns = {"In": [""]}
        for cell in cells:
            ns["In"].append(cell)
            exec(cell, ns)
        out = io.StringIO()
        with contextlib.redirect_stdout(out):
            assert phonglab.check(ns) is True
        assert "tudo certo: todos os passos impressos são os do gabarito" in out.getvalue(), out.getvalue()
        with pytest.raises(phonglab.SceneError, match="nenhuma célula da lista"):
            phonglab.check({"In": [""]})
    finally:
        phonglab.set_language("en")


@pytest.mark.parametrize("given", [globals, "globals", "globals()"])
def test_globals_not_called_is_told_to_pass_globals_call(given):
    # N8: phonglab.check(globals) or check("globals") in Jupyter.
    with pytest.raises(phonglab.SceneError) as e:
        phonglab.check(given)
    assert "pass globals(), with its brackets: phonglab.check(globals())" in str(e.value)
    assert "this Python has none" not in str(e.value)


@pytest.mark.parametrize(
    "lang, label",
    [
        ("en", "the formula with this mistake (a model of it, not your code): "),
        ("pt-PT", "a fórmula com este erro (um modelo dele, não o seu código): "),
        ("pt-BR", "a fórmula com esse erro (um modelo dele, não o seu código): "),
    ],
)
def test_the_mistakes_formula_is_labelled_as_a_model_not_the_students_code(cells, lang, label):
    # N10: the line under "likely cause" is the catalogue's formula, said so.
    right, text = run(mistaken(cells, VECTORS, "pass"), lang=lang)
    assert not right
    lines = text.splitlines()
    formulas = [line.strip() for line in lines if line.strip().startswith(label)]
    assert formulas, text
    assert formulas[0] == label + "# vlv = vlv/np.linalg.norm(vlv)", text


def test_the_vectors_cell_run_twice_is_named_with_what_to_do(cells):
    # N9: a correct notebook whose vectors cell ran twice: named, with Restart & Run All.
    k = next(i for i, c in enumerate(cells) if VECTORS in c)
    right, text = run(cells[: k + 1] + [cells[k]] + cells[k + 1 :])
    assert not right
    assert "likely cause: the normal looks transformed twice" in text, text
    assert "[vectors-cell-run-twice]" in text and "Restart & Run All" in text, text
    assert "no mistake in the catalogue" not in text, text
    # A normal transformed twice alone (not the whole cell) is not this cause.
    right, text = run(mistaken(cells, "vertexNormal = np.matmul(mview, vertexNormal)", "vertexNormal = np.matmul(mview, np.matmul(mview, vertexNormal))"))
    assert not right and "[vectors-cell-run-twice]" not in text, text
