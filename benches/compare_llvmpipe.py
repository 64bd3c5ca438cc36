#!/usr/bin/env python3
"""phonglab's CPU renderer against Mesa llvmpipe on docs/lighting.md's benchmark scene, in one run.

  benches/compare_llvmpipe.py --glref GLREF [--frames 200] [--rounds 3] [--size 512] [--threads 2] [--slices 50]

Runs `phonglab bench render` and glref's `bench_llvmpipe.py` (default thread count: all
cores) alternately, `--rounds` times each, so background load hits both alike, and takes
each configuration's best round. Prints one line per object and shading:

  object shading phonglab_ms llvmpipe_ms ratio (phonglab / llvmpipe; < 1 is faster)

`--slices N` cuts the sphere into N slices and stacks in both (the harness's own script is
run from a copy with its gluSphere call changed; the teapot is unchanged). Gouraud is
compared with llvmpipe's fixed-function pipeline, Phong with the harness's per-pixel GLSL; Flat has no llvmpipe counterpart and is shown alone. The harness needs its
setup (glref/setup.sh: Mesa, Xvfb, a venv with PyOpenGL); phonglab itself needs nothing.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def phonglab(frames, size, threads, slices):
    exe = os.path.join(ROOT, "target", "release", "phonglab")
    cmd = [exe, "bench", "render", "--frames", str(frames), "--size", str(size), "--slices", str(slices)]
    if threads != "default":
        cmd += ["--threads", threads]
    out = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    rows = {}
    for line in out.splitlines():
        if line.startswith("#") or line.startswith("object"):
            continue
        obj, shading, ms, tris, cov = line.split()[:5]
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


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--glref", required=True, help="the glref harness directory (with its .venv)")
    ap.add_argument("--frames", type=int, default=200)
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--size", type=int, default=512, help="image side in pixels, both renderers")
    ap.add_argument("--threads", default="default", help="threads for both (default: all cores)")
    ap.add_argument("--slices", type=int, default=50, help="the sphere's slices and stacks, both renderers")
    a = ap.parse_args()
    subprocess.run(["cargo", "build", "--release", "--locked", "-q"], cwd=ROOT, check=True)
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
