//! The one GL-shaped interface: a scene is recorded once as a list of
//! [`Call`]s, and every back end replays that list its own way.

use softgl::{
    BlendEquation, BlendFactor, Capability, ClearMask, CompareFunc, Face, FrontFace, LogicOp, MatrixMode, PolygonMode,
    PrimitiveMode, ShadeModel, StencilOp,
};

/// One GL 1.x call, with GL's arguments.
#[derive(Clone, Debug, PartialEq)]
pub enum Call {
    Enable(Capability),
    Disable(Capability),
    ClearColor([f32; 4]),
    ClearDepth(f64),
    ClearStencil(i32),
    Clear(ClearMask),
    Viewport([i32; 4]),
    DepthRange(f64, f64),
    Scissor([i32; 4]),
    MatrixMode(MatrixMode),
    LoadIdentity,
    /// Column-major, as `glLoadMatrixf` takes it.
    LoadMatrix([f32; 16]),
    PushMatrix,
    PopMatrix,
    Translate([f32; 3]),
    Scale([f32; 3]),
    /// Degrees about an axis.
    Rotate(f32, [f32; 3]),
    Frustum([f64; 6]),
    Ortho([f64; 6]),
    ShadeModel(ShadeModel),
    FrontFace(FrontFace),
    CullFace(Face),
    PolygonMode(Face, PolygonMode),
    PolygonOffset(f32, f32),
    PointSize(f32),
    LineWidth(f32),
    AlphaFunc(CompareFunc, f32),
    StencilFunc(CompareFunc, i32, u32),
    StencilOp(StencilOp, StencilOp, StencilOp),
    StencilMask(u32),
    DepthFunc(CompareFunc),
    DepthMask(bool),
    BlendFunc(BlendFactor, BlendFactor),
    BlendFuncSeparate([BlendFactor; 4]),
    BlendEquation(BlendEquation),
    BlendColor([f32; 4]),
    LogicOp(LogicOp),
    ColorMask([bool; 4]),
    Begin(PrimitiveMode),
    End,
    Color([f32; 4]),
    Vertex([f32; 4]),
    /// `glDrawArrays` over client arrays of 4-component positions and colours.
    DrawArrays {
        mode: PrimitiveMode,
        positions: Vec<[f32; 4]>,
        colors: Vec<[f32; 4]>,
    },
}

/// Records calls; its methods read like the GL calls they stand for.
#[derive(Debug, Default)]
pub struct Rec {
    pub calls: Vec<Call>,
}

impl Rec {
    pub fn call(&mut self, c: Call) -> &mut Self {
        self.calls.push(c);
        self
    }
    pub fn enable(&mut self, c: Capability) -> &mut Self {
        self.call(Call::Enable(c))
    }
    pub fn disable(&mut self, c: Capability) -> &mut Self {
        self.call(Call::Disable(c))
    }
    pub fn clear_color(&mut self, r: f32, g: f32, b: f32, a: f32) -> &mut Self {
        self.call(Call::ClearColor([r, g, b, a]))
    }
    pub fn clear(&mut self, m: ClearMask) -> &mut Self {
        self.call(Call::Clear(m))
    }
    pub fn viewport(&mut self, x: i32, y: i32, w: i32, h: i32) -> &mut Self {
        self.call(Call::Viewport([x, y, w, h]))
    }
    pub fn scissor(&mut self, x: i32, y: i32, w: i32, h: i32) -> &mut Self {
        self.call(Call::Scissor([x, y, w, h]))
    }
    pub fn matrix_mode(&mut self, m: MatrixMode) -> &mut Self {
        self.call(Call::MatrixMode(m))
    }
    pub fn load_identity(&mut self) -> &mut Self {
        self.call(Call::LoadIdentity)
    }
    pub fn ortho(&mut self, l: f64, r: f64, b: f64, t: f64, n: f64, f: f64) -> &mut Self {
        self.call(Call::Ortho([l, r, b, t, n, f]))
    }
    pub fn frustum(&mut self, l: f64, r: f64, b: f64, t: f64, n: f64, f: f64) -> &mut Self {
        self.call(Call::Frustum([l, r, b, t, n, f]))
    }
    pub fn translate(&mut self, x: f32, y: f32, z: f32) -> &mut Self {
        self.call(Call::Translate([x, y, z]))
    }
    pub fn shade_model(&mut self, m: ShadeModel) -> &mut Self {
        self.call(Call::ShadeModel(m))
    }
    pub fn begin(&mut self, m: PrimitiveMode) -> &mut Self {
        self.call(Call::Begin(m))
    }
    pub fn end(&mut self) -> &mut Self {
        self.call(Call::End)
    }
    pub fn color(&mut self, r: f32, g: f32, b: f32, a: f32) -> &mut Self {
        self.call(Call::Color([r, g, b, a]))
    }
    pub fn vertex(&mut self, x: f32, y: f32, z: f32) -> &mut Self {
        self.call(Call::Vertex([x, y, z, 1.0]))
    }
    pub fn vertex4(&mut self, x: f32, y: f32, z: f32, w: f32) -> &mut Self {
        self.call(Call::Vertex([x, y, z, w]))
    }
    /// An axis-aligned quad as two triangles (no `GL_QUADS` diagonal question).
    pub fn rect(&mut self, x0: f32, y0: f32, x1: f32, y1: f32, z: f32) -> &mut Self {
        self.begin(PrimitiveMode::TriangleStrip)
            .vertex(x0, y0, z)
            .vertex(x1, y0, z)
            .vertex(x0, y1, z)
            .vertex(x1, y1, z)
            .end()
    }
    /// The colour a scene clears to first, if it sets one (for coverage).
    pub fn background(calls: &[Call]) -> [u8; 4] {
        calls
            .iter()
            .find_map(|c| match c {
                Call::ClearColor(c) => Some(c.map(|v| (v.clamp(0.0, 1.0) * 255.0).round() as u8)),
                _ => None,
            })
            .unwrap_or([0; 4])
    }
}

