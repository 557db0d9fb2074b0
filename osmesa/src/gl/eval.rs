//! Evaluators (GL 1.5 §5.1): `glMap1`/`glMap2`, `glMapGrid`, `glGetMap`,
//! `glEvalCoord`, `glEvalPoint`, `glEvalMesh`, a thin layer over
//! [`softgl::eval`]. The maps' enables (and `GL_AUTO_NORMAL`) are kept with
//! the other stored capabilities (`GlState::inert_caps`); `glMap` copies
//! its points when it is called, also while a display list is compiled.

use super::{now, outside, rec};
use crate::consts::GLenum;
use crate::gl_state::GlState;
use softgl::eval::{check_map1, check_map2, EvalEnables, MapTarget, MeshMode, AUTO_NORMAL};
use softgl::{Context, GlError, GlResult};

/// `GL_AUTO_NORMAL`.
const GL_AUTO_NORMAL: GLenum = 0x0D80;

/// The capabilities `GL_EVAL_BIT` (and `GL_ENABLE_BIT`) save: the 18 maps
/// and `GL_AUTO_NORMAL`.
pub(crate) fn eval_caps() -> impl Iterator<Item = GLenum> {
    (0x0D90..=0x0D98).chain(0x0DB0..=0x0DB8).chain([GL_AUTO_NORMAL])
}

/// The enabled maps, from the stored capabilities.
fn enables(os: &GlState) -> EvalEnables {
    let mut bits = 0;
    for &c in &os.inert_caps {
        if c == GL_AUTO_NORMAL {
            bits |= AUTO_NORMAL;
        } else if let Some(t) = MapTarget::from_gl(c) {
            bits |= t.bit();
        }
    }
    EvalEnables(bits)
}

/// Copies `n` values from `points` as `f32`s (none for a null pointer).
///
/// # Safety
/// `points` is null or points to `n` readable values.
unsafe fn read_points<T: Copy + Into<f64>>(points: *const T, n: usize) -> Vec<f32> {
    if points.is_null() {
        return Vec::new();
    }
    // SAFETY: `n` readable values, by the caller's contract.
    let s = unsafe { std::slice::from_raw_parts(points, n) };
    s.iter().map(|&x| x.into() as f32).collect()
}

/// `glMap1` on `pts` (copied when the call was made).
fn map1(target: GLenum, u1: f32, u2: f32, stride: i32, order: i32, pts: Vec<f32>) {
    rec(move |os, gl| {
        outside(gl)?;
        let (t, n) = check_map1(target, u1, u2, stride, order)?;
        if pts.len() < n {
            return Err(GlError::InvalidValue); // a null `points`
        }
        if gl.active_texture_unit() != 0 {
            return Err(GlError::InvalidOperation); // as Mesa's `map1`
        }
        os.eval.map1(t, u1, u2, stride as usize, order as usize, &pts)
    })
}

/// `glMap2` on `pts`.
#[allow(clippy::too_many_arguments)]
fn map2(target: GLenum, u: (f32, f32, i32, i32), v: (f32, f32, i32, i32), pts: Vec<f32>) {
    rec(move |os, gl| {
        outside(gl)?;
        let (t, n) = check_map2(target, u.0, u.1, u.2, u.3, v.0, v.1, v.2, v.3)?;
        if pts.len() < n {
            return Err(GlError::InvalidValue);
        }
        if gl.active_texture_unit() != 0 {
            return Err(GlError::InvalidOperation);
        }
        let uu = (u.0, u.1, u.2 as usize, u.3 as usize);
        let vv = (v.0, v.1, v.2 as usize, v.3 as usize);
        os.eval.map2(t, uu, vv, &pts)
    })
}

/// The number of values `glMap1`'s `points` holds (0 when the call fails).
fn len1(target: GLenum, u1: f32, u2: f32, stride: i32, order: i32) -> usize {
    check_map1(target, u1, u2, stride, order).map_or(0, |(_, n)| n)
}

#[allow(clippy::too_many_arguments)]
fn len2(target: GLenum, u: (f32, f32, i32, i32), v: (f32, f32, i32, i32)) -> usize {
    check_map2(target, u.0, u.1, u.2, u.3, v.0, v.1, v.2, v.3).map_or(0, |(_, n)| n)
}

