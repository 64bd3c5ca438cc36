//! Where the shaded view's picture is on screen, and how the object's and the eye's spaces
//! map onto it: what the arrows and the lights' markers are drawn with, and what a dragged
//! marker is turned back into.

use glam::{DVec3, DVec4};

/// Where the shaded view's image is, and how object and eye space map onto it.
pub(super) struct Overlay {
    /// The image on screen.
    pub rect: egui::Rect,
    /// The view's projection of the object.
    pub clip_from_object: glam::DMat4,
    /// The inverse of the scene's modelview, as the view lights it.
    pub object_from_eye: glam::DMat4,
}

impl Overlay {
    /// An object-space point (homogeneous) on screen, or `None` behind the camera.
    pub fn screen_from_object(&self, p: DVec4) -> Option<egui::Pos2> {
        let c = self.clip_from_object * p;
        if c.w <= 0.0 || !c.is_finite() {
            return None;
        }
        let (x, y) = (c.x / c.w, c.y / c.w);
        let size = self.rect.size();
        Some(self.rect.min + egui::vec2(((x + 1.0) * 0.5) as f32 * size.x, ((1.0 - y) * 0.5) as f32 * size.y))
    }

    /// An eye-space point on screen.
    pub fn screen_from_eye(&self, p: DVec3) -> Option<egui::Pos2> {
        self.screen_from_object(self.object_from_eye * p.extend(1.0))
    }

    /// The object-space point `at` (behind the camera, where no screen point is its) moved
    /// by `delta` points in the plane facing the viewer at its distance: as far as `delta`
    /// would move a point that far in front, so a marker at the picture's edge drags a
    /// light behind the camera the way the pointer goes.
    pub fn moved_behind(&self, at: DVec4, delta: egui::Vec2) -> Option<DVec4> {
        let eye = self.object_from_eye.inverse() * at;
        let clip_from_eye = self.clip_from_object * self.object_from_eye;
        let (sx, sy) = (clip_from_eye.x_axis.x, clip_from_eye.y_axis.y);
        if eye.w == 0.0 || sx == 0.0 || sy == 0.0 {
            return None;
        }
        let depth = (eye.z / eye.w).abs();
        let dx = delta.x as f64 * 2.0 / self.rect.width() as f64 * depth / sx;
        let dy = -delta.y as f64 * 2.0 / self.rect.height() as f64 * depth / sy;
        let moved = eye / eye.w + DVec4::new(dx, dy, 0.0, 0.0);
        let p = self.object_from_eye * moved;
        (p.is_finite() && p.w != 0.0).then(|| p / p.w)
    }

    /// The object-space point under the screen point `pos`, at the depth of the
    /// object-space point `at` (so a dragged marker stays at its distance).
    pub fn object_at(&self, pos: egui::Pos2, at: DVec4) -> Option<DVec4> {
        let c = self.clip_from_object * at;
        if c.w <= 0.0 {
            return None;
        }
        let rel = (pos - self.rect.min) / self.rect.size();
        let ndc = DVec4::new(rel.x as f64 * 2.0 - 1.0, 1.0 - rel.y as f64 * 2.0, c.z / c.w, 1.0);
        let p = self.clip_from_object.inverse() * ndc;
        (p.w != 0.0 && p.is_finite()).then(|| p / p.w)
    }
}
