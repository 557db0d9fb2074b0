//! Texturing as a fragment stage: the types the key, the uniforms and the
//! texture store share, and the reference sampler and texture environment
//! (`docs/llvmpipe-facts.md` §16 sampling, §17 environment).
//!
//! A unit that is enabled and complete contributes a [`TexUnitKey`] to
//! [`ShadeKey::tex`](crate::key::ShadeKey::tex): everything about it that
//! changes code. What it samples (images, sizes, LOD values, border colour)
//! arrives per draw as a [`TextureRef`] in a [`TextureSet`] and is never part
//! of the key.
//!
//! [`sample_quad`] (the fragment's 2×2 quad, exact for every target; [`sample`]
//! takes three of its pixels and is exact except for cube maps with per-pixel
//! λ) and [`environment`] are the reference: [`crate::shade::fragment`] calls
//! them per fragment, and compiled code must compute the same bits (or call
//! them back through `jit/src/callout.rs`). [`uses_aos`] says which of
//! llvmpipe's two filtering paths a sampler takes; [`filter`], [`lod`],
//! [`cube`] and [`arith`] hold their steps (`docs/llvmpipe-facts.md` §16, §17).
//! `jit/tests/texture.rs` checks all of it against llvmpipe's pixels.

pub mod arith;
pub mod cube;
mod env;
pub mod filter;
pub mod lod;
mod sample;

pub use env::{combine, environment};
pub use sample::{sample, sample_quad, uses_aos, QuadSample};

/// `GL_MAX_TEXTURE_UNITS`.
pub const MAX_UNITS: usize = 8;
/// Levels of a 4096 texture (`GL_MAX_TEXTURE_SIZE`; Mesa/llvmpipe report 16384, softgl caps at 4096).
pub const MAX_LEVELS: usize = 13;
/// Levels of a 256 3D texture (`GL_MAX_3D_TEXTURE_SIZE`).
pub const MAX_3D_LEVELS: usize = 9;

/// A texture target.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TexTarget {
    D1,
    D2,
    D3,
    Cube,
    /// `GL_TEXTURE_RECTANGLE_ARB`: one level, 2D, sampled at unnormalized
    /// coordinates (s in `[0, width]`, t in `[0, height]`).
    Rect,
}

impl TexTarget {
    /// Whether coordinates are normalized (all targets but [`TexTarget::Rect`]:
    /// llvmpipe's `normalized_coords`, which Mesa's `st_convert_sampler`
    /// clears for rectangle textures).
    pub const fn normalized(self) -> bool {
        !matches!(self, TexTarget::Rect)
    }
}

/// How texels are stored (chosen at upload for sampling speed).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TexelFormat {
    /// 4 bytes R, G, B, A unorm8: every base format expanded to RGBA at upload
    /// (L→LLL1, A→000A, I→IIII, LA→LLLA, RGB→RGB1).
    Rgba8,
    /// As `Rgba8`, RGB sRGB-encoded (decoded to linear when sampled, where llvmpipe decodes).
    Srgba8,
    /// 4 × `u16` unorm, native endian (formats llvmpipe keeps at 16 bits; its float SoA path).
    Rgba16,
    /// 1 × `f32` depth in `[0, 1]`, native endian.
    Depth32F,
}

impl TexelFormat {
    /// Bytes one texel takes.
    pub const fn bytes_per_texel(self) -> usize {
        match self {
            TexelFormat::Rgba8 | TexelFormat::Srgba8 | TexelFormat::Depth32F => 4,
            TexelFormat::Rgba16 => 8,
        }
    }
}

/// The GL base internal format: decides the texture environment (GL 1.5 tables 3.22, 3.23).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BaseFormat {
    Alpha,
    Luminance,
    LuminanceAlpha,
    Intensity,
    Rgb,
    Rgba,
    Depth,
}

/// A minification or magnification filter.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Filter {
    Nearest,
    Linear,
}

