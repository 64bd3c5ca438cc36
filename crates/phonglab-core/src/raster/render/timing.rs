//! The time a frame spends in each stage, read off one clock as the stages end.

/// A frame's clock: each stage's milliseconds, in [`super::Stats::stage_ms`]'s order
/// (vertices, setup, rasterisation, resolve).
pub(super) struct StageTimes {
    clock: web_time::Instant,
    ms: [f64; 4],
}

impl StageTimes {
    /// The clock started: the first stage begins now.
    pub fn start() -> Self {
        Self { clock: web_time::Instant::now(), ms: [0.0; 4] }
    }

    /// The time since the last stage ended (or the start).
    fn lap(&mut self) -> f64 {
        let now = web_time::Instant::now();
        let ms = (now - self.clock).as_secs_f64() * 1e3;
        self.clock = now;
        ms
    }

    /// The vertices' stage ends now.
    pub fn vertices_done(&mut self) {
        self.ms[0] = self.lap();
    }

    /// Setup ends now.
    pub fn setup_done(&mut self) {
        self.ms[1] = self.lap();
    }

    /// The bands end now: rasterisation and the resolve ran together, band by band, and
    /// their time is split by `[raster_share, resolve_share]`.
    pub fn bands_done(&mut self, [raster_share, resolve_share]: [f64; 2]) {
        let bands = self.lap();
        (self.ms[2], self.ms[3]) = (bands * raster_share, bands * resolve_share);
    }

    /// Each stage's milliseconds.
    pub fn ms(&self) -> [f64; 4] {
        self.ms
    }
}
