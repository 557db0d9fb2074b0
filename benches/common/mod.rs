//! Inputs shared by the benchmarks, so that each figure is measured on the same work.
// Each bench binary uses part of this module.
#![allow(dead_code)]

use softgl_jit::{
    BlendKey, ColorFormat, ColorMask, CompareFunc, DepthFormat, DepthKey, FragmentKey, StencilKey, StencilOp,
};

/// Scissor + alpha (GREATER) + stencil (EQUAL, INCR) + depth (LESS) + blend
/// (SRC_ALPHA, ONE_MINUS_SRC_ALPHA) + a color mask without alpha, RGBA8/D24S8.
pub fn all_ops_key() -> FragmentKey {
    FragmentKey {
        scissor: true,
        alpha_test: Some(CompareFunc::Greater),
        stencil: Some(StencilKey {
            func: CompareFunc::Equal,
            fail: StencilOp::Keep,
            zfail: StencilOp::Keep,
            zpass: StencilOp::Incr,
        }),
        depth: Some(DepthKey {
            func: CompareFunc::Less,
            write: true,
        }),
        blend: Some(BlendKey::OVER),
        color_mask: ColorMask {
            a: false,
            ..ColorMask::ALL
        },
        ..FragmentKey::new(ColorFormat::Rgba8, Some(DepthFormat::D24), true)
    }
}

/// Positions (xyz, NDC) and colors (rgba) of `count` seeded random triangles,
/// each within `extent` (NDC units) of its centre, alpha in `min_alpha..1`.
pub fn random_triangles(count: usize, seed: u32, extent: f32, min_alpha: f32) -> (Vec<f32>, Vec<f32>) {
    let mut rng = softgl_jit::rng::Rng::new(seed);
    let mut next = move || rng.unit();
    let (mut pos, mut col) = (Vec::new(), Vec::new());
    for _ in 0..count {
        let (cx, cy, z) = (next() * 2.0 - 1.0, next() * 2.0 - 1.0, next() * 2.0 - 1.0);
        for _ in 0..3 {
            pos.extend([cx + (next() - 0.5) * extent, cy + (next() - 0.5) * extent, z]);
            col.extend([next(), next(), next(), min_alpha + next() * (1.0 - min_alpha)]);
        }
    }
    (pos, col)
}
