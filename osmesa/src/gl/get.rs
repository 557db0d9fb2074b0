//! `glGetString`, `glGet{Integer,Float,Double,Boolean}v`, `glIsEnabled`.

use super::enums::{self, Cap};
use crate::consts::*;
use crate::gl_state::{GlState, PixelStore, HINTS};
use crate::state::with_gl;
use softgl::{Backend, Context, GlEnum, GlError, GlResult, MatrixMode};
use std::ffi::c_char;

/// A queried value before conversion to the caller's type.
pub(super) enum Val {
    /// Integers and enumerants.
    I(Vec<i64>),
    /// Floats that convert to integers by rounding.
    F(Vec<f64>),
    /// Colours and depths in [0, 1]: to integers they map onto the full range.
    N(Vec<f64>),
    B(Vec<bool>),
}

impl Val {
    fn ints(&self) -> Vec<i32> {
        match self {
            Val::I(v) => v
                .iter()
                .map(|&x| x.clamp(i32::MIN.into(), i32::MAX.into()) as i32)
                .collect(),
            Val::F(v) => v
                .iter()
                .map(|&x| x.round().clamp(i32::MIN.into(), i32::MAX.into()) as i32)
                .collect(),
            Val::N(v) => v.iter().map(|&x| (x * f64::from(i32::MAX)).round() as i32).collect(),
            Val::B(v) => v.iter().map(|&b| i32::from(b)).collect(),
        }
    }

    fn doubles(&self) -> Vec<f64> {
        match self {
            Val::I(v) => v.iter().map(|&x| x as f64).collect(),
            Val::F(v) | Val::N(v) => v.clone(),
            Val::B(v) => v.iter().map(|&b| f64::from(u8::from(b))).collect(),
        }
    }

    fn bools(&self) -> Vec<bool> {
        match self {
            Val::I(v) => v.iter().map(|&x| x != 0).collect(),
            Val::F(v) | Val::N(v) => v.iter().map(|&x| x != 0.0).collect(),
            Val::B(v) => v.clone(),
        }
    }
}

fn i(v: impl Into<i64>) -> Val {
    Val::I(vec![v.into()])
}

fn e(v: GLenum) -> Val {
    Val::I(vec![i64::from(v)])
}

fn f(v: f32) -> Val {
    Val::F(vec![f64::from(v)])
}

fn matrix(gl: &Context, mode: MatrixMode) -> Val {
    Val::F(gl.matrix(mode).to_cols_array().iter().map(|&x| f64::from(x)).collect())
}

/// `glIsEnabled`.
pub(super) fn is_enabled(os: &GlState, gl: &Context, cap: GLenum) -> GlResult<bool> {
    if gl.inside_begin() {
        return Err(GlError::InvalidOperation);
    }
    Ok(match cap {
        GL_VERTEX_ARRAY => os.vertex.enabled,
        GL_COLOR_ARRAY => os.color.enabled,
        GL_NORMAL_ARRAY => os.normal.enabled,
        GL_TEXTURE_COORD_ARRAY => os.tex_coord().enabled,
        super::fog::GL_SECONDARY_COLOR_ARRAY => os.secondary.enabled,
        super::fog::GL_FOG_COORD_ARRAY => os.fog_coord.enabled,
        GL_INDEX_ARRAY => os.index.enabled,
        GL_EDGE_FLAG_ARRAY => os.edge_flag.enabled,
        _ => match enums::cap(cap)? {
            Cap::Core(c) => gl.is_enabled(c),
            Cap::Inert(c) => os.inert_caps.contains(&c),
            Cap::Missing => false,
        },
    })
}

fn store_value(s: &PixelStore, pname: GLenum, pack: bool) -> Option<Val> {
    let base = if pack { GL_PACK_SWAP_BYTES } else { GL_UNPACK_SWAP_BYTES };
    let (skip_images, image_height) = if pack {
        (GL_PACK_SKIP_IMAGES, GL_PACK_IMAGE_HEIGHT)
    } else {
        (GL_UNPACK_SKIP_IMAGES, GL_UNPACK_IMAGE_HEIGHT)
    };
    Some(match pname {
        p if p == base => Val::B(vec![s.swap_bytes]),
        p if p == base + 1 => Val::B(vec![s.lsb_first]),
        p if p == base + 2 => i(s.row_length),
        p if p == base + 3 => i(s.skip_rows),
        p if p == base + 4 => i(s.skip_pixels),
        p if p == base + 5 => i(s.alignment),
        p if p == skip_images => i(s.skip_images),
        p if p == image_height => i(s.image_height),
        _ => return None,
    })
}

