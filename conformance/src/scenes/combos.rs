//! Stages in the combinations applications use them in.

use super::stages::show_stencil;
use super::{gradient_background, random_triangles, Group, Rng, Scene, Size, Tolerance};
use crate::call::{Call, Rec};
use softgl::{BlendFactor, Capability, ClearMask, ColorFormat, CompareFunc, LogicOp, PrimitiveMode, StencilOp};

const G: Group = Group::Combination;
const E: Tolerance = Tolerance::EXACT;

pub fn scenes() -> Vec<Scene> {
    vec![
        Scene::new("decal_stencil", G, E, decal_stencil),
        Scene::new("transparency_depth_write_off", G, E, transparency),
        Scene::new("xor_rubber_band", G, E, xor_rubber_band),
        Scene::new("masked_clear", G, E, masked_clear),
        Scene::new("scissored_clears", G, E, scissored_clears),
        Scene::new("stencil_depth_fail", G, E, stencil_depth_fail),
        Scene::new("all_stages", G, E, all_stages),
        Scene::new("rgb565", G, E, rgb565).in_format(ColorFormat::Rgb565),
    ]
}

/// The decal pattern: the base writes stencil 1 where it is drawn, the decal
/// is drawn only there with the depth test off.
fn decal_stencil(r: &mut Rec, s: Size) {
    let (w, h) = (s.wf(), s.hf());
    r.enable(Capability::DepthTest)
        .call(Call::DepthFunc(CompareFunc::Less))
        .enable(Capability::StencilTest)
        .call(Call::StencilFunc(CompareFunc::Always, 1, 0xff))
        .call(Call::StencilOp(StencilOp::Keep, StencilOp::Keep, StencilOp::Replace));
    r.begin(PrimitiveMode::Triangles)
        .color(0.2, 0.4, 0.8, 1.0)
        .vertex(w * 0.1, h * 0.1, 0.2)
        .color(0.3, 0.6, 0.2, 1.0)
        .vertex(w * 0.9, h * 0.2, -0.3)
        .color(0.8, 0.3, 0.3, 1.0)
        .vertex(w * 0.4, h * 0.9, 0.1)
        .end();
    r.call(Call::StencilFunc(CompareFunc::Equal, 1, 0xff))
        .call(Call::StencilOp(StencilOp::Keep, StencilOp::Keep, StencilOp::Keep))
        .disable(Capability::DepthTest);
    let mut rng = Rng::new(20);
    random_triangles(r, &mut rng, s.count(120), s, 10.0, (1.0, 1.0));
}

/// Opaque geometry with depth writes, then transparent geometry blended over
/// it with depth writes off.
fn transparency(r: &mut Rec, s: Size) {
    let mut rng = Rng::new(21);
    r.enable(Capability::DepthTest).call(Call::DepthFunc(CompareFunc::Less));
    random_triangles(r, &mut rng, s.count(200), s, 20.0, (1.0, 1.0));
    r.call(Call::DepthMask(false))
        .enable(Capability::Blend)
        .call(Call::BlendFunc(BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha));
    random_triangles(r, &mut rng, s.count(200), s, 30.0, (0.2, 0.7));
}

/// A rubber band: rectangles outlined with XOR lines, each drawn twice except
/// the last, so only the last remains, over a scene.
fn xor_rubber_band(r: &mut Rec, s: Size) {
    gradient_background(r, s);
    r.enable(Capability::ColorLogicOp).call(Call::LogicOp(LogicOp::Xor));
    r.color(1.0, 1.0, 1.0, 1.0);
    let band = |r: &mut Rec, k: f32| {
        let (x0, y0) = (s.wf() * 0.1 + k, s.hf() * 0.1 + k * 0.5);
        let (x1, y1) = (s.wf() * 0.5 + 2.0 * k, s.hf() * 0.4 + k);
        r.begin(PrimitiveMode::LineLoop)
            .vertex(x0 + 0.5, y0 + 0.5, 0.0)
            .vertex(x1 + 0.5, y0 + 0.5, 0.0)
            .vertex(x1 + 0.5, y1 + 0.5, 0.0)
            .vertex(x0 + 0.5, y1 + 0.5, 0.0)
            .end();
    };
    for k in 0..6 {
        band(r, k as f32 * 3.0);
        band(r, k as f32 * 3.0);
    }
    band(r, 20.0);
}

fn masked_clear(r: &mut Rec, s: Size) {
    gradient_background(r, s);
    r.call(Call::ColorMask([true, false, true, false]))
        .clear_color(0.3, 0.9, 0.1, 0.7)
        .clear(ClearMask::COLOR);
    r.call(Call::ColorMask([false, true, false, true]))
        .enable(Capability::ScissorTest)
        .scissor(s.w as i32 / 3, s.h as i32 / 3, s.w as i32 / 2, s.h as i32 / 2)
        .clear_color(0.6, 0.2, 0.9, 0.4)
        .clear(ClearMask::COLOR);
}

