//! lavapipe (Mesa's Vulkan on the CPU, Debian's `mesa-vulkan-drivers`)
//! through `ash`, for the scenes Vulkan can express: filled triangles (all
//! triangle modes, flat and smooth), depth, stencil, blending, logic ops,
//! scissor, colour masks, polygon offset as depth bias, and the alpha test as
//! a `discard` in the fragment shader. Points, lines, polygon modes other
//! than fill and masked clears are reported as unsupported.
//!
//! GL's vertex work (matrices, primitive assembly, flat colours, colour
//! clamping) is done here on the CPU; Vulkan gets GL's clip-space triangles
//! with z mapped from GL's [-w, w] to Vulkan's [0, w], and renders GL's window
//! row y into its framebuffer row y (so Vulkan's top-left fill rule is GL's
//! bottom-left, as llvmpipe has it); the image is flipped on read-back.
//! Shaders are WGSL compiled to SPIR-V by naga.

use super::{median, Outcome, Timing};
use crate::call::Call;
use crate::scenes::Recording;
use ash::vk;
use glam::{Mat4, Vec3, Vec4};
use softgl::{
    BlendEquation, BlendFactor, Capability, CompareFunc, Face, FrontFace, LogicOp, MatrixMode, PolygonMode,
    PrimitiveMode, ShadeModel, StencilOp,
};
use std::collections::HashMap;
use std::time::Instant;

/// The pipeline state one draw needs (everything but viewport and scissor).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
struct PipeKey {
    depth_test: bool,
    depth_write: bool,
    depth_func: CompareFunc,
    stencil_test: bool,
    stencil_func: CompareFunc,
    stencil_ref: u32,
    stencil_value_mask: u32,
    stencil_write_mask: u32,
    stencil_ops: [StencilOp; 3],
    blend: bool,
    blend_factors: [BlendFactor; 4],
    blend_equations: [BlendEquation; 2],
    blend_color: [u32; 4],
    logic_op: Option<LogicOp>,
    color_mask: [bool; 4],
    cull: Option<Face>,
    front_ccw: bool,
    offset: Option<(u32, u32)>,
    alpha: Option<(CompareFunc, u32)>,
    flat: bool,
}

#[derive(Clone, Copy, Debug)]
enum Op {
    Clear {
        rect: vk::Rect2D,
        color: Option<[f32; 4]>,
        depth: Option<f32>,
        stencil: Option<u32>,
    },
    Draw {
        key: PipeKey,
        viewport: vk::Viewport,
        scissor: vk::Rect2D,
        first: u32,
        count: u32,
    },
}

#[repr(C)]
#[derive(Clone, Copy, Debug)]
struct Vertex {
    pos: [f32; 4],
    color: [f32; 4],
}

/// GL's state, as far as the scenes use it, tracked on the CPU.
struct GlState {
    w: u32,
    h: u32,
    caps: HashMap<Capability, bool>,
    clear_color: [f32; 4],
    clear_depth: f64,
    clear_stencil: i32,
    viewport: [i32; 4],
    depth_range: (f64, f64),
    scissor: [i32; 4],
    mode: MatrixMode,
    modelview: Vec<Mat4>,
    projection: Vec<Mat4>,
    shade: ShadeModel,
    front: FrontFace,
    cull_face: Face,
    polygon_mode: [PolygonMode; 2],
    offset: (f32, f32),
    alpha: (CompareFunc, f32),
    stencil: (CompareFunc, i32, u32),
    stencil_ops: [StencilOp; 3],
    stencil_mask: u32,
    depth_func: CompareFunc,
    depth_mask: bool,
    blend_factors: [BlendFactor; 4],
    blend_equation: BlendEquation,
    blend_color: [f32; 4],
    logic_op: LogicOp,
    color_mask: [bool; 4],
    color: [f32; 4],
    begun: Option<PrimitiveMode>,
    batch: Vec<([f32; 4], [f32; 4])>,
}

/// The frame as Vulkan work: ops over one vertex buffer.
struct Plan {
    ops: Vec<Op>,
    vertices: Vec<Vertex>,
}

impl GlState {
    fn new(w: u32, h: u32) -> GlState {
        GlState {
            w,
            h,
            caps: HashMap::new(),
            clear_color: [0.0; 4],
            clear_depth: 1.0,
            clear_stencil: 0,
            viewport: [0, 0, w as i32, h as i32],
            depth_range: (0.0, 1.0),
            scissor: [0, 0, w as i32, h as i32],
            mode: MatrixMode::Modelview,
            modelview: vec![Mat4::IDENTITY],
            projection: vec![Mat4::IDENTITY],
            shade: ShadeModel::Smooth,
            front: FrontFace::Ccw,
            cull_face: Face::Back,
            polygon_mode: [PolygonMode::Fill; 2],
            offset: (0.0, 0.0),
            alpha: (CompareFunc::Always, 0.0),
            stencil: (CompareFunc::Always, 0, 0xff),
            stencil_ops: [StencilOp::Keep; 3],
            stencil_mask: 0xff,
            depth_func: CompareFunc::Less,
            depth_mask: true,
            blend_factors: [BlendFactor::One, BlendFactor::Zero, BlendFactor::One, BlendFactor::Zero],
            blend_equation: BlendEquation::Add,
            blend_color: [0.0; 4],
            logic_op: LogicOp::Copy,
            color_mask: [true; 4],
            color: [1.0; 4],
            begun: None,
            batch: Vec::new(),
        }
    }

    fn on(&self, c: Capability) -> bool {
        self.caps.get(&c).copied().unwrap_or(c == Capability::Dither)
    }

    fn top(&mut self) -> &mut Mat4 {
        let s = match self.mode {
            MatrixMode::Projection => &mut self.projection,
            _ => &mut self.modelview,
        };
        s.last_mut().expect("stacks are never empty")
    }

    /// GL's window rectangle, inside the framebuffer (Vulkan's rows are GL's rows).
    fn rect(&self, r: [i32; 4]) -> vk::Rect2D {
        let (w, h) = (self.w as i64, self.h as i64);
        let x0 = (r[0] as i64).clamp(0, w);
        let x1 = (r[0] as i64 + r[2] as i64).clamp(0, w);
        let y0 = (r[1] as i64).clamp(0, h);
        let y1 = (r[1] as i64 + r[3] as i64).clamp(0, h);
        vk::Rect2D {
            offset: vk::Offset2D {
                x: x0 as i32,
                y: y0 as i32,
            },
            extent: vk::Extent2D {
                width: (x1 - x0) as u32,
                height: (y1 - y0) as u32,
            },
        }
    }