/// `glGetMap*v`: writes the values of `query` through `write`.
fn get_map(target: GLenum, query: GLenum, write: impl FnOnce(&[f32])) {
    now(|os, gl| {
        outside(gl)?;
        let vals = os.eval.get_map(target, query)?;
        write(&vals);
        Ok(())
    })
}

/// Writes `vals` converted by `f` through `out` (nothing when it is null).
///
/// # Safety
/// `out` is null or has room for `vals.len()` values.
unsafe fn write_out<T>(out: *mut T, vals: &[f32], f: impl Fn(f32) -> T) {
    if out.is_null() {
        return;
    }
    for (i, &x) in vals.iter().enumerate() {
        // SAFETY: room for `vals.len()` values, by the caller's contract.
        unsafe { out.add(i).write_unaligned(f(x)) };
    }
}

fn coord1(u: f32) {
    rec(move |os, gl| {
        os.eval.eval_coord1(enables(os), gl, u);
        Ok(())
    })
}

fn coord2(u: f32, v: f32) {
    rec(move |os, gl| {
        os.eval.eval_coord2(enables(os), gl, u, v);
        Ok(())
    })
}

/// Reads `n` values through `p` as `f32`s, or `None` for a null pointer.
///
/// # Safety
/// `p` is null or points to `n` readable values.
unsafe fn read2<T: Copy + Into<f64>>(p: *const T, n: usize) -> Option<[f32; 2]> {
    // SAFETY: as `read_points`'.
    let v = unsafe { read_points(p, n) };
    (v.len() == n).then(|| [v[0], *v.get(1).unwrap_or(&0.0)])
}

fn mesh(f: impl Fn(&GlState, &mut Context) -> GlResult + Send + Sync + 'static) {
    rec(move |os, gl| {
        outside(gl)?;
        f(os, gl)
    })
}

fn mode(m: GLenum) -> GlResult<MeshMode> {
    MeshMode::from_gl(m).ok_or(GlError::InvalidEnum)
}

