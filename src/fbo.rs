//! Framebuffer objects (ARB_framebuffer_object, GL 3.0 §4.4): renderbuffers,
//! attachments, the draw and read bindings, completeness, `glBlitFramebuffer`.
//!
//! # Design
//!
//! A context renders into exactly one [`Framebuffer`] (`Context::fb`), which
//! the deferred tiled rasterizer (`raster/scene.rs`) flushes into. Binding a
//! framebuffer object for drawing does not teach the rasterizer anything new:
//! the object's attachments are *assembled* into a `Framebuffer`
//! ([`Framebuffer::from_parts`]) that takes the context's place, and the
//! window framebuffer (OSMesa's or EGL's buffer, object 0) waits in
//! [`FboState::window`] until object 0 is bound again. Every path that draws,
//! clears or reads therefore works on an object unchanged.
//!
//! Where an attachment's pixels live:
//! - **Renderbuffers** own their storage; assembling *moves* it into the
//!   framebuffer (O(1): a `Vec` changes hands) and releasing moves it back.
//!   While it is out, [`Renderbuffer::storage`] is `None`; a read framebuffer
//!   that shares it copies it from the draw framebuffer.
//! - **Texture images** keep their texels (a sampler may read them at any
//!   time, so a texture image is never hollow). The framebuffer holds a copy
//!   in render format (RGBA8 bytes as they are; `Depth32F` texels converted to
//!   the 16/24/32-bit integers the depth test compares, with
//!   `unpack::depth_unsampled`), written back into the image
//!   (`unpack::depth_sampled`, llvmpipe's sampler conversion) at the *sync
//!   points*: when the draw binding changes, before a texture call reads or
//!   writes an attached texture (`glTexImage`, `glTexSubImage`, `glCopyTex*`,
//!   `glGetTexImage`, `glGenerateMipmap`, `glDeleteTextures`), and before a
//!   draw that samples an attached texture (a feedback loop, undefined in GL:
//!   the draw then samples what was rendered before it). Each sync point
//!   flushes the pending scene first. After a texture call the framebuffer is
//!   released and assembled again at the next draw, clear or read, so that a
//!   redefined image re-runs the completeness rules. `glDrawBuffer` and
//!   `glReadBuffer` naming the buffer already set are not sync points
//!   (MuJoCo sets `GL_NONE` on its shadow map at every bind: that was a
//!   second 64 MiB write-back per pass, 48 M instructions a frame of
//!   `osmesa/bench/shadow_fbo.c`).
//! - **Depth textures** of 24 bits or float depth (2D images) are not
//!   written back: releasing the framebuffer hands its depth buffer to the
//!   image ([`TexImage::units`]), which the samplers read in place,
//!   converting each unit as the write-back did (`z · f32(1/(2^24 − 1))`,
//!   float depth as stored: `softgl_jit::texture::DepthUnits`). The texels
//!   are written from the units only when a texture call reads them
//!   (`sync_texture`) or writes them (`TexImage::texels_mut`), and a read
//!   framebuffer converts them as it converted the texels. The object
//!   keeps the image's previous units, once no draw reads them, as the
//!   buffer to draw into next ([`FramebufferObject::spare_depth`]); the
//!   units it handed over are drawn into again as they are (as the former
//!   cache did), copied; and a `glClear` of the whole depth buffer as the
//!   object's first use skips even that copy ([`FboState::depth_cleared`]):
//!   MuJoCo's shadow map pass. The write-back was 64 MiB read and 64 MiB
//!   written per pass, ~4.4 ms, two a MuJoCo frame. 16 and 32-bit unorm
//!   depth textures are still written back (their units are not the
//!   `u32` texels the native sampler reads, and MuJoCo uses neither).
//! - A blit's read object lends its renderbuffers (moved out and back, as
//!   for drawing) unless the draw framebuffer holds one of them; other reads
//!   copy them. Unscaled blits of 8-bit colour copy rows, and a 4× resolve
//!   of that kind writes the destination directly (`resolve_color_into`):
//!   28 M → 6 M instructions a 320×240 frame.
//! - An object without a colour attachment to draw (a depth-only shadow map,
//!   or draw buffer `GL_NONE`) draws into a 2-byte-per-pixel scratch colour
//!   buffer with colour writes off ([`Framebuffer::set_color_enabled`]): the
//!   fragment key gets a `NONE` colour mask, so no colour stage runs. The
//!   scratch buffer is kept in the object and reused (32 MiB at 4096²).
//!
//! Colour formats the rasterizer writes: RGBA8 (`GL_RGBA`, `GL_RGBA8`), RGB8
//! (`GL_RGB`, `GL_RGB8`: alpha reads 1, as llvmpipe's `R8G8B8X8`), RGB565,
//! and the deep ones, RGBA16, RGB16 (RGBX), RGBA16F, RGB16F, RGBA32F and
//! RGB32F, each stored as llvmpipe stores it (half floats as f32 holding a
//! half's value). GL's other colour formats take the storage llvmpipe
//! chooses when softgl has it (`GL_RGBA12` and `GL_RGB12` are RGBA16 and
//! RGB16 there too), else the nearest one with at least the bits asked for
//! (`RenderbufferFormat::kind`), and report its sizes.
//! Depth: 16, 24 and 32-bit unorm; stencil: 8 bits, only together with depth
//! in one `GL_DEPTH24_STENCIL8` renderbuffer or alone (Mesa's gallium
//! framebuffers take no separate depth and stencil renderbuffers:
//! `main/fbobject.c` `do_validate_framebuffer`, `GL_FRAMEBUFFER_UNSUPPORTED`).
//! Other formats are accepted by `glRenderbufferStorage` (they are GL's) and
//! make the framebuffer `GL_FRAMEBUFFER_UNSUPPORTED`, which GL allows for any
//! combination an implementation cannot render: their pixels would differ
//! from llvmpipe's (it stores `GL_RGBA4` at 4 bits, for instance).
//!
//! Multisampling: `glRenderbufferStorageMultisample` records the sample
//! count (up to [`MAX_SAMPLES`]) and the object's `GL_SAMPLES`; rendering is
//! single-sampled until the framebuffer grows samples (the `msaa` work): the
//! seam is [`Renderbuffer::samples`], read when assembling, and
//! [`Context::blit_framebuffer`]'s resolve, which is then a copy.

use crate::context::Context;
use crate::error::{GlError, GlResult};
use crate::framebuffer::{DepthBuffer, Framebuffer, FramebufferDesc, Rect};
use crate::names::Names;
use crate::texture::jit::{BaseFormat, TexTarget, TexelFormat};
use crate::texture::unpack::{depth_sampled, depth_unsampled};
use crate::texture::{ImageUnits, TexImage};
use softgl_jit::{pixel, ColorFormat, DepthFormat};

/// `GL_MAX_RENDERBUFFER_SIZE` (llvmpipe: 16384, its largest texture).
pub const MAX_RENDERBUFFER_SIZE: u32 = 16384;
/// `GL_MAX_COLOR_ATTACHMENTS`.
pub const MAX_COLOR_ATTACHMENTS: usize = 8;
/// `GL_MAX_SAMPLES` (llvmpipe's).
pub const MAX_SAMPLES: u32 = 4;

/// A renderbuffer internal format (`glRenderbufferStorage`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum RenderbufferFormat {
    Rgba,
    Rgba8,
    Rgb,
    Rgb8,
    Rgb565,
    Rgba2,
    Rgba4,
    Rgb5A1,
    R3G3B2,
    Rgb4,
    Rgb5,
    Rgb10,
    Rgb10A2,
    Rgb12,
    Rgba12,
    Rgb16,
    Rgba16,
    /// `GL_RGBA16F`, `GL_RGB16F`: half floats (`ColorFormat::Rgba16F`, `Rgbx16F`).
    Rgba16F,
    Rgb16F,
    /// `GL_RGBA32F`, `GL_RGB32F` (`ColorFormat::Rgba32F`, `Rgbx32F`).
    Rgba32F,
    Rgb32F,
    DepthComponent,
    DepthComponent16,
    DepthComponent24,
    DepthComponent32,
    DepthStencil,
    Depth24Stencil8,
    /// ARB_depth_buffer_float.
    DepthComponent32F,
    Depth32FStencil8,
    StencilIndex,
    StencilIndex1,
    StencilIndex4,
    StencilIndex8,
    StencilIndex16,
}

/// What a renderbuffer format is stored as, when the rasterizer can write it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RenderbufferKind {
    Color(ColorFormat),
    Depth(DepthFormat),
    DepthStencil(DepthFormat),
    Stencil,
}

impl RenderbufferFormat {
    /// The storage, or `None` for a format the rasterizer cannot write.
    pub fn kind(self) -> Option<RenderbufferKind> {
        use RenderbufferFormat as F;
        use RenderbufferKind as K;
        Some(match self {
            // llvmpipe: B4G4R4A4, B5G5R5A1 (docs/llvmpipe-facts.md §44).
            F::Rgba | F::Rgba8 | F::Rgba2 | F::Rgba4 | F::Rgb5A1 => K::Color(ColorFormat::Rgba8),
            F::Rgb | F::Rgb8 => K::Color(ColorFormat::Rgb8),
            // llvmpipe: B2G3R3, B4G4R4X4, B5G5R5X1.
            F::Rgb565 | F::R3G3B2 | F::Rgb4 | F::Rgb5 => K::Color(ColorFormat::Rgb565),
            // llvmpipe: R16G16B16A16 for RGBA12 too; B10G10R10A2 for RGB10_A2.
            F::Rgba16 | F::Rgba12 | F::Rgb10A2 => K::Color(ColorFormat::Rgba16),
            // llvmpipe: R16G16B16X16 for RGB12 too; B10G10R10X2 for RGB10.
            F::Rgb16 | F::Rgb12 | F::Rgb10 => K::Color(ColorFormat::Rgbx16),
            F::Rgba16F => K::Color(ColorFormat::Rgba16F),
            F::Rgb16F => K::Color(ColorFormat::Rgbx16F),
            F::Rgba32F => K::Color(ColorFormat::Rgba32F),
            F::Rgb32F => K::Color(ColorFormat::Rgbx32F),
            F::DepthComponent | F::DepthComponent24 => K::Depth(DepthFormat::D24),
            F::DepthComponent16 => K::Depth(DepthFormat::D16),
            F::DepthComponent32 => K::Depth(DepthFormat::D32),
            F::DepthStencil | F::Depth24Stencil8 => K::DepthStencil(DepthFormat::D24),
            F::DepthComponent32F => K::Depth(DepthFormat::D32F),
            F::Depth32FStencil8 => K::DepthStencil(DepthFormat::D32F),
            F::StencilIndex | F::StencilIndex8 => K::Stencil,
            F::StencilIndex1 | F::StencilIndex4 | F::StencilIndex16 => return None,
        })
    }

    /// `GL_RENDERBUFFER_{RED,GREEN,BLUE,ALPHA,DEPTH,STENCIL}_SIZE`: a colour
    /// format's are its storage's (`GL_RGBA4` is stored, and reports, 8 bits
    /// a channel).
    pub fn bits(self) -> [u32; 6] {
        use RenderbufferFormat as F;
        if let Some(RenderbufferKind::Color(c)) = self.kind() {
            return [
                c.channel_bits(0),
                c.channel_bits(1),
                c.channel_bits(2),
                c.channel_bits(3),
                0,
                0,
            ];
        }
        match self {
            F::Rgba | F::Rgba8 => [8, 8, 8, 8, 0, 0],
            F::Rgb | F::Rgb8 => [8, 8, 8, 0, 0, 0],
            F::Rgb565 => [5, 6, 5, 0, 0, 0],
            F::Rgba2 => [2, 2, 2, 2, 0, 0],
            F::Rgba4 => [4, 4, 4, 4, 0, 0],
            F::Rgb5A1 => [5, 5, 5, 1, 0, 0],
            F::R3G3B2 => [3, 3, 2, 0, 0, 0],
            F::Rgb4 => [4, 4, 4, 0, 0, 0],
            F::Rgb5 => [5, 5, 5, 0, 0, 0],
            F::Rgb10 => [10, 10, 10, 0, 0, 0],
            F::Rgb10A2 => [10, 10, 10, 2, 0, 0],
            F::Rgb12 => [12, 12, 12, 0, 0, 0],
            F::Rgba12 => [12, 12, 12, 12, 0, 0],
            F::Rgb16 => [16, 16, 16, 0, 0, 0],
            F::Rgba16 | F::Rgba16F => [16, 16, 16, 16, 0, 0],
            F::Rgb16F => [16, 16, 16, 0, 0, 0],
            F::Rgba32F => [32, 32, 32, 32, 0, 0],
            F::Rgb32F => [32, 32, 32, 0, 0, 0],
            F::DepthComponent | F::DepthComponent24 => [0, 0, 0, 0, 24, 0],
            F::DepthComponent16 => [0, 0, 0, 0, 16, 0],
            F::DepthComponent32 => [0, 0, 0, 0, 32, 0],
            F::DepthStencil | F::Depth24Stencil8 => [0, 0, 0, 0, 24, 8],
            F::DepthComponent32F => [0, 0, 0, 0, 32, 0],
            F::Depth32FStencil8 => [0, 0, 0, 0, 32, 8],
            F::StencilIndex1 => [0, 0, 0, 0, 0, 1],
            F::StencilIndex4 => [0, 0, 0, 0, 0, 4],
            F::StencilIndex | F::StencilIndex8 => [0, 0, 0, 0, 0, 8],
            F::StencilIndex16 => [0, 0, 0, 0, 0, 16],
        }
    }

