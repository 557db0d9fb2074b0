//! The one GL-shaped interface: a scene is recorded once as a list of
//! [`Call`]s, and every back end replays that list its own way.

use softgl::fbo::{AttachmentPoint, BlitFilter, BlitMask, FramebufferTarget, RenderbufferFormat};
use softgl::pixel_rect::{CopyKind, DrawKind};
use softgl::pixel_transfer::PixelTransferParam;
use softgl::AccumOp;
use softgl::{
    BlendEquation, BlendFactor, Capability, ClearMask, ColorMaterialMode, CompareFunc, Face, FogParam, FrontFace,
    InternalFormat, LightModelParam, LightParam, LogicOp, MaterialParam, MatrixMode, PixelFormat, PixelType,
    PolygonMode, PrimitiveMode, ShadeModel, StencilOp, TexCoordName, TexEnvParam, TexGenParam, TexImageTarget,
    TexParam, TextureTarget,
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
    /// `glFog*`: one parameter.
    Fog(FogParam),
    /// `glSecondaryColor3f`.
    SecondaryColor([f32; 3]),
    /// `glFogCoordf`.
    FogCoord(f32),
    /// `glNormal3f`.
    Normal([f32; 3]),
    /// `glLight*` on light `GL_LIGHT0 + index`.
    Light(u32, LightParam),
    /// `glLightModel*`.
    LightModel(LightModelParam),
    /// `glMaterial*`.
    Material(Face, MaterialParam),
    /// `glColorMaterial`.
    ColorMaterial(Face, ColorMaterialMode),
    /// `glClipPlane(GL_CLIP_PLANE0 + index, equation)`.
    ClipPlane(u32, [f64; 4]),
    /// `glActiveTexture(GL_TEXTURE0 + unit)`.
    ActiveTexture(u32),
    /// `glBindTexture` on the active unit; the scene picks the names (GL
    /// makes the object at its first bind).
    BindTexture(TextureTarget, u32),
    /// `glTexImage1D/2D/3D` (border 0) at GL's default unpack state: rows
    /// start on 4-byte boundaries, as [`Rec::tex_image`] lays them out.
    TexImage {
        target: TexImageTarget,
        level: i32,
        internal: InternalFormat,
        size: [i32; 3],
        format: PixelFormat,
        ty: PixelType,
        pixels: Vec<u8>,
    },
    /// `glTexParameter*` on the active unit's texture of a target.
    TexParameter(TextureTarget, TexParam),
    /// `glTexEnv*` on the active unit.
    TexEnv(TexEnvParam),
    /// `glTexGen*` on the active unit.
    TexGen(TexCoordName, TexGenParam),
    /// `glMultiTexCoord4f(GL_TEXTURE0 + unit, …)` (unit 0 is `glTexCoord4f`).
    TexCoord(u32, [f32; 4]),
    /// `glDrawArrays` over client arrays of 4-component positions and colours.
    DrawArrays {
        mode: PrimitiveMode,
        positions: Vec<[f32; 4]>,
        colors: Vec<[f32; 4]>,
    },
    // Framebuffer objects (ARB_framebuffer_object). The scene picks the
    // names: GL's compatibility profile makes an object at its first bind
    // (Mesa's `bind_framebuffer`, `bind_renderbuffer`).
    /// `glBindFramebuffer`.
    BindFramebuffer(FramebufferTarget, u32),
    /// `glBindRenderbuffer(GL_RENDERBUFFER, name)`.
    BindRenderbuffer(u32),
    /// `glRenderbufferStorageMultisample` on the bound renderbuffer
    /// (`samples` 0: `glRenderbufferStorage`).
    RenderbufferStorage {
        samples: i32,
        format: RenderbufferFormat,
        size: [i32; 2],
    },
    /// `glFramebufferRenderbuffer`.
    FramebufferRenderbuffer(FramebufferTarget, AttachmentPoint, u32),
    /// `glFramebufferTexture2D(target, point, tex_target, name, level)`.
    FramebufferTexture2D(FramebufferTarget, AttachmentPoint, TexImageTarget, u32, i32),
    /// `glBlitFramebuffer(src, dst, mask, filter)`, rectangles as `[x0, y0, x1, y1]`.
    BlitFramebuffer {
        src: [i32; 4],
        dst: [i32; 4],
        mask: BlitMask,
        filter: BlitFilter,
    },
    /// `glGenerateMipmap`.
    GenerateMipmap(TextureTarget),
    /// `glDeleteFramebuffers` of one name.
    DeleteFramebuffer(u32),
    /// `glDeleteRenderbuffers` of one name.
    DeleteRenderbuffer(u32),
    /// `glDeleteTextures` of one name.
    DeleteTexture(u32),
    // Occlusion queries (GL 1.5).
    /// `glBeginQuery(GL_SAMPLES_PASSED, name)`.
    BeginQuery(u32),
    /// `glEndQuery(GL_SAMPLES_PASSED)`.
    EndQuery,
    /// `glGetQueryObjectuiv(name, GL_QUERY_RESULT)`, then `glClearColor` of
    /// the count's bytes (red the low byte, green the next, blue the third,
    /// alpha 1): a scissored clear after it writes the count into the image,
    /// where the harness compares it with llvmpipe's.
    ClearColorFromQuery(u32),
    // Raster position, bitmaps and pixel rectangles.
    /// `glRasterPos4f`.
    RasterPos([f32; 4]),
    /// `glWindowPos3f`.
    WindowPos([f32; 3]),
    /// `glBitmap` of `bits` laid out at GL's default unpack state (rows
    /// padded to 4 bytes, most significant bit first).
    Bitmap {
        size: [i32; 2],
        orig: [f32; 2],
        moves: [f32; 2],
        bits: Vec<u8>,
    },
    /// `glDrawPixels` at GL's default unpack state; `kind` picks the GL
    /// format (`format` is the colour format of `DrawKind::Color`).
    DrawPixels {
        size: [i32; 2],
        kind: DrawKind,
        format: PixelFormat,
        ty: PixelType,
        pixels: Vec<u8>,
    },
    /// `glPixelZoom`.
    PixelZoom(f32, f32),
    /// `glPixelTransferf`.
    PixelTransfer(PixelTransferParam),
    /// `glCopyPixels(x, y, width, height, type)`.
    CopyPixels {
        at: [i32; 2],
        size: [i32; 2],
        kind: CopyKind,
    },
    /// `glAccum`.
    Accum(AccumOp, f32),
    /// `glClearAccum`.
    ClearAccum([f32; 4]),
    // Display lists.
    /// `glNewList(name, GL_COMPILE)`.
    NewList(u32),
    /// `glEndList`.
    EndList,
    /// `glCallList`.
    CallList(u32),
    /// `glListBase`.
    ListBase(u32),
    /// `glCallLists(n, GL_UNSIGNED_BYTE, names)`.
    CallLists(Vec<u8>),
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
    pub fn fog(&mut self, p: FogParam) -> &mut Self {
        self.call(Call::Fog(p))
    }
    pub fn secondary_color(&mut self, r: f32, g: f32, b: f32) -> &mut Self {
        self.call(Call::SecondaryColor([r, g, b]))
    }
    pub fn fog_coord(&mut self, c: f32) -> &mut Self {
        self.call(Call::FogCoord(c))
    }
    pub fn normal(&mut self, x: f32, y: f32, z: f32) -> &mut Self {
        self.call(Call::Normal([x, y, z]))
    }
    pub fn light(&mut self, index: u32, p: LightParam) -> &mut Self {
        self.call(Call::Light(index, p))
    }
    pub fn light_model(&mut self, p: LightModelParam) -> &mut Self {
        self.call(Call::LightModel(p))
    }
    pub fn material(&mut self, face: Face, p: MaterialParam) -> &mut Self {
        self.call(Call::Material(face, p))
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
    /// `glTexCoord2f`.
    pub fn tex_coord(&mut self, s: f32, t: f32) -> &mut Self {
        self.call(Call::TexCoord(0, [s, t, 0.0, 1.0]))
    }
    pub fn tex_parameter(&mut self, target: TextureTarget, p: TexParam) -> &mut Self {
        self.call(Call::TexParameter(target, p))
    }
    pub fn tex_env(&mut self, p: TexEnvParam) -> &mut Self {
        self.call(Call::TexEnv(p))
    }
    /// `glTexImage*` of unsigned bytes, `components` per texel, `size`
    /// texels, given tightly packed: rows are padded to GL's default
    /// 4-byte unpack alignment here.
    pub fn tex_image(
        &mut self,
        target: TexImageTarget,
        level: i32,
        internal: InternalFormat,
        format: PixelFormat,
        size: [i32; 3],
        texels: &[u8],
    ) -> &mut Self {
        let components = format.components().len();
        let row = size[0] as usize * components;
        let padded = row.div_ceil(4) * 4;
        let mut pixels = Vec::with_capacity(padded * texels.len() / row.max(1));
        for r in texels.chunks(row.max(1)) {
            pixels.extend_from_slice(r);
            pixels.resize(pixels.len() + padded - r.len(), 0);
        }
        self.call(Call::TexImage {
            target,
            level,
            internal,
            size,
            format,
            ty: PixelType::UnsignedByte,
            pixels,
        })
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

/// `glClear`'s bits; the GL values of the enumerated arguments come from
/// their one table, [`softgl::GlEnum::to_gl`].
pub fn clear_bits(m: ClearMask) -> u32 {
    (if m.color { 0x4000 } else { 0 })
        | (if m.depth { 0x100 } else { 0 })
        | (if m.stencil { 0x400 } else { 0 })
        | (if m.accum { 0x200 } else { 0 })
}

/// Pads rows of `row` bytes to GL's default unpack alignment of 4.
pub fn pad_rows(bytes: &[u8], row: usize) -> Vec<u8> {
    let padded = row.div_ceil(4) * 4;
    let mut out = Vec::with_capacity(padded * bytes.len() / row.max(1));
    for r in bytes.chunks(row.max(1)) {
        out.extend_from_slice(r);
        out.resize(out.len() + padded - r.len(), 0);
    }
    out
}
