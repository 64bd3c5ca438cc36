//! Criterion benchmarks of the general lighting engine (full breakdown per vertex):
//! one evaluation, and a batch of 1M vertices, in f32 and f64.

// criterion_group! defines undocumented functions.
#![allow(missing_docs)]

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use glam::DVec4;
use phonglab_core::{Engine, Real, Vertex, presets};

/// `n` vertices on a unit sphere ([`presets::sphere_points`]), scaled by 200 and placed in
/// front of the worksheet's camera.
fn sphere_vertices(n: usize) -> Vec<Vertex> {
    let (points, normals) = presets::sphere_points(n);
    let offset = DVec4::new(-512.0, -384.0, 0.0, 0.0);
    points
        .iter()
        .zip(&normals)
        .map(|(p, n)| {
            let v = Vertex::from_f32(*p, *n);
            Vertex { position: (v.position.truncate() * 200.0).extend(1.0) + offset, ..v }
        })
        .collect()
}

fn one<S: Real>(c: &mut Criterion) {
    let scene = presets::worksheet(5);
    let engine = Engine::<S>::new(&scene).unwrap();
    let v = scene.vertex;
    c.bench_function(&format!("general/one_vertex/{}", S::NAME), |b| {
        b.iter(|| black_box(engine.light(black_box(&v))).front.primary);
    });
}

fn batch<S: Real>(c: &mut Criterion, vertices: &[Vertex]) {
    let scene = presets::worksheet(5);
    let engine = Engine::<S>::new(&scene).unwrap();
    let mut g = c.benchmark_group("general/batch");
    g.sample_size(10);
    g.throughput(Throughput::Elements(vertices.len() as u64));
    g.bench_with_input(BenchmarkId::new(S::NAME, vertices.len()), vertices, |b, vs| {
        b.iter(|| {
            let mut sum = S::ZERO;
            for v in vs {
                sum += engine.light(v).front.primary[0];
            }
            black_box(sum)
        });
    });
    g.finish();
}

fn benches(c: &mut Criterion) {
    one::<f32>(c);
    one::<f64>(c);
    let vs = sphere_vertices(1_000_000);
    batch::<f32>(c, &vs);
    batch::<f64>(c, &vs);
}

criterion_group!(lighting, benches);
criterion_main!(lighting);
