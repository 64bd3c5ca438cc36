"""phonglab: OpenGL's fixed-function vertex lighting, worked step by step, from Python.

The numbers are phonglab's core's (the Rust crate phonglab-core), the same as the app's and
the command line's; this package converts them to and from NumPy arrays.

    >>> import phonglab
    >>> scene = phonglab.Scene.worksheet(5)
    >>> lit = phonglab.light(scene)
    >>> lit.I            # the vertex's colour, as the worksheet prints it
    >>> print(lit.explain(lang="pt-PT"))
"""

from __future__ import annotations

import json
import os
import tempfile
import warnings
from typing import Any, Dict, List, Optional, Tuple

import numpy as np

from . import _core
from ._core import SceneError
from ._selfcheck import check

__all__ = [
    "Scene",
    "SceneError",
    "NotebookNotice",
    "Lighting",
    "Picture",
    "light",
    "light_many",
    "render",
    "probe",
    "shader",
    "share_link",
    "check",
]

class NotebookNotice(UserWarning):
    """What Scene.from_notebook says of a notebook's line it could not read, or read
    otherwise (the same notices `phonglab import` prints)."""


_LIGHT_FIELDS = (
    "ambient",
    "diffuse",
    "specular",
    "position",
    "spot_direction",
    "spot_cutoff",
    "spot_exponent",
    "attenuation",
)
_MATERIAL_FIELDS = ("ambient", "diffuse", "specular", "emission", "shininess")
_SCALARS = ("spot_cutoff", "spot_exponent", "shininess")


def _numbers(value: Any) -> List[float]:
    return [float(x) for x in np.asarray(value, dtype=np.float64).reshape(-1)]


class _Fields:
    """Named numbers of a scene (a light, the material, the vertex) as NumPy arrays.

    Reading gives a copy; assigning checks the value as the app checks an edit and raises
    SceneError (leaving the scene as it was) when it refuses it."""

    _names: Tuple[str, ...] = ()

    def __init__(self, scene: "Scene", prefix: str) -> None:
        object.__setattr__(self, "_scene", scene)
        object.__setattr__(self, "_prefix", prefix)

    def __getattr__(self, name: str) -> Any:
        if name not in self._names:
            raise AttributeError(name)
        values = self._scene._inner.get(self._prefix + name)
        return values[0] if name in _SCALARS else np.array(values)

    def __setattr__(self, name: str, value: Any) -> None:
        if name not in self._names:
            raise AttributeError(name)
        self._scene._inner.set(self._prefix + name, _numbers(value))

    def __dir__(self) -> List[str]:
        return list(self._names)

    def __repr__(self) -> str:
        fields = ", ".join(f"{n}={getattr(self, n)!r}" for n in self._names)
        return f"{type(self).__name__}({fields})"


class Light(_Fields):
    """One enabled light: ambient, diffuse, specular, position (x, y, z, w), spot_direction,
    spot_cutoff, spot_exponent, attenuation (constant, linear, quadratic)."""

    _names = _LIGHT_FIELDS


class Material(_Fields):
    """The front material: ambient, diffuse, specular, emission (rgba), shininess."""

    _names = _MATERIAL_FIELDS


class Vertex(_Fields):
    """The worked vertex: position (x, y, z, w) and normal (x, y, z), in object space."""

    _names = ("position", "normal")