    fn scissor_rect(&self) -> vk::Rect2D {
        if self.on(Capability::ScissorTest) {
            self.rect(self.scissor)
        } else {
            self.rect([0, 0, self.w as i32, self.h as i32])
        }
    }

    fn key(&self) -> PipeKey {
        let logic = self.on(Capability::ColorLogicOp);
        PipeKey {
            depth_test: self.on(Capability::DepthTest),
            depth_write: self.depth_mask,
            depth_func: self.depth_func,
            stencil_test: self.on(Capability::StencilTest),
            stencil_func: self.stencil.0,
            stencil_ref: self.stencil.1.clamp(0, 255) as u32,
            stencil_value_mask: self.stencil.2 & 0xff,
            stencil_write_mask: self.stencil_mask & 0xff,
            stencil_ops: self.stencil_ops,
            blend: self.on(Capability::Blend) && !logic,
            blend_factors: self.blend_factors,
            blend_equations: [self.blend_equation; 2],
            blend_color: self.blend_color.map(|v| v.clamp(0.0, 1.0).to_bits()),
            logic_op: logic.then_some(self.logic_op),
            color_mask: self.color_mask,
            cull: self.on(Capability::CullFace).then_some(self.cull_face),
            front_ccw: self.front == FrontFace::Ccw,
            offset: self
                .on(Capability::PolygonOffsetFill)
                .then_some((self.offset.0.to_bits(), self.offset.1.to_bits())),
            alpha: self
                .on(Capability::AlphaTest)
                .then_some((self.alpha.0, self.alpha.1.clamp(0.0, 1.0).to_bits())),
            flat: self.shade == ShadeModel::Flat,
        }
    }
}

fn flush(st: &mut GlState, mode: PrimitiveMode, plan: &mut Plan) -> Result<(), String> {
    let verts = std::mem::take(&mut st.batch);
    let mvp = *st.projection.last().expect("stack") * *st.modelview.last().expect("stack");
    let n = verts.len();
    // (a, b, c, provoking) per triangle, GL's decomposition as llvmpipe does it.
    let mut tris: Vec<[usize; 4]> = Vec::new();
    match mode {
        PrimitiveMode::Points | PrimitiveMode::Lines | PrimitiveMode::LineStrip | PrimitiveMode::LineLoop => {
            return Err(format!("{mode:?}: Vulkan's line and point rasterization is not GL's"));
        }
        PrimitiveMode::Triangles => tris.extend((0..n / 3).map(|i| [3 * i, 3 * i + 1, 3 * i + 2, 3 * i + 2])),
        PrimitiveMode::TriangleStrip => tris.extend((0..n.saturating_sub(2)).map(|i| {
            if i % 2 == 0 {
                [i, i + 1, i + 2, i + 2]
            } else {
                [i + 1, i, i + 2, i + 2]
            }
        })),
        PrimitiveMode::TriangleFan => tris.extend((0..n.saturating_sub(2)).map(|i| [0, i + 1, i + 2, i + 2])),
        // llvmpipe splits a lone quad along v0-v2 but quads batched two or
        // more to a glBegin along v1-v3 (measured with OSMesa 22.3.6).
        PrimitiveMode::Quads if n / 4 == 1 => {
            tris.push([0, 1, 2, 3]);
            tris.push([0, 2, 3, 3]);
        }
        PrimitiveMode::Quads => {
            for q in 0..n / 4 {
                let b = 4 * q;
                tris.push([b, b + 1, b + 3, b + 3]);
                tris.push([b + 1, b + 2, b + 3, b + 3]);
            }
        }
        PrimitiveMode::QuadStrip => {
            for q in 0..(n / 2).saturating_sub(1) {
                let b = 2 * q;
                tris.push([b, b + 1, b + 3, b + 3]);
                tris.push([b, b + 3, b + 2, b + 3]);
            }
        }
        PrimitiveMode::Polygon => tris.extend((1..n.saturating_sub(1)).map(|i| [0, i, i + 1, 0])),
    }
    if tris.is_empty() {
        return Ok(());
    }
    if st.polygon_mode != [PolygonMode::Fill; 2] {
        return Err("polygon modes other than fill".into());
    }
    let key = st.key();
    let first = plan.vertices.len() as u32;
    for t in &tris {
        for &i in &t[..3] {
            let p = mvp * Vec4::from_array(verts[i].0);
            let c = if key.flat { verts[t[3]].1 } else { verts[i].1 };
            plan.vertices.push(Vertex {
                pos: [p.x, p.y, (p.z + p.w) * 0.5, p.w],
                color: c.map(|v| if v.is_nan() { 0.0 } else { v.clamp(0.0, 1.0) }),
            });
        }
    }
    let [x, y, w, h] = st.viewport;
    let viewport = vk::Viewport {
        x: x as f32,
        y: y as f32,
        width: w as f32,
        height: h as f32,
        min_depth: st.depth_range.0.clamp(0.0, 1.0) as f32,
        max_depth: st.depth_range.1.clamp(0.0, 1.0) as f32,
    };
    let scissor = st.scissor_rect();
    if scissor.extent.width > 0 && scissor.extent.height > 0 {
        plan.ops.push(Op::Draw {
            key,
            viewport,
            scissor,
            first,
            count: plan.vertices.len() as u32 - first,
        });
    }
    Ok(())
}

