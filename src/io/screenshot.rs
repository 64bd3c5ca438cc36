//! What a screenshot of the window shows: the one list that `phonglab screenshot --open`
//! reads ([`crate::cli`]) and the window opens before drawing itself ([`crate::app`]).

use clap::ValueEnum;

/// What to open before the picture is taken.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Opened {
    /// Compare, with the scene pinned as A and B the same scene in Phong shading.
    Compare,
    /// The reflection lobe in the plot's place.
    Lobe,
    /// The quiz on the scene.
    Quiz,
    /// The Shader window.
    Shader,
    /// The Cost of accuracy window.
    Cost,
    /// The Phong demo's three corrections, side by side with the demo's own picture.
    DemoFixes,
}
