"""1 000 random scenes: phonglab.light against the command line's `phonglab eval`."""

import json

import numpy as np

import phonglab

COUNT = 1000


def rows(m):
    return "[" + ", ".join("[" + ", ".join(repr(float(x)) for x in r) + "]" for r in m) + "]"


def vec(v):
    return "[" + ", ".join(repr(float(x)) for x in v) + "]"


def random_case(rng, k):
    """One random scene: (its scene file text, the same scene as a glref case)."""
    q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    m = np.eye(4)
    m[:3, :3], m[:3, 3] = q, rng.uniform(-3, 3, 3) + [0, 0, -8]
    normal = rng.normal(size=3)
    normal /= np.linalg.norm(normal)
    vertex = [*rng.uniform(-1, 1, 3), 1.0]
    colour = lambda: [*rng.uniform(0, 1, 3), 1.0]  # noqa: E731
    material = dict(ambient=colour(), diffuse=colour(), specular=colour(), emission=[*rng.uniform(0, 0.2, 3), 1.0],
                    shininess=float(rng.uniform(0, 128)))
    lights = []
    for _ in range(int(rng.integers(1, 4))):
        w = float(rng.integers(0, 2))
        spot = rng.random() < 0.3
        lights.append(dict(
            position=[*rng.uniform(-10, 10, 3), w], ambient=colour(), diffuse=colour(), specular=colour(),
            spot_direction=list(rng.normal(size=3)), spot_cutoff=float(rng.uniform(5, 90)) if spot else 180.0,
            spot_exponent=float(rng.uniform(0, 64)) if spot else 0.0,
            attenuation=[1.0, float(rng.uniform(0, 0.2)), float(rng.uniform(0, 0.05))] if w else [1.0, 0.0, 0.0]))
    local = bool(rng.random() < 0.5)
    scene_ambient = [*rng.uniform(0, 0.3, 3), 1.0]
    toml = [f'name = "random {k}"', 'rules = "opengl"', 'normals = "as-is"', "[light_model]",
            f"ambient = {vec(scene_ambient)}", f"local_viewer = {str(local).lower()}",
            "[camera]", 'kind = "matrix"', f"rows = {rows(m)}", "[material]"]
    toml += [f"{key} = {vec(v) if isinstance(v, list) else repr(v)}" for key, v in material.items()]
    for light in lights:
        toml.append("[[lights]]")
        toml += [f"{key} = {vec(v) if isinstance(v, list) else repr(v)}" for key, v in light.items()]
        toml.append('placement = "eye"')
    toml += ["[vertex]", f"position = {vec(vertex)}", f"normal = {vec(normal)}"]
    case = dict(
        id=f"r{k}", modelview=m.tolist(), light_modelview=np.eye(4).tolist(), vertex=vertex, normal=list(normal),
        lights=[dict({key: v for key, v in light.items() if key != "attenuation"},
                     constant_attenuation=light["attenuation"][0], linear_attenuation=light["attenuation"][1],
                     quadratic_attenuation=light["attenuation"][2]) for light in lights],
        material=dict(material, name="random"), light_model_ambient=scene_ambient, local_viewer=local,
        two_sided=False, separate_specular=False, normalize=False, rescale_normal=False)
    return "\n".join(toml) + "\n", case


def test_a_thousand_random_scenes_agree_with_the_command_lines_eval(tmp_path, cli):
    rng = np.random.default_rng(58)
    made = [random_case(rng, k) for k in range(COUNT)]
    cases = tmp_path / "cases.json"
    cases.write_text(json.dumps({"cases": [case for _, case in made]}))
    results = json.loads(cli("eval", cases, "--precision", "f64").stdout)["results"]
    assert len(results) == COUNT
    spots = 0
    for (toml, case), result in zip(made, results):
        assert result["id"] == case["id"]
        lit = phonglab.light(phonglab.Scene.from_toml(toml))
        # rgb: the worked calculation prints I as the worksheet does, its fourth number 0.
        assert list(lit.I[:3]) == result["front"][:3], case["id"]  # the same engine: bit for bit
        spots += any(light["spot_cutoff"] != 180 for light in case["lights"])
    assert spots > 100  # spotlights among them
