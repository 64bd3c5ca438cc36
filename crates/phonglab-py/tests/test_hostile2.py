"""The second hostile review's findings: what a notebook, a link or a memory limit must not
make the package do (write over its input, print raw terminal controls, abort Python, make a
link phonglab will not open)."""

import os
import subprocess
import sys
import textwrap
import warnings

import pytest

import phonglab


def test_a_copy_keeps_where_the_scene_came_from_and_never_saves_over_its_notebook(tmp_path, cli):
    path = tmp_path / "nb.ipynb"
    cli("export", "--to", "notebook", "-o", path)
    before = path.read_bytes()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        scene = phonglab.Scene.from_notebook(path)
    copy = scene.copy()
    with pytest.raises(phonglab.SceneError, match="is the notebook or script .*nb.ipynb"):
        copy.save(path)
    assert path.read_bytes() == before
    copy.material.shininess = 77
    assert scene.material.shininess != 77, "the copy is independent"
    copy.save(tmp_path / "nb.toml")
    assert phonglab.Scene.load(tmp_path / "nb.toml").material.shininess == 77


def test_a_notebooks_notices_write_terminal_controls_visibly(tmp_path):
    path = tmp_path / "w.py"
    path.write_text("matDif = [0.5, 0.5, 0.5, 1]\nlightPos = \x1b]0;pwned\x07\x1b[2J\u202e\n", encoding="utf-8")
    with warnings.catch_warnings(record=True) as seen:
        warnings.simplefilter("always")
        phonglab.Scene.from_notebook(path)
    said = [str(w.message) for w in seen if issubclass(w.category, phonglab.NotebookNotice)]
    assert said, "a line not read is said"
    for text in said:
        for raw in ("\x1b", "\x07", "\u202e"):
            assert raw not in text, repr(text)
    assert any("\\u{1B}]0;pwned\\u{7}" in t for t in said), said


def test_render_past_the_memory_it_can_have_is_a_memory_error_not_an_abort():
    code = textwrap.dedent(
        """
        import resource, phonglab
        resource.setrlimit(resource.RLIMIT_AS, (2_500 << 20, 2_500 << 20))
        try:
            phonglab.render(phonglab.Scene.worksheet(5), size=8192, object="teapot", shading="phong")
            print("rendered")
        except MemoryError as e:
            print("MemoryError:", e)
        """
    )
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr[-2000:]
    out = run.stdout
    assert out.startswith("MemoryError:") and "8192 x 8192" in out and "choose a smaller size" in out, out
    # The estimate said: the command line's for the picture and the mesh, and the picture twice.
    assert "about 1 611 485 696 bytes (1536.8 MiB)" in out, out


def test_a_link_longer_than_phonglab_opens_is_not_made():
    import random

    rng = random.Random(7)
    scene = phonglab.Scene.from_toml('name = "' + "".join(rng.choice("abcdefghij") for _ in range(30_000)) + '"\n')
    with pytest.raises(phonglab.SceneError, match="at most 16384"):
        phonglab.share_link(scene)


def test_a_page_without_a_host_is_refused():
    with pytest.raises(phonglab.SceneError, match="http:// or https://"):
        phonglab.share_link(phonglab.Scene.worksheet(5), base="https:///")
    assert phonglab.share_link(phonglab.Scene.worksheet(5), base="https://e.org/").startswith("https://e.org/#v1.")


class _LieF(float):
    """A float that prints one number and tells float() another."""

    def __float__(self):
        return 25.6


def test_a_setter_reads_the_number_held_not_what_float_is_told():
    scene = phonglab.Scene.worksheet(5)
    scene.material.shininess = _LieF(0.5)
    assert scene.material.shininess == 0.5


@pytest.mark.filterwarnings("ignore::PendingDeprecationWarning")  # np.matrix's own
def test_a_huge_int_and_a_matrix_are_scene_errors_or_read():
    scene = phonglab.Scene.worksheet(5)
    with pytest.raises(phonglab.SceneError, match="position"):
        scene.lights[0].position = [10**400, 0, 0, 1]
    import numpy as np

    scene.lights[0].position = np.matrix([0, 0, 90, 1])
    assert list(scene.lights[0].position) == [0, 0, 90, 1]
    with pytest.raises(phonglab.SceneError, match="shininess"):
        scene.material.shininess = [[25.6]]
    scene.material.shininess = 30
    assert scene.material.shininess == 30


from test_selfcheck import cells, run  # noqa: E402,F401 - the exported notebook's cells, run as Jupyter runs them


def test_the_self_check_refuses_a_complex_value(cells):  # noqa: F811
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no ComplexWarning: the value is not converted
        right, text = run(cells, "Idif = Idif + 1j")
    assert not right, text
    assert "all right" not in text and "Idif" in text, text


def test_the_self_check_reads_the_number_a_float_holds_as_the_command_line_does(cells):  # noqa: F811
    lie = "class F(float):\n    def __float__(self):\n        return 0.13925483454\ncosTheta = F(0.9)\n"
    right, text = run(cells, lie)
    assert not right, text
    assert "first wrong step: cosTheta (yours 0.9" in text, text


def test_f32_lighting_past_float32s_range_is_refused_naming_the_step_and_f64_is_not():
    import numpy as np

    scene = phonglab.Scene.worksheet(5)
    scene.material.diffuse = [-3.4e38, -3.4e38, -3.4e38, 1]
    scene.lights[0].diffuse = [3.4e38, 3.4e38, 3.4e38, 1]
    with pytest.raises(phonglab.SceneError, match=r"in f32: the scene's numbers are past what f32 holds"):
        phonglab.light(scene, precision="f32")
    with pytest.raises(phonglab.SceneError, match=r"row 0 is .*inf.* in f32"):
        phonglab.light_many(scene, np.array([[0.0, 0.0, 0.0]]), np.array([[0.0, 0.0, 1.0]]))
    lit = phonglab.light(scene, precision="f64")
    assert np.all(np.isfinite(lit.I)) and lit.I[0] < -1e70, lit.I


def test_the_self_check_refuses_a_nan_given_naming_it_as_the_command_line_does(cells):  # noqa: F811
    from test_selfcheck import mistaken

    nan = mistaken(cells, "lightPos = np.array([0, 0, 90, 1])", "lightPos = np.array([0, 0, np.nan, 1])")
    with pytest.raises(phonglab.SceneError, match=r"a given is not a finite number \(lightPos"):
        run(nan)


def test_a_step_assigned_again_after_it_was_printed_is_said(cells):  # noqa: F811
    right, text = run(cells, "for I in range(3):\n    pass\n")
    assert "Note: I is assigned again in a cell run after the one that prints it" in text, text
    assert "phonglab check reads the printed one" in text, text
    right, text = run(cells, "for k in range(3):\n    J = k  # I = 1 in a comment\n")
    assert right and "Note:" not in text, text
    _, text = run(cells, "I = 0", lang="pt-PT")
    assert "Nota: I volta a ser atribuído" in text, text
