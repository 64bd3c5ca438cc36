//! Ready-made documents, as the app and the CLI open them: the worksheet with each of its
//! modelviews, the Phong demo as its own program draws it, and the demo's departures from
//! OpenGL as switches; the rendering benchmark's job.

use glam::DVec4;

use crate::formats::document::Document;
use crate::model::camera::CameraSpec;
use crate::model::presets::{phong_demo, worksheet};
use crate::model::transform::phong_demo_eye_from_object;
use crate::model::view::{FlatNormal, Framing, LightingSpace, View};

/// The shaded view as the demo's program draws: clip space (no projection), the spin of
/// 0.5 degrees a frame (the first frame drawn has taken one step), lit in object space,
/// `normalize(position)` for normals, Phong without renormalising, Flat from the screen
/// derivatives, gluCylinder not centred, a black background, sphere and Gouraud first.
pub fn phong_demo_view() -> View {
    // The tessellations, the sphere and Gouraud are the default view's: the demo's own.
    View {
        demo_normals: true,
        auto_rotate: true,
        spin_degrees: 0.5,
        framing: Framing::ClipSpace,
        lighting_space: LightingSpace::Object,
        flat_normal: FlatNormal::ScreenDerivatives,
        phong_renormalize: false,
        cylinder_centered: false,
        background: [0.0, 0.0, 0.0],
        ..View::default()
    }
}

/// The Phong demo as a document: [`phong_demo`] lit, [`phong_demo_view`] drawn.
pub fn phong_demo_document() -> Document {
    let mut d = Document::from_scene("the Phong demo", CameraSpec::Matrix(phong_demo_eye_from_object()), phong_demo());
    d.view = phong_demo_view();
    d
}

/// Where the Phong demo departs from OpenGL's lighting: each a switch a teacher can flip.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum DemoDeparture {
    /// The light turns with the object (lit in object space).
    LightTurnsWithObject,
    /// Normals are `normalize(position)`.
    PositionNormals,
    /// The highlight is multiplied by the object's colour.
    HighlightInObjectColour,
}

impl DemoDeparture {
    /// All three, in the order the document lists them.
    pub const ALL: [DemoDeparture; 3] =
        [DemoDeparture::LightTurnsWithObject, DemoDeparture::PositionNormals, DemoDeparture::HighlightInObjectColour];

    /// The correction's name, as the switch shows it.
    pub fn fix_label(self) -> String {
        match self {
            DemoDeparture::LightTurnsWithObject => crate::t!("fix-light-world"),
            DemoDeparture::PositionNormals => crate::t!("fix-true-normals"),
            DemoDeparture::HighlightInObjectColour => crate::t!("fix-highlight-colour"),
        }
    }

    /// One sentence on why.
    pub fn why(self) -> String {
        match self {
            DemoDeparture::LightTurnsWithObject => crate::t!("why-light-world"),
            DemoDeparture::PositionNormals => crate::t!("why-true-normals"),
            DemoDeparture::HighlightInObjectColour => crate::t!("why-highlight-colour"),
        }
    }

    /// Applies the correction to a document.
    pub fn correct(self, d: &mut Document) {
        match self {
            DemoDeparture::LightTurnsWithObject => d.view.lighting_space = LightingSpace::Eye,
            DemoDeparture::PositionNormals => d.view.demo_normals = false,
            DemoDeparture::HighlightInObjectColour => {
                let s = d.scene.material.specular;
                let k = s.x.max(s.y).max(s.z);
                d.scene.material.specular = DVec4::new(k, k, k, s.w);
            }
        }
    }

    /// Does the document still make this departure?
    pub fn present_in(self, d: &Document) -> bool {
        match self {
            DemoDeparture::LightTurnsWithObject => d.view.lighting_space == LightingSpace::Object,
            DemoDeparture::PositionNormals => d.view.demo_normals,
            // Only under the demo's rules: a coloured specular material is ordinary OpenGL
            // (the worksheet's is brass), not the demo's object colour in the highlight.
            DemoDeparture::HighlightInObjectColour => {
                let s = d.scene.material.specular;
                d.scene.rules.set == crate::model::rules::RuleSet::PhongDemo && !(s.x == s.y && s.y == s.z)
            }
        }
    }
}

