"""Shared fixtures of the phonglab package's tests (run by scripts/test-python)."""

import json
import os
import pathlib
import struct
import subprocess
import zlib

import numpy as np
import pytest

ROOT = pathlib.Path(__file__).resolve().parents[3]


@pytest.fixture(scope="session")
def cli():
    """Runs the phonglab command line (PHONGLAB_BIN, else target/debug/phonglab)."""
    binary = os.environ.get("PHONGLAB_BIN", str(ROOT / "target/debug/phonglab"))
    if not os.path.exists(binary):
        pytest.fail(f"{binary} is missing: build it first (cargo build --bin phonglab)")

    def run(*args, env_lang="C.UTF-8", **kwargs):
        env = dict(os.environ, LC_ALL=env_lang, LANG=env_lang)
        return subprocess.run([binary, *map(str, args)], capture_output=True, text=True, check=True, env=env, **kwargs)

    return run


@pytest.fixture(scope="session")
def worksheet_runs():
    """The worksheet's own cells run with each modelview (tests/data/worksheet_cells.json)."""
    return json.loads((ROOT / "tests/data/worksheet_cells.json").read_text())["runs"]


def read_png(path):
    """An 8-bit RGBA (or RGB) non-interlaced PNG as an (H, W, 4) uint8 array."""
    data = pathlib.Path(path).read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    at, idat = 8, b""
    while at < len(data):
        (length,) = struct.unpack(">I", data[at : at + 4])
        kind, body = data[at + 4 : at + 8], data[at + 8 : at + 8 + length]
        if kind == b"IHDR":
            w, h, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert depth == 8 and colour in (2, 6) and interlace == 0
        elif kind == b"IDAT":
            idat += body
        at += 12 + length
    bpp = 4 if colour == 6 else 3
    raw = zlib.decompress(idat)
    stride = w * bpp
    out = np.zeros((h, stride), dtype=np.int32)
    prev = np.zeros(stride, dtype=np.int32)
    for y in range(h):
        f = raw[y * (stride + 1)]
        line = np.frombuffer(raw, dtype=np.uint8, count=stride, offset=y * (stride + 1) + 1).astype(np.int32)
        cur = np.zeros(stride, dtype=np.int32)
        for x in range(stride):
            a = cur[x - bpp] if x >= bpp else 0
            b, c = prev[x], (prev[x - bpp] if x >= bpp else 0)
            if f == 0:
                p = 0
            elif f == 1:
                p = a
            elif f == 2:
                p = b
            elif f == 3:
                p = (a + b) // 2
            else:
                pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                p = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
            cur[x] = (line[x] + p) & 0xFF
        out[y], prev = cur, cur
    img = out.astype(np.uint8).reshape(h, w, bpp)
    if bpp == 3:
        img = np.concatenate([img, np.full((h, w, 1), 255, np.uint8)], axis=2)
    return img