/// The value of `pname`, or `GL_INVALID_ENUM`.
fn value(os: &GlState, gl: &Context, pname: GLenum) -> GlResult<Val> {
    if gl.inside_begin() {
        return Err(GlError::InvalidOperation);
    }
    let s = gl.state();
    let fb = gl.framebuffer_pending();
    let rect = |r: softgl::state::WindowRect| Val::I(vec![r.x.into(), r.y.into(), r.width.into(), r.height.into()]);
    let color_bits = |c: usize| -> i64 { fb.color_format().channel_bits(c).into() };
    if let Some(v) = store_value(&os.pack, pname, true).or_else(|| store_value(&os.unpack, pname, false)) {
        return Ok(v);
    }
    if let Some(h) = HINTS.iter().position(|&t| t == pname) {
        return Ok(e(os.hints[h]));
    }
    if let Some(v) = super::gl14::value(gl, pname) {
        return Ok(v);
    }
    if let Some(v) = super::buffers::value(os, gl, pname) {
        return Ok(v);
    }
    if let Some(v) = super::fog::value(os, gl, pname)
        .or_else(|| super::texture::value(os, gl, pname))
        .or_else(|| super::texunit::value(gl, pname))
        .or_else(|| super::raster_pos::value(gl, pname))
        .or_else(|| super::pixel_rect::value(gl, pname))
        .or_else(|| super::select::value(os, gl, pname))
    {
        return Ok(v);
    }
    let b = s.blend_func;
    let cm = s.color_mask;
    // Clamped as Mesa's get clamps it (the state keeps it unclamped).
    let clamped_clear = gl.clear_color_value();
    Ok(match pname {
        0x0BA2 => rect(s.viewport),                                              // VIEWPORT
        0x0C10 => rect(s.scissor),                                               // SCISSOR_BOX
        0x0B70 => Val::N(vec![s.depth_range.0, s.depth_range.1]),                // DEPTH_RANGE
        0x935C => i(s.clip_control.to_gl().0),                                   // CLIP_ORIGIN
        0x935D => i(s.clip_control.to_gl().1),                                   // CLIP_DEPTH_MODE
        0x0C22 => Val::N(clamped_clear.iter().map(|&c| f64::from(c)).collect()), // COLOR_CLEAR_VALUE
        0x0B73 => Val::N(vec![s.clear_depth]),                                   // DEPTH_CLEAR_VALUE
        0x0B91 => i(s.clear_stencil),                                            // STENCIL_CLEAR_VALUE
        0x0B00 => Val::N(gl.current().color.to_array().iter().map(|&c| f64::from(c)).collect()), // CURRENT_COLOR
        0x0B02 => Val::F(gl.current().normal.to_array().iter().map(|&c| f64::from(c)).collect()), // CURRENT_NORMAL
        0x0BA6 => matrix(gl, MatrixMode::Modelview),                             // MODELVIEW_MATRIX
        0x0BA7 => matrix(gl, MatrixMode::Projection),                            // PROJECTION_MATRIX
        0x0BA8 => matrix(gl, MatrixMode::Texture),                               // TEXTURE_MATRIX
        0x0BA0 => e(gl.current_matrix_mode().to_gl()),                           // MATRIX_MODE
        0x0BA3 => i(gl.matrix_depth(MatrixMode::Modelview) as i64),              // MODELVIEW_STACK_DEPTH
        0x0BA4 => i(gl.matrix_depth(MatrixMode::Projection) as i64),             // PROJECTION_STACK_DEPTH
        0x0BA5 => i(gl.matrix_depth(MatrixMode::Texture) as i64),                // TEXTURE_STACK_DEPTH
        0x0D36 => i(softgl::matrix::MAX_MODELVIEW_DEPTH as i64),
        0x0D38 => i(softgl::matrix::MAX_PROJECTION_DEPTH as i64),
        0x0D39 => i(softgl::matrix::MAX_TEXTURE_DEPTH as i64),
        0x0D3A => Val::I(vec![MAX_SIZE.into(), MAX_SIZE.into()]), // MAX_VIEWPORT_DIMS
        0x0B31 => i(super::lists::MAX_NESTING),                   // MAX_LIST_NESTING
        0x0B32 => i(os.list_base),                                // LIST_BASE
        0x0B33 => i(super::lists::compiling_state(os).0),         // LIST_INDEX
        0x0B30 => e(super::lists::compiling_state(os).1),         // LIST_MODE
        0x0D35 | 0x0D3B => i(super::attrib::MAX_DEPTH as i64),    // MAX_(CLIENT_)ATTRIB_STACK_DEPTH
        0x0BB0 => i(super::attrib::depths(os).0 as i64),          // ATTRIB_STACK_DEPTH
        0x0BB1 => i(super::attrib::depths(os).1 as i64),          // CLIENT_ATTRIB_STACK_DEPTH
        0x0D50 => i(8),                                           // SUBPIXEL_BITS
        0x0D52 => i(color_bits(0)),                               // RED_BITS
        0x0D53 => i(color_bits(1)),
        0x0D54 => i(color_bits(2)),
        0x0D55 => i(color_bits(3)),
        0x0D56 => i(fb.depth_format().map_or(0, |zbufformat| zbufformat.bits())), // DEPTH_BITS
        0x0D57 => i(if fb.has_stencil() { 8 } else { 0 }),                        // STENCIL_BITS
        0x0D58..=0x0D5B => i(if fb.has_accum() {
            i64::from(softgl::accum::ACCUM_BITS)
        } else {
            0
        }), // ACCUM_*_BITS
        0x0B80 => Val::N(s.clear_accum.iter().map(|&c| f64::from(c)).collect()),  // ACCUM_CLEAR_VALUE
        0x80A8 => i(u32::from(gl.samples() > 1)),                                 // SAMPLE_BUFFERS
        0x80A9 => i(if gl.samples() > 1 { gl.samples() } else { 0 }),             // SAMPLES
        0x8D57 => i(softgl::multisample::MAX_SAMPLES),                            // MAX_SAMPLES
        0x80AA => f(s.multisample.coverage_value),                                // SAMPLE_COVERAGE_VALUE
        0x80AB => Val::B(vec![s.multisample.coverage_invert]),                    // SAMPLE_COVERAGE_INVERT
        0x0C32 => Val::B(vec![false]),                                            // DOUBLEBUFFER
        0x0C33 => Val::B(vec![false]),                                            // STEREO
        0x0C31 => Val::B(vec![true]),                                             // RGBA_MODE
        0x0C01 => e(GL_FRONT),                                                    // DRAW_BUFFER
        0x0C02 => e(GL_FRONT),                                                    // READ_BUFFER
        0x0B54 => e(s.shade_model.to_gl()),                                       // SHADE_MODEL
        0x0B46 => e(s.front_face.to_gl()),                                        // FRONT_FACE
        0x0B45 => e(s.cull_face.to_gl()),                                         // CULL_FACE_MODE
        0x0B40 => Val::I(vec![
            s.polygon_mode_front.to_gl().into(),
            s.polygon_mode_back.to_gl().into(),
        ]),
        0x8038 => f(s.offset_factor),                   // POLYGON_OFFSET_FACTOR
        0x2A00 => f(s.offset_units),                    // POLYGON_OFFSET_UNITS
        0x0B11 => f(s.point_size),                      // POINT_SIZE
        0x0B21 => f(s.line_width),                      // LINE_WIDTH
        0x0B25 => i(i32::from(s.line_stipple_pattern)), // LINE_STIPPLE_PATTERN
        0x0B26 => i(s.line_stipple_factor),             // LINE_STIPPLE_REPEAT
        // ALIASED_POINT/LINE ranges and the GL 1.1 POINT_SIZE_RANGE/LINE_WIDTH_RANGE.
        0x846D | 0x846E | 0x0B12 | 0x0B22 => Val::F(vec![1.0, 255.0]),
        0x0B13 | 0x0B23 => f(0.1),                      // granularities
        0x0BC1 => e(s.alpha_func.to_gl()),              // ALPHA_TEST_FUNC
        0x0BC2 => Val::N(vec![f64::from(s.alpha_ref)]), // ALPHA_TEST_REF
        0x0B92 => e(s.stencil_func.to_gl()),            // STENCIL_FUNC
        0x0B97 => i(s.stencil_ref),                     // STENCIL_REF
        0x0B93 => i(s.stencil_value_mask & 0xff),       // STENCIL_VALUE_MASK
        0x0B98 => i(s.stencil_write_mask & 0xff),       // STENCIL_WRITEMASK
        0x0B94 => e(s.stencil_fail.to_gl()),
        0x0B95 => e(s.stencil_zfail.to_gl()),
        0x0B96 => e(s.stencil_zpass.to_gl()),
        0x0B74 => e(s.depth_func.to_gl()),       // DEPTH_FUNC
        0x0B72 => Val::B(vec![s.depth_write]),   // DEPTH_WRITEMASK
        0x0BE1 | 0x80C9 => e(b.src_rgb.to_gl()), // BLEND_SRC, _SRC_RGB
        0x0BE0 | 0x80C8 => e(b.dst_rgb.to_gl()), // BLEND_DST, _DST_RGB
        0x80CB => e(b.src_alpha.to_gl()),
        0x80CA => e(b.dst_alpha.to_gl()),
        0x8009 => e(b.eq_rgb.to_gl()), // BLEND_EQUATION(_RGB)
        0x883D => e(b.eq_alpha.to_gl()),
        0x8005 => Val::N(s.blend_color.iter().map(|&c| f64::from(c)).collect()), // BLEND_COLOR
        0x0BF0 => e(s.logic_op.to_gl()),                                         // LOGIC_OP_MODE
        0x0C23 => Val::B(vec![cm.r, cm.g, cm.b, cm.a]),                          // COLOR_WRITEMASK
        0x0D30 => i(softgl::eval::MAX_EVAL_ORDER as i64),                        // MAX_EVAL_ORDER
        0x0D31 => i(softgl::lighting::MAX_LIGHTS as i64),                        // MAX_LIGHTS
        0x0D32 => i(softgl::lighting::MAX_CLIP_PLANES as i64),                   // MAX_CLIP_PLANES
        0x0B53 => Val::N(s.lighting.model_ambient.iter().map(|&c| f64::from(c)).collect()), // LIGHT_MODEL_AMBIENT
        0x0B51 => Val::B(vec![s.lighting.local_viewer]),                         // LIGHT_MODEL_LOCAL_VIEWER
        0x0B52 => Val::B(vec![s.lighting.two_side]),                             // LIGHT_MODEL_TWO_SIDE
        0x81F8 => e(s.lighting.color_control.to_gl()),                           // LIGHT_MODEL_COLOR_CONTROL
        0x0B55 => e(s.lighting.color_material_face.to_gl()),                     // COLOR_MATERIAL_FACE
        0x0B56 => e(s.lighting.color_material_mode.to_gl()),                     // COLOR_MATERIAL_PARAMETER
        GL_VERTEX_ARRAY => Val::B(vec![os.vertex.enabled]),
        GL_COLOR_ARRAY => Val::B(vec![os.color.enabled]),
        GL_NORMAL_ARRAY => Val::B(vec![os.normal.enabled]),
        0x807A => i(os.vertex.size), // VERTEX_ARRAY_SIZE
        0x807B => e(os.vertex.ty),
        0x807C => i(os.vertex.stride),
        0x8081 => i(os.color.size), // COLOR_ARRAY_SIZE
        0x8082 => e(os.color.ty),
        0x8083 => i(os.color.stride),
        0x807E => e(os.normal.ty), // NORMAL_ARRAY_TYPE
        0x807F => i(os.normal.stride),
        GL_EDGE_FLAG_ARRAY => Val::B(vec![os.edge_flag.enabled]),
        0x808C => i(os.edge_flag.stride), // EDGE_FLAG_ARRAY_STRIDE
        GL_INDEX_ARRAY => Val::B(vec![os.index.enabled]),
        0x8085 => e(os.index.ty),                       // INDEX_ARRAY_TYPE
        0x8086 => i(os.index.stride),                   // INDEX_ARRAY_STRIDE
        0x0C20 => f(os.clear_index),                    // INDEX_CLEAR_VALUE
        0x0C21 => i(i64::from(os.index_mask as i32)),   // INDEX_WRITEMASK
        0x0B01 => f(gl.current().index),                // CURRENT_INDEX
        0x0B43 => Val::B(vec![gl.current().edge_flag]), // EDGE_FLAG
        0x0DD0..=0x0DD3 => eval_grid(&os.eval.grid, pname),
        _ => match enums::cap(pname)? {
            Cap::Core(c) => Val::B(vec![gl.is_enabled(c)]),
            Cap::Inert(c) => Val::B(vec![os.inert_caps.contains(&c)]),
            Cap::Missing => Val::B(vec![false]),
        },
    })
}