    fn has_depth(self) -> bool {
        self.bits()[4] > 0
    }

    fn has_stencil(self) -> bool {
        self.bits()[5] > 0
    }

    fn has_color(self) -> bool {
        !self.has_depth() && !self.has_stencil()
    }
}

/// A renderbuffer's pixels.
#[derive(Clone, Debug)]
enum RbStorage {
    Color(Vec<u8>),
    Depth(DepthBuffer),
    Stencil(Vec<u8>),
    DepthStencil(DepthBuffer, Vec<u8>),
}

/// A renderbuffer object.
#[derive(Clone, Debug)]
pub struct Renderbuffer {
    pub format: RenderbufferFormat,
    pub width: u32,
    pub height: u32,
    /// `GL_RENDERBUFFER_SAMPLES`: the samples a pixel Mesa gives the count
    /// `glRenderbufferStorageMultisample` asked for (0: single-sampled; 1 to
    /// 4: 4, `multisample::renderbuffer_samples`).
    pub samples: u32,
    /// One storage a sample (one when single-sampled). `None` before
    /// `glRenderbufferStorage`, for an unsupported format, and while a
    /// framebuffer holds the pixels.
    storage: Vec<Option<RbStorage>>,
    /// Whether storage was defined (`glRenderbufferStorage` ran).
    defined: bool,
}

impl Default for Renderbuffer {
    fn default() -> Self {
        Renderbuffer {
            format: RenderbufferFormat::Rgba,
            width: 0,
            height: 0,
            samples: 0,
            storage: vec![None],
            defined: false,
        }
    }
}

/// What an attachment point holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Attachment {
    #[default]
    None,
    Renderbuffer(u32),
    /// A texture image: `face` is the cube face (0 otherwise), `layer` the
    /// slice of a 3D texture.
    Texture {
        name: u32,
        level: u32,
        face: u32,
        layer: u32,
    },
}

/// An attachment point of a framebuffer object.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AttachmentPoint {
    Color(u32),
    Depth,
    Stencil,
    /// `GL_DEPTH_STENCIL_ATTACHMENT`: depth and stencil at once.
    DepthStencil,
}

/// One of the window framebuffer's buffers, as `glGetFramebufferAttachmentParameteriv`
/// names them on object 0 (`GL_FRONT_LEFT`…, `GL_DEPTH`, `GL_STENCIL`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum WindowBuffer {
    Color,
    Depth,
    Stencil,
}

/// The draw and read bindings (`glBindFramebuffer`'s targets).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FramebufferTarget {
    /// `GL_FRAMEBUFFER`: both.
    Both,
    Draw,
    Read,
}

/// `glCheckFramebufferStatus`'s answers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FramebufferStatus {
    Complete,
    IncompleteAttachment,
    MissingAttachment,
    IncompleteDrawBuffer,
    IncompleteReadBuffer,
    Unsupported,
    IncompleteMultisample,
}

impl FramebufferStatus {
    /// The GL enumerant.
    pub const fn code(self) -> u32 {
        match self {
            FramebufferStatus::Complete => 0x8CD5,
            FramebufferStatus::IncompleteAttachment => 0x8CD6,
            FramebufferStatus::MissingAttachment => 0x8CD7,
            FramebufferStatus::IncompleteDrawBuffer => 0x8CDB,
            FramebufferStatus::IncompleteReadBuffer => 0x8CDC,
            FramebufferStatus::Unsupported => 0x8CDD,
            FramebufferStatus::IncompleteMultisample => 0x8D56,
        }
    }
}

/// A framebuffer object.
#[derive(Clone, Debug)]
pub struct FramebufferObject {
    pub color: [Attachment; MAX_COLOR_ATTACHMENTS],
    pub depth: Attachment,
    pub stencil: Attachment,
    /// `glDrawBuffer`: the colour attachment drawn, `None` for `GL_NONE`.
    pub draw_buffer: Option<u32>,
    /// `glReadBuffer`: the colour attachment read, `None` for `GL_NONE`.
    pub read_buffer: Option<u32>,
    /// The colour bytes drawn when no colour attachment is (see the module doc).
    scratch: Vec<u8>,
    /// The depth units a depth texture image held before the object last
    /// rendered into it ([`TexImage::units`]), no longer read by anyone:
    /// the buffer the next assembly draws into (a shadow map's two buffers
    /// take turns, without fresh pages).
    spare_depth: Option<DepthBuffer>,
    /// The depth attachment's units the object last handed to its image
    /// ([`TexImage::units`]): when the image still holds them, the next
    /// assembly draws into them as they are (converting the texels back
    /// is not always exact at 24 bits, and costs a pass over them).
    rendered: Option<(Attachment, std::sync::Weak<Vec<u32>>)>,
}

impl Default for FramebufferObject {
    fn default() -> Self {
        FramebufferObject {
            color: [Attachment::None; MAX_COLOR_ATTACHMENTS],
            depth: Attachment::None,
            stencil: Attachment::None,
            draw_buffer: Some(0),
            read_buffer: Some(0),
            scratch: Vec::new(),
            spare_depth: None,
            rendered: None,
        }
    }
}

/// One attachment as the framebuffer sees it: its size and format.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Image {
    width: u32,
    height: u32,
    samples: u32,
    kind: Option<RenderbufferKind>,
}

/// What a draw framebuffer was assembled from, to put its buffers back.
#[derive(Clone, Copy, Debug)]
struct Checkout {
    fbo: u32,
    color: Attachment,
    depth: Attachment,
    stencil: Attachment,
}

/// Framebuffer and renderbuffer objects, the bindings, and the window
/// framebuffer while an object is drawn into.
#[derive(Debug, Default)]
pub struct FboState {
    framebuffers: Names<FramebufferObject>,
    renderbuffers: Names<Renderbuffer>,
    pub(crate) draw: u32,
    pub(crate) read: u32,
    pub(crate) renderbuffer: u32,
    /// The window framebuffer while `Context::fb` holds an object's buffers.
    pub(crate) window: Option<Framebuffer>,
    /// What `Context::fb` was assembled from (with `window` set).
    checkout: Option<Checkout>,
    /// The window's draw/read buffers are `GL_NONE` (`glDrawBuffer(GL_NONE)` on object 0).
    pub(crate) window_draw_none: bool,
    pub(crate) window_read_none: bool,
    /// Set by `glClear` while it assembles the draw framebuffer when it
    /// clears the whole depth buffer: a depth texture's contents are not
    /// needed then ([`Context::take_depth`]).
    pub(crate) depth_cleared: bool,
    /// The bound draw object waits for its first use to be assembled
    /// (`Context::bind_framebuffer`); the calls that use `Context::fb`
    /// without `ensure_draw` assemble it first ([`Context::acquire_deferred`]).
    pub(crate) deferred: bool,
}

impl FboState {
    /// The object `name` (`None` for 0 or an unknown name).
    pub fn framebuffer(&self, name: u32) -> Option<&FramebufferObject> {
        self.framebuffers.get(name)
    }

    fn framebuffer_mut(&mut self, name: u32) -> Option<&mut FramebufferObject> {
        self.framebuffers.get_mut(name)
    }

    pub fn renderbuffer(&self, name: u32) -> Option<&Renderbuffer> {
        self.renderbuffers.get(name)
    }

    /// `GL_DRAW_FRAMEBUFFER_BINDING`.
    pub fn draw_binding(&self) -> u32 {
        self.draw
    }

    /// `GL_READ_FRAMEBUFFER_BINDING`.
    pub fn read_binding(&self) -> u32 {
        self.read
    }

    /// `GL_RENDERBUFFER_BINDING`.
    pub fn renderbuffer_binding(&self) -> u32 {
        self.renderbuffer
    }

    /// Whether `glDrawBuffer(GL_NONE)` turned the window's colour writes off.
    pub fn window_draw_none(&self) -> bool {
        self.window_draw_none
    }

    /// Whether `glReadBuffer(GL_NONE)` was called on the window.
    pub fn window_read_none(&self) -> bool {
        self.window_read_none
    }

    /// Whether the draw framebuffer holds the texture `name`'s images.
    fn holds_texture(&self, name: u32) -> bool {
        self.checkout.is_some_and(|c| {
            [c.color, c.depth, c.stencil]
                .iter()
                .any(|a| matches!(a, Attachment::Texture { name: n, .. } if *n == name))
        })
    }

    fn holds_any_texture(&self) -> bool {
        self.checkout.is_some_and(|c| {
            [c.color, c.depth, c.stencil]
                .iter()
                .any(|a| matches!(a, Attachment::Texture { .. }))
        })
    }
}

/// The image an attachment names, if it exists.
fn image_of(fbo: &FboState, textures: &crate::texture::TextureStore, a: Attachment) -> Option<Image> {
    match a {
        Attachment::None => None,
        Attachment::Renderbuffer(name) => {
            let rb = fbo.renderbuffer(name)?;
            Some(Image {
                width: rb.width,
                height: rb.height,
                samples: rb.samples,
                kind: if rb.defined { rb.format.kind() } else { None },
            })
        }
        Attachment::Texture {
            name,
            level,
            face,
            layer,
        } => {
            let img = textures.object(name)?.image(level as usize, face as usize)?;
            if layer >= img.depth.max(1) {
                return Some(Image {
                    width: 0,
                    height: 0,
                    samples: 0,
                    kind: None,
                });
            }
            Some(Image {
                width: img.width,
                height: img.height,
                samples: 0,
                kind: texture_kind(img),
            })
        }
    }
}

/// How a texture image renders, when the rasterizer writes its format
/// exactly: 8-bit RGBA/RGB (stored as RGBA8 texels) and depth.
fn texture_kind(img: &TexImage) -> Option<RenderbufferKind> {
    let s = img.internal.storage();
    match (s.base, img.texel_format()) {
        (BaseFormat::Depth, _) if s.float => Some(RenderbufferKind::Depth(DepthFormat::D32F)),
        (BaseFormat::Depth, _) => Some(RenderbufferKind::Depth(match s.bits[0] {
            16 => DepthFormat::D16,
            32 => DepthFormat::D32,
            _ => DepthFormat::D24,
        })),
        (BaseFormat::Rgba | BaseFormat::Rgb, TexelFormat::Rgba8) if s.bits[..3] == [8, 8, 8] => {
            Some(RenderbufferKind::Color(ColorFormat::Rgba8))
        }
        // `GL_RGBA16` (and `GL_RGBA12`, stored alike): its texels are
        // `ColorFormat::Rgba16`'s pixels.
        (BaseFormat::Rgba, TexelFormat::Rgba16) => Some(RenderbufferKind::Color(ColorFormat::Rgba16)),
        _ => None,
    }
}

/// Whether texture attachment `a` names a packed depth-stencil image.
fn texture_stencil(textures: &crate::texture::TextureStore, a: Attachment) -> bool {
    let Attachment::Texture { name, level, face, .. } = a else {
        return false;
    };
    textures
        .object(name)
        .and_then(|o| o.image(level as usize, face as usize))
        .is_some_and(|img| img.internal.stencil_bits() > 0)
}

