//! Textures: objects and their bindings per unit ([`store`]), images and
//! completeness ([`object`]), formats and their llvmpipe storage
//! ([`format`]), pixel transfer ([`unpack`]), mipmap generation
//! ([`mipmap`]) and the `Context` calls ([`api`]); texture units (enables,
//! environment, coordinate generation, matrices: [`unit`]) and the texture
//! coordinates of the vertex stage ([`texgen`]).
//!
//! Texels are converted once, at upload, to the precision Mesa 22.3.6 stores
//! on llvmpipe and laid out in a [`TexelFormat`] the sampler reads fast
//! (RGBA expanded); the draw asks [`TextureStore::sampling`] for a unit's key
//! parts and texel views.

pub mod api;
pub mod format;
pub mod index;
pub mod mipmap;
pub mod object;
pub mod store;
pub mod texgen;
pub mod unit;
pub mod unpack;

pub(crate) use softgl_jit::texture as jit;

pub use api::{check_format_type, MAX_3D_TEXTURE_SIZE, MAX_TEXTURE_SIZE};
pub use format::{InternalFormat, PixelFormat, PixelType, Storage};
pub use jit::{
    BaseFormat, CombineFn, CombineSrc, DepthMode, EnvMode, Filter, MipFilter, Operand, TexTarget as TextureTarget,
    TexelFormat, Wrap,
};
pub use object::{ImageUnits, SamplerState, TexImage, TextureObject};
pub use store::{Sampling, TextureStore};

use softgl_jit::CompareFunc;

/// Where an image goes: a target's image, one cube face, or a proxy.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TexImageTarget {
    D1,
    D2,
    D3,
    /// 0..6: +X, −X, +Y, −Y, +Z, −Z.
    CubeFace(u8),
    /// `GL_TEXTURE_RECTANGLE_ARB` (level 0 only).
    Rect,
    Proxy(TextureTarget),
}

impl TexImageTarget {
    /// The texture target the image belongs to.
    pub fn texture_target(self) -> TextureTarget {
        match self {
            TexImageTarget::D1 => TextureTarget::D1,
            TexImageTarget::D2 => TextureTarget::D2,
            TexImageTarget::D3 => TextureTarget::D3,
            TexImageTarget::CubeFace(_) => TextureTarget::Cube,
            TexImageTarget::Rect => TextureTarget::Rect,
            TexImageTarget::Proxy(t) => t,
        }
    }

    /// The image's face (0 except for cube faces).
    pub fn face(self) -> usize {
        match self {
            TexImageTarget::CubeFace(f) => usize::from(f),
            _ => 0,
        }
    }

    /// The GL enumerant (`GL_TEXTURE_2D`, `GL_TEXTURE_CUBE_MAP_POSITIVE_X + f`,
    /// `GL_PROXY_TEXTURE_2D`, …).
    pub fn to_gl(self) -> u32 {
        match self {
            TexImageTarget::D1 => 0x0DE0,
            TexImageTarget::D2 => 0x0DE1,
            TexImageTarget::D3 => 0x806F,
            TexImageTarget::CubeFace(f) => 0x8515 + u32::from(f),
            TexImageTarget::Proxy(TextureTarget::D1) => 0x8063,
            TexImageTarget::Proxy(TextureTarget::D2) => 0x8064,
            TexImageTarget::Proxy(TextureTarget::D3) => 0x8070,
            TexImageTarget::Proxy(TextureTarget::Cube) => 0x851B,
            TexImageTarget::Rect => 0x84F5,
            TexImageTarget::Proxy(TextureTarget::Rect) => 0x84F7,
        }
    }

