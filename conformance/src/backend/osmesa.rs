//! Mesa's OSMesa (`libOSMesa.so.8` from Debian's `libosmesa6`), loaded at run
//! time. Runs inside a child process: the Gallium driver (`GALLIUM_DRIVER`)
//! is fixed when the library loads.

use super::softgl::{framebuffer_target_gl, query_color};
use super::{Outcome, Timing};
use crate::call::{clear_bits, Call};
use crate::scenes::Recording;
use softgl::fbo::{AttachmentPoint, BlitFilter, RenderbufferFormat};
use softgl::pixel_rect::{CopyKind, DrawKind};
use softgl::pixel_transfer::PixelTransferParam;
use softgl::texture::min_filter_to_gl;
use softgl::{ColorFormat, FogParam, GlEnum, LightModelParam, LightParam, MaterialParam};
use softgl::{MipFilter, TexEnvParam, TexGenParam, TexImageTarget, TexParam, TextureTarget};
use std::ffi::{c_char, c_void, CStr, CString};
use std::time::Instant;

type Ctx = *mut c_void;
const GL_RGBA: u32 = 0x1908;
const GL_UNSIGNED_BYTE: u32 = 0x1401;
const OSMESA_RGB_565: u32 = 0x5;
const GL_UNSIGNED_SHORT_5_6_5: u32 = 0x8363;
const GL_FLOAT: u32 = 0x1406;
const GL_VERTEX_ARRAY: u32 = 0x8074;
const GL_COLOR_ARRAY: u32 = 0x8076;
const GL_RENDERER: u32 = 0x1F01;
const GL_TEXTURE0: u32 = 0x84C0;
const GL_RENDERBUFFER: u32 = 0x8D41;
const GL_SAMPLES_PASSED: u32 = 0x8914;
const GL_QUERY_RESULT: u32 = 0x8866;
const GL_COMPILE: u32 = 0x1300;

/// The library name the loader looks for.
pub const LIBRARY: &str = "libOSMesa.so.8";

macro_rules! gl_fns {
    ($($name:ident ( $($arg:ty),* ) $(-> $ret:ty)?;)*) => {
        /// GL entry points, from `OSMesaGetProcAddress`.
        #[allow(non_snake_case)]
        struct Gl { $($name: unsafe extern "C" fn($($arg),*) $(-> $ret)?,)* }
        impl Gl {
            fn load(get: &dyn Fn(&CStr) -> *const c_void) -> Result<Gl, String> {
                Ok(Gl { $($name: {
                    let name = CString::new(stringify!($name)).expect("no NUL in a GL name");
                    let p = get(&name);
                    if p.is_null() {
                        return Err(format!("OSMesaGetProcAddress({}) returned NULL", stringify!($name)));
                    }
                    // SAFETY: Mesa returned this address for this GL entry point, whose C
                    // signature is the one declared here (from the GL 1.x specification).
                    unsafe { std::mem::transmute::<*const c_void, unsafe extern "C" fn($($arg),*) $(-> $ret)?>(p) }
                },)* })
            }
        }
    };
}

