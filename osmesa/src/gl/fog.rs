//! Fog, secondary colour and fog coordinates: `glFog*`, `glFogCoord*`,
//! `glSecondaryColor3*`, their arrays, and their `glGet` values.

use super::arrays::{pointer, COLOR_TYPES};
use super::enums::decode;
use super::get::Val;
use super::immediate::{read, Norm};
use super::{attr, checked};
use crate::consts::*;
use crate::gl_state::GlState;
use softgl::fog::FogState;
use softgl::{Context, FogCoordSrc, FogMode, FogParam, GlEnum, GlError, GlResult};
use std::ffi::c_void;

const GL_FOG_INDEX: GLenum = 0x0B61;
const GL_FOG_DENSITY: GLenum = 0x0B62;
const GL_FOG_START: GLenum = 0x0B63;
const GL_FOG_END: GLenum = 0x0B64;
const GL_FOG_MODE: GLenum = 0x0B65;
const GL_FOG_COLOR: GLenum = 0x0B66;
const GL_FOG_COORD_SRC: GLenum = 0x8450;
const GL_CURRENT_FOG_COORD: GLenum = 0x8453;
const GL_FOG_COORD_ARRAY_TYPE: GLenum = 0x8454;
const GL_FOG_COORD_ARRAY_STRIDE: GLenum = 0x8455;
pub const GL_FOG_COORD_ARRAY: GLenum = 0x8457;
const GL_CURRENT_SECONDARY_COLOR: GLenum = 0x8459;
const GL_SECONDARY_COLOR_ARRAY_SIZE: GLenum = 0x845A;
const GL_SECONDARY_COLOR_ARRAY_TYPE: GLenum = 0x845B;
const GL_SECONDARY_COLOR_ARRAY_STRIDE: GLenum = 0x845C;
pub const GL_SECONDARY_COLOR_ARRAY: GLenum = 0x845E;

/// A `glFog` parameter from `pname` and its values; `ints` says the values
/// came from `glFogi(v)` (colours then map signed integers onto [-1, 1]).
fn param(pname: GLenum, v: &[f64], ints: bool) -> GlResult<FogParam> {
    let x = v[0];
    Ok(match pname {
        GL_FOG_MODE => FogParam::Mode(decode::<FogMode>(x as i64 as GLenum)?),
        GL_FOG_DENSITY => FogParam::Density(x as f32),
        GL_FOG_START => FogParam::Start(x as f32),
        GL_FOG_END => FogParam::End(x as f32),
        GL_FOG_INDEX => FogParam::Index(x as f32),
        GL_FOG_COORD_SRC => FogParam::CoordSrc(decode::<FogCoordSrc>(x as i64 as GLenum)?),
        GL_FOG_COLOR => FogParam::Color(std::array::from_fn(|k| {
            if ints {
                (v[k] as i32).norm()
            } else {
                v[k] as f32
            }
        })),
        _ => return Err(GlError::InvalidEnum),
    })
}

/// How many values `glFog*v` reads for `pname` (0 for an unknown name).
fn count(pname: GLenum) -> usize {
    match pname {
        GL_FOG_COLOR => 4,
        GL_FOG_MODE | GL_FOG_DENSITY | GL_FOG_START | GL_FOG_END | GL_FOG_INDEX | GL_FOG_COORD_SRC => 1,
        _ => 0,
    }
}

/// Records `glFog` with values `v` (at least one; four for the colour).
fn fog(pname: GLenum, v: [f64; 4], ints: bool) {
    checked(move |gl| {
        if count(pname) == 0 {
            return Err(GlError::InvalidEnum);
        }
        gl.fog(param(pname, &v, ints)?)
    })
}

/// Reads `glFog*v`'s values through `p` (as many as `pname` takes).
///
/// # Safety
/// `p` is null or holds the values `pname` takes.
unsafe fn fog_v<T: Copy + Into<f64>>(pname: GLenum, p: *const T, ints: bool) {
    let mut v = [0.0; 4];
    if p.is_null() {
        return;
    }
    for (k, out) in v.iter_mut().enumerate().take(count(pname).max(1)) {
        // SAFETY: `pname`'s values are readable (GL's contract).
        *out = unsafe { p.add(k).read_unaligned() }.into();
    }
    fog(pname, v, ints)
}

/// Restores the `GL_FOG_BIT` group from `s`.
pub(super) fn restore(gl: &mut Context, s: &FogState) -> GlResult {
    for p in [
        FogParam::Mode(s.mode),
        FogParam::Density(s.density),
        FogParam::Start(s.start),
        FogParam::End(s.end),
        FogParam::Color(s.color),
        FogParam::Index(s.index),
        FogParam::CoordSrc(s.coord_src),
    ] {
        gl.fog(p)?;
    }
    Ok(())
}