/// GL 3.0 §4.4.4's completeness of object `name` (0: the window, complete).
fn status(fbo: &FboState, textures: &crate::texture::TextureStore, name: u32) -> FramebufferStatus {
    use FramebufferStatus as S;
    let Some(f) = fbo.framebuffer(name) else {
        return S::Complete;
    };
    let mut images = Vec::new();
    // Attachment completeness: each attached image exists with a non-zero
    // size and a format renderable at its point.
    for (a, point) in f.color.iter().map(|a| (*a, 0)).chain([(f.depth, 1), (f.stencil, 2)]) {
        if a == Attachment::None {
            continue;
        }
        let Some(img) = image_of(fbo, textures, a) else {
            return S::IncompleteAttachment;
        };
        if img.width == 0 || img.height == 0 {
            return S::IncompleteAttachment;
        }
        let fits = match (point, a) {
            (0, Attachment::Renderbuffer(n)) => fbo.renderbuffer(n).is_some_and(|r| r.format.has_color()),
            (1, Attachment::Renderbuffer(n)) => fbo.renderbuffer(n).is_some_and(|r| r.format.has_depth()),
            (2, Attachment::Renderbuffer(n)) => fbo.renderbuffer(n).is_some_and(|r| r.format.has_stencil()),
            (0, _) => !matches!(img.kind, Some(RenderbufferKind::Depth(_))),
            (1, _) => matches!(img.kind, Some(RenderbufferKind::Depth(_)) | None),
            // Stencil textures: the packed depth-stencil formats.
            _ => texture_stencil(textures, a),
        };
        if !fits {
            return S::IncompleteAttachment;
        }
        images.push((a, img));
    }
    if images.is_empty() {
        return S::MissingAttachment;
    }
    if images.iter().any(|(_, i)| i.samples != images[0].1.samples) {
        return S::IncompleteMultisample;
    }
    // No INCOMPLETE_DRAW_BUFFER / INCOMPLETE_READ_BUFFER: Mesa skips GL
    // 3.0's draw- and read-buffer rules when ARB_ES2_compatibility is on, as
    // on llvmpipe (`main/fbobject.c`, docs/llvmpipe-facts.md): a buffer
    // naming an empty attachment draws nothing and reads are errors.
    // Mesa's gallium check (`do_validate_framebuffer`): depth and stencil one buffer.
    let ds_split = match (f.depth, f.stencil) {
        (Attachment::None, _) | (_, Attachment::None) => false,
        (Attachment::Renderbuffer(a), Attachment::Renderbuffer(b)) => a != b,
        (a @ Attachment::Texture { .. }, b @ Attachment::Texture { .. }) => a != b,
        _ => true,
    };
    // Images of different sizes (ARB_framebuffer_object allows them, the
    // framebuffer is their intersection) are not rendered by softgl yet.
    let mixed = images
        .iter()
        .any(|(_, i)| (i.width, i.height) != (images[0].1.width, images[0].1.height));
    if ds_split || mixed || images.iter().any(|(_, i)| i.kind.is_none()) {
        return S::Unsupported;
    }
    S::Complete
}

/// The read framebuffer, made for one read ([`Context::read_framebuffer`]).
pub enum ReadFb {
    /// Reads come from `Context::fb`.
    Draw,
    /// From the window framebuffer, waiting in [`FboState::window`].
    Window,
    /// Assembled from object attachments, put back after the read.
    Assembled(Framebuffer),
}

/// Which buffers `glBlitFramebuffer` copies.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct BlitMask {
    pub color: bool,
    pub depth: bool,
    pub stencil: bool,
}

/// `glBlitFramebuffer`'s filter.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BlitFilter {
    Nearest,
    Linear,
}

impl Context {
    /// The framebuffer objects and bindings.
    pub fn fbo_state(&self) -> &FboState {
        &self.fbo
    }

    /// `glGenFramebuffers`.
    pub fn gen_framebuffers(&mut self, n: i32) -> GlResult<Vec<u32>> {
        self.outside()?;
        let n = self.record(usize::try_from(n).map_err(|_| GlError::InvalidValue))?;
        let names = self.fbo.framebuffers.gen(n).ok_or(GlError::OutOfMemory);
        self.record(names)
    }

    /// `glIsFramebuffer`: a name bound at least once.
    pub fn is_framebuffer(&self, name: u32) -> bool {
        self.fbo.framebuffer(name).is_some()
    }

    /// `glBindFramebuffer`: a name never generated is created on bind (the
    /// compatibility profile's rule, as Mesa's).
    pub fn bind_framebuffer(&mut self, target: FramebufferTarget, name: u32) -> GlResult {
        self.outside()?;
        if name != 0 {
            self.fbo
                .framebuffers
                .object_or_insert_with(name, FramebufferObject::default);
        }
        if matches!(target, FramebufferTarget::Both | FramebufferTarget::Draw) && self.fbo.draw != name {
            self.release_draw();
            self.fbo.draw = name;
            // An object whose depth texture holds the units it rendered is
            // assembled at its first draw, clear or read (as after a texture
            // call): a clear of its whole depth buffer then copies none of
            // them (MuJoCo binds its shadow map, then clears it).
            let units = self
                .fbo
                .framebuffer(name)
                .is_some_and(|f| f.rendered.as_ref().is_some_and(|(a, _)| *a == f.depth));
            self.fbo.deferred = units;
            if !units {
                self.acquire_draw();
            }
        }
        if matches!(target, FramebufferTarget::Both | FramebufferTarget::Read) {
            self.fbo.read = name;
        }
        Ok(())
    }

    /// `glDeleteFramebuffers`: a bound object reverts to 0.
    pub fn delete_framebuffers(&mut self, names: &[u32]) -> GlResult {
        self.outside()?;
        for &name in names {
            if !self.fbo.framebuffers.is_reserved(name) {
                continue;
            }
            if self.fbo.draw == name {
                self.bind_framebuffer(FramebufferTarget::Draw, 0)?;
            }
            if self.fbo.read == name {
                self.fbo.read = 0;
            }
            self.fbo.framebuffers.remove(name);
        }
        Ok(())
    }

    /// `glCheckFramebufferStatus` of the draw or read binding.
    pub fn check_framebuffer_status(&mut self, target: FramebufferTarget) -> GlResult<FramebufferStatus> {
        self.outside()?;
        let name = match target {
            FramebufferTarget::Read => self.fbo.read,
            _ => self.fbo.draw,
        };
        Ok(status(&self.fbo, &self.textures, name))
    }

    /// `glGenRenderbuffers`.
    pub fn gen_renderbuffers(&mut self, n: i32) -> GlResult<Vec<u32>> {
        self.outside()?;
        let n = self.record(usize::try_from(n).map_err(|_| GlError::InvalidValue))?;
        let names = self.fbo.renderbuffers.gen(n).ok_or(GlError::OutOfMemory);
        self.record(names)
    }

    /// `glIsRenderbuffer`: a name bound at least once.
    pub fn is_renderbuffer(&self, name: u32) -> bool {
        self.fbo.renderbuffer(name).is_some()
    }

    /// `glBindRenderbuffer` (creating the object on first bind).
    pub fn bind_renderbuffer(&mut self, name: u32) -> GlResult {
        self.outside()?;
        if name != 0 {
            self.fbo
                .renderbuffers
                .object_or_insert_with(name, Renderbuffer::default);
        }
        self.fbo.renderbuffer = name;
        Ok(())
    }

    /// `glDeleteRenderbuffers`: detached from the bound framebuffers (GL
    /// 3.0 §4.4.2), unbound.
    pub fn delete_renderbuffers(&mut self, names: &[u32]) -> GlResult {
        self.outside()?;
        for &name in names {
            if !self.fbo.renderbuffers.is_reserved(name) {
                continue;
            }
            self.release_draw();
            for fb in [self.fbo.draw, self.fbo.read] {
                if let Some(f) = self.fbo.framebuffer_mut(fb) {
                    for a in f.color.iter_mut().chain([&mut f.depth, &mut f.stencil]) {
                        if *a == Attachment::Renderbuffer(name) {
                            *a = Attachment::None;
                        }
                    }
                }
            }
            if self.fbo.renderbuffer == name {
                self.fbo.renderbuffer = 0;
            }
            self.fbo.renderbuffers.remove(name);
        }
        self.acquire_draw();
        Ok(())
    }

    /// `glRenderbufferStorageMultisample` (`samples` 0: `glRenderbufferStorage`)
    /// on the bound renderbuffer: its pixels are undefined in GL; softgl
    /// clears them to zero (depth to 1.0).
    pub fn renderbuffer_storage(
        &mut self,
        samples: i32,
        format: RenderbufferFormat,
        width: i32,
        height: i32,
    ) -> GlResult {
        self.outside()?;
        let name = self.fbo.renderbuffer;
        let r = if name == 0 {
            Err(GlError::InvalidOperation)
        } else if !(0..=MAX_RENDERBUFFER_SIZE as i32).contains(&width)
            || !(0..=MAX_RENDERBUFFER_SIZE as i32).contains(&height)
        {
            Err(GlError::InvalidValue)
        } else {
            crate::multisample::renderbuffer_samples(samples)
        };
        let per_pixel = self.record(r)?;
        self.release_draw();
        let n = width as usize * height as usize;
        let one = || match format.kind() {
            None => Ok(None),
            Some(RenderbufferKind::Color(c)) => color_storage(c, n).map(|v| Some(RbStorage::Color(v))),
            Some(RenderbufferKind::Depth(d)) => depth_buffer(d, n).map(|d| Some(RbStorage::Depth(d))),
            Some(RenderbufferKind::DepthStencil(d)) => {
                depth_buffer(d, n).and_then(|d| Ok(Some(RbStorage::DepthStencil(d, alloc(n, 0u8)?))))
            }
            Some(RenderbufferKind::Stencil) => alloc(n, 0u8).map(|s| Some(RbStorage::Stencil(s))),
        };
        let storage: GlResult<Vec<Option<RbStorage>>> = (0..per_pixel).map(|_| one()).collect();
        let samples = if per_pixel > 1 { per_pixel } else { 0 };
        let r = storage.map(|storage| {
            if let Some(rb) = self.fbo.renderbuffers.get_mut(name) {
                *rb = Renderbuffer {
                    format,
                    width: width as u32,
                    height: height as u32,
                    samples,
                    storage,
                    defined: true,
                };
            }
        });
        self.acquire_draw();
        self.record(r)
    }

    /// `glFramebufferRenderbuffer` on the `target` binding (`Both`: draw).
    pub fn framebuffer_renderbuffer(&mut self, target: FramebufferTarget, point: AttachmentPoint, rb: u32) -> GlResult {
        self.outside()?;
        let r = if rb != 0 && self.fbo.renderbuffer(rb).is_none() {
            Err(GlError::InvalidOperation)
        } else {
            Ok(())
        };
        self.record(r)?;
        let a = if rb == 0 {
            Attachment::None
        } else {
            Attachment::Renderbuffer(rb)
        };
        self.attach(target, point, a)
    }

    /// `glFramebufferTexture1D/2D/3D` and `glFramebufferTextureLayer`:
    /// `target` the texture's (`CubeFace` for cube maps), `name` 0 detaches.
    /// `layer` is the slice of a 3D texture.
    pub fn framebuffer_texture(
        &mut self,
        fb_target: FramebufferTarget,
        point: AttachmentPoint,
        tex_target: Option<crate::texture::TexImageTarget>,
        name: u32,
        level: i32,
        layer: i32,
    ) -> GlResult {
        use crate::texture::TexImageTarget as T;
        self.outside()?;
        if name == 0 {
            return self.attach(fb_target, point, Attachment::None);
        }
        let Some(obj_target) = self.textures.object(name).map(|o| o.target) else {
            return self.record(Err(GlError::InvalidOperation));
        };
        let face = match tex_target {
            Some(T::CubeFace(f)) => u32::from(f),
            _ => 0,
        };
        let ok_target = match tex_target {
            None => true,
            Some(t) => t.texture_target() == obj_target && !matches!(t, T::Proxy(_)),
        };
        self.record(if ok_target {
            Ok(())
        } else {
            Err(GlError::InvalidOperation)
        })?;
        let max_level = crate::texture::max_levels(obj_target) as i32;
        let layer_ok = layer >= 0 && (obj_target == TexTarget::D3 || layer == 0);
        self.record(if (0..max_level).contains(&level) && layer_ok {
            Ok(())
        } else {
            Err(GlError::InvalidValue)
        })?;
        let a = Attachment::Texture {
            name,
            level: level as u32,
            face,
            layer: layer as u32,
        };
        self.attach(fb_target, point, a)
    }

    fn attach(&mut self, target: FramebufferTarget, point: AttachmentPoint, a: Attachment) -> GlResult {
        let name = match target {
            FramebufferTarget::Read => self.fbo.read,
            _ => self.fbo.draw,
        };
        if name == 0 {
            return self.record(Err(GlError::InvalidOperation));
        }
        if let AttachmentPoint::Color(i) = point {
            if i as usize >= MAX_COLOR_ATTACHMENTS {
                return self.record(Err(GlError::InvalidEnum));
            }
        }
        let redraw = name == self.fbo.draw;
        if redraw {
            self.release_draw();
        }
        if let Some(f) = self.fbo.framebuffer_mut(name) {
            match point {
                AttachmentPoint::Color(i) => f.color[i as usize] = a,
                AttachmentPoint::Depth => f.depth = a,
                AttachmentPoint::Stencil => f.stencil = a,
                AttachmentPoint::DepthStencil => (f.depth, f.stencil) = (a, a),
            }
        }
        if redraw {
            self.acquire_draw();
        }
        Ok(())
    }