/// Every built-in document, in menu order: the worksheet with each modelview, the demo.
pub fn documents() -> Vec<(String, Document)> {
    let mut v: Vec<(String, Document)> = (1..=5u8)
        .map(|k| {
            let name = crate::t!("doc-worksheet-preset", k = k.to_string());
            (name.clone(), Document::from_scene(&name, CameraSpec::Worksheet(k), worksheet(k as usize)))
        })
        .collect();
    v.push(("Phong demo".into(), phong_demo_document()));
    v
}

/// A document's name as this language says it: the built-in and shipped scenes' names (in
/// whichever language they were made: scene files keep the English) in the current
/// language; any other name as it is.
pub fn localised_name(name: &str) -> String {
    for id in ["doc-worksheet", "doc-worksheet-preset"] {
        for k in 1..=5 {
            let args = [("k", crate::locale::Arg::Text(k.to_string()))];
            if crate::locale::Lang::ALL.iter().any(|l| crate::locale::tr_in(*l, id, &args) == name) {
                return crate::locale::tr_args(id, &args);
            }
        }
    }
    for id in
        ["doc-phong-demo", "doc-spotlight", "doc-three-lights", "doc-of-set-color", "doc-gouraud-misses-the-highlight"]
    {
        if crate::locale::Lang::ALL.iter().any(|l| crate::locale::tr_in(*l, id, &[]) == name) {
            return crate::locale::tr(id);
        }
    }
    if let Some(material) = name.strip_prefix("Red Book teapots: ") {
        let material = crate::model::materials::display_name(&material.replace(' ', "-"));
        return crate::locale::tr_args("doc-redbook-teapot", &[("material", crate::locale::Arg::Text(material))]);
    }
    name.to_string()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::locale::{Lang, Locale, with_locale};

    #[test]
    fn the_built_in_names_follow_the_language() {
        let english = with_locale(Locale::of(Lang::En), || crate::formats::document::Document::default().name);
        assert_eq!(english, "the worksheet, mview5");
        assert_eq!(with_locale(Locale::of(Lang::PtPt), || localised_name(&english)), "a ficha, mview5");
        assert_eq!(with_locale(Locale::of(Lang::PtBr), || localised_name("Ficha, mview3")), "Lista, mview3");
        assert_eq!(with_locale(Locale::of(Lang::En), || localised_name("Ficha, mview3")), "Worksheet, mview3");
        assert_eq!(localised_name("my scene"), "my scene");
        // The shipped scene files' names (English in the files).
        let pt = |name: &str| with_locale(Locale::of(Lang::PtPt), || localised_name(name));
        assert_eq!(pt("the Phong demo"), "a demo de Phong");
        assert_eq!(pt("a spotlight"), "um foco");
        assert_eq!(pt("three coloured lights and a headlight"), "três luzes coloridas e uma luz presa ao observador");
        assert_eq!(pt("Red Book teapots: yellow rubber"), "bules do Red Book: borracha amarela");
        assert_eq!(with_locale(Locale::of(Lang::En), || localised_name("um foco")), "a spotlight");
    }

    use crate::model::view::{ObjectKind, Shading};

    #[test]
    fn the_demo_view_draws_the_demos_objects() {
        // gluSphere(0.5, 50, 50), glutSolidTeapot's 7 per patch side, gluCylinder(.., 20, 5)
        // with no caps; the sphere under Gouraud first, as the program opens.
        let v = phong_demo_view();
        assert_eq!((v.object, v.shading), (ObjectKind::Sphere, Shading::Gouraud));
        assert_eq!((v.sphere_slices, v.sphere_stacks, v.teapot_grid), (50, 50, 7));
        assert_eq!((v.cylinder_slices, v.cylinder_stacks, v.cylinder_caps), (20, 5, false));
    }
}