fn scissored_clears(r: &mut Rec, s: Size) {
    r.enable(Capability::ScissorTest);
    let mut rng = Rng::new(22);
    for _ in 0..12 {
        let (x, y) = (rng.range(-10.0, s.wf()) as i32, rng.range(-10.0, s.hf()) as i32);
        let (w, h) = (rng.range(0.0, s.wf() / 2.0) as i32, rng.range(0.0, s.hf() / 2.0) as i32);
        r.scissor(x, y, w, h)
            .clear_color(rng.unit(), rng.unit(), rng.unit(), 1.0)
            .clear(ClearMask::COLOR | ClearMask::DEPTH);
    }
    r.disable(Capability::ScissorTest);
}

/// Stencil shadow-volume counting: depth-fail increments and decrements.
fn stencil_depth_fail(r: &mut Rec, s: Size) {
    let mut rng = Rng::new(23);
    r.enable(Capability::DepthTest).call(Call::DepthFunc(CompareFunc::Less));
    random_triangles(r, &mut rng, s.count(100), s, 30.0, (1.0, 1.0));
    r.enable(Capability::StencilTest)
        .call(Call::StencilFunc(CompareFunc::Always, 0, 0xff))
        .call(Call::DepthMask(false))
        .call(Call::ColorMask([false; 4]))
        .call(Call::StencilOp(StencilOp::Keep, StencilOp::IncrWrap, StencilOp::Keep));
    random_triangles(r, &mut rng, s.count(80), s, 40.0, (1.0, 1.0));
    r.call(Call::StencilOp(StencilOp::Keep, StencilOp::DecrWrap, StencilOp::Keep));
    random_triangles(r, &mut rng, s.count(80), s, 40.0, (1.0, 1.0));
    r.call(Call::DepthMask(true));
    let values: Vec<u8> = (0..=6).chain(250..=255).collect();
    show_stencil(r, s, &values);
}

/// scissor + alpha + stencil + depth + blend + colour mask together.
fn all_stages(r: &mut Rec, s: Size) {
    let mut rng = Rng::new(24);
    r.enable(Capability::ScissorTest)
        .scissor(3, 5, s.w as i32 - 9, s.h as i32 - 8)
        .enable(Capability::AlphaTest)
        .call(Call::AlphaFunc(CompareFunc::Greater, 0.2))
        .enable(Capability::StencilTest)
        .call(Call::StencilFunc(CompareFunc::Lequal, 1, 0x7f))
        .call(Call::StencilOp(StencilOp::Keep, StencilOp::Incr, StencilOp::Incr))
        .enable(Capability::DepthTest)
        .call(Call::DepthFunc(CompareFunc::Lequal))
        .enable(Capability::Blend)
        .call(Call::BlendFunc(BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha))
        .call(Call::ColorMask([true, true, false, true]));
    random_triangles(r, &mut rng, s.count(600), s, 20.0, (0.0, 1.0));
}

/// Into an RGB 5-6-5 buffer (`OSMESA_RGB_565`), GL_DITHER on (GL's default):
/// a whole-buffer clear between 5- and 6-bit steps, a smooth gradient, blended
/// triangles, XOR, a colour-masked and a scissored clear. llvmpipe ignores
/// GL_DITHER, truncates unorm8 to the high bits and rounds whole-buffer clears
/// half up (docs/llvmpipe-facts.md §13).
fn rgb565(r: &mut Rec, s: Size) {
    let mut rng = Rng::new(25);
    r.clear_color(0.1, 0.2, 0.3, 0.4).clear(ClearMask::COLOR);
    r.begin(PrimitiveMode::Triangles);
    r.color(1.0, 0.0, 0.5, 1.0).vertex(0.0, 0.0, 0.0);
    r.color(0.0, 1.0, 0.25, 1.0).vertex(s.wf(), 0.0, 0.0);
    r.color(0.3, 0.6, 1.0, 1.0).vertex(0.0, s.hf() * 0.8, 0.0);
    r.end();
    r.enable(Capability::Blend)
        .call(Call::BlendFunc(BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha));
    random_triangles(r, &mut rng, s.count(150), s, 25.0, (0.1, 0.9));
    r.disable(Capability::Blend)
        .enable(Capability::ColorLogicOp)
        .call(Call::LogicOp(LogicOp::Xor))
        .color(0.7, 0.35, 0.9, 1.0)
        .rect(s.wf() * 0.2, s.hf() * 0.3, s.wf() * 0.7, s.hf() * 0.6, 0.0);
    r.disable(Capability::ColorLogicOp)
        .call(Call::ColorMask([true, false, true, true]))
        .clear_color(0.55, 0.9, 0.45, 1.0)
        .clear(ClearMask::COLOR)
        .call(Call::ColorMask([true; 4]))
        .enable(Capability::ScissorTest)
        .scissor(s.w as i32 / 2, s.h as i32 / 4, s.w as i32 / 3, s.h as i32 / 2)
        .clear_color(0.61, 0.33, 0.77, 1.0)
        .clear(ClearMask::COLOR)
        .disable(Capability::ScissorTest);
}
