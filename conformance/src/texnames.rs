//! The texturing names of issue 12's contract (`/work/issue12-contract.md`):
//! softgl's (store's) texture objects and uploads, re-exported; the texture
//! unit names (pipe's `TexEnvParam`, `TexCoordName`, `TexGenMode`,
//! `TexGenParam`) standing in until pipe's branch is merged, when they become
//! re-exports too. GL values: softgl's [`softgl::GlEnum`] where it has them,
//! [`ToGl`] for the rest.

pub use softgl::{
    CombineFn, CombineSrc, DepthMode, EnvMode, Filter, InternalFormat, MipFilter, Operand, PixelFormat, PixelType,
    TexImageTarget, TexParam, TextureTarget, Wrap,
};

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
            TexCapability::Texture(t) => softgl::GlEnum::to_gl(t),
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
