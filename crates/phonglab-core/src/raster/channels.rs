//! Term channels: one term of the lighting equation at every pixel, as an image.
//!
//! Each covered pixel gets the probe's terms ([`Surfaces::terms_at`]: the same function, so
//! a channel's value at a pixel is the probe's there). The colour terms (emission, scene
//! ambient, and each light's ambient, diffuse and specular after attenuation and spot)
//! add up to the colour before any clamp: for Phong and Flat the fragment's, for Gouraud
//! the interpolation of the vertices' unclamped colours. The others are scalars of one
//! light (attenuation, spot factor, `n . L`, `n . H`), the normal, and the number of lights
//! that reach the pixel.
//!
//! Shown in false colour ([`ChannelImage::false_colour`]): a scalar (a colour term's
//! Rec. 709 luminance) mapped over [`ChannelImage::range`] by viridis or cividis, both
//! readable with every common colour-vision deficiency; the normal as `n / 2 + 1/2` in rgb.

use crate::equation::plan::{Key, Program, Stage};
use crate::model::error::SceneError;
use crate::model::rules::SpecularVector;
use crate::model::scene::Side;
use crate::raster::probe::{LightShare, Surfaces, Terms};
use crate::raster::render::{Job, Renderer};

/// One term as an image.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default, serde::Serialize, serde::Deserialize)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
#[serde(rename_all = "kebab-case")]
pub enum Channel {
    /// `e_cm`.
    Emission,
    /// `a_cm a_cs`.
    SceneAmbient,
    /// `att spot a_cm a_cl`, summed over the lights (or one light's).
    Ambient,
    /// `att spot max(n . L, 0) d_cm d_cl`.
    #[default]
    Diffuse,
    /// `att spot f max(n . H, 0)^s s_cm s_cl`.
    Specular,
    /// One light's attenuation.
    Attenuation,
    /// One light's spot factor.
    Spot,
    /// One light's `n . L`.
    NDotL,
    /// One light's specular cosine, `n . H`.
    NDotH,
    /// The normal the pixel is lit with, as a colour.
    Normal,
    /// How many lights reach the pixel (on the side it shows, with a share of light).
    LightCount,
}

impl Channel {
    /// Every channel, in menu order.
    pub const ALL: [Channel; 11] = [
        Channel::Emission,
        Channel::SceneAmbient,
        Channel::Ambient,
        Channel::Diffuse,
        Channel::Specular,
        Channel::Attenuation,
        Channel::Spot,
        Channel::NDotL,
        Channel::NDotH,
        Channel::Normal,
        Channel::LightCount,
    ];

