//! Occlusion queries through the Rust API: the count of a query equals the
//! pixels its draws wrote (with every test passing), on every back end and
//! thread count, across scene flushes mid-query; draws outside a query count
//! nothing.

use softgl::{
    Backend, Capability, ClearMask, CompareFunc, Context, FramebufferDesc, GlError, PrimitiveMode, QueryTarget,
};

const W: u32 = 150;
const H: u32 = 130;

fn context(backend: Backend, threads: usize) -> Context {
    let mut gl = Context::new(FramebufferDesc::rgba8_d24s8(W, H)).unwrap();
    gl.set_backend(backend);
    gl.set_threads(threads);
    gl.clear_color(0.0, 0.0, 0.0, 1.0).unwrap();
    gl.clear(ClearMask::COLOR | ClearMask::DEPTH).unwrap();
    gl
}

/// A triangle of `rgb` at depth `z` (window -1..1 coordinates).
fn tri(gl: &mut Context, v: [[f32; 2]; 3], z: f32, rgb: [f32; 3]) {
    gl.begin(PrimitiveMode::Triangles).unwrap();
    gl.color3(rgb[0], rgb[1], rgb[2]);
    for [x, y] in v {
        gl.vertex3(x, y, z);
    }
    gl.end().unwrap();
}

fn lit(gl: &mut Context, channel: usize) -> u64 {
    let fb = gl.framebuffer();
    let mut n = 0;
    for y in 0..H {
        for x in 0..W {
            n += u64::from(fb.pixel(x, y).unwrap()[channel] != 0);
        }
    }
    n
}

#[test]
fn a_query_counts_the_fragments_that_pass() {
    for backend in [Backend::Interpreter, Backend::Jit] {
        for threads in [1, 3] {
            let mut gl = context(backend, threads);
            gl.enable(Capability::DepthTest).unwrap();
            gl.depth_func(CompareFunc::Less).unwrap();
            let q = gl.queries_mut().gen(2).unwrap();
            // Outside any query: counted by none.
            tri(&mut gl, [[-0.9, -0.9], [0.1, -0.8], [-0.7, 0.2]], 0.0, [1.0, 0.0, 0.0]);
            gl.queries_mut().begin(QueryTarget::SamplesPassed, q[0]).unwrap();
            tri(&mut gl, [[-0.2, -0.1], [0.9, 0.0], [0.3, 0.95]], 0.0, [0.0, 1.0, 0.0]);
            // A flush mid-query (a read-back) keeps the count.
            let _ = gl.framebuffer();
            // Behind the first red triangle where they overlap: those fail.
            tri(
                &mut gl,
                [[-0.95, -0.95], [0.0, -0.95], [-0.95, 0.0]],
                0.5,
                [0.0, 1.0, 0.0],
            );
            gl.queries_mut().end(QueryTarget::SamplesPassed).unwrap();
            let n = gl.query_result(q[0]).unwrap();
            assert_eq!(n, lit(&mut gl, 1), "{backend:?}, {threads} threads");
            assert!(n > 1000);
            // A query over a draw the depth test rejects entirely.
            gl.queries_mut().begin(QueryTarget::SamplesPassed, q[1]).unwrap();
            tri(&mut gl, [[-0.2, -0.1], [0.9, 0.0], [0.3, 0.95]], 0.9, [0.0, 0.0, 1.0]);
            gl.queries_mut().end(QueryTarget::SamplesPassed).unwrap();
            assert_eq!(gl.query_result(q[1]), Ok(0));
            assert_eq!(gl.query_result(7), Err(GlError::InvalidOperation));
        }
    }
}