    /// What `point` of the `target` binding holds (`glGetFramebufferAttachmentParameteriv`);
    /// `InvalidOperation` on object 0.
    pub fn framebuffer_attachment(
        &mut self,
        target: FramebufferTarget,
        point: AttachmentPoint,
    ) -> GlResult<Attachment> {
        self.outside()?;
        let name = match target {
            FramebufferTarget::Read => self.fbo.read,
            _ => self.fbo.draw,
        };
        let r = match self.fbo.framebuffer(name) {
            None => Err(GlError::InvalidOperation),
            Some(f) => match point {
                AttachmentPoint::Color(i) => f.color.get(i as usize).copied().ok_or(GlError::InvalidEnum),
                AttachmentPoint::Depth => Ok(f.depth),
                AttachmentPoint::Stencil => Ok(f.stencil),
                // Only when both are the same image (GL 3.0 §6.1.13).
                AttachmentPoint::DepthStencil if f.depth == f.stencil => Ok(f.depth),
                AttachmentPoint::DepthStencil => Err(GlError::InvalidOperation),
            },
        };
        self.record(r)
    }

    /// The bits of red, green, blue, alpha, depth and stencil of one of the
    /// window framebuffer's buffers (object 0's "attachments", GL 3.0
    /// §6.1.13), or `None` when the window has no such buffer. The window is
    /// single-buffered like OSMesa's; depth and stencil together are one
    /// packed depth-stencil buffer (llvmpipe's `Z24_UNORM_S8_UINT`), so each
    /// reports both sizes (docs/llvmpipe-facts.md, "window attachments").
    pub fn window_buffer_bits(&self, buffer: WindowBuffer) -> Option<[u32; 6]> {
        let fb = self.framebuffer_pending();
        let depth = fb.depth_format().map_or(0, |f| f.bits());
        let stencil = if fb.has_stencil() { 8 } else { 0 };
        let c = fb.color_format();
        match buffer {
            WindowBuffer::Color => Some([
                c.channel_bits(0),
                c.channel_bits(1),
                c.channel_bits(2),
                c.channel_bits(3),
                0,
                0,
            ]),
            WindowBuffer::Depth if depth == 0 => None,
            WindowBuffer::Stencil if stencil == 0 => None,
            WindowBuffer::Depth | WindowBuffer::Stencil if depth > 0 && stencil > 0 => {
                Some([0, 0, 0, 0, depth, stencil])
            }
            WindowBuffer::Depth => Some([0, 0, 0, 0, depth, 0]),
            WindowBuffer::Stencil => Some([0, 0, 0, 0, 0, stencil]),
        }
    }

    /// The bits of red, green, blue, alpha, depth and stencil of `point`'s image.
    pub fn attachment_bits(&self, a: Attachment) -> [u32; 6] {
        match a {
            Attachment::None => [0; 6],
            Attachment::Renderbuffer(n) => self.fbo.renderbuffer(n).map_or([0; 6], |r| r.format.bits()),
            Attachment::Texture { name, level, face, .. } => {
                let img = self
                    .textures
                    .object(name)
                    .and_then(|o| o.image(level as usize, face as usize));
                img.map_or([0; 6], |i| {
                    let s = i.internal.storage();
                    if s.base == BaseFormat::Depth {
                        [0, 0, 0, 0, s.bits[0], 0]
                    } else {
                        [s.bits[0], s.bits[1], s.bits[2], s.bits[3], 0, 0]
                    }
                })
            }
        }
    }

    /// Whether attachment `a` is a float depth image (`GL_DEPTH_COMPONENT32F`,
    /// `GL_DEPTH32F_STENCIL8`): its `GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE` is `GL_FLOAT`.
    pub fn attachment_float_depth(&self, a: Attachment) -> bool {
        match a {
            Attachment::None => false,
            Attachment::Renderbuffer(n) => self.fbo.renderbuffer(n).is_some_and(|r| {
                matches!(
                    r.format,
                    RenderbufferFormat::DepthComponent32F | RenderbufferFormat::Depth32FStencil8
                )
            }),
            Attachment::Texture { name, level, face, .. } => self
                .textures
                .object(name)
                .and_then(|o| o.image(level as usize, face as usize))
                .is_some_and(|i| i.internal.storage().float),
        }
    }

    /// `GL_COLOR_CLEAR_VALUE` as Mesa answers it (`main/get.c`): clamped to
    /// `[0, 1]` (NaN as 0) when fragment colours are clamped for the draw
    /// framebuffer (`_mesa_get_clamp_fragment_color`: always with
    /// `GL_CLAMP_FRAGMENT_COLOR` on, under `GL_FIXED_ONLY` unless a float
    /// object is drawn; the OSMesa window counts as fixed-point whatever its
    /// type), else as `glClearColor` gave it.
    pub fn clear_color_value(&self) -> [f32; 4] {
        let c = self.state().clear_color;
        let float_object = self.fbo.draw != 0 && self.fb.color_format().is_float();
        if float_object && !self.state().clamp_fragment_color {
            return c;
        }
        c.map(|v| if v > 0.0 { v.min(1.0) } else { 0.0 })
    }

    /// Whether attachment `a` is a float colour image (`GL_RGBA16F`, `GL_RGB16F`,
    /// `GL_RGBA32F`, `GL_RGB32F`): its `GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE` is `GL_FLOAT`.
    pub fn attachment_float_color(&self, a: Attachment) -> bool {
        match a {
            Attachment::Renderbuffer(n) => self
                .fbo
                .renderbuffer(n)
                .is_some_and(|r| matches!(r.format.kind(), Some(RenderbufferKind::Color(c)) if c.is_float())),
            Attachment::None | Attachment::Texture { .. } => false,
        }
    }

    /// `glDrawBuffer` on an object: `Some(i)` is `GL_COLOR_ATTACHMENTi`, `None` `GL_NONE`.
    /// On object 0 only `None` and the window's buffers (the caller's
    /// business) are taken; here `None` turns the window's colour writes off.
    pub fn draw_buffer(&mut self, buffer: Option<u32>) -> GlResult {
        self.outside()?;
        let name = self.fbo.draw;
        if buffer.is_some_and(|i| i as usize >= MAX_COLOR_ATTACHMENTS) {
            return self.record(Err(GlError::InvalidOperation));
        }
        if name == 0 {
            if buffer.is_some() {
                return self.record(Err(GlError::InvalidOperation));
            }
            self.finish_scene();
            self.fbo.window_draw_none = true;
            self.fb.set_color_enabled(false);
            return Ok(());
        }
        // The same buffer again (MuJoCo sets `GL_NONE` on its shadow map at
        // every bind): nothing to re-assemble. Releasing would write a
        // depth texture back (a 64 MiB conversion at 4096²) for nothing.
        if self.fbo.framebuffer(name).is_some_and(|f| f.draw_buffer == buffer) {
            return Ok(());
        }
        self.release_draw();
        if let Some(f) = self.fbo.framebuffer_mut(name) {
            f.draw_buffer = buffer;
        }
        self.acquire_draw();
        Ok(())
    }

    /// The window's colour buffer drawn again (`glDrawBuffer(GL_FRONT/BACK/…)` on object 0).
    pub fn draw_buffer_window(&mut self) -> GlResult {
        self.outside()?;
        if self.fbo.draw != 0 {
            return self.record(Err(GlError::InvalidOperation));
        }
        self.finish_scene();
        self.fbo.window_draw_none = false;
        self.fb.set_color_enabled(true);
        Ok(())
    }

    /// `glReadBuffer`: as [`Context::draw_buffer`], for reads; `window` is a
    /// window buffer name on object 0.
    pub fn read_buffer(&mut self, buffer: Option<u32>, window: bool) -> GlResult {
        self.outside()?;
        let name = self.fbo.read;
        if buffer.is_some_and(|i| i as usize >= MAX_COLOR_ATTACHMENTS) {
            return self.record(Err(GlError::InvalidOperation));
        }
        if name == 0 {
            if buffer.is_some() {
                return self.record(Err(GlError::InvalidOperation));
            }
            self.fbo.window_read_none = !window;
            return Ok(());
        }
        if window {
            return self.record(Err(GlError::InvalidOperation));
        }
        // Unchanged: nothing to re-assemble (see `draw_buffer`).
        if self.fbo.framebuffer(name).is_some_and(|f| f.read_buffer == buffer) {
            return Ok(());
        }
        if name == self.fbo.draw {
            self.release_draw();
        }
        if let Some(f) = self.fbo.framebuffer_mut(name) {
            f.read_buffer = buffer;
        }
        self.acquire_draw();
        Ok(())
    }

    /// The description (size, formats) of the draw framebuffer, and whether
    /// it has a colour buffer drawn: what `GL_RED_BITS`, `GL_DEPTH_BITS`, …
    /// answer. `None` for an incomplete object.
    pub fn draw_framebuffer_desc(&mut self) -> Option<(FramebufferDesc, bool)> {
        self.acquire_draw();
        if self.fbo.draw != 0 && self.fbo.checkout.is_none() {
            return None;
        }
        Some((*self.fb.desc(), self.fb.color_enabled()))
    }

    /// `GL_SAMPLES` of the draw framebuffer (the samples of its renderbuffers).
    pub fn draw_framebuffer_samples(&self) -> u32 {
        let Some(f) = self.fbo.framebuffer(self.fbo.draw) else {
            return 0;
        };
        f.color
            .iter()
            .chain([&f.depth, &f.stencil])
            .find_map(|a| match a {
                Attachment::Renderbuffer(n) => self.fbo.renderbuffer(*n).map(|r| r.samples),
                _ => None,
            })
            .unwrap_or(0)
    }

    // ----- assembling and releasing -----

    /// Makes sure the draw framebuffer is assembled; `InvalidFramebufferOperation`
    /// when the bound object is incomplete. Draws, clears and reads call it.
    pub(crate) fn ensure_draw(&mut self) -> GlResult {
        if self.fbo.draw == 0 {
            return Ok(());
        }
        self.acquire_draw();
        if self.fbo.checkout.is_none() {
            return self.record(Err(GlError::InvalidFramebufferOperation));
        }
        Ok(())
    }

    /// Whether the samplers read a depth texture a framebuffer object
    /// rendered into in its units, in place (the default), or the texels
    /// written from them as each object releases it (before the units):
    /// a switch for tests comparing the two, set before rendering.
    #[doc(hidden)]
    pub fn set_depth_units_sampled(&mut self, on: bool) {
        self.finish_scene();
        self.textures.get_mut().sample_units = on;
    }

    /// Before a texture call that reads or writes texture `name`'s images:
    /// writes the draw framebuffer's copy back and releases it (assembled
    /// again at the next draw).
    pub(crate) fn sync_texture(&mut self, name: u32) {
        if self.fbo.holds_texture(name) {
            self.release_draw();
        }
        // Depth kept as units written into the texels, which the call reads.
        let units = |o: &crate::texture::TextureObject| {
            o.images
                .iter()
                .flatten()
                .any(|i| i.units.as_ref().is_some_and(|u| !u.written))
        };
        if name != 0 && self.textures.object(name).is_some_and(units) {
            if let Some(o) = self.textures.get_mut().object_mut(name) {
                o.images.iter_mut().flatten().for_each(TexImage::materialise);
            }
        }
    }

    /// `glDeleteTextures` of `name`: written back, then detached from the
    /// bound framebuffer objects (GL 3.0 §4.4.2).
    pub(crate) fn forget_texture(&mut self, name: u32) {
        if name == 0 || !self.textures.is_texture(name) {
            return;
        }
        self.release_draw();
        for fb in [self.fbo.draw, self.fbo.read] {
            if let Some(f) = self.fbo.framebuffer_mut(fb) {
                for a in f.color.iter_mut().chain([&mut f.depth, &mut f.stencil]) {
                    if matches!(a, Attachment::Texture { name: n, .. } if *n == name) {
                        *a = Attachment::None;
                    }
                }
            }
        }
        self.acquire_draw();
    }

    /// Before a draw sampling the textures `names`: writes back an attached
    /// one (a feedback loop), keeping the framebuffer assembled.
    pub(crate) fn sync_sampled(&mut self) {
        if !self.fbo.holds_any_texture() {
            return;
        }
        let mask = self.tex_units.enabled_mask();
        let targets = [
            TexTarget::D1,
            TexTarget::D2,
            TexTarget::D3,
            TexTarget::Cube,
            TexTarget::Rect,
        ];
        let held = (0..softgl_jit::texture::MAX_UNITS)
            .filter(|u| mask & (1 << u) != 0)
            .flat_map(|u| targets.map(|t| self.textures.binding(u, t)))
            .any(|n| n != 0 && self.fbo.holds_texture(n));
        if held {
            self.release_draw();
            self.acquire_draw();
        }
    }

