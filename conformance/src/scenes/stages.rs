//! Each per-fragment stage alone.

use super::{gradient_background, panels, random_triangles, Group, Near, Rng, Scene, Size, Tolerance};
use crate::call::{Call, Rec};
use softgl::{
    BlendEquation, BlendFactor, Capability, ClearMask, CompareFunc, LogicOp, PrimitiveMode, ShadeModel, StencilOp,
};

const G: Group = Group::Stage;
const E: Tolerance = Tolerance::EXACT;

/// Constant-colour and SRC_ALPHA_SATURATE factors round differently from llvmpipe's by up to 2 LSB (measured 47 pixels at 96x96, none at 256x256).
const CONSTANT_BLEND: Tolerance = Tolerance {
    channel: 2,
    near: Near { test: 47, report: 0 },
    share_over: 0.0,
    coverage: 0,
    reason: "Constant-colour and SRC_ALPHA_SATURATE factors round differently from llvmpipe's by up to 2 LSB (measured 47 pixels at 96x96, none at 256x256).",
};

pub fn scenes() -> Vec<Scene> {
    vec![
        Scene::new("clear", G, E, clear),
        Scene::new("smooth_triangles", G, E, smooth_triangles),
        Scene::new("flat_triangles", G, E, flat_triangles),
        Scene::new("depth_less", G, E, depth_less),
        Scene::new("depth_funcs", G, E, depth_funcs),
        Scene::new("depth_mask_off", G, E, depth_mask_off),
        Scene::new("depth_range", G, E, depth_range),
        Scene::new("scissor", G, E, scissor),
        Scene::new("alpha_funcs", G, E, alpha_funcs),
        Scene::new("stencil_ops", G, E, stencil_ops),
        Scene::new("blend_alpha", G, E, blend_alpha),
        Scene::new("blend_additive", G, E, blend_additive),
        Scene::new("blend_factors", G, CONSTANT_BLEND, blend_factors),
        Scene::new("blend_equations", G, E, blend_equations),
        Scene::new("blend_separate", G, E, blend_separate),
        Scene::new("logic_ops", G, E, logic_ops),
        Scene::new("color_masks", G, E, color_masks),
        Scene::new("dither_off", G, E, dither_off),
    ]
}

fn clear(r: &mut Rec, _s: Size) {
    r.clear_color(0.25, 0.5, 0.75, 1.0).clear(ClearMask::COLOR);
}

fn smooth_triangles(r: &mut Rec, s: Size) {
    random_triangles(r, &mut Rng::new(1), s.count(400), s, 16.0, (1.0, 1.0));
}

fn flat_triangles(r: &mut Rec, s: Size) {
    r.shade_model(ShadeModel::Flat);
    random_triangles(r, &mut Rng::new(2), s.count(400), s, 16.0, (1.0, 1.0));
}

fn depth_less(r: &mut Rec, s: Size) {
    r.enable(Capability::DepthTest).call(Call::DepthFunc(CompareFunc::Less));
    random_triangles(r, &mut Rng::new(3), s.count(800), s, 20.0, (1.0, 1.0));
}

/// Per panel: a grey rectangle at z = 0, then three triangles sloping through
/// z = 0 tested with one of the eight functions.
fn depth_funcs(r: &mut Rec, s: Size) {
    r.enable(Capability::DepthTest);
    for (p, f) in panels(8, s).into_iter().zip(CompareFunc::ALL) {
        r.call(Call::DepthFunc(CompareFunc::Always));
        r.color(0.5, 0.5, 0.5, 1.0).rect(p[0], p[1], p[2], p[3], 0.0);
        r.call(Call::DepthFunc(f));
        let (w, h) = (p[2] - p[0], p[3] - p[1]);
        r.begin(PrimitiveMode::Triangles);
        for k in 0..3 {
            let y = p[1] + h * (k as f32 + 0.5) / 3.0;
            r.color(1.0, 0.2 * k as f32, 0.0, 1.0)
                .vertex(p[0] + 1.0, y - h / 7.0, -0.9);
            r.color(0.0, 1.0, 0.3 * k as f32, 1.0).vertex(p[2] - 1.0, y, 0.9);
            r.color(0.0, 0.0, 1.0, 1.0).vertex(p[0] + w * 0.3, y + h / 7.0, 0.0);
        }
        r.end();
    }
}

fn depth_mask_off(r: &mut Rec, s: Size) {
    r.enable(Capability::DepthTest).call(Call::DepthFunc(CompareFunc::Less));
    let mut rng = Rng::new(4);
    random_triangles(r, &mut rng, s.count(200), s, 20.0, (1.0, 1.0));
    r.call(Call::DepthMask(false));
    random_triangles(r, &mut rng, s.count(200), s, 20.0, (1.0, 1.0));
}