/// Runs GL's state machine over the calls and collects the Vulkan work.
fn plan(rec: &Recording) -> Result<Plan, String> {
    let mut st = GlState::new(rec.width, rec.height);
    let mut plan = Plan {
        ops: Vec::new(),
        vertices: Vec::new(),
    };
    for c in &rec.calls {
        match c {
            Call::Enable(cap) => {
                st.caps.insert(*cap, true);
            }
            Call::Disable(cap) => {
                st.caps.insert(*cap, false);
            }
            Call::ClearColor(c) => st.clear_color = c.map(|v| v.clamp(0.0, 1.0)),
            Call::ClearDepth(d) => st.clear_depth = d.clamp(0.0, 1.0),
            Call::ClearStencil(s) => st.clear_stencil = *s,
            Call::Clear(m) => {
                if m.color && st.color_mask != [true; 4] {
                    return Err("masked colour clear".into());
                }
                if m.stencil && st.stencil_mask & 0xff != 0xff {
                    return Err("masked stencil clear".into());
                }
                if m.depth && !st.depth_mask {
                    return Err("depth clear with depth writes off".into());
                }
                let rect = st.scissor_rect();
                if rect.extent.width > 0 && rect.extent.height > 0 {
                    plan.ops.push(Op::Clear {
                        rect,
                        color: m.color.then_some(st.clear_color),
                        depth: m.depth.then_some(st.clear_depth as f32),
                        stencil: m.stencil.then_some((st.clear_stencil & 0xff) as u32),
                    });
                }
            }
            Call::Viewport(v) => st.viewport = *v,
            Call::DepthRange(n, f) => st.depth_range = (*n, *f),
            Call::Scissor(s) => st.scissor = *s,
            Call::MatrixMode(m) => st.mode = *m,
            Call::LoadIdentity => *st.top() = Mat4::IDENTITY,
            Call::LoadMatrix(m) => *st.top() = Mat4::from_cols_array(m),
            Call::PushMatrix => {
                let top = *st.top();
                match st.mode {
                    MatrixMode::Projection => st.projection.push(top),
                    _ => st.modelview.push(top),
                }
            }
            Call::PopMatrix => {
                let s = match st.mode {
                    MatrixMode::Projection => &mut st.projection,
                    _ => &mut st.modelview,
                };
                if s.len() > 1 {
                    s.pop();
                }
            }
            Call::Translate(t) => *st.top() *= Mat4::from_translation(Vec3::from_array(*t)),
            Call::Scale(s) => *st.top() *= Mat4::from_scale(Vec3::from_array(*s)),
            Call::Rotate(a, axis) => {
                let axis = Vec3::from_array(*axis).normalize_or_zero();
                *st.top() *= Mat4::from_axis_angle(axis, a.to_radians());
            }
            Call::Frustum([l, r, b, t, n, f]) => {
                let m = Mat4::from_cols_array(&[
                    (2.0 * n / (r - l)) as f32,
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                    (2.0 * n / (t - b)) as f32,
                    0.0,
                    0.0,
                    ((r + l) / (r - l)) as f32,
                    ((t + b) / (t - b)) as f32,
                    (-(f + n) / (f - n)) as f32,
                    -1.0,
                    0.0,
                    0.0,
                    (-2.0 * f * n / (f - n)) as f32,
                    0.0,
                ]);
                *st.top() *= m;
            }
            Call::Ortho([l, r, b, t, n, f]) => {
                let m = Mat4::from_cols_array(&[
                    (2.0 / (r - l)) as f32,
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                    (2.0 / (t - b)) as f32,
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                    (-2.0 / (f - n)) as f32,
                    0.0,
                    (-(r + l) / (r - l)) as f32,
                    (-(t + b) / (t - b)) as f32,
                    (-(f + n) / (f - n)) as f32,
                    1.0,
                ]);
                *st.top() *= m;
            }
            Call::ShadeModel(m) => st.shade = *m,
            Call::FrontFace(f) => st.front = *f,
            Call::CullFace(f) => st.cull_face = *f,
            Call::PolygonMode(f, m) => match f {
                Face::Front => st.polygon_mode[0] = *m,
                Face::Back => st.polygon_mode[1] = *m,
                Face::FrontAndBack => st.polygon_mode = [*m; 2],
            },
            Call::PolygonOffset(f, u) => st.offset = (*f, *u),
            Call::PointSize(_) | Call::LineWidth(_) => {}
            Call::AlphaFunc(f, r) => st.alpha = (*f, *r),
            Call::StencilFunc(f, r, m) => st.stencil = (*f, *r, *m),
            Call::StencilOp(a, b, c) => st.stencil_ops = [*a, *b, *c],
            Call::StencilMask(m) => st.stencil_mask = *m,
            Call::DepthFunc(f) => st.depth_func = *f,
            Call::DepthMask(m) => st.depth_mask = *m,
            Call::BlendFunc(s, d) => st.blend_factors = [*s, *d, *s, *d],
            Call::BlendFuncSeparate(f) => st.blend_factors = *f,
            Call::BlendEquation(e) => st.blend_equation = *e,
            Call::BlendColor(c) => st.blend_color = *c,
            Call::LogicOp(o) => st.logic_op = *o,
            Call::ColorMask(m) => st.color_mask = *m,
            Call::Begin(m) => st.begun = Some(*m),
            Call::End => {
                if let Some(m) = st.begun.take() {
                    flush(&mut st, m, &mut plan)?;
                }
            }
            Call::Color(c) => st.color = *c,
            Call::Vertex(v) => {
                let color = st.color;
                st.batch.push((*v, color));
            }
            Call::DrawArrays {
                mode,
                positions,
                colors,
            } => {
                st.batch = positions.iter().copied().zip(colors.iter().copied()).collect();
                flush(&mut st, *mode, &mut plan)?;
            }
        }
    }
    Ok(plan)
}

fn compare_op(f: CompareFunc) -> vk::CompareOp {
    match f {
        CompareFunc::Never => vk::CompareOp::NEVER,
        CompareFunc::Less => vk::CompareOp::LESS,
        CompareFunc::Equal => vk::CompareOp::EQUAL,
        CompareFunc::Lequal => vk::CompareOp::LESS_OR_EQUAL,
        CompareFunc::Greater => vk::CompareOp::GREATER,
        CompareFunc::Notequal => vk::CompareOp::NOT_EQUAL,
        CompareFunc::Gequal => vk::CompareOp::GREATER_OR_EQUAL,
        CompareFunc::Always => vk::CompareOp::ALWAYS,
    }
}

fn stencil_op(o: StencilOp) -> vk::StencilOp {
    match o {
        StencilOp::Keep => vk::StencilOp::KEEP,
        StencilOp::Zero => vk::StencilOp::ZERO,
        StencilOp::Replace => vk::StencilOp::REPLACE,
        StencilOp::Incr => vk::StencilOp::INCREMENT_AND_CLAMP,
        StencilOp::Decr => vk::StencilOp::DECREMENT_AND_CLAMP,
        StencilOp::Invert => vk::StencilOp::INVERT,
        StencilOp::IncrWrap => vk::StencilOp::INCREMENT_AND_WRAP,
        StencilOp::DecrWrap => vk::StencilOp::DECREMENT_AND_WRAP,
    }
}

fn blend_factor(f: BlendFactor) -> vk::BlendFactor {
    match f {
        BlendFactor::Zero => vk::BlendFactor::ZERO,
        BlendFactor::One => vk::BlendFactor::ONE,
        BlendFactor::SrcColor => vk::BlendFactor::SRC_COLOR,
        BlendFactor::OneMinusSrcColor => vk::BlendFactor::ONE_MINUS_SRC_COLOR,
        BlendFactor::DstColor => vk::BlendFactor::DST_COLOR,
        BlendFactor::OneMinusDstColor => vk::BlendFactor::ONE_MINUS_DST_COLOR,
        BlendFactor::SrcAlpha => vk::BlendFactor::SRC_ALPHA,
        BlendFactor::OneMinusSrcAlpha => vk::BlendFactor::ONE_MINUS_SRC_ALPHA,
        BlendFactor::DstAlpha => vk::BlendFactor::DST_ALPHA,
        BlendFactor::OneMinusDstAlpha => vk::BlendFactor::ONE_MINUS_DST_ALPHA,
        BlendFactor::ConstantColor => vk::BlendFactor::CONSTANT_COLOR,
        BlendFactor::OneMinusConstantColor => vk::BlendFactor::ONE_MINUS_CONSTANT_COLOR,
        BlendFactor::ConstantAlpha => vk::BlendFactor::CONSTANT_ALPHA,
        BlendFactor::OneMinusConstantAlpha => vk::BlendFactor::ONE_MINUS_CONSTANT_ALPHA,
        BlendFactor::SrcAlphaSaturate => vk::BlendFactor::SRC_ALPHA_SATURATE,
    }
}