    /// Assembles a draw object whose assembly `glBindFramebuffer` deferred
    /// ([`FboState::deferred`]), for a call that uses `Context::fb` as it is
    /// (pixel rectangles, `glAccum`).
    pub(crate) fn acquire_deferred(&mut self) {
        if self.fbo.deferred {
            self.acquire_draw();
        }
    }

    /// Assembles the bound draw object into `self.fb` when complete and not yet done.
    fn acquire_draw(&mut self) {
        self.fbo.deferred = false;
        let name = self.fbo.draw;
        if name == 0 || self.fbo.checkout.is_some() {
            return;
        }
        if status(&self.fbo, &self.textures, name) != FramebufferStatus::Complete {
            return;
        }
        let Some(f) = self.fbo.framebuffer(name) else {
            return;
        };
        let color = f.draw_buffer.map_or(Attachment::None, |i| f.color[i as usize]);
        let (depth, stencil) = (f.depth, f.stencil);
        let checkout = Checkout {
            fbo: name,
            color,
            depth,
            stencil,
        };
        match self.assemble(checkout, true) {
            Ok(fb) => {
                self.finish_scene();
                let window = std::mem::replace(&mut self.fb, fb);
                self.fbo.window = Some(window);
                self.fbo.checkout = Some(checkout);
                self.follow_samples();
            }
            Err(e) => {
                self.record_error(e);
            }
        }
    }

    /// Puts the draw framebuffer's buffers back where they live (writing
    /// texture copies back), and the window framebuffer in its place.
    pub(crate) fn release_draw(&mut self) {
        let Some(checkout) = self.fbo.checkout else {
            return;
        };
        self.finish_scene();
        let Some(window) = self.fbo.window.take() else {
            return;
        };
        let fb = std::mem::replace(&mut self.fb, window);
        self.fbo.checkout = None;
        self.follow_samples();
        self.disassemble(fb, checkout, true);
    }

    /// A framebuffer of `c`'s attachments. `take`: renderbuffer storage is
    /// moved out (the draw framebuffer); otherwise copied from wherever it
    /// is (a read framebuffer while the draw one holds it).
    fn assemble(&mut self, c: Checkout, take: bool) -> GlResult<Framebuffer> {
        let mut fb = self.assemble_sample(c, 0, take)?;
        // A multisampled object (its images all have the same samples:
        // `status`): samples 1.. beside sample 0, as `new_multisample`.
        let samples = [c.color, c.depth, c.stencil]
            .iter()
            .filter_map(|a| image_of(&self.fbo, &self.textures, *a))
            .map(|i| i.samples)
            .max()
            .unwrap_or(0);
        for s in 1..samples as usize {
            match self.assemble_sample(c, s, take) {
                Ok(more) => fb.samples.push(more),
                Err(e) => {
                    if take {
                        self.disassemble(fb, c, false);
                    }
                    return Err(e);
                }
            }
        }
        Ok(fb)
    }

    /// Sample `s`'s framebuffer of `c`'s attachments (see [`Context::assemble`]).
    fn assemble_sample(&mut self, c: Checkout, s: usize, take: bool) -> GlResult<Framebuffer> {
        let images: Vec<Option<Image>> = [c.color, c.depth, c.stencil]
            .iter()
            .map(|a| image_of(&self.fbo, &self.textures, *a))
            .collect();
        let present: Vec<&Image> = images.iter().flatten().collect();
        let width = present.iter().map(|i| i.width).min().unwrap_or(0);
        let height = present.iter().map(|i| i.height).min().unwrap_or(0);
        // Images larger than the framebuffer (ARB_framebuffer_object allows
        // mixed sizes) are not supported by the single-size Framebuffer:
        // the caller reports such objects unsupported.
        if present.iter().any(|i| i.width != width || i.height != height) || width == 0 {
            return Err(GlError::InvalidFramebufferOperation);
        }
        let n = width as usize * height as usize;
        let color_format = match images[0].and_then(|i| i.kind) {
            Some(RenderbufferKind::Color(f)) => f,
            _ => ColorFormat::Rgb565,
        };
        let depth_format = match images[1].and_then(|i| i.kind) {
            Some(RenderbufferKind::Depth(d) | RenderbufferKind::DepthStencil(d)) => Some(d),
            _ => None,
        };
        let has_stencil = c.stencil != Attachment::None;
        // The colour bytes.
        let color = match c.color {
            Attachment::None => {
                let f = self.fbo.framebuffer_mut(c.fbo).ok_or(GlError::InvalidOperation)?;
                // Samples 1.. of a multisampled object draw into scratch of their own.
                let mut v = if s == 0 {
                    std::mem::take(&mut f.scratch)
                } else {
                    Vec::new()
                };
                if v.len() != n * 2 {
                    v = alloc(n * 2, 0u8)?;
                }
                v
            }
            a => self.take_color(a, s, take)?,
        };
        let depth = match c.depth {
            Attachment::None => None,
            a => Some(self.take_depth(c.fbo, a, s, take)?),
        };
        let stencil = match c.stencil {
            Attachment::None => None,
            a => Some(self.take_stencil(a, s, take)?),
        };
        let desc = FramebufferDesc {
            width,
            height,
            color: color_format,
            depth_bits: FramebufferDesc::depth_bits_of(depth_format),
            stencil_bits: if has_stencil { 8 } else { 0 },
        };
        let mut fb = Framebuffer::from_parts(desc, color, depth, stencil)?;
        fb.set_color_enabled(c.color != Attachment::None);
        Ok(fb)
    }

    /// The inverse of [`Context::assemble`]: `write`: texture copies are written back.
    fn disassemble(&mut self, mut fb: Framebuffer, c: Checkout, write: bool) {
        let more = std::mem::take(&mut fb.samples);
        self.disassemble_sample(fb, c, 0, write);
        for (s, fb) in more.into_iter().enumerate() {
            self.disassemble_sample(fb, c, s + 1, write);
        }
    }

    /// Puts sample `s`'s buffers back (see [`Context::disassemble`]).
    fn disassemble_sample(&mut self, fb: Framebuffer, c: Checkout, s: usize, write: bool) {
        let (w, h) = (fb.width(), fb.height());
        let (color, depth, stencil) = fb.into_parts();
        match c.color {
            Attachment::None => {
                if let Some(f) = self.fbo.framebuffer_mut(c.fbo).filter(|_| s == 0) {
                    f.scratch = color;
                }
            }
            Attachment::Renderbuffer(n) => self.put_rb(n, s, |s| match s {
                None => Some(RbStorage::Color(color)),
                other => other,
            }),
            Attachment::Texture { .. } if write => self.write_texture(c.color, w, h, |img, off| {
                let len = w as usize * h as usize * img.texel_format().bytes_per_texel();
                img.texels_mut()[off..off + len].copy_from_slice(&color[..len]);
            }),
            Attachment::Texture { .. } => {}
        }
        // Depth and stencil may be one renderbuffer.
        let mut depth = depth;
        let mut stencil = stencil;
        if let (Attachment::Renderbuffer(d), Attachment::Renderbuffer(st)) = (c.depth, c.stencil) {
            if d == st {
                if let (Some(dv), Some(sv)) = (depth.take(), stencil.take()) {
                    self.put_rb(d, s, |_| Some(RbStorage::DepthStencil(dv, sv)));
                }
            }
        }
        if let Some(dv) = depth {
            match c.depth {
                Attachment::Renderbuffer(n) => self.put_rb(n, s, |s| match s {
                    Some(RbStorage::Stencil(sv)) => Some(RbStorage::DepthStencil(dv, sv)),
                    None => Some(RbStorage::Depth(dv)),
                    other => other,
                }),
                Attachment::Texture { .. } if write => {
                    let bits = dv.format().bits();
                    let (mut spare, mut rendered) = (None, None);
                    let sample_units = self.textures.sample_units;
                    self.write_texture(c.depth, w, h, |img, off| {
                        // 24-bit and float depth of a 2D image: the buffer
                        // becomes the image's depth, read in place.
                        let units = match dv {
                            DepthBuffer::D24(z) if img.depth == 1 => Ok((z, true)),
                            DepthBuffer::D32F(z) if img.depth == 1 => Ok((z, false)),
                            dv => Err(dv),
                        };
                        match units {
                            Ok((z, unorm24)) => {
                                let z = std::sync::Arc::new(z);
                                rendered = Some(std::sync::Arc::downgrade(&z));
                                let old = img.units.replace(ImageUnits {
                                    z,
                                    unorm24,
                                    written: false,
                                });
                                if !sample_units {
                                    img.materialise();
                                }
                                spare = old.and_then(|u| {
                                    let z = std::sync::Arc::try_unwrap(u.z).ok()?;
                                    Some(if u.unorm24 {
                                        DepthBuffer::D24(z)
                                    } else {
                                        DepthBuffer::D32F(z)
                                    })
                                });
                            }
                            Err(dv) => {
                                let t = &mut img.texels_mut()[off..];
                                let n = w as usize * h as usize;
                                convert_back(&dv, bits, &mut t[..4 * n]);
                            }
                        }
                    });
                    if let Some(f) = self.fbo.framebuffer_mut(c.fbo) {
                        f.spare_depth = spare.or(f.spare_depth.take());
                        f.rendered = rendered.map(|w| (c.depth, w));
                    }
                }
                _ => {}
            }
        }
        if let (Some(sv), a @ Attachment::Texture { layer, .. }, true) = (&stencil, c.stencil, write) {
            self.write_texture(a, w, h, |img, _| {
                let off = img.stencil_offset(0, 0, layer as usize);
                img.stencil_texels_mut()[off..off + sv.len()].copy_from_slice(sv);
            });
        }
        if let (Some(sv), Attachment::Renderbuffer(n)) = (stencil, c.stencil) {
            self.put_rb(n, s, |s| match s {
                Some(RbStorage::Depth(dv)) => Some(RbStorage::DepthStencil(dv, sv)),
                None => Some(RbStorage::Stencil(sv)),
                other => other,
            });
        }
    }

    /// Puts sample `s`'s storage of renderbuffer `name` back through `f`.
    fn put_rb(&mut self, name: u32, s: usize, f: impl FnOnce(Option<RbStorage>) -> Option<RbStorage>) {
        if let Some(slot) = self
            .fbo
            .renderbuffers
            .get_mut(name)
            .and_then(|rb| rb.storage.get_mut(s))
        {
            *slot = f(slot.take());
        }
    }

    /// Runs `f` on texture attachment `a`'s image and the byte offset of its layer.
    fn write_texture(&mut self, a: Attachment, w: u32, h: u32, f: impl FnOnce(&mut TexImage, usize)) {
        let Attachment::Texture {
            name,
            level,
            face,
            layer,
        } = a
        else {
            return;
        };
        let Some(obj) = self.textures.get_mut().object_mut(name) else {
            return;
        };
        if let Some(Some(img)) = obj.image_mut(level as usize, face as usize) {
            if img.width == w && img.height == h {
                let off = img.offset(0, 0, layer as usize);
                f(img, off);
            }
        }
    }

    /// Object `fbo`'s spare depth buffer ([`FramebufferObject::spare_depth`])
    /// when it is of `format` and `n` pixels.
    fn spare_depth(&mut self, fbo: u32, format: DepthFormat, n: usize) -> Option<Vec<u32>> {
        let f = self.fbo.framebuffer_mut(fbo)?;
        match f.spare_depth.take()? {
            DepthBuffer::D24(z) if format == DepthFormat::D24 && z.len() == n => Some(z),
            DepthBuffer::D32F(z) if format == DepthFormat::D32F && z.len() == n => Some(z),
            _ => None,
        }
    }

    /// The depth units texture attachment `a`'s image holds ([`TexImage::units`]).
    fn texture_units(&self, a: Attachment) -> Option<ImageUnits> {
        let Attachment::Texture { name, level, face, .. } = a else {
            return None;
        };
        let img = self.textures.object(name)?.image(level as usize, face as usize)?;
        img.units.clone()
    }

    /// The texels of texture attachment `a`'s layer.
    fn texture_layer(&self, a: Attachment) -> Option<(&[u8], usize)> {
        let Attachment::Texture {
            name,
            level,
            face,
            layer,
        } = a
        else {
            return None;
        };
        let img = self.textures.object(name)?.image(level as usize, face as usize)?;
        let n = img.width as usize * img.height as usize;
        let off = img.offset(0, 0, layer as usize);
        let bpp = img.texel_format().bytes_per_texel();
        Some((img.texels.get(off..off + n * bpp)?, n))
    }

    fn take_color(&mut self, a: Attachment, s: usize, take: bool) -> GlResult<Vec<u8>> {
        match a {
            Attachment::Renderbuffer(n) => match self.rb_storage(n, s, take)? {
                RbStorage::Color(v) => Ok(v),
                _ => Err(GlError::InvalidOperation),
            },
            _ => {
                let (t, _) = self.texture_layer(a).ok_or(GlError::InvalidOperation)?;
                let mut v = alloc(t.len(), 0u8)?;
                v.copy_from_slice(t);
                Ok(v)
            }
        }
    }