gl_fns! {
    glEnable(u32);
    glDisable(u32);
    glClearColor(f32, f32, f32, f32);
    glClearDepth(f64);
    glClearStencil(i32);
    glClear(u32);
    glViewport(i32, i32, i32, i32);
    glDepthRange(f64, f64);
    glScissor(i32, i32, i32, i32);
    glMatrixMode(u32);
    glLoadIdentity();
    glLoadMatrixf(*const f32);
    glPushMatrix();
    glPopMatrix();
    glTranslatef(f32, f32, f32);
    glScalef(f32, f32, f32);
    glRotatef(f32, f32, f32, f32);
    glFrustum(f64, f64, f64, f64, f64, f64);
    glOrtho(f64, f64, f64, f64, f64, f64);
    glShadeModel(u32);
    glFrontFace(u32);
    glCullFace(u32);
    glPolygonMode(u32, u32);
    glPolygonOffset(f32, f32);
    glPointSize(f32);
    glLineWidth(f32);
    glAlphaFunc(u32, f32);
    glStencilFunc(u32, i32, u32);
    glStencilOp(u32, u32, u32);
    glStencilMask(u32);
    glDepthFunc(u32);
    glDepthMask(u8);
    glBlendFuncSeparate(u32, u32, u32, u32);
    glBlendEquation(u32);
    glBlendColor(f32, f32, f32, f32);
    glLogicOp(u32);
    glColorMask(u8, u8, u8, u8);
    glBegin(u32);
    glEnd();
    glColor4f(f32, f32, f32, f32);
    glVertex4f(f32, f32, f32, f32);
    glFogf(u32, f32);
    glFogi(u32, i32);
    glFogfv(u32, *const f32);
    glSecondaryColor3f(f32, f32, f32);
    glFogCoordf(f32);
    glNormal3f(f32, f32, f32);
    glLightf(u32, u32, f32);
    glLightfv(u32, u32, *const f32);
    glLightModelfv(u32, *const f32);
    glLightModeli(u32, i32);
    glMaterialf(u32, u32, f32);
    glMaterialfv(u32, u32, *const f32);
    glColorMaterial(u32, u32);
    glClipPlane(u32, *const f64);
    glEnableClientState(u32);
    glDisableClientState(u32);
    glVertexPointer(i32, u32, i32, *const c_void);
    glColorPointer(i32, u32, i32, *const c_void);
    glDrawArrays(u32, i32, i32);
    glFinish();
    glGetString(u32) -> *const u8;
    glActiveTexture(u32);
    glBindTexture(u32, u32);
    glTexImage1D(u32, i32, i32, i32, i32, u32, u32, *const c_void);
    glTexImage2D(u32, i32, i32, i32, i32, i32, u32, u32, *const c_void);
    glTexImage3D(u32, i32, i32, i32, i32, i32, i32, u32, u32, *const c_void);
    glTexParameteri(u32, u32, i32);
    glTexParameterf(u32, u32, f32);
    glTexParameterfv(u32, u32, *const f32);
    glTexEnvi(u32, u32, i32);
    glTexEnvf(u32, u32, f32);
    glTexEnvfv(u32, u32, *const f32);
    glTexGeni(u32, u32, i32);
    glTexGenfv(u32, u32, *const f32);
    glMultiTexCoord4f(u32, f32, f32, f32, f32);
    glBindFramebuffer(u32, u32);
    glBindRenderbuffer(u32, u32);
    glRenderbufferStorageMultisample(u32, i32, u32, i32, i32);
    glFramebufferRenderbuffer(u32, u32, u32, u32);
    glFramebufferTexture2D(u32, u32, u32, u32, i32);
    glBlitFramebuffer(i32, i32, i32, i32, i32, i32, i32, i32, u32, u32);
    glGenerateMipmap(u32);
    glDeleteFramebuffers(i32, *const u32);
    glDeleteRenderbuffers(i32, *const u32);
    glDeleteTextures(i32, *const u32);
    glBeginQuery(u32, u32);
    glEndQuery(u32);
    glGetQueryObjectuiv(u32, u32, *mut u32);
    glRasterPos4f(f32, f32, f32, f32);
    glWindowPos3f(f32, f32, f32);
    glBitmap(i32, i32, f32, f32, f32, f32, *const u8);
    glDrawPixels(i32, i32, u32, u32, *const c_void);
    glPixelZoom(f32, f32);
    glPixelTransferf(u32, f32);
    glCopyPixels(i32, i32, i32, i32, u32);
    glAccum(u32, f32);
    glClearAccum(f32, f32, f32, f32);
    glNewList(u32, u32);
    glEndList();
    glCallList(u32);
    glListBase(u32);
    glCallLists(i32, u32, *const c_void);
    glGetError() -> u32;
}

type CreateContextExt = unsafe extern "C" fn(u32, i32, i32, i32, Ctx) -> Ctx;
type MakeCurrent = unsafe extern "C" fn(Ctx, *mut c_void, u32, i32, i32) -> u8;
type DestroyContext = unsafe extern "C" fn(Ctx);
type GetProcAddress = unsafe extern "C" fn(*const c_char) -> *const c_void;

/// The loaded library and its OSMesa entry points.
pub struct OsMesa {
    create: CreateContextExt,
    make_current: MakeCurrent,
    destroy: DestroyContext,
    get_proc: GetProcAddress,
    _lib: libloading::Library,
}

impl OsMesa {
    /// Loads `libOSMesa.so.8`, or says why not.
    pub fn load() -> Result<OsMesa, String> {
        // SAFETY: loading Mesa runs its initialisers, which are sound to run in
        // any process; the library stays loaded for as long as `OsMesa` lives.
        let lib = unsafe { libloading::Library::new(LIBRARY) }
            .map_err(|e| format!("{LIBRARY} is not installed ({e}); install Debian's libosmesa6"))?;
        // SAFETY: these symbols are OSMesa's, with the C signatures of <GL/osmesa.h>.
        unsafe {
            let create = *lib
                .get::<CreateContextExt>(b"OSMesaCreateContextExt\0")
                .map_err(|e| e.to_string())?;
            let make_current = *lib
                .get::<MakeCurrent>(b"OSMesaMakeCurrent\0")
                .map_err(|e| e.to_string())?;
            let destroy = *lib
                .get::<DestroyContext>(b"OSMesaDestroyContext\0")
                .map_err(|e| e.to_string())?;
            let get_proc = *lib
                .get::<GetProcAddress>(b"OSMesaGetProcAddress\0")
                .map_err(|e| e.to_string())?;
            Ok(OsMesa {
                create,
                make_current,
                destroy,
                get_proc,
                _lib: lib,
            })
        }
    }

