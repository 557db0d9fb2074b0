//! Texture units: the environment (`glTexEnv*`, COMBINE and the
//! `GL_TEXTUREn` crossbar), coordinate generation (`glTexGen*`), the active
//! and client active units and the multitexture coordinates
//! (`glMultiTexCoord*`), with their `glGet` values.

use super::enums::decode;
use super::get::Val;
use super::immediate::read;
use super::texture::{color, floats, ints, with_values, write, Value};
use super::{attr, checked, now, outside};
use crate::consts::*;
use crate::gl_state::MAX_UNITS;
use softgl::texture::unit::{TexCoordName, TexEnvParam, TexEnvParamName, TexGenParam, TexGenParamName};
use softgl::texture::{CombineFn, CombineSrc, EnvMode, Operand};
use softgl::{Context, GlEnum, GlError, GlResult};
use std::ffi::c_void;

const GL_TEXTURE_ENV_MODE: GLenum = 0x2200;
const GL_TEXTURE_ENV_COLOR: GLenum = 0x2201;
const GL_COMBINE_RGB: GLenum = 0x8571;
const GL_COMBINE_ALPHA: GLenum = 0x8572;
const GL_RGB_SCALE: GLenum = 0x8573;
const GL_ALPHA_SCALE: GLenum = 0x0D1C;
const GL_SOURCE0_RGB: GLenum = 0x8580;
const GL_SOURCE0_ALPHA: GLenum = 0x8588;
const GL_OPERAND0_RGB: GLenum = 0x8590;
const GL_OPERAND0_ALPHA: GLenum = 0x8598;
const GL_TEXTURE_LOD_BIAS: GLenum = 0x8501;
const GL_TEXTURE_GEN_MODE: GLenum = 0x2500;
const GL_OBJECT_PLANE: GLenum = 0x2501;
const GL_EYE_PLANE: GLenum = 0x2502;

/// The unit `GL_TEXTUREi` names (its range is checked by softgl).
fn unit(texture: GLenum) -> u32 {
    texture.wrapping_sub(GL_TEXTURE0)
}

// ----- the texture environment -----

/// A combine function; the alpha one has no `DOT3`.
fn combine_fn(v: GLenum, alpha: bool) -> GlResult<CombineFn> {
    match decode(v)? {
        CombineFn::Dot3Rgb | CombineFn::Dot3Rgba if alpha => Err(GlError::InvalidEnum),
        f => Ok(f),
    }
}

/// An operand; the alpha ones take alpha only.
fn operand(v: GLenum, alpha: bool) -> GlResult<Operand> {
    match decode(v)? {
        Operand::SrcColor | Operand::OneMinusSrcColor if alpha => Err(GlError::InvalidEnum),
        o => Ok(o),
    }
}

/// The environment parameter `target`/`pname` names.
fn env_name(target: GLenum, pname: GLenum) -> GlResult<TexEnvParamName> {
    let n = |base: GLenum| (pname - base) as u8;
    Ok(match (target, pname) {
        (GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS) => TexEnvParamName::LodBias,
        (GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE) => TexEnvParamName::Mode,
        (GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR) => TexEnvParamName::Color,
        (GL_TEXTURE_ENV, GL_COMBINE_RGB) => TexEnvParamName::CombineRgb,
        (GL_TEXTURE_ENV, GL_COMBINE_ALPHA) => TexEnvParamName::CombineAlpha,
        (GL_TEXTURE_ENV, GL_SOURCE0_RGB..=0x8582) => TexEnvParamName::SrcRgb(n(GL_SOURCE0_RGB)),
        (GL_TEXTURE_ENV, GL_SOURCE0_ALPHA..=0x858A) => TexEnvParamName::SrcAlpha(n(GL_SOURCE0_ALPHA)),
        (GL_TEXTURE_ENV, GL_OPERAND0_RGB..=0x8592) => TexEnvParamName::OperandRgb(n(GL_OPERAND0_RGB)),
        (GL_TEXTURE_ENV, GL_OPERAND0_ALPHA..=0x859A) => TexEnvParamName::OperandAlpha(n(GL_OPERAND0_ALPHA)),
        (GL_TEXTURE_ENV, GL_RGB_SCALE) => TexEnvParamName::RgbScale,
        (GL_TEXTURE_ENV, GL_ALPHA_SCALE) => TexEnvParamName::AlphaScale,
        _ => return Err(GlError::InvalidEnum),
    })
}

