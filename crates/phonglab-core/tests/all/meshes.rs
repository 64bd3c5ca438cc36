//! Meshes: the triangle counts of GLU and GLUT, unit outward normals, counter-clockwise
//! winding from outside, finite normals at the teapot's degenerate corners.

use glam::Vec3;
use phonglab_core::mesh::{Mesh, cylinder, obj, sphere, teapot};
use phonglab_core::{ObjectKind, View};

/// Every normal unit length and finite; every non-degenerate triangle's geometric normal
/// (from its winding) agrees with its vertex normals.
fn assert_consistent(m: &Mesh, what: &str) {
    for (i, n) in m.normals.iter().enumerate() {
        assert!(n.is_finite() && (n.length() - 1.0).abs() < 1e-5, "{what}: normal {i} = {n}");
    }
    let mut checked = 0;
    for t in &m.triangles {
        let [a, b, c] = t.map(|i| m.positions[i as usize]);
        let g = (b - a).cross(c - a);
        if g.length() < 1e-9 {
            continue; // collapsed at a pole or patch corner
        }
        checked += 1;
        for &i in t {
            assert!(g.dot(m.normals[i as usize]) > 0.0, "{what}: triangle {t:?} winds against its normals");
        }
    }
    assert!(checked >= m.triangles.len() * 3 / 4, "{what}: too many degenerate triangles");
}

/// Signed volume by the divergence theorem: positive when the faces point outward.
fn signed_volume(m: &Mesh) -> f64 {
    m.triangles
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|i| m.positions[i as usize].as_dvec3());
            a.dot(b.cross(c)) / 6.0
        })
        .sum()
}

#[test]
fn glu_sphere_has_glus_layout() {
    let m = sphere::glu_sphere(1.0, 50, 50);
    assert_eq!(m.triangle_count(), 4900, "2 slices + 2 slices (stacks - 2)");
    assert_consistent(&m, "sphere");
    for (p, n) in m.positions.iter().zip(&m.normals) {
        assert!((p.length() - 1.0).abs() < 1e-6 && (*p - *n).length() < 1e-6);
    }
    let v = signed_volume(&m);
    assert!((v - 4.0 / 3.0 * std::f64::consts::PI).abs() < 0.02, "{v}");
}

#[test]
fn glu_cylinder_has_glus_layout() {
    let m = cylinder::glu_cylinder(0.3, 0.3, 0.5, 20, 5, false);
    assert_eq!(m.triangle_count(), 200);
    assert_consistent(&m, "cylinder");
    for (p, n) in m.positions.iter().zip(&m.normals) {
        assert!(n.z.abs() < 1e-6 && (Vec3::new(p.x, p.y, 0.0).normalize() - *n).length() < 1e-5, "radial normals");
    }
    let capped = cylinder::glu_cylinder(0.3, 0.3, 0.5, 20, 5, true);
    assert_eq!(capped.triangle_count(), 240);
    assert_consistent(&capped, "capped cylinder");
    let v = signed_volume(&capped);
    let exact = std::f64::consts::PI * 0.09 * 0.5;
    assert!(v > 0.0 && (v - exact).abs() < 0.02 * exact, "{v} vs {exact}");
    let cone = cylinder::glu_cylinder(0.5, 0.0, 1.0, 32, 4, false);
    assert_consistent(&cone, "cone");
    assert!(cone.normals.iter().all(|n| n.z > 0.4), "a cone's normals tilt up");
}

#[test]
fn glut_teapot_has_3136_triangles_and_outward_finite_normals() {
    let m = teapot::glut_teapot(0.8, 7);
    assert_eq!(m.triangle_count(), 3136);
    assert_consistent(&m, "teapot");
    assert!(signed_volume(&m) > 0.0, "faces point outward");
    // The lid's knob top (highest point) and the bottom's centre (on the axis, lowest).
    let top = m.positions.iter().enumerate().max_by(|a, b| a.1.y.total_cmp(&b.1.y)).unwrap().0;
    assert!(m.normals[top].y > 0.999, "knob top normal {}", m.normals[top]);
    let bottom_centre = m
        .positions
        .iter()
        .enumerate()
        .filter(|(_, p)| p.x.abs() < 1e-6 && p.z.abs() < 1e-6)
        .min_by(|a, b| a.1.y.total_cmp(&b.1.y))
        .unwrap()
        .0;
    assert!(m.normals[bottom_centre].y < -0.999, "bottom centre normal {}", m.normals[bottom_centre]);
    // glutSolidTeapot(0.8) = 0.4 x the patches: x from the handle (-3.0) to the spout's tip
    // (3.434; its control point 3.52 is not on the curve), y from the bottom (0 - 1.575) to
    // the knob (3.15 - 1.575): centred.
    let (lo, hi) = m.positions.iter().fold((Vec3::MAX, Vec3::MIN), |(lo, hi), p| (lo.min(*p), hi.max(*p)));
    assert!((lo.x + 1.2).abs() < 1e-5 && (hi.x - 1.3735).abs() < 1e-3, "{lo} {hi}");
    assert!((lo.y + 0.63).abs() < 1e-5 && (hi.y - 0.63).abs() < 1e-5, "{lo} {hi}");
}