class Scene:
    """A scene as the app holds it: lights, material, camera, the worked vertex and the
    shaded view. Make one with Scene.load, Scene.worksheet, Scene.preset or
    Scene.from_notebook."""

    def __init__(self, inner: "_core.Scene") -> None:
        self._inner = inner

    @staticmethod
    def load(path: "os.PathLike[str] | str") -> "Scene":
        """Reads a scene file (TOML) as the app and the command line read it."""
        with open(path, encoding="utf-8") as f:
            text = f.read()
        folder = os.path.dirname(os.path.abspath(path))
        try:
            return Scene(_core.Scene.from_toml(text, folder))
        except SceneError as e:
            raise SceneError(f"{os.fspath(path)}: {e}") from None

    @staticmethod
    def from_toml(text: str) -> "Scene":
        """A scene from a scene file's text."""
        return Scene(_core.Scene.from_toml(text))

    @staticmethod
    def worksheet(n: int = 5) -> "Scene":
        """The worksheet's scene with modelview n (1 to 5)."""
        return Scene(_core.Scene.worksheet(int(n)))

    @staticmethod
    def preset(name: str) -> "Scene":
        """A ready-made scene: "worksheet" (the app's start scene) or "phong-demo"."""
        return Scene(_core.Scene.preset(name))

    @staticmethod
    def from_notebook(path: "os.PathLike[str] | str") -> "Scene":
        """The scene a worksheet notebook (.ipynb) or script (.py) sets up, read as the
        app's Import reads it (nothing in it is run). What `phonglab import` says of it (a
        line not read, a given replaced by the worksheet's value) comes as a
        NotebookNotice warning each."""
        with open(path, encoding="utf-8") as f:
            text = f.read()
        name = os.path.basename(os.fspath(path))
        inner, notices = _core.Scene.from_notebook(text, name.endswith(".ipynb"), name)
        # What `phonglab import` says of the lines it could not read, or read otherwise.
        for notice in notices:
            warnings.warn(NotebookNotice(notice), stacklevel=2)
        return Scene(inner)

    def save(self, path: "os.PathLike[str] | str") -> None:
        """Writes the scene file whole or not at all (a temporary file renamed over it)."""
        text = self._inner.to_toml()
        folder = os.path.dirname(os.path.abspath(path))
        fd, tmp = tempfile.mkstemp(dir=folder, prefix=".phonglab-", suffix=".tmp")
        try:
            with os.fdopen(fd, "w", encoding="utf-8") as f:
                f.write(text)
                f.flush()
                os.fsync(f.fileno())
            os.replace(tmp, path)
        except BaseException:
            os.unlink(tmp)
            raise

    def to_toml(self) -> str:
        """The scene file's text."""
        return self._inner.to_toml()

    def copy(self) -> "Scene":
        """An independent copy."""
        return Scene.from_toml(self.to_toml())

    @property
    def name(self) -> str:
        """The scene's title."""
        return self._inner.name

    @property
    def lights(self) -> List[Light]:
        """The enabled lights, in order (GL_LIGHT0 first)."""
        return [Light(self, f"light.{i}.") for i in range(self._inner.light_count())]

    @property
    def material(self) -> Material:
        """The front material."""
        return Material(self, "material.")

    @property
    def vertex(self) -> Vertex:
        """The worked vertex."""
        return Vertex(self, "vertex.")

    def __repr__(self) -> str:
        return f"phonglab.Scene({self.name!r})"


class Lighting:
    """The worked calculation of one vertex, as computed when it was made (a later change
    to the scene does not change it). Each step is an attribute under the worksheet's name
    (vertexNormal, vlv, vov, H, cosTheta, cosBeta, Iamb, Idif, Ispec, at, spot, I)
    holding a NumPy array (4 components, or 1 for a scalar), or None where the step does
    not apply. With several lights, a light's step is a list with one value per light, as
    the worksheet's notebook holds it (lit.vlv[0] is light 0's vlv), and .per_light[k]
    holds light k's steps by their names (lit.per_light[0]["vlv"]).

    In Jupyter it shows as the calculation's table in the language given to light()
    (lang=); explain(lang=...) gives it as text (or Markdown) in any language."""

    def __init__(self, rows: list, text: str, markdown: str, scene: Scene, precision: str, lang: str = "en") -> None:
        self._rows = rows
        self._text, self._markdown = text, markdown
        # The scene as it was: explain() and the displays show this calculation.
        self._scene, self._precision, self._lang = Scene(scene._inner.__copy__()), precision, lang
        self.per_light: Dict[int, Dict[str, Optional[np.ndarray]]] = {}
        self.steps: Dict[str, Any] = {}
        lights = 1 + max((light for *_, light, _shown in rows if light is not None), default=0)
        for name, _title, _formula, value, light, _shown in rows:
            array = None if value is None else np.array(value)
            self.steps.setdefault(name, array)
            if light is None:
                continue
            base = name.split("[", 1)[0]
            self.per_light.setdefault(light, {}).setdefault(base, array)
            if base != name:
                # `vlv[1]`: the list `vlv`, one value per light, as the notebook holds it.
                per = self.steps.setdefault(base, [None] * lights)
                if isinstance(per, list) and per[light] is None:
                    per[light] = array

    def __getattr__(self, name: str) -> Any:
        steps = self.__dict__.get("steps", {})
        if name in steps:
            return steps[name]
        raise AttributeError(name)

    def __dir__(self) -> List[str]:
        return list(self.steps) + ["explain", "steps", "per_light"]

    def explain(self, lang: str = "en", markdown: bool = False) -> str:
        """The worked calculation as text (or Markdown) in lang: "en", "pt-PT" or "pt-BR"
        (its words and its decimal mark)."""
        text, md, _html = _core.explain_tables(self._scene._inner, self._precision, lang)
        return md if markdown else text

    def _repr_markdown_(self) -> str:
        return _core.explain_tables(self._scene._inner, self._precision, self._lang)[1]

    def _repr_html_(self) -> str:
        return _core.explain_tables(self._scene._inner, self._precision, self._lang)[2]

    def __repr__(self) -> str:
        return self._text