fn env_count(pname: GLenum) -> usize {
    if pname == GL_TEXTURE_ENV_COLOR {
        4
    } else {
        1
    }
}

/// The environment parameter `name` set to `v`.
fn env_param(name: TexEnvParamName, v: &[f64], ints: bool) -> GlResult<TexEnvParam> {
    let e = v[0] as i64 as GLenum;
    Ok(match name {
        TexEnvParamName::Mode => TexEnvParam::Mode(decode::<EnvMode>(e)?),
        TexEnvParamName::Color => TexEnvParam::Color(color(v, ints)),
        TexEnvParamName::CombineRgb => TexEnvParam::CombineRgb(combine_fn(e, false)?),
        TexEnvParamName::CombineAlpha => TexEnvParam::CombineAlpha(combine_fn(e, true)?),
        TexEnvParamName::SrcRgb(i) => TexEnvParam::SrcRgb(i, decode::<CombineSrc>(e)?),
        TexEnvParamName::SrcAlpha(i) => TexEnvParam::SrcAlpha(i, decode::<CombineSrc>(e)?),
        TexEnvParamName::OperandRgb(i) => TexEnvParam::OperandRgb(i, operand(e, false)?),
        TexEnvParamName::OperandAlpha(i) => TexEnvParam::OperandAlpha(i, operand(e, true)?),
        TexEnvParamName::RgbScale => TexEnvParam::RgbScale(v[0] as f32),
        TexEnvParamName::AlphaScale => TexEnvParam::AlphaScale(v[0] as f32),
        TexEnvParamName::LodBias => TexEnvParam::LodBias(v[0] as f32),
    })
}

fn env_value(p: TexEnvParam) -> Value {
    match p {
        TexEnvParam::Mode(m) => Value::Enum(m.to_gl()),
        TexEnvParam::Color(c) => Value::Color(c),
        TexEnvParam::CombineRgb(f) | TexEnvParam::CombineAlpha(f) => Value::Enum(f.to_gl()),
        TexEnvParam::SrcRgb(_, s) | TexEnvParam::SrcAlpha(_, s) => Value::Enum(s.to_gl()),
        TexEnvParam::OperandRgb(_, o) | TexEnvParam::OperandAlpha(_, o) => Value::Enum(o.to_gl()),
        TexEnvParam::RgbScale(x) | TexEnvParam::AlphaScale(x) | TexEnvParam::LodBias(x) => Value::Num(f64::from(x)),
    }
}

/// Records `glTexEnv` with values `v`.
fn tex_env(target: GLenum, pname: GLenum, v: [f64; 4], ints: bool) {
    checked(move |gl| {
        outside(gl)?;
        let name = env_name(target, pname)?;
        gl.tex_env(env_param(name, &v, ints)?)
    })
}

/// # Safety
/// `p` is null or holds the values `pname` takes.
unsafe fn tex_env_v<T: Copy + Into<f64>>(target: GLenum, pname: GLenum, p: *const T, ints: bool) {
    // SAFETY: passed on.
    unsafe { with_values(p, env_count(pname), |v| tex_env(target, pname, v, ints)) }
}

fn get_tex_env<T: Copy>(target: GLenum, pname: GLenum, out: *mut T, conv: fn(Value) -> Vec<T>) {
    now(|_, gl| {
        outside(gl)?;
        let value = env_value(gl.get_tex_env(env_name(target, pname)?)?);
        // SAFETY: room for the parameter's values (GL's contract).
        unsafe { write(out, &conv(value)) };
        Ok(())
    })
}