fn blend_op(e: BlendEquation) -> vk::BlendOp {
    match e {
        BlendEquation::Add => vk::BlendOp::ADD,
        BlendEquation::Subtract => vk::BlendOp::SUBTRACT,
        BlendEquation::ReverseSubtract => vk::BlendOp::REVERSE_SUBTRACT,
        BlendEquation::Min => vk::BlendOp::MIN,
        BlendEquation::Max => vk::BlendOp::MAX,
    }
}

fn logic_op(o: LogicOp) -> vk::LogicOp {
    match o {
        LogicOp::Clear => vk::LogicOp::CLEAR,
        LogicOp::And => vk::LogicOp::AND,
        LogicOp::AndReverse => vk::LogicOp::AND_REVERSE,
        LogicOp::Copy => vk::LogicOp::COPY,
        LogicOp::AndInverted => vk::LogicOp::AND_INVERTED,
        LogicOp::Noop => vk::LogicOp::NO_OP,
        LogicOp::Xor => vk::LogicOp::XOR,
        LogicOp::Or => vk::LogicOp::OR,
        LogicOp::Nor => vk::LogicOp::NOR,
        LogicOp::Equiv => vk::LogicOp::EQUIVALENT,
        LogicOp::Invert => vk::LogicOp::INVERT,
        LogicOp::OrReverse => vk::LogicOp::OR_REVERSE,
        LogicOp::CopyInverted => vk::LogicOp::COPY_INVERTED,
        LogicOp::OrInverted => vk::LogicOp::OR_INVERTED,
        LogicOp::Nand => vk::LogicOp::NAND,
        LogicOp::Set => vk::LogicOp::SET,
    }
}

/// The WGSL of the shaders for a key: flat or smooth colour, and the alpha test.
fn wgsl(key: &PipeKey) -> String {
    let interp = if key.flat { "@interpolate(flat)" } else { "" };
    let test = match key.alpha {
        None => String::new(),
        Some((f, r)) => {
            let r = f32::from_bits(r);
            let cond = match f {
                CompareFunc::Never => "false".to_string(),
                CompareFunc::Always => "true".to_string(),
                f => {
                    let op = match f {
                        CompareFunc::Less => "<",
                        CompareFunc::Equal => "==",
                        CompareFunc::Lequal => "<=",
                        CompareFunc::Greater => ">",
                        CompareFunc::Notequal => "!=",
                        _ => ">=",
                    };
                    format!("i.color.a {op} {r:?}")
                }
            };
            format!("if (!({cond})) {{ discard; }}")
        }
    };
    format!(
        "struct VOut {{ @builtin(position) pos: vec4<f32>, @location(0) {interp} color: vec4<f32> }};
@vertex fn vs(@location(0) p: vec4<f32>, @location(1) c: vec4<f32>) -> VOut {{
    var o: VOut; o.pos = p; o.color = c; return o;
}}
@fragment fn fs(i: VOut) -> @location(0) vec4<f32> {{ {test} return i.color; }}"
    )
}

/// SPIR-V for one entry point of `src`.
fn spirv(src: &str, stage: naga::ShaderStage, entry: &str) -> Result<Vec<u32>, String> {
    let module = naga::front::wgsl::parse_str(src).map_err(|e| e.emit_to_string(src))?;
    let info = naga::valid::Validator::new(naga::valid::ValidationFlags::all(), naga::valid::Capabilities::empty())
        .validate(&module)
        .map_err(|e| format!("{e:?}"))?;
    let options = naga::back::spv::Options {
        // Keep positions as given: the y flip is done on the CPU.
        flags: naga::back::spv::WriterFlags::empty(),
        ..Default::default()
    };
    let pipeline = naga::back::spv::PipelineOptions {
        shader_stage: stage,
        entry_point: entry.into(),
    };
    naga::back::spv::write_vec(&module, &info, &options, Some(&pipeline)).map_err(|e| e.to_string())
}

/// A device, the render targets for one size, and compiled pipelines.
struct Gpu {
    _entry: ash::Entry,
    instance: ash::Instance,
    device: ash::Device,
    queue: vk::Queue,
    name: String,
    mem_props: vk::PhysicalDeviceMemoryProperties,
    pool: vk::CommandPool,
    cmd: vk::CommandBuffer,
    fence: vk::Fence,
    render_pass: vk::RenderPass,
    framebuffer: vk::Framebuffer,
    images: Vec<(vk::Image, vk::ImageView, vk::DeviceMemory)>,
    readback: (vk::Buffer, vk::DeviceMemory),
    layout: vk::PipelineLayout,
    pipelines: HashMap<PipeKey, vk::Pipeline>,
    width: u32,
    height: u32,
}

fn vk_err(what: &str) -> impl Fn(vk::Result) -> String + '_ {
    move |e| format!("{what}: {e}")
}

