"""Every error a user can cause is a phonglab.SceneError saying what was wrong and what to
do, in the language asked; values that are not real, finite numbers are refused, never
coerced."""

import os
import subprocess
import sys
import traceback

import numpy as np
import pytest

import phonglab


@pytest.fixture(autouse=True)
def english():
    """Each test starts (and leaves the process) in English."""
    phonglab.set_language("en")
    yield
    phonglab.set_language("en")


def test_the_class_is_shown_as_phonglab_scene_error_and_the_traceback_ends_at_the_users_line():
    assert phonglab.SceneError.__module__ == "phonglab" and phonglab.SceneError.__name__ == "SceneError"
    scene = phonglab.Scene.worksheet(5)
    try:
        scene.material.shininess = 200
    except phonglab.SceneError as e:
        shown = "".join(traceback.format_exception(type(e), e, e.__traceback__))
    assert "phonglab.SceneError: material.shininess = 200 is out of range" in shown, shown
    assert "_inner.set" not in shown and "__cause__" not in shown, shown


@pytest.mark.parametrize(
    "value",
    ["25", "25,6", True, np.bool_(False), 1 + 2j, None, object(), ["1", "2"], np.array(["3"])],
    ids=["str", "comma", "bool", "np.bool", "complex", "None", "object", "str list", "str array"],
)
def test_a_value_that_is_not_a_real_number_is_refused_not_coerced(value):
    scene = phonglab.Scene.worksheet(5)
    before = scene.to_toml()
    with pytest.raises(phonglab.SceneError, match=r"material.shininess = .*: not a number"):
        scene.material.shininess = value
    assert scene.to_toml() == before


def test_a_decimal_comma_is_refused_saying_how_python_writes_the_number():
    with pytest.raises(phonglab.SceneError, match=r"""material.shininess = '25,6': not a number.*write 25.6, not "25,6\""""):
        phonglab.Scene.worksheet(5).material.shininess = "25,6"


@pytest.mark.parametrize(
    "value",
    ["0 0 90 1", [True, 0, 90, 1], ["0", "0", "90", "1"], np.array([0, 0, 90, 1], dtype=complex), np.array([0, 0, 90, 1], dtype=object)],
)
def test_a_position_that_is_not_real_numbers_is_refused(value):
    with pytest.raises(phonglab.SceneError, match=r"lights\[0\].position = .*: not a number"):
        phonglab.Scene.worksheet(5).lights[0].position = value


def test_numpy_numbers_and_ints_are_taken():
    scene = phonglab.Scene.worksheet(5)
    scene.material.shininess = np.float32(25.5)
    scene.lights[0].position = [np.int64(0), 0, np.float64(45), 1]
    assert scene.material.shininess == 25.5 and list(scene.lights[0].position) == [0, 0, 45, 1]


def test_the_wrong_count_names_the_field_and_none_is_not_a_number():
    scene = phonglab.Scene.worksheet(5)
    with pytest.raises(phonglab.SceneError, match=r"^lights\[0\].position: 3 numbers given, 4 expected"):
        scene.lights[0].position = [0, 0, 1]
    with pytest.raises(phonglab.SceneError, match=r"lights\[0\].position = None: not a number"):
        scene.lights[0].position = None


def test_the_vertex_position_takes_x_y_z_as_light_does():
    scene = phonglab.Scene.worksheet(5)
    scene.vertex.position = [1, 2, 3]
    assert list(scene.vertex.position) == [1, 2, 3, 1]
    assert list(phonglab.light(scene).I) == list(phonglab.light(phonglab.Scene.worksheet(5), vertex=[1, 2, 3]).I)


def test_a_vertex_at_infinity_is_explained_with_w_0():
    lit = phonglab.light(phonglab.Scene.worksheet(5), vertex=[1, 2, 3, 0])
    assert lit.vertexPos[3] == 0 and "vertexPos = [1 3.4 1.2 0]" in lit.explain()


