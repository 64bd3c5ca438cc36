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

import difflib
import functools
import json
import os
import warnings
from typing import Any, Callable, Dict, Iterator, List, Optional, Tuple, TypeVar

import numpy as np

from . import _core
from ._core import SceneError, __version__
from ._selfcheck import check

__all__ = [
    "Scene",
    "SceneError",
    "NotebookNotice",
    "UnknownName",
    "NoSuchLight",
    "set_language",
    "language",
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


class UnknownName(SceneError, AttributeError):
    """A name that a scene's part, a worked calculation or the package does not have (a
    typo such as `material.shinyness`): a SceneError that is also an AttributeError, so
    that hasattr() and getattr()'s default work. The message says the likeliest name meant."""


class NoSuchLight(SceneError, IndexError):
    """A light the scene does not have (`scene.lights[1]` in a scene with one light): a
    SceneError that is also an IndexError."""


_F = TypeVar("_F", bound=Callable[..., Any])


def _refusals_here(function: _F) -> _F:
    """Raises a SceneError from `function` with the package's inner frames cut: the
    traceback shows the call the user wrote, then this wrapper's one line, never the
    frames inside (the message says what was wrong; they would only hide it). The line of
    this wrapper stays: Python records every Python frame an exception leaves, the one
    that raises it included, so only a function written in C (or Rust) could raise with
    no frame of its own; IPython's `__tracebackhide__` never hides the last frame either."""

    @functools.wraps(function)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        try:
            return function(*args, **kwargs)
        except SceneError as e:
            raise e.with_traceback(None) from None

    return wrapper  # type: ignore[return-value]


def set_language(lang: str) -> None:
    """Sets the language of phonglab's messages from now on ("en", "pt-PT" or "pt-BR"):
    every SceneError, and the worked calculation where no lang= is given. The messages are
    the command line's (the same Fluent catalogue)."""
    _core.set_language(lang)


def language() -> str:
    """The language of phonglab's messages now ("en" unless set_language chose another)."""
    return _core.language()


def _refuse(kind: str, what: str, value: Any, names: str = "", guess: str = "") -> SceneError:
    return SceneError(_core.refusal(kind, what, repr(value), names, guess))


def _is_real(x: Any) -> bool:
    """Is `x` a real number as phonglab takes one: an int or a float (Python's or NumPy's),
    not a bool, a text, a complex number or None."""
    if isinstance(x, (bool, np.bool_)):
        return False
    return isinstance(x, (int, float, np.integer, np.floating))


def _numbers(value: Any, what: str = "value") -> List[float]:
    """The real numbers `value` holds (a number, a list or tuple of them, or a NumPy array of
    integers or floats), flattened; refused with a SceneError naming `what` when anything in
    it is not a real number (a text, True/False, None, a complex number, an object)."""
    if isinstance(value, np.ndarray):
        if value.dtype.kind not in "iuf":
            raise _refuse("not-real", what, value)
        # A plain array of the values held (a 1x4 np.matrix, a subclass: their numbers).
        return [float(x) for x in np.asarray(value).astype(np.float64).reshape(-1).tolist()]
    items = list(value) if isinstance(value, (list, tuple)) else [value]
    flat: List[Any] = []
    for x in items:
        if isinstance(x, (list, tuple, np.ndarray)):
            flat += _numbers(x, what)
        elif _is_real(x):
            flat.append(_value_of(x))
        else:
            raise _refuse("not-real", what, value)
    return flat


def _nested(value: Any) -> bool:
    """Does `value` hold a list in a list (or an array of two dimensions or more)?"""
    if isinstance(value, np.ndarray):
        return value.ndim > 1
    return isinstance(value, (list, tuple)) and any(isinstance(x, (list, tuple, np.ndarray)) for x in value)


def _value_of(x: Any) -> float:
    """The number `x` holds and prints, as a float: a float's (or int's) own value, never
    what a subclass's __float__ says; an int beyond a float's range is the infinity of its
    sign (refused as not finite by the scene's check, never an OverflowError)."""
    if isinstance(x, float):
        return float.__float__(x)
    if isinstance(x, np.generic):
        return float(np.asarray(x).astype(np.float64))
    try:
        return float(int.__int__(x))
    except OverflowError:
        return float("inf") if int.__int__(x) > 0 else float("-inf")


def _integer(value: Any, what: str) -> int:
    """`value` as an int (Python's or NumPy's), refused when it is not one (a float, a text,
    True/False)."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)):
        raise _refuse("not-integer", what, value)
    return int(value)


def _inner_of(scene: Any, what: str) -> "_core.Scene":
    """The core's scene inside `scene`, refused when `scene` is not a phonglab.Scene (a
    file name given where a scene is expected)."""
    if not isinstance(scene, Scene):
        raise _refuse("not-a-scene", what, scene)
    return scene._inner


def _unknown_name(owner: str, name: str, names: List[str]) -> UnknownName:
    guesses = difflib.get_close_matches(name, names, n=1)
    return UnknownName(_core.refusal("no-field", owner, name, ", ".join(names), guesses[0] if guesses else ""))


class _Fields:
    """Named numbers of a scene (a light, the material, the vertex) as NumPy arrays.

    Reading gives a copy; assigning checks the value as the app checks an edit and raises
    SceneError (leaving the scene as it was) when it refuses it."""

    _names: Tuple[str, ...] = ()

    def __init__(self, scene: "Scene", prefix: str) -> None:
        object.__setattr__(self, "_scene", scene)
        object.__setattr__(self, "_prefix", prefix)

    def __getattr__(self, name: str) -> Any:
        if name.startswith("_"):
            raise AttributeError(name)  # Python's own lookups (copy, pickle, NumPy)
        if name not in self._names:
            raise _unknown_name(self._shown(), name, list(self._names))
        values = self._scene._inner.get(self._prefix + name)
        return values[0] if name in _SCALARS else np.array(values)

    @_refusals_here
    def __setattr__(self, name: str, value: Any) -> None:
        if name not in self._names:
            raise _unknown_name(self._shown(), name, list(self._names))
        shown = f"{self._shown()}.{name}"
        # One number is one number: not a nested list ([[25.6]]) nor an array of several dimensions.
        if name in _SCALARS and _nested(value):
            raise _refuse("not-real", shown, value)
        self._scene._inner.set(self._prefix + name, _numbers(value, shown))

    def _shown(self) -> str:
        """This part as Python names it: lights[0], material, vertex."""
        parts = self._prefix.rstrip(".").split(".")
        return f"lights[{parts[1]}]" if parts[0] == "light" else parts[0]

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
    """The worked vertex: position (x, y, z, w; x, y, z alone takes w = 1) and normal
    (x, y, z; the worksheet's x, y, z, 0 is taken too), in object space."""

    _names = ("position", "normal")


class _Lights:
    """The scene's enabled lights, in order (GL_LIGHT0 first): index them, iterate, len().
    Their number is the scene's: a light is added or removed in a scene file."""

    def __init__(self, scene: "Scene") -> None:
        self._scene = scene

    def __len__(self) -> int:
        return int(self._scene._inner.light_count())

    def __getitem__(self, i: Any) -> Light:
        if isinstance(i, slice):
            return [self[k] for k in range(len(self))[i]]  # type: ignore[return-value]
        k = _integer(i, "lights[i]")
        count = len(self)
        if not -count <= k < count:
            raise NoSuchLight(_core.refusal("no-light", "lights", str(k), str(count)))
        return Light(self._scene, f"light.{k % count}.")

    def __iter__(self) -> Iterator[Light]:
        return (self[k] for k in range(len(self)))

    @_refusals_here
    def __setitem__(self, i: Any, value: Any) -> None:
        raise _refuse("edit-fields", "scene.lights[i]", value, "scene.lights[0].position = [0, 0, 90, 1]")

    def __getattr__(self, name: str) -> Any:
        if name.startswith("_"):
            raise AttributeError(name)  # Python's own lookups (copy, pickle, NumPy)
        raise UnknownName(_core.refusal("lights-fixed", "lights", name))

    def __repr__(self) -> str:
        return repr(list(self))


class Scene:
    """A scene as the app holds it: lights, material, camera, the worked vertex and the
    shaded view. Make one with Scene.load, Scene.worksheet, Scene.preset or
    Scene.from_notebook."""

    def __init__(self, inner: "_core.Scene") -> None:
        self._inner = inner
        self._code: Optional[str] = None

    @staticmethod
    @_refusals_here
    def load(path: "os.PathLike[str] | str") -> "Scene":
        """Reads a scene file (TOML) with the command line's reader: a regular file of at
        most 1 MiB, UTF-8, opened without waiting (a FIFO, a device or a folder is refused
        at once); a relative mesh path is read from the file's folder. A scene's share
        link (https://…/#v1.…, as share_link writes it) is read in its place, decoded as
        the command line decodes it. A file or link that cannot be read or used raises
        SceneError naming it."""
        return Scene(_core.Scene.load(path))

    @staticmethod
    @_refusals_here
    def from_toml(text: str) -> "Scene":
        """A scene from a scene file's text (at most 1 MiB, as a scene file)."""
        return Scene(_core.Scene.from_toml(text))

    @staticmethod
    @_refusals_here
    def worksheet(n: int = 5) -> "Scene":
        """The worksheet's scene with modelview n (1 to 5)."""
        return Scene(_core.Scene.worksheet(_integer(n, "Scene.worksheet(n)")))

    @staticmethod
    @_refusals_here
    def preset(name: str) -> "Scene":
        """A ready-made scene: "worksheet" (the app's start scene) or "phong-demo"."""
        return Scene(_core.Scene.preset(name))

    @staticmethod
    @_refusals_here
    def from_notebook(path: "os.PathLike[str] | str") -> "Scene":
        """The scene a worksheet notebook (.ipynb) or script (.py) sets up, read as
        `phonglab import` reads it (a regular file of at most 16 MiB; nothing in it is
        run), named after the file (its control characters written visibly). What
        `phonglab import` says of it (a line not read, a given replaced by the worksheet's
        value) comes as a NotebookNotice warning each."""
        inner, notices = _core.Scene.import_file(path)
        for notice in notices:
            warnings.warn(NotebookNotice(notice), stacklevel=3)
        scene = Scene(inner)
        scene._code = os.path.abspath(path)  # an input: save never writes over it
        return scene

    @_refusals_here
    def save(self, path: "os.PathLike[str] | str") -> None:
        """Writes the scene file as the app's Save and `phonglab export -o` write one: whole
        or not at all (a temporary file beside it, renamed over it), a file replaced keeping
        its permissions; through a symbolic link to the file it names (the link stays).
        Refused, with nothing written: a folder, a FIFO, a device, the scene's own mesh, the
        notebook or script it was imported from."""
        self._inner.save(path, self._code)

    def to_toml(self) -> str:
        """The scene file's text."""
        return self._inner.to_toml()

    def copy(self) -> "Scene":
        """An independent copy, keeping where the scene came from: its save never writes
        over the notebook or script it was imported from either."""
        scene = Scene(self._inner.__copy__())
        scene._code = self._code
        return scene

    @property
    def name(self) -> str:
        """The scene's title, shown by explain, the window and a share link. Settable:
        assigning a modelview keeps the name (Scene.worksheet(5) stays "the worksheet,
        mview5"), so name what the scene is now: scene.name = "mview3's camera". A name
        that is not a str raises SceneError."""
        return self._inner.name

    @name.setter
    @_refusals_here
    def name(self, value: str) -> None:
        if not isinstance(value, str):
            raise _refuse("not-a-name", "name", value)
        self._inner.name = value

    @property
    def lights(self) -> _Lights:
        """The enabled lights, in order (GL_LIGHT0 first): scene.lights[0], len(scene.lights)."""
        return _Lights(self)

    @property
    def modelview(self) -> np.ndarray:
        """The modelview (object to eye coordinates), a 4x4 array (row by row, as written
        on paper). Assigning a 4x4 array (16 numbers, row by row) makes it the camera, typed in as the app's
        Camera → Matrix, and the object's own transform the identity; checked as the app
        checks it."""
        return np.array(self._inner.modelview()).reshape(4, 4)

    @modelview.setter
    @_refusals_here
    def modelview(self, value: Any) -> None:
        self._inner.set_modelview(_numbers(value, "modelview"))

    @property
    def material(self) -> Material:
        """The front material (edited field by field: scene.material.diffuse = ...)."""
        return Material(self, "material.")

    @material.setter
    @_refusals_here
    def material(self, value: Any) -> None:
        raise _refuse("edit-fields", "scene.material", value, "scene.material.diffuse = [0.8, 0.2, 0.2, 1]")

    @property
    def vertex(self) -> Vertex:
        """The worked vertex (edited field by field: scene.vertex.normal = ...)."""
        return Vertex(self, "vertex.")

    @vertex.setter
    @_refusals_here
    def vertex(self, value: Any) -> None:
        raise _refuse("edit-fields", "scene.vertex", value, "scene.vertex.normal = [0, 0, 1]")

    def __repr__(self) -> str:
        return f"phonglab.Scene({self.name!r})"


class Lighting:
    """The worked calculation of one vertex, as computed when it was made (a later change
    to the scene does not change it). Each step is an attribute under the worksheet's name
    (vertexNormal, vlv, vov, H, cosTheta, cosBeta, Iamb, Idif, Ispec, at, spot, I)
    holding a NumPy array of 4 components, or a NumPy float64 for a scalar step (cosTheta,
    cosBeta, d, at, spot: printed as the worksheet prints it, 0.13925483), or None where
    the step does not apply. With several lights, a light's step is a list with one value per light, as
    the worksheet's notebook holds it (lit.vlv[0] is light 0's vlv), and .per_light[k]
    holds light k's steps by their names (lit.per_light[0]["vlv"]).

    In Jupyter it shows as the calculation's table in the language given to light()
    (lang=); explain(lang=...) gives it as text (or Markdown) in any language."""

    def __init__(self, rows: list, text: str, markdown: str, scene: Scene, precision: str, lang: str = "en") -> None:
        self._rows = rows
        self._text, self._markdown = text, markdown
        # The scene as it was: explain() and the displays show this calculation.
        self._scene, self._precision, self._lang = Scene(scene._inner.__copy__()), precision, lang
        self.per_light: Dict[int, Dict[str, Any]] = {}
        self.steps: Dict[str, Any] = {}
        lights = 1 + max((light for *_, light, _shown in rows if light is not None), default=0)
        for name, _title, _formula, value, light, _shown in rows:
            # A scalar step (cosTheta, d, at, spot) as the worksheet prints it: a float64.
            array = None if value is None else np.float64(value[0]) if len(value) == 1 else np.array(value)
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
        raise _unknown_name("Lighting", name, list(steps) + ["explain", "steps", "per_light"])

    def __dir__(self) -> List[str]:
        return list(self.steps) + ["explain", "steps", "per_light"]

    def explain(self, lang: Optional[str] = None, markdown: bool = False) -> str:
        """The worked calculation as text (or Markdown) in lang: "en", "pt-PT" or "pt-BR"
        (its words and its decimal mark); default, the language set_language chose."""
        lang = language() if lang is None else lang
        text, md, _html = _core.explain_tables(self._scene._inner, self._precision, lang)
        return md if markdown else text

    def _repr_markdown_(self) -> str:
        return _core.explain_tables(self._scene._inner, self._precision, self._lang)[1]

    def _repr_html_(self) -> str:
        return _core.explain_tables(self._scene._inner, self._precision, self._lang)[2]

    def __repr__(self) -> str:
        return self._text


@_refusals_here
def light(
    scene: Scene,
    vertex: Any = None,
    normal: Any = None,
    precision: str = "f64",
    lang: Optional[str] = None,
) -> Lighting:
    """Lights the scene's vertex (or vertex/normal, in object space) step by step as the
    worksheet does (vertex: x, y, z with w = 1, or x, y, z, w; normal: x, y, z, or the
    worksheet's x, y, z, 0); precision "f64" or "f32"; lang the language of its text (default: the
    one set_language chose)."""
    _inner_of(scene, "light(scene)")
    if vertex is not None or normal is not None:
        scene = scene.copy()
        if vertex is not None:
            scene._inner.set("vertex.position", _numbers(vertex, "light(vertex=)"), "light(vertex=)")
        if normal is not None:
            scene._inner.set("vertex.normal", _numbers(normal, "light(normal=)"), "light(normal=)")
    lang = language() if lang is None else lang
    rows, text, markdown = _core.light(scene._inner, precision, lang)
    return Lighting(rows, text, markdown, scene, precision, lang)


def _vectors(value: Any, what: str) -> np.ndarray:
    """`value` as a C-contiguous little-endian float32 array, refused when it holds
    anything but real numbers (texts, True/False, complex numbers, objects). A float64
    beyond float32's range becomes an infinity here, which the core refuses by its row."""
    array = value if isinstance(value, np.ndarray) else np.asarray(value)
    if array.dtype.kind not in "iuf":
        raise _refuse("not-real", what, value if isinstance(value, str) else array.dtype)
    with np.errstate(over="ignore", invalid="ignore"):
        return np.ascontiguousarray(array, dtype="<f4")


@_refusals_here
def light_many(scene: Scene, positions: Any, normals: Any) -> np.ndarray:
    """Lights N vertices ((N, 3) positions and normals, object space) through phonglab's
    specialised lighter in float32, without holding the GIL: (N, 4) float32 colours
    (primary + secondary, unclamped; alpha the material's diffuse alpha, as OpenGL gives
    it, where light(scene).I[3] is the fourth component of the worksheet's I, as its
    formula gives it: 0 for the worksheet's scene). A number that is not finite (NaN, an infinity, beyond float32's range) is
    refused with a SceneError naming its row; memory that cannot be had is MemoryError."""
    inner = _inner_of(scene, "light_many(scene)")
    p = _vectors(positions, "light_many(positions)")
    n = _vectors(normals, "light_many(normals)")
    out = _core.light_many(inner, p.tobytes(), n.tobytes(), (list(p.shape), list(n.shape)))
    return np.frombuffer(out, dtype="<f4").reshape(-1, 4).copy()


class Picture(np.ndarray):
    """An (H, W, 4) uint8 RGBA picture that Jupyter shows as a PNG."""

    def _repr_png_(self) -> Optional[bytes]:
        """The picture as a PNG: an (H, W, 4) or (H, W, 3) array of bytes as it is now
        (a crop or a flip of one included); None for anything else (a row, a channel, a
        transposed array), which Jupyter then shows as numbers."""
        import struct
        import zlib

        if self.ndim != 3 or self.shape[2] not in (3, 4) or self.dtype != np.uint8 or 0 in self.shape:
            return None
        h, w, channels = self.shape
        raw = b"".join(b"\x00" + self[y].tobytes() for y in range(h))

        def chunk(kind: bytes, data: bytes) -> bytes:
            body = kind + data
            return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))

        header = struct.pack(">IIBBBBB", w, h, 8, 6 if channels == 4 else 2, 0, 0, 0)
        return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b"")


