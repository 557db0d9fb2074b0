//! Whole-frame cost through the Rust API (geometry + raster + fragment stages),
//! on each back end: 20,000 seeded random triangles at 1024x1024, depth-tested,
//! and the same with scissor + alpha + stencil + depth + blend + color mask —
//! the work behind DESIGN.md's llvmpipe figures (~75 ms and ~91 ms a frame with
//! 2 threads).

use criterion::{criterion_group, criterion_main, Criterion};
use softgl::{
    Backend, BlendFactor, Capability, ClearMask, CompareFunc, Context, FramebufferDesc, PrimitiveMode, StencilOp,
    VertexArrays,
};

mod common;

const SIZE: u32 = 1024;
const TRIANGLES: usize = 20_000;

/// Seeded random triangles in NDC, each about 30 pixels across.
fn scene() -> (Vec<f32>, Vec<f32>) {
    common::random_triangles(TRIANGLES, 0x9e37_79b9, 0.06, 0.5)
}

fn frame(gl: &mut Context, pos: &[f32], col: &[f32]) {
    gl.clear(ClearMask::ALL).unwrap();
    let arrays = VertexArrays::with_colors(3, pos, 4, col);
    gl.draw_arrays(PrimitiveMode::Triangles, 0, TRIANGLES * 3, &arrays)
        .unwrap();
}

fn bench(c: &mut Criterion) {
    let (pos, col) = scene();
    let mut group = c.benchmark_group("frame_1024_20k_triangles");
    group.sample_size(10);
    for backend in [Backend::Interpreter, Backend::Jit] {
        let mut gl = depth_context(backend);
        group.bench_function(format!("depth/{backend:?}"), |b| b.iter(|| frame(&mut gl, &pos, &col)));
        let mut gl = all_ops_context(backend);
        group.bench_function(format!("all_ops/{backend:?}"), |b| {
            b.iter(|| frame(&mut gl, &pos, &col))
        });
    }
    group.finish();
}

fn depth_context(backend: Backend) -> Context {
    let mut gl = Context::new(FramebufferDesc::rgba8_d24s8(SIZE, SIZE)).unwrap();
    gl.set_backend(backend);
    gl.enable(Capability::DepthTest).unwrap();
    gl
}

fn all_ops_context(backend: Backend) -> Context {
    let mut gl = Context::new(FramebufferDesc::rgba8_d24s8(SIZE, SIZE)).unwrap();
    gl.set_backend(backend);
    gl.enable(Capability::DepthTest).unwrap();
    gl.enable(Capability::ScissorTest).unwrap();
    gl.scissor(8, 8, SIZE as i32 - 16, SIZE as i32 - 16).unwrap();
    gl.enable(Capability::AlphaTest).unwrap();
    gl.alpha_func(CompareFunc::Greater, 0.55).unwrap();
    gl.enable(Capability::StencilTest).unwrap();
    gl.stencil_func(CompareFunc::Always, 1, 0xff).unwrap();
    gl.stencil_op(StencilOp::Keep, StencilOp::Keep, StencilOp::Incr)
        .unwrap();
    gl.enable(Capability::Blend).unwrap();
    gl.blend_func(BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha)
        .unwrap();
    gl.color_mask(true, true, true, false).unwrap();
    gl
}

criterion_group!(benches, bench);
criterion_main!(benches);
