uniform mat4 u_eye_from_object;
uniform mat3 u_normal_matrix;
varying vec3 v_pos;
varying vec3 v_normal;
varying vec4 v_color;
varying vec4 v_front;
varying vec3 v_front_secondary;
varying vec4 v_back;
varying vec3 v_back_secondary;

vec4 clamped(vec4 c) {
#if CLAMP_VERTEX_COLORS
    return clamp(c, 0.0, 1.0);
#else
    return c;
#endif
}

// The vertex's colours, front and back, in the varyings Gouraud interpolates and in GL's
// own colour varyings, which GL gives a whole triangle from its provoking (last) vertex
// under glShadeModel(GL_FLAT), as fixed-function OpenGL does.
void vertex_colours() {
    vec3 N = lighting_normal(v_normal);
    vec4 p;
    vec3 s;
    light_side(side_material(false, gl_Color), N, false, v_pos, p, s);
    v_front = clamped(p);
    v_front_secondary = clamped(vec4(s, 1.0)).rgb;
    v_back = v_front;
    v_back_secondary = v_front_secondary;
    if (u_two_side != 0) {
        light_side(side_material(true, gl_Color), -N, true, v_pos, p, s);
        v_back = clamped(p);
        v_back_secondary = clamped(vec4(s, 1.0)).rgb;
    }
    gl_FrontColor = v_front;
    gl_FrontSecondaryColor = vec4(v_front_secondary, 1.0);
    gl_BackColor = v_back;
    gl_BackSecondaryColor = vec4(v_back_secondary, 1.0);
}

void main() {
    vec4 Ph = u_eye_from_object * vec4(gl_Vertex.xyz / gl_Vertex.w, 1.0);
    v_pos = Ph.xyz / Ph.w;
    v_normal = u_normal_matrix * gl_Normal;
    v_color = gl_Color;
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
#if PER_FRAGMENT
    if (u_flat != 0) vertex_colours();
#else
    vertex_colours();
#endif
}
