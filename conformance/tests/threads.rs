//! Every conformance scene gives the same bytes on 1, 2 and 8 rasterizer
//! threads, on the JIT and on the interpreter: a tile belongs to one thread
//! for a whole flush, so no image may depend on how tiles were shared out.

use softgl::{Backend, FramebufferDesc};
use softgl_conformance::backend::softgl::{context, Replayer};
use softgl_conformance::scenes;

/// Color, depth and stencil bytes of `scene` rendered with `threads` threads.
fn render(rec: &softgl_conformance::scenes::Recording, backend: Backend, threads: usize) -> Vec<u8> {
    let desc = FramebufferDesc {
        color: rec.color,
        ..FramebufferDesc::rgba8_d24s8(rec.width, rec.height)
    };
    let mut gl = context(desc, rec.accum).expect("context");
    gl.set_backend(backend);
    gl.set_threads(threads);
    let mut lists = Replayer::default();
    for c in &rec.calls {
        // Errors a scene provokes are the scene's; the bytes are what is compared.
        let _ = lists.call(&mut gl, c);
    }
    let fb = gl.framebuffer();
    let mut bytes = fb.color_bytes().to_vec();
    if let Some(d) = fb.depth_buffer() {
        bytes.extend(format!("{d:?}").bytes());
    }
    bytes.extend_from_slice(fb.stencil_buffer().unwrap_or(&[]));
    bytes
}

#[test]
fn every_scene_is_the_same_bytes_on_1_2_and_8_threads_jit_and_interpreter() {
    let mut multi_band = 0;
    for s in scenes::all() {
        // Full size (256² for most: four bands of tiles) unless it is one of
        // the 1024² timing scenes, which run at their test size here.
        let full = s.size(true);
        let rec = s.record(full.w * full.h <= 256 * 256);
        multi_band += usize::from(rec.height > 64);
        let one = render(&rec, Backend::Interpreter, 1);
        for (backend, threads) in [
            (Backend::Interpreter, 8),
            (Backend::Jit, 1),
            (Backend::Jit, 2),
            (Backend::Jit, 8),
        ] {
            let got = render(&rec, backend, threads);
            let differ = got.iter().zip(&one).filter(|(a, b)| a != b).count();
            assert!(
                got == one,
                "{}: {backend:?} on {threads} threads differs from the interpreter on 1 in {differ} bytes",
                s.name
            );
        }
    }
    assert!(multi_band >= 100, "only {multi_band} scenes span several bands");
}