    /// Its name on the command line and in files.
    pub fn name(self) -> &'static str {
        match self {
            Channel::Emission => "emission",
            Channel::SceneAmbient => "scene-ambient",
            Channel::Ambient => "ambient",
            Channel::Diffuse => "diffuse",
            Channel::Specular => "specular",
            Channel::Attenuation => "attenuation",
            Channel::Spot => "spot",
            Channel::NDotL => "n-dot-l",
            Channel::NDotH => "n-dot-h",
            Channel::Normal => "normal",
            Channel::LightCount => "light-count",
        }
    }

    /// Its label's message id in the catalogue.
    pub fn message_id(self) -> &'static str {
        match self {
            Channel::Emission => "channel-emission",
            Channel::SceneAmbient => "channel-scene-ambient",
            Channel::Ambient => "channel-ambient",
            Channel::Diffuse => "channel-diffuse",
            Channel::Specular => "channel-specular",
            Channel::Attenuation => "channel-attenuation",
            Channel::Spot => "channel-spot",
            Channel::NDotL => "channel-n-dot-l",
            Channel::NDotH => "channel-n-dot-h",
            Channel::Normal => "channel-normal",
            Channel::LightCount => "channel-light-count",
        }
    }

    /// Its label's message id for a scene whose program is `program`: the specular cosine
    /// is named as the program forms it (`N·H`, or Phong's `R·V`).
    pub fn message_id_for(self, program: &Program) -> &'static str {
        let mut id = self.message_id();
        for &stage in &program.stages {
            match stage {
                Stage::SpecularCosine(_, _, vector) if self == Channel::NDotH => {
                    id = match vector {
                        SpecularVector::Halfway => "channel-n-dot-h",
                        SpecularVector::Reflection => "channel-r-dot-v",
                    }
                }
                // The other channels' terms have one name whatever their stages.
                Stage::SpecularCosine(..)
                | Stage::TransformNormal
                | Stage::RescaleNormal
                | Stage::NormalizeNormal
                | Stage::NormalizeNormalFast
                | Stage::TransformPosition
                | Stage::TransformPositionProjective
                | Stage::TranslatePosition
                | Stage::ZeroNormals
                | Stage::ViewVector(_)
                | Stage::LightVector(_)
                | Stage::LightConstant(_)
                | Stage::Attenuate(_)
                | Stage::SpotCone(_)
                | Stage::SpotPower(_)
                | Stage::Halfway(_)
                | Stage::HalfwayConstant(_)
                | Stage::Reflect(_)
                | Stage::DiffuseCosine(..)
                | Stage::Power(..)
                | Stage::Sum(..)
                | Stage::SceneColor => {}
            }
        }
        id
    }

    /// An rgb value per pixel (the colour terms and the normal), else one.
    pub fn components(self) -> usize {
        match self {
            Channel::Emission
            | Channel::SceneAmbient
            | Channel::Ambient
            | Channel::Diffuse
            | Channel::Specular
            | Channel::Normal => 3,
            _ => 1,
        }
    }

    /// A term of one light (its value for the light asked, or, for the colour terms,
    /// summed over the lights when none is asked).
    pub fn per_light(self) -> bool {
        matches!(
            self,
            Channel::Ambient
                | Channel::Diffuse
                | Channel::Specular
                | Channel::Attenuation
                | Channel::Spot
                | Channel::NDotL
                | Channel::NDotH
        )
    }

    /// The channel's value from a pixel's terms and normal: `light` picks a light by its
    /// place among the enabled ones (the colour terms sum them all when `None`; the scalar
    /// terms take the first).
    pub fn value(self, terms: &Terms, normal: [f64; 3], light: Option<usize>) -> [f64; 3] {
        let pick = |f: &dyn Fn(&LightShare) -> f64| -> [f64; 3] {
            let v = terms.lights.get(light.unwrap_or(0)).map_or(0.0, f);
            [v, v, v]
        };
        let sum = |f: &dyn Fn(&LightShare) -> [f64; 3]| -> [f64; 3] {
            let chosen: Vec<&LightShare> = match light {
                Some(i) => terms.lights.get(i).into_iter().collect(),
                None => terms.lights.iter().collect(),
            };
            std::array::from_fn(|c| chosen.iter().map(|l| f(l)[c]).sum())
        };
        match self {
            Channel::Emission => terms.emission,
            Channel::SceneAmbient => terms.scene_ambient,
            Channel::Ambient => sum(&|l| l.ambient),
            Channel::Diffuse => sum(&|l| l.diffuse),
            Channel::Specular => sum(&|l| l.specular),
            Channel::Attenuation => pick(&|l| l.attenuation),
            Channel::Spot => pick(&|l| l.spot),
            Channel::NDotL => pick(&|l| l.n_dot_l),
            Channel::NDotH => pick(&|l| l.n_dot_h),
            Channel::Normal => normal,
            Channel::LightCount => {
                let n = terms.lights_reaching() as f64;
                [n, n, n]
            }
        }
    }
}

/// A colour map readable with every common colour-vision deficiency.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default, serde::Serialize, serde::Deserialize)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
#[serde(rename_all = "kebab-case")]
pub enum ColourMap {
    /// Matplotlib's viridis (dark blue, green, yellow).
    #[default]
    Viridis,
    /// Cividis (blue to yellow), made for deuteranopia and protanopia.
    Cividis,
}

impl ColourMap {
    /// The map's colour at `t` in [0, 1] (clamped), sRGB bytes.
    pub fn at(self, t: f64) -> [u8; 3] {
        let g = match self {
            ColourMap::Viridis => colorous::VIRIDIS,
            ColourMap::Cividis => colorous::CIVIDIS,
        };
        let c = g.eval_continuous(if t.is_finite() { t.clamp(0.0, 1.0) } else { 0.0 });
        [c.r, c.g, c.b]
    }
}

