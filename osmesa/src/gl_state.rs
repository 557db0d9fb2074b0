//! The GL state this library keeps beside [`softgl::Context`]: client
//! arrays, pixel store, hints, capabilities without effect yet, the attribute
//! stacks and the display lists. The GL entry points (`gl/*`) work on it; the
//! OSMesa context ([`crate::state::OsContext`]) owns one and hands it to them
//! with the GL context. It imports neither: `gl/*` → `state` → `gl_state`.

use crate::consts::*;
use softgl::context::ImmediateRun;
use softgl::state::RasterState;
use softgl::texture::unit::TexUnit;
use softgl::texture::{TexParam, TextureTarget};
use softgl::{Context, CurrentAttribs, MatrixMode};
use std::collections::HashMap;
use std::sync::Arc;

/// A client vertex array (`glVertexPointer` and friends).
#[derive(Clone, Copy, Debug)]
pub struct ClientArray {
    pub enabled: bool,
    pub size: i32,
    pub ty: GLenum,
    pub stride: i32,
    /// A client pointer, or an offset into `buffer` when that is not 0.
    pub ptr: *const u8,
    /// The `GL_ARRAY_BUFFER` bound when the pointer was set (GL 1.5).
    pub buffer: u32,
}

impl ClientArray {
    pub const fn new(size: i32) -> ClientArray {
        ClientArray {
            enabled: false,
            size,
            ty: GL_FLOAT,
            stride: 0,
            ptr: std::ptr::null(),
            buffer: 0,
        }
    }
}

// SAFETY: the pointer is the caller's, read only while drawing on the thread
// where the context is current, under GL's contract for client arrays.
unsafe impl Send for ClientArray {}

/// `glPixelStore` state for one direction (pack or unpack): softgl's.
pub use softgl::texture::PixelStore;

/// `glHint` targets, in the order of [`GlState::hints`].
pub const HINTS: [GLenum; 7] = [
    GL_PERSPECTIVE_CORRECTION_HINT,
    GL_POINT_SMOOTH_HINT,
    GL_LINE_SMOOTH_HINT,
    GL_POLYGON_SMOOTH_HINT,
    GL_FOG_HINT,
    GL_TEXTURE_COMPRESSION_HINT,
    GL_GENERATE_MIPMAP_HINT,
];

/// Texture units, each with its texture coordinate array.
pub const MAX_UNITS: usize = 8;

/// A command of a display list: a GL call with its arguments.
pub type Cmd = Arc<dyn Fn(&mut GlState, &mut Context) + Send + Sync>;

/// The list `glNewList` opened.
pub struct Compiling {
    pub name: u32,
    pub execute: bool,
    pub cmds: Vec<Cmd>,
    /// The `glBegin` … `glEnd` being compiled into arrays, while only
    /// vertex attribute calls come (`gl::lists`).
    pub run: Option<ImmediateRun>,
}

/// The state one `glPushAttrib` saved.
#[derive(Clone)]
pub struct SavedAttrib {
    pub mask: u32,
    pub state: RasterState,
    pub current: CurrentAttribs,
    /// The raster position (`GL_CURRENT_BIT`).
    pub raster: softgl::raster_pos::RasterPos,
    /// Pixel zoom, transfer and maps (`GL_PIXEL_MODE_BIT`), saved only with that bit.
    pub pixel: Option<softgl::pixel_transfer::PixelState>,
    pub matrix_mode: MatrixMode,
    pub hints: [GLenum; 7],
    pub inert_caps: Vec<GLenum>,
    /// For `GL_EVAL_BIT`: the grids.
    pub eval_grid: softgl::eval::Grid,
    /// For `GL_TEXTURE_BIT` and `GL_ENABLE_BIT`.
    pub textures: Option<SavedTextures>,
    /// `glClearIndex` and `glIndexMask`, for `GL_COLOR_BUFFER_BIT`.
    pub index: (f32, u32),
    /// `GL_DRAW_BUFFER` (`GL_COLOR_BUFFER_BIT`) and `GL_READ_BUFFER` (`GL_PIXEL_MODE_BIT`).
    pub buffers: (GLenum, GLenum),
}

