//! softgl itself, in process, through its public API.

use super::{Backend, Compiles, Outcome, Timing};
use crate::call::Call;
use crate::scenes::Scene;
use softgl::{Context, FramebufferDesc, GlResult, VertexArrays};
use std::time::Instant;

/// softgl with one fragment back end.
pub struct Softgl {
    backend: softgl::Backend,
    name: String,
    /// softgl's opt-in ordered dither (`Context::set_ordered_dither`), off by
    /// default: the report shows what it costs against llvmpipe, which never dithers.
    dither: bool,
}

impl Softgl {
    pub fn new(backend: softgl::Backend) -> Softgl {
        let name = match backend {
            softgl::Backend::Interpreter => "softgl-interp",
            softgl::Backend::Jit => "softgl-jit",
        };
        Softgl {
            backend,
            name: name.to_string(),
            dither: false,
        }
    }

    /// The JIT with the opt-in 4x4 ordered dither on ("softgl-jit-dither"):
    /// the error it buys on 5-6-5 buffers, on the report's plots.
    pub fn dithered() -> Softgl {
        Softgl {
            backend: softgl::Backend::Jit,
            name: "softgl-jit-dither".to_string(),
            dither: true,
        }
    }
}

impl Backend for Softgl {
    fn name(&self) -> &str {
        &self.name
    }

    fn probe(&self) -> Result<String, super::Unavailable> {
        Ok(format!(
            "softgl {} (in process, {} rasterizer threads)",
            env!("CARGO_PKG_VERSION"),
            softgl::raster::pool::default_threads()
        ))
    }

    fn render(&mut self, scene: &Scene, full: bool, runs: usize) -> Outcome {
        let rec = scene.record(full);
        let desc = FramebufferDesc {
            color: rec.color,
            ..FramebufferDesc::rgba8_d24s8(rec.width, rec.height)
        };
        let mut gl = match Context::new(desc) {
            Ok(gl) => gl,
            Err(e) => return Outcome::Failed(format!("context: {e}")),
        };
        gl.set_backend(self.backend);
        gl.set_ordered_dither(self.dither);
        let frame = |gl: &mut Context| {
            let t = Instant::now();
            for c in &rec.calls {
                // GL errors are part of what a scene may provoke; they are
                // not this harness's business (the API tests pin them).
                let _ = replay(gl, c);
            }
            let image = gl.framebuffer().to_rgba_image();
            (image, t.elapsed())
        };
        let (image, first) = frame(&mut gl);
        let after_first = gl.specialist_stats();
        let times: Vec<_> = (0..runs).map(|_| frame(&mut gl).1).collect();
        let end = gl.specialist_stats();
        let compiles = (self.backend == softgl::Backend::Jit).then_some(Compiles {
            first: after_first.misses,
            later: end.misses - after_first.misses,
            failures: end.failures,
            first_time: after_first.total_compile,
        });
        Outcome::Rendered {
            image,
            timing: Timing::measured(first, times, runs),
            compiles,
        }
    }
}

