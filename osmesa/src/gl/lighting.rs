//! Lighting and user clip planes: `glLight*`, `glLightModel*`,
//! `glMaterial*` (also between `glBegin` and `glEnd`), `glGetLight*`,
//! `glGetMaterial*`, `glColorMaterial`, `glClipPlane`, `glGetClipPlane`.
//! Integer colours convert as GL 1.x says (`(2c + 1) / (2^32 − 1)`), and back
//! as Mesa's `FLOAT_TO_INT`; other integer values convert as numbers.

use super::enums::decode;
use super::{checked, now, rec};
use crate::consts::GLenum;
use softgl::lighting::MAX_CLIP_PLANES;
use softgl::{
    ColorControl, ColorMaterialMode, Face, GlError, GlResult, LightModelParam, LightParam, LightParamName,
    MaterialParam, MaterialParamName,
};

const GL_LIGHT0: GLenum = 0x4000;
const GL_CLIP_PLANE0: GLenum = 0x3000;
const GL_LIGHT_MODEL_LOCAL_VIEWER: GLenum = 0x0B51;
const GL_LIGHT_MODEL_TWO_SIDE: GLenum = 0x0B52;
const GL_LIGHT_MODEL_AMBIENT: GLenum = 0x0B53;
const GL_LIGHT_MODEL_COLOR_CONTROL: GLenum = 0x81F8;
const GL_AMBIENT_AND_DIFFUSE: GLenum = 0x1602;
const GL_COLOR_INDEXES: GLenum = 0x1603;

/// `GL_INVALID_OPERATION` between `glBegin` and `glEnd`: Mesa checks that
/// before any argument (`ASSERT_OUTSIDE_BEGIN_END`, or the begin/end dispatch).
fn outside(gl: &softgl::Context) -> GlResult {
    if gl.inside_begin() {
        Err(GlError::InvalidOperation)
    } else {
        Ok(())
    }
}

/// How many values a light parameter has.
fn light_count(name: LightParamName) -> usize {
    match name {
        LightParamName::Ambient | LightParamName::Diffuse | LightParamName::Specular | LightParamName::Position => 4,
        LightParamName::SpotDirection => 3,
        _ => 1,
    }
}

/// Whether a parameter's values are colours (converted as normalized integers).
fn light_is_color(name: LightParamName) -> bool {
    matches!(
        name,
        LightParamName::Ambient | LightParamName::Diffuse | LightParamName::Specular
    )
}

fn four(v: &[f32]) -> [f32; 4] {
    [v[0], v[1], v[2], v[3]]
}

/// The `LightParam` of `name` from its values.
fn light_param(name: LightParamName, v: &[f32]) -> LightParam {
    match name {
        LightParamName::Ambient => LightParam::Ambient(four(v)),
        LightParamName::Diffuse => LightParam::Diffuse(four(v)),
        LightParamName::Specular => LightParam::Specular(four(v)),
        LightParamName::Position => LightParam::Position(four(v)),
        LightParamName::SpotDirection => LightParam::SpotDirection([v[0], v[1], v[2]]),
        LightParamName::SpotExponent => LightParam::SpotExponent(v[0]),
        LightParamName::SpotCutoff => LightParam::SpotCutoff(v[0]),
        LightParamName::ConstantAttenuation => LightParam::ConstantAttenuation(v[0]),
        LightParamName::LinearAttenuation => LightParam::LinearAttenuation(v[0]),
        LightParamName::QuadraticAttenuation => LightParam::QuadraticAttenuation(v[0]),
    }
}

/// The values of a `LightParam`.
fn light_values(p: LightParam) -> Vec<f32> {
    match p {
        LightParam::Ambient(c) | LightParam::Diffuse(c) | LightParam::Specular(c) | LightParam::Position(c) => {
            c.to_vec()
        }
        LightParam::SpotDirection(d) => d.to_vec(),
        LightParam::SpotExponent(x)
        | LightParam::SpotCutoff(x)
        | LightParam::ConstantAttenuation(x)
        | LightParam::LinearAttenuation(x)
        | LightParam::QuadraticAttenuation(x) => vec![x],
    }
}

/// The light index `GL_LIGHTi` names (`InvalidEnum` past the last, checked by the context).
fn light_index(light: GLenum) -> GlResult<u32> {
    light.checked_sub(GL_LIGHT0).ok_or(GlError::InvalidEnum)
}

/// GL 1.x's signed integer to float (colours).
fn int_color(c: i32) -> f32 {
    ((2.0 * f64::from(c) + 1.0) / 4294967295.0) as f32
}