def test_numbers_given_as_text_to_light_and_the_worksheet_are_refused():
    scene = phonglab.Scene.worksheet(5)
    with pytest.raises(phonglab.SceneError, match=r"light\(vertex=\) = '1, 2, 3': not a number"):
        phonglab.light(scene, vertex="1, 2, 3")
    with pytest.raises(phonglab.SceneError, match=r"Scene.worksheet\(n\) = 'five': not a whole number"):
        phonglab.Scene.worksheet("five")
    with pytest.raises(phonglab.SceneError, match=r"Scene.worksheet\(n\) = 2.0: not a whole number"):
        phonglab.Scene.worksheet(2.0)


def test_a_file_name_given_for_a_scene_says_how_to_make_one():
    with pytest.raises(phonglab.SceneError, match=r"light\(scene\): 'worksheet.toml' is not a phonglab.Scene; make one first: phonglab.Scene.load"):
        phonglab.light("worksheet.toml")
    with pytest.raises(phonglab.SceneError, match=r"render\(scene\): .* is not a phonglab.Scene"):
        phonglab.render(None)


def test_sizes_and_pixels_out_of_range_are_scene_errors():
    scene = phonglab.Scene.worksheet(5)
    with pytest.raises(phonglab.SceneError, match=r"size=-5: the values it takes are 1 \.\.\. 8192"):
        phonglab.render(scene, size=-5)
    with pytest.raises(phonglab.SceneError, match=r"size=.*: not a whole number"):
        phonglab.render(scene, size="64")
    with pytest.raises(phonglab.SceneError, match=r'x, y = "-1, 5": the values it takes are 0 \.\.\. 511'):
        phonglab.probe(scene, -1, 5)
    with pytest.raises(phonglab.SceneError, match=r'x, y = "1, 99999999999999999999": the values it takes are 0 \.\.\. 63'):
        phonglab.probe(scene, 1, 99999999999999999999, size=64)


def test_a_light_the_scene_does_not_have_says_how_many_it_has():
    lights = phonglab.Scene.worksheet(5).lights
    with pytest.raises(phonglab.SceneError, match="there is no light 1: the scene has 1 light, numbered 0") as raised:
        lights[1]
    assert isinstance(raised.value, IndexError)
    assert len(lights) == 1 and len(list(lights)) == 1 and lights[-1].position[2] == 90
    with pytest.raises(phonglab.SceneError, match="scene.lights has no append: the lights are the scene's"):
        lights.append(lights[0])


def test_a_misspelt_name_says_the_likeliest_one():
    scene = phonglab.Scene.worksheet(5)
    with pytest.raises(phonglab.SceneError, match="material has no shinyness: did you mean shininess?") as raised:
        scene.material.shinyness = 10
    assert isinstance(raised.value, AttributeError)
    with pytest.raises(phonglab.SceneError, match="Lighting has no cos_theta: did you mean cosTheta?"):
        phonglab.light(scene).cos_theta
    assert not hasattr(scene.material, "shinyness") and getattr(scene.material, "nope", 7) == 7


def test_refusals_are_in_the_language_set_with_the_command_lines_words(cli):
    phonglab.set_language("pt-PT")
    assert phonglab.language() == "pt-PT"
    scene = phonglab.Scene.worksheet(5)
    with pytest.raises(phonglab.SceneError, match="material.shininess = 200 está fora do intervalo"):
        scene.material.shininess = 200
    with pytest.raises(phonglab.SceneError, match="foram dados 3 números, esperavam-se 4"):
        scene.material.diffuse = [1, 1, 1]
    phonglab.set_language("pt-BR")
    with pytest.raises(phonglab.SceneError, match="não existe a luz 2: a cena tem 1 luz"):
        scene.lights[2]
    with pytest.raises(phonglab.SceneError, match="não é um número"):
        scene.material.shininess = "x"
    with pytest.raises(phonglab.SceneError, match='lang="fr"'):
        phonglab.set_language("fr")