/// How minification chooses between mipmap levels (`None`: level `base_level` only).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum MipFilter {
    None,
    Nearest,
    Linear,
}

/// A wrap mode.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Wrap {
    Repeat,
    Clamp,
    ClampToEdge,
    ClampToBorder,
    MirroredRepeat,
}

/// `GL_DEPTH_TEXTURE_MODE`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum DepthMode {
    Luminance,
    Intensity,
    Alpha,
}

impl DepthMode {
    /// The base format a depth texture takes in the texture environment
    /// (Mesa `texstate.c`, `update_tex_combine`).
    pub const fn base(self) -> BaseFormat {
        match self {
            DepthMode::Luminance => BaseFormat::Luminance,
            DepthMode::Intensity => BaseFormat::Intensity,
            DepthMode::Alpha => BaseFormat::Alpha,
        }
    }
}

/// Everything about a unit's sampling that changes code.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct SamplerKey {
    pub target: TexTarget,
    pub format: TexelFormat,
    pub min: Filter,
    pub mip: MipFilter,
    pub mag: Filter,
    /// s, t, r; dimensions the target lacks are `Wrap::Repeat`.
    pub wrap: [Wrap; 3],
    /// `GL_COMPARE_R_TO_TEXTURE` with this function (depth formats only).
    pub compare: Option<crate::key::CompareFunc>,
    pub depth_mode: DepthMode,
    /// What natively sampled units compile in from the bound texture
    /// ([`SamplerKey::with_statics`]); the default for the others.
    pub statics: SamplerStatics,
}

/// Facts about the bound texture that llvmpipe compiles into its sampler
/// rather than reading at run time, and so does the native sampler
/// (`crate::compile::native_unit`): `lp_static_texture_state`'s
/// `pot_width`/`pot_height` and `lp_static_sampler_state`'s
/// `min_max_lod_equal`, `apply_min_lod`, `apply_max_lod` and
/// `lod_bias_non_zero` (`gallivm/lp_bld_sample.c`,
/// `lp_sampler_static_texture_state` and `lp_sampler_static_sampler_state`).
/// Sizes, addresses and the LOD values themselves stay uniforms. A key
/// whose statics disagree with the texture it is drawn with runs on the
/// interpreter (`crate::callout::TexView::new` refuses it).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct SamplerStatics {
    /// Level 0's width and height are powers of two, on the axes that REPEAT
    /// (false on the others, where nothing depends on it).
    pub pot: [bool; 2],
    /// [`lod::LodState`]'s flags.
    pub min_max_equal: bool,
    pub apply_min: bool,
    pub apply_max: bool,
    pub bias_non_zero: bool,
    /// A compared depth texture is float depth ([`TextureRef::float_depth`]:
    /// the reference is not clamped; llvmpipe's format is static too).
    pub float_depth: bool,
    /// The sampled level's depth texels are 24-bit depth-test units
    /// ([`DepthUnits::unorm24`]), converted per lookup.
    pub depth_units: bool,
}

impl SamplerStatics {
    /// The statics of `tex` sampled with `key`.
    pub fn of(key: &SamplerKey, tex: &TextureRef<'_>) -> SamplerStatics {
        let pot = sample::pot(tex, key.target);
        let repeats = |a: usize| key.wrap[a] == Wrap::Repeat && pot[a];
        let lod = lod::LodState::new(key, tex);
        SamplerStatics {
            pot: [repeats(0), repeats(1)],
            min_max_equal: lod.min_max_equal,
            apply_min: lod.apply_min,
            apply_max: lod.apply_max,
            bias_non_zero: lod.bias != 0.0,
            float_depth: key.format == TexelFormat::Depth32F && key.compare.is_some() && tex.float_depth,
            depth_units: key.format == TexelFormat::Depth32F
                && key.target != TexTarget::Cube
                && tex
                    .images
                    .get(tex.base_level as usize)
                    .and_then(|i| i.units)
                    .is_some_and(|u| u.unorm24),
        }
    }

