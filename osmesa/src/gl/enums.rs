//! GL enumerants to softgl's types; anything else is `GL_INVALID_ENUM`.

use crate::consts::GLenum;
use softgl::{
    BlendEquation, BlendFactor, Capability, CompareFunc, Face, FrontFace, GlError, GlResult, LogicOp, MatrixMode,
    PolygonMode, PrimitiveMode, ShadeModel, StencilOp,
};

pub fn primitive(v: GLenum) -> GlResult<PrimitiveMode> {
    Ok(match v {
        0 => PrimitiveMode::Points,
        1 => PrimitiveMode::Lines,
        2 => PrimitiveMode::LineLoop,
        3 => PrimitiveMode::LineStrip,
        4 => PrimitiveMode::Triangles,
        5 => PrimitiveMode::TriangleStrip,
        6 => PrimitiveMode::TriangleFan,
        7 => PrimitiveMode::Quads,
        8 => PrimitiveMode::QuadStrip,
        9 => PrimitiveMode::Polygon,
        _ => return Err(GlError::InvalidEnum),
    })
}

pub fn compare(v: GLenum) -> GlResult<CompareFunc> {
    Ok(match v {
        0x200 => CompareFunc::Never,
        0x201 => CompareFunc::Less,
        0x202 => CompareFunc::Equal,
        0x203 => CompareFunc::Lequal,
        0x204 => CompareFunc::Greater,
        0x205 => CompareFunc::Notequal,
        0x206 => CompareFunc::Gequal,
        0x207 => CompareFunc::Always,
        _ => return Err(GlError::InvalidEnum),
    })
}

pub fn compare_enum(f: CompareFunc) -> GLenum {
    match f {
        CompareFunc::Never => 0x200,
        CompareFunc::Less => 0x201,
        CompareFunc::Equal => 0x202,
        CompareFunc::Lequal => 0x203,
        CompareFunc::Greater => 0x204,
        CompareFunc::Notequal => 0x205,
        CompareFunc::Gequal => 0x206,
        CompareFunc::Always => 0x207,
    }
}

pub fn stencil_op(v: GLenum) -> GlResult<StencilOp> {
    Ok(match v {
        0x1E00 => StencilOp::Keep,
        0 => StencilOp::Zero,
        0x1E01 => StencilOp::Replace,
        0x1E02 => StencilOp::Incr,
        0x1E03 => StencilOp::Decr,
        0x150A => StencilOp::Invert,
        0x8507 => StencilOp::IncrWrap,
        0x8508 => StencilOp::DecrWrap,
        _ => return Err(GlError::InvalidEnum),
    })
}

pub fn stencil_op_enum(op: StencilOp) -> GLenum {
    match op {
        StencilOp::Keep => 0x1E00,
        StencilOp::Zero => 0,
        StencilOp::Replace => 0x1E01,
        StencilOp::Incr => 0x1E02,
        StencilOp::Decr => 0x1E03,
        StencilOp::Invert => 0x150A,
        StencilOp::IncrWrap => 0x8507,
        StencilOp::DecrWrap => 0x8508,
    }
}

pub fn blend_factor(v: GLenum) -> GlResult<BlendFactor> {
    Ok(match v {
        0 => BlendFactor::Zero,
        1 => BlendFactor::One,
        0x300 => BlendFactor::SrcColor,
        0x301 => BlendFactor::OneMinusSrcColor,
        0x302 => BlendFactor::SrcAlpha,
        0x303 => BlendFactor::OneMinusSrcAlpha,
        0x304 => BlendFactor::DstAlpha,
        0x305 => BlendFactor::OneMinusDstAlpha,
        0x306 => BlendFactor::DstColor,
        0x307 => BlendFactor::OneMinusDstColor,
        0x308 => BlendFactor::SrcAlphaSaturate,
        0x8001 => BlendFactor::ConstantColor,
        0x8002 => BlendFactor::OneMinusConstantColor,
        0x8003 => BlendFactor::ConstantAlpha,
        0x8004 => BlendFactor::OneMinusConstantAlpha,
        _ => return Err(GlError::InvalidEnum),
    })
}

pub fn blend_factor_enum(f: BlendFactor) -> GLenum {
    match f {
        BlendFactor::Zero => 0,
        BlendFactor::One => 1,
        BlendFactor::SrcColor => 0x300,
        BlendFactor::OneMinusSrcColor => 0x301,
        BlendFactor::SrcAlpha => 0x302,
        BlendFactor::OneMinusSrcAlpha => 0x303,
        BlendFactor::DstAlpha => 0x304,
        BlendFactor::OneMinusDstAlpha => 0x305,
        BlendFactor::DstColor => 0x306,
        BlendFactor::OneMinusDstColor => 0x307,
        BlendFactor::SrcAlphaSaturate => 0x308,
        BlendFactor::ConstantColor => 0x8001,
        BlendFactor::OneMinusConstantColor => 0x8002,
        BlendFactor::ConstantAlpha => 0x8003,
        BlendFactor::OneMinusConstantAlpha => 0x8004,
    }
}

pub fn blend_equation(v: GLenum) -> GlResult<BlendEquation> {
    Ok(match v {
        0x8006 => BlendEquation::Add,
        0x8007 => BlendEquation::Min,
        0x8008 => BlendEquation::Max,
        0x800A => BlendEquation::Subtract,
        0x800B => BlendEquation::ReverseSubtract,
        _ => return Err(GlError::InvalidEnum),
    })
}

