//! The texturing names of issue 12's contract (`/work/issue12-contract.md`),
//! standing in until softgl's texture API (branches `store`, `pipe`) is
//! merged: then this file becomes one `pub use softgl::{...}` line and the
//! scenes do not change. Each type's GL value is in [`ToGl`].

/// `GL_TEXTURE_1D`, `_2D`, `_3D`, `_CUBE_MAP`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TextureTarget {
    D1,
    D2,
    D3,
    Cube,
}

/// Where an image goes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TexImageTarget {
    D1,
    D2,
    D3,
    /// 0..6: +X −X +Y −Y +Z −Z.
    CubeFace(u8),
    Proxy(TextureTarget),
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum InternalFormat {
    Alpha,
    Luminance,
    LuminanceAlpha,
    Intensity,
    Rgb,
    Rgba,
    DepthComponent,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PixelFormat {
    Rgba,
    Rgb,
    Luminance,
    LuminanceAlpha,
    Alpha,
    DepthComponent,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PixelType {
    UnsignedByte,
    Float,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Filter {
    Nearest,
    Linear,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum MipFilter {
    None,
    Nearest,
    Linear,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Wrap {
    Repeat,
    Clamp,
    ClampToEdge,
    ClampToBorder,
    MirroredRepeat,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum DepthMode {
    Luminance,
    Intensity,
    Alpha,
}

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
    CompareMode(bool),
    CompareFunc(softgl::CompareFunc),
    DepthMode(DepthMode),
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum EnvMode {
    Modulate,
    Replace,
    Decal,
    Blend,
    Add,
    Combine,
}

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

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CombineSrc {
    Texture,
    TextureUnit(u8),
    Constant,
    PrimaryColor,
    Previous,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Operand {
    SrcColor,
    OneMinusSrcColor,
    SrcAlpha,
    OneMinusSrcAlpha,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TexEnvParam {
    Mode(EnvMode),
    Color([f32; 4]),
    CombineRgb(CombineFn),
    CombineAlpha(CombineFn),
    SrcRgb(u8, CombineSrc),
    SrcAlpha(u8, CombineSrc),
    OperandRgb(u8, Operand),
    OperandAlpha(u8, Operand),
    RgbScale(f32),
    AlphaScale(f32),
    LodBias(f32),
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TexCoordName {
    S,
    T,
    R,
    Q,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TexGenMode {
    ObjectLinear,
    EyeLinear,
    SphereMap,
    NormalMap,
    ReflectionMap,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TexGenParam {
    Mode(TexGenMode),
    ObjectPlane([f32; 4]),
    EyePlane([f32; 4]),
}

/// `glEnable` of the texturing capabilities (`Capability::Texture`,
/// `Capability::TexGen` once softgl has them).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TexCapability {
    Texture(TextureTarget),
    TexGen(TexCoordName),
}

/// The GL value of a name (`softgl::GlEnum::to_gl` once softgl has them).
pub trait ToGl {
    fn to_gl(self) -> u32;
}

impl ToGl for TextureTarget {
    fn to_gl(self) -> u32 {
        match self {
            TextureTarget::D1 => 0x0DE0,
            TextureTarget::D2 => 0x0DE1,
            TextureTarget::D3 => 0x806F,
            TextureTarget::Cube => 0x8513,
        }
    }
}

impl ToGl for TexImageTarget {
    fn to_gl(self) -> u32 {
        match self {
            TexImageTarget::D1 => 0x0DE0,
            TexImageTarget::D2 => 0x0DE1,
            TexImageTarget::D3 => 0x806F,
            TexImageTarget::CubeFace(f) => 0x8515 + u32::from(f),
            TexImageTarget::Proxy(TextureTarget::D1) => 0x8063,
            TexImageTarget::Proxy(TextureTarget::D2) => 0x8064,
            TexImageTarget::Proxy(TextureTarget::D3) => 0x8070,
            TexImageTarget::Proxy(TextureTarget::Cube) => 0x851B,
        }
    }
}

impl ToGl for InternalFormat {
    fn to_gl(self) -> u32 {
        match self {
            InternalFormat::Alpha => 0x1906,
            InternalFormat::Luminance => 0x1909,
            InternalFormat::LuminanceAlpha => 0x190A,
            InternalFormat::Intensity => 0x8049,
            InternalFormat::Rgb => 0x1907,
            InternalFormat::Rgba => 0x1908,
            InternalFormat::DepthComponent => 0x1902,
        }
    }
}

impl ToGl for PixelFormat {
    fn to_gl(self) -> u32 {
        match self {
            PixelFormat::Rgba => 0x1908,
            PixelFormat::Rgb => 0x1907,
            PixelFormat::Luminance => 0x1909,
            PixelFormat::LuminanceAlpha => 0x190A,
            PixelFormat::Alpha => 0x1906,
            PixelFormat::DepthComponent => 0x1902,
        }
    }
}

impl ToGl for PixelType {
    fn to_gl(self) -> u32 {
        match self {
            PixelType::UnsignedByte => 0x1401,
            PixelType::Float => 0x1406,
        }
    }
}

impl ToGl for Wrap {
    fn to_gl(self) -> u32 {
        match self {
            Wrap::Repeat => 0x2901,
            Wrap::Clamp => 0x2900,
            Wrap::ClampToEdge => 0x812F,
            Wrap::ClampToBorder => 0x812D,
            Wrap::MirroredRepeat => 0x8370,
        }
    }
}

impl ToGl for DepthMode {
    fn to_gl(self) -> u32 {
        match self {
            DepthMode::Luminance => 0x1909,
            DepthMode::Intensity => 0x8049,
            DepthMode::Alpha => 0x1906,
        }
    }
}

impl ToGl for EnvMode {
    fn to_gl(self) -> u32 {
        match self {
            EnvMode::Modulate => 0x2100,
            EnvMode::Replace => 0x1E01,
            EnvMode::Decal => 0x2101,
            EnvMode::Blend => 0x0BE2,
            EnvMode::Add => 0x0104,
            EnvMode::Combine => 0x8570,
        }
    }
}

impl ToGl for CombineFn {
    fn to_gl(self) -> u32 {
        match self {
            CombineFn::Replace => 0x1E01,
            CombineFn::Modulate => 0x2100,
            CombineFn::Add => 0x0104,
            CombineFn::AddSigned => 0x8574,
            CombineFn::Interpolate => 0x8575,
            CombineFn::Subtract => 0x84E7,
            CombineFn::Dot3Rgb => 0x86AE,
            CombineFn::Dot3Rgba => 0x86AF,
        }
    }
}

impl ToGl for CombineSrc {
    fn to_gl(self) -> u32 {
        match self {
            CombineSrc::Texture => 0x1702,
            CombineSrc::TextureUnit(u) => 0x84C0 + u32::from(u),
            CombineSrc::Constant => 0x8576,
            CombineSrc::PrimaryColor => 0x8577,
            CombineSrc::Previous => 0x8578,
        }
    }
}

impl ToGl for Operand {
    fn to_gl(self) -> u32 {
        match self {
            Operand::SrcColor => 0x0300,
            Operand::OneMinusSrcColor => 0x0301,
            Operand::SrcAlpha => 0x0302,
            Operand::OneMinusSrcAlpha => 0x0303,
        }
    }
}

impl ToGl for TexCoordName {
    fn to_gl(self) -> u32 {
        match self {
            TexCoordName::S => 0x2000,
            TexCoordName::T => 0x2001,
            TexCoordName::R => 0x2002,
            TexCoordName::Q => 0x2003,
        }
    }
}

impl ToGl for TexGenMode {
    fn to_gl(self) -> u32 {
        match self {
            TexGenMode::ObjectLinear => 0x2401,
            TexGenMode::EyeLinear => 0x2400,
            TexGenMode::SphereMap => 0x2402,
            TexGenMode::NormalMap => 0x8511,
            TexGenMode::ReflectionMap => 0x8512,
        }
    }
}

impl ToGl for TexCapability {
    fn to_gl(self) -> u32 {
        match self {
            TexCapability::Texture(t) => t.to_gl(),
            // GL_TEXTURE_GEN_S..Q
            TexCapability::TexGen(c) => 0x0C60 + c.to_gl() - 0x2000,
        }
    }
}

/// `GL_TEXTURE_MIN_FILTER`'s value for a (filter, mipmap filter) pair.
pub fn min_filter_gl(f: Filter, m: MipFilter) -> u32 {
    match (f, m) {
        (Filter::Nearest, MipFilter::None) => 0x2600,
        (Filter::Linear, MipFilter::None) => 0x2601,
        (Filter::Nearest, MipFilter::Nearest) => 0x2700,
        (Filter::Linear, MipFilter::Nearest) => 0x2701,
        (Filter::Nearest, MipFilter::Linear) => 0x2702,
        (Filter::Linear, MipFilter::Linear) => 0x2703,
    }
}

/// `GL_TEXTURE_MAG_FILTER`'s value.
pub fn mag_filter_gl(f: Filter) -> u32 {
    min_filter_gl(f, MipFilter::None)
}