    /// Sample `s`'s depth buffer of attachment `a` of object `fbo` (see
    /// [`Context::assemble`]). A texture image's depth is its units when it
    /// holds them, else its texels converted; a draw framebuffer whose
    /// first use clears the whole depth buffer ([`FboState::depth_cleared`])
    /// skips both (MuJoCo's shadow map, every pass).
    fn take_depth(&mut self, fbo: u32, a: Attachment, s: usize, take: bool) -> GlResult<DepthBuffer> {
        match a {
            Attachment::Renderbuffer(n) => {
                match self.rb_storage(n, s, take)? {
                    RbStorage::Depth(d) => Ok(d),
                    RbStorage::DepthStencil(d, st) => {
                        // The stencil half stays for `take_stencil`.
                        if take {
                            self.put_rb(n, s, |_| Some(RbStorage::Stencil(st)));
                        }
                        Ok(d)
                    }
                    _ => Err(GlError::InvalidOperation),
                }
            }
            _ => {
                let kind = image_of(&self.fbo, &self.textures, a).and_then(|i| i.kind);
                let Some(RenderbufferKind::Depth(format)) = kind else {
                    return Err(GlError::InvalidOperation);
                };
                let units = self.texture_units(a);
                let cleared = take && self.fbo.depth_cleared;
                // The units this object rendered, still the image's: drawn
                // into again as they are (as the texels would be converted
                // by another object, or once written over).
                let rendered = match self.fbo.framebuffer_mut(fbo) {
                    Some(f) if take && s == 0 => f.rendered.take(),
                    _ => None,
                };
                let own = units.as_ref().filter(|u| {
                    rendered
                        .as_ref()
                        .is_some_and(|(at, w)| *at == a && std::sync::Weak::as_ptr(w) == std::sync::Arc::as_ptr(&u.z))
                });
                if own.is_some() || cleared {
                    let n = self.texture_layer(a).ok_or(GlError::InvalidOperation)?.1;
                    let spare = if take { self.spare_depth(fbo, format, n) } else { None };
                    let mut z = match spare {
                        Some(z) => z,
                        None => alloc(n, 0u32)?,
                    };
                    match own.filter(|_| !cleared) {
                        Some(u) if u.z.len() == n && u.unorm24 == (format == DepthFormat::D24) => {
                            z.copy_from_slice(&u.z)
                        }
                        // Units of another size or kind: the image was redefined
                        // past `sync_texture`, which cannot happen.
                        Some(_) => return Err(GlError::InvalidOperation),
                        None => {}
                    }
                    return Ok(match format {
                        DepthFormat::D16 => DepthBuffer::D16(z.into_iter().map(|v| v as u16).collect()),
                        DepthFormat::D24 => DepthBuffer::D24(z),
                        DepthFormat::D32 => DepthBuffer::D32(z),
                        DepthFormat::D32F => DepthBuffer::D32F(z),
                    });
                }
                let (t, n) = self.texture_layer(a).ok_or(GlError::InvalidOperation)?;
                // Units the texels do not hold yet: converted from the texels
                // they make (`TexImage::materialise` without the image).
                let written;
                let t = match units.filter(|u| !u.written) {
                    Some(u) => {
                        let mut v = alloc(4 * n, 0u8)?;
                        u.write_texels(&mut v);
                        written = v;
                        &written[..]
                    }
                    None => t,
                };
                if format == DepthFormat::D32F {
                    let mut out = alloc(n, 0u32)?;
                    for (o, t) in out.iter_mut().zip(t.chunks_exact(4)) {
                        *o = format.from_window(f32::from_ne_bytes([t[0], t[1], t[2], t[3]]));
                    }
                    return Ok(DepthBuffer::D32F(out));
                }
                let bits = format.bits();
                let z = |i: usize| {
                    let f = f32::from_ne_bytes([t[4 * i], t[4 * i + 1], t[4 * i + 2], t[4 * i + 3]]);
                    // The nearest integer is the answer unless neighbours share an f32.
                    let max = ((1u64 << bits) - 1) as f64;
                    let guess = (f64::from(f) * max).round().clamp(0.0, max) as u32;
                    if depth_sampled(guess, bits) == f {
                        guess
                    } else {
                        depth_unsampled(f, bits)
                    }
                };
                let mut out = alloc(n, 0u32)?;
                // Runs of equal texels (a fresh image is all zeros, a shadow
                // map mostly its clear value) convert once: binding a new
                // 4096² map cost ~930 M instructions, 55 a texel (callgrind).
                let mut last: Option<(u32, u32)> = None;
                for (i, (o, b)) in out.iter_mut().zip(t.chunks_exact(4)).enumerate() {
                    let bits = u32::from_ne_bytes([b[0], b[1], b[2], b[3]]);
                    *o = match last {
                        Some((b, v)) if b == bits => v,
                        _ => {
                            let v = z(i);
                            last = Some((bits, v));
                            v
                        }
                    };
                }
                Ok(match format {
                    DepthFormat::D16 => DepthBuffer::D16(out.into_iter().map(|v| v as u16).collect()),
                    DepthFormat::D24 => DepthBuffer::D24(out),
                    DepthFormat::D32 => DepthBuffer::D32(out),
                    DepthFormat::D32F => DepthBuffer::D32F(out),
                })
            }
        }
    }

    fn take_stencil(&mut self, a: Attachment, s: usize, take: bool) -> GlResult<Vec<u8>> {
        match a {
            Attachment::Renderbuffer(n) => match self.rb_storage(n, s, take)? {
                RbStorage::Stencil(s) | RbStorage::DepthStencil(_, s) => Ok(s),
                _ => Err(GlError::InvalidOperation),
            },
            Attachment::Texture {
                name,
                level,
                face,
                layer,
            } => {
                // A depth-stencil texture's stencil plane (a copy: the image keeps its own).
                let img = self
                    .textures
                    .object(name)
                    .and_then(|o| o.image(level as usize, face as usize));
                let img = img
                    .filter(|i| i.internal.stencil_bits() > 0)
                    .ok_or(GlError::InvalidOperation)?;
                let n = img.width as usize * img.height as usize;
                let off = img.stencil_offset(0, 0, layer as usize);
                Ok(img.texels.get(off..off + n).ok_or(GlError::InvalidOperation)?.to_vec())
            }
            Attachment::None => Err(GlError::InvalidOperation),
        }
    }

    /// Sample `s`'s storage of renderbuffer `n`: moved out (`take`), or
    /// copied; when the draw framebuffer holds it, copied from there.
    fn rb_storage(&mut self, n: u32, s: usize, take: bool) -> GlResult<RbStorage> {
        let rb = self.fbo.renderbuffer(n).ok_or(GlError::InvalidOperation)?;
        if let Some(st) = rb.storage.get(s).ok_or(GlError::InvalidOperation)? {
            if take {
                let rb = self.fbo.renderbuffers.get_mut(n);
                return rb
                    .and_then(|r| r.storage.get_mut(s)?.take())
                    .ok_or(GlError::InvalidOperation);
            }
            return Ok(st.clone());
        }
        // Held by the draw framebuffer: copy its buffers (a read of a
        // renderbuffer that is also drawn into).
        let c = self.fbo.checkout.ok_or(GlError::InvalidOperation)?;
        let fb = self.fb.sample(s as u32).ok_or(GlError::InvalidOperation)?;
        let a = Attachment::Renderbuffer(n);
        let depth = (c.depth == a).then(|| fb.depth_buffer().cloned()).flatten();
        let stencil = (c.stencil == a)
            .then(|| fb.stencil_buffer().map(<[u8]>::to_vec))
            .flatten();
        Ok(match (c.color == a, depth, stencil) {
            (true, _, _) => RbStorage::Color(fb.color_bytes().to_vec()),
            (_, Some(d), Some(s)) => RbStorage::DepthStencil(d, s),
            (_, Some(d), None) => RbStorage::Depth(d),
            (_, None, Some(s)) => RbStorage::Stencil(s),
            _ => return Err(GlError::InvalidOperation),
        })
    }

    // ----- reading -----

    /// The read framebuffer for one read: `InvalidFramebufferOperation` when incomplete.
    fn take_read(&mut self, need_color: bool) -> GlResult<ReadFb> {
        self.take_read_as(need_color, false).map(|(r, _)| r)
    }

    /// [`Context::take_read`]; `lend`: an object's renderbuffers are moved
    /// out instead of copied when the draw framebuffer does not hold any of
    /// them (and it has no texture image), with what to put back through
    /// [`Context::disassemble`] (`write` false) once read. A multisampled
    /// 640×480 object was 11 MB copied, in fresh pages, per MuJoCo resolve.
    fn take_read_as(&mut self, need_color: bool, lend: bool) -> GlResult<(ReadFb, Option<Checkout>)> {
        self.ensure_draw()?;
        let (read, draw) = (self.fbo.read, self.fbo.draw);
        if read == 0 {
            if need_color && self.fbo.window_read_none {
                return Err(GlError::InvalidOperation);
            }
            return Ok((if draw == 0 { ReadFb::Draw } else { ReadFb::Window }, None));
        }
        if status(&self.fbo, &self.textures, read) != FramebufferStatus::Complete {
            return Err(GlError::InvalidFramebufferOperation);
        }
        let f = self.fbo.framebuffer(read).ok_or(GlError::InvalidOperation)?;
        let color = f.read_buffer.map_or(Attachment::None, |i| f.color[i as usize]);
        if need_color && color == Attachment::None {
            return Err(GlError::InvalidOperation);
        }
        let c = Checkout {
            fbo: read,
            color,
            depth: f.depth,
            stencil: f.stencil,
        };
        if let Some(d) = self.fbo.checkout {
            if d.fbo == read && d.color == color {
                return Ok((ReadFb::Draw, None));
            }
        }
        let attachments = [c.color, c.depth, c.stencil];
        let held = self.fbo.checkout.is_some_and(|d| {
            attachments
                .iter()
                .any(|a| matches!(a, Attachment::Renderbuffer(_)) && [d.color, d.depth, d.stencil].contains(a))
        });
        let textured = attachments.iter().any(|a| matches!(a, Attachment::Texture { .. }));
        let lend = lend && !held && !textured;
        let fb = self.assemble(c, lend)?;
        Ok((ReadFb::Assembled(fb), lend.then_some(c)))
    }

    /// The framebuffer reads come from now (`GL_READ_FRAMEBUFFER`'s, its
    /// read buffer as colour), every draw rasterized; view it with
    /// [`Context::read_view`]. `need_color`: `InvalidOperation` when the
    /// read buffer is `GL_NONE` or empty; `InvalidFramebufferOperation` for
    /// an incomplete object. Errors are recorded.
    pub fn read_framebuffer(&mut self, need_color: bool) -> GlResult<ReadFb> {
        self.outside()?;
        self.finish_scene();
        let r = self.take_read_single(need_color);
        self.record(r)
    }

    /// [`Context::take_read`] for the reads other than a blit:
    /// `InvalidOperation` from a multisampled object (GL 3.0 §4.3.2,
    /// Mesa's `_mesa_ReadnPixelsARB`, `copy_texture_sub_image_err`,
    /// `_mesa_CopyPixels`: after the completeness check). A multisampled
    /// window is read resolved.
    fn take_read_single(&mut self, need_color: bool) -> GlResult<ReadFb> {
        let r = self.take_read(need_color)?;
        if self.fbo.read != 0 && self.samples_of(self.fbo.read) > 0 {
            return Err(GlError::InvalidOperation);
        }
        Ok(r)
    }

    /// The framebuffer of a [`Context::read_framebuffer`].
    pub fn read_view<'a>(&'a self, r: &'a ReadFb) -> &'a Framebuffer {
        self.read_ref(r)
    }

    pub(crate) fn take_read_unflushed(&mut self, need_color: bool) -> GlResult<ReadFb> {
        self.take_read_single(need_color)
    }

    pub(crate) fn read_ref<'a>(&'a self, r: &'a ReadFb) -> &'a Framebuffer {
        match r {
            ReadFb::Draw => &self.fb,
            ReadFb::Window => self.fbo.window.as_ref().unwrap_or(&self.fb),
            ReadFb::Assembled(fb) => fb,
        }
    }

    /// Runs `f` on the read framebuffer (`GL_READ_FRAMEBUFFER`'s, through
    /// its read buffer), with every draw rasterized. `need_color`: a colour
    /// read, `InvalidOperation` when the read buffer is `GL_NONE`.
    pub fn with_read_framebuffer<R>(&mut self, need_color: bool, f: impl FnOnce(&Framebuffer) -> R) -> GlResult<R> {
        self.outside()?;
        self.finish_scene();
        let r = self.take_read_single(need_color);
        let r = self.record(r)?;
        let out = f(self.read_ref(&r));
        // Nothing was moved out of the objects for a read (copies only).
        drop(r);
        Ok(out)
    }