// ----- texture coordinate generation -----

fn gen_name(pname: GLenum) -> GlResult<TexGenParamName> {
    Ok(match pname {
        GL_TEXTURE_GEN_MODE => TexGenParamName::Mode,
        GL_OBJECT_PLANE => TexGenParamName::ObjectPlane,
        GL_EYE_PLANE => TexGenParamName::EyePlane,
        _ => return Err(GlError::InvalidEnum),
    })
}

fn gen_count(pname: GLenum) -> usize {
    if matches!(pname, GL_OBJECT_PLANE | GL_EYE_PLANE) {
        4
    } else {
        1
    }
}

/// Records `glTexGen` with values `v`. The scalar forms pass `(param, 0, 0,
/// 0)`, a plane too, as Mesa's do (`texgen.c` `_mesa_TexGenf`, `dlist.c`
/// `save_TexGenf`: no error; llvmpipe facts §19).
fn tex_gen(c: GLenum, pname: GLenum, v: [f64; 4]) {
    checked(move |gl| {
        outside(gl)?;
        let c = decode::<TexCoordName>(c)?;
        let p = match gen_name(pname)? {
            TexGenParamName::Mode => TexGenParam::Mode(decode(v[0] as i64 as GLenum)?),
            TexGenParamName::ObjectPlane => TexGenParam::ObjectPlane(v.map(|x| x as f32)),
            TexGenParamName::EyePlane => TexGenParam::EyePlane(v.map(|x| x as f32)),
        };
        gl.tex_gen(c, p)
    })
}

/// # Safety
/// `p` is null or holds the values `pname` takes.
unsafe fn tex_gen_v<T: Copy + Into<f64>>(c: GLenum, pname: GLenum, p: *const T) {
    // SAFETY: passed on.
    unsafe { with_values(p, gen_count(pname), |v| tex_gen(c, pname, v)) }
}

fn get_tex_gen<T: Copy>(c: GLenum, pname: GLenum, out: *mut T, conv: fn(Value) -> Vec<T>) {
    now(|_, gl| {
        outside(gl)?;
        let v: Vec<T> = match gl.get_tex_gen(decode(c)?, gen_name(pname)?)? {
            TexGenParam::Mode(m) => conv(Value::Enum(m.to_gl())),
            // Planes are numbers, not colours: each converted as one.
            TexGenParam::ObjectPlane(p) | TexGenParam::EyePlane(p) => {
                p.iter().flat_map(|&x| conv(Value::Num(f64::from(x)))).collect()
            }
        };
        // SAFETY: room for the parameter's values (GL's contract).
        unsafe { write(out, &v) };
        Ok(())
    })
}

// ----- units and multitexture coordinates -----

/// `glMultiTexCoord`: `v` is (s, t, r, q).
fn multi_tex_coord(target: GLenum, v: [f32; 4]) {
    // (The context records `InvalidEnum` for a unit past the last.)
    attr(move |gl| {
        let _ = gl.multi_tex_coord(unit(target), v);
    })
}

/// `n` coordinates padded to (s, t, r, q) with GL's 0, 0, 1.
fn pad<const N: usize>(c: [f32; N]) -> [f32; 4] {
    std::array::from_fn(|k| {
        if k < N {
            c[k]
        } else if k == 3 {
            1.0
        } else {
            0.0
        }
    })
}

/// `glMultiTexCoord{1,2,3,4}{s,i,f,d}[v][ARB]`.
macro_rules! multi_tex_coords {
    ($($n:literal $t:ty: $f:ident $fv:ident $fa:ident $fva:ident ($($a:ident),*);)*) => {
        exports! {
            $(
                [] fn $f(target: GLenum, $($a: $t),*) {
                    multi_tex_coord(target, pad::<$n>([$($a as f32),*]))
                }
                /// # Safety
                /// `v` is null or points to the coordinates.
                [unsafe] fn $fv(target: GLenum, v: *const $t) {
                    // SAFETY: readable coordinates by GL's contract; null is ignored.
                    if let Some(v) = unsafe { read::<$t, $n>(v) } {
                        multi_tex_coord(target, pad(v.map(|x| x as f32)))
                    }
                }
                [] fn $fa(target: GLenum, $($a: $t),*) {
                    $f(target, $($a),*)
                }
                /// # Safety
                /// `v` is null or points to the coordinates.
                [unsafe] fn $fva(target: GLenum, v: *const $t) {
                    // SAFETY: passed on.
                    unsafe { $fv(target, v) }
                }
            )*
        }
    };
}

