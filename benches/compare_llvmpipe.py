#!/usr/bin/env python3
"""phonglab's CPU renderer against Mesa llvmpipe on docs/lighting.md's benchmark scene, in one run.

  benches/compare_llvmpipe.py --glref GLREF [--frames 200] [--rounds 3] [--size 512] [--threads 2] [--slices 50]
  benches/compare_llvmpipe.py --glref GLREF --mesh sphere:700 [--mesh scan:8] [--mesh FILE.obj] [--size 1024] ...

Runs `phonglab bench render` and glref's `bench_llvmpipe.py` (default thread count: all
cores) alternately, `--rounds` times each, so background load hits both alike, and takes
each configuration's best round. Prints one line per object and shading:

  object shading phonglab_ms llvmpipe_ms ratio (phonglab / llvmpipe; < 1 is faster)

`--slices N` cuts the sphere into N slices and stacks in both (the harness's own script is
run from a copy with its gluSphere call changed; the teapot is unchanged). Gouraud is
compared with llvmpipe's fixed-function pipeline, Phong with the harness's per-pixel GLSL; Flat has no llvmpipe counterpart and is shown alone. The harness needs its
setup (glref/setup.sh: Mesa, Xvfb, a venv with PyOpenGL); phonglab itself needs nothing.

`--mesh SPEC` (repeatable) times large meshes instead: `sphere:N` (gluSphere's N slices
and stacks), `scan:LEVEL` (the scan-like mesh of 20 x 4^LEVEL triangles) or an OBJ file.
`phonglab bench render --write-mesh` writes the mesh exactly as it times it, and this
repository's `benches/llvmpipe_arrays.py` (run with glref's venv) draws those very vertex
arrays in llvmpipe from vertex buffers, one glDrawElements a frame, in the same scene. One
line per mesh and shading, with phonglab's stages:

  mesh triangles shading phonglab_ms llvmpipe_ms ratio setup_ms raster_ms resolve_ms

`--moving light` (with `--mesh`) keeps the object still and circles the light round it in
both, as when a student drags the light: llvmpipe draws every frame whole, phonglab keeps
the visibility and lights and shades it again.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


EXE = os.path.join(ROOT, "target", "release", "phonglab")


def bench_render_rows(frames, size, threads, chosen):
    """The figure lines of `phonglab bench render` (split in words), `chosen` its options
    that pick the objects."""
    cmd = [EXE, "bench", "render", "--frames", str(frames), "--size", str(size)] + chosen
    if threads != "default":
        cmd += ["--threads", threads]
    out = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    return [line.split() for line in out.splitlines() if not line.startswith(("#", "object"))]


def phonglab(frames, size, threads, slices):
    rows = {}
    for w in bench_render_rows(frames, size, threads, ["--slices", str(slices)]):
        obj, shading, ms = w[:3]
        rows[(obj, shading)] = float(ms)
    return rows


def llvmpipe(glref, frames, size, threads, slices):
    py = os.path.join(glref, ".venv", "bin", "python")
    with tempfile.TemporaryDirectory() as d:
        j = os.path.join(d, "r.json")
        script = os.path.join(glref, "bench_llvmpipe.py")
        if slices != 50:
            text = open(script).read()
            call = "gluSphere(quad, 1.0, 50, 50)"
            if call not in text:
                sys.exit("bench_llvmpipe.py has no %r to change; --slices needs it" % call)
            script = os.path.join(d, "bench_llvmpipe_slices.py")
            open(script, "w").write(text.replace(call, "gluSphere(quad, 1.0, %d, %d)" % (slices, slices)))
        env = dict(os.environ, PYTHONPATH=glref)
        subprocess.run([py, script, "--frames", str(frames), "--size", str(size), "--threads", threads, "--json", j],
                       check=True, capture_output=True, text=True, env=env, cwd=glref)
        res = json.load(open(j))[0]["results"]
    names = {"sphere_50x50": "sphere", "glut_teapot": "teapot"}
    modes = {"ff_gouraud": "gouraud", "glsl_phong": "phong"}
    return {(names[r["mesh"]], modes[r["mode"]]): r["ms_per_frame"] for r in res}


def mesh_selector(spec):
    """`phonglab bench render`'s options that choose the mesh SPEC names."""
    kind, _, value = spec.partition(":")
    if kind == "sphere" and value.isdigit():
        return ["--sphere", value, "--object", "sphere"]
    if kind == "scan" and value.isdigit():
        return ["--scan", value]
    if os.path.isfile(spec):
        return ["--mesh", os.path.abspath(spec)]
    sys.exit("--mesh %r: expected sphere:N, scan:LEVEL or an OBJ file" % spec)


def phonglab_mesh(selector, frames, size, threads, moving):
    """{shading: (ms, triangles, setup, raster, resolve)} of `bench render` on one mesh."""
    rows = {}
    for w in bench_render_rows(frames, size, threads, selector + ["--moving", moving]):
        rows[w[1]] = (float(w[2]), int(w[3]), float(w[6]), float(w[7]), float(w[8]))
    return rows


