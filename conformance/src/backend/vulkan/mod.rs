//! lavapipe (Mesa's Vulkan on the CPU, Debian's `mesa-vulkan-drivers`)
//! through `ash`, for the scenes Vulkan can express: filled triangles (all
//! triangle modes, flat and smooth), depth, stencil, blending, logic ops,
//! scissor, colour masks, polygon offset as depth bias, and the alpha test as
//! a `discard` in the fragment shader. Points, lines, polygon modes other
//! than fill, masked clears, and the fixed-function stages its pipelines do
//! not have (fog, the colour sum, lighting, clip planes, texturing: no
//! samplers or texture environment) are reported as unsupported.
//!
//! GL's vertex work (matrices, primitive assembly, flat colours, colour
//! clamping) is done here on the CPU; Vulkan gets GL's clip-space triangles
//! with z mapped from GL's [-w, w] to Vulkan's [0, w], and renders GL's window
//! row y into its framebuffer row y (so Vulkan's top-left fill rule is GL's
//! bottom-left, as llvmpipe has it); the image is flipped on read-back.
//! Shaders are WGSL compiled to SPIR-V by naga.
//!
//! [`plan`]: GL's state on the CPU, the frame as Vulkan work; [`device`]:
//! set-up and teardown; [`pipeline`]: a pipeline per draw state; [`frame`]:
//! record, submit, read back.

mod device;
mod frame;
mod pipeline;
mod plan;

use super::{Outcome, Timing};
use crate::scenes::Recording;
pub use device::installed;
use device::Gpu;
use plan::plan;
use std::time::Instant;

/// Renders a recording on lavapipe: the first frame (including pipeline
/// compiles), then `runs` more.
pub fn render(rec: &Recording, runs: usize) -> (Outcome, String) {
    let mut gpu = match Gpu::new(rec.width, rec.height) {
        Ok(g) => g,
        Err(e) => return (Outcome::Failed(e), String::new()),
    };
    let name = gpu.name.clone();
    if let Err(why) = plan(rec) {
        return (Outcome::Unsupported(why), name);
    }
    if rec.color != softgl::ColorFormat::Rgba8 {
        return (Outcome::Unsupported(format!("{:?} colour buffers", rec.color)), name);
    }
    let t = Instant::now();
    let image = match gpu.frame(rec) {
        Ok(i) => i,
        Err(e) => return (Outcome::Failed(e), name),
    };
    let first = t.elapsed();
    let mut times = Vec::new();
    for _ in 0..runs {
        let t = Instant::now();
        if let Err(e) = gpu.frame(rec) {
            return (Outcome::Failed(e), name);
        }
        times.push(t.elapsed());
    }
    (
        Outcome::Rendered {
            image,
            timing: Timing::measured(first, times, runs),
            compiles: None,
        },
        name,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::call::{Call, Rec};
    use softgl::PrimitiveMode;

    fn recording(build: impl Fn(&mut Rec)) -> Recording {
        let mut r = Rec::default();
        build(&mut r);
        Recording {
            width: 8,
            height: 8,
            color: softgl::ColorFormat::Rgba8,
            accum: false,
            calls: r.calls,
        }
    }

    #[test]
    fn lines_points_and_masked_clears_are_not_expressed() {
        for mode in [PrimitiveMode::Points, PrimitiveMode::Lines, PrimitiveMode::LineLoop] {
            let rec = recording(|r| {
                r.begin(mode).vertex(1.0, 1.0, 0.0).vertex(5.0, 5.0, 0.0).end();
            });
            assert!(plan(&rec).is_err(), "{mode:?}");
        }
        let rec = recording(|r| {
            r.call(Call::ColorMask([true, false, true, true]))
                .clear(softgl::ClearMask::COLOR);
        });
        assert!(plan(&rec).is_err());
    }

    #[test]
    fn quads_split_as_llvmpipe_splits_them() {
        let quad = |r: &mut Rec, x: f32| {
            for (dx, dy) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
                r.vertex(x + dx, dy, 0.0);
            }
        };
        let xs = |n: usize| {
            let rec = recording(|r| {
                r.begin(PrimitiveMode::Quads);
                for q in 0..n {
                    quad(r, 10.0 * q as f32);
                }
                r.end();
            });
            let p = plan(&rec).expect("expressible");
            p.vertices.iter().map(|v| (v.pos[0], v.pos[1])).collect::<Vec<_>>()
        };
        // A lone quad: (v0, v1, v2), (v0, v2, v3).
        assert_eq!(
            xs(1),
            [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
        );
        // Batched: (v0, v1, v3), (v1, v2, v3).
        assert_eq!(
            &xs(2)[..6],
            [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
        );
    }
}