/// Makes one call on a softgl context.
pub fn replay(gl: &mut Context, c: &Call) -> GlResult {
    match c {
        Call::Enable(cap) => gl.enable(*cap),
        Call::Disable(cap) => gl.disable(*cap),
        Call::ClearColor([r, g, b, a]) => gl.clear_color(*r, *g, *b, *a),
        Call::ClearDepth(d) => gl.clear_depth(*d),
        Call::ClearStencil(s) => gl.clear_stencil(*s),
        Call::Clear(m) => gl.clear(*m),
        Call::Viewport([x, y, w, h]) => gl.viewport(*x, *y, *w, *h),
        Call::DepthRange(n, f) => gl.depth_range(*n, *f),
        Call::Scissor([x, y, w, h]) => gl.scissor(*x, *y, *w, *h),
        Call::MatrixMode(m) => gl.matrix_mode(*m),
        Call::LoadIdentity => gl.load_identity(),
        Call::LoadMatrix(m) => gl.load_matrix(&glam::Mat4::from_cols_array(m)),
        Call::PushMatrix => gl.push_matrix(),
        Call::PopMatrix => gl.pop_matrix(),
        Call::Translate([x, y, z]) => gl.translate(*x, *y, *z),
        Call::Scale([x, y, z]) => gl.scale(*x, *y, *z),
        Call::Rotate(a, [x, y, z]) => gl.rotate(*a, *x, *y, *z),
        Call::Frustum([l, r, b, t, n, f]) => gl.frustum(*l, *r, *b, *t, *n, *f),
        Call::Ortho([l, r, b, t, n, f]) => gl.ortho(*l, *r, *b, *t, *n, *f),
        Call::ShadeModel(m) => gl.shade_model(*m),
        Call::FrontFace(f) => gl.front_face(*f),
        Call::CullFace(f) => gl.cull_face(*f),
        Call::PolygonMode(f, m) => gl.polygon_mode(*f, *m),
        Call::PolygonOffset(f, u) => gl.polygon_offset(*f, *u),
        Call::PointSize(s) => gl.point_size(*s),
        Call::LineWidth(w) => gl.line_width(*w),
        Call::AlphaFunc(f, r) => gl.alpha_func(*f, *r),
        Call::StencilFunc(f, r, m) => gl.stencil_func(*f, *r, *m),
        Call::StencilOp(a, b, c) => gl.stencil_op(*a, *b, *c),
        Call::StencilMask(m) => gl.stencil_mask(*m),
        Call::DepthFunc(f) => gl.depth_func(*f),
        Call::DepthMask(m) => gl.depth_mask(*m),
        Call::BlendFunc(s, d) => gl.blend_func(*s, *d),
        Call::BlendFuncSeparate([a, b, c, d]) => gl.blend_func_separate(*a, *b, *c, *d),
        Call::BlendEquation(e) => gl.blend_equation(*e),
        Call::BlendColor([r, g, b, a]) => gl.blend_color(*r, *g, *b, *a),
        Call::LogicOp(o) => gl.logic_op(*o),
        Call::ColorMask([r, g, b, a]) => gl.color_mask(*r, *g, *b, *a),
        Call::Begin(m) => gl.begin(*m),
        Call::End => gl.end(),
        Call::Color([r, g, b, a]) => {
            gl.color4(*r, *g, *b, *a);
            Ok(())
        }
        Call::Vertex([x, y, z, w]) => {
            gl.vertex4(*x, *y, *z, *w);
            Ok(())
        }
        Call::Fog(p) => gl.fog(*p),
        Call::SecondaryColor([r, g, b]) => {
            gl.secondary_color3(*r, *g, *b);
            Ok(())
        }
        Call::FogCoord(c) => {
            gl.fog_coord(*c);
            Ok(())
        }
        Call::Normal([x, y, z]) => {
            gl.normal3(*x, *y, *z);
            Ok(())
        }
        Call::Light(i, p) => gl.light(*i, *p),
        Call::LightModel(p) => gl.light_model(*p),
        Call::Material(f, p) => gl.material(*f, *p),
        Call::ColorMaterial(f, m) => gl.color_material(*f, *m),
        Call::ClipPlane(i, p) => gl.clip_plane(*i, *p),
        Call::ActiveTexture(u) => gl.active_texture(*u),
        Call::BindTexture(t, name) => gl.bind_texture(*t, *name),
        Call::TexImage {
            target,
            level,
            internal,
            size,
            format,
            ty,
            pixels,
        } => {
            let data = softgl::PixelData {
                format: *format,
                ty: *ty,
                store: softgl::PixelStore::default(),
                bytes: pixels,
            };
            gl.tex_image(*target, *level, *internal, *size, 0, Some(data))
        }
        Call::TexParameter(t, p) => gl.tex_parameter(*t, *p),
        Call::TexEnv(p) => gl.tex_env(*p),
        Call::TexGen(c, p) => gl.tex_gen(*c, *p),
        Call::TexCoord(0, c) => {
            gl.tex_coord(*c);
            Ok(())
        }
        Call::TexCoord(u, c) => gl.multi_tex_coord(*u, *c),
        Call::DrawArrays {
            mode,
            positions,
            colors,
        } => {
            let pos: &[f32] = positions.as_flattened();
            let col: &[f32] = colors.as_flattened();
            gl.draw_arrays(*mode, 0, positions.len(), &VertexArrays::with_colors(4, pos, 4, col))
        }
    }
}
