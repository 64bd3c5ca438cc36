//! The general shaders the exported programs draw with: the whole of OpenGL 2.1's
//! lighting read from GL's own state (`gl_LightSource[]`, `gl_FrontMaterial`,
//! `gl_BackMaterial`, `gl_LightModel`, and uniforms the program reads with `glGet*` for
//! what GLSL has no variable for: the local viewer, two-sided lighting, the colour
//! control, the enabled lights, `GL_NORMALIZE` and `GL_COLOR_MATERIAL`). A student who
//! edits a `glLight*`, `glMaterial*` or `glLightModel*` call of the program changes what
//! they draw, as fixed-function GL would. Only the rule set's departures from OpenGL (the
//! worksheet's, the Phong demo's, energy-conserving Blinn-Phong) are fixed, as `#define`
//! lines at the top; `phonglab shader` keeps printing the scene's specialised shaders.
//!
//! GLSL 1.20, so a GL 2.1 context (openFrameworks' default renderer) compiles them as a
//! compatibility-profile one does.

use crate::model::rules::{Rules, SpecularGate, SpecularVector};

/// The lighting function both stages include (see the module's documentation).
const LIGHTING: &str = include_str!("templates/lighting.glsl");
/// The vertex stage: eye-space position and normal; the lighting itself under Gouraud.
const VERTEX: &str = include_str!("templates/general.vert");
/// The fragment stage: the lighting under Phong, else the interpolated colours.
const FRAGMENT: &str = include_str!("templates/general.frag");

/// The two stages (vertex, fragment) for `rules`, lighting per fragment (Phong shading)
/// or per vertex (Gouraud).
pub fn stages(rules: Rules, per_fragment: bool) -> (String, String) {
    let head = format!("#version 120\n{}{LIGHTING}\n", defines(rules, per_fragment));
    (format!("{head}{VERTEX}"), format!("{head}{FRAGMENT}"))
}

/// The `#define` lines that fix the shading and the rule set's departures from OpenGL 2.1
/// (each flag 1 or 0, as named; the specular gate 0: none, 1: OpenGL's n.L > 0, 2: the
/// worksheet's cosine > 0).
fn defines(rules: Rules, per_fragment: bool) -> String {
    let gate = match rules.specular_gate() {
        SpecularGate::None => 0,
        SpecularGate::LitSide => 1,
        SpecularGate::PositiveCosine => 2,
    };
    // Every form of the term named, so a new one makes the compiler point here.
    let reflection = match rules.specular.vector() {
        SpecularVector::Halfway => false,
        SpecularVector::Reflection => true,
    };
    let flags = [
        ("PER_FRAGMENT", per_fragment),
        ("SCENE_AMBIENT", rules.scene_ambient() && rules.emission()),
        ("CLAMP_VERTEX_COLORS", rules.clamps_vertex_colors()),
        ("VIEWER_FROM_EYE_PLANE", rules.viewer_from_eye_plane()),
        ("SPECULAR_REFLECTION", reflection),
        ("REFLECT_CLAMPED", rules.reflect_clamped()),
        ("SPECULAR_NORMALISED", rules.specular.normalised()),
    ];
    let mut s: String = flags.iter().map(|(name, on)| format!("#define {name} {}\n", u8::from(*on))).collect();
    s.push_str(&format!("#define SPECULAR_GATE {gate}\n"));
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_defines_follow_the_rule_set() {
        let (v, f) = stages(Rules::OPENGL, true);
        for text in [&v, &f] {
            assert!(text.starts_with("#version 120\n#define PER_FRAGMENT 1\n#define SCENE_AMBIENT 1\n"));
            assert!(text.contains("#define SPECULAR_GATE 1\n"));
            assert!(text.contains("gl_LightSource[i].position"));
        }
        let (v, _) = stages(Rules::PHONG_DEMO, false);
        assert!(v.contains("#define PER_FRAGMENT 0\n#define SCENE_AMBIENT 0\n#define CLAMP_VERTEX_COLORS 0\n"));
        assert!(v.contains("#define SPECULAR_REFLECTION 1\n#define REFLECT_CLAMPED 1\n"));
        assert!(v.contains("#define SPECULAR_GATE 0\n"));
        let (v, _) = stages(Rules::WORKSHEET, false);
        assert!(v.contains("#define VIEWER_FROM_EYE_PLANE 1\n") && v.contains("#define SPECULAR_GATE 2\n"));
    }
}