@_refusals_here
def render(
    scene: Scene,
    object: Optional[str] = None,
    shading: Optional[str] = None,
    size: int = 512,
) -> Picture:
    """The shaded view as `phonglab render` draws it: an (H, W, 4) uint8 array.
    object: "sphere", "teapot" or "cylinder"; shading: "gouraud", "phong" or "flat"
    (default: the scene's)."""
    inner = _inner_of(scene, "render(scene)")
    rgba, w, h = _core.render(inner, object, shading, _integer(size, "render(size=)"))
    return np.frombuffer(rgba, dtype=np.uint8).reshape(h, w, 4).copy().view(Picture)


@_refusals_here
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
    inner = _inner_of(scene, "probe(scene)")
    x, y = _integer(x, "probe(x)"), _integer(y, "probe(y)")
    return json.loads(_core.probe(inner, x, y, object, shading, _integer(size, "probe(size=)")))


@_refusals_here
def shader(scene: Scene, target: str = "glsl", shading: str = "gouraud") -> str:
    """The program ("glsl" or "wgsl"; "gouraud" or "phong") that draws the scene's view."""
    return _core.shader(_inner_of(scene, "shader(scene)"), target, shading)


@_refusals_here
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
    inner = _inner_of(scene, "share_link(scene)")
    if base is None:
        return _core.share_link(inner, open_in=open_in, present=bool(present), channel=channel)
    return _core.share_link(inner, base, open_in, bool(present), channel)


def __dir__() -> List[str]:
    """The package's own names (not the modules it uses inside)."""
    return sorted(__all__ + ["__version__"])