    /// The target for a GL enumerant; `None` for any other value.
    pub fn from_gl(value: u32) -> Option<TexImageTarget> {
        Some(match value {
            0x0DE0 => TexImageTarget::D1,
            0x0DE1 => TexImageTarget::D2,
            0x806F => TexImageTarget::D3,
            0x8515..=0x851A => TexImageTarget::CubeFace((value - 0x8515) as u8),
            0x8063 => TexImageTarget::Proxy(TextureTarget::D1),
            0x8064 => TexImageTarget::Proxy(TextureTarget::D2),
            0x8070 => TexImageTarget::Proxy(TextureTarget::D3),
            0x851B => TexImageTarget::Proxy(TextureTarget::Cube),
            0x84F5 => TexImageTarget::Rect,
            0x84F7 => TexImageTarget::Proxy(TextureTarget::Rect),
            _ => return None,
        })
    }

    /// Dimensions of an image of this target (cube faces are 2D).
    pub fn dims(self) -> u32 {
        match self.texture_target() {
            TextureTarget::D1 => 1,
            TextureTarget::D2 | TextureTarget::Cube | TextureTarget::Rect => 2,
            TextureTarget::D3 => 3,
        }
    }
}

/// `glPixelStore` state for one direction (pack or unpack).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PixelStore {
    pub swap_bytes: bool,
    /// Bitmaps only: kept and queryable, without effect on textures.
    pub lsb_first: bool,
    pub row_length: i32,
    pub skip_rows: i32,
    pub skip_pixels: i32,
    /// 1, 2, 4 (the default) or 8.
    pub alignment: i32,
    pub image_height: i32,
    pub skip_images: i32,
}

impl PixelStore {
    /// GL's initial state: everything 0 or false, alignment 4.
    pub const DEFAULT: PixelStore = PixelStore {
        swap_bytes: false,
        lsb_first: false,
        row_length: 0,
        skip_rows: 0,
        skip_pixels: 0,
        alignment: 4,
        image_height: 0,
        skip_images: 0,
    };
}

impl Default for PixelStore {
    fn default() -> Self {
        PixelStore::DEFAULT
    }
}

/// Client pixels for an upload. `bytes` must hold the image as `store` lays
/// it out (else `InvalidOperation`, as Mesa says of a pixel buffer object too small).
#[derive(Clone, Copy, Debug)]
pub struct PixelData<'a> {
    pub format: PixelFormat,
    pub ty: PixelType,
    pub store: PixelStore,
    pub bytes: &'a [u8],
}

impl<'a> PixelData<'a> {
    /// Tightly packed `GL_RGBA`/`GL_UNSIGNED_BYTE` pixels, default unpack state.
    pub fn rgba8(bytes: &'a [u8]) -> PixelData<'a> {
        PixelData {
            format: PixelFormat::Rgba,
            ty: PixelType::UnsignedByte,
            store: PixelStore::DEFAULT,
            bytes,
        }
    }
}

/// A `glTexParameter` value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TexParam {
    MinFilter(Filter, MipFilter),
    MagFilter(Filter),
    WrapS(Wrap),
    WrapT(Wrap),
    WrapR(Wrap),
    BorderColor([f32; 4]),
    MinLod(f32),
    MaxLod(f32),
    BaseLevel(i32),
    MaxLevel(i32),
    LodBias(f32),
    /// Clamped to [0, 1] when set.
    Priority(f32),
    GenerateMipmap(bool),
    /// `GL_TEXTURE_COMPARE_MODE`: `true` is `GL_COMPARE_R_TO_TEXTURE`, `false` `GL_NONE`.
    CompareMode(bool),
    CompareFunc(CompareFunc),
    DepthMode(DepthMode),
    /// `GL_TEXTURE_RESIDENT`: query only (always true); setting it is `InvalidEnum`.
    Resident(bool),
}

