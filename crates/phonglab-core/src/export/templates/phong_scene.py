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

{{rules_comment}}RULES = {{rules:str}}
SIZE = 512
BACKGROUND = ({{background}})

{{shaders_comment}}vertex_shader = """
{{vertex_shader:block}}"""

fragment_shader = """
{{fragment_shader:block}}"""

{{matrices}}{{lighting_state}}def scalar(v):
    return float(np.asarray(v).reshape(-1)[0])


def set_uniforms(program):
    """{{reader_doc:doc}}"""
    def location(name):
        return glGetUniformLocation(program, name)

    def flag(value):
        return 1 if value else 0

    modelview = LIGHTING_MODELVIEW
    m3 = modelview[:3, :3]
    # {{normal_matrix_comment:comment}}
    normal_matrix = m3 if RULES == "worksheet" else np.linalg.inv(m3).T
    glUniformMatrix4fv(location("u_eye_from_object"), 1, GL_TRUE, np.asarray(modelview, dtype=np.float32))
    glUniformMatrix3fv(location("u_normal_matrix"), 1, GL_TRUE, np.asarray(normal_matrix, dtype=np.float32))
    glUniform1f(location("u_rescale"), 1.0 / np.linalg.norm(np.linalg.inv(m3)[2]))
    glUniform1iv(location("u_light_on"), 8, np.array([flag(glIsEnabled(GL_LIGHT0 + i)) for i in range(8)], dtype=np.int32))
    glUniform1i(location("u_local_viewer"), flag(scalar(glGetIntegerv(GL_LIGHT_MODEL_LOCAL_VIEWER))))
    glUniform1i(location("u_two_side"), flag(scalar(glGetIntegerv(GL_LIGHT_MODEL_TWO_SIDE))))
    control = int(scalar(glGetIntegerv(GL_LIGHT_MODEL_COLOR_CONTROL)))
    glUniform1i(location("u_separate_specular"), flag(control == GL_SEPARATE_SPECULAR_COLOR))
    glUniform1i(location("u_normal_mode"), 1 if glIsEnabled(GL_NORMALIZE) else 2 if glIsEnabled(GL_RESCALE_NORMAL) else 0)
    tracked = {int(GL_AMBIENT): 1, int(GL_DIFFUSE): 2, int(GL_SPECULAR): 3, int(GL_EMISSION): 4, int(GL_AMBIENT_AND_DIFFUSE): 5}
    faces = {int(GL_FRONT): 1, int(GL_BACK): 2, int(GL_FRONT_AND_BACK): 3}
    mode = tracked.get(int(scalar(glGetIntegerv(GL_COLOR_MATERIAL_PARAMETER))), 0)
    glUniform1i(location("u_color_material"), mode if glIsEnabled(GL_COLOR_MATERIAL) else 0)
    glUniform1i(location("u_color_material_face"), faces.get(int(scalar(glGetIntegerv(GL_COLOR_MATERIAL_FACE))), 3))
    glUniform1i(location("u_flat"), flag(int(scalar(glGetIntegerv(GL_SHADE_MODEL))) == GL_FLAT))

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
{{two_side_comment}}    glEnable(GL_VERTEX_PROGRAM_TWO_SIDE)
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
