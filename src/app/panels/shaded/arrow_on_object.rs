//! One vector of the worked calculation drawn on the shaded picture: where it starts and
//! ends on the screen, and whether it is drawn faded. The overlay finds and draws them; the
//! view hands them to the shell (and the tests) with the rest of what it drew.

use egui::Color32;

/// One of N, V, L, H (or R) drawn from the worked calculation's vertex on the picture.
#[derive(Clone, Debug, PartialEq)]
pub struct ArrowOnObject {
    /// Its name (`L1` with several lights).
    pub name: String,
    /// Its colour (the plot's).
    pub colour: Color32,
    /// The vertex on the picture.
    pub from: egui::Pos2,
    /// Its tip on the picture: the vector, one world length long, projected (so one that
    /// points at the viewer is foreshortened).
    pub to: egui::Pos2,
    /// It points away from the viewer (into the picture).
    pub away: bool,
    /// It points into the surface (below the tangent plane, against N).
    pub behind: bool,
}

impl ArrowOnObject {
    /// Drawn faded, with an open head: it points away from the viewer or into the surface.
    pub fn faded(&self) -> bool {
        self.away || self.behind
    }
}
