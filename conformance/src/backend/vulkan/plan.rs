//! GL's state machine on the CPU, as far as the scenes use it: matrices,
//! primitive assembly, flat colours and clamping, turned into the frame's
//! Vulkan work (clears and draws over one vertex buffer, each draw with the
//! [`PipeKey`] of its pipeline).

use crate::call::Call;
use crate::scenes::Recording;
use ash::vk;
use glam::{Mat4, Vec3, Vec4};
use softgl::{
    BlendEquation, BlendFactor, Capability, CompareFunc, Face, FrontFace, LogicOp, MatrixMode, PolygonMode,
    PrimitiveMode, ShadeModel, StencilOp,
};
use std::collections::HashMap;

/// The pipeline state one draw needs (everything but viewport and scissor).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(super) struct PipeKey {
    pub(super) depth_test: bool,
    pub(super) depth_write: bool,
    pub(super) depth_func: CompareFunc,
    pub(super) stencil_test: bool,
    pub(super) stencil_func: CompareFunc,
    pub(super) stencil_ref: u32,
    pub(super) stencil_value_mask: u32,
    pub(super) stencil_write_mask: u32,
    pub(super) stencil_ops: [StencilOp; 3],
    pub(super) blend: bool,
    pub(super) blend_factors: [BlendFactor; 4],
    pub(super) blend_equations: [BlendEquation; 2],
    pub(super) blend_color: [u32; 4],
    pub(super) logic_op: Option<LogicOp>,
    pub(super) color_mask: [bool; 4],
    pub(super) cull: Option<Face>,
    pub(super) front_ccw: bool,
    pub(super) offset: Option<(u32, u32)>,
    pub(super) alpha: Option<(CompareFunc, u32)>,
    pub(super) flat: bool,
}

#[derive(Clone, Copy, Debug)]
pub(super) enum Op {
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
pub(super) struct Vertex {
    pub(super) pos: [f32; 4],
    pub(super) color: [f32; 4],
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
pub(super) struct Plan {
    pub(super) ops: Vec<Op>,
    pub(super) vertices: Vec<Vertex>,
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
pub(super) fn plan(rec: &Recording) -> Result<Plan, String> {
    let mut st = GlState::new(rec.width, rec.height);
    let mut plan = Plan {
        ops: Vec::new(),
        vertices: Vec::new(),
    };
    for c in &rec.calls {
        match c {
            Call::Enable(cap) => {
                if matches!(
                    cap,
                    Capability::Fog
                        | Capability::ColorSum
                        | Capability::Lighting
                        | Capability::ClipPlane(_)
                        | Capability::Texture(_)
                ) {
                    return Err(format!(
                        "{cap:?}: a fixed-function fragment stage this back end's pipelines do not have"
                    ));
                }
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
            // Without GL_FOG, GL_COLOR_SUM, GL_LIGHTING and the clip planes
            // (refused above) these change no pixel.
            Call::Fog(_)
            | Call::SecondaryColor(_)
            | Call::FogCoord(_)
            | Call::Normal(_)
            | Call::Light(..)
            | Call::LightModel(_)
            | Call::Material(..)
            | Call::ColorMaterial(..)
            | Call::ClipPlane(..) => {}
            // Without a texture enabled (refused above) these change no pixel.
            Call::ActiveTexture(_)
            | Call::BindTexture(..)
            | Call::TexImage { .. }
            | Call::TexParameter(..)
            | Call::TexEnv(_)
            | Call::TexGen(..)
            | Call::TexCoord(..) => {}
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
            Call::BindFramebuffer(..)
            | Call::BindRenderbuffer(_)
            | Call::RenderbufferStorage { .. }
            | Call::FramebufferRenderbuffer(..)
            | Call::FramebufferTexture2D(..)
            | Call::BlitFramebuffer { .. }
            | Call::GenerateMipmap(_)
            | Call::DeleteFramebuffer(_)
            | Call::DeleteRenderbuffer(_)
            | Call::DeleteTexture(_) => return Err("framebuffer objects and blits are not planned for Vulkan".into()),
            Call::BeginQuery(_) | Call::EndQuery | Call::ClearColorFromQuery(_) => {
                return Err("occlusion queries are not planned for Vulkan".into())
            }
            Call::RasterPos(_)
            | Call::WindowPos(_)
            | Call::Bitmap { .. }
            | Call::DrawPixels { .. }
            | Call::PixelZoom(..)
            | Call::PixelTransfer(_)
            | Call::CopyPixels { .. }
            | Call::Accum(..)
            | Call::ClearAccum(_) => {
                return Err("raster position, pixel rectangles and the accumulation buffer: GL 1.x only".into())
            }
            Call::NewList(_) | Call::EndList | Call::CallList(_) | Call::ListBase(_) | Call::CallLists(_) => {
                return Err("display lists: GL 1.x only".into())
            }
        }
    }
    Ok(plan)
}