/// One channel at every pixel, rows top to bottom.
#[derive(Clone, Debug, PartialEq)]
pub struct ChannelImage {
    /// The channel.
    pub channel: Channel,
    /// Width in pixels.
    pub width: usize,
    /// Height in pixels.
    pub height: usize,
    /// Values per pixel ([`Channel::components`]); `None` where no surface covers it.
    pub values: Vec<Option<[f64; 3]>>,
    /// The lights enabled (for the light count's scale).
    pub lights: usize,
    /// The channel's label's message id for this scene ([`Channel::message_id_for`]).
    pub message_id: &'static str,
}

/// Rec. 709's luminance of a linear rgb.
pub fn luminance(c: [f64; 3]) -> f64 {
    0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]
}

impl ChannelImage {
    /// The scalar a pixel is coloured by: the value (one component), or a colour term's
    /// luminance.
    pub fn scalar(&self, v: [f64; 3]) -> f64 {
        if self.channel.components() == 1 { v[0] } else { luminance(v) }
    }

    /// The range the false colour spans: the cosines over [-1, 1], the spot factor over
    /// [0, 1], the light count over [0, lights]; the rest from 0 to the largest value
    /// shown (at least 1 for the attenuation, which is 1 without it).
    pub fn range(&self) -> (f64, f64) {
        let max = self.values.iter().flatten().map(|v| self.scalar(*v)).fold(0.0f64, f64::max);
        match self.channel {
            Channel::NDotL | Channel::NDotH | Channel::Normal => (-1.0, 1.0),
            Channel::Spot => (0.0, 1.0),
            Channel::LightCount => (0.0, self.lights.max(1) as f64),
            Channel::Attenuation => (0.0, max.max(1.0)),
            _ => (0.0, if max > 0.0 { max } else { 1.0 }),
        }
    }

    /// The picture: each covered pixel in false colour over [`ChannelImage::range`] (the
    /// normal as rgb), the rest `background`; RGBA8.
    pub fn false_colour(&self, map: ColourMap, background: [u8; 3]) -> Vec<u8> {
        self.false_colour_over(map, background, self.range())
    }

    /// [`ChannelImage::false_colour`] over the range `(lo, hi)` (two pictures compared
    /// share one).
    pub fn false_colour_over(&self, map: ColourMap, background: [u8; 3], (lo, hi): (f64, f64)) -> Vec<u8> {
        let span = if hi > lo { hi - lo } else { 1.0 };
        let to_byte = |x: f64| ((x * 0.5 + 0.5).clamp(0.0, 1.0) * 255.0).round() as u8;
        self.values
            .iter()
            .flat_map(|v| {
                let rgb = match v {
                    None => background,
                    Some(n) if self.channel == Channel::Normal => n.map(to_byte),
                    Some(v) => map.at((self.scalar(*v) - lo) / span),
                };
                [rgb[0], rgb[1], rgb[2], 255]
            })
            .collect()
    }
}

/// Channel `channel` (of light `light`, by its place among the enabled ones) of the frame
/// `renderer` last drew from `job` (read from the visibility the renderer keeps).
pub fn channel_image(
    renderer: &Renderer,
    job: &Job<'_>,
    channel: Channel,
    light: Option<usize>,
) -> Result<ChannelImage, SceneError> {
    let (width, height) = renderer.size();
    let mut surfaces = Surfaces::new(job)?;
    let two = job.scene.light_model.two_sided;
    let mut values = Vec::with_capacity(width * height);
    for i in 0..width * height {
        values.push(renderer.surface_at(i).map(|s| {
            let side = Side::back_if(s.back && two);
            let (terms, normal) = surfaces.terms_and_normal_at(&s, side);
            channel.value(&terms, normal, light)
        }));
    }
    let message_id = channel.message_id_for(&Key::of(job.scene, job.options).program());
    Ok(ChannelImage { channel, width, height, values, lights: job.scene.lights.len(), message_id })
}

/// The channel's values as a portable float map (PFM): "PF" (rgb) or "Pf" (one value), the
/// size, -1 (little-endian), then the rows bottom to top; NaN where no surface covers
/// the pixel.
pub fn pfm(image: &ChannelImage) -> Vec<u8> {
    let n = image.channel.components();
    let mut out =
        format!("{}\n{} {}\n-1.0\n", if n == 3 { "PF" } else { "Pf" }, image.width, image.height).into_bytes();
    for row in image.values.chunks(image.width.max(1)).rev() {
        for v in row {
            let v = v.unwrap_or([f64::NAN; 3]);
            for c in v.iter().take(n) {
                out.extend_from_slice(&(*c as f32).to_le_bytes());
            }
        }
    }
    out
}