    // ----- blits -----

    /// Whether both bound framebuffers are complete (`glBlitFramebuffer`
    /// checks it before its arguments).
    pub fn framebuffers_complete(&self) -> bool {
        let c = |n| status(&self.fbo, &self.textures, n) == FramebufferStatus::Complete;
        c(self.fbo.draw) && c(self.fbo.read)
    }

    /// `glBlitFramebuffer`: `src` and `dst` are `[x0, y0, x1, y1]`; the
    /// scissor test applies to the destination. Errors in Mesa's order
    /// (`main/blit.c`), after the caller's enum checks.
    pub fn blit_framebuffer(&mut self, src: [i32; 4], dst: [i32; 4], mask: BlitMask, filter: BlitFilter) -> GlResult {
        self.outside()?;
        if !self.framebuffers_complete() {
            return self.record(Err(GlError::InvalidFramebufferOperation));
        }
        if (mask.depth || mask.stencil) && filter != BlitFilter::Nearest {
            return self.record(Err(GlError::InvalidOperation));
        }
        let read_samples = self
            .fbo
            .framebuffer(self.fbo.read)
            .map_or(0, |_| self.samples_of(self.fbo.read));
        let draw_samples = self.draw_framebuffer_samples();
        if read_samples > 0 && draw_samples > 0 && read_samples != draw_samples {
            return self.record(Err(GlError::InvalidOperation));
        }
        let size = |r: [i32; 4]| {
            (
                (i64::from(r[2]) - i64::from(r[0])).abs(),
                (i64::from(r[3]) - i64::from(r[1])).abs(),
            )
        };
        if (read_samples > 0 || draw_samples > 0) && size(src) != size(dst) {
            return self.record(Err(GlError::InvalidOperation));
        }
        self.ensure_draw()?;
        self.finish_scene();
        let read = self.take_read_as(false, true);
        let (read, lent) = self.record(read)?;
        let r = self.blit_from(&read, src, dst, mask, filter);
        if let (ReadFb::Assembled(fb), Some(c)) = (read, lent) {
            self.disassemble(fb, c, false);
        }
        self.record(r)
    }

    /// `GL_SAMPLES` of object `name` (0 for the window and single-sampled objects).
    pub(crate) fn samples_of(&self, name: u32) -> u32 {
        let Some(f) = self.fbo.framebuffer(name) else {
            return 0;
        };
        f.color
            .iter()
            .chain([&f.depth, &f.stencil])
            .find_map(|a| match a {
                Attachment::Renderbuffer(n) => self.fbo.renderbuffer(*n).map(|r| r.samples),
                _ => None,
            })
            .unwrap_or(0)
    }

    fn blit_from(
        &mut self,
        read: &ReadFb,
        src: [i32; 4],
        dst: [i32; 4],
        mask: BlitMask,
        filter: BlitFilter,
    ) -> GlResult {
        let draw_color = self.fb.color_enabled();
        let (read_color, depth_ok, stencil_ok) = {
            let s = self.read_ref(read);
            let color = match read {
                ReadFb::Draw | ReadFb::Window => {
                    if self.fbo.read == 0 {
                        !self.fbo.window_read_none
                    } else {
                        s.color_enabled()
                    }
                }
                ReadFb::Assembled(fb) => fb.color_enabled(),
            };
            let d = self.fb.depth_format();
            let sd = s.depth_format();
            let depth = match (mask.depth, sd, d) {
                (true, Some(a), Some(b)) if a != b => return Err(GlError::InvalidOperation),
                (true, Some(_), Some(_)) => true,
                _ => false,
            };
            let stencil = mask.stencil && s.has_stencil() && self.fb.has_stencil();
            if stencil && sd.is_some() && d.is_some() && sd != d {
                return Err(GlError::InvalidOperation);
            }
            (color, depth, stencil)
        };
        let color = mask.color && read_color && draw_color;
        if !(color || depth_ok || stencil_ok) {
            return Ok(());
        }
        let st = self.state();
        let clip = if st.scissor_test {
            let b = st.scissor;
            self.fb
                .clip_rect(i64::from(b.x), i64::from(b.y), i64::from(b.width), i64::from(b.height))
        } else {
            self.fb.bounds()
        };
        let what = (color, depth_ok, stencil_ok);
        match read {
            // Its own buffers (copies of the objects').
            ReadFb::Assembled(from) => blit_samples(from, &mut self.fb, src, dst, clip, what, filter),
            // The window's buffers, waiting beside the object drawn.
            ReadFb::Window => match self.fbo.window.as_ref() {
                Some(from) => blit_samples(from, &mut self.fb, src, dst, clip, what, filter),
                None => Ok(()),
            },
            // One framebuffer: the source is copied first.
            ReadFb::Draw => {
                let from = self.fb.clone();
                blit_samples(&from, &mut self.fb, src, dst, clip, what, filter)
            }
        }
    }
}

/// One axis of a blit as llvmpipe's blitter draws it (`util/u_blitter.c`
/// `get_texcoords`, then the rectangle's linear interpolation): the source
/// edges normalized by the source size in f32, a plane `a0 + dadx·x`
/// evaluated at the destination pixel centre. Destination pixels `d0..d1`
/// (`d0 < d1`) take source positions `s_first`…`s_last` (reversed for a flip).
#[derive(Clone, Copy, Debug)]
struct Axis {
    a0: f32,
    dadx: f32,
    len: f32,
}

impl Axis {
    fn new(d0: i32, d1: i32, s_first: i32, s_last: i32, len: u32) -> Axis {
        let lenf = len as f32;
        let (u0, u1) = (s_first as f32 / lenf, s_last as f32 / lenf);
        let dadx = (u1 - u0) / (d1 - d0) as f32;
        Axis {
            a0: u0 - dadx * d0 as f32,
            dadx,
            len: lenf,
        }
    }

    /// The normalized source coordinate at destination pixel `x`.
    fn at(&self, x: u32) -> f32 {
        self.a0 + self.dadx * (x as f32 + 0.5)
    }

    /// The nearest texel (`ifloor(u · len)`), `None` outside the source.
    fn nearest(&self, x: u32) -> Option<u32> {
        let i = (self.at(x) * self.len).floor();
        (i >= 0.0 && i < self.len).then_some(i as u32)
    }
}

/// [`blit`] between framebuffers of any samples (the caller checked GL's
/// rules: equal counts or one side single-sampled, unscaled when either is
/// multisampled): a multisampled source into a single-sampled destination
/// is resolved first ([`Framebuffer::resolve`]: colour averaged, depth and
/// stencil sample 0's, as llvmpipe); equal counts copy sample to sample; a
/// single-sampled source is written into every sample.
fn blit_samples(
    from: &Framebuffer,
    to: &mut Framebuffer,
    s: [i32; 4],
    d: [i32; 4],
    clip: Rect,
    what: (bool, bool, bool),
    filter: BlitFilter,
) -> GlResult {
    let (n_from, n_to) = (from.samples(), to.samples());
    if n_from > 1 && n_to == 1 && what.0 {
        // Unscaled and unflipped (GL makes a multisampled blit unscaled):
        // the colour resolved straight into the destination's rectangle.
        if let Some(r) = unscaled(from, to, s, d, clip) {
            if r.moved.is_empty() || from.resolve_color_into(to, r.moved) {
                blit(from, to, s, d, clip, (false, what.1, what.2), filter);
                return Ok(());
            }
        }
    }
    if n_from > 1 && n_to == 1 && !what.0 {
        // Depth and stencil only: sample 0's are `from`'s own buffers.
        blit(from, to, s, d, clip, what, filter);
        return Ok(());
    }
    if n_from > 1 && n_to == 1 {
        let resolved = from.resolve_for(to.color_format())?;
        blit(&resolved, to, s, d, clip, what, filter);
        return Ok(());
    }
    for k in 0..n_to {
        let src = if n_from == n_to { from.sample(k) } else { Some(from) };
        if let (Some(src), Some(dst)) = (src, to.sample_mut(k)) {
            blit(src, dst, s, d, clip, what, filter);
        }
    }
    Ok(())
}

/// A blit that moves pixels one for one: the destination pixels written.
#[derive(Clone, Copy, Debug)]
struct Unscaled {
    moved: Rect,
}

/// [`blit`]'s destination pixels when the source and destination
/// rectangles have the same size, neither flipped, the source at the same
/// place as the destination and inside `from` wherever it is read: then
/// each destination pixel takes the source pixel at its own position
/// ([`Axis::nearest`] of an unscaled axis is `x - d0 + s0`, its error
/// ≤ 2^-24 · 16384 far from a half), so rows copy as they are.
fn unscaled(from: &Framebuffer, to: &Framebuffer, s: [i32; 4], d: [i32; 4], clip: Rect) -> Option<Unscaled> {
    if s != d || s[0] >= s[2] || s[1] >= s[3] || s[0] < 0 || s[1] < 0 {
        return None;
    }
    let out = clip.intersect(to.bounds()).intersect(Rect {
        x0: d[0] as u32,
        y0: d[1] as u32,
        x1: d[2] as u32,
        y1: d[3] as u32,
    });
    // Pixels past the source are left alone by `blit`: not ours to copy.
    let moved = out.intersect(from.bounds());
    Some(Unscaled { moved })
}

/// Copies `src`'s rectangle to `dst`'s, scaled and flipped, inside `clip`,
/// as llvmpipe's blitter draws it ([`Axis`]): NEAREST takes `ifloor(u·len)`;
/// LINEAR samples the source as an RGBA8 texture with CLAMP_TO_EDGE on
/// llvmpipe's AoS path (8.8 fixed-point coordinates, 8-bit lerps:
/// `softgl_jit::texture::filter::aos`). Depth and stencil are copied
/// nearest. Destination pixels whose nearest source texel is outside the
/// read buffer are left as they are (Mesa clips such blits, `_mesa_clip_blit`).
fn blit(
    from: &Framebuffer,
    to: &mut Framebuffer,
    s: [i32; 4],
    d: [i32; 4],
    clip: Rect,
    (color, depth, stencil): (bool, bool, bool),
    filter: BlitFilter,
) {
    use softgl_jit::texture::filter::{aos, Level};
    use softgl_jit::texture::{Filter, Image, TexelFormat, Wrap};
    // Destination rectangles are drawn left to right, bottom to top; the
    // source edges follow the destination's (a reversed pair flips).
    let (dx0, dx1, sxa, sxb) = if d[0] <= d[2] {
        (d[0], d[2], s[0], s[2])
    } else {
        (d[2], d[0], s[2], s[0])
    };
    let (dy0, dy1, sya, syb) = if d[1] <= d[3] {
        (d[1], d[3], s[1], s[3])
    } else {
        (d[3], d[1], s[3], s[1])
    };
    // Nothing to copy (a resolve's colour went `resolve_color_into`): the
    // pixel loop below ran empty over the rectangle, 2.4 M instructions a
    // 320×240 MuJoCo frame.
    if dx0 == dx1 || dy0 == dy1 || s[0] == s[2] || s[1] == s[3] || !(color || depth || stencil) {
        return;
    }
    let ax = Axis::new(dx0, dx1, sxa, sxb, from.width());
    let ay = Axis::new(dy0, dy1, sya, syb, from.height());
    let out = clip.intersect(to.bounds()).intersect(Rect {
        x0: dx0.max(0) as u32,
        y0: dy0.max(0) as u32,
        x1: dx1.max(0) as u32,
        y1: dy1.max(0) as u32,
    });
    if out.is_empty() {
        return;
    }
    // Depth and stencil of a blit that moves pixels one for one: rows
    // copied (MuJoCo's depth mode blits its 320×240 depth every frame,
    // ~60 instructions a pixel through `depth_at` and `Axis::nearest`).
    if !color {
        if let Some(u) = unscaled(from, to, s, d, clip) {
            copy_test_rows(from, to, u.moved, depth, stencil);
            return;
        }
    }
    // 8-bit channels only: their `pixel` and `pack` round-trip the bytes
    // (RGB565's expansion to 8 bits and back is not checked here).
    let bytewise = matches!(
        from.color_format(),
        ColorFormat::Rgba8 | ColorFormat::Bgra8 | ColorFormat::Rgb8
    );
    if color && filter == BlitFilter::Nearest && from.color_format() == to.color_format() && bytewise {
        if let Some(u) = unscaled(from, to, s, d, clip) {
            // Same bytes per pixel both sides: rows copied (a 640×480 resolve
            // blit was ~300 instructions a pixel through `pixel`/`pack`).
            let r = u.moved;
            if !r.is_empty() {
                let bytes = (r.x1 - r.x0) as usize * from.color_format().bytes_per_pixel();
                let mut t = to.target();
                for y in r.y0..r.y1 {
                    let src = &from.color_bytes()[from.color_offset(r.x0, y)..][..bytes];
                    let o = t.color_offset(r.x0, y);
                    t.color_mut()[o..o + bytes].copy_from_slice(src);
                }
            }
            if depth || stencil {
                blit(from, to, s, d, clip, (false, depth, stencil), filter);
            }
            return;
        }
    }
    // The source as RGBA8 texels, for LINEAR.
    let texels: Vec<u8> = if color && filter == BlitFilter::Linear {
        let (w, h) = (from.width(), from.height());
        (0..h)
            .flat_map(|y| (0..w).map(move |x| (x, y)))
            .flat_map(|(x, y)| from.pixel(x, y).unwrap_or([0; 4]))
            .collect()
    } else {
        Vec::new()
    };
    let image = Image {
        texels: &texels,
        units: None,
        width: from.width(),
        height: from.height(),
        depth: 1,
    };
    let level = Level {
        image: &image,
        format: TexelFormat::Rgba8,
        pot: [from.width().is_power_of_two(), from.height().is_power_of_two(), true],
    };
    let mut t = to.target();
    let cf = t.color_format();
    // A deep format on either side: colour goes through f32 (`deep_blit_colour`).
    let deep = color && (from.color_format().is_deep() || cf.is_deep());
    for y in out.y0..out.y1 {
        let ny = ay.nearest(y);
        for x in out.x0..out.x1 {
            let nx = ax.nearest(x);
            let (Some(nx), Some(ny)) = (nx, ny) else {
                continue;
            };
            let i = t.index(x, y);
            if deep {
                let c = match filter {
                    BlitFilter::Nearest => source_f32(from, nx, ny),
                    BlitFilter::Linear => linear_f32(from, [ax.at(x), ay.at(y)]),
                };
                let off = t.color_offset(x, y);
                store_f32(cf, &mut t.color_mut()[off..], c);
            } else if color {
                let rgba = match filter {
                    BlitFilter::Nearest => from.pixel(nx, ny).unwrap_or([0; 4]),
                    BlitFilter::Linear => {
                        let coord = [ax.at(x), ay.at(y), 0.0];
                        aos(&level, Filter::Linear, 2, coord, [Wrap::ClampToEdge; 3])
                    }
                };
                let off = t.color_offset(x, y);
                let v = pixel::pack(cf, rgba, None);
                pixel::store(cf, &mut t.color_mut()[off..], v);
            }
            if depth {
                if let Some(z) = from.depth_at(nx, ny) {
                    match t.depth_mut() {
                        Some(softgl_jit::DepthTarget::D16(dd)) => dd[i] = z as u16,
                        Some(
                            softgl_jit::DepthTarget::D24(dd)
                            | softgl_jit::DepthTarget::D32(dd)
                            | softgl_jit::DepthTarget::D32F(dd),
                        ) => dd[i] = z,
                        None => {}
                    }
                }
            }
            if stencil {
                if let (Some(v), Some(ss)) = (from.stencil_at(nx, ny), t.stencil_mut()) {
                    ss[i] = v;
                }
            }
        }
    }
}