fn depth_range(r: &mut Rec, s: Size) {
    r.enable(Capability::DepthTest)
        .call(Call::DepthFunc(CompareFunc::Lequal));
    let mut rng = Rng::new(5);
    r.call(Call::DepthRange(0.25, 0.75));
    random_triangles(r, &mut rng, s.count(200), s, 20.0, (1.0, 1.0));
    r.call(Call::DepthRange(0.6, 0.1));
    random_triangles(r, &mut rng, s.count(200), s, 20.0, (1.0, 1.0));
}

fn scissor(r: &mut Rec, s: Size) {
    let (w, h) = (s.w as i32, s.h as i32);
    r.enable(Capability::ScissorTest).scissor(w / 5, h / 4, w / 2, h / 3);
    random_triangles(r, &mut Rng::new(6), s.count(300), s, 24.0, (1.0, 1.0));
}

/// Per panel: a quad whose alpha runs 0..1 across x, tested with one function
/// against 0.5 (and exactly 128/255 in the second half of the panels' rows).
fn alpha_funcs(r: &mut Rec, s: Size) {
    r.enable(Capability::AlphaTest);
    for (i, (p, f)) in panels(16, s)
        .into_iter()
        .zip(CompareFunc::ALL.iter().cycle())
        .enumerate()
    {
        let reference = if i < 8 { 0.5 } else { 128.0 / 255.0 };
        r.call(Call::AlphaFunc(*f, reference));
        r.begin(PrimitiveMode::TriangleStrip)
            .color(1.0, 0.0, 0.0, 0.0)
            .vertex(p[0], p[1], 0.0)
            .color(0.0, 1.0, 0.0, 1.0)
            .vertex(p[2], p[1], 0.0)
            .color(1.0, 0.0, 1.0, 0.0)
            .vertex(p[0], p[3], 0.0)
            .color(0.0, 1.0, 1.0, 1.0)
            .vertex(p[2], p[3], 0.0)
            .end();
    }
}

/// Shows the stencil buffer: for each value, a rectangle drawn where the
/// stencil equals it, in a colour coding the value.
pub fn show_stencil(r: &mut Rec, s: Size, values: &[u8]) {
    r.enable(Capability::StencilTest)
        .call(Call::StencilOp(StencilOp::Keep, StencilOp::Keep, StencilOp::Keep))
        .call(Call::ColorMask([true; 4]))
        .disable(Capability::DepthTest)
        .disable(Capability::Blend);
    for &v in values {
        r.call(Call::StencilFunc(CompareFunc::Equal, v as i32, 0xff));
        r.color(
            (v % 4) as f32 / 3.0,
            (v / 4 % 4) as f32 / 3.0,
            (v / 16) as f32 / 15.0,
            1.0,
        )
        .rect(0.0, 0.0, s.wf(), s.hf(), 0.0);
    }
}

/// Per panel: three overlapping triangles update the stencil with one op
/// (the stencil starts at 2); then the values are shown.
fn stencil_ops(r: &mut Rec, s: Size) {
    r.call(Call::ClearStencil(2)).clear(ClearMask::STENCIL);
    r.enable(Capability::StencilTest)
        .call(Call::StencilFunc(CompareFunc::Always, 7, 0xff))
        .call(Call::ColorMask([false; 4]));
    for (p, op) in panels(8, s).into_iter().zip(StencilOp::ALL) {
        r.call(Call::StencilOp(StencilOp::Keep, StencilOp::Keep, op));
        let (w, h) = (p[2] - p[0], p[3] - p[1]);
        r.begin(PrimitiveMode::Triangles);
        for k in 0..3 {
            let o = k as f32 * w / 6.0;
            r.vertex(p[0] + o, p[1] + 1.0, 0.0)
                .vertex(p[0] + o + w * 0.6, p[1] + h * 0.3, 0.0)
                .vertex(p[0] + o + w * 0.2, p[3] - 1.0, 0.0);
        }
        r.end();
    }
    let values: Vec<u8> = (0..=9).chain(248..=255).collect();
    show_stencil(r, s, &values);
}

fn blend_alpha(r: &mut Rec, s: Size) {
    r.enable(Capability::Blend)
        .call(Call::BlendFunc(BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha));
    random_triangles(r, &mut Rng::new(7), s.count(400), s, 20.0, (0.0, 1.0));
}

fn blend_additive(r: &mut Rec, s: Size) {
    r.enable(Capability::Blend)
        .call(Call::BlendFunc(BlendFactor::One, BlendFactor::One));
    random_triangles(r, &mut Rng::new(8), s.count(400), s, 20.0, (0.0, 1.0));
}