impl Gpu {
    fn new(width: u32, height: u32) -> Result<Gpu, String> {
        // SAFETY: loads the system's Vulkan loader (libvulkan.so.1); ash keeps it loaded in `Entry`.
        let entry = unsafe { ash::Entry::load() }
            .map_err(|e| format!("libvulkan is not installed ({e}); install libvulkan1 and mesa-vulkan-drivers"))?;
        let app = vk::ApplicationInfo::default().api_version(vk::make_api_version(0, 1, 1, 0));
        // SAFETY: valid create info; every Vulkan call below passes handles created here,
        // and they are destroyed in `Drop` in reverse order.
        unsafe {
            let instance = entry
                .create_instance(&vk::InstanceCreateInfo::default().application_info(&app), None)
                .map_err(vk_err("vkCreateInstance"))?;
            let pdev = instance
                .enumerate_physical_devices()
                .map_err(vk_err("vkEnumeratePhysicalDevices"))?
                .into_iter()
                .find(|&p| {
                    let props = instance.get_physical_device_properties(p);
                    let name = props.device_name_as_c_str().unwrap_or_default().to_string_lossy();
                    props.device_type == vk::PhysicalDeviceType::CPU && name.contains("llvmpipe")
                });
            let Some(pdev) = pdev else {
                instance.destroy_instance(None);
                return Err("no lavapipe device (install mesa-vulkan-drivers)".into());
            };
            let props = instance.get_physical_device_properties(pdev);
            let name = props
                .device_name_as_c_str()
                .unwrap_or_default()
                .to_string_lossy()
                .into_owned();
            let family = instance
                .get_physical_device_queue_family_properties(pdev)
                .iter()
                .position(|q| q.queue_flags.contains(vk::QueueFlags::GRAPHICS))
                .ok_or("no graphics queue")? as u32;
            let features = vk::PhysicalDeviceFeatures::default().logic_op(true);
            let prio = [1.0];
            let qinfo = [vk::DeviceQueueCreateInfo::default()
                .queue_family_index(family)
                .queue_priorities(&prio)];
            let device = instance
                .create_device(
                    pdev,
                    &vk::DeviceCreateInfo::default()
                        .queue_create_infos(&qinfo)
                        .enabled_features(&features),
                    None,
                )
                .map_err(vk_err("vkCreateDevice"))?;
            let queue = device.get_device_queue(family, 0);
            let mem_props = instance.get_physical_device_memory_properties(pdev);
            let pool = device
                .create_command_pool(
                    &vk::CommandPoolCreateInfo::default()
                        .queue_family_index(family)
                        .flags(vk::CommandPoolCreateFlags::RESET_COMMAND_BUFFER),
                    None,
                )
                .map_err(vk_err("vkCreateCommandPool"))?;
            let cmd = device
                .allocate_command_buffers(
                    &vk::CommandBufferAllocateInfo::default()
                        .command_pool(pool)
                        .command_buffer_count(1),
                )
                .map_err(vk_err("vkAllocateCommandBuffers"))?[0];
            let fence = device
                .create_fence(&vk::FenceCreateInfo::default(), None)
                .map_err(vk_err("vkCreateFence"))?;
            let depth_format = [vk::Format::D24_UNORM_S8_UINT, vk::Format::D32_SFLOAT_S8_UINT]
                .into_iter()
                .find(|&f| {
                    instance
                        .get_physical_device_format_properties(pdev, f)
                        .optimal_tiling_features
                        .contains(vk::FormatFeatureFlags::DEPTH_STENCIL_ATTACHMENT)
                })
                .ok_or("no depth-stencil format")?;
            let mut gpu = Gpu {
                _entry: entry,
                instance,
                device,
                queue,
                name,
                mem_props,
                pool,
                cmd,
                fence,
                render_pass: vk::RenderPass::null(),
                framebuffer: vk::Framebuffer::null(),
                images: Vec::new(),
                readback: (vk::Buffer::null(), vk::DeviceMemory::null()),
                layout: vk::PipelineLayout::null(),
                pipelines: HashMap::new(),
                width,
                height,
            };
            gpu.targets(depth_format)?;
            Ok(gpu)
        }
    }

    fn memory_type(&self, bits: u32, flags: vk::MemoryPropertyFlags) -> Result<u32, String> {
        (0..self.mem_props.memory_type_count)
            .find(|&i| bits & (1 << i) != 0 && self.mem_props.memory_types[i as usize].property_flags.contains(flags))
            .ok_or_else(|| format!("no memory type {flags:?}"))
    }

    /// # Safety
    /// Called once, from `new`, with the device alive.
    unsafe fn targets(&mut self, depth_format: vk::Format) -> Result<(), String> {
        let d = &self.device;
        let extent = vk::Extent3D {
            width: self.width,
            height: self.height,
            depth: 1,
        };
        for (format, usage, aspect) in [
            (
                vk::Format::R8G8B8A8_UNORM,
                vk::ImageUsageFlags::COLOR_ATTACHMENT | vk::ImageUsageFlags::TRANSFER_SRC,
                vk::ImageAspectFlags::COLOR,
            ),
            (
                depth_format,
                vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT,
                vk::ImageAspectFlags::DEPTH | vk::ImageAspectFlags::STENCIL,
            ),
        ] {
            // SAFETY: (for the block) valid create infos on a live device.
            let image = unsafe {
                d.create_image(
                    &vk::ImageCreateInfo::default()
                        .image_type(vk::ImageType::TYPE_2D)
                        .format(format)
                        .extent(extent)
                        .mip_levels(1)
                        .array_layers(1)
                        .samples(vk::SampleCountFlags::TYPE_1)
                        .tiling(vk::ImageTiling::OPTIMAL)
                        .usage(usage),
                    None,
                )
            }
            .map_err(vk_err("vkCreateImage"))?;
            // SAFETY: `image` was just created on this device.
            let req = unsafe { d.get_image_memory_requirements(image) };
            let mem_type = self.memory_type(req.memory_type_bits, vk::MemoryPropertyFlags::DEVICE_LOCAL)?;
            // SAFETY: valid allocation info; memory is bound once, to this image.
            let (memory, view) = unsafe {
                let memory = d
                    .allocate_memory(
                        &vk::MemoryAllocateInfo::default()
                            .allocation_size(req.size)
                            .memory_type_index(mem_type),
                        None,
                    )
                    .map_err(vk_err("vkAllocateMemory"))?;
                d.bind_image_memory(image, memory, 0)
                    .map_err(vk_err("vkBindImageMemory"))?;
                let view = d
                    .create_image_view(
                        &vk::ImageViewCreateInfo::default()
                            .image(image)
                            .view_type(vk::ImageViewType::TYPE_2D)
                            .format(format)
                            .subresource_range(
                                vk::ImageSubresourceRange::default()
                                    .aspect_mask(aspect)
                                    .level_count(1)
                                    .layer_count(1),
                            ),
                        None,
                    )
                    .map_err(vk_err("vkCreateImageView"))?;
                (memory, view)
            };
            self.images.push((image, view, memory));
        }
        let attachments = [
            vk::AttachmentDescription::default()
                .format(vk::Format::R8G8B8A8_UNORM)
                .samples(vk::SampleCountFlags::TYPE_1)
                .load_op(vk::AttachmentLoadOp::CLEAR)
                .store_op(vk::AttachmentStoreOp::STORE)
                .initial_layout(vk::ImageLayout::UNDEFINED)
                .final_layout(vk::ImageLayout::TRANSFER_SRC_OPTIMAL),
            vk::AttachmentDescription::default()
                .format(depth_format)
                .samples(vk::SampleCountFlags::TYPE_1)
                .load_op(vk::AttachmentLoadOp::CLEAR)
                .store_op(vk::AttachmentStoreOp::DONT_CARE)
                .stencil_load_op(vk::AttachmentLoadOp::CLEAR)
                .stencil_store_op(vk::AttachmentStoreOp::DONT_CARE)
                .initial_layout(vk::ImageLayout::UNDEFINED)
                .final_layout(vk::ImageLayout::DEPTH_STENCIL_ATTACHMENT_OPTIMAL),
        ];
        let color_ref = [vk::AttachmentReference {
            attachment: 0,
            layout: vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL,
        }];
        let depth_ref = vk::AttachmentReference {
            attachment: 1,
            layout: vk::ImageLayout::DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
        };
        let subpass = [vk::SubpassDescription::default()
            .pipeline_bind_point(vk::PipelineBindPoint::GRAPHICS)
            .color_attachments(&color_ref)
            .depth_stencil_attachment(&depth_ref)];
        let views = [self.images[0].1, self.images[1].1];
        let bytes = self.width as u64 * self.height as u64 * 4;
        // SAFETY: valid create infos on a live device; handles are kept in `self` and freed in Drop.
        unsafe {
            self.render_pass = d
                .create_render_pass(
                    &vk::RenderPassCreateInfo::default()
                        .attachments(&attachments)
                        .subpasses(&subpass),
                    None,
                )
                .map_err(vk_err("vkCreateRenderPass"))?;
            self.framebuffer = d
                .create_framebuffer(
                    &vk::FramebufferCreateInfo::default()
                        .render_pass(self.render_pass)
                        .attachments(&views)
                        .width(self.width)
                        .height(self.height)
                        .layers(1),
                    None,
                )
                .map_err(vk_err("vkCreateFramebuffer"))?;
            self.layout = d
                .create_pipeline_layout(&vk::PipelineLayoutCreateInfo::default(), None)
                .map_err(vk_err("vkCreatePipelineLayout"))?;
        }
        self.readback = self.host_buffer(bytes, vk::BufferUsageFlags::TRANSFER_DST)?;
        Ok(())
    }

