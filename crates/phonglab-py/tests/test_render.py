"""phonglab.render and probe against `phonglab render` and `phonglab probe`."""

import json

import numpy as np
import pytest

import phonglab
from conftest import read_png


@pytest.mark.parametrize("preset, object, shading", [("worksheet", "teapot", "phong"), ("phong-demo", "sphere", "gouraud"), ("worksheet", "sphere", "flat")])
def test_render_is_the_command_lines_png_pixel_for_pixel(preset, object, shading, tmp_path, cli):
    out = tmp_path / "cli.png"
    cli("render", "--preset", preset, "--object", object, "--shading", shading, "--size", 96, "-o", out)
    ours = phonglab.render(phonglab.Scene.preset(preset), object=object, shading=shading, size=96)
    assert ours.shape == (96, 96, 4) and ours.dtype == np.uint8
    theirs = read_png(out)
    assert (ours != theirs).sum() == 0
    assert len(np.unique(ours.reshape(-1, 4), axis=0)) > 20  # a picture, not a flat colour
    assert ours._repr_png_().startswith(b"\x89PNG")


def test_probe_is_the_command_lines_json(cli):
    ours = phonglab.probe(phonglab.Scene.preset("worksheet"), 48, 48, object="sphere", size=96)
    theirs = json.loads(cli("probe", "--object", "sphere", "--size", 96, "--at", "48,48", "--json").stdout)
    assert ours == theirs and ours["covered"]
    assert phonglab.probe(phonglab.Scene.preset("worksheet"), 0, 0, object="sphere", size=96)["covered"] is False


def test_a_bad_name_or_size_is_refused():
    scene = phonglab.Scene.worksheet(5)
    with pytest.raises(phonglab.SceneError, match='object="cube"'):
        phonglab.render(scene, object="cube", size=8)
    with pytest.raises(phonglab.SceneError, match="size=0"):
        phonglab.render(scene, size=0)