impl TexParam {
    /// The parameter's name.
    pub fn name(&self) -> TexParamName {
        match self {
            TexParam::MinFilter(..) => TexParamName::MinFilter,
            TexParam::MagFilter(_) => TexParamName::MagFilter,
            TexParam::WrapS(_) => TexParamName::WrapS,
            TexParam::WrapT(_) => TexParamName::WrapT,
            TexParam::WrapR(_) => TexParamName::WrapR,
            TexParam::BorderColor(_) => TexParamName::BorderColor,
            TexParam::MinLod(_) => TexParamName::MinLod,
            TexParam::MaxLod(_) => TexParamName::MaxLod,
            TexParam::BaseLevel(_) => TexParamName::BaseLevel,
            TexParam::MaxLevel(_) => TexParamName::MaxLevel,
            TexParam::LodBias(_) => TexParamName::LodBias,
            TexParam::Priority(_) => TexParamName::Priority,
            TexParam::GenerateMipmap(_) => TexParamName::GenerateMipmap,
            TexParam::CompareMode(_) => TexParamName::CompareMode,
            TexParam::CompareFunc(_) => TexParamName::CompareFunc,
            TexParam::DepthMode(_) => TexParamName::DepthMode,
            TexParam::Resident(_) => TexParamName::Resident,
        }
    }
}

/// The name of a `glGetTexParameter` query.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TexParamName {
    MinFilter,
    MagFilter,
    WrapS,
    WrapT,
    WrapR,
    BorderColor,
    MinLod,
    MaxLod,
    BaseLevel,
    MaxLevel,
    LodBias,
    Priority,
    GenerateMipmap,
    CompareMode,
    CompareFunc,
    DepthMode,
    Resident,
}

/// The name of a `glGetTexLevelParameter` query.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TexLevelParamName {
    Width,
    Height,
    Depth,
    Border,
    InternalFormat,
    RedSize,
    GreenSize,
    BlueSize,
    AlphaSize,
    LuminanceSize,
    IntensitySize,
    DepthSize,
    /// `GL_TEXTURE_STENCIL_SIZE` (GL 3.0; Mesa answers it in any context, piglit's
    /// `sized-texture-format-channels` asks): 0, no texture has stencil.
    StencilSize,
    Compressed,
}

/// The GL enumerant of a minification filter.
pub fn min_filter_to_gl(filter: Filter, mip: MipFilter) -> u32 {
    match (filter, mip) {
        (Filter::Nearest, MipFilter::None) => 0x2600,
        (Filter::Linear, MipFilter::None) => 0x2601,
        (Filter::Nearest, MipFilter::Nearest) => 0x2700,
        (Filter::Linear, MipFilter::Nearest) => 0x2701,
        (Filter::Nearest, MipFilter::Linear) => 0x2702,
        (Filter::Linear, MipFilter::Linear) => 0x2703,
    }
}

/// The minification filter of a GL enumerant; `None` for any other value.
pub fn min_filter_from_gl(value: u32) -> Option<(Filter, MipFilter)> {
    Some(match value {
        0x2600 => (Filter::Nearest, MipFilter::None),
        0x2601 => (Filter::Linear, MipFilter::None),
        0x2700 => (Filter::Nearest, MipFilter::Nearest),
        0x2701 => (Filter::Linear, MipFilter::Nearest),
        0x2702 => (Filter::Nearest, MipFilter::Linear),
        0x2703 => (Filter::Linear, MipFilter::Linear),
        _ => return None,
    })
}

/// Levels a target can have (GL_MAX_TEXTURE_SIZE 4096, GL_MAX_3D_TEXTURE_SIZE 256,
/// GL_MAX_CUBE_MAP_TEXTURE_SIZE 4096; rectangle textures have level 0 only,
/// Mesa's `_mesa_max_texture_levels`).
pub fn max_levels(target: TextureTarget) -> usize {
    match target {
        TextureTarget::D3 => jit::MAX_3D_LEVELS,
        TextureTarget::Rect => 1,
        TextureTarget::D1 | TextureTarget::D2 | TextureTarget::Cube => jit::MAX_LEVELS,
    }
}

/// Faces a target has.
pub fn faces(target: TextureTarget) -> usize {
    if target == TextureTarget::Cube {
        6
    } else {
        1
    }
}
