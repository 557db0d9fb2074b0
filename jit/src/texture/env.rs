//! The texture environment: each enabled unit's combine, in order, as Mesa's
//! fixed-function fragment shader builds it (`emit_texenv`, `emit_combine` in
//! `src/mesa/main/ff_fragment_shader.cpp`; `docs/llvmpipe-facts.md` §17).

use super::{CombineFn, CombineKey, CombineSrc, Operand, TexUnitKey, MAX_UNITS};
use crate::shade::saturate;

/// The colour after the texture environment of every enabled unit, from
/// the interpolated `primary` colour, each unit's texture sample
/// (`samples[u]`, ignored for units that are `None`) and each unit's
/// `GL_TEXTURE_ENV_COLOR`. A unit's `Previous` is the last enabled unit's
/// result (the primary colour before the first); a `TextureUnit(n)` source
/// naming a disabled unit reads 0 (`load_texture` of `ff_fragment_shader.cpp`).
pub fn environment(
    units: &[Option<TexUnitKey>; MAX_UNITS],
    samples: &[[f32; 4]; MAX_UNITS],
    primary: [f32; 4],
    env_color: &[[f32; 4]; MAX_UNITS],
) -> [f32; 4] {
    let mut previous = primary;
    for (u, unit) in units.iter().enumerate() {
        let Some(unit) = unit else { continue };
        let source = |s: CombineSrc| -> [f32; 4] {
            match s {
                CombineSrc::Texture => samples[u],
                CombineSrc::TextureUnit(n) => match units.get(n as usize) {
                    Some(Some(_)) => samples[n as usize],
                    _ => [0.0; 4],
                },
                CombineSrc::Constant => env_color[u],
                CombineSrc::PrimaryColor => primary,
                CombineSrc::Previous => previous,
            }
        };
        previous = combine(&unit.env, source);
    }
    previous
}

/// One unit's combine with its sources read through `source`.
pub fn combine(k: &CombineKey, source: impl Fn(CombineSrc) -> [f32; 4]) -> [f32; 4] {
    // Both scales apply to every function, DOT3 included: `emit_texenv`
    // drops them only for the EXT_texture_env_dot3 modes.
    let (rgb_shift, alpha_shift) = (k.scale_rgb, k.scale_alpha);
    let rgb_arg = |i: usize| operand(k.op_rgb[i], source(k.src_rgb[i]));
    let rgb = function(k.rgb, [rgb_arg(0), rgb_arg(1), rgb_arg(2)]);
    let alpha = if k.rgb == CombineFn::Dot3Rgba {
        rgb[3]
    } else {
        let alpha_arg = |i: usize| operand(k.op_alpha[i], source(k.src_alpha[i]));
        function(k.alpha, [alpha_arg(0), alpha_arg(1), alpha_arg(2)])[3]
    };
    let mut out = [rgb[0], rgb[1], rgb[2], alpha];
    if rgb_shift != 1 || alpha_shift != 1 {
        // A scale saturates all four channels after the multiply.
        for (c, v) in out.iter_mut().enumerate() {
            let s = if c < 3 { rgb_shift } else { alpha_shift };
            *v = saturate(*v * f32::from(s));
        }
    } else {
        for (c, v) in out.iter_mut().enumerate() {
            let f = if c < 3 { k.rgb } else { k.alpha };
            let f = if k.rgb == CombineFn::Dot3Rgba { k.rgb } else { f };
            if needs_saturate(f) {
                *v = saturate(*v);
            }
        }
    }
    out
}

/// Whether a function's result is clamped (`need_saturate`): not for those
/// whose inputs in `[0, 1]` keep it there.
fn needs_saturate(f: CombineFn) -> bool {
    match f {
        CombineFn::Replace | CombineFn::Modulate | CombineFn::Interpolate => false,
        CombineFn::Add | CombineFn::AddSigned | CombineFn::Subtract | CombineFn::Dot3Rgb | CombineFn::Dot3Rgba => true,
    }
}

/// An operand applied to a source colour (alpha operands give the alpha in
/// every channel; `emit_combine_source`).
fn operand(op: Operand, c: [f32; 4]) -> [f32; 4] {
    match op {
        Operand::SrcColor => c,
        Operand::OneMinusSrcColor => c.map(|v| 1.0 - v),
        Operand::SrcAlpha => [c[3]; 4],
        Operand::OneMinusSrcAlpha => [1.0 - c[3]; 4],
    }
}

/// A combine function of three operands, channel by channel (`emit_combine`);
/// DOT3 puts its scalar in every channel.
fn function(f: CombineFn, a: [[f32; 4]; 3]) -> [f32; 4] {
    let per = |g: fn(f32, f32, f32) -> f32| std::array::from_fn(|c| g(a[0][c], a[1][c], a[2][c]));
    match f {
        CombineFn::Replace => a[0],
        CombineFn::Modulate => per(|x, y, _| x * y),
        CombineFn::Add => per(|x, y, _| x + y),
        // `(a + b) + #c` becomes `(a + #c) + b` (nir_opt_algebraic.py).
        CombineFn::AddSigned => per(|x, y, _| (x + -0.5) + y),
        CombineFn::Interpolate => per(|x, y, z| x * z + y * (1.0 - z)),
        CombineFn::Subtract => per(|x, y, _| x - y),
        CombineFn::Dot3Rgb | CombineFn::Dot3Rgba => {
            let s = a[0].map(|v| v * 2.0 + -1.0);
            let t = a[1].map(|v| v * 2.0 + -1.0);
            [dot3(s, t); 4]
        }
    }
}

/// A three-component dot product as NIR lowers `fdot3` for llvmpipe: products
/// summed from the last component, unfused (`lower_reduction`).
fn dot3(s: [f32; 4], t: [f32; 4]) -> f32 {
    (s[2] * t[2] + s[1] * t[1]) + s[0] * t[0]
}