/// A panel per factor as source (destination ONE_MINUS_SRC_ALPHA) and as
/// destination (source SRC_ALPHA), over the gradient, with a blend colour set.
fn blend_factors(r: &mut Rec, s: Size) {
    gradient_background(r, s);
    r.enable(Capability::Blend).call(Call::BlendColor([0.2, 0.6, 0.9, 0.4]));
    let pairs: Vec<(BlendFactor, BlendFactor)> = BlendFactor::ALL
        .iter()
        .map(|&f| (f, BlendFactor::OneMinusSrcAlpha))
        .chain(
            BlendFactor::ALL
                .iter()
                .filter(|&&f| f != BlendFactor::SrcAlphaSaturate)
                .map(|&f| (BlendFactor::SrcAlpha, f)),
        )
        .collect();
    for (p, (src, dst)) in panels(pairs.len(), s).into_iter().zip(pairs) {
        r.call(Call::BlendFunc(src, dst));
        r.begin(PrimitiveMode::Triangles)
            .color(1.0, 0.5, 0.0, 0.8)
            .vertex(p[0], p[1], 0.0)
            .color(0.0, 0.7, 1.0, 0.3)
            .vertex(p[2], p[1], 0.0)
            .color(0.9, 0.9, 0.9, 0.6)
            .vertex(p[0], p[3], 0.0)
            .end();
    }
}

fn blend_equations(r: &mut Rec, s: Size) {
    gradient_background(r, s);
    r.enable(Capability::Blend)
        .call(Call::BlendFunc(BlendFactor::SrcAlpha, BlendFactor::One));
    for (p, eq) in panels(5, s).into_iter().zip(BlendEquation::ALL) {
        r.call(Call::BlendEquation(eq));
        r.begin(PrimitiveMode::Triangles)
            .color(1.0, 0.2, 0.0, 0.9)
            .vertex(p[0], p[1], 0.0)
            .color(0.0, 0.6, 1.0, 0.4)
            .vertex(p[2], p[1], 0.0)
            .color(0.5, 0.5, 0.5, 0.7)
            .vertex(p[2], p[3], 0.0)
            .end();
    }
}

fn blend_separate(r: &mut Rec, s: Size) {
    gradient_background(r, s);
    r.enable(Capability::Blend);
    let sets = [
        [
            BlendFactor::SrcAlpha,
            BlendFactor::OneMinusSrcAlpha,
            BlendFactor::One,
            BlendFactor::Zero,
        ],
        [
            BlendFactor::DstColor,
            BlendFactor::Zero,
            BlendFactor::Zero,
            BlendFactor::One,
        ],
        [
            BlendFactor::One,
            BlendFactor::One,
            BlendFactor::OneMinusDstAlpha,
            BlendFactor::DstAlpha,
        ],
        [
            BlendFactor::SrcAlphaSaturate,
            BlendFactor::One,
            BlendFactor::One,
            BlendFactor::OneMinusSrcAlpha,
        ],
    ];
    let mut rng = Rng::new(9);
    for (p, f) in panels(4, s).into_iter().zip(sets) {
        r.call(Call::BlendFuncSeparate(f));
        r.begin(PrimitiveMode::Triangles);
        for _ in 0..6 {
            for _ in 0..3 {
                r.color(rng.unit(), rng.unit(), rng.unit(), rng.unit()).vertex(
                    rng.range(p[0], p[2]),
                    rng.range(p[1], p[3]),
                    0.0,
                );
            }
        }
        r.end();
    }
}

fn logic_ops(r: &mut Rec, s: Size) {
    gradient_background(r, s);
    r.enable(Capability::ColorLogicOp);
    for (p, op) in panels(16, s).into_iter().zip(LogicOp::ALL) {
        r.call(Call::LogicOp(op));
        r.begin(PrimitiveMode::Triangles)
            .color(1.0, 0.5, 0.25, 1.0)
            .vertex(p[0], p[1], 0.0)
            .color(0.0, 0.75, 1.0, 0.5)
            .vertex(p[2], p[1], 0.0)
            .color(0.3, 0.1, 0.9, 0.0)
            .vertex(p[2], p[3], 0.0)
            .end();
    }
}

fn color_masks(r: &mut Rec, s: Size) {
    gradient_background(r, s);
    for (i, p) in panels(16, s).into_iter().enumerate() {
        r.call(Call::ColorMask([i & 1 != 0, i & 2 != 0, i & 4 != 0, i & 8 != 0]));
        r.color(0.9, 0.6, 0.3, 0.1)
            .rect(p[0] + 2.0, p[1] + 2.0, p[2] - 2.0, p[3] - 2.0, 0.0);
    }
}

fn dither_off(r: &mut Rec, s: Size) {
    r.disable(Capability::Dither);
    gradient_background(r, s);
    random_triangles(r, &mut Rng::new(10), s.count(100), s, 30.0, (1.0, 1.0));
}
