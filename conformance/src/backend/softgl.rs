//! softgl itself, in process, through its public API.

use super::{Backend, Compiles, Outcome, Timing};
use crate::call::Call;
use crate::scenes::Scene;
use softgl::fbo::FramebufferTarget;
use softgl::{Context, Framebuffer, FramebufferDesc, GlError, GlResult, QueryTarget, VertexArrays};
use std::collections::HashMap;
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
        let mut gl = match context(desc, rec.accum) {
            Ok(gl) => gl,
            Err(e) => return Outcome::Failed(format!("context: {e}")),
        };
        gl.set_backend(self.backend);
        gl.set_ordered_dither(self.dither);
        let mut lists = Replayer::default();
        let mut frame = |gl: &mut Context| {
            let t = Instant::now();
            for c in &rec.calls {
                // GL errors are part of what a scene may provoke; they are
                // not this harness's business (the API tests pin them).
                let _ = lists.call(gl, c);
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

/// A context for `desc`, with an accumulation buffer (16 bits a channel,
/// as OSMesa gives for any accumulation bits) when `accum`.
pub fn context(desc: FramebufferDesc, accum: bool) -> GlResult<Context> {
    if accum {
        Ok(Context::with_framebuffer(Framebuffer::new(desc)?.with_accum_buffer()?))
    } else {
        Context::new(desc)
    }
}

/// Display lists, which softgl's Rust API does not have (they are its C
/// ABI's, `osmesa/src/gl/lists.rs`): the calls between `NewList` and
/// `EndList` are kept (a `Bitmap`'s bits with them, as GL copies them at
/// compile time) and replayed by `CallList`/`CallLists`. Every other call
/// goes to [`replay`].
#[derive(Debug, Default)]
pub struct Replayer {
    lists: HashMap<u32, Vec<Call>>,
    compiling: Option<(u32, Vec<Call>)>,
    base: u32,
    depth: usize,
}

/// GL's `GL_MAX_LIST_NESTING` (Mesa's is 64).
const MAX_LIST_NESTING: usize = 64;

impl Replayer {
    /// Makes (or, inside `NewList`…`EndList`, compiles) one call.
    pub fn call(&mut self, gl: &mut Context, c: &Call) -> GlResult {
        if let Some((_, list)) = &mut self.compiling {
            return match c {
                Call::EndList => {
                    let (name, list) = self.compiling.take().expect("compiling");
                    self.lists.insert(name, list);
                    Ok(())
                }
                Call::NewList(_) => Err(GlError::InvalidOperation),
                _ => {
                    list.push(c.clone());
                    Ok(())
                }
            };
        }
        match c {
            Call::NewList(0) => Err(GlError::InvalidValue),
            Call::NewList(name) => {
                self.compiling = Some((*name, Vec::new()));
                Ok(())
            }
            Call::EndList => Err(GlError::InvalidOperation),
            Call::CallList(name) => self.call_list(gl, *name),
            Call::ListBase(b) => {
                self.base = *b;
                Ok(())
            }
            Call::CallLists(names) => {
                for &n in names {
                    self.call_list(gl, self.base.wrapping_add(u32::from(n)))?;
                }
                Ok(())
            }
            _ => replay(gl, c),
        }
    }

    fn call_list(&mut self, gl: &mut Context, name: u32) -> GlResult {
        if self.depth >= MAX_LIST_NESTING {
            return Ok(());
        }
        let Some(list) = self.lists.get(&name).cloned() else {
            return Ok(());
        };
        self.depth += 1;
        for c in &list {
            let _ = self.call(gl, c);
        }
        self.depth -= 1;
        Ok(())
    }
}

/// Makes one call on a softgl context (display-list calls are
/// [`Replayer`]'s: here they are `InvalidOperation`).
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
        Call::BindFramebuffer(t, name) => gl.bind_framebuffer(*t, *name),
        Call::BindRenderbuffer(name) => gl.bind_renderbuffer(*name),
        Call::RenderbufferStorage {
            samples,
            format,
            size: [w, h],
        } => {
            // The C ABI's checks before the Rust call (`osmesa/src/gl/fbo.rs`).
            if *samples > softgl::fbo::MAX_SAMPLES as i32 {
                return recorded(gl, Err(GlError::InvalidOperation));
            }
            gl.renderbuffer_storage(*samples, *format, *w, *h)
        }
        Call::FramebufferRenderbuffer(t, p, name) => gl.framebuffer_renderbuffer(*t, *p, *name),
        Call::FramebufferTexture2D(t, p, target, name, level) => {
            gl.framebuffer_texture(*t, *p, Some(*target), *name, *level, 0)
        }
        Call::BlitFramebuffer { src, dst, mask, filter } => {
            // The C ABI checks completeness first, as Mesa's `main/blit.c`.
            if !gl.framebuffers_complete() {
                return recorded(gl, Err(GlError::InvalidFramebufferOperation));
            }
            gl.blit_framebuffer(*src, *dst, *mask, *filter)
        }
        Call::GenerateMipmap(t) => gl.generate_mipmap(*t),
        Call::DeleteFramebuffer(name) => gl.delete_framebuffers(&[*name]),
        Call::DeleteRenderbuffer(name) => gl.delete_renderbuffers(&[*name]),
        Call::DeleteTexture(name) => {
            gl.delete_textures(&[*name]);
            Ok(())
        }
        Call::BeginQuery(name) => {
            let r = gl.queries_mut().begin(QueryTarget::SamplesPassed, *name);
            recorded(gl, r)
        }
        Call::EndQuery => {
            let r = gl.queries_mut().end(QueryTarget::SamplesPassed);
            recorded(gl, r)
        }
        Call::ClearColorFromQuery(name) => {
            let n = gl.query_result(*name)?;
            let [r, g, b] = query_color(n);
            gl.clear_color(r, g, b, 1.0)
        }
        Call::RasterPos([x, y, z, w]) => gl.raster_pos(*x, *y, *z, *w),
        Call::WindowPos([x, y, z]) => gl.window_pos(*x, *y, *z),
        Call::Bitmap {
            size: [w, h],
            orig,
            moves,
            bits,
        } => {
            let image = softgl::pixel_rect::BitmapImage::unpack(*w, *h, bits, &softgl::PixelStore::default());
            let image = recorded(gl, image)?;
            gl.bitmap(&image, *orig, *moves)
        }
        Call::DrawPixels {
            size: [w, h],
            kind,
            format,
            ty,
            pixels,
        } => {
            use softgl::pixel_rect::DrawKind;
            // The format the C ABI hands on for each kind (`draw_format`).
            let format = match kind {
                DrawKind::Color => *format,
                DrawKind::DepthStencil => softgl::PixelFormat::DepthStencil,
                _ => softgl::PixelFormat::DepthComponent,
            };
            let data = softgl::PixelData {
                format,
                ty: *ty,
                store: softgl::PixelStore::default(),
                bytes: pixels,
            };
            gl.draw_pixels(*w, *h, *kind, &data)
        }
        Call::PixelZoom(x, y) => gl.pixel_zoom(*x, *y),
        Call::PixelTransfer(p) => gl.pixel_transfer(*p),
        Call::CopyPixels {
            at: [x, y],
            size: [w, h],
            kind,
        } => gl.copy_pixels(*x, *y, *w, *h, *kind),
        Call::Accum(op, v) => gl.accum(*op, *v),
        Call::ClearAccum([r, g, b, a]) => gl.clear_accum(*r, *g, *b, *a),
        Call::NewList(_) | Call::EndList | Call::CallList(_) | Call::ListBase(_) | Call::CallLists(_) => {
            Err(GlError::InvalidOperation)
        }
    }
}

/// `r`, its error recorded for `glGetError` as the C ABI records it.
fn recorded<T>(gl: &mut Context, r: GlResult<T>) -> GlResult<T> {
    if let Err(e) = &r {
        gl.record_error(*e);
    }
    r
}

/// The clear colour that writes count `n` into a pixel: its low three
/// bytes as red, green and blue (exact: `b / 255` converts back to `b`).
pub fn query_color(n: u64) -> [f32; 3] {
    [0, 8, 16].map(|s| ((n >> s) & 0xff) as f32 / 255.0)
}

/// `FramebufferTarget` as GL names it.
pub fn framebuffer_target_gl(t: FramebufferTarget) -> u32 {
    match t {
        FramebufferTarget::Both => 0x8D40,
        FramebufferTarget::Draw => 0x8CA9,
        FramebufferTarget::Read => 0x8CA8,
    }
}
