//! What specialists cost besides running them: compile time per key (textured
//! keys in both tiers: `quick` is what a draw waits for, `optimized` what the
//! background thread then spends), the cost of a cache hit on each draw, and a state-thrash frame (256 distinct keys × 50
//! small triangles at 1024x1024) on a cold and a warm cache, against the
//! interpreter. llvmpipe, for the same frame on this machine: 2.8–3.1 s the
//! first time (LLVM compiles each state for 11–12 ms), 18–23 ms after.

use criterion::{criterion_group, criterion_main, BatchSize, Criterion};
use softgl::{
    Backend, Capability, ClearMask, CompareFunc, Context, FramebufferDesc, LogicOp, PrimitiveMode, VertexArrays,
};
use softgl_jit::texture::{EnvMode, Filter, MipFilter, Wrap};
use softgl_jit::{ColorFormat, FragmentKey, Specialist, SpecialistCache, Tier};
use std::hint::black_box;
use std::time::Duration;

mod common;
#[path = "../jit/tests/support/mod.rs"]
#[allow(dead_code, reason = "only its keys and textures are used here")]
mod support;

const SIZE: u32 = 1024;
const STATES: usize = 256;
const TRIANGLES_PER_STATE: usize = 50;

/// Keys with texture units: one 2D RGBA8 unit, MODULATE, REPEAT, NEAREST,
/// bilinear or trilinear; and two trilinear units.
fn textured_keys() -> [(&'static str, FragmentKey); 4] {
    let one = |filter, mip| support::one_unit_key(filter, mip, filter, Wrap::Repeat, EnvMode::Modulate);
    let trilinear = one(Filter::Linear, MipFilter::Linear);
    let mut two = trilinear;
    if let Some(shade) = two.shade.as_mut() {
        shade.tex[1] = shade.tex[0];
    }
    // With the statics of a power-of-two texture under GL's default LOD state.
    let levels: Vec<(u32, u32, Vec<u8>)> = (0..4)
        .map(|l| {
            let s = 8u32 >> l;
            (s, s, vec![0; (s * s * 4) as usize])
        })
        .collect();
    let images = support::images(&levels);
    let set = support::two_units(&images);
    [
        ("nearest", one(Filter::Nearest, MipFilter::None)),
        ("bilinear", one(Filter::Linear, MipFilter::None)),
        ("trilinear", trilinear),
        ("two_trilinear", two),
    ]
    .map(|(name, key)| (name, support::bind(&key, &set)))
}

fn compile(c: &mut Criterion) {
    let mut group = c.benchmark_group("compile");
    for (name, key) in [
        ("minimal", FragmentKey::new(ColorFormat::Rgba8, None, false)),
        ("all_ops", common::all_ops_key()),
    ] {
        group.bench_function(name, |b| {
            b.iter(|| black_box(Specialist::compile(&key).expect("compiles")))
        });
    }
    for (name, key) in textured_keys() {
        for (tier_name, tier) in [("quick", Tier::Quick), ("optimized", Tier::Optimized)] {
            group.bench_function(format!("{name}/{tier_name}"), |b| {
                b.iter(|| black_box(Specialist::compile_tier(&key, tier).expect("compiles")))
            });
        }
    }
    group.finish();
}

fn cache_hit(c: &mut Criterion) {
    let key = common::all_ops_key();
    let mut cache = SpecialistCache::new(64);
    cache.get(&key).expect("compiles");
    c.bench_function("cache_hit/lookup", |b| {
        b.iter(|| black_box(cache.get(black_box(&key)).is_some()))
    });

    // One draw of a one-pixel triangle: the per-draw cost of each back end,
    // which for the JIT includes the cache lookup.
    let pos = [0.0f32, 0.0, 0.0, 0.001, 0.0, 0.0, 0.0, 0.001, 0.0];
    for backend in [Backend::Interpreter, Backend::Jit] {
        let mut gl = thrash_context(backend, 64);
        gl.enable(Capability::DepthTest).unwrap();
        let arrays = VertexArrays::positions(3, &pos);
        c.bench_function(&format!("cache_hit/draw_tiny_triangle/{backend:?}"), |b| {
            b.iter(|| gl.draw_arrays(PrimitiveMode::Triangles, 0, 3, &arrays).unwrap())
        });
    }
}

/// Seeded small triangles (about 12 pixels across) with colors.
fn triangles() -> (Vec<f32>, Vec<f32>) {
    common::random_triangles(STATES * TRIANGLES_PER_STATE, 0x1234_5678, 0.025, 0.0)
}

fn thrash_context(backend: Backend, capacity: usize) -> Context {
    let mut gl = Context::new(FramebufferDesc::rgba8_d24s8(SIZE, SIZE)).unwrap();
    gl.set_backend(backend);
    gl.set_specialist_capacity(capacity);
    gl
}

/// State `i` of 256 distinct fragment keys: depth function × logic op × alpha test on/off.
fn set_state(gl: &mut Context, i: usize) {
    gl.enable(Capability::DepthTest).unwrap();
    gl.depth_func(CompareFunc::ALL[i % 8]).unwrap();
    gl.enable(Capability::ColorLogicOp).unwrap();
    gl.logic_op(LogicOp::ALL[(i / 8) % 16]).unwrap();
    if i / 128 == 1 {
        gl.enable(Capability::AlphaTest).unwrap();
        gl.alpha_func(CompareFunc::Greater, 0.25).unwrap();
    } else {
        gl.disable(Capability::AlphaTest).unwrap();
    }
}

fn thrash_frame(gl: &mut Context, pos: &[f32], col: &[f32]) {
    gl.clear(ClearMask::ALL).unwrap();
    let arrays = VertexArrays::with_colors(3, pos, 4, col);
    for i in 0..STATES {
        set_state(gl, i);
        let first = i * TRIANGLES_PER_STATE * 3;
        gl.draw_arrays(PrimitiveMode::Triangles, first, TRIANGLES_PER_STATE * 3, &arrays)
            .unwrap();
    }
}

fn state_thrash(c: &mut Criterion) {
    let (pos, col) = triangles();
    let mut group = c.benchmark_group("state_thrash_256_keys");
    group.sample_size(10);
    // Cold: a new context each time, so all 256 specialists are compiled.
    group.bench_function("jit_first_frame", |b| {
        b.iter_batched_ref(
            || thrash_context(Backend::Jit, STATES),
            |gl| thrash_frame(gl, &pos, &col),
            BatchSize::LargeInput,
        )
    });
    for (name, backend, capacity) in [
        ("jit_warm", Backend::Jit, STATES),
        ("jit_cache_64", Backend::Jit, 64),
        ("interpreter", Backend::Interpreter, STATES),
    ] {
        let mut gl = thrash_context(backend, capacity);
        thrash_frame(&mut gl, &pos, &col);
        group.bench_function(name, |b| b.iter(|| thrash_frame(&mut gl, &pos, &col)));
    }
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default()
        .sample_size(30)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(3));
    targets = compile, cache_hit, state_thrash
}
criterion_main!(benches);