/// Mesa's `FLOAT_TO_INT`.
fn color_int(c: f32) -> i32 {
    (2147483647.0 * f64::from(c)) as i32
}

/// Reads `n` values through `p`; `InvalidValue` for a null pointer.
///
/// # Safety
/// `p` is null or points to `n` readable values.
unsafe fn read_n<T: Copy>(p: *const T, n: usize) -> GlResult<Vec<T>> {
    if p.is_null() {
        return Err(GlError::InvalidValue);
    }
    // SAFETY: `n` readable values by the caller's contract.
    Ok(unsafe { std::slice::from_raw_parts(p, n) }.to_vec())
}

/// Writes `v` through `out` when it is not null.
///
/// # Safety
/// `out` is null or has room for `v.len()` values.
unsafe fn write_n<T: Copy>(out: *mut T, v: &[T]) {
    if !out.is_null() {
        // SAFETY: room for every value, by GL's contract.
        unsafe { std::ptr::copy_nonoverlapping(v.as_ptr(), out, v.len()) };
    }
}

/// `glLight*v`: `conv(values, is_color)` turns the caller's values into floats.
///
/// # Safety
/// `params` is null or holds the parameter's values.
unsafe fn light_v<T: Copy>(light: GLenum, pname: GLenum, params: *const T, conv: fn(T, bool) -> f32) {
    let parsed = decode::<LightParamName>(pname).and_then(|name| {
        // SAFETY: passed on from the caller.
        let raw = unsafe { read_n(params, light_count(name)) }?;
        let v: Vec<f32> = raw.iter().map(|&x| conv(x, light_is_color(name))).collect();
        Ok(light_param(name, &v))
    });
    checked(move |gl| {
        outside(gl)?;
        let index = light_index(light)?;
        gl.light(index, parsed?)
    })
}

/// `glGetLight*v`.
fn get_light<T: Copy>(light: GLenum, pname: GLenum, out: *mut T, conv: fn(f32, bool) -> T) {
    now(|_, gl| {
        outside(gl)?;
        let index = light_index(light)?;
        let name = decode::<LightParamName>(pname)?;
        let v = light_values(gl.get_light(index, name)?);
        let vals: Vec<T> = v.iter().map(|&x| conv(x, light_is_color(name))).collect();
        // SAFETY: room for the parameter's values (GL's contract).
        unsafe { write_n(out, &vals) };
        Ok(())
    })
}

/// `glLightModel*`: `v` the values (up to 4, colours already converted).
fn light_model(pname: GLenum, v: Vec<f32>) {
    let parsed = match pname {
        GL_LIGHT_MODEL_AMBIENT => Ok(LightModelParam::Ambient(four(&v))),
        GL_LIGHT_MODEL_LOCAL_VIEWER => Ok(LightModelParam::LocalViewer(v[0] != 0.0)),
        GL_LIGHT_MODEL_TWO_SIDE => Ok(LightModelParam::TwoSide(v[0] != 0.0)),
        GL_LIGHT_MODEL_COLOR_CONTROL => {
            // An enumerant passed as a number.
            decode::<ColorControl>(v[0] as u32).map(LightModelParam::ColorControl)
        }
        _ => Err(GlError::InvalidEnum),
    };
    checked(move |gl| {
        outside(gl)?;
        gl.light_model(parsed?)
    })
}

/// How many values `glLightModel*v` reads for `pname` (1 for unknown names:
/// the call then fails on the name).
fn model_count(pname: GLenum) -> usize {
    if pname == GL_LIGHT_MODEL_AMBIENT {
        4
    } else {
        1
    }
}

/// The material parameter `pname` names, with its values (`None` for
/// `GL_COLOR_INDEXES`, which RGBA rendering ignores).
fn material_param(pname: GLenum, v: &[f32]) -> GlResult<Option<MaterialParam>> {
    if pname == GL_AMBIENT_AND_DIFFUSE {
        return Ok(Some(MaterialParam::AmbientAndDiffuse(four(v))));
    }
    if pname == GL_COLOR_INDEXES {
        return Ok(None);
    }
    Ok(Some(match decode::<MaterialParamName>(pname)? {
        MaterialParamName::Ambient => MaterialParam::Ambient(four(v)),
        MaterialParamName::Diffuse => MaterialParam::Diffuse(four(v)),
        MaterialParamName::Specular => MaterialParam::Specular(four(v)),
        MaterialParamName::Emission => MaterialParam::Emission(four(v)),
        MaterialParamName::Shininess => MaterialParam::Shininess(v[0]),
    }))
}