#[test]
fn every_teapot_patch_faces_out() {
    // The rotationally symmetric patches (rim, body, lid, bottom: 0-11 and 20-31) face away
    // from the teapot's axis or along it; the handle's and spout's side patches (12-19)
    // face away from the plane y = 0 that splits them, on their own side.
    let m = teapot::glut_teapot(1.0, 12);
    let per_patch = 13 * 13;
    for k in 0..32 {
        let centre = k * per_patch + 6 * 13 + 6;
        let (p, n) = (m.positions[centre], m.normals[centre]);
        let ok = match k {
            0..=3 => n.y > 0.9,                                                        // rim: its top faces up
            4..=11 => Vec3::new(p.x, 0.0, p.z).normalize().dot(n) > 0.3,               // body: outward
            12..=19 => n.z * p.z > 0.0,                                                // handle, spout sides
            20..=23 => Vec3::new(p.x, 0.0, p.z).normalize().dot(n) > 0.3 || n.y > 0.5, // lid knob
            24..=27 => n.y > 0.5,                                                      // lid: up
            _ => n.y < -0.5,                                                           // bottom: down
        };
        assert!(ok, "patch {k}: normal {n} at {p} points inside");
    }
}

#[test]
fn the_patch_file_is_parsed_and_bad_ones_are_reported() {
    assert_eq!(teapot::parse_bpt(teapot::TEAPOT_BPT).unwrap().len(), 32);
    let e = teapot::parse_bpt("1\n3 2\n").unwrap_err();
    assert!(e.contains("line 2") && e.contains("bicubic"), "{e}");
    let e = teapot::parse_bpt("1\n3 3\n0 0 0\n1 2\n").unwrap_err();
    assert!(e.contains("line 4"), "{e}");
}

#[test]
fn view_meshes_and_the_demos_normals() {
    let v = View::default();
    assert_eq!(v.mesh().triangle_count(), 4900);
    let t = (View { object: ObjectKind::Teapot, ..View::default() }).mesh();
    assert_eq!(t.triangle_count(), 3136);
    let c = (View { object: ObjectKind::Cylinder, ..View::default() }).mesh();
    let demo = (View { object: ObjectKind::Cylinder, demo_normals: true, ..View::default() }).mesh();
    // normalize(position) is wrong on a cylinder: up to 40 degrees off near its ends.
    let worst = c.normals.iter().zip(&demo.normals).map(|(a, b)| a.dot(*b)).fold(1.0f32, f32::min);
    assert!(worst < 0.8, "{worst}");
    let s = View::default().mesh();
    let sd = (View { demo_normals: true, ..View::default() }).mesh();
    assert!(s.normals.iter().zip(&sd.normals).all(|(a, b)| (*a - *b).length() < 1e-5), "right on a sphere");
}

#[test]
fn obj_files_load_with_or_without_normals() {
    let cube = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n\
                f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
    let m = obj::parse_obj(cube).unwrap();
    assert_eq!(m.triangle_count(), 12);
    assert!((signed_volume(&m) - 1.0).abs() < 1e-6);
    assert!(m.normals.iter().all(|n| (n.length() - 1.0).abs() < 1e-5));
    let tri = obj::parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 2\nf 1//1 2//1 3//1\n").unwrap();
    assert_eq!(tri.normals[0], Vec3::Z);
    let e = obj::parse_obj("v 0 0 0\nf 1 2 3\n").unwrap_err();
    assert!(e.contains("line 2") && e.contains("out of range"), "{e}");
    assert!(obj::parse_obj("v 0 0 x\n").unwrap_err().contains("line 1"));
}

/// A triangle soup (each triangle its own three corners, as STL conversions write) is read
/// as the shared mesh of the same surface: its repeated corners welded (the same bytes
/// only), so it takes the shared mesh's memory and its computed normals are the shared
/// mesh's, smooth across the edge the two triangles share.
#[test]
fn a_soup_is_read_as_its_shared_mesh() {
    let soup = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nv 1 0 0\nv 1 1 0.5\nv 0 1 0\nf 4 5 6\n";
    let shared = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0.5\nf 1 2 3\nf 2 4 3\n";
    let (a, b) =
        (phonglab_core::mesh::obj::parse_obj(soup).unwrap(), phonglab_core::mesh::obj::parse_obj(shared).unwrap());
    assert_eq!(a.positions.len(), 4);
    assert_eq!(a, b);
    // Nothing merely close is merged: a corner moved by one unit in the last place stays apart.
    let near = soup.replace("v 1 0 0\nv 1 1", "v 1.0000000000000002 0 0\nv 1 1");
    assert_eq!(phonglab_core::mesh::obj::parse_obj(&near).unwrap().positions.len(), 5);
}
