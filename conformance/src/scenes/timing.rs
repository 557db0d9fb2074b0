//! Large seeded scenes, to time: 20k triangles at 1024x1024 in the report
//! (2.5k at 256x256 in the tests).

use super::{random_triangles, Group, Rng, Scene, Size, Tolerance};
use crate::call::{Call, Rec};
use softgl::{BlendFactor, Capability, CompareFunc, StencilOp};

const G: Group = Group::Timing;
const E: Tolerance = Tolerance::EXACT;

const FULL: (u32, u32) = (1024, 1024);
const TEST: (u32, u32) = (256, 256);

pub fn scenes() -> Vec<Scene> {
    vec![
        Scene::new("random_20k_depth", G, E, depth).sized(FULL, TEST),
        Scene::new("random_20k_all_stages", G, E, all_stages).sized(FULL, TEST),
        Scene::new("overdraw_blend_16", G, E, overdraw).sized(FULL, TEST),
    ]
}

fn depth(r: &mut Rec, s: Size) {
    r.enable(Capability::DepthTest).call(Call::DepthFunc(CompareFunc::Less));
    random_triangles(r, &mut Rng::new(70), s.count(20_000), s, s.wf() / 40.0, (1.0, 1.0));
}

fn all_stages(r: &mut Rec, s: Size) {
    r.enable(Capability::ScissorTest)
        .scissor(16, 16, s.w as i32 - 32, s.h as i32 - 32)
        .enable(Capability::AlphaTest)
        .call(Call::AlphaFunc(CompareFunc::Greater, 0.1))
        .enable(Capability::StencilTest)
        .call(Call::StencilFunc(CompareFunc::Always, 1, 0xff))
        .call(Call::StencilOp(StencilOp::Keep, StencilOp::Keep, StencilOp::Incr))
        .enable(Capability::DepthTest)
        .call(Call::DepthFunc(CompareFunc::Lequal))
        .enable(Capability::Blend)
        .call(Call::BlendFunc(BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha))
        .call(Call::ColorMask([true, true, true, false]));
    random_triangles(r, &mut Rng::new(71), s.count(20_000), s, s.wf() / 40.0, (0.0, 1.0));
}

/// Sixteen full-window blended layers: fill rate.
fn overdraw(r: &mut Rec, s: Size) {
    r.enable(Capability::Blend)
        .call(Call::BlendFunc(BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha));
    let mut rng = Rng::new(72);
    for _ in 0..16 {
        r.color(rng.unit(), rng.unit(), rng.unit(), rng.range(0.1, 0.9))
            .rect(0.0, 0.0, s.wf(), s.hf(), 0.0);
    }
}