    fn host_buffer(&self, size: u64, usage: vk::BufferUsageFlags) -> Result<(vk::Buffer, vk::DeviceMemory), String> {
        let d = &self.device;
        // SAFETY: valid create infos on a live device; the memory is bound once, to this buffer.
        unsafe {
            let buffer = d
                .create_buffer(&vk::BufferCreateInfo::default().size(size.max(4)).usage(usage), None)
                .map_err(vk_err("vkCreateBuffer"))?;
            let req = d.get_buffer_memory_requirements(buffer);
            let mem_type = self.memory_type(
                req.memory_type_bits,
                vk::MemoryPropertyFlags::HOST_VISIBLE | vk::MemoryPropertyFlags::HOST_COHERENT,
            )?;
            let memory = d
                .allocate_memory(
                    &vk::MemoryAllocateInfo::default()
                        .allocation_size(req.size)
                        .memory_type_index(mem_type),
                    None,
                )
                .map_err(vk_err("vkAllocateMemory"))?;
            d.bind_buffer_memory(buffer, memory, 0)
                .map_err(vk_err("vkBindBufferMemory"))?;
            Ok((buffer, memory))
        }
    }

    fn pipeline(&mut self, key: &PipeKey) -> Result<vk::Pipeline, String> {
        if let Some(&p) = self.pipelines.get(key) {
            return Ok(p);
        }
        let src = wgsl(key);
        let vs = spirv(&src, naga::ShaderStage::Vertex, "vs")?;
        let fs = spirv(&src, naga::ShaderStage::Fragment, "fs")?;
        let d = &self.device;
        let stencil = vk::StencilOpState {
            fail_op: stencil_op(key.stencil_ops[0]),
            depth_fail_op: stencil_op(key.stencil_ops[1]),
            pass_op: stencil_op(key.stencil_ops[2]),
            compare_op: compare_op(key.stencil_func),
            compare_mask: key.stencil_value_mask,
            write_mask: key.stencil_write_mask,
            reference: key.stencil_ref,
        };
        let mut mask = vk::ColorComponentFlags::empty();
        for (on, bit) in key.color_mask.iter().zip([
            vk::ColorComponentFlags::R,
            vk::ColorComponentFlags::G,
            vk::ColorComponentFlags::B,
            vk::ColorComponentFlags::A,
        ]) {
            if *on {
                mask |= bit;
            }
        }
        let blend = [vk::PipelineColorBlendAttachmentState::default()
            .blend_enable(key.blend)
            .src_color_blend_factor(blend_factor(key.blend_factors[0]))
            .dst_color_blend_factor(blend_factor(key.blend_factors[1]))
            .src_alpha_blend_factor(blend_factor(key.blend_factors[2]))
            .dst_alpha_blend_factor(blend_factor(key.blend_factors[3]))
            .color_blend_op(blend_op(key.blend_equations[0]))
            .alpha_blend_op(blend_op(key.blend_equations[1]))
            .color_write_mask(mask)];
        let blend_state = vk::PipelineColorBlendStateCreateInfo::default()
            .logic_op_enable(key.logic_op.is_some())
            .logic_op(key.logic_op.map_or(vk::LogicOp::COPY, logic_op))
            .attachments(&blend)
            .blend_constants(key.blend_color.map(f32::from_bits));
        // Vulkan's framebuffer row r is GL's window row r, so the same
        // coordinates wind the other way in Vulkan's (y-down) convention.
        let front = if key.front_ccw {
            vk::FrontFace::CLOCKWISE
        } else {
            vk::FrontFace::COUNTER_CLOCKWISE
        };
        let cull = match key.cull {
            None => vk::CullModeFlags::NONE,
            Some(Face::Front) => vk::CullModeFlags::FRONT,
            Some(Face::Back) => vk::CullModeFlags::BACK,
            Some(Face::FrontAndBack) => vk::CullModeFlags::FRONT_AND_BACK,
        };
        let (factor, units) = key
            .offset
            .map_or((0.0, 0.0), |(f, u)| (f32::from_bits(f), f32::from_bits(u)));
        let raster = vk::PipelineRasterizationStateCreateInfo::default()
            .polygon_mode(vk::PolygonMode::FILL)
            .cull_mode(cull)
            .front_face(front)
            .depth_bias_enable(key.offset.is_some())
            .depth_bias_constant_factor(units)
            .depth_bias_slope_factor(factor)
            .line_width(1.0);
        let depth = vk::PipelineDepthStencilStateCreateInfo::default()
            .depth_test_enable(key.depth_test)
            .depth_write_enable(key.depth_test && key.depth_write)
            .depth_compare_op(compare_op(key.depth_func))
            .stencil_test_enable(key.stencil_test)
            .front(stencil)
            .back(stencil);
        let bindings = [vk::VertexInputBindingDescription {
            binding: 0,
            stride: std::mem::size_of::<Vertex>() as u32,
            input_rate: vk::VertexInputRate::VERTEX,
        }];
        let attrs = [
            vk::VertexInputAttributeDescription {
                location: 0,
                binding: 0,
                format: vk::Format::R32G32B32A32_SFLOAT,
                offset: 0,
            },
            vk::VertexInputAttributeDescription {
                location: 1,
                binding: 0,
                format: vk::Format::R32G32B32A32_SFLOAT,
                offset: 16,
            },
        ];
        let input = vk::PipelineVertexInputStateCreateInfo::default()
            .vertex_binding_descriptions(&bindings)
            .vertex_attribute_descriptions(&attrs);
        let assembly =
            vk::PipelineInputAssemblyStateCreateInfo::default().topology(vk::PrimitiveTopology::TRIANGLE_LIST);
        let viewport = vk::PipelineViewportStateCreateInfo::default()
            .viewport_count(1)
            .scissor_count(1);
        let ms = vk::PipelineMultisampleStateCreateInfo::default().rasterization_samples(vk::SampleCountFlags::TYPE_1);
        let dynamic = [vk::DynamicState::VIEWPORT, vk::DynamicState::SCISSOR];
        let dynamic = vk::PipelineDynamicStateCreateInfo::default().dynamic_states(&dynamic);
        // SAFETY: the SPIR-V came from naga's validated module; every create info points at
        // locals that outlive the calls; modules are destroyed once the pipeline exists.
        unsafe {
            let vm = d
                .create_shader_module(&vk::ShaderModuleCreateInfo::default().code(&vs), None)
                .map_err(vk_err("vkCreateShaderModule"))?;
            let fm = d
                .create_shader_module(&vk::ShaderModuleCreateInfo::default().code(&fs), None)
                .map_err(vk_err("vkCreateShaderModule"))?;
            let stages = [
                vk::PipelineShaderStageCreateInfo::default()
                    .stage(vk::ShaderStageFlags::VERTEX)
                    .module(vm)
                    .name(c"vs"),
                vk::PipelineShaderStageCreateInfo::default()
                    .stage(vk::ShaderStageFlags::FRAGMENT)
                    .module(fm)
                    .name(c"fs"),
            ];
            let info = vk::GraphicsPipelineCreateInfo::default()
                .stages(&stages)
                .vertex_input_state(&input)
                .input_assembly_state(&assembly)
                .viewport_state(&viewport)
                .rasterization_state(&raster)
                .multisample_state(&ms)
                .depth_stencil_state(&depth)
                .color_blend_state(&blend_state)
                .dynamic_state(&dynamic)
                .layout(self.layout)
                .render_pass(self.render_pass)
                .subpass(0);
            let p = d
                .create_graphics_pipelines(vk::PipelineCache::null(), &[info], None)
                .map_err(|(_, e)| format!("vkCreateGraphicsPipelines: {e}"))?[0];
            d.destroy_shader_module(vm, None);
            d.destroy_shader_module(fm, None);
            self.pipelines.insert(*key, p);
            Ok(p)
        }
    }