    /// λ's integer part comes from ρ's exponent alone: no bias, no clamp, no
    /// fraction (`lod::select`'s shortcut).
    pub fn exponent_only(&self, mip: MipFilter) -> bool {
        !self.bias_non_zero && !self.apply_min && !self.apply_max && mip != MipFilter::Linear
    }
}

/// `units` with the statics of the textures of `set` ([`SamplerKey::with_statics`];
/// a unit without a texture keeps its key).
pub fn with_statics(units: &[Option<TexUnitKey>; MAX_UNITS], set: &TextureSet<'_>) -> [Option<TexUnitKey>; MAX_UNITS] {
    std::array::from_fn(|u| {
        units[u].map(|unit| match &set.units[u] {
            Some(tex) => TexUnitKey {
                sampler: unit.sampler.with_statics(tex),
                ..unit
            },
            None => unit,
        })
    })
}

impl SamplerKey {
    /// This key with the statics of `tex` where the native sampler uses
    /// them (2D and rectangle RGBA8 REPEAT/CLAMP_TO_EDGE, 2D depth NEAREST:
    /// `crate::compile::native_unit`),
    /// the default elsewhere (so that those keys do not multiply).
    pub fn with_statics(self, tex: &TextureRef<'_>) -> SamplerKey {
        let statics = if crate::compile::native_sampler(&self) {
            SamplerStatics::of(&self, tex)
        } else {
            SamplerStatics::default()
        };
        SamplerKey { statics, ..self }
    }
}

/// A combine function (`GL_COMBINE_RGB`, `GL_COMBINE_ALPHA`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CombineFn {
    Replace,
    Modulate,
    Add,
    AddSigned,
    Interpolate,
    Subtract,
    Dot3Rgb,
    Dot3Rgba,
}

/// A combine source (`GL_SOURCEn_RGB`, `GL_SOURCEn_ALPHA`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CombineSrc {
    /// This unit's texture.
    Texture,
    /// Unit `n`'s texture (`GL_TEXTUREn`, ARB_texture_env_crossbar).
    TextureUnit(u8),
    /// `GL_TEXTURE_ENV_COLOR`.
    Constant,
    /// The interpolated primary colour.
    PrimaryColor,
    /// The previous unit's result (the primary colour for unit 0).
    Previous,
}

/// A combine operand (`GL_OPERANDn_RGB`, `GL_OPERANDn_ALPHA`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Operand {
    SrcColor,
    OneMinusSrcColor,
    SrcAlpha,
    OneMinusSrcAlpha,
}

/// The texture environment as a combine (legacy modes are translated per
/// base format by [`effective_combine`], as Mesa's `texstate.c` does).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct CombineKey {
    pub rgb: CombineFn,
    pub alpha: CombineFn,
    pub src_rgb: [CombineSrc; 3],
    pub op_rgb: [Operand; 3],
    pub src_alpha: [CombineSrc; 3],
    /// `SrcAlpha` or `OneMinusSrcAlpha` only.
    pub op_alpha: [Operand; 3],
    /// 1, 2 or 4.
    pub scale_rgb: u8,
    /// 1, 2 or 4.
    pub scale_alpha: u8,
}

impl CombineKey {
    /// GL's initial combine state (and Mesa's `default_combine_state`):
    /// MODULATE of texture and previous, third source the constant colour.
    pub const DEFAULT: CombineKey = CombineKey {
        rgb: CombineFn::Modulate,
        alpha: CombineFn::Modulate,
        src_rgb: [CombineSrc::Texture, CombineSrc::Previous, CombineSrc::Constant],
        op_rgb: [Operand::SrcColor, Operand::SrcColor, Operand::SrcAlpha],
        src_alpha: [CombineSrc::Texture, CombineSrc::Previous, CombineSrc::Constant],
        op_alpha: [Operand::SrcAlpha, Operand::SrcAlpha, Operand::SrcAlpha],
        scale_rgb: 1,
        scale_alpha: 1,
    };
}

