"""Runs phonglab's generated GLSL under a real OpenGL (Mesa llvmpipe, headless through the
glref harness's EGL-surfaceless context) and writes each picture as a PNG.

Usage:
    PHONGLAB_MESA_INPUTS=/tmp/glsl-in cargo test --test all shader_mesa::write_inputs -- --ignored
    $GLREF/.venv/bin/python scripts/shader_mesa.py /tmp/glsl-in tests/data/mesa_glsl

GLREF is the glref harness's directory (docs/lighting.md says what it is); its venv has
PyOpenGL and numpy. Each input NAME.json holds a program exactly as `phonglab shader`
prints it (vertex and fragment GLSL 3.30), its uniforms' values, the mesh (positions,
normals, triangle indices) and the picture's size and background; the output is NAME.png,
rows top to bottom, as phonglab's CPU renderer writes them. Drawn as the CPU renderer
draws: depth test LESS, no culling, cleared to the background, one sample a pixel.
"""
import glob
import json
import os
import struct
import sys
import zlib

GLREF = os.environ.get("GLREF")
if not GLREF:
    sys.exit("set GLREF to the glref harness's directory")
sys.path.insert(0, GLREF)
import glctx  # noqa: E402

glctx.select_backend("egl")
info = glctx.create_context(16, 16)

import numpy as np  # noqa: E402
from OpenGL import GL  # noqa: E402


def write_png(path, rgb, size):
    raw = b"".join(b"\x00" + rgb[y].tobytes() for y in range(size))

    def chunk(kind, data):
        c = kind + data
        return struct.pack(">I", len(data)) + c + struct.pack(">I", zlib.crc32(c) & 0xFFFFFFFF)

    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", size, size, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
    open(path, "wb").write(png)


def compile_program(vs, fs):
    prog = GL.glCreateProgram()
    for kind, src in ((GL.GL_VERTEX_SHADER, vs), (GL.GL_FRAGMENT_SHADER, fs)):
        sh = GL.glCreateShader(kind)
        GL.glShaderSource(sh, src)
        GL.glCompileShader(sh)
        if not GL.glGetShaderiv(sh, GL.GL_COMPILE_STATUS):
            raise RuntimeError(GL.glGetShaderInfoLog(sh).decode())
        GL.glAttachShader(prog, sh)
    GL.glLinkProgram(prog)
    if not GL.glGetProgramiv(prog, GL.GL_LINK_STATUS):
        raise RuntimeError(GL.glGetProgramInfoLog(prog).decode())
    return prog


def set_uniform(prog, u):
    loc = GL.glGetUniformLocation(prog, u["name"])
    if loc < 0:
        return  # declared but unused: the compiler removed it
    v = np.array(u["value"], dtype=np.float32)
    t = u["type"]
    if t == "mat4":
        GL.glUniformMatrix4fv(loc, 1, GL.GL_FALSE, v)
    elif t == "mat3":
        GL.glUniformMatrix3fv(loc, 1, GL.GL_FALSE, v)
    elif t == "vec4":
        GL.glUniform4fv(loc, 1, v)
    elif t == "vec3":
        GL.glUniform3fv(loc, 1, v)
    elif t == "float":
        GL.glUniform1f(loc, float(v[0]))
    else:
        raise ValueError(t)


def draw(inp, out_dir):
    size = inp["size"]
    fbo = GL.glGenFramebuffers(1)
    GL.glBindFramebuffer(GL.GL_FRAMEBUFFER, fbo)
    rc, rd = GL.glGenRenderbuffers(2)
    GL.glBindRenderbuffer(GL.GL_RENDERBUFFER, rc)
    GL.glRenderbufferStorage(GL.GL_RENDERBUFFER, GL.GL_RGBA8, size, size)
    GL.glFramebufferRenderbuffer(GL.GL_FRAMEBUFFER, GL.GL_COLOR_ATTACHMENT0, GL.GL_RENDERBUFFER, rc)
    GL.glBindRenderbuffer(GL.GL_RENDERBUFFER, rd)
    GL.glRenderbufferStorage(GL.GL_RENDERBUFFER, GL.GL_DEPTH_COMPONENT32F, size, size)
    GL.glFramebufferRenderbuffer(GL.GL_FRAMEBUFFER, GL.GL_DEPTH_ATTACHMENT, GL.GL_RENDERBUFFER, rd)
    assert GL.glCheckFramebufferStatus(GL.GL_FRAMEBUFFER) == GL.GL_FRAMEBUFFER_COMPLETE
    GL.glViewport(0, 0, size, size)
    GL.glEnable(GL.GL_DEPTH_TEST)
    GL.glDepthFunc(GL.GL_LESS)
    GL.glDisable(GL.GL_CULL_FACE)
    bg = [round(min(max(c, 0.0), 1.0) * 255.0) / 255.0 for c in inp["background"]]
    GL.glClearColor(bg[0], bg[1], bg[2], 1.0)
    GL.glClearDepth(1.0)
    GL.glClear(GL.GL_COLOR_BUFFER_BIT | GL.GL_DEPTH_BUFFER_BIT)
    prog = compile_program(inp["vertex"], inp["fragment"])
    GL.glUseProgram(prog)
    for u in inp["uniforms"]:
        set_uniform(prog, u)
    vao = GL.glGenVertexArrays(1)
    GL.glBindVertexArray(vao)
    pos = np.array(inp["positions"], dtype=np.float32)
    nrm = np.array(inp["normals"], dtype=np.float32)
    idx = np.array(inp["indices"], dtype=np.uint32)
    bufs = GL.glGenBuffers(3)
    for loc, (buf, data) in enumerate(((bufs[0], pos), (bufs[1], nrm))):
        GL.glBindBuffer(GL.GL_ARRAY_BUFFER, buf)
        GL.glBufferData(GL.GL_ARRAY_BUFFER, data.nbytes, data, GL.GL_STATIC_DRAW)
        GL.glEnableVertexAttribArray(loc)
        GL.glVertexAttribPointer(loc, 3, GL.GL_FLOAT, GL.GL_FALSE, 0, None)
    GL.glBindBuffer(GL.GL_ELEMENT_ARRAY_BUFFER, bufs[2])
    GL.glBufferData(GL.GL_ELEMENT_ARRAY_BUFFER, idx.nbytes, idx, GL.GL_STATIC_DRAW)
    GL.glDrawElements(GL.GL_TRIANGLES, len(idx), GL.GL_UNSIGNED_INT, None)
    err = GL.glGetError()
    if err:
        raise RuntimeError("GL error 0x%x" % err)
    GL.glFinish()
    px = GL.glReadPixels(0, 0, size, size, GL.GL_RGB, GL.GL_UNSIGNED_BYTE)
    rgb = np.frombuffer(px, dtype=np.uint8).reshape(size, size, 3)[::-1]  # GL's rows run bottom up
    write_png(os.path.join(out_dir, inp["name"] + ".png"), np.ascontiguousarray(rgb), size)
    GL.glDeleteBuffers(3, bufs)
    GL.glDeleteVertexArrays(1, [vao])
    GL.glDeleteProgram(prog)
    GL.glDeleteFramebuffers(1, [fbo])
    GL.glDeleteRenderbuffers(2, [rc, rd])


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    in_dir, out_dir = sys.argv[1], sys.argv[2]
    os.makedirs(out_dir, exist_ok=True)
    files = sorted(glob.glob(os.path.join(in_dir, "*.json")))
    for f in files:
        draw(json.load(open(f)), out_dir)
    print("%d pictures by %s (%s) in %s" % (len(files), info["GL_RENDERER"], info["GL_VERSION"], out_dir))


main()