    /// One frame: plan on the CPU, upload, record, submit, wait, read back.
    fn frame(&mut self, rec: &Recording) -> Result<image::RgbaImage, String> {
        let plan = plan(rec)?;
        let mut pipes = Vec::new();
        for op in &plan.ops {
            if let Op::Draw { key, .. } = op {
                pipes.push(self.pipeline(key)?);
            }
        }
        let bytes = (plan.vertices.len() * std::mem::size_of::<Vertex>()) as u64;
        let vbuf = self.host_buffer(bytes, vk::BufferUsageFlags::VERTEX_BUFFER)?;
        let d = &self.device;
        let (w, h) = (self.width, self.height);
        // SAFETY: every handle is live; the mapped ranges are within the allocations
        // (`bytes` for the vertices, w*h*4 for the read-back); the queue is idle when
        // the fence has signalled, before the buffers are read or freed.
        let pixels = unsafe {
            if bytes > 0 {
                let p = d
                    .map_memory(vbuf.1, 0, bytes, vk::MemoryMapFlags::empty())
                    .map_err(vk_err("vkMapMemory"))?;
                std::ptr::copy_nonoverlapping(plan.vertices.as_ptr().cast::<u8>(), p.cast::<u8>(), bytes as usize);
                d.unmap_memory(vbuf.1);
            }
            d.reset_command_buffer(self.cmd, vk::CommandBufferResetFlags::empty())
                .map_err(vk_err("vkResetCommandBuffer"))?;
            d.begin_command_buffer(self.cmd, &vk::CommandBufferBeginInfo::default())
                .map_err(vk_err("vkBeginCommandBuffer"))?;
            let clears = [
                vk::ClearValue {
                    color: vk::ClearColorValue { float32: [0.0; 4] },
                },
                vk::ClearValue {
                    depth_stencil: vk::ClearDepthStencilValue { depth: 1.0, stencil: 0 },
                },
            ];
            let full = vk::Rect2D {
                offset: vk::Offset2D::default(),
                extent: vk::Extent2D { width: w, height: h },
            };
            d.cmd_begin_render_pass(
                self.cmd,
                &vk::RenderPassBeginInfo::default()
                    .render_pass(self.render_pass)
                    .framebuffer(self.framebuffer)
                    .render_area(full)
                    .clear_values(&clears),
                vk::SubpassContents::INLINE,
            );
            if bytes > 0 {
                d.cmd_bind_vertex_buffers(self.cmd, 0, &[vbuf.0], &[0]);
            }
            let mut pipes = pipes.into_iter();
            for op in &plan.ops {
                match *op {
                    Op::Clear {
                        rect,
                        color,
                        depth,
                        stencil,
                    } => {
                        let mut atts = Vec::new();
                        if let Some(c) = color {
                            atts.push(vk::ClearAttachment {
                                aspect_mask: vk::ImageAspectFlags::COLOR,
                                color_attachment: 0,
                                clear_value: vk::ClearValue {
                                    color: vk::ClearColorValue { float32: c },
                                },
                            });
                        }
                        let mut aspect = vk::ImageAspectFlags::empty();
                        if depth.is_some() {
                            aspect |= vk::ImageAspectFlags::DEPTH;
                        }
                        if stencil.is_some() {
                            aspect |= vk::ImageAspectFlags::STENCIL;
                        }
                        if !aspect.is_empty() {
                            atts.push(vk::ClearAttachment {
                                aspect_mask: aspect,
                                color_attachment: 0,
                                clear_value: vk::ClearValue {
                                    depth_stencil: vk::ClearDepthStencilValue {
                                        depth: depth.unwrap_or(1.0),
                                        stencil: stencil.unwrap_or(0),
                                    },
                                },
                            });
                        }
                        let r = [vk::ClearRect {
                            rect,
                            base_array_layer: 0,
                            layer_count: 1,
                        }];
                        d.cmd_clear_attachments(self.cmd, &atts, &r);
                    }
                    Op::Draw {
                        viewport,
                        scissor,
                        first,
                        count,
                        ..
                    } => {
                        let p = pipes.next().expect("one pipeline per draw");
                        d.cmd_bind_pipeline(self.cmd, vk::PipelineBindPoint::GRAPHICS, p);
                        d.cmd_set_viewport(self.cmd, 0, &[viewport]);
                        d.cmd_set_scissor(self.cmd, 0, &[scissor]);
                        d.cmd_draw(self.cmd, count, 1, first, 0);
                    }
                }
            }
            d.cmd_end_render_pass(self.cmd);
            let region = vk::BufferImageCopy::default()
                .image_subresource(
                    vk::ImageSubresourceLayers::default()
                        .aspect_mask(vk::ImageAspectFlags::COLOR)
                        .layer_count(1),
                )
                .image_extent(vk::Extent3D {
                    width: w,
                    height: h,
                    depth: 1,
                });
            d.cmd_copy_image_to_buffer(
                self.cmd,
                self.images[0].0,
                vk::ImageLayout::TRANSFER_SRC_OPTIMAL,
                self.readback.0,
                &[region],
            );
            d.end_command_buffer(self.cmd).map_err(vk_err("vkEndCommandBuffer"))?;
            let cmds = [self.cmd];
            d.queue_submit(
                self.queue,
                &[vk::SubmitInfo::default().command_buffers(&cmds)],
                self.fence,
            )
            .map_err(vk_err("vkQueueSubmit"))?;
            d.wait_for_fences(&[self.fence], true, u64::MAX)
                .map_err(vk_err("vkWaitForFences"))?;
            d.reset_fences(&[self.fence]).map_err(vk_err("vkResetFences"))?;
            let size = w as usize * h as usize * 4;
            let p = d
                .map_memory(self.readback.1, 0, size as u64, vk::MemoryMapFlags::empty())
                .map_err(vk_err("vkMapMemory"))?;
            // Row 0 is GL's bottom row: flip to top row first.
            let rows = std::slice::from_raw_parts(p.cast::<u8>(), size);
            let stride = w as usize * 4;
            let pixels: Vec<u8> = rows.chunks_exact(stride).rev().flatten().copied().collect();
            d.unmap_memory(self.readback.1);
            d.destroy_buffer(vbuf.0, None);
            d.free_memory(vbuf.1, None);
            pixels
        };
        image::RgbaImage::from_raw(w, h, pixels).ok_or_else(|| "read-back has the wrong size".into())
    }
}

