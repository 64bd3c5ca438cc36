#!/usr/bin/env python3
"""Mesa llvmpipe drawing a mesh's own vertex arrays in the rendering benchmark's scene.

  llvmpipe_arrays.py MESH.obj [--frames 20] [--size 1024] [--png PREFIX] [--moving object|light]

Run with a Python that has PyOpenGL and NumPy (glref's .venv) and LP_NUM_THREADS set for
the thread count; benches/compare_llvmpipe.py runs it. MESH.obj is what `phonglab bench
render --write-mesh` wrote: the vertices as the benchmark places them, each number the
exact f32 phonglab times. They go into vertex buffers (positions, normals, 32-bit
indices) drawn by one glDrawElements a frame, in docs/lighting.md's benchmark scene:
gluPerspective(40, 1, 0.5, 20), the object 4 in front of the eye and turned 3 degrees a
frame about (0.3, 1, 0.1), bronze under one positional light (ambient 0.2, linear
attenuation 0.05), GL_NORMALIZE, depth test, into a SIZE x SIZE RGBA8 + DEPTH24
framebuffer. Shadings (the same as glref's bench_llvmpipe.py):
  ff_gouraud  fixed-function per-vertex lighting (GL_SMOOTH);
  glsl_phong  GLSL 1.20 per-pixel Blinn-Phong of the same equation.
A frame is clear + draw + glFinish; prints one JSON line `RESULT {...}` with the mean
ms per frame over FRAMES after 5 warm-up frames, the primitives drawn and the share of
pixels covered. The parsed arrays are kept beside the OBJ (MESH.npz) for the next run.
freeglut needs an X display: an Xvfb of its own is started when DISPLAY is unset.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import time

# The benchmark's per-pixel shader (glref's bench_llvmpipe.py's, unchanged).
VS = """#version 120
varying vec3 P;
varying vec3 N;
void main() {
    P = vec3(gl_ModelViewMatrix * gl_Vertex);
    N = gl_NormalMatrix * gl_Normal;
    gl_Position = ftransform();
}
"""
FS = """#version 120
varying vec3 P;
varying vec3 N;
void main() {
    vec3 n = normalize(N);
    vec4 Lp = gl_LightSource[0].position;
    vec3 L;
    float att = 1.0;
    if (Lp.w != 0.0) {
        vec3 d = Lp.xyz - P;
        float dist = length(d);
        L = d / dist;
        att = 1.0 / (gl_LightSource[0].constantAttenuation +
                     gl_LightSource[0].linearAttenuation * dist +
                     gl_LightSource[0].quadraticAttenuation * dist * dist);
    } else {
        L = normalize(Lp.xyz);
    }
    float ndl = dot(n, L);
    vec3 H = normalize(L + vec3(0.0, 0.0, 1.0));   /* infinite viewer */
    float spec = ndl > 0.0 ? pow(max(dot(n, H), 0.0), gl_FrontMaterial.shininess) : 0.0;
    vec3 c = gl_FrontLightModelProduct.sceneColor.rgb +
             att * (gl_FrontLightProduct[0].ambient.rgb +
                    max(ndl, 0.0) * gl_FrontLightProduct[0].diffuse.rgb +
                    spec * gl_FrontLightProduct[0].specular.rgb);
    gl_FragColor = vec4(c, gl_FrontMaterial.diffuse.a);
}
"""


def load_arrays(path):
    """(positions f32 [n,3], normals f32 [n,3], indices u32 [m*3]) of an OBJ whose faces are
    `f a//a b//b c//c` (one normal per position, as --write-mesh writes them)."""
    import numpy as np
    cache = os.path.splitext(path)[0] + ".npz"
    if os.path.exists(cache) and os.path.getmtime(cache) >= os.path.getmtime(path):
        z = np.load(cache)
        return z["p"], z["n"], z["i"]
    v, vn, f = [], [], []
    with open(path) as fh:
        for line in fh:
            tag = line[:2]
            if tag == "v ":
                v.append(line[2:])
            elif tag == "vn":
                vn.append(line[3:])
            elif tag == "f ":
                f.append(line[2:].replace("//", " "))
    # Each number is an f32's exact value: read as f64, then narrowed without rounding.
    p = np.array(" ".join(v).split(), dtype=np.float64).astype(np.float32).reshape(-1, 3)
    n = np.array(" ".join(vn).split(), dtype=np.float64).astype(np.float32).reshape(-1, 3)
    pairs = np.array(" ".join(f).split(), dtype=np.int64).reshape(-1, 6)
    if len(p) != len(n) or not np.array_equal(pairs[:, 0::2], pairs[:, 1::2]):
        sys.exit("%s: expected one normal per position and faces `f a//a b//b c//c`" % path)
    i = (pairs[:, 0::2] - 1).astype(np.uint32).ravel()
    np.savez(cache, p=p, n=n, i=i)
    return p, n, i


def start_xvfb():
    r, w = os.pipe()
    p = subprocess.Popen(["Xvfb", "-displayfd", str(w), "-screen", "0", "640x480x24", "-nolisten", "tcp"],
                         pass_fds=(w,), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    os.close(w)
    num = b""
    while not num.endswith(b"\n"):
        ch = os.read(r, 1)
        if not ch:
            raise RuntimeError("Xvfb failed to start")
        num += ch
    os.close(r)
    return p, ":" + num.decode().strip()


def run(mesh, frames, size, png, moving):
    import numpy as np
    from OpenGL import GL, GLU, GLUT
    positions, normals, indices = load_arrays(mesh)
    GLUT.glutInit(sys.argv[:1])
    GLUT.glutInitDisplayMode(GLUT.GLUT_RGBA | GLUT.GLUT_DEPTH)
    GLUT.glutInitWindowSize(64, 64)
    GLUT.glutCreateWindow(b"bench")
    info = {"GL_RENDERER": GL.glGetString(GL.GL_RENDERER).decode(),
            "LP_NUM_THREADS": os.environ.get("LP_NUM_THREADS", "default")}
    fbo = GL.glGenFramebuffers(1)
    GL.glBindFramebuffer(GL.GL_FRAMEBUFFER, fbo)
    rc, rd = GL.glGenRenderbuffers(2)
    GL.glBindRenderbuffer(GL.GL_RENDERBUFFER, rc)
    GL.glRenderbufferStorage(GL.GL_RENDERBUFFER, GL.GL_RGBA8, size, size)
    GL.glFramebufferRenderbuffer(GL.GL_FRAMEBUFFER, GL.GL_COLOR_ATTACHMENT0, GL.GL_RENDERBUFFER, rc)
    GL.glBindRenderbuffer(GL.GL_RENDERBUFFER, rd)
    GL.glRenderbufferStorage(GL.GL_RENDERBUFFER, GL.GL_DEPTH_COMPONENT24, size, size)
    GL.glFramebufferRenderbuffer(GL.GL_FRAMEBUFFER, GL.GL_DEPTH_ATTACHMENT, GL.GL_RENDERBUFFER, rd)
    assert GL.glCheckFramebufferStatus(GL.GL_FRAMEBUFFER) == GL.GL_FRAMEBUFFER_COMPLETE
    GL.glViewport(0, 0, size, size)

    prog = GL.glCreateProgram()
    for typ, src in ((GL.GL_VERTEX_SHADER, VS), (GL.GL_FRAGMENT_SHADER, FS)):
        s = GL.glCreateShader(typ)
        GL.glShaderSource(s, src)
        GL.glCompileShader(s)
        if not GL.glGetShaderiv(s, GL.GL_COMPILE_STATUS):
            raise RuntimeError(GL.glGetShaderInfoLog(s))
        GL.glAttachShader(prog, s)
    GL.glLinkProgram(prog)
    if not GL.glGetProgramiv(prog, GL.GL_LINK_STATUS):
        raise RuntimeError(GL.glGetProgramInfoLog(prog))

    GL.glMatrixMode(GL.GL_PROJECTION)
    GL.glLoadIdentity()
    GLU.gluPerspective(40.0, 1.0, 0.5, 20.0)
    GL.glMatrixMode(GL.GL_MODELVIEW)
    GL.glLoadIdentity()
    GL.glEnable(GL.GL_DEPTH_TEST)
    GL.glEnable(GL.GL_LIGHTING)
    GL.glEnable(GL.GL_LIGHT0)
    GL.glEnable(GL.GL_NORMALIZE)
    GL.glShadeModel(GL.GL_SMOOTH)
    GL.glLightfv(GL.GL_LIGHT0, GL.GL_POSITION, (2.0, 3.0, 1.0, 1.0))
    GL.glLightfv(GL.GL_LIGHT0, GL.GL_AMBIENT, (0.2, 0.2, 0.2, 1.0))
    GL.glLightfv(GL.GL_LIGHT0, GL.GL_DIFFUSE, (1.0, 1.0, 1.0, 1.0))
    GL.glLightfv(GL.GL_LIGHT0, GL.GL_SPECULAR, (1.0, 1.0, 1.0, 1.0))
    GL.glLightf(GL.GL_LIGHT0, GL.GL_LINEAR_ATTENUATION, 0.05)
    GL.glMaterialfv(GL.GL_FRONT_AND_BACK, GL.GL_AMBIENT, (0.2125, 0.1275, 0.054, 1.0))
    GL.glMaterialfv(GL.GL_FRONT_AND_BACK, GL.GL_DIFFUSE, (0.714, 0.4284, 0.18144, 1.0))
    GL.glMaterialfv(GL.GL_FRONT_AND_BACK, GL.GL_SPECULAR, (0.393548, 0.271906, 0.166721, 1.0))
    GL.glMaterialf(GL.GL_FRONT_AND_BACK, GL.GL_SHININESS, 25.6)
    GL.glClearColor(0.1, 0.1, 0.15, 1.0)

    # The arrays in buffers on the "GPU" (llvmpipe's memory), drawn by one call a frame.
    vbo_p, vbo_n, ibo = GL.glGenBuffers(3)
    GL.glBindBuffer(GL.GL_ARRAY_BUFFER, vbo_p)
    GL.glBufferData(GL.GL_ARRAY_BUFFER, positions.nbytes, positions, GL.GL_STATIC_DRAW)
    GL.glVertexPointer(3, GL.GL_FLOAT, 0, None)
    GL.glBindBuffer(GL.GL_ARRAY_BUFFER, vbo_n)
    GL.glBufferData(GL.GL_ARRAY_BUFFER, normals.nbytes, normals, GL.GL_STATIC_DRAW)
    GL.glNormalPointer(GL.GL_FLOAT, 0, None)
    GL.glBindBuffer(GL.GL_ELEMENT_ARRAY_BUFFER, ibo)
    GL.glBufferData(GL.GL_ELEMENT_ARRAY_BUFFER, indices.nbytes, indices, GL.GL_STATIC_DRAW)
    GL.glEnableClientState(GL.GL_VERTEX_ARRAY)
    GL.glEnableClientState(GL.GL_NORMAL_ARRAY)
    count = len(indices)

    q = GL.glGenQueries(1)
    q = int(q[0]) if hasattr(q, "__len__") else int(q)
    results = []
    for mode in ("ff_gouraud", "glsl_phong"):
        GL.glUseProgram(prog if mode == "glsl_phong" else 0)

        def frame(i):
            GL.glClear(GL.GL_COLOR_BUFFER_BIT | GL.GL_DEPTH_BUFFER_BIT)
            GL.glLoadIdentity()
            if moving == "light":
                # The light circles the standing object, 3 degrees a frame about the eye's y
                # axis (set under the identity: in eye coordinates), as `bench render
                # --moving light` moves it.
                t = math.radians(3.0 * i)
                x, y, z = 2.0, 3.0, 1.0
                GL.glLightfv(GL.GL_LIGHT0, GL.GL_POSITION,
                             (x * math.cos(t) + z * math.sin(t), y, -x * math.sin(t) + z * math.cos(t), 1.0))
            GL.glTranslatef(0.0, 0.0, -4.0)
            GL.glRotatef(3.0 * i if moving == "object" else 0.0, 0.3, 1.0, 0.1)
            GL.glDrawElements(GL.GL_TRIANGLES, count, GL.GL_UNSIGNED_INT, None)
            GL.glFinish()
        GL.glBeginQuery(GL.GL_PRIMITIVES_GENERATED, q)
        frame(0)
        GL.glEndQuery(GL.GL_PRIMITIVES_GENERATED)
        prims = int(GL.glGetQueryObjectuiv(q, GL.GL_QUERY_RESULT))
        for i in range(5):
            frame(i)
        t0 = time.perf_counter()
        for i in range(frames):
            frame(i)
        ms = (time.perf_counter() - t0) / frames * 1000.0
        px = GL.glReadPixels(0, 0, size, size, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE)
        arr = np.frombuffer(px, np.uint8).reshape(size, size, 4)
        covered = float(np.mean(np.any(arr[:, :, :3] != arr[0, 0, :3], axis=2)))
        if png:
            write_png("%s_%s.png" % (png, mode), arr[::-1, :, :3])
        results.append({"mode": mode, "ms_per_frame": round(ms, 3), "primitives": prims,
                        "coverage": round(covered, 4)})
        GL.glUseProgram(0)
    print("RESULT " + json.dumps({"info": info, "triangles": count // 3, "results": results}))


def write_png(path, rgb):
    import struct
    import zlib
    h, w, _ = rgb.shape
    raw = b"".join(b"\x00" + rgb[y].tobytes() for y in range(h))

    def chunk(t, d):
        return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xffffffff)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
                + chunk(b"IDAT", zlib.compress(raw, 6)) + chunk(b"IEND", b""))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("mesh")
    ap.add_argument("--frames", type=int, default=20)
    ap.add_argument("--size", type=int, default=1024)
    ap.add_argument("--png", default=None, help="also write PREFIX_<shading>.png of the last frame")
    ap.add_argument("--moving", choices=("object", "light"), default="object",
                    help="what changes from frame to frame: the object turns, or the light circles it")
    a = ap.parse_args()
    xvfb = None
    if not os.environ.get("DISPLAY"):
        xvfb, os.environ["DISPLAY"] = start_xvfb()
    try:
        run(a.mesh, a.frames, a.size, a.png, a.moving)
    finally:
        sys.stdout.flush()
        if xvfb:
            xvfb.terminate()
    # Without freeglut's exit handlers, which would talk to the X server just stopped.
    os._exit(0)


if __name__ == "__main__":
    main()
