//! Keys shared by the contract tests and the texel bench
//! (`#[path]`-included by `jit/benches/texels.rs`).

use softgl_jit::texture::{
    effective_combine, BaseFormat, CombineKey, DepthMode, EnvMode, Filter, MipFilter, SamplerKey, TexTarget,
    TexUnitKey, TexelFormat, Wrap, MAX_UNITS,
};
use softgl_jit::{ColorFormat, FragmentKey, ShadeKey};

/// A key with one 2D RGBA8 unit (RGBA base, environment `mode`) with these
/// filters and wrap, shading an RGBA8 buffer's colour.
pub fn one_unit_key(min: Filter, mip: MipFilter, mag: Filter, wrap: Wrap, mode: EnvMode) -> FragmentKey {
    let unit = TexUnitKey {
        sampler: SamplerKey {
            target: TexTarget::D2,
            format: TexelFormat::Rgba8,
            min,
            mip,
            mag,
            wrap: [wrap; 3],
            compare: None,
            depth_mode: DepthMode::Luminance,
        },
        base: BaseFormat::Rgba,
        env: effective_combine(mode, BaseFormat::Rgba, CombineKey::DEFAULT),
    };
    let mut tex = [None; MAX_UNITS];
    tex[0] = Some(unit);
    FragmentKey {
        shade: Some(ShadeKey {
            color: true,
            tex,
            ..ShadeKey::default()
        }),
        ..FragmentKey::new(ColorFormat::Rgba8, None, false)
    }
}