/// How many texture targets a unit binds (1D, 2D, 3D, cube map, rectangle).
pub const TEXTURE_TARGETS: usize = 5;

/// The texture state `glPushAttrib` saved: every unit (enables,
/// environment, coordinate generation), its bindings, the active unit and,
/// for `GL_TEXTURE_BIT`, the parameters of every bound texture object.
#[derive(Clone)]
pub struct SavedTextures {
    pub active: usize,
    pub units: [TexUnit; MAX_UNITS],
    /// Per unit, the name bound to each target of `gl::texture::TARGETS`.
    pub bindings: [[u32; TEXTURE_TARGETS]; MAX_UNITS],
    /// The bound objects (each once) with their parameters.
    pub objects: Vec<(TextureTarget, u32, Vec<TexParam>)>,
}

/// The client arrays and the client active texture unit, as
/// `GL_CLIENT_VERTEX_ARRAY_BIT` saves them.
#[derive(Clone, Copy)]
pub struct ClientArrays {
    pub vertex: ClientArray,
    pub color: ClientArray,
    pub normal: ClientArray,
    pub tex_coords: [ClientArray; MAX_UNITS],
    pub secondary: ClientArray,
    pub fog_coord: ClientArray,
    pub edge_flag: ClientArray,
    pub index: ClientArray,
    pub client_active: usize,
    /// The `GL_ARRAY_BUFFER` and `GL_ELEMENT_ARRAY_BUFFER` bindings (the
    /// GL context holds them: `gl::attrib` fills them in).
    pub buffers: (u32, u32),
}

/// The state one `glPushClientAttrib` saved.
#[derive(Clone)]
pub struct SavedClient {
    pub mask: u32,
    pub pack: PixelStore,
    pub unpack: PixelStore,
    pub arrays: ClientArrays,
}

/// The GL state of one context that `softgl::Context` does not hold.
pub struct GlState {
    pub vertex: ClientArray,
    pub color: ClientArray,
    pub normal: ClientArray,
    /// Each unit's `glTexCoordPointer`.
    pub tex_coords: [ClientArray; MAX_UNITS],
    /// `glClientActiveTexture`: the unit `glTexCoordPointer` and the
    /// `GL_TEXTURE_COORD_ARRAY` enable name.
    pub client_active: usize,
    pub secondary: ClientArray,
    pub fog_coord: ClientArray,
    /// `glEdgeFlagPointer`: `GLboolean`s.
    pub edge_flag: ClientArray,
    /// `glIndexPointer`: colour indices, kept and queried (RGBA contexts
    /// draw without them, as GL says).
    pub index: ClientArray,
    /// `glClearIndex` and `glIndexMask` (state only in RGBA).
    pub clear_index: f32,
    pub index_mask: u32,
    pub pack: PixelStore,
    pub unpack: PixelStore,
    /// `glHint` modes, in the order of [`HINTS`].
    pub hints: [GLenum; 7],
    /// Capabilities accepted but without effect until lighting lands
    /// (`GL_NORMALIZE`, `GL_RESCALE_NORMAL`, `GL_COLOR_MATERIAL`, `GL_AUTO_NORMAL`).
    pub inert_caps: Vec<GLenum>,
    /// The evaluators' maps and grids (`glMap`, `glMapGrid`); their enables
    /// are among `inert_caps`.
    pub eval: softgl::eval::Evaluators,
    /// `glPushAttrib` and `glPushClientAttrib` stacks.
    pub attrib_stack: Vec<SavedAttrib>,
    pub client_attrib_stack: Vec<SavedClient>,
    /// Display lists by name, the one being compiled, `glListBase`, and how
    /// deep `glCallList` is nested.
    pub lists: HashMap<u32, Arc<Vec<Cmd>>>,
    pub compiling: Option<Compiling>,
    pub list_base: u32,
    pub call_depth: u32,
    /// `glSelectBuffer`'s and `glFeedbackBuffer`'s buffers.
    pub mode_buffers: crate::gl::select::ModeBuffers,
}

