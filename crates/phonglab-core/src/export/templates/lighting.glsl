// The whole of OpenGL 2.1's lighting (section 2.14.1), read from GL's own state:
// gl_LightSource[i], gl_FrontMaterial, gl_BackMaterial and gl_LightModel, and, for the
// state GLSL has no variable for, the u_ uniforms the program reads with glGet* each frame.
// Every glLight*, glMaterial*, glLightModel*, glEnable(GL_LIGHTi) and glColorMaterial call
// of the program changes what this computes, as it would change fixed-function GL.
// The defines above say the rule set's departures from OpenGL, fixed when it was written.
uniform int u_light_on[8];         // glIsEnabled(GL_LIGHTi)
uniform int u_local_viewer;        // GL_LIGHT_MODEL_LOCAL_VIEWER
uniform int u_two_side;            // GL_LIGHT_MODEL_TWO_SIDE
uniform int u_separate_specular;   // GL_LIGHT_MODEL_COLOR_CONTROL == GL_SEPARATE_SPECULAR_COLOR
uniform int u_color_material;      // 0: off; 1 ambient, 2 diffuse, 3 specular, 4 emission, 5 ambient and diffuse
uniform int u_color_material_face; // 1 GL_FRONT, 2 GL_BACK, 3 GL_FRONT_AND_BACK
uniform int u_flat;                // glGetIntegerv(GL_SHADE_MODEL) == GL_FLAT

struct Side {
    vec4 ambient;
    vec4 diffuse;
    vec4 specular;
    vec4 emission;
    float shininess;
};

// A side's material, with the current colour where GL_COLOR_MATERIAL tracks it.
Side side_material(bool back, vec4 color) {
    Side m;
    if (back) {
        m = Side(gl_BackMaterial.ambient, gl_BackMaterial.diffuse, gl_BackMaterial.specular,
                 gl_BackMaterial.emission, gl_BackMaterial.shininess);
    } else {
        m = Side(gl_FrontMaterial.ambient, gl_FrontMaterial.diffuse, gl_FrontMaterial.specular,
                 gl_FrontMaterial.emission, gl_FrontMaterial.shininess);
    }
    bool tracked = u_color_material != 0 && (u_color_material_face == 3 || u_color_material_face == (back ? 2 : 1));
    if (tracked) {
        if (u_color_material == 1 || u_color_material == 5) m.ambient = color;
        if (u_color_material == 2 || u_color_material == 5) m.diffuse = color;
        if (u_color_material == 3) m.specular = color;
        if (u_color_material == 4) m.emission = color;
    }
    return m;
}

// x^e with 0^0 = 1 (GLSL's pow leaves x <= 0 undefined).
float power(float x, float e) {
    if (e == 0.0) return 1.0;
    return x > 0.0 ? pow(x, e) : 0.0;
}

// One side's colours at the eye-space point P with the side's unit normal N (the zero
// vector where the normal has no direction; -n for the back side, `back`): primary (rgb,
// alpha) and secondary.
void light_side(Side m, vec3 N, bool back, vec3 P, out vec4 primary, out vec3 secondary) {
    vec3 sum = vec3(0.0);
    secondary = vec3(0.0);
    bool n_ok = dot(N, N) > 0.0;
    vec3 V = vec3(0.0, 0.0, 1.0);
    bool v_ok = true;
    if (u_local_viewer != 0) {
        v_ok = dot(P, P) > 0.0;
        V = v_ok ? normalize(-P) : vec3(0.0);
    } else {
#if VIEWER_FROM_EYE_PLANE
        v_ok = P.z != 0.0;
        V = vec3(0.0, 0.0, P.z > 0.0 ? -1.0 : 1.0);
#endif
    }
    for (int i = 0; i < 8; i++) {
        if (u_light_on[i] == 0) continue;
        vec4 lp = gl_LightSource[i].position;
        vec3 L;
        bool l_ok = true;
        float att = 1.0;
        if (lp.w != 0.0) {
            vec3 toL = lp.xyz / lp.w - P;
            float d = length(toL);
            l_ok = d > 0.0;
            L = l_ok ? toL / d : vec3(0.0);
            att = 1.0 / (gl_LightSource[i].constantAttenuation + gl_LightSource[i].linearAttenuation * d
                         + gl_LightSource[i].quadraticAttenuation * d * d);
        } else {
            L = normalize(lp.xyz);
        }
        float spot = 1.0;
        if (gl_LightSource[i].spotCutoff != 180.0) {
            float c = l_ok ? dot(-L, normalize(gl_LightSource[i].spotDirection)) : 0.0;
            spot = (l_ok && c >= gl_LightSource[i].spotCosCutoff) ? power(max(c, 0.0), gl_LightSource[i].spotExponent) : 0.0;
        }
        vec3 amb = gl_LightSource[i].ambient.rgb * m.ambient.rgb;
        vec3 dif = vec3(0.0);
        vec3 spe = vec3(0.0);
        if (n_ok && l_ok) {
            float ndl = dot(N, L);
            float c = 0.0;
            bool c_ok = v_ok;
#if SPECULAR_REFLECTION
            // R as phonglab forms it: once per light, about the front side's normal (the
            // same R for both sides, but where the demo's rule clamps n.L).
            vec3 Nf = back ? -N : N;
#if REFLECT_CLAMPED
            vec3 R = 2.0 * max(dot(Nf, L), 0.0) * Nf - L;
#else
            vec3 R = 2.0 * dot(Nf, L) * Nf - L;
#endif
            c = dot(R, V);
#else
            vec3 LV = L + V;
            c_ok = c_ok && dot(LV, LV) > 0.0;
            c = c_ok ? dot(N, normalize(LV)) : 0.0;
#endif
#if SPECULAR_GATE == 1
            bool allowed = c_ok && ndl > 0.0;
#elif SPECULAR_GATE == 2
            bool allowed = c_ok && c > 0.0;
#else
            bool allowed = c_ok;
#endif
            float p = allowed ? power(max(c, 0.0), m.shininess) : 0.0;
#if SPECULAR_NORMALISED
            p = p * (m.shininess + 8.0) / (8.0 * 3.14159265358979);
#endif
            dif = gl_LightSource[i].diffuse.rgb * m.diffuse.rgb * max(ndl, 0.0);
            spe = gl_LightSource[i].specular.rgb * m.specular.rgb * p;
        }
        if (u_separate_specular != 0) {
            sum += att * spot * (amb + dif);
            secondary += att * spot * spe;
        } else {
            sum += att * spot * (amb + dif + spe);
        }
    }
#if SCENE_AMBIENT
    sum += m.emission.rgb + m.ambient.rgb * gl_LightModel.ambient.rgb;
#endif
    primary = vec4(sum, m.diffuse.a);
}

// The normal as the lighting uses it: GL_NORMALIZE's or GL_RESCALE_NORMAL's (u_normal_mode
// 1 or 2, from glIsEnabled), else as it came; the zero vector where it has no direction.
uniform int u_normal_mode;
uniform float u_rescale;

vec3 lighting_normal(vec3 n) {
    if (u_normal_mode == 1) return dot(n, n) > 0.0 ? normalize(n) : vec3(0.0);
    if (u_normal_mode == 2) return n * u_rescale;
    return n;
}
