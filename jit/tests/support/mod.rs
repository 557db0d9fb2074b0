//! Keys shared by the contract and tier tests and the benches
//! (`#[path]`-included by `jit/benches/texels.rs`).

use softgl_jit::texture::{
    effective_combine, BaseFormat, CombineKey, DepthMode, EnvMode, Filter, Image, MipFilter, SamplerKey,
    SamplerStatics, TexTarget, TexUnitKey, TexelFormat, TextureRef, TextureSet, Wrap, MAX_UNITS,
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
            statics: SamplerStatics::default(),
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

/// `key` with a second unit: a copy of unit 0 sampling bilinear (no mipmap),
/// CLAMP_TO_EDGE, its environment over unit 0's result.
#[allow(
    dead_code,
    reason = "the tier tests and the texel bench use it, the contract tests do not"
)]
pub fn with_bilinear_second_unit(key: FragmentKey) -> FragmentKey {
    let mut two = key;
    if let Some(shade) = two.shade.as_mut() {
        let mut second = shade.tex[0].expect("unit 0 is on");
        second.sampler.mip = MipFilter::None;
        second.sampler.wrap = [Wrap::ClampToEdge; 3];
        shade.tex[1] = Some(second);
    }
    two
}

/// The images of `levels` (width, height, RGBA8 texels), depth 1.
pub fn images(levels: &[(u32, u32, Vec<u8>)]) -> Vec<Image<'_>> {
    levels
        .iter()
        .map(|(width, height, texels)| Image {
            texels,
            units: None,
            width: *width,
            height: *height,
            depth: 1,
        })
        .collect()
}

/// A texture sampling every one of `images` as its chain from level 0, no
/// LOD clamp or bias, black border.
pub fn whole_chain<'a>(images: &'a [Image<'a>]) -> TextureRef<'a> {
    TextureRef {
        images,
        base_level: 0,
        max_level: images.len() as u32 - 1,
        min_lod: -1000.0,
        max_lod: 1000.0,
        lod_bias: 0.0,
        border: [0.0; 4],
        float_depth: false,
    }
}

/// A set with [`whole_chain`] of `images` on units 0 and 1.
pub fn two_units<'a>(images: &'a [Image<'a>]) -> TextureSet<'a> {
    let mut set = TextureSet::default();
    set.units[0] = Some(whole_chain(images));
    set.units[1] = set.units[0];
    set
}

/// `key` with the statics of `set`'s textures (`softgl_jit::texture::with_statics`):
/// without them a natively sampled unit would run on the interpreter.
pub fn bind(key: &FragmentKey, set: &TextureSet<'_>) -> FragmentKey {
    let mut key = *key;
    if let Some(shade) = key.shade.as_mut() {
        shade.tex = softgl_jit::texture::with_statics(&shade.tex, set);
    }
    key
}
