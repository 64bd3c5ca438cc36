"""The exported notebook's self-check cell, uncommented and run headless by nbclient."""

import json

import pytest

nbclient = pytest.importorskip("nbclient")
nbformat = pytest.importorskip("nbformat")


def exported(cli, tmp_path, lang):
    """The worksheet's notebook as `phonglab export --to notebook` writes it in lang."""
    path = tmp_path / f"worksheet-{lang}.ipynb"
    cli("export", "--to", "notebook", "-o", path, env_lang=lang)
    return json.loads(path.read_text())


def uncommented(nb):
    """The notebook with its last cell, the self-check, uncommented."""
    last = nb["cells"][-1]
    source = "".join(last["source"])
    assert source.startswith("# import phonglab; phonglab.check(globals()"), source
    last["source"] = source[2:]
    return nb


def run(nb):
    """Runs every cell headless; the self-check cell's printed text."""
    notebook = nbformat.reads(json.dumps(nb), as_version=4)
    nbclient.NotebookClient(notebook, timeout=120, kernel_name="python3").execute()
    last = notebook.cells[-1]
    return "".join(o.get("text", "") for o in last.outputs if o.get("output_type") == "stream")


def test_the_exported_notebook_checks_itself_all_right(cli, tmp_path):
    text = run(uncommented(exported(cli, tmp_path, "en")))
    assert "all right: every step printed is the key's" in text
    assert "vlv: yours" in text and "first wrong step" not in text


def test_a_mistake_is_named_with_its_step_in_the_notebooks_language(cli, tmp_path):
    nb = uncommented(exported(cli, tmp_path, "pt-PT"))
    cells = [c for c in nb["cells"] if c["cell_type"] == "code" and "cosTheta" in "".join(c["source"])]
    source = "".join(cells[0]["source"])
    # The mistake: the light vector left unnormalised in the diffuse term.
    assert "max(0, np.dot(vertexNormal, vlv))" in source or "np.dot(vertexNormal, vlv)" in source, source
    cells[0]["source"] = source.replace("np.dot(vertexNormal, vlv)", "np.dot(vertexNormal, 2*vlv)", 1)
    text = run(nb)
    assert "cosTheta" in text and "primeiro passo errado: cosTheta" in text, text


def test_a_given_changed_in_place_is_refused_naming_it():
    """As `phonglab check` refuses it: never checked as a value Python did not use."""
    import phonglab

    code = (
        "import numpy as np\nvertexPos = np.array([-512, -384, 0, 1])\n"
        "lightPos = np.array([0, 0, 45, 1])\nlightPos[2] *= 2\n"
    )
    with pytest.raises(phonglab.SceneError, match=r"changed in place.*lightPos \(line 4\)"):
        phonglab.check({"In": [code]})


def test_the_check_cell_shows_its_table_and_no_bare_true_or_false(cli, tmp_path):
    # N11: the cell's `;` keeps Jupyter from showing check()'s return value under the table.
    nb = uncommented(exported(cli, tmp_path, "en"))
    assert "".join(nb["cells"][-1]["source"]).rstrip().endswith(";")
    notebook = nbformat.reads(json.dumps(nb), as_version=4)
    nbclient.NotebookClient(notebook, timeout=120, kernel_name="python3").execute()
    kinds = [o.get("output_type") for o in notebook.cells[-1].outputs]
    assert kinds == ["stream"], notebook.cells[-1].outputs