/// GL enum values, for the back ends that speak C GL.
pub mod gl_enum {
    use super::*;

    pub fn cap(c: Capability) -> u32 {
        match c {
            Capability::AlphaTest => 0x0BC0,
            Capability::Blend => 0x0BE2,
            Capability::ColorLogicOp => 0x0BF2,
            Capability::CullFace => 0x0B44,
            Capability::DepthTest => 0x0B71,
            Capability::Dither => 0x0BD0,
            Capability::PolygonOffsetFill => 0x8037,
            Capability::PolygonOffsetLine => 0x2A02,
            Capability::PolygonOffsetPoint => 0x2A01,
            Capability::ScissorTest => 0x0C11,
            Capability::StencilTest => 0x0B90,
        }
    }
    pub fn mode(m: PrimitiveMode) -> u32 {
        match m {
            PrimitiveMode::Points => 0,
            PrimitiveMode::Lines => 1,
            PrimitiveMode::LineLoop => 2,
            PrimitiveMode::LineStrip => 3,
            PrimitiveMode::Triangles => 4,
            PrimitiveMode::TriangleStrip => 5,
            PrimitiveMode::TriangleFan => 6,
            PrimitiveMode::Quads => 7,
            PrimitiveMode::QuadStrip => 8,
            PrimitiveMode::Polygon => 9,
        }
    }
    pub fn func(f: CompareFunc) -> u32 {
        0x0200
            + match f {
                CompareFunc::Never => 0,
                CompareFunc::Less => 1,
                CompareFunc::Equal => 2,
                CompareFunc::Lequal => 3,
                CompareFunc::Greater => 4,
                CompareFunc::Notequal => 5,
                CompareFunc::Gequal => 6,
                CompareFunc::Always => 7,
            }
    }
    pub fn stencil_op(o: StencilOp) -> u32 {
        match o {
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
    pub fn factor(f: BlendFactor) -> u32 {
        match f {
            BlendFactor::Zero => 0,
            BlendFactor::One => 1,
            BlendFactor::SrcColor => 0x0300,
            BlendFactor::OneMinusSrcColor => 0x0301,
            BlendFactor::SrcAlpha => 0x0302,
            BlendFactor::OneMinusSrcAlpha => 0x0303,
            BlendFactor::DstAlpha => 0x0304,
            BlendFactor::OneMinusDstAlpha => 0x0305,
            BlendFactor::DstColor => 0x0306,
            BlendFactor::OneMinusDstColor => 0x0307,
            BlendFactor::SrcAlphaSaturate => 0x0308,
            BlendFactor::ConstantColor => 0x8001,
            BlendFactor::OneMinusConstantColor => 0x8002,
            BlendFactor::ConstantAlpha => 0x8003,
            BlendFactor::OneMinusConstantAlpha => 0x8004,
        }
    }
    pub fn equation(e: BlendEquation) -> u32 {
        match e {
            BlendEquation::Add => 0x8006,
            BlendEquation::Subtract => 0x800A,
            BlendEquation::ReverseSubtract => 0x800B,
            BlendEquation::Min => 0x8007,
            BlendEquation::Max => 0x8008,
        }
    }
    pub fn logic_op(o: LogicOp) -> u32 {
        0x1500
            + match o {
                LogicOp::Clear => 0,
                LogicOp::And => 1,
                LogicOp::AndReverse => 2,
                LogicOp::Copy => 3,
                LogicOp::AndInverted => 4,
                LogicOp::Noop => 5,
                LogicOp::Xor => 6,
                LogicOp::Or => 7,
                LogicOp::Nor => 8,
                LogicOp::Equiv => 9,
                LogicOp::Invert => 10,
                LogicOp::OrReverse => 11,
                LogicOp::CopyInverted => 12,
                LogicOp::OrInverted => 13,
                LogicOp::Nand => 14,
                LogicOp::Set => 15,
            }
    }
    pub fn face(f: Face) -> u32 {
        match f {
            Face::Front => 0x0404,
            Face::Back => 0x0405,
            Face::FrontAndBack => 0x0408,
        }
    }
    pub fn front_face(f: FrontFace) -> u32 {
        match f {
            FrontFace::Cw => 0x0900,
            FrontFace::Ccw => 0x0901,
        }
    }
    pub fn polygon_mode(m: PolygonMode) -> u32 {
        match m {
            PolygonMode::Point => 0x1B00,
            PolygonMode::Line => 0x1B01,
            PolygonMode::Fill => 0x1B02,
        }
    }
    pub fn shade_model(m: ShadeModel) -> u32 {
        match m {
            ShadeModel::Flat => 0x1D00,
            ShadeModel::Smooth => 0x1D01,
        }
    }
    pub fn matrix_mode(m: MatrixMode) -> u32 {
        match m {
            MatrixMode::Modelview => 0x1700,
            MatrixMode::Projection => 0x1701,
            MatrixMode::Texture => 0x1702,
        }
    }
    pub fn clear_mask(m: ClearMask) -> u32 {
        (if m.color { 0x4000 } else { 0 }) | (if m.depth { 0x100 } else { 0 }) | (if m.stencil { 0x400 } else { 0 })
    }
}
