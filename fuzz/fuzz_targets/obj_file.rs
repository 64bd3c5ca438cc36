//! Any bytes as a Wavefront OBJ file: it parses or is refused with a line number, never
//! panics; an accepted mesh has indices in range and unit or zero normals, and once fitted
//! (in f64) every position lies within the view's radius, whatever the coordinates' scale.
#![no_main]

use libfuzzer_sys::fuzz_target;
use phonglab_core::mesh::obj;

fuzz_target!(|data: &[u8]| {
    let dir = std::env::temp_dir().join(format!("phonglab-fuzz-obj-{}", std::process::id()));
    let _ = std::fs::create_dir_all(&dir);
    let path = dir.join("input.obj");
    if std::fs::write(&path, data).is_err() {
        return;
    }
    let Ok(loaded) = obj::load_obj(&path) else { return };
    let m = &loaded.mesh;
    assert!(m.triangles.iter().flatten().all(|&i| (i as usize) < m.positions.len()));
    for p in &m.positions {
        assert!(p.is_finite() && p.length() <= 0.5 + 1e-5, "{p:?}");
    }
    for n in &m.normals {
        assert!(n.is_finite() && (n.length() - 1.0).abs() < 1e-3 || *n == glam::Vec3::ZERO, "{n:?}");
    }
});