pub fn blend_equation_enum(e: BlendEquation) -> GLenum {
    match e {
        BlendEquation::Add => 0x8006,
        BlendEquation::Min => 0x8007,
        BlendEquation::Max => 0x8008,
        BlendEquation::Subtract => 0x800A,
        BlendEquation::ReverseSubtract => 0x800B,
    }
}

pub fn logic_op(v: GLenum) -> GlResult<LogicOp> {
    v.checked_sub(0x1500)
        .and_then(|i| LogicOp::ALL.get(i as usize).copied())
        .ok_or(GlError::InvalidEnum)
}

pub fn logic_op_enum(op: LogicOp) -> GLenum {
    0x1500 + LogicOp::ALL.iter().position(|&o| o == op).unwrap_or(3) as GLenum
}

pub fn face(v: GLenum) -> GlResult<Face> {
    Ok(match v {
        0x404 => Face::Front,
        0x405 => Face::Back,
        0x408 => Face::FrontAndBack,
        _ => return Err(GlError::InvalidEnum),
    })
}

pub fn face_enum(f: Face) -> GLenum {
    match f {
        Face::Front => 0x404,
        Face::Back => 0x405,
        Face::FrontAndBack => 0x408,
    }
}

pub fn front_face(v: GLenum) -> GlResult<FrontFace> {
    Ok(match v {
        0x900 => FrontFace::Cw,
        0x901 => FrontFace::Ccw,
        _ => return Err(GlError::InvalidEnum),
    })
}

pub fn polygon_mode(v: GLenum) -> GlResult<PolygonMode> {
    Ok(match v {
        0x1B00 => PolygonMode::Point,
        0x1B01 => PolygonMode::Line,
        0x1B02 => PolygonMode::Fill,
        _ => return Err(GlError::InvalidEnum),
    })
}

pub fn polygon_mode_enum(m: PolygonMode) -> GLenum {
    match m {
        PolygonMode::Point => 0x1B00,
        PolygonMode::Line => 0x1B01,
        PolygonMode::Fill => 0x1B02,
    }
}

pub fn shade_model(v: GLenum) -> GlResult<ShadeModel> {
    Ok(match v {
        0x1D00 => ShadeModel::Flat,
        0x1D01 => ShadeModel::Smooth,
        _ => return Err(GlError::InvalidEnum),
    })
}

pub fn matrix_mode(v: GLenum) -> GlResult<MatrixMode> {
    Ok(match v {
        0x1700 => MatrixMode::Modelview,
        0x1701 => MatrixMode::Projection,
        0x1702 => MatrixMode::Texture,
        _ => return Err(GlError::InvalidEnum),
    })
}

pub fn matrix_mode_enum(m: MatrixMode) -> GLenum {
    match m {
        MatrixMode::Modelview => 0x1700,
        MatrixMode::Projection => 0x1701,
        MatrixMode::Texture => 0x1702,
    }
}

/// What `glEnable`/`glDisable` can name.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Cap {
    /// A capability softgl implements.
    Core(Capability),
    /// Accepted and stored; without effect until lighting lands.
    Inert(GLenum),
    /// A valid GL 1.x capability softgl does not implement yet.
    Missing,
}

pub const CORE_CAPS: [(GLenum, Capability); 11] = [
    (0x0BC0, Capability::AlphaTest),
    (0x0BE2, Capability::Blend),
    (0x0BF2, Capability::ColorLogicOp),
    (0x0B44, Capability::CullFace),
    (0x0B71, Capability::DepthTest),
    (0x0BD0, Capability::Dither),
    (0x8037, Capability::PolygonOffsetFill),
    (0x2A02, Capability::PolygonOffsetLine),
    (0x2A01, Capability::PolygonOffsetPoint),
    (0x0C11, Capability::ScissorTest),
    (0x0B90, Capability::StencilTest),
];

pub fn cap(v: GLenum) -> GlResult<Cap> {
    if let Some(&(_, c)) = CORE_CAPS.iter().find(|(e, _)| *e == v) {
        return Ok(Cap::Core(c));
    }
    match v {
        // NORMALIZE, RESCALE_NORMAL, COLOR_MATERIAL, AUTO_NORMAL
        0x0BA1 | 0x803A | 0x0B57 | 0x0D80 => Ok(Cap::Inert(v)),
        // LIGHTING, LIGHT0..7, TEXTURE_1D/2D/3D, FOG, LINE/POLYGON_STIPPLE,
        // POINT/LINE/POLYGON_SMOOTH, CLIP_PLANE0..5, TEXTURE_GEN_S..Q,
        // MAP1_*, MAP2_*, INDEX_LOGIC_OP
        0x0B50
        | 0x4000..=0x4007
        | 0x0DE0
        | 0x0DE1
        | 0x806F
        | 0x0B60
        | 0x0B24
        | 0x0B42
        | 0x0B10
        | 0x0B20
        | 0x0B41
        | 0x3000..=0x3005
        | 0x0C60..=0x0C63
        | 0x0D90..=0x0D98
        | 0x0DB0..=0x0DB8
        | 0x0BF1 => Ok(Cap::Missing),
        _ => Err(GlError::InvalidEnum),
    }
}