impl Default for GlState {
    fn default() -> GlState {
        GlState {
            vertex: ClientArray::new(4),
            color: ClientArray::new(4),
            normal: ClientArray::new(3),
            tex_coords: [ClientArray::new(4); MAX_UNITS],
            client_active: 0,
            secondary: ClientArray::new(3),
            fog_coord: ClientArray::new(1),
            edge_flag: ClientArray {
                ty: GL_UNSIGNED_BYTE,
                ..ClientArray::new(1)
            },
            index: ClientArray::new(1),
            clear_index: 0.0,
            index_mask: u32::MAX,
            pack: PixelStore::DEFAULT,
            unpack: PixelStore::DEFAULT,
            hints: [GL_DONT_CARE; 7],
            inert_caps: Vec::new(),
            eval: Default::default(),
            attrib_stack: Vec::new(),
            client_attrib_stack: Vec::new(),
            lists: HashMap::new(),
            compiling: None,
            list_base: 0,
            call_depth: 0,
            mode_buffers: Default::default(),
        }
    }
}

impl GlState {
    /// The client arrays, as `glPushClientAttrib` saves them.
    pub fn arrays(&self) -> ClientArrays {
        ClientArrays {
            vertex: self.vertex,
            color: self.color,
            normal: self.normal,
            tex_coords: self.tex_coords,
            secondary: self.secondary,
            fog_coord: self.fog_coord,
            edge_flag: self.edge_flag,
            index: self.index,
            client_active: self.client_active,
            buffers: (0, 0),
        }
    }

    /// Puts back what [`GlState::arrays`] saved.
    pub fn set_arrays(&mut self, a: ClientArrays) {
        (self.vertex, self.color, self.normal) = (a.vertex, a.color, a.normal);
        (self.tex_coords, self.client_active) = (a.tex_coords, a.client_active);
        (self.secondary, self.fog_coord, self.edge_flag) = (a.secondary, a.fog_coord, a.edge_flag);
        self.index = a.index;
    }

    /// The client active unit's texture coordinate array.
    pub fn tex_coord(&self) -> &ClientArray {
        &self.tex_coords[self.client_active]
    }

    /// Every client array, to visit (`glDeleteBuffers` unbinds them).
    pub fn all_arrays_mut(&mut self) -> impl Iterator<Item = &mut ClientArray> {
        [&mut self.vertex, &mut self.color, &mut self.normal]
            .into_iter()
            .chain(self.tex_coords.iter_mut())
            .chain([
                &mut self.secondary,
                &mut self.fog_coord,
                &mut self.edge_flag,
                &mut self.index,
            ])
    }

    /// The client array `glEnableClientState` names, if softgl has it.
    pub fn array_mut(&mut self, array: GLenum) -> Option<&mut ClientArray> {
        Some(match array {
            GL_VERTEX_ARRAY => &mut self.vertex,
            GL_COLOR_ARRAY => &mut self.color,
            GL_NORMAL_ARRAY => &mut self.normal,
            GL_TEXTURE_COORD_ARRAY => &mut self.tex_coords[self.client_active],
            GL_EDGE_FLAG_ARRAY => &mut self.edge_flag,
            GL_INDEX_ARRAY => &mut self.index,
            0x845E => &mut self.secondary, // GL_SECONDARY_COLOR_ARRAY
            0x8457 => &mut self.fog_coord, // GL_FOG_COORD_ARRAY
            _ => return None,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn as_many_units_as_softgl() {
        let gl = Context::new(softgl::FramebufferDesc::rgba8_d24s8(1, 1)).unwrap();
        assert_eq!(gl.tex_units().units.len(), MAX_UNITS);
    }
}