fn material_count(pname: GLenum) -> usize {
    match pname {
        0x1601 => 1,           // SHININESS
        GL_COLOR_INDEXES => 3, // COLOR_INDEXES
        _ => 4,
    }
}

/// Records a `glMaterial` (allowed between `glBegin` and `glEnd`).
fn material(face: GLenum, param: GlResult<Option<MaterialParam>>) {
    rec(move |_, gl| {
        let face = decode::<Face>(face)?;
        match param? {
            Some(p) => gl.material(face, p),
            None => Ok(()),
        }
    })
}

/// `glMaterial*v`.
///
/// # Safety
/// `params` is null or holds the parameter's values.
unsafe fn material_v<T: Copy>(face: GLenum, pname: GLenum, params: *const T, conv: fn(T, bool) -> f32) {
    // SAFETY: passed on from the caller.
    let parsed = unsafe { read_n(params, material_count(pname)) }.and_then(|raw| {
        let color = material_count(pname) == 4;
        let v: Vec<f32> = raw.iter().map(|&x| conv(x, color)).collect();
        material_param(pname, &v)
    });
    material(face, parsed)
}

/// `glGetMaterial*v`.
fn get_material<T: Copy>(face: GLenum, pname: GLenum, out: *mut T, conv: fn(f32, bool) -> T) {
    now(|_, gl| {
        outside(gl)?;
        let face = decode::<Face>(face)?;
        let name = decode::<MaterialParamName>(pname)?;
        let (v, color) = match gl.get_material(face, name)? {
            MaterialParam::Ambient(c)
            | MaterialParam::Diffuse(c)
            | MaterialParam::AmbientAndDiffuse(c)
            | MaterialParam::Specular(c)
            | MaterialParam::Emission(c) => (c.to_vec(), true),
            MaterialParam::Shininess(s) => (vec![s], false),
        };
        let vals: Vec<T> = v.iter().map(|&x| conv(x, color)).collect();
        // SAFETY: room for the parameter's values (GL's contract).
        unsafe { write_n(out, &vals) };
        Ok(())
    })
}

fn f_in(x: f32, _: bool) -> f32 {
    x
}

fn i_in(x: i32, color: bool) -> f32 {
    if color {
        int_color(x)
    } else {
        x as f32
    }
}

fn f_out(x: f32, _: bool) -> f32 {
    x
}

/// Colours as `FLOAT_TO_INT`; other values truncated, as Mesa's `glGetLightiv`.
fn i_out(x: f32, color: bool) -> i32 {
    if color {
        color_int(x)
    } else {
        x as i32
    }
}

/// Material shininess as integer: rounded (Mesa's `IROUND`).
fn i_out_material(x: f32, color: bool) -> i32 {
    if color {
        color_int(x)
    } else {
        x.round() as i32
    }
}