def test_the_modelview_can_be_set_from_python():
    scene = phonglab.Scene.worksheet(5)
    m3 = phonglab.Scene.worksheet(3).modelview
    assert m3.shape == (4, 4) and not np.array_equal(m3, scene.modelview)
    scene.modelview = m3
    np.testing.assert_array_equal(scene.modelview, m3)
    np.testing.assert_allclose(phonglab.light(scene).I, phonglab.light(phonglab.Scene.worksheet(3)).I, rtol=0, atol=1e-12)
    scene.modelview = np.eye(4)
    assert np.array_equal(scene.modelview, np.eye(4))
    with pytest.raises(phonglab.SceneError, match="modelview: 9 numbers given, 16 expected"):
        scene.modelview = np.eye(3)
    with pytest.raises(phonglab.SceneError, match=r"camera.matrix\[0\] must be a finite number, not NaN"):
        scene.modelview = np.full((4, 4), np.nan)
    assert np.array_equal(scene.modelview, np.eye(4))


@pytest.mark.parametrize(
    "positions, normals, message",
    [
        ([[0, 0, np.nan]], [[0, 0, 1]], r"light_many\(positions\): row 0 is \[0, 0, NaN\]: every number must be finite"),
        ([[0, 0, 0], [1e39, 0, 0]], [[0, 0, 1]] * 2, r"light_many\(positions\): row 1 is \[inf, 0, 0\]"),
        ([[0, 0, 0]], [[np.nan, 0, 1]], r"light_many\(normals\): row 0 is \[NaN, 0, 1\]"),
        ("0,0,0", "0,0,1", r"light_many\(positions\) = '0,0,0': not a number"),
        (np.array([[0, 0, 0]], dtype=object), [[0, 0, 1]], r"light_many\(positions\) = dtype\('O'\): not a number"),
        ([[True, False, True]], [[0, 0, 1]], r"light_many\(positions\) = dtype\('bool'\): not a number"),
        (np.zeros((1, 3), complex), [[0, 0, 1]], r"light_many\(positions\) = dtype\('complex128'\): not a number"),
        (np.zeros(3), np.zeros(3), r"light_many\(positions\): an array of shape \(3,\), where \(N, 3\) is expected"),
    ],
)
def test_light_many_refuses_what_light_refuses(positions, normals, message):
    with pytest.raises(phonglab.SceneError, match=message):
        phonglab.light_many(phonglab.Scene.worksheet(5), positions, normals)


def test_light_many_out_of_memory_is_a_memory_error_not_an_abort():
    # The address space is capped just above what the inputs take, so that the core's own
    # arrays cannot be had: Python's MemoryError, the process alive to say so.
    code = """
import resource, numpy as np, phonglab
from phonglab import _core
n = 20_000_000
p = np.zeros((n, 3), '<f4').tobytes(); q = np.zeros((n, 3), '<f4').tobytes()
scene = phonglab.Scene.worksheet(5)
size = int(open('/proc/self/status').read().split('VmSize:')[1].split()[0]) * 1024
resource.setrlimit(resource.RLIMIT_AS, (size + (300 << 20), resource.RLIM_INFINITY))
try:
    _core.light_many(scene._inner, p, q, ([n, 3], [n, 3]))
    print('lit')
except MemoryError as e:
    print('MemoryError:', e)
"""
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=dict(os.environ, RAYON_NUM_THREADS="1"))
    assert run.returncode == 0, (run.returncode, run.stderr[-2000:])
    assert run.stdout.startswith("MemoryError: not enough memory: 240000000 bytes could not be had"), run.stdout


def test_light_many_alpha_is_opengls_and_the_docstrings_say_how_it_differs_from_the_worksheets_I():
    scene = phonglab.Scene.worksheet(5)
    scene.material.diffuse = [0.4, 0.3, 0.2, 0.75]
    colours = phonglab.light_many(scene, [scene.vertex.position[:3]], [scene.vertex.normal])
    assert colours[0, 3] == np.float32(0.75)  # glColor's alpha: the material's diffuse alpha
    assert phonglab.light(scene).I[3] == 0  # the worksheet's formula's fourth component
    assert "alpha" in phonglab.light_many.__doc__ and "I[3]" in phonglab.light_many.__doc__


