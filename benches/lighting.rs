//! Vertex lighting throughput: vertices lit per second through
//! `LightSetup::light_batch` in batches of 256 (the vertex batch size), for one
//! infinite light (the fast path) and for 8 local spot lights with attenuation
//! and a local viewer (the general path), one- and two-sided.

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use glam::{Mat4, Vec3, Vec4};
use softgl::geometry::lighting::{LightInput, LightSetup, LitColors};
use softgl::lighting::{Light, LightingState};
use std::hint::black_box;

const N: usize = 256;

fn inputs() -> Vec<LightInput> {
    let mut rng = softgl::rng::Rng::new(7);
    (0..N)
        .map(|_| LightInput {
            pos: Vec4::new(rng.range(-1.0, 1.0), rng.range(-1.0, 1.0), rng.range(-1.0, 1.0), 1.0),
            normal: Vec3::new(rng.range(-1.0, 1.0), rng.range(-1.0, 1.0), rng.range(-1.0, 1.0)).normalize(),
            color: Vec4::new(rng.unit(), rng.unit(), rng.unit(), 1.0),
        })
        .collect()
}

fn infinite(two_side: bool) -> LightingState {
    let mut st = LightingState {
        enabled: true,
        two_side,
        ..LightingState::default()
    };
    st.lights[0].enabled = true;
    st.lights[0].position = [1.0, 1.0, 1.0, 0.0];
    st.materials[0].shininess = 32.0;
    st.materials[0].specular = [1.0; 4];
    st
}

fn eight_spots(two_side: bool) -> LightingState {
    let mut st = infinite(two_side);
    st.local_viewer = true;
    for i in 0..8 {
        let a = i as f32 * 0.785;
        st.lights[i] = Light {
            enabled: true,
            position: [2.0 * a.cos(), 2.0 * a.sin(), 2.0, 1.0],
            spot_direction: [-a.cos(), -a.sin(), -2.0],
            spot_cutoff: 40.0,
            spot_exponent: 8.0,
            attenuation: [1.0, 0.1, 0.02],
            ..Light::new(i)
        };
    }
    st
}

fn lighting(c: &mut Criterion) {
    let inputs = inputs();
    let mut out = vec![LitColors::default(); N];
    let mv = Mat4::from_translation(Vec3::new(0.0, 0.0, -5.0)) * Mat4::from_rotation_y(0.3);
    let mut group = c.benchmark_group("vertex_lighting");
    group.throughput(Throughput::Elements(N as u64));
    for (name, st) in [
        ("1_infinite", infinite(false)),
        ("1_infinite_two_sided", infinite(true)),
        ("8_local_spots", eight_spots(false)),
        ("8_local_spots_two_sided", eight_spots(true)),
    ] {
        let setup = LightSetup::new(&st, &mv);
        group.bench_function(name, |b| {
            b.iter(|| {
                setup.light_batch(black_box(&inputs), &mut out);
                black_box(&out);
            })
        });
    }
    group.finish();
}

criterion_group!(benches, lighting);
criterion_main!(benches);