    /// A current context with 24-bit depth and 8-bit stencil drawing into its
    /// own `width` x `height` buffer of `color` (RGBA8 or RGB 5-6-5).
    pub fn context(&self, width: u32, height: u32, color: ColorFormat, accum: bool) -> Result<Context<'_>, String> {
        let (format, ty) = match color {
            ColorFormat::Rgba8 => (GL_RGBA, GL_UNSIGNED_BYTE),
            ColorFormat::Rgb565 => (OSMESA_RGB_565, GL_UNSIGNED_SHORT_5_6_5),
            other => return Err(format!("no OSMesa buffer set up for {other:?}")),
        };
        // SAFETY: plain OSMesa call; a NULL share list is allowed.
        let ctx = unsafe { (self.create)(format, 24, 8, if accum { 16 } else { 0 }, std::ptr::null_mut()) };
        if ctx.is_null() {
            return Err("OSMesaCreateContextExt failed".into());
        }
        let bpp = color.bytes_per_pixel();
        let mut buffer = vec![0u8; width as usize * height as usize * bpp].into_boxed_slice();
        // SAFETY: `buffer` holds width*height pixels of `color` and outlives the
        // context (both are dropped together by `Context`, the context first).
        let ok = unsafe { (self.make_current)(ctx, buffer.as_mut_ptr().cast(), ty, width as i32, height as i32) };
        if ok == 0 {
            // SAFETY: `ctx` came from OSMesaCreateContextExt and is not current.
            unsafe { (self.destroy)(ctx) };
            return Err("OSMesaMakeCurrent failed".into());
        }
        let get = |name: &CStr| {
            // SAFETY: `name` is NUL-terminated; a context is current.
            unsafe { (self.get_proc)(name.as_ptr()) }
        };
        let gl = Gl::load(&get)?;
        Ok(Context {
            mesa: self,
            ctx,
            buffer,
            color,
            width,
            height,
            gl,
        })
    }
}

/// A current OSMesa context and the buffer it draws into.
pub struct Context<'m> {
    mesa: &'m OsMesa,
    ctx: Ctx,
    buffer: Box<[u8]>,
    color: ColorFormat,
    width: u32,
    height: u32,
    gl: Gl,
}

impl Drop for Context<'_> {
    fn drop(&mut self) {
        // SAFETY: `ctx` came from OSMesaCreateContextExt; the buffer is freed after this.
        unsafe { (self.mesa.destroy)(self.ctx) };
    }
}