exports! {
    /// A vector `pname` is no error: the value and three zeros, as Mesa's
    /// `_mesa_Lightf` (`main/light.c`); the same for the three below.
    [] fn glLightf(light: GLenum, pname: GLenum, param: f32) {
        // SAFETY: 4 readable floats.
        unsafe { glLightfv(light, pname, [param, 0.0, 0.0, 0.0].as_ptr()) }
    }
    [] fn glLighti(light: GLenum, pname: GLenum, param: i32) {
        // SAFETY: 4 readable integers.
        unsafe { glLightiv(light, pname, [param, 0, 0, 0].as_ptr()) }
    }
    /// # Safety
    /// `params` is null or holds the parameter's values.
    [unsafe] fn glLightfv(light: GLenum, pname: GLenum, params: *const f32) {
        // SAFETY: passed on.
        unsafe { light_v(light, pname, params, f_in) }
    }
    /// # Safety
    /// `params` is null or holds the parameter's values.
    [unsafe] fn glLightiv(light: GLenum, pname: GLenum, params: *const i32) {
        // SAFETY: passed on.
        unsafe { light_v(light, pname, params, i_in) }
    }
    /// # Safety
    /// `params` is null or has room for the parameter's values.
    [unsafe] fn glGetLightfv(light: GLenum, pname: GLenum, params: *mut f32) {
        get_light(light, pname, params, f_out)
    }
    /// # Safety
    /// `params` is null or has room for the parameter's values.
    [unsafe] fn glGetLightiv(light: GLenum, pname: GLenum, params: *mut i32) {
        get_light(light, pname, params, i_out)
    }
    [] fn glLightModelf(pname: GLenum, param: f32) {
        // SAFETY: 4 readable floats.
        unsafe { glLightModelfv(pname, [param, 0.0, 0.0, 0.0].as_ptr()) }
    }
    [] fn glLightModeli(pname: GLenum, param: i32) {
        // SAFETY: 4 readable integers.
        unsafe { glLightModeliv(pname, [param, 0, 0, 0].as_ptr()) }
    }
    /// # Safety
    /// `params` is null or holds the parameter's values.
    [unsafe] fn glLightModelfv(pname: GLenum, params: *const f32) {
        // SAFETY: the parameter's values, by GL's contract.
        match unsafe { read_n(params, model_count(pname)) } {
            Ok(v) => light_model(pname, v),
            Err(e) => checked(move |gl| {
                outside(gl)?;
                Err(e)
            }),
        }
    }
    /// # Safety
    /// `params` is null or holds the parameter's values.
    [unsafe] fn glLightModeliv(pname: GLenum, params: *const i32) {
        // SAFETY: the parameter's values, by GL's contract.
        match unsafe { read_n(params, model_count(pname)) } {
            Ok(v) => {
                let color = pname == GL_LIGHT_MODEL_AMBIENT;
                light_model(pname, v.iter().map(|&x| i_in(x, color)).collect())
            }
            Err(e) => checked(move |gl| {
                outside(gl)?;
                Err(e)
            }),
        }
    }
    /// A colour `pname` is no error: as Mesa's `TAG(Materialf)`
    /// (`vbo/vbo_attrib_tmp.h`), the value becomes the first component (Mesa
    /// leaves the other three unset; softgl takes 0, 0, 1).
    [] fn glMaterialf(face: GLenum, pname: GLenum, param: f32) {
        material(face, material_param(pname, &[param, 0.0, 0.0, 1.0]))
    }
    [] fn glMateriali(face: GLenum, pname: GLenum, param: i32) {
        glMaterialf(face, pname, param as f32)
    }
    /// # Safety
    /// `params` is null or holds the parameter's values.
    [unsafe] fn glMaterialfv(face: GLenum, pname: GLenum, params: *const f32) {
        // SAFETY: passed on.
        unsafe { material_v(face, pname, params, f_in) }
    }
    /// # Safety
    /// `params` is null or holds the parameter's values.
    [unsafe] fn glMaterialiv(face: GLenum, pname: GLenum, params: *const i32) {
        // SAFETY: passed on.
        unsafe { material_v(face, pname, params, i_in) }
    }
    /// # Safety
    /// `params` is null or has room for the parameter's values.
    [unsafe] fn glGetMaterialfv(face: GLenum, pname: GLenum, params: *mut f32) {
        get_material(face, pname, params, f_out)
    }
    /// # Safety
    /// `params` is null or has room for the parameter's values.
    [unsafe] fn glGetMaterialiv(face: GLenum, pname: GLenum, params: *mut i32) {
        get_material(face, pname, params, i_out_material)
    }
    [] fn glColorMaterial(face: GLenum, mode: GLenum) {
        checked(move |gl| gl.color_material(decode::<Face>(face)?, decode::<ColorMaterialMode>(mode)?))
    }
    /// # Safety
    /// `equation` is null or points to 4 doubles.
    [unsafe] fn glClipPlane(plane: GLenum, equation: *const f64) {
        // SAFETY: 4 readable doubles, by GL's contract.
        let eq = unsafe { read_n(equation, 4) };
        checked(move |gl| {
            outside(gl)?;
            let index = plane.checked_sub(GL_CLIP_PLANE0).filter(|&i| (i as usize) < MAX_CLIP_PLANES);
            let index = index.ok_or(GlError::InvalidEnum)?;
            let eq = eq.clone()?;
            gl.clip_plane(index, [eq[0], eq[1], eq[2], eq[3]])
        })
    }
    /// # Safety
    /// `equation` is null or has room for 4 doubles.
    [unsafe] fn glGetClipPlane(plane: GLenum, equation: *mut f64) {
        now(|_, gl| {
            outside(gl)?;
            let index = plane.checked_sub(GL_CLIP_PLANE0).ok_or(GlError::InvalidEnum)?;
            let eq = gl.get_clip_plane(index)?;
            // SAFETY: room for 4 doubles (GL's contract).
            unsafe { write_n(equation, &eq) };
            Ok(())
        })
    }
}