/// Writes `vals` through `out`, which GL says has room for them all.
///
/// # Safety
/// `out` is null or has room for `vals.len()` values.
unsafe fn write<T: Copy>(out: *mut T, vals: &[T]) {
    if out.is_null() {
        return;
    }
    // SAFETY: room for every value of `pname`, by GL's contract.
    unsafe { std::ptr::copy_nonoverlapping(vals.as_ptr(), out, vals.len()) };
}

/// Runs a `glGet*v`: converts the value of `pname` with `conv` and writes it.
fn get<T: Copy>(pname: GLenum, out: *mut T, conv: impl FnOnce(&Val) -> Vec<T>) {
    let fbo = |gl: &mut Context| match gl.inside_begin() {
        true => None,
        false => super::fbo::value(gl, pname),
    };
    with_gl((), |os, gl| match fbo(gl).map_or_else(|| value(os, gl, pname), Ok) {
        // SAFETY: `out` has room for the value of `pname` (GL's contract).
        Ok(v) => unsafe { write(out, &conv(&v)) },
        Err(err) => gl.record_error(err),
    })
}

const VENDOR: &std::ffi::CStr = c"softgl";
const RENDERER_INTERP: &std::ffi::CStr = c"softgl (interpreter)";
const RENDERER_JIT: &std::ffi::CStr = c"softgl (Cranelift JIT)";
pub(crate) use super::extensions::VERSION;

