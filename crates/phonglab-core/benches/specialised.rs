//! The specialised evaluator against the general engine on the three scenes of issue 5,
//! 1M vertices each (ns per vertex = time / 1M).

// criterion_group! defines undocumented functions.
#![allow(missing_docs)]

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use phonglab_core::lighter::{Lighter, Lit};
use phonglab_core::presets::{LightingBench, sphere_points};
use phonglab_core::{Engine, EvalOptions, Vertex};

const N: usize = 1_000_000;

fn benches(c: &mut Criterion) {
    let (pos, nrm) = sphere_points(N);
    let verts: Vec<Vertex> = pos.iter().zip(&nrm).map(|(p, n)| Vertex::from_f32(*p, *n)).collect();
    let mut out = vec![Lit::default(); N];
    let mut g = c.benchmark_group("lighting");
    g.sample_size(10);
    g.throughput(Throughput::Elements(N as u64));
    for b in LightingBench::ALL {
        let scene = b.scene();
        let engine = Engine::<f32>::new(&scene).unwrap();
        g.bench_function(BenchmarkId::new("general", b.name()), |bch| {
            bch.iter(|| {
                let mut s = 0.0f32;
                for v in &verts {
                    s += engine.light(v).front.primary[0];
                }
                black_box(s)
            });
        });
        let lighter = Lighter::new(&scene, EvalOptions::default()).unwrap();
        g.bench_function(BenchmarkId::new("specialised", b.name()), |bch| {
            bch.iter(|| {
                lighter.light_batch(&pos, &nrm, &mut out, None);
                black_box(out[N / 2].primary[0])
            });
        });
    }
    g.finish();
}

criterion_group!(specialised, benches);
criterion_main!(specialised);