def llvmpipe_mesh(glref, obj, frames, size, threads, moving):
    """{shading: ms} of llvmpipe drawing OBJ's arrays (benches/llvmpipe_arrays.py)."""
    env = dict(os.environ)
    env.pop("DISPLAY", None)
    if threads != "default":
        env["LP_NUM_THREADS"] = threads
    out = subprocess.run([os.path.join(glref, ".venv", "bin", "python"), os.path.join(HERE, "llvmpipe_arrays.py"), obj,
                          "--frames", str(frames), "--size", str(size), "--moving", moving],
                         check=True, capture_output=True, text=True, env=env).stdout
    res = json.loads(out.split("RESULT ", 1)[1])
    modes = {"ff_gouraud": "gouraud", "glsl_phong": "phong"}
    return {modes[r["mode"]]: r["ms_per_frame"] for r in res["results"]}


def compare_meshes(a):
    """--mesh: each mesh written once, then phonglab and llvmpipe alternately, best rounds."""
    ours, theirs = {}, {}
    with tempfile.TemporaryDirectory() as d:
        objs = []
        for k, spec in enumerate(a.mesh):
            obj = os.path.join(d, "mesh%d.obj" % k)
            subprocess.run([EXE, "bench", "render", "--write-mesh", obj] + mesh_selector(spec), check=True,
                           capture_output=True)
            objs.append(obj)
        for r in range(a.rounds):
            for spec, obj in zip(a.mesh, objs):
                for sh, row in phonglab_mesh(mesh_selector(spec), a.frames, a.size, a.threads, a.moving).items():
                    if (spec, sh) not in ours or row[0] < ours[(spec, sh)][0]:
                        ours[(spec, sh)] = row
                for sh, ms in llvmpipe_mesh(a.glref, obj, a.frames, a.size, a.threads, a.moving).items():
                    theirs[(spec, sh)] = min(ms, theirs.get((spec, sh), float("inf")))
            print("round %d of %d done" % (r + 1, a.rounds), file=sys.stderr)
    print("# %dx%d, %d frames, best of %d alternating rounds, threads %s, %d cpus, moving %s"
          % (a.size, a.size, a.frames, a.rounds, a.threads, os.cpu_count(), a.moving))
    print("mesh triangles shading phonglab_ms llvmpipe_ms ratio setup_ms raster_ms resolve_ms")
    for spec in a.mesh:
        for sh in ("gouraud", "phong", "flat"):
            if (spec, sh) not in ours:
                continue
            ms, tris, setup, raster, resolve = ours[(spec, sh)]
            t = theirs.get((spec, sh))
            ratio = ("%.3f %.2f" % (t, ms / t)) if t else "- -"
            print("%s %d %s %.3f %s %.3f %.3f %.3f" % (spec, tris, sh, ms, ratio, setup, raster, resolve))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--glref", required=True, help="the glref harness directory (with its .venv)")
    ap.add_argument("--frames", type=int, default=200)
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--size", type=int, default=512, help="image side in pixels, both renderers")
    ap.add_argument("--threads", default="default", help="threads for both (default: all cores)")
    ap.add_argument("--slices", type=int, default=50, help="the sphere's slices and stacks, both renderers")
    ap.add_argument("--mesh", action="append", help="sphere:N, scan:LEVEL or FILE.obj (repeatable): large meshes")
    ap.add_argument("--moving", choices=("object", "light"), default="object",
                    help="with --mesh: what changes from frame to frame, in both renderers: the object turns "
                         "(every frame drawn whole), or the light circles the standing object")
    a = ap.parse_args()
    subprocess.run(["cargo", "build", "--release", "--locked", "-q"], cwd=ROOT, check=True)
    if a.mesh:
        return compare_meshes(a)
    ours, theirs = {}, {}
    for r in range(a.rounds):
        for k, v in phonglab(a.frames, a.size, a.threads, a.slices).items():
            ours[k] = min(v, ours.get(k, float("inf")))
        for k, v in llvmpipe(a.glref, a.frames, a.size, a.threads, a.slices).items():
            theirs[k] = min(v, theirs.get(k, float("inf")))
        print("round %d of %d done" % (r + 1, a.rounds), file=sys.stderr)
    print("# %dx%d, sphere %dx%d, %d frames, best of %d alternating rounds, threads %s, %d cpus" % (a.size, a.size, a.slices, a.slices, a.frames, a.rounds, a.threads, os.cpu_count()))
    print("object shading phonglab_ms llvmpipe_ms ratio")
    for (obj, sh), ms in sorted(ours.items()):
        t = theirs.get((obj, sh))
        if t:
            print("%s %s %.3f %.3f %.2f" % (obj, sh, ms, t, ms / t))
        else:
            print("%s %s %.3f - -" % (obj, sh, ms))


if __name__ == "__main__":
    main()