impl Drop for Gpu {
    fn drop(&mut self) {
        // SAFETY: every handle was created on this device/instance and is destroyed
        // once, after the device is idle, children before parents.
        unsafe {
            let d = &self.device;
            let _ = d.device_wait_idle();
            for (_, p) in self.pipelines.drain() {
                d.destroy_pipeline(p, None);
            }
            d.destroy_pipeline_layout(self.layout, None);
            d.destroy_buffer(self.readback.0, None);
            d.free_memory(self.readback.1, None);
            d.destroy_framebuffer(self.framebuffer, None);
            d.destroy_render_pass(self.render_pass, None);
            for (image, view, memory) in self.images.drain(..) {
                d.destroy_image_view(view, None);
                d.destroy_image(image, None);
                d.free_memory(memory, None);
            }
            d.destroy_fence(self.fence, None);
            d.destroy_command_pool(self.pool, None);
            d.destroy_device(None);
            self.instance.destroy_instance(None);
        }
    }
}

/// Renders a recording on lavapipe: the first frame (including pipeline
/// compiles), then `runs` more.
pub fn render(rec: &Recording, runs: usize) -> (Outcome, String) {
    let mut gpu = match Gpu::new(rec.width, rec.height) {
        Ok(g) => g,
        Err(e) => return (Outcome::Failed(e), String::new()),
    };
    let name = gpu.name.clone();
    if let Err(why) = plan(rec) {
        return (Outcome::Unsupported(why), name);
    }
    if rec.color != softgl::ColorFormat::Rgba8 {
        return (Outcome::Unsupported(format!("{:?} colour buffers", rec.color)), name);
    }
    let t = Instant::now();
    let image = match gpu.frame(rec) {
        Ok(i) => i,
        Err(e) => return (Outcome::Failed(e), name),
    };
    let first = t.elapsed();
    let mut times = Vec::new();
    for _ in 0..runs {
        let t = Instant::now();
        if let Err(e) = gpu.frame(rec) {
            return (Outcome::Failed(e), name);
        }
        times.push(t.elapsed());
    }
    let steady = if runs == 0 { first } else { median(&mut times) };
    (
        Outcome::Rendered {
            image,
            timing: Timing { first, steady, runs },
            compiles: None,
        },
        name,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::call::Rec;

    fn recording(build: impl Fn(&mut Rec)) -> Recording {
        let mut r = Rec::default();
        build(&mut r);
        Recording {
            width: 8,
            height: 8,
            color: softgl::ColorFormat::Rgba8,
            calls: r.calls,
        }
    }

    #[test]
    fn lines_points_and_masked_clears_are_not_expressed() {
        for mode in [PrimitiveMode::Points, PrimitiveMode::Lines, PrimitiveMode::LineLoop] {
            let rec = recording(|r| {
                r.begin(mode).vertex(1.0, 1.0, 0.0).vertex(5.0, 5.0, 0.0).end();
            });
            assert!(plan(&rec).is_err(), "{mode:?}");
        }
        let rec = recording(|r| {
            r.call(Call::ColorMask([true, false, true, true]))
                .clear(softgl::ClearMask::COLOR);
        });
        assert!(plan(&rec).is_err());
    }

    #[test]
    fn quads_split_as_llvmpipe_splits_them() {
        let quad = |r: &mut Rec, x: f32| {
            for (dx, dy) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
                r.vertex(x + dx, dy, 0.0);
            }
        };
        let xs = |n: usize| {
            let rec = recording(|r| {
                r.begin(PrimitiveMode::Quads);
                for q in 0..n {
                    quad(r, 10.0 * q as f32);
                }
                r.end();
            });
            let p = plan(&rec).expect("expressible");
            p.vertices.iter().map(|v| (v.pos[0], v.pos[1])).collect::<Vec<_>>()
        };
        // A lone quad: (v0, v1, v2), (v0, v2, v3).
        assert_eq!(
            xs(1),
            [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
        );
        // Batched: (v0, v1, v3), (v1, v2, v3).
        assert_eq!(
            &xs(2)[..6],
            [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
        );
    }
}
