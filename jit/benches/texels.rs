//! Texels per second of the texture stage, per filter, JIT against the
//! interpreter: a 256×256 RGBA8 target covered by spans of one primitive
//! whose texture coordinates map it onto a 256² mipmapped RGBA8 texture,
//! minified by 1.37 (λ ≈ 0.45, so trilinear blends levels 0 and 1), MODULATE
//! over a constant colour, REPEAT. Each fragment samples once: texels/s is
//! fragments/s (`two_trilinear_units`: twice, the same texture; still
//! fragments/s). `jit_quick` is the quick code a tiered specialist runs
//! until its optimized code is installed (single-pass register allocation,
//! every unit sampled by the reference through the callout).
//!
//! `cargo bench -p softgl-jit --bench texels`

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use softgl_jit::shade::slot;
use softgl_jit::texture::{EnvMode, Filter, MipFilter, Wrap, MAX_UNITS};
use softgl_jit::SPAN_MAX;
use softgl_jit::{interp, ColorFormat, FragmentKey, FragmentSpan, FragmentUniforms, Planes, Specialist, Target, Tier};
use std::hint::black_box;
use std::time::Duration;

const SIZE: u32 = 256;
const TEX: u32 = 256;
const MINIFY: f32 = 1.37;

#[path = "../tests/support/mod.rs"]
mod support;

/// The key of one textured unit with `min`/`mag` and mip filter `mip`.
fn key(filter: Filter, mip: MipFilter) -> FragmentKey {
    support::one_unit_key(filter, mip, filter, Wrap::Repeat, EnvMode::Modulate)
}

/// The texture's levels, 256² down to 1², with a seeded pattern.
fn levels() -> Vec<(u32, u32, Vec<u8>)> {
    let mut rng = softgl_jit::rng::Rng::new(0x7e11);
    (0..=TEX.trailing_zeros())
        .map(|l| {
            let s = TEX >> l;
            (s, s, (0..s * s * 4).map(|_| rng.next_u64() as u8).collect())
        })
        .collect()
}

/// One primitive: white, w = 1, s and t of units 0 and 1 growing by `MINIFY / TEX` a pixel.
fn planes() -> Planes {
    let mut p = Planes::default();
    p.constant(slot::INV_W, 1.0);
    for c in 0..4 {
        p.constant(slot::COLOR + c, 1.0);
    }
    let d = MINIFY / TEX as f32;
    for unit in 0..2 {
        p.set(slot::tex(unit), 0.25 * d, d, 0.0);
        p.set(slot::tex(unit) + 1, 0.25 * d, 0.0, d);
        p.constant(slot::tex(unit) + 2, 0.0);
        p.constant(slot::tex(unit) + 3, 1.0);
    }
    p
}

/// Full spans over the whole target.
fn spans() -> Vec<FragmentSpan> {
    let mut spans = Vec::new();
    for y in 0..SIZE {
        for x in (0..SIZE).step_by(SPAN_MAX) {
            let mut s = FragmentSpan::new(x, y);
            for i in 0..SPAN_MAX {
                s.set(i, [0; 4], 0);
            }
            spans.push(s);
        }
    }
    spans
}

fn texels(c: &mut Criterion) {
    let levels = levels();
    let images = support::images(&levels);
    let set = support::two_units(&images);
    let planes = [planes()];
    let spans = spans();
    let u = FragmentUniforms::default();
    let mut color = vec![0u8; (SIZE * SIZE * 4) as usize];

    let mut group = c.benchmark_group("texels");
    group.throughput(Throughput::Elements(u64::from(SIZE * SIZE)));
    group.sample_size(20).measurement_time(Duration::from_secs(4));
    let trilinear = key(Filter::Linear, MipFilter::Linear);
    let mut two_trilinear = trilinear;
    if let Some(shade) = two_trilinear.shade.as_mut() {
        shade.tex[1] = shade.tex[0];
    }
    for (name, key) in [
        ("nearest", key(Filter::Nearest, MipFilter::None)),
        ("linear", key(Filter::Linear, MipFilter::None)),
        ("trilinear", trilinear),
        // Two samples a fragment: texels/s counts fragments.
        ("two_trilinear_units", two_trilinear),
    ] {
        // The key for the bench's texture (its statics: power-of-two, no LOD
        // clamp or bias). `jit`: the code a draw runs once the background
        // upgrade is installed; `jit_quick`: the quick code it runs until then
        // (single-pass, every unit through the callout).
        let key = support::bind(&key, &set);
        let specialist = Specialist::compile_tier(&key, Tier::Optimized).expect("the bench key compiles");
        let quick = Specialist::compile_tier(&key, Tier::Quick).expect("the bench key compiles");
        for backend in ["jit", "jit_quick", "interpreter"] {
            group.bench_function(format!("{name}/{backend}"), |b| {
                b.iter(|| {
                    let mut t = Target::new(
                        SIZE,
                        SIZE,
                        ColorFormat::Rgba8,
                        &mut color,
                        SIZE as usize * 4,
                        None,
                        None,
                    )
                    .expect("buffer sized for the target");
                    let spans = black_box(&spans);
                    match backend {
                        "jit" => specialist.run_with_planes(&u, &set, spans, &planes, &mut t),
                        "jit_quick" => quick.run_with_planes(&u, &set, spans, &planes, &mut t),
                        _ => interp::run_with_planes(&key, &u, &set, spans, &planes, &mut t),
                    }
                    .expect("the key names the buffers");
                })
            });
        }
    }
    group.finish();
}

/// Compile time of textured keys in both tiers: one trilinear unit; two units
/// (trilinear and bilinear, the second MODULATE over the first); and the
/// shaded key without texturing, for scale.
fn compile(c: &mut Criterion) {
    // The statics of the bench's texture (power-of-two, no LOD clamp or bias).
    let levels = levels();
    let images = support::images(&levels);
    let set = support::two_units(&images);
    let one = support::bind(&key(Filter::Linear, MipFilter::Linear), &set);
    let two = support::bind(&support::with_bilinear_second_unit(one), &set);
    // For scale, in the same run: the same key without its unit.
    let mut untextured = one;
    if let Some(shade) = untextured.shade.as_mut() {
        shade.tex = [None; MAX_UNITS];
    }
    let mut group = c.benchmark_group("compile");
    for (name, key) in [
        ("untextured", untextured),
        ("textured_1_unit", one),
        ("textured_2_units", two),
    ] {
        for (tier_name, tier) in [("quick", Tier::Quick), ("optimized", Tier::Optimized)] {
            group.bench_function(format!("{name}/{tier_name}"), |b| {
                b.iter(|| black_box(Specialist::compile_tier(&key, tier).expect("compiles")))
            });
        }
    }
    group.finish();
}

criterion_group!(benches, compile, texels);
criterion_main!(benches);