impl Context<'_> {
    /// `GL_RENDERER`, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
    pub fn renderer(&self) -> String {
        // SAFETY: the context is current; glGetString returns a static C string or NULL.
        unsafe {
            let p = (self.gl.glGetString)(GL_RENDERER);
            if p.is_null() {
                String::new()
            } else {
                CStr::from_ptr(p.cast()).to_string_lossy().into_owned()
            }
        }
    }

    /// Makes every call, waits for the driver, and returns the image top row first.
    pub fn frame(&mut self, calls: &[Call]) -> image::RgbaImage {
        // `SOFTGL_CONFORMANCE_GL_ERRORS=1`: each GL error on stderr, with the call.
        let errors = std::env::var_os("SOFTGL_CONFORMANCE_GL_ERRORS").is_some();
        let mut inside = false;
        for (i, c) in calls.iter().enumerate() {
            self.call(c);
            match c {
                Call::Begin(_) => inside = true,
                Call::End => inside = false,
                _ => {}
            }
            // glGetError is itself an error between glBegin and glEnd.
            if errors && !inside {
                // SAFETY: the context is current.
                let e = unsafe { (self.gl.glGetError)() };
                if e != 0 {
                    eprintln!("GL error 0x{e:04X} after call {i}: {c:?}");
                }
            }
        }
        // SAFETY: the context is current.
        unsafe { (self.gl.glFinish)() };
        // OSMesa renders y up: row 0 of the buffer is the bottom row.
        let (w, h) = (self.width, self.height);
        let row = w as usize * self.color.bytes_per_pixel();
        let mut out = Vec::with_capacity(w as usize * h as usize * 4);
        for y in (0..h as usize).rev() {
            let line = &self.buffer[y * row..(y + 1) * row];
            if self.color == ColorFormat::Rgb565 {
                // To RGBA8 by bit replication, as softgl's `to_rgba_image` reads 5-6-5.
                for p in line.chunks_exact(2).map(|p| u16::from_le_bytes([p[0], p[1]])) {
                    let (r, g, b) = (p >> 11, (p >> 5) & 63, p & 31);
                    out.extend([(r << 3) | (r >> 2), (g << 2) | (g >> 4), (b << 3) | (b >> 2), 255].map(|c| c as u8));
                }
            } else {
                out.extend_from_slice(line);
            }
        }
        image::RgbaImage::from_raw(w, h, out).expect("buffer is w*h*4 bytes")
    }

    fn call(&mut self, c: &Call) {
        let g = &self.gl;
        let b = |v: bool| v as u8;
        // SAFETY: the context is current, and every argument is a plain value
        // of the type the GL entry point takes (pointers: see DrawArrays).
        unsafe {
            match c {
                Call::Enable(cap) => (g.glEnable)(cap.to_gl()),
                Call::Disable(cap) => (g.glDisable)(cap.to_gl()),
                Call::ClearColor([r, gg, bb, a]) => (g.glClearColor)(*r, *gg, *bb, *a),
                Call::ClearDepth(d) => (g.glClearDepth)(*d),
                Call::ClearStencil(s) => (g.glClearStencil)(*s),
                Call::Clear(m) => (g.glClear)(clear_bits(*m)),
                Call::Viewport([x, y, w, h]) => (g.glViewport)(*x, *y, *w, *h),
                Call::DepthRange(n, f) => (g.glDepthRange)(*n, *f),
                Call::Scissor([x, y, w, h]) => (g.glScissor)(*x, *y, *w, *h),
                Call::MatrixMode(m) => (g.glMatrixMode)(m.to_gl()),
                Call::LoadIdentity => (g.glLoadIdentity)(),
                Call::LoadMatrix(m) => (g.glLoadMatrixf)(m.as_ptr()),
                Call::PushMatrix => (g.glPushMatrix)(),
                Call::PopMatrix => (g.glPopMatrix)(),
                Call::Translate([x, y, z]) => (g.glTranslatef)(*x, *y, *z),
                Call::Scale([x, y, z]) => (g.glScalef)(*x, *y, *z),
                Call::Rotate(a, [x, y, z]) => (g.glRotatef)(*a, *x, *y, *z),
                Call::Frustum([l, r, bo, t, n, f]) => (g.glFrustum)(*l, *r, *bo, *t, *n, *f),
                Call::Ortho([l, r, bo, t, n, f]) => (g.glOrtho)(*l, *r, *bo, *t, *n, *f),
                Call::ShadeModel(m) => (g.glShadeModel)(m.to_gl()),
                Call::FrontFace(f) => (g.glFrontFace)(f.to_gl()),
                Call::CullFace(f) => (g.glCullFace)(f.to_gl()),
                Call::PolygonMode(f, m) => (g.glPolygonMode)(f.to_gl(), m.to_gl()),
                Call::PolygonOffset(f, u) => (g.glPolygonOffset)(*f, *u),
                Call::PointSize(s) => (g.glPointSize)(*s),
                Call::LineWidth(w) => (g.glLineWidth)(*w),
                Call::AlphaFunc(f, r) => (g.glAlphaFunc)(f.to_gl(), *r),
                Call::StencilFunc(f, r, m) => (g.glStencilFunc)(f.to_gl(), *r, *m),
                Call::StencilOp(a, bb, cc) => (g.glStencilOp)(a.to_gl(), bb.to_gl(), cc.to_gl()),
                Call::StencilMask(m) => (g.glStencilMask)(*m),
                Call::DepthFunc(f) => (g.glDepthFunc)(f.to_gl()),
                Call::DepthMask(m) => (g.glDepthMask)(b(*m)),
                Call::BlendFunc(s, d) => (g.glBlendFuncSeparate)(s.to_gl(), d.to_gl(), s.to_gl(), d.to_gl()),
                Call::BlendFuncSeparate([s, d, sa, da]) => {
                    (g.glBlendFuncSeparate)(s.to_gl(), d.to_gl(), sa.to_gl(), da.to_gl())
                }
                Call::BlendEquation(q) => (g.glBlendEquation)(q.to_gl()),
                Call::BlendColor([r, gg, bb, a]) => (g.glBlendColor)(*r, *gg, *bb, *a),
                Call::LogicOp(o) => (g.glLogicOp)(o.to_gl()),
                Call::ColorMask([r, gg, bb, a]) => (g.glColorMask)(b(*r), b(*gg), b(*bb), b(*a)),
                Call::Begin(m) => (g.glBegin)(m.to_gl()),
                Call::End => (g.glEnd)(),
                Call::Color([r, gg, bb, a]) => (g.glColor4f)(*r, *gg, *bb, *a),
                Call::Vertex([x, y, z, w]) => (g.glVertex4f)(*x, *y, *z, *w),
                Call::Fog(p) => match p {
                    FogParam::Mode(m) => (g.glFogi)(0x0B65, m.to_gl() as i32), // GL_FOG_MODE
                    FogParam::Density(d) => (g.glFogf)(0x0B62, *d),
                    FogParam::Start(v) => (g.glFogf)(0x0B63, *v),
                    FogParam::End(v) => (g.glFogf)(0x0B64, *v),
                    FogParam::Color(c) => (g.glFogfv)(0x0B66, c.as_ptr()),
                    FogParam::Index(i) => (g.glFogf)(0x0B61, *i),
                    FogParam::CoordSrc(s) => (g.glFogi)(0x8450, s.to_gl() as i32), // GL_FOG_COORD_SRC
                },
                Call::SecondaryColor([r, gg, bb]) => (g.glSecondaryColor3f)(*r, *gg, *bb),
                Call::FogCoord(c) => (g.glFogCoordf)(*c),
                Call::Normal([x, y, z]) => (g.glNormal3f)(*x, *y, *z),
                Call::Light(i, p) => {
                    let light = 0x4000 + i; // GL_LIGHT0 + i
                    match p {
                        LightParam::Ambient(v) => (g.glLightfv)(light, 0x1200, v.as_ptr()),
                        LightParam::Diffuse(v) => (g.glLightfv)(light, 0x1201, v.as_ptr()),
                        LightParam::Specular(v) => (g.glLightfv)(light, 0x1202, v.as_ptr()),
                        LightParam::Position(v) => (g.glLightfv)(light, 0x1203, v.as_ptr()),
                        LightParam::SpotDirection(v) => (g.glLightfv)(light, 0x1204, v.as_ptr()),
                        LightParam::SpotExponent(v) => (g.glLightf)(light, 0x1205, *v),
                        LightParam::SpotCutoff(v) => (g.glLightf)(light, 0x1206, *v),
                        LightParam::ConstantAttenuation(v) => (g.glLightf)(light, 0x1207, *v),
                        LightParam::LinearAttenuation(v) => (g.glLightf)(light, 0x1208, *v),
                        LightParam::QuadraticAttenuation(v) => (g.glLightf)(light, 0x1209, *v),
                    }
                }
                Call::LightModel(p) => match p {
                    LightModelParam::Ambient(v) => (g.glLightModelfv)(0x0B53, v.as_ptr()),
                    LightModelParam::LocalViewer(on) => (g.glLightModeli)(0x0B51, i32::from(*on)),
                    LightModelParam::TwoSide(on) => (g.glLightModeli)(0x0B52, i32::from(*on)),
                    LightModelParam::ColorControl(c) => (g.glLightModeli)(0x81F8, c.to_gl() as i32),
                },
                Call::Material(face, p) => {
                    let f = face.to_gl();
                    match p {
                        MaterialParam::Ambient(v) => (g.glMaterialfv)(f, 0x1200, v.as_ptr()),
                        MaterialParam::Diffuse(v) => (g.glMaterialfv)(f, 0x1201, v.as_ptr()),
                        MaterialParam::Specular(v) => (g.glMaterialfv)(f, 0x1202, v.as_ptr()),
                        MaterialParam::Emission(v) => (g.glMaterialfv)(f, 0x1600, v.as_ptr()),
                        MaterialParam::AmbientAndDiffuse(v) => (g.glMaterialfv)(f, 0x1602, v.as_ptr()),
                        MaterialParam::Shininess(s) => (g.glMaterialf)(f, 0x1601, *s),
                    }
                }
                Call::ColorMaterial(face, mode) => (g.glColorMaterial)(face.to_gl(), mode.to_gl()),
                Call::ClipPlane(i, p) => (g.glClipPlane)(0x3000 + i, p.as_ptr()), // GL_CLIP_PLANE0 + i
                Call::ActiveTexture(u) => (g.glActiveTexture)(GL_TEXTURE0 + u),
                Call::BindTexture(t, name) => (g.glBindTexture)(t.to_gl(), *name),
                Call::TexImage {
                    target,
                    level,
                    internal,
                    size: [w, h, d],
                    format,
                    ty,
                    pixels,
                } => {
                    // Read during the call only, while `pixels` is borrowed.
                    let (t, i, f, ty, p) = (
                        target.to_gl(),
                        internal.to_gl() as i32,
                        format.to_gl(),
                        ty.to_gl(),
                        pixels.as_ptr().cast(),
                    );
                    match target {
                        TexImageTarget::D1 | TexImageTarget::Proxy(TextureTarget::D1) => {
                            (g.glTexImage1D)(t, *level, i, *w, 0, f, ty, p)
                        }
                        TexImageTarget::D3 | TexImageTarget::Proxy(TextureTarget::D3) => {
                            (g.glTexImage3D)(t, *level, i, *w, *h, *d, 0, f, ty, p)
                        }
                        _ => (g.glTexImage2D)(t, *level, i, *w, *h, 0, f, ty, p),
                    }
                }
                Call::TexParameter(target, p) => {
                    let t = target.to_gl();
                    let int = |pname: u32, v: u32| (g.glTexParameteri)(t, pname, v as i32);
                    match p {
                        TexParam::MinFilter(f, m) => int(0x2801, min_filter_to_gl(*f, *m)),
                        TexParam::MagFilter(f) => int(0x2800, min_filter_to_gl(*f, MipFilter::None)),
                        TexParam::WrapS(w) => int(0x2802, w.to_gl()),
                        TexParam::WrapT(w) => int(0x2803, w.to_gl()),
                        TexParam::WrapR(w) => int(0x8072, w.to_gl()),
                        TexParam::BorderColor(c) => (g.glTexParameterfv)(t, 0x1004, c.as_ptr()),
                        TexParam::MinLod(v) => (g.glTexParameterf)(t, 0x813A, *v),
                        TexParam::MaxLod(v) => (g.glTexParameterf)(t, 0x813B, *v),
                        TexParam::BaseLevel(v) => (g.glTexParameteri)(t, 0x813C, *v),
                        TexParam::MaxLevel(v) => (g.glTexParameteri)(t, 0x813D, *v),
                        TexParam::LodBias(v) => (g.glTexParameterf)(t, 0x8501, *v),
                        // GL_COMPARE_R_TO_TEXTURE or GL_NONE
                        TexParam::CompareMode(on) => int(0x884C, if *on { 0x884E } else { 0 }),
                        TexParam::CompareFunc(f) => int(0x884D, f.to_gl()),
                        TexParam::DepthMode(m) => int(0x884B, m.to_gl()),
                        TexParam::Priority(v) => (g.glTexParameterf)(t, 0x8066, *v),
                        TexParam::GenerateMipmap(on) => int(0x8191, u32::from(*on)),
                        // Query only: GL_INVALID_ENUM in Mesa too.
                        TexParam::Resident(_) => int(0x8067, 1),
                    }
                }
                Call::TexEnv(p) => {
                    const ENV: u32 = 0x2300; // GL_TEXTURE_ENV
                    let int = |pname: u32, v: u32| (g.glTexEnvi)(ENV, pname, v as i32);
                    match p {
                        TexEnvParam::Mode(m) => int(0x2200, m.to_gl()),
                        TexEnvParam::Color(c) => (g.glTexEnvfv)(ENV, 0x2201, c.as_ptr()),
                        TexEnvParam::CombineRgb(f) => int(0x8571, f.to_gl()),
                        TexEnvParam::CombineAlpha(f) => int(0x8572, f.to_gl()),
                        TexEnvParam::SrcRgb(n, src) => int(0x8580 + u32::from(*n), src.to_gl()),
                        TexEnvParam::SrcAlpha(n, src) => int(0x8588 + u32::from(*n), src.to_gl()),
                        TexEnvParam::OperandRgb(n, o) => int(0x8590 + u32::from(*n), o.to_gl()),
                        TexEnvParam::OperandAlpha(n, o) => int(0x8598 + u32::from(*n), o.to_gl()),
                        TexEnvParam::RgbScale(v) => (g.glTexEnvf)(ENV, 0x8573, *v),
                        TexEnvParam::AlphaScale(v) => (g.glTexEnvf)(ENV, 0x0D1C, *v),
                        // GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS
                        TexEnvParam::LodBias(v) => (g.glTexEnvf)(0x8500, 0x8501, *v),
                    }
                }
                Call::TexGen(coord, p) => {
                    let c = coord.to_gl();
                    match p {
                        TexGenParam::Mode(m) => (g.glTexGeni)(c, 0x2500, m.to_gl() as i32),
                        TexGenParam::ObjectPlane(v) => (g.glTexGenfv)(c, 0x2501, v.as_ptr()),
                        TexGenParam::EyePlane(v) => (g.glTexGenfv)(c, 0x2502, v.as_ptr()),
                    }
                }
                Call::TexCoord(u, [s, t, r, q]) => (g.glMultiTexCoord4f)(GL_TEXTURE0 + u, *s, *t, *r, *q),
                Call::DrawArrays {
                    mode,
                    positions,
                    colors,
                } => {
                    // The arrays are read during glDrawArrays only, while they are borrowed.
                    let n = positions.len().min(colors.len()) as i32;
                    (g.glEnableClientState)(GL_VERTEX_ARRAY);
                    (g.glEnableClientState)(GL_COLOR_ARRAY);
                    (g.glVertexPointer)(4, GL_FLOAT, 0, positions.as_ptr().cast());
                    (g.glColorPointer)(4, GL_FLOAT, 0, colors.as_ptr().cast());
                    (g.glDrawArrays)(mode.to_gl(), 0, n);
                    (g.glDisableClientState)(GL_VERTEX_ARRAY);
                    (g.glDisableClientState)(GL_COLOR_ARRAY);
                }
                Call::BindFramebuffer(t, name) => (g.glBindFramebuffer)(framebuffer_target_gl(*t), *name),
                Call::BindRenderbuffer(name) => (g.glBindRenderbuffer)(GL_RENDERBUFFER, *name),
                Call::RenderbufferStorage {
                    samples,
                    format,
                    size: [w, h],
                } => (g.glRenderbufferStorageMultisample)(
                    GL_RENDERBUFFER,
                    *samples,
                    renderbuffer_format_gl(*format),
                    *w,
                    *h,
                ),
                Call::FramebufferRenderbuffer(t, p, name) => {
                    (g.glFramebufferRenderbuffer)(framebuffer_target_gl(*t), attachment_gl(*p), GL_RENDERBUFFER, *name)
                }
                Call::FramebufferTexture2D(t, p, target, name, level) => (g.glFramebufferTexture2D)(
                    framebuffer_target_gl(*t),
                    attachment_gl(*p),
                    target.to_gl(),
                    *name,
                    *level,
                ),
                Call::BlitFramebuffer { src, dst, mask, filter } => {
                    let m = clear_bits(softgl::ClearMask {
                        color: mask.color,
                        depth: mask.depth,
                        stencil: mask.stencil,
                        accum: false,
                    });
                    let f = match filter {
                        BlitFilter::Nearest => 0x2600,
                        BlitFilter::Linear => 0x2601,
                    };
                    (g.glBlitFramebuffer)(src[0], src[1], src[2], src[3], dst[0], dst[1], dst[2], dst[3], m, f)
                }
                Call::GenerateMipmap(t) => (g.glGenerateMipmap)(t.to_gl()),
                // Each reads one name during the call.
                Call::DeleteFramebuffer(name) => (g.glDeleteFramebuffers)(1, name),
                Call::DeleteRenderbuffer(name) => (g.glDeleteRenderbuffers)(1, name),
                Call::DeleteTexture(name) => (g.glDeleteTextures)(1, name),
                Call::BeginQuery(name) => (g.glBeginQuery)(GL_SAMPLES_PASSED, *name),
                Call::EndQuery => (g.glEndQuery)(GL_SAMPLES_PASSED),
                Call::ClearColorFromQuery(name) => {
                    let mut n = 0u32;
                    // Writes one value into `n`.
                    (g.glGetQueryObjectuiv)(*name, GL_QUERY_RESULT, &mut n);
                    let [r, gg, bb] = query_color(u64::from(n));
                    (g.glClearColor)(r, gg, bb, 1.0);
                }
                Call::RasterPos([x, y, z, w]) => (g.glRasterPos4f)(*x, *y, *z, *w),
                Call::WindowPos([x, y, z]) => (g.glWindowPos3f)(*x, *y, *z),
                Call::Bitmap {
                    size: [w, h],
                    orig,
                    moves,
                    bits,
                } => {
                    // `bits` holds the rows at the default unpack state; read during the call.
                    (g.glBitmap)(*w, *h, orig[0], orig[1], moves[0], moves[1], bits.as_ptr())
                }
                Call::DrawPixels {
                    size: [w, h],
                    kind,
                    format,
                    ty,
                    pixels,
                } => {
                    let f = match kind {
                        DrawKind::Color => format.to_gl(),
                        DrawKind::Index => 0x1900,        // GL_COLOR_INDEX
                        DrawKind::Depth => 0x1902,        // GL_DEPTH_COMPONENT
                        DrawKind::Stencil => 0x1901,      // GL_STENCIL_INDEX
                        DrawKind::DepthStencil => 0x84F9, // GL_DEPTH_STENCIL
                    };
                    // `pixels` holds the image at the default unpack state; read during the call.
                    (g.glDrawPixels)(*w, *h, f, ty.to_gl(), pixels.as_ptr().cast())
                }
                Call::PixelZoom(x, y) => (g.glPixelZoom)(*x, *y),
                Call::PixelTransfer(p) => {
                    let (pname, v) = pixel_transfer_gl(*p);
                    (g.glPixelTransferf)(pname, v)
                }
                Call::CopyPixels {
                    at: [x, y],
                    size: [w, h],
                    kind,
                } => {
                    let t = match kind {
                        CopyKind::Color => 0x1800,
                        CopyKind::Depth => 0x1801,
                        CopyKind::Stencil => 0x1802,
                        CopyKind::DepthStencil => 0x84F9,
                    };
                    (g.glCopyPixels)(*x, *y, *w, *h, t)
                }
                Call::Accum(op, v) => (g.glAccum)(op.to_gl(), *v),
                Call::ClearAccum([r, gg, bb, a]) => (g.glClearAccum)(*r, *gg, *bb, *a),
                Call::NewList(name) => (g.glNewList)(*name, GL_COMPILE),
                Call::EndList => (g.glEndList)(),
                Call::CallList(name) => (g.glCallList)(*name),
                Call::ListBase(base) => (g.glListBase)(*base),
                // Read during the call.
                Call::CallLists(names) => (g.glCallLists)(names.len() as i32, GL_UNSIGNED_BYTE, names.as_ptr().cast()),
            }
        }
    }
}