@pytest.mark.parametrize(
    "base",
    ["javascript:alert(1)//", "data:text/html,x", "https://a.b/\x1b[2J", 'https://a.b/"onmouseover=x', "not a url", "https://", "ftp://a.b/"],
)
def test_share_link_refuses_a_base_that_is_not_a_web_address(base):
    with pytest.raises(phonglab.SceneError, match="must be an http:// or https:// address") as raised:
        phonglab.share_link(phonglab.Scene.worksheet(5), base)
    assert "\x1b" not in str(raised.value)


def test_share_link_takes_an_http_address():
    link = phonglab.share_link(phonglab.Scene.worksheet(5), "http://localhost:8000/phonglab/")
    assert link.startswith("http://localhost:8000/phonglab/#v1")


def test_a_crop_or_a_channel_of_a_picture_is_a_true_png_or_none(tmp_path):
    from conftest import read_png

    def decoded(png):
        (tmp_path / "p.png").write_bytes(png)
        return read_png(tmp_path / "p.png")

    pic = phonglab.render(phonglab.Scene.worksheet(5), size=8)
    np.testing.assert_array_equal(decoded(pic[:, :, :3]._repr_png_())[:, :, :3], pic[:, :, :3])
    np.testing.assert_array_equal(decoded(pic[2:5, 1:7]._repr_png_()), pic[2:5, 1:7])
    np.testing.assert_array_equal(decoded(pic[::-1]._repr_png_()), pic[::-1])
    assert pic[0]._repr_png_() is None and pic.T._repr_png_() is None and pic[:, :, 0]._repr_png_() is None


def test_the_package_shows_its_own_names_and_a_version():
    names = dir(phonglab)
    assert "Scene" in names and "light_many" in names and "__version__" in names
    assert not {"np", "json", "os", "tempfile", "Any", "Dict"} & set(names)
    assert phonglab.__version__ == "0.1.0"


def test_vector_lengths_take_what_the_worksheet_writes_and_hint_the_rest():
    # N5: normals as the worksheet writes them, (x, y, z, 0); the hints a short value needs.
    s = phonglab.Scene.worksheet(5)
    s.vertex.normal = [0, 0, 1, 0]
    assert s.vertex.normal.tolist() == [0.0, 0.0, 1.0]
    lit = phonglab.light(s, normal=[0, 1, 0, 0])
    assert lit.explain() != phonglab.light(s).explain()
    cases = [
        (lambda: setattr(s.vertex, "normal", [0, 0, 1, 1]), "vertex.normal: 4 numbers given, 3 expected; a normal is a direction"),
        (lambda: phonglab.light(s, normal=[0, 0, 1, 1]), "light(normal=): 4 numbers given, 3 expected; a normal is a direction"),
        (lambda: setattr(s.lights[0], "position", [0, 0, 90]), "lights[0].position: 3 numbers given, 4 expected; a light's position is x, y, z, w: w = 1"),
        (lambda: setattr(s.material, "diffuse", [0.8, 0.2, 0.2]), "material.diffuse: 3 numbers given, 4 expected; a colour is r, g, b, a: add its alpha"),
        (lambda: phonglab.light(s, vertex=[1, 2]), "light(vertex=): 2 numbers given, 3 or 4 expected; a vertex is x, y, z"),
        (lambda: setattr(s.lights[0], "diffuse", 0.5), "lights[0].diffuse: 1 number given, 4 expected"),
        (lambda: setattr(s, "material", None), "scene.material is not replaced whole: edit its fields one by one"),
        (lambda: s.lights.__setitem__(0, None), "scene.lights[i] is not replaced whole: edit its fields one by one"),
    ]
    before = s.to_toml()
    for act, said in cases:
        with pytest.raises(phonglab.SceneError) as e:
            act()
        assert said in str(e.value), str(e.value)
    assert s.to_toml() == before
    try:
        phonglab.set_language("pt-PT")
        with pytest.raises(phonglab.SceneError) as e:
            s.lights[0].diffuse = 0.5
        assert "lights[0].diffuse: foi dado 1 número, esperavam-se 4" in str(e.value), str(e.value)
    finally:
        phonglab.set_language("en")
