#!/usr/bin/env python3
"""phonglab.light_many against the worksheet's formula written over whole NumPy arrays
(f32), on the same 1 M vertices, in one run; the wheel's size and import time too.

    python crates/phonglab-py/bench/light_many.py [--vertices 1000000] [--rounds 3]

Run it in the virtual environment scripts/test-python makes (target/py-test). The scene is
the worksheet's (mview5: one positional attenuated light, infinite viewer, bronze). The
NumPy colours must agree with light_many's to 1e-5 before anything is timed. Each figure
is the best of the rounds, which alternate the two.
"""
import argparse
import glob
import os
import subprocess
import sys
import time

# One thread each, as `phonglab bench lighting` measures (RAYON_NUM_THREADS=0 for all).
for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "RAYON_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402

import phonglab  # noqa: E402


def numpy_worksheet(scene, p, n):
    """The worksheet's steps over arrays: what a student vectorises."""
    mview = np.array([[1, 0, 0, 0], [0, 0.8, 0.6, 0], [0, -0.6, 0.8, -960], [0, 0, 0, 1]], np.float32)
    light = scene.lights[0]
    mat = scene.material
    lamb, ldif, lspec = (np.float32(light.ambient[:3]), np.float32(light.diffuse[:3]), np.float32(light.specular[:3]))
    c, l, q = np.float32(light.attenuation)
    ns = np.float32(mat.shininess)
    r3 = mview[:3, :3]
    normal = n @ r3.T
    normal /= np.linalg.norm(normal, axis=1, keepdims=True)
    pos = p @ r3.T + mview[:3, 3]
    light_pos = (mview @ np.float32(light.position))[:3]
    to_light = light_pos - pos
    d = np.linalg.norm(to_light, axis=1, keepdims=True)
    vlv = to_light / d
    vov = np.array([0, 0, 1], np.float32)
    h = vlv + vov
    h /= np.linalg.norm(h, axis=1, keepdims=True)
    cos_theta = np.maximum(np.einsum("ij,ij->i", normal, vlv), 0)[:, None]
    cos_beta = np.maximum(np.einsum("ij,ij->i", normal, h), 0)[:, None]
    iamb = lamb * np.float32(mat.ambient[:3])
    idif = ldif * np.float32(mat.diffuse[:3]) * cos_theta
    ispec = lspec * np.float32(mat.specular[:3]) * cos_beta**ns  # the worksheet: no gate on n.L
    at = 1 / (c + l * d + q * d * d)
    return at * (iamb + idif + ispec)


def best(f, rounds):
    times = []
    for _ in range(rounds):
        t = time.perf_counter()
        f()
        times.append(time.perf_counter() - t)
    return min(times)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--vertices", type=int, default=1_000_000)
    ap.add_argument("--rounds", type=int, default=3)
    a = ap.parse_args()
    scene = phonglab.Scene.worksheet(5)
    rng = np.random.default_rng(1)
    p = rng.uniform(-600, 600, (a.vertices, 3)).astype(np.float32)
    n = rng.normal(size=(a.vertices, 3)).astype(np.float32)
    n /= np.linalg.norm(n, axis=1, keepdims=True)
    ours, theirs = phonglab.light_many(scene, p, n)[:, :3], numpy_worksheet(scene, p, n)
    worst = float(np.abs(ours - theirs).max())
    assert worst < 1e-5, f"NumPy and light_many disagree by {worst}"
    t_numpy = t_ours = float("inf")
    for _ in range(a.rounds):
        t_numpy = min(t_numpy, best(lambda: numpy_worksheet(scene, p, n), 1))
        t_ours = min(t_ours, best(lambda: phonglab.light_many(scene, p, n), 1))
    per = 1e9 / a.vertices
    print(f"vertices {a.vertices}, agree to {worst:.1e}")
    print(f"numpy {t_numpy * per:.1f} ns/vertex, light_many {t_ours * per:.1f} ns/vertex, ratio {t_numpy / t_ours:.1f}")
    print(f"threads: RAYON_NUM_THREADS={os.environ['RAYON_NUM_THREADS']}, NumPy one")
    wheels = glob.glob(os.path.join(os.path.dirname(__file__), "../../../target/wheels/phonglab-*.whl"))
    for w in wheels:
        print(f"wheel {os.path.basename(w)}: {os.path.getsize(w) / 1e6:.2f} MB")
    imports = []
    for _ in range(5):
        out = subprocess.run([sys.executable, "-X", "importtime", "-c", "import phonglab"], capture_output=True, text=True)
        line = [x for x in out.stderr.splitlines() if x.rstrip().endswith("| phonglab")][-1]
        imports.append(int(line.split("|")[1]))
    print(f"import phonglab (with numpy), cumulative: best {min(imports) / 1e3:.1f} ms of 5")


if __name__ == "__main__":
    main()