exports! {
    /// `GL_VENDOR`, `GL_RENDERER`, `GL_VERSION` ("1.5 softgl …") and
    /// `GL_EXTENSIONS`; `NULL` and `GL_INVALID_ENUM` for other names.
    [] fn glGetString(name: GLenum) -> *const u8 {
        with_gl(std::ptr::null(), |_, gl| {
            let s = match name {
                GL_VENDOR => VENDOR,
                GL_RENDERER if gl.backend() == Backend::Jit => RENDERER_JIT,
                GL_RENDERER => RENDERER_INTERP,
                GL_VERSION => VERSION,
                GL_EXTENSIONS => super::extensions::extensions_string(),
                _ => {
                    gl.record_error(GlError::InvalidEnum);
                    return std::ptr::null();
                }
            };
            if gl.inside_begin() {
                gl.record_error(GlError::InvalidOperation);
                return std::ptr::null();
            }
            s.as_ptr().cast::<c_char>().cast()
        })
    }
    /// # Safety
    /// `out` is null or has room for the value of `pname`.
    [unsafe] fn glGetIntegerv(pname: GLenum, out: *mut i32) {
        get(pname, out, Val::ints)
    }
    /// # Safety
    /// `out` is null or has room for the value of `pname`.
    [unsafe] fn glGetFloatv(pname: GLenum, out: *mut f32) {
        get(pname, out, |v| v.doubles().iter().map(|&x| x as f32).collect())
    }
    /// # Safety
    /// `out` is null or has room for the value of `pname`.
    [unsafe] fn glGetDoublev(pname: GLenum, out: *mut f64) {
        get(pname, out, Val::doubles)
    }
    /// # Safety
    /// `out` is null or has room for the value of `pname`.
    [unsafe] fn glGetBooleanv(pname: GLenum, out: *mut u8) {
        get(pname, out, |v| v.bools().iter().map(|&b| u8::from(b)).collect())
    }
}

/// `GL_MAP1_GRID_DOMAIN`, `_SEGMENTS`, `GL_MAP2_GRID_DOMAIN`, `_SEGMENTS`.
fn eval_grid(g: &softgl::eval::Grid, pname: GLenum) -> Val {
    let fs = |v: &[f32]| Val::F(v.iter().map(|&x| f64::from(x)).collect());
    match pname {
        0x0DD0 => fs(&[g.u1_1, g.u1_2]),
        0x0DD1 => i(g.un1),
        0x0DD2 => fs(&[g.u2_1, g.u2_2, g.v2_1, g.v2_2]),
        _ => Val::I(vec![g.un2.into(), g.vn2.into()]),
    }
}
