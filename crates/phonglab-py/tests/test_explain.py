"""The worked calculation a student reads: what was computed (not the scene as it is now),
each light's steps, and the notebook's displays in the student's language."""

import re
import warnings

import numpy as np
import pytest

import phonglab
from conftest import ROOT


def test_explain_shows_the_calculation_made_not_the_scene_changed_since():
    # py_hostile D14.
    scene = phonglab.Scene.worksheet(5)
    lit = phonglab.light(scene)
    before = lit.explain()
    scene.lights[0].position = [0, 0, -500, 1]
    assert lit.explain() == before
    i_line = next(line for line in before.splitlines() if line.strip().startswith("I = "))
    shown = [float(x) for x in i_line.split("[")[1].rstrip("]").split()]
    np.testing.assert_allclose(shown, lit.I, rtol=1e-7)
    assert lit._repr_html_() == phonglab.light(phonglab.Scene.worksheet(5))._repr_html_()
    assert not np.allclose(phonglab.light(scene).I, lit.I)


def test_with_several_lights_a_step_is_a_list_one_value_per_light():
    # py_teacher 5: lit.vlv, as the notebook holds it; per_light by the worksheet's names.
    scene = phonglab.Scene.load(ROOT / "assets/scenes/three-lights.toml")
    lit = phonglab.light(scene)
    n = len(scene.lights)
    assert n > 1
    assert isinstance(lit.vlv, list) and len(lit.vlv) == n
    for k in range(n):
        np.testing.assert_array_equal(lit.vlv[k], lit.steps[f"vlv[{k}]"])
        np.testing.assert_array_equal(lit.per_light[k]["vlv"], lit.vlv[k])
        assert f"vlv[{k}]" not in lit.per_light[k]
    assert not np.allclose(lit.vlv[0], lit.vlv[1])
    # A step of the vertex is one array still.
    assert isinstance(lit.I, np.ndarray) and lit.I.shape == (4,)


def test_the_html_display_carries_the_text_forms_heading_headers_and_notes():
    # py_teacher 14: headers, the title line, every note; formulas left-aligned, no wrapping in a value.
    scene = phonglab.Scene.worksheet(2)
    lit = phonglab.light(scene, lang="pt-PT")
    html = lit._repr_html_()
    text = lit.explain(lang="pt-PT")
    heading = text.splitlines()[0]
    assert heading in html
    for header in ("<th", "passo", "fórmula", "valor", "notas"):
        assert header in html
    notes = [line.strip()[len("nota: ") :] for line in text.splitlines() if line.strip().startswith("nota: ")]
    assert notes, text
    for note in notes:
        assert note.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;") in html, note
    assert "text-align:left" in html and "white-space:nowrap" in html
    rows = re.findall(r"<tr><td", html)
    assert len(rows) == len(re.findall(r"^\s*\d+\. ", text, re.M))


def test_the_displays_are_in_the_language_and_its_decimal_mark():
    # py_teacher 15: the Markdown header and the values in the student's language.
    lit = phonglab.light(phonglab.Scene.worksheet(5), lang="pt-BR")
    md = lit._repr_markdown_()
    assert "| # | passo | fórmula | valor | observações |" in md, md[:300]
    assert "`vlv = [0,79220526 0,55887606 -0,2450885 0]`" in md
    assert "vlv = [0,79220526 0,55887606 -0,2450885 0]" in lit._repr_html_()
    en = phonglab.light(phonglab.Scene.worksheet(5))
    assert "| # | step | formula | value | notes |" in en._repr_markdown_()
    assert "vlv = [0.79220526 0.55887606 -0.2450885 0]" in en._repr_html_()
    assert "vlv = [0,79220526" in en.explain(lang="pt-PT")


def test_from_notebook_says_what_it_did_not_read_as_import_does(tmp_path, cli):
    # py_hostile D15.
    script = tmp_path / "ws.py"
    script.write_text(
        "import numpy as np\nvertexPos = np.array([-512, -384, 0, 1])\n"
        "vertexNormal = np.array([0, 0, 1, 0])\nlightPos = np.array([0, 0, np.inf, 1])\n"
    )
    said = cli("import", script, "-o", tmp_path / "out.toml").stderr
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        phonglab.Scene.from_notebook(script)
    notices = [str(w.message) for w in caught if issubclass(w.category, phonglab.NotebookNotice)]
    assert notices, said
    assert all(n in said for n in notices), (notices, said)
    assert any("lightPos" in n for n in notices), notices


def test_share_link_refuses_a_page_that_is_not_http_and_takes_the_command_lines_options(cli):
    # py_teacher 8.
    scene = phonglab.Scene.worksheet(5)
    for base in ("not a url", "javascript:alert(1)//", "data:text/html,x", "https://e.org/\x1b[31m", 'https://e.org/"x'):
        with pytest.raises(phonglab.SceneError, match="http:// or https://"):
            phonglab.share_link(scene, base=base)
    link = phonglab.share_link(scene, base="http://localhost:8080/p/", open_in="pt-PT", present=True, channel="diffuse")
    assert link.startswith("http://localhost:8080/p/#v1.")
    with pytest.raises(phonglab.SceneError, match="pt-BR"):
        phonglab.share_link(scene, open_in="fr")
    with pytest.raises(phonglab.SceneError, match="channel="):
        phonglab.share_link(scene, channel="nope")
    path = "scene.toml"
    import os
    import tempfile

    with tempfile.TemporaryDirectory() as d:
        scene.save(os.path.join(d, path))
        same = cli(
            "share", os.path.join(d, path), "--base", "http://localhost:8080/p/", "--open-in", "pt-PT",
            "--present", "--channel", "diffuse",
        ).stdout.strip()
    assert same == link


def test_explain_without_lang_speaks_the_language_set():
    # N3: print(lit.explain()) after set_language("pt-PT").
    lit = phonglab.light(phonglab.Scene.worksheet(5), lang="en")
    try:
        phonglab.set_language("pt-PT")
        assert lit.explain() == lit.explain(lang="pt-PT")
        assert lit.explain() != lit.explain(lang="en")
    finally:
        phonglab.set_language("en")