def light(
    scene: Scene,
    vertex: Any = None,
    normal: Any = None,
    precision: str = "f64",
    lang: str = "en",
) -> Lighting:
    """Lights the scene's vertex (or vertex/normal, in object space) step by step as the
    worksheet does; precision "f64" or "f32"."""
    if vertex is not None or normal is not None:
        scene = scene.copy()
        if vertex is not None:
            v = _numbers(vertex)
            scene.vertex.position = v + [1.0] if len(v) == 3 else v
        if normal is not None:
            scene.vertex.normal = normal
    rows, text, markdown = _core.light(scene._inner, precision, lang)
    return Lighting(rows, text, markdown, scene, precision, lang)


def light_many(scene: Scene, positions: Any, normals: Any) -> np.ndarray:
    """Lights N vertices ((N, 3) positions and normals, object space) through phonglab's
    specialised lighter in float32, without holding the GIL: (N, 4) float32 colours
    (primary + secondary, unclamped; alpha the material's)."""
    p = np.ascontiguousarray(positions, dtype="<f4")
    n = np.ascontiguousarray(normals, dtype="<f4")
    out = _core.light_many(scene._inner, p.tobytes(), n.tobytes(), (list(p.shape), list(n.shape)))
    return np.frombuffer(out, dtype="<f4").reshape(-1, 4).copy()


class Picture(np.ndarray):
    """An (H, W, 4) uint8 RGBA picture that Jupyter shows as a PNG."""

    def _repr_png_(self) -> bytes:
        import struct
        import zlib

        h, w = self.shape[:2]
        raw = b"".join(b"\x00" + self[y].tobytes() for y in range(h))

        def chunk(kind: bytes, data: bytes) -> bytes:
            body = kind + data
            return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))

        header = struct.pack(">IIBBBBB", w, h, 8, 6, 0, 0, 0)
        return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b"")


def render(
    scene: Scene,
    object: Optional[str] = None,
    shading: Optional[str] = None,
    size: int = 512,
) -> Picture:
    """The shaded view as `phonglab render` draws it: an (H, W, 4) uint8 array.
    object: "sphere", "teapot" or "cylinder"; shading: "gouraud", "phong" or "flat"
    (default: the scene's)."""
    rgba, w, h = _core.render(scene._inner, object, shading, int(size))
    return np.frombuffer(rgba, dtype=np.uint8).reshape(h, w, 4).copy().view(Picture)


def probe(
    scene: Scene,
    x: int,
    y: int,
    object: Optional[str] = None,
    shading: Optional[str] = None,
    size: int = 512,
) -> Dict[str, Any]:
    """Why pixel (x, y) of render(scene, object, shading, size) is its colour: the numbers
    `phonglab probe --json` prints, as a dict ({"covered": False, ...} off the object)."""
    return json.loads(_core.probe(scene._inner, int(x), int(y), object, shading, int(size)))


def shader(scene: Scene, target: str = "glsl", shading: str = "gouraud") -> str:
    """The program ("glsl" or "wgsl"; "gouraud" or "phong") that draws the scene's view."""
    return _core.shader(scene._inner, target, shading)


def share_link(
    scene: Scene,
    base: Optional[str] = None,
    open_in: Optional[str] = None,
    present: bool = False,
    channel: Optional[str] = None,
) -> str:
    """The scene as a link that opens it in phonglab's browser build, as `phonglab share`
    writes it: base, the page (an http:// or https:// address; default the published
    build); open_in, the language it opens in ("en", "pt-PT", "pt-BR"); present, opened
    presenting to a class; channel, the term shown in place of the picture (a name
    `phonglab share --channel` takes). SceneError for anything else."""
    if base is None:
        return _core.share_link(scene._inner, open_in=open_in, present=bool(present), channel=channel)
    return _core.share_link(scene._inner, base, open_in, bool(present), channel)