/// A renderbuffer format's GL name (the formats the scenes use; others GL_NONE).
fn renderbuffer_format_gl(f: RenderbufferFormat) -> u32 {
    use RenderbufferFormat as F;
    match f {
        F::Rgba => 0x1908,
        F::Rgba8 => 0x8058,
        F::Rgb => 0x1907,
        F::Rgb8 => 0x8051,
        F::Rgb565 => 0x8D62,
        F::DepthComponent => 0x1902,
        F::DepthComponent16 => 0x81A5,
        F::DepthComponent24 => 0x81A6,
        F::DepthComponent32 => 0x81A7,
        F::DepthStencil => 0x84F9,
        F::Depth24Stencil8 => 0x88F0,
        F::StencilIndex8 => 0x8D48,
        _ => 0,
    }
}

/// An attachment point's GL name.
fn attachment_gl(p: AttachmentPoint) -> u32 {
    match p {
        AttachmentPoint::Color(i) => 0x8CE0 + i,
        AttachmentPoint::Depth => 0x8D00,
        AttachmentPoint::Stencil => 0x8D20,
        AttachmentPoint::DepthStencil => 0x821A,
    }
}

/// `glPixelTransferf`'s name and value.
fn pixel_transfer_gl(p: PixelTransferParam) -> (u32, f32) {
    use PixelTransferParam as P;
    let scale = [0x0D14, 0x0D18, 0x0D1A, 0x0D1C];
    let bias = [0x0D15, 0x0D19, 0x0D1B, 0x0D1D];
    match p {
        P::MapColor(on) => (0x0D10, f32::from(u8::from(on))),
        P::MapStencil(on) => (0x0D11, f32::from(u8::from(on))),
        P::IndexShift(v) => (0x0D12, v as f32),
        P::IndexOffset(v) => (0x0D13, v as f32),
        P::Scale(c, v) => (scale[c.min(3)], v),
        P::Bias(c, v) => (bias[c.min(3)], v),
        P::DepthScale(v) => (0x0D1E, v),
        P::DepthBias(v) => (0x0D1F, v),
    }
}

/// Renders a recording in a fresh context: the first frame, then `runs` more.
pub fn render(mesa: &OsMesa, rec: &Recording, runs: usize) -> (Outcome, String) {
    let mut ctx = match mesa.context(rec.width, rec.height, rec.color, rec.accum) {
        Ok(c) => c,
        Err(e) => return (Outcome::Failed(e), String::new()),
    };
    let renderer = ctx.renderer();
    let t = Instant::now();
    let image = ctx.frame(&rec.calls);
    let first = t.elapsed();
    let times: Vec<_> = (0..runs)
        .map(|_| {
            let t = Instant::now();
            ctx.frame(&rec.calls);
            t.elapsed()
        })
        .collect();
    (
        Outcome::Rendered {
            image,
            timing: Timing::measured(first, times, runs),
            compiles: None,
        },
        renderer,
    )
}
