varying vec3 v_pos;
varying vec3 v_normal;
varying vec4 v_color;
varying vec4 v_front;
varying vec3 v_front_secondary;
varying vec4 v_back;
varying vec3 v_back_secondary;

void main() {
    bool back = u_two_side != 0 && !gl_FrontFacing;
    vec4 p;
    vec3 s;
    if (u_flat != 0) {
        // glShadeModel(GL_FLAT): the triangle's provoking vertex's colours, the side it
        // shows (GL_VERTEX_PROGRAM_TWO_SIDE), as fixed-function OpenGL draws it.
        p = gl_Color;
        s = gl_SecondaryColor.rgb;
    } else {
#if PER_FRAGMENT
        vec3 N = lighting_normal(v_normal);
        light_side(side_material(back, v_color), back ? -N : N, back, v_pos, p, s);
#if CLAMP_VERTEX_COLORS
        p = clamp(p, 0.0, 1.0);
        s = clamp(s, 0.0, 1.0);
#endif
#else
        p = back ? v_back : v_front;
        s = back ? v_back_secondary : v_front_secondary;
#endif
    }
    gl_FragColor = vec4(clamp(p.rgb + s, 0.0, 1.0), p.a);
}