mod multi {
    use super::*;
    multi_tex_coords! {
        1 i16: glMultiTexCoord1s glMultiTexCoord1sv glMultiTexCoord1sARB glMultiTexCoord1svARB (s);
        1 i32: glMultiTexCoord1i glMultiTexCoord1iv glMultiTexCoord1iARB glMultiTexCoord1ivARB (s);
        1 f32: glMultiTexCoord1f glMultiTexCoord1fv glMultiTexCoord1fARB glMultiTexCoord1fvARB (s);
        1 f64: glMultiTexCoord1d glMultiTexCoord1dv glMultiTexCoord1dARB glMultiTexCoord1dvARB (s);
        2 i16: glMultiTexCoord2s glMultiTexCoord2sv glMultiTexCoord2sARB glMultiTexCoord2svARB (s, t);
        2 i32: glMultiTexCoord2i glMultiTexCoord2iv glMultiTexCoord2iARB glMultiTexCoord2ivARB (s, t);
        2 f32: glMultiTexCoord2f glMultiTexCoord2fv glMultiTexCoord2fARB glMultiTexCoord2fvARB (s, t);
        2 f64: glMultiTexCoord2d glMultiTexCoord2dv glMultiTexCoord2dARB glMultiTexCoord2dvARB (s, t);
        3 i16: glMultiTexCoord3s glMultiTexCoord3sv glMultiTexCoord3sARB glMultiTexCoord3svARB (s, t, r);
        3 i32: glMultiTexCoord3i glMultiTexCoord3iv glMultiTexCoord3iARB glMultiTexCoord3ivARB (s, t, r);
        3 f32: glMultiTexCoord3f glMultiTexCoord3fv glMultiTexCoord3fARB glMultiTexCoord3fvARB (s, t, r);
        3 f64: glMultiTexCoord3d glMultiTexCoord3dv glMultiTexCoord3dARB glMultiTexCoord3dvARB (s, t, r);
        4 i16: glMultiTexCoord4s glMultiTexCoord4sv glMultiTexCoord4sARB glMultiTexCoord4svARB (s, t, r, q);
        4 i32: glMultiTexCoord4i glMultiTexCoord4iv glMultiTexCoord4iARB glMultiTexCoord4ivARB (s, t, r, q);
        4 f32: glMultiTexCoord4f glMultiTexCoord4fv glMultiTexCoord4fARB glMultiTexCoord4fvARB (s, t, r, q);
        4 f64: glMultiTexCoord4d glMultiTexCoord4dv glMultiTexCoord4dARB glMultiTexCoord4dvARB (s, t, r, q);
    }
}
pub use multi::*;

/// The multitexture coordinate exports' table.
pub(super) fn multi_table() -> Vec<(&'static str, *const c_void)> {
    multi::table()
}

