"""phonglab.light against the worksheet's own printout and the command line's explain."""

import re

import numpy as np
import pytest

import phonglab

STEPS = ["vertexNormal", "vlv", "vov", "Iamb", "cosTheta", "Idif", "H", "vertexPos", "lightPos", "cosBeta", "Ispec", "d", "I"]


def printed(text):
    """NumPy's printout `[0.  0.6 0.8 0. ]` as numbers."""
    return [float(x) for x in text.strip("[]").split()]


@pytest.mark.parametrize("k", [1, 2, 3, 4, 5])
def test_every_modelview_gives_what_the_worksheets_code_prints(k, worksheet_runs):
    run = next(r for r in worksheet_runs if r["mview"] == k)
    lit = phonglab.light(phonglab.Scene.worksheet(k))
    for name in STEPS:
        want = np.array(run["values"][name], dtype=float)  # a scalar step is a scalar
        tol = 1e-7 * float(want) if name == "d" else 1e-7
        got = getattr(lit, name)
        assert got.shape == want.shape, name
        np.testing.assert_allclose(got, want, rtol=0, atol=tol, err_msg=f"mview{k} {name}")
    np.testing.assert_allclose(lit.at, np.atleast_1d(run["values"]["at"]), rtol=1e-7, atol=0, err_msg=f"mview{k} at")
    assert lit.spot is not None and lit.Ilight is not None
    for name, text in run["printed"].items():
        np.testing.assert_allclose(getattr(lit, name), printed(text), rtol=0, atol=1e-8, err_msg=f"printed {name}")


def explained(text):
    """The `name = [a b c d]` lines of `phonglab explain --digits 17`, as numbers."""
    values = {}
    for m in re.finditer(r"^ +(\w+) = (\[[^\]]*\]|\S+)$", text, re.M):
        values.setdefault(m.group(1), [float(x) for x in m.group(2).strip("[]").split()])
    return values


@pytest.mark.parametrize("k", [1, 3, 5])
@pytest.mark.parametrize("precision", ["f64", "f32"])
def test_the_numbers_are_the_command_lines_explain_exactly(k, precision, cli):
    want = explained(cli("explain", "--worksheet", k, "--digits", 17, "--precision", precision).stdout)
    lit = phonglab.light(phonglab.Scene.worksheet(k), precision=precision)
    assert set(want) >= {"vertexNormal", "vlv", "H", "I"}
    for name, values in want.items():
        assert np.atleast_1d(getattr(lit, name)).tolist() == values, name


def test_explain_speaks_the_language_asked_and_jupyter_shows_the_table():
    lit = phonglab.light(phonglab.Scene.worksheet(5))
    assert "Transformed normal" in lit.explain()
    assert "Vetor normal transformado" in lit.explain(lang="pt-PT")
    assert "0,8" in lit.explain(lang="pt-BR")
    md = lit._repr_markdown_()
    assert md.count("\n|") >= 10 and "vertexNormal" in md
    html = lit._repr_html_()
    assert "<table>" in html and "<code>cosTheta = 0.13925483</code>" in html and "0.059587089" in html
    with pytest.raises(phonglab.SceneError, match="lang="):
        lit.explain(lang="fr")


def test_a_vertex_and_normal_given_are_lit_instead_of_the_scenes():
    scene = phonglab.Scene.worksheet(5)
    a = phonglab.light(scene, vertex=[-512, -384, 0], normal=[0, 0, 1])
    assert list(a.I) == list(phonglab.light(scene).I)
    b = phonglab.light(scene, vertex=[0, 0, 0], normal=[0, 1, 0])
    assert b.vertexNormal[1] != a.vertexNormal[1]
    assert list(scene.vertex.position) == [-512, -384, 0, 1]  # the scene itself is unchanged


def test_light_many_is_the_engines_colour_in_f32():
    scene = phonglab.Scene.worksheet(5)
    rng = np.random.default_rng(7)
    p = rng.uniform(-600, 600, (50, 3))
    n = rng.normal(size=(50, 3))
    n /= np.linalg.norm(n, axis=1, keepdims=True)
    many = phonglab.light_many(scene, p, n)
    assert many.shape == (50, 4) and many.dtype == np.float32
    for i in range(0, 50, 7):
        one = phonglab.light(scene, vertex=p[i].astype(np.float32), normal=n[i].astype(np.float32), precision="f32")
        np.testing.assert_allclose(many[i, :3], one.I[:3], rtol=0, atol=2e-6)


def test_scalar_steps_are_scalars_as_the_worksheet_prints_them():
    # N11: cosTheta, d, at print as the worksheet's 0.13925483, not [0.13925483].
    lit = phonglab.light(phonglab.Scene.worksheet(5))
    for name in ["cosTheta", "cosBeta", "d", "at"]:
        value = getattr(lit, name)
        assert isinstance(value, np.float64) and np.ndim(value) == 0, (name, value)
    assert str(lit.cosTheta) == "0.13925483139909867"
    assert lit.I.shape == (4,)