/// Copies the depth (when `depth`) and stencil (when `stencil`) of `r`,
/// inside both framebuffers, from `from` to the same pixels of `to`: an
/// unscaled [`blit`]'s (the formats are the same: the caller checked).
fn copy_test_rows(from: &Framebuffer, to: &mut Framebuffer, r: Rect, depth: bool, stencil: bool) {
    use softgl_jit::DepthTarget;
    let r = r.intersect(from.bounds()).intersect(to.bounds());
    if r.is_empty() {
        return;
    }
    let n = (r.x1 - r.x0) as usize;
    let (fw, tw) = (from.width() as usize, to.width() as usize);
    let rows = |w: usize| (r.y0..r.y1).map(move |y| y as usize * w + r.x0 as usize);
    let mut t = to.target();
    if depth {
        match (from.depth_buffer(), t.depth_mut()) {
            (Some(DepthBuffer::D16(a)), Some(DepthTarget::D16(b))) => {
                for (i, o) in rows(fw).zip(rows(tw)) {
                    b[o..o + n].copy_from_slice(&a[i..i + n]);
                }
            }
            (Some(DepthBuffer::D24(a)), Some(DepthTarget::D24(b)))
            | (Some(DepthBuffer::D32(a)), Some(DepthTarget::D32(b)))
            | (Some(DepthBuffer::D32F(a)), Some(DepthTarget::D32F(b))) => {
                for (i, o) in rows(fw).zip(rows(tw)) {
                    b[o..o + n].copy_from_slice(&a[i..i + n]);
                }
            }
            _ => {}
        }
    }
    if stencil {
        if let (Some(a), Some(b)) = (from.stencil_buffer(), t.stencil_mut()) {
            for (i, o) in rows(fw).zip(rows(tw)) {
                b[o..o + n].copy_from_slice(&a[i..i + n]);
            }
        }
    }
}

/// The colour of source pixel `(x, y)` in f32 as llvmpipe's sampler reads
/// it (`lp_build_unsigned_norm_to_float`: unorm `v · f32(1/max)`; floats as
/// stored).
fn source_f32(from: &Framebuffer, x: u32, y: u32) -> [f32; 4] {
    if from.color_format().is_deep() {
        from.pixel_f32(x, y).unwrap_or([0.0; 4])
    } else {
        from.pixel(x, y).unwrap_or([0; 4]).map(|v| f32::from(v) * (1.0 / 255.0))
    }
}

/// The source's colour at normalized `coord`, bilinear with CLAMP_TO_EDGE
/// in f32 as llvmpipe's SoA sampler filters (`filter::soa`'s axis weights
/// and lerp order: along x within each row, then y).
fn linear_f32(from: &Framebuffer, coord: [f32; 2]) -> [f32; 4] {
    use softgl_jit::texture::arith::lerp;
    use softgl_jit::texture::filter::soa_linear_axis;
    use softgl_jit::texture::Wrap;
    let size = [from.width(), from.height()];
    let [(x0, x1, wx), (y0, y1, wy)] = std::array::from_fn(|a| {
        soa_linear_axis(coord[a], size[a] as i32, size[a].is_power_of_two(), Wrap::ClampToEdge)
    });
    let at = |x: i32, y: i32| source_f32(from, x.max(0) as u32, y.max(0) as u32);
    let (a, b, c, d) = (at(x0, y0), at(x1, y0), at(x0, y1), at(x1, y1));
    std::array::from_fn(|k| lerp(wy, lerp(wx, a[k], b[k]), lerp(wx, c[k], d[k])))
}

/// Stores float colour `c` as a fragment of format `cf` (unorm8 as
/// `shade::unorm8`, unorm16 as `deep::unorm16`, both clamped; floats
/// exactly) at the start of `px`.
fn store_f32(cf: ColorFormat, px: &mut [u8], c: [f32; 4]) {
    use softgl_jit::deep;
    if cf.is_deep() {
        for (k, v) in deep::from_float(cf, c).into_iter().enumerate() {
            deep::store_channel(cf, px, k, v);
        }
    } else {
        let v = pixel::pack(cf, c.map(softgl_jit::shade::unorm8), None);
        pixel::store(cf, px, v);
    }
}

/// Writes depth-test units back as the `Depth32F` texels llvmpipe's sampler
/// would read (`unpack::depth_sampled`), on two threads for big images
/// (4096²: a 64 MiB pass).
fn convert_back(d: &DepthBuffer, bits: u32, out: &mut [u8]) {
    // `depth_sampled` with its scale hoisted, for the loop to vectorize
    // (up to 24 bits: `z · f32(1/max)`, exactly as `depth_sampled`).
    let scale = (1.0 / ((1u64 << bits.min(24)) - 1) as f64) as f32;
    let run = |range: std::ops::Range<usize>, out: &mut [u8]| match d {
        DepthBuffer::D16(v) => {
            for (o, &z) in out.chunks_exact_mut(4).zip(&v[range]) {
                o.copy_from_slice(&(f32::from(z) * scale).to_ne_bytes());
            }
        }
        DepthBuffer::D24(v) => {
            // A 24-bit value converts exactly through i32, which x86's
            // packed conversion takes (`cvtdq2ps`: 4 a time; from u32 the
            // loop stayed scalar, ~2.9 instructions a texel, callgrind on
            // osmesa/bench/shadow_fbo.c). Depth-test units of a D24 buffer
            // are below 2^24 (`depth_to_unorm`, clears, blits).
            for (o, &z) in out.chunks_exact_mut(4).zip(&v[range]) {
                let z = (z & 0x7fff_ffff) as i32;
                o.copy_from_slice(&(z as f32 * scale).to_ne_bytes());
            }
        }
        DepthBuffer::D32(v) => {
            for (o, &z) in out.chunks_exact_mut(4).zip(&v[range]) {
                o.copy_from_slice(&depth_sampled(z, bits).to_ne_bytes());
            }
        }
        // Float depth: the texels are the stored floats.
        DepthBuffer::D32F(v) => {
            for (o, &z) in out.chunks_exact_mut(4).zip(&v[range]) {
                o.copy_from_slice(&z.to_ne_bytes());
            }
        }
    };
    let n = out.len() / 4;
    if n < 1 << 16 {
        return run(0..n, out);
    }
    let half = n / 2;
    let (a, b) = out.split_at_mut(4 * half);
    std::thread::scope(|s| {
        s.spawn(|| run(0..half, a));
        run(half..n, b);
    });
}

/// `n` pixels of colour format `c`, zero but for the alpha 1 of a deep
/// format without alpha (what its fourth channel always holds).
fn color_storage(c: ColorFormat, n: usize) -> GlResult<Vec<u8>> {
    let bpp = c.bytes_per_pixel();
    let mut v = alloc(n * bpp, 0u8)?;
    if c.is_deep() && !c.has_alpha() {
        let mut px = [0u8; 16];
        for (k, value) in softgl_jit::deep::from_float(c, [0.0, 0.0, 0.0, 1.0])
            .into_iter()
            .enumerate()
        {
            softgl_jit::deep::store_channel(c, &mut px, k, value);
        }
        for p in v.chunks_exact_mut(bpp) {
            p.copy_from_slice(&px[..bpp]);
        }
    }
    Ok(v)
}

fn depth_buffer(format: DepthFormat, n: usize) -> GlResult<DepthBuffer> {
    Ok(match format {
        DepthFormat::D16 => DepthBuffer::D16(alloc(n, u16::MAX)?),
        DepthFormat::D24 => DepthBuffer::D24(alloc(n, format.max_value())?),
        DepthFormat::D32 => DepthBuffer::D32(alloc(n, format.max_value())?),
        DepthFormat::D32F => DepthBuffer::D32F(alloc(n, format.max_value())?),
    })
}

/// A vector of `n` `value`s, or `OutOfMemory` instead of an abort.
fn alloc<T: Clone>(n: usize, value: T) -> GlResult<Vec<T>> {
    let mut v = Vec::new();
    v.try_reserve_exact(n).map_err(|_| GlError::OutOfMemory)?;
    v.resize(n, value);
    Ok(v)
}

#[cfg(test)]
mod tests {
    use super::convert_back;
    use crate::framebuffer::DepthBuffer;
    use crate::texture::ImageUnits;
    use std::sync::Arc;

    /// Units kept in a depth texture make the texels the write-back made
    /// (`glGetTexImage` and every other reader materialise them).
    #[test]
    fn units_materialise_as_the_write_back_converts() {
        let mut z: Vec<u32> = (0..1u32 << 24).step_by(4093).collect();
        z.extend([0, 1, 2, 0xff_fffe, 0xff_ffff, 0x7f_ffff, 0x80_0000, 0x80_0001]);
        // Float depth: any bits, NaNs and negatives included.
        let f: Vec<u32> = z
            .iter()
            .map(|&v| v.wrapping_mul(0x9e37_79b9))
            .chain([0x7fc0_0001, 0xff80_0000, 0x8000_0000, 0x3f80_0000])
            .collect();
        for (d, units) in [
            (DepthBuffer::D24(z.clone()), (z, true)),
            (DepthBuffer::D32F(f.clone()), (f, false)),
        ] {
            let n = units.0.len();
            let mut back = vec![0u8; 4 * n];
            convert_back(&d, d.format().bits(), &mut back);
            let u = ImageUnits {
                z: Arc::new(units.0),
                unorm24: units.1,
                written: false,
            };
            let mut made = vec![0u8; 4 * n];
            u.write_texels(&mut made);
            assert_eq!(made, back);
            // And what the samplers read of each unit.
            for (i, &v) in u.z.iter().enumerate() {
                let t = softgl_jit::texture::DepthUnits::texel(v, u.unorm24).to_bits();
                assert_eq!(t.to_ne_bytes(), back[4 * i..4 * i + 4]);
            }
        }
    }
}