fn client_active_texture(texture: GLenum) {
    now(|os, gl| {
        let u = unit(texture) as usize;
        if u >= MAX_UNITS {
            return Err(GlError::InvalidEnum);
        }
        os.client_active = u;
        gl.client_active_texture(u as u32)
    })
}
exports! {
    // ----- environment -----
    [] fn glTexEnvf(target: GLenum, pname: GLenum, param: f32) {
        tex_env(target, pname, [f64::from(param), 0.0, 0.0, 0.0], false)
    }
    [] fn glTexEnvi(target: GLenum, pname: GLenum, param: i32) {
        tex_env(target, pname, [f64::from(param), 0.0, 0.0, 0.0], true)
    }
    /// # Safety
    /// `params` is null or holds the values `pname` takes.
    [unsafe] fn glTexEnvfv(target: GLenum, pname: GLenum, params: *const f32) {
        // SAFETY: passed on.
        unsafe { tex_env_v(target, pname, params, false) }
    }
    /// # Safety
    /// `params` is null or holds the values `pname` takes.
    [unsafe] fn glTexEnviv(target: GLenum, pname: GLenum, params: *const i32) {
        // SAFETY: passed on.
        unsafe { tex_env_v(target, pname, params, true) }
    }
    /// # Safety
    /// `params` is null or has room for the values of `pname`.
    [unsafe] fn glGetTexEnvfv(target: GLenum, pname: GLenum, params: *mut f32) {
        get_tex_env(target, pname, params, floats)
    }
    /// # Safety
    /// `params` is null or has room for the values of `pname`.
    [unsafe] fn glGetTexEnviv(target: GLenum, pname: GLenum, params: *mut i32) {
        get_tex_env(target, pname, params, ints)
    }

    // ----- coordinate generation -----
    [] fn glTexGeni(coord: GLenum, pname: GLenum, param: i32) {
        tex_gen(coord, pname, [f64::from(param), 0.0, 0.0, 0.0])
    }
    [] fn glTexGenf(coord: GLenum, pname: GLenum, param: f32) {
        tex_gen(coord, pname, [f64::from(param), 0.0, 0.0, 0.0])
    }
    [] fn glTexGend(coord: GLenum, pname: GLenum, param: f64) {
        tex_gen(coord, pname, [param, 0.0, 0.0, 0.0])
    }
    /// # Safety
    /// `params` is null or holds the values `pname` takes.
    [unsafe] fn glTexGeniv(coord: GLenum, pname: GLenum, params: *const i32) {
        // SAFETY: passed on.
        unsafe { tex_gen_v(coord, pname, params) }
    }
    /// # Safety
    /// `params` is null or holds the values `pname` takes.
    [unsafe] fn glTexGenfv(coord: GLenum, pname: GLenum, params: *const f32) {
        // SAFETY: passed on.
        unsafe { tex_gen_v(coord, pname, params) }
    }
    /// # Safety
    /// `params` is null or holds the values `pname` takes.
    [unsafe] fn glTexGendv(coord: GLenum, pname: GLenum, params: *const f64) {
        // SAFETY: passed on.
        unsafe { tex_gen_v(coord, pname, params) }
    }
    /// # Safety
    /// `params` is null or has room for the values of `pname`.
    [unsafe] fn glGetTexGeniv(coord: GLenum, pname: GLenum, params: *mut i32) {
        get_tex_gen(coord, pname, params, ints)
    }
    /// # Safety
    /// `params` is null or has room for the values of `pname`.
    [unsafe] fn glGetTexGenfv(coord: GLenum, pname: GLenum, params: *mut f32) {
        get_tex_gen(coord, pname, params, floats)
    }
    /// # Safety
    /// `params` is null or has room for the values of `pname`.
    [unsafe] fn glGetTexGendv(coord: GLenum, pname: GLenum, params: *mut f64) {
        get_tex_gen(coord, pname, params, |v| floats(v).into_iter().map(f64::from).collect())
    }

    // ----- units -----
    [] fn glClientActiveTexture(texture: GLenum) {
        client_active_texture(texture)
    }
    [] fn glClientActiveTextureARB(texture: GLenum) {
        client_active_texture(texture)
    }
}

/// The `glGet` values of the units: the active unit's current coordinates.
pub(super) fn value(gl: &Context, pname: GLenum) -> Option<Val> {
    let unit = gl.active_texture_unit();
    Some(match pname {
        GL_CURRENT_TEXTURE_COORDS => Val::F(
            gl.current().tex_coords[unit]
                .to_array()
                .iter()
                .map(|&c| f64::from(c))
                .collect(),
        ),
        _ => return None,
    })
}
