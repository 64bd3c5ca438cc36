#!/usr/bin/env python3
"""{{title:doc}}

{{usage:doc}}
"""
import sys
import math
import struct
import zlib

from OpenGL.GLUT import *
from OpenGL.GL import *
from OpenGL.GLU import *
import OpenGL.GL.shaders
import numpy as np  # matrix manipulation

RULES = {{rules:str}}  # {{rules_comment:comment}}
SIZE = 512
BACKGROUND = ({{background}})

# {{shaders_comment:comment}}
vertex_shader = """
{{vertex_shader:block}}"""

fragment_shader = """
{{fragment_shader:block}}"""

# {{uniforms_comment:comment}}
UNIFORMS = [{{uniforms}}]

{{matrices}}{{lighting_state}}def scalar(v):
    return float(np.asarray(v).reshape(-1)[0])


def normalize(v):
    n = np.linalg.norm(v)
    return v / n if n > 0 else v


def state_value(name):
    """{{reader_doc:doc}}"""
    modelview = LIGHTING_MODELVIEW
    m3 = modelview[:3, :3]
    if name.startswith("light"):
        index, what = name[len("light"):].split("_", 1)
        light = GL_LIGHT0 + int(index)
        position = np.array(glGetLightfv(light, GL_POSITION), dtype=np.float64)
        if what == "position":
            return position
        if what == "direction":
            return normalize(position[:3])
        if what == "halfway":
            return normalize(normalize(position[:3]) + np.array([0.0, 0.0, 1.0]))
        if what in ("ambient", "diffuse", "specular"):
            return np.array(glGetLightfv(light, {"ambient": GL_AMBIENT, "diffuse": GL_DIFFUSE, "specular": GL_SPECULAR}[what]))[:3]
        if what == "attenuation":
            return np.array([scalar(glGetLightfv(light, k)) for k in (GL_CONSTANT_ATTENUATION, GL_LINEAR_ATTENUATION, GL_QUADRATIC_ATTENUATION)])
        if what == "spot_direction":
            return np.array(glGetLightfv(light, GL_SPOT_DIRECTION))
        if what == "spot_cos_cutoff":
            return np.array([math.cos(math.radians(scalar(glGetLightfv(light, GL_SPOT_CUTOFF))))])
        if what == "spot_exponent":
            return np.array([scalar(glGetLightfv(light, GL_SPOT_EXPONENT))])
    if name.startswith("mat_") or name.startswith("back_"):
        face = GL_FRONT if name.startswith("mat_") else GL_BACK
        what = name.split("_", 1)[1]
        key = {"ambient": GL_AMBIENT, "diffuse": GL_DIFFUSE, "specular": GL_SPECULAR, "shininess": GL_SHININESS}[what]
        value = np.array(glGetMaterialfv(face, key), dtype=np.float64).reshape(-1)
        return value if what == "diffuse" else value[:1] if what == "shininess" else value[:3]
    if name == "clip_from_object":
        projection = np.array(glGetFloatv(GL_PROJECTION_MATRIX)).T
        drawing = np.array(glGetFloatv(GL_MODELVIEW_MATRIX)).T
        return projection @ drawing
    if name == "eye_from_object":
        return modelview
    if name == "normal_matrix":
        # {{normal_matrix_comment:comment}}
        return m3 if RULES == "worksheet" else np.linalg.inv(m3).T
    if name == "rescale":
        return np.array([1.0 / np.linalg.norm(np.linalg.inv(m3)[2])])
    if name == "scene_color":
        if RULES != "opengl":
            return np.zeros(3)
        emission = np.array(glGetMaterialfv(GL_FRONT, GL_EMISSION))[:3]
        ambient = np.array(glGetMaterialfv(GL_FRONT, GL_AMBIENT))[:3]
        return emission + ambient * np.array(glGetFloatv(GL_LIGHT_MODEL_AMBIENT))[:3]
{{color_reader}}    raise KeyError(name)


def set_uniforms(program):
    for name, kind in UNIFORMS:
        location = glGetUniformLocation(program, "u_" + name)
        if location < 0:
            continue
        value = np.asarray(state_value(name), dtype=np.float32)
        if kind == "mat4":
            glUniformMatrix4fv(location, 1, GL_TRUE, value)
        elif kind == "mat3":
            glUniformMatrix3fv(location, 1, GL_TRUE, value)
        elif kind == "vec4":
            glUniform4fv(location, 1, value)
        elif kind == "vec3":
            glUniform3fv(location, 1, value)
        else:
            glUniform1f(location, float(value[0]))

{{object}}def draw():
    glClearColor(BACKGROUND[0], BACKGROUND[1], BACKGROUND[2], 1.0)
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT)
    glMatrixMode(GL_PROJECTION)
    glLoadIdentity()
    if PROJECTION is None:
        gluPerspective(40, 1, 0.1, 100)
    else:
        glLoadMatrixf(PROJECTION.T)
    glMatrixMode(GL_MODELVIEW)
    glLoadMatrixf(MODELVIEW.T)
    glUseProgram(program)
    set_uniforms(program)
    draw_object(quadric)
    glUseProgram(0)


def save_png(path):
    glPixelStorei(GL_PACK_ALIGNMENT, 1)
    pixels = glReadPixels(0, 0, SIZE, SIZE, GL_RGB, GL_UNSIGNED_BYTE)
    rows = [pixels[(SIZE - 1 - y) * SIZE * 3:(SIZE - y) * SIZE * 3] for y in range(SIZE)]
    raw = b"".join(b"\x00" + bytes(r) for r in rows)
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", SIZE, SIZE, 8, 2, 0, 0, 0))
                + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def display():
    draw()
    glutSwapBuffers()


def main():
    global program, quadric, SIZE
    png = sys.argv[sys.argv.index("--png") + 1] if "--png" in sys.argv else None
    if "--size" in sys.argv:
        SIZE = int(sys.argv[sys.argv.index("--size") + 1])
    glutInit(sys.argv)
    glutInitDisplayMode(GLUT_RGBA | GLUT_DOUBLE | GLUT_DEPTH)
    glutInitWindowSize(SIZE, SIZE)
    glutCreateWindow(b"phonglab")
    glEnable(GL_DEPTH_TEST)
    set_lighting_state()
    program = OpenGL.GL.shaders.compileProgram(
        OpenGL.GL.shaders.compileShader(vertex_shader, GL_VERTEX_SHADER),
        OpenGL.GL.shaders.compileShader(fragment_shader, GL_FRAGMENT_SHADER),
    )
    quadric = gluNewQuadric()
    if png:
        draw()
        glFinish()
        save_png(png)
        return
    glutDisplayFunc(display)
    glutMainLoop()


if __name__ == "__main__":
    main()