impl Default for CombineKey {
    fn default() -> CombineKey {
        CombineKey::DEFAULT
    }
}

/// `glTexEnv` `GL_TEXTURE_ENV_MODE`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum EnvMode {
    Modulate,
    Replace,
    Decal,
    Blend,
    Add,
    Combine,
}

/// The combine a legacy mode makes of a texture of base format `base`, as
/// Mesa's `calculate_derived_texenv` (`texstate.c`) builds it: sources and
/// operands from [`CombineKey::DEFAULT`], changed per format and mode, and a
/// function whose first source is `Previous` becomes `Replace` (which passes
/// the previous colour through). `Combine` returns `combine` unchanged. For
/// depth textures pass `DepthMode::base()` (Mesa substitutes
/// `GL_DEPTH_TEXTURE_MODE`); `Depth` itself is taken as its default, luminance.
pub fn effective_combine(mode: EnvMode, base: BaseFormat, combine: CombineKey) -> CombineKey {
    use BaseFormat as B;
    use CombineFn as F;
    use CombineSrc as S;
    let base = if base == B::Depth { B::Luminance } else { base };
    let mut k = CombineKey::DEFAULT;
    match base {
        B::Alpha => k.src_rgb[0] = S::Previous,
        B::Luminance | B::Rgb => k.src_alpha[0] = S::Previous,
        B::LuminanceAlpha | B::Intensity | B::Rgba | B::Depth => {}
    }
    let (rgb, alpha) = match mode {
        EnvMode::Combine => return combine,
        EnvMode::Replace | EnvMode::Modulate => {
            let f = if mode == EnvMode::Replace {
                F::Replace
            } else {
                F::Modulate
            };
            (if base == B::Alpha { F::Replace } else { f }, f)
        }
        EnvMode::Decal => {
            k.src_alpha[0] = S::Previous;
            let mut rgb = F::Interpolate;
            match base {
                B::Alpha | B::Luminance | B::LuminanceAlpha | B::Intensity => k.src_rgb[0] = S::Previous,
                B::Rgb => rgb = F::Replace,
                B::Rgba => k.src_rgb[2] = S::Texture,
                B::Depth => {}
            }
            (rgb, F::Replace)
        }
        EnvMode::Blend => {
            let mut alpha = F::Modulate;
            if base == B::Alpha {
                (F::Replace, alpha)
            } else {
                if base == B::Intensity {
                    alpha = F::Interpolate;
                    k.src_alpha[0] = S::Constant;
                    k.op_alpha[2] = Operand::SrcAlpha;
                }
                k.src_rgb[2] = S::Texture;
                k.src_alpha[2] = S::Texture;
                k.src_rgb[0] = S::Constant;
                k.op_rgb[2] = Operand::SrcColor;
                (F::Interpolate, alpha)
            }
        }
        EnvMode::Add => (
            if base == B::Alpha { F::Replace } else { F::Add },
            if base == B::Intensity { F::Add } else { F::Modulate },
        ),
    };
    k.rgb = if k.src_rgb[0] != S::Previous { rgb } else { F::Replace };
    k.alpha = if k.src_alpha[0] != S::Previous {
        alpha
    } else {
        F::Replace
    };
    k
}

/// Mesa's `util_quantize_lod_bias` of a `GL_TEXTURE_LOD_BIAS`: clamped to
/// ±16 and rounded to 1/256 (`roundf`, half away from zero). The object's
/// and the unit's biases are each quantized, then summed
/// (`st_convert_sampler`): that sum is [`TextureRef::lod_bias`].
pub fn quantized_lod_bias(bias: f32) -> f32 {
    (bias.clamp(-16.0, 16.0) * 256.0).round() / 256.0
}

/// One enabled, complete unit as the key sees it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct TexUnitKey {
    pub sampler: SamplerKey,
    pub base: BaseFormat,
    pub env: CombineKey,
}