exports! {
    /// # Safety
    /// `points` is null or holds `(order - 1) * stride + k` values.
    [unsafe] fn glMap1f(target: GLenum, u1: f32, u2: f32, stride: i32, order: i32, points: *const f32) {
        // SAFETY: the caller's contract.
        let pts = unsafe { read_points(points, len1(target, u1, u2, stride, order)) };
        map1(target, u1, u2, stride, order, pts)
    }
    /// # Safety
    /// As `glMap1f`.
    [unsafe] fn glMap1d(target: GLenum, u1: f64, u2: f64, stride: i32, order: i32, points: *const f64) {
        let (u1, u2) = (u1 as f32, u2 as f32);
        // SAFETY: the caller's contract.
        let pts = unsafe { read_points(points, len1(target, u1, u2, stride, order)) };
        map1(target, u1, u2, stride, order, pts)
    }
    /// # Safety
    /// `points` is null or holds the `uorder × vorder` points GL reads.
    [unsafe] fn glMap2f(target: GLenum, u1: f32, u2: f32, ustride: i32, uorder: i32, v1: f32, v2: f32, vstride: i32, vorder: i32, points: *const f32) {
        let (u, v) = ((u1, u2, ustride, uorder), (v1, v2, vstride, vorder));
        // SAFETY: the caller's contract.
        let pts = unsafe { read_points(points, len2(target, u, v)) };
        map2(target, u, v, pts)
    }
    /// # Safety
    /// As `glMap2f`.
    [unsafe] fn glMap2d(target: GLenum, u1: f64, u2: f64, ustride: i32, uorder: i32, v1: f64, v2: f64, vstride: i32, vorder: i32, points: *const f64) {
        let u = (u1 as f32, u2 as f32, ustride, uorder);
        let v = (v1 as f32, v2 as f32, vstride, vorder);
        // SAFETY: the caller's contract.
        let pts = unsafe { read_points(points, len2(target, u, v)) };
        map2(target, u, v, pts)
    }
    [] fn glMapGrid1f(un: i32, u1: f32, u2: f32) {
        rec(move |os, gl| {
            outside(gl)?;
            os.eval.map_grid1(un, u1, u2)
        })
    }
    [] fn glMapGrid1d(un: i32, u1: f64, u2: f64) {
        glMapGrid1f(un, u1 as f32, u2 as f32)
    }
    [] fn glMapGrid2f(un: i32, u1: f32, u2: f32, vn: i32, v1: f32, v2: f32) {
        rec(move |os, gl| {
            outside(gl)?;
            os.eval.map_grid2(un, u1, u2, vn, v1, v2)
        })
    }
    [] fn glMapGrid2d(un: i32, u1: f64, u2: f64, vn: i32, v1: f64, v2: f64) {
        glMapGrid2f(un, u1 as f32, u2 as f32, vn, v1 as f32, v2 as f32)
    }
    /// # Safety
    /// `v` is null or has room for the values of `query`.
    [unsafe] fn glGetMapfv(target: GLenum, query: GLenum, v: *mut f32) {
        // SAFETY: the caller's contract.
        get_map(target, query, |vals| unsafe { write_out(v, vals, |x| x) })
    }
    /// # Safety
    /// As `glGetMapfv`.
    [unsafe] fn glGetMapdv(target: GLenum, query: GLenum, v: *mut f64) {
        // SAFETY: the caller's contract.
        get_map(target, query, |vals| unsafe { write_out(v, vals, f64::from) })
    }
    /// # Safety
    /// As `glGetMapfv`. Values are rounded as Mesa's `lroundf`.
    [unsafe] fn glGetMapiv(target: GLenum, query: GLenum, v: *mut i32) {
        // SAFETY: the caller's contract.
        get_map(target, query, |vals| unsafe { write_out(v, vals, |x| x.round() as i32) })
    }
    [] fn glEvalCoord1f(u: f32) {
        coord1(u)
    }
    [] fn glEvalCoord1d(u: f64) {
        coord1(u as f32)
    }
    /// # Safety
    /// `u` is null or readable.
    [unsafe] fn glEvalCoord1fv(u: *const f32) {
        // SAFETY: the caller's contract.
        if let Some([u, _]) = unsafe { read2(u, 1) } {
            coord1(u)
        }
    }
    /// # Safety
    /// `u` is null or readable.
    [unsafe] fn glEvalCoord1dv(u: *const f64) {
        // SAFETY: the caller's contract.
        if let Some([u, _]) = unsafe { read2(u, 1) } {
            coord1(u)
        }
    }
    [] fn glEvalCoord2f(u: f32, v: f32) {
        coord2(u, v)
    }
    [] fn glEvalCoord2d(u: f64, v: f64) {
        coord2(u as f32, v as f32)
    }
    /// # Safety
    /// `u` is null or holds 2 values.
    [unsafe] fn glEvalCoord2fv(u: *const f32) {
        // SAFETY: the caller's contract.
        if let Some([u, v]) = unsafe { read2(u, 2) } {
            coord2(u, v)
        }
    }
    /// # Safety
    /// `u` is null or holds 2 values.
    [unsafe] fn glEvalCoord2dv(u: *const f64) {
        // SAFETY: the caller's contract.
        if let Some([u, v]) = unsafe { read2(u, 2) } {
            coord2(u, v)
        }
    }
    [] fn glEvalPoint1(i: i32) {
        rec(move |os, gl| {
            os.eval.eval_point1(enables(os), gl, i);
            Ok(())
        })
    }
    [] fn glEvalPoint2(i: i32, j: i32) {
        rec(move |os, gl| {
            os.eval.eval_point2(enables(os), gl, i, j);
            Ok(())
        })
    }
    [] fn glEvalMesh1(m: GLenum, i1: i32, i2: i32) {
        mesh(move |os, gl| os.eval.eval_mesh1(enables(os), gl, mode(m)?, i1, i2))
    }
    [] fn glEvalMesh2(m: GLenum, i1: i32, i2: i32, j1: i32, j2: i32) {
        mesh(move |os, gl| os.eval.eval_mesh2(enables(os), gl, mode(m)?, i1, i2, j1, j2))
    }
}