/// The `glGet` value of fog and the GL 1.4 attributes, if `pname` is one.
pub(super) fn value(os: &GlState, gl: &Context, pname: GLenum) -> Option<Val> {
    let s = gl.fog_state();
    let fl = |v: f32| Val::F(vec![f64::from(v)]);
    Some(match pname {
        GL_FOG_MODE => Val::I(vec![s.mode.to_gl().into()]),
        GL_FOG_DENSITY => fl(s.density),
        GL_FOG_START => fl(s.start),
        GL_FOG_END => fl(s.end),
        GL_FOG_INDEX => fl(s.index),
        GL_FOG_COLOR => Val::N(s.color.iter().map(|&c| f64::from(c)).collect()),
        GL_FOG_COORD_SRC => Val::I(vec![s.coord_src.to_gl().into()]),
        GL_CURRENT_FOG_COORD => fl(gl.current().fog_coord),
        GL_CURRENT_SECONDARY_COLOR => Val::N(
            gl.current()
                .secondary
                .to_array()
                .iter()
                .map(|&c| f64::from(c))
                .collect(),
        ),
        GL_FOG_COORD_ARRAY => Val::B(vec![os.fog_coord.enabled]),
        GL_FOG_COORD_ARRAY_TYPE => Val::I(vec![os.fog_coord.ty.into()]),
        GL_FOG_COORD_ARRAY_STRIDE => Val::I(vec![os.fog_coord.stride.into()]),
        GL_SECONDARY_COLOR_ARRAY => Val::B(vec![os.secondary.enabled]),
        GL_SECONDARY_COLOR_ARRAY_SIZE => Val::I(vec![os.secondary.size.into()]),
        GL_SECONDARY_COLOR_ARRAY_TYPE => Val::I(vec![os.secondary.ty.into()]),
        GL_SECONDARY_COLOR_ARRAY_STRIDE => Val::I(vec![os.secondary.stride.into()]),
        _ => return None,
    })
}

#[inline]
fn secondary(r: f32, g: f32, b: f32) {
    attr(move |gl| gl.secondary_color3(r, g, b))
}

#[inline]
fn fog_coord(c: f32) {
    attr(move |gl| gl.fog_coord(c))
}

/// `glSecondaryColor3{t}` and `glSecondaryColor3{t}v` for each component type.
macro_rules! secondary_colors {
    ($($f:ident $fv:ident $t:ty;)*) => {
        exports! {
            $(
                [] fn $f(r: $t, g: $t, b: $t) {
                    secondary(r.norm(), g.norm(), b.norm())
                }
                /// # Safety
                /// `v` is null or points to 3 values.
                [unsafe] fn $fv(v: *const $t) {
                    // SAFETY: 3 readable values by GL's contract; null is ignored.
                    if let Some(v) = unsafe { read::<$t, 3>(v) } {
                        secondary(v[0].norm(), v[1].norm(), v[2].norm())
                    }
                }
            )*
        }
    };
}

mod colors {
    use super::*;
    secondary_colors! {
        glSecondaryColor3b glSecondaryColor3bv i8;
        glSecondaryColor3s glSecondaryColor3sv i16;
        glSecondaryColor3i glSecondaryColor3iv i32;
        glSecondaryColor3f glSecondaryColor3fv f32;
        glSecondaryColor3d glSecondaryColor3dv f64;
        glSecondaryColor3ub glSecondaryColor3ubv u8;
        glSecondaryColor3us glSecondaryColor3usv u16;
        glSecondaryColor3ui glSecondaryColor3uiv u32;
    }
}
pub use colors::*;

/// The secondary colour exports' table.
pub(super) fn color_table() -> Vec<(&'static str, *const c_void)> {
    colors::table()
}

exports! {
    [] fn glFogf(pname: GLenum, param: f32) {
        fog(pname, [f64::from(param), 0.0, 0.0, 0.0], false)
    }
    [] fn glFogi(pname: GLenum, param: i32) {
        fog(pname, [f64::from(param), 0.0, 0.0, 0.0], true)
    }
    /// # Safety
    /// `params` is null or holds the values `pname` takes.
    [unsafe] fn glFogfv(pname: GLenum, params: *const f32) {
        // SAFETY: by GL's contract, forwarded.
        unsafe { fog_v(pname, params, false) }
    }
    /// # Safety
    /// `params` is null or holds the values `pname` takes.
    [unsafe] fn glFogiv(pname: GLenum, params: *const i32) {
        // SAFETY: by GL's contract, forwarded.
        unsafe { fog_v(pname, params, true) }
    }
    [] fn glFogCoordf(c: f32) {
        fog_coord(c)
    }
    [] fn glFogCoordd(c: f64) {
        fog_coord(c as f32)
    }
    /// # Safety
    /// `c` is null or points to a value.
    [unsafe] fn glFogCoordfv(c: *const f32) {
        // SAFETY: 1 readable value by GL's contract; null is ignored.
        if let Some([c]) = unsafe { read::<f32, 1>(c) } {
            fog_coord(c)
        }
    }
    /// # Safety
    /// `c` is null or points to a value.
    [unsafe] fn glFogCoorddv(c: *const f64) {
        // SAFETY: 1 readable value by GL's contract; null is ignored.
        if let Some([c]) = unsafe { read::<f64, 1>(c) } {
            fog_coord(c as f32)
        }
    }
    /// # Safety
    /// `ptr` stays valid while drawing reads it (GL's contract).
    [unsafe] fn glFogCoordPointer(ty: GLenum, stride: i32, ptr: *const c_void) {
        pointer(|o| &mut o.fog_coord, &[1], 1, ty, &[GL_FLOAT, GL_DOUBLE], stride, ptr)
    }
    /// # Safety
    /// `ptr` stays valid while drawing reads it (GL's contract).
    [unsafe] fn glSecondaryColorPointer(size: i32, ty: GLenum, stride: i32, ptr: *const c_void) {
        pointer(|o| &mut o.secondary, &[3], size, ty, &COLOR_TYPES, stride, ptr)
    }
}