/// One mip level (one face of one level for cube maps); texels tightly
/// packed in [`TexelFormat`], rows bottom-up as GL uploads them.
#[derive(Clone, Copy, Debug)]
pub struct Image<'a> {
    pub texels: &'a [u8],
    /// A `Depth32F` image's texels as the depth test's units, when a
    /// framebuffer object rendered into it: they are the texels then
    /// (`texels` is stale).
    pub units: Option<DepthUnits<'a>>,
    pub width: u32,
    pub height: u32,
    pub depth: u32,
}

/// The depth texels of an image a framebuffer object rendered into, kept
/// in the depth test's units rather than written back as `Depth32F`
/// texels (`softgl::fbo`: the write-back was 64 MiB read and 64 MiB
/// written per pass into a 4096² shadow map, ~4.4 ms, two a MuJoCo
/// frame). Texel `i` is [`DepthUnits::texel`] of `z[i]`, what the
/// write-back would have stored.
#[derive(Clone, Copy, Debug)]
pub struct DepthUnits<'a> {
    pub z: &'a [u32],
    /// 24-bit unorm units, else float depth (`f32` bits).
    pub unorm24: bool,
}

/// `f32(1 / (2^24 − 1))`: a 24-bit unit's step as the sampler reads it.
pub const UNORM24_SCALE: f32 = (1.0 / 16_777_215.0f64) as f32;

impl DepthUnits<'_> {
    /// The `Depth32F` texel of depth-test unit `z`: `z · f32(1/(2^24 − 1))`
    /// for 24-bit units (through i32, exact below 2^31: llvmpipe's
    /// `Z24` fetch), the stored float for float depth.
    #[inline(always)]
    pub fn texel(z: u32, unorm24: bool) -> f32 {
        if unorm24 {
            (z & 0x7fff_ffff) as i32 as f32 * UNORM24_SCALE
        } else {
            f32::from_bits(z)
        }
    }
}

impl Image<'_> {
    /// An image with no texels (levels outside the sampled range).
    pub const EMPTY: Image<'static> = Image {
        texels: &[],
        units: None,
        width: 0,
        height: 0,
        depth: 0,
    };
}

/// What a unit samples beyond its key: never part of the key, except for
/// the few facts of [`SamplerStatics`] (so a change of size or LOD range
/// compiles nothing unless it changes one of those).
#[derive(Clone, Copy, Debug)]
pub struct TextureRef<'a> {
    /// Level `l` (relative to level 0 of the object) at `images[l]`; cube
    /// maps: `images[l * 6 + face]` (faces +X, −X, +Y, −Y, +Z, −Z). Levels
    /// outside `base_level..=max_level` may be empty.
    pub images: &'a [Image<'a>],
    pub base_level: u32,
    /// Last level sampled: min(`GL_TEXTURE_MAX_LEVEL`, the last level of the complete chain).
    pub max_level: u32,
    pub min_lod: f32,
    pub max_lod: f32,
    /// `GL_TEXTURE_LOD_BIAS` of the object plus the unit's (`glTexEnv`
    /// `GL_TEXTURE_FILTER_CONTROL`), each through [`quantized_lod_bias`].
    pub lod_bias: f32,
    pub border: [f32; 4],
    /// A float depth texture (`GL_DEPTH_COMPONENT32F`, llvmpipe's `Z32_FLOAT`):
    /// neither the comparison's reference nor the border is clamped to [0, 1]
    /// (`lp_bld_sample_soa.c`: both clamps are for non-float channels).
    pub float_depth: bool,
}

/// Per draw: every unit's texture and `GL_TEXTURE_ENV_COLOR`. `Default`: no textures.
#[derive(Clone, Copy, Debug, Default)]
pub struct TextureSet<'a> {
    pub units: [Option<TextureRef<'a>>; MAX_UNITS],
    pub env_color: [[f32; 4]; MAX_UNITS],
}
