"""Scenes: made, edited as NumPy arrays, checked as the app checks them, saved and read back."""

import numpy as np
import pytest

import phonglab


def test_scene_error_is_a_value_error():
    assert issubclass(phonglab.SceneError, ValueError)


def test_lights_and_material_are_numpy_arrays_that_can_be_set():
    scene = phonglab.Scene.worksheet(5)
    assert len(scene.lights) == 1
    assert list(scene.lights[0].position) == [0, 0, 90, 1]
    scene.lights[0].position = np.array([0, 0, 45, 1])
    assert list(scene.lights[0].position) == [0, 0, 45, 1]
    scene.material.shininess = 10
    assert scene.material.shininess == 10.0
    assert phonglab.light(scene).I[0] != phonglab.light(phonglab.Scene.worksheet(5)).I[0]


@pytest.mark.parametrize(
    "field, value, message",
    [
        ("position", [0, 0, np.nan, 1], r"lights\[0\]\.position\[2\] must be a finite number, not NaN"),
        ("position", [0, 0, 1], "position: 3 numbers given, 4 expected"),
        ("spot_cutoff", 120, "spot"),
    ],
)
def test_bad_values_raise_scene_error_with_the_message_and_change_nothing(field, value, message):
    scene = phonglab.Scene.worksheet(5)
    before = scene.to_toml()
    with pytest.raises(phonglab.SceneError, match=message):
        setattr(scene.lights[0], field, value)
    assert scene.to_toml() == before


def test_the_file_message_is_the_command_lines(tmp_path, cli):
    bad = tmp_path / "bad.toml"
    bad.write_text('rules = "worksheet"\n[material]\nshininess = 200\n')
    with pytest.raises(phonglab.SceneError) as raised:
        phonglab.Scene.load(bad)
    import subprocess

    with pytest.raises(subprocess.CalledProcessError) as failed:
        cli("explain", bad)
    ours = str(raised.value).split(": ", 1)[1]
    assert ours in failed.value.stderr, (ours, failed.value.stderr)


def test_unknown_names_are_refused_naming_the_values_taken():
    with pytest.raises(phonglab.SceneError, match='preset="nope": the values it takes are worksheet, phong-demo'):
        phonglab.Scene.preset("nope")
    with pytest.raises(phonglab.SceneError, match="worksheet=6"):
        phonglab.Scene.worksheet(6)
    with pytest.raises(phonglab.SceneError, match="there is no light 3"):
        phonglab.Scene.worksheet(5)._inner.get("light.3.position")


def test_save_then_load_gives_the_same_scene(tmp_path):
    scene = phonglab.Scene.preset("phong-demo")
    scene.material.diffuse = [0.5, 0.25, 0.125, 1]
    path = tmp_path / "s.toml"
    scene.save(path)
    again = phonglab.Scene.load(path)
    assert again.to_toml() == scene.to_toml()
    assert list(again.material.diffuse) == [0.5, 0.25, 0.125, 1]
    assert [p.name for p in tmp_path.iterdir()] == ["s.toml"]  # no temporary file left


def test_shader_and_share_link_are_the_command_lines(cli):
    scene = phonglab.Scene.preset("worksheet")
    assert phonglab.shader(scene) == cli("shader").stdout
    assert phonglab.shader(scene, target="wgsl", shading="phong") == cli("shader", "--target", "wgsl", "--shading", "phong").stdout
    assert phonglab.share_link(scene) == cli("share").stdout.strip()
    with pytest.raises(phonglab.SceneError, match='target="hlsl"'):
        phonglab.shader(scene, target="hlsl")


def test_a_notebook_read_back_is_the_scene_it_was_written_from(tmp_path, cli):
    path = tmp_path / "w.ipynb"
    cli("export", "--to", "notebook", "-o", path)
    scene = phonglab.Scene.from_notebook(path)
    assert list(phonglab.light(scene).I) == list(phonglab.light(phonglab.Scene.worksheet(5)).I)
    assert list(scene.lights[0].position) == [0, 0, 90, 1]


def test_a_scene_can_be_renamed_for_what_it_is_now():
    # N6: a worksheet scene given another modelview keeps its name until renamed.
    s = phonglab.Scene.worksheet(5)
    s.modelview = phonglab.Scene.worksheet(3).modelview
    assert s.name == phonglab.Scene.worksheet(5).name
    s.name = "mview3's camera"
    assert s.name == "mview3's camera"
    assert repr(s) == "phonglab.Scene(\"mview3's camera\")"
    assert phonglab.Scene.load(phonglab.share_link(s)).name == "mview3's camera"
    assert "mview3's camera" in s.to_toml()
    with pytest.raises(phonglab.SceneError, match="not a text"):
        s.name = 3
    assert s.name == "mview3's camera"
