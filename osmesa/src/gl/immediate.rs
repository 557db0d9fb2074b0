//! Immediate mode: `glBegin`/`glEnd` and every `glVertex`, `glColor`,
//! `glNormal`, `glTexCoord` and `glRect` variant of GL 1.1.

use super::enums::decode;
use super::lists::{begin_run, end_run, record_attrib};
use super::{checked, gl};
use crate::state::attrib;
use softgl::Context;

/// Integer colour components to floats, GL 1.x's rules: unsigned `c / max`,
/// signed `(2c + 1) / (2 max + 1)`.
pub(super) trait Norm: Copy {
    fn norm(self) -> f32;
}
impl Norm for f32 {
    fn norm(self) -> f32 {
        self
    }
}
impl Norm for f64 {
    fn norm(self) -> f32 {
        self as f32
    }
}
impl Norm for u8 {
    fn norm(self) -> f32 {
        f32::from(self) / 255.0
    }
}
impl Norm for i8 {
    fn norm(self) -> f32 {
        (2.0 * f32::from(self) + 1.0) / 255.0
    }
}
impl Norm for u16 {
    fn norm(self) -> f32 {
        f32::from(self) / 65535.0
    }
}
impl Norm for i16 {
    fn norm(self) -> f32 {
        (2.0 * f32::from(self) + 1.0) / 65535.0
    }
}
impl Norm for u32 {
    fn norm(self) -> f32 {
        (f64::from(self) / 4294967295.0) as f32
    }
}
impl Norm for i32 {
    fn norm(self) -> f32 {
        ((2.0 * f64::from(self) + 1.0) / 4294967295.0) as f32
    }
}

/// Reads `N` values through `v`, or `None` for a null pointer.
///
/// # Safety
/// `v` is null or points to `N` readable values.
pub(super) unsafe fn read<T: Copy, const N: usize>(v: *const T) -> Option<[T; N]> {
    if v.is_null() {
        return None;
    }
    // SAFETY: `N` readable values by the caller's contract.
    Some(unsafe { std::ptr::read_unaligned(v.cast::<[T; N]>()) })
}

// Each attribute call runs at once through [`attrib`]'s fast path (no
// lock, no `RefCell`, no `catch_unwind`: the closures cannot panic); while a
// list is compiled it comes back and goes into the list's run or is recorded.

#[inline]
fn vertex(x: f32, y: f32, z: f32, w: f32) {
    if attrib(move |gl: &mut Context| gl.vertex4(x, y, z, w)).is_some() {
        record_attrib(move |r| r.vertex4(x, y, z, w), move |gl| gl.vertex4(x, y, z, w))
    }
}

#[inline]
fn color(r: f32, g: f32, b: f32, a: f32) {
    if attrib(move |gl: &mut Context| gl.color4(r, g, b, a)).is_some() {
        record_attrib(move |run| run.color4(r, g, b, a), move |gl| gl.color4(r, g, b, a))
    }
}

#[inline]
fn normal(x: f32, y: f32, z: f32) {
    if attrib(move |gl: &mut Context| gl.normal3(x, y, z)).is_some() {
        record_attrib(move |r| r.normal3(x, y, z), move |gl| gl.normal3(x, y, z))
    }
}

#[inline]
fn tex_coord(s: f32, t: f32, r: f32, q: f32) {
    if attrib(move |gl: &mut Context| gl.tex_coord([s, t, r, q])).is_some() {
        record_attrib(
            move |run| run.tex_coord([s, t, r, q]),
            move |gl| gl.tex_coord([s, t, r, q]),
        )
    }
}

fn rect(x1: f32, y1: f32, x2: f32, y2: f32) {
    gl(move |gl| {
        gl.begin(softgl::PrimitiveMode::Polygon)?;
        gl.vertex2(x1, y1);
        gl.vertex2(x2, y1);
        gl.vertex2(x2, y2);
        gl.vertex2(x1, y2);
        gl.end()
    })
}

exports! {
    [] fn glBegin(mode: u32) {
        if !begin_run(mode) {
            checked(move |gl| gl.begin(decode(mode)?))
        }
    }
    [] fn glEnd() {
        if !end_run() {
            gl(Context::end)
        }
    }
    [] fn glVertex2d(x: f64, y: f64) {
        vertex(x as f32, y as f32, 0.0, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 2 values.
    [unsafe] fn glVertex2dv(v: *const f64) {
        // SAFETY: 2 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<f64, 2>(v) } {
            vertex(v[0] as f32, v[1] as f32, 0.0, 1.0)
        }
    }
    [] fn glVertex3d(x: f64, y: f64, z: f64) {
        vertex(x as f32, y as f32, z as f32, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 3 values.
    [unsafe] fn glVertex3dv(v: *const f64) {
        // SAFETY: 3 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<f64, 3>(v) } {
            vertex(v[0] as f32, v[1] as f32, v[2] as f32, 1.0)
        }
    }
    [] fn glVertex4d(x: f64, y: f64, z: f64, w: f64) {
        vertex(x as f32, y as f32, z as f32, w as f32)
    }
    /// # Safety
    /// `v` is null or points to 4 values.
    [unsafe] fn glVertex4dv(v: *const f64) {
        // SAFETY: 4 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<f64, 4>(v) } {
            vertex(v[0] as f32, v[1] as f32, v[2] as f32, v[3] as f32)
        }
    }
    [] fn glVertex2f(x: f32, y: f32) {
        vertex(x, y, 0.0, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 2 values.
    [unsafe] fn glVertex2fv(v: *const f32) {
        // SAFETY: 2 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<f32, 2>(v) } {
            vertex(v[0], v[1], 0.0, 1.0)
        }
    }
    [] fn glVertex3f(x: f32, y: f32, z: f32) {
        vertex(x, y, z, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 3 values.
    [unsafe] fn glVertex3fv(v: *const f32) {
        // SAFETY: 3 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<f32, 3>(v) } {
            vertex(v[0], v[1], v[2], 1.0)
        }
    }
    [] fn glVertex4f(x: f32, y: f32, z: f32, w: f32) {
        vertex(x, y, z, w)
    }
    /// # Safety
    /// `v` is null or points to 4 values.
    [unsafe] fn glVertex4fv(v: *const f32) {
        // SAFETY: 4 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<f32, 4>(v) } {
            vertex(v[0], v[1], v[2], v[3])
        }
    }
    [] fn glVertex2i(x: i32, y: i32) {
        vertex(x as f32, y as f32, 0.0, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 2 values.
    [unsafe] fn glVertex2iv(v: *const i32) {
        // SAFETY: 2 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i32, 2>(v) } {
            vertex(v[0] as f32, v[1] as f32, 0.0, 1.0)
        }
    }
    [] fn glVertex3i(x: i32, y: i32, z: i32) {
        vertex(x as f32, y as f32, z as f32, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 3 values.
    [unsafe] fn glVertex3iv(v: *const i32) {
        // SAFETY: 3 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i32, 3>(v) } {
            vertex(v[0] as f32, v[1] as f32, v[2] as f32, 1.0)
        }
    }
    [] fn glVertex4i(x: i32, y: i32, z: i32, w: i32) {
        vertex(x as f32, y as f32, z as f32, w as f32)
    }
    /// # Safety
    /// `v` is null or points to 4 values.
    [unsafe] fn glVertex4iv(v: *const i32) {
        // SAFETY: 4 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i32, 4>(v) } {
            vertex(v[0] as f32, v[1] as f32, v[2] as f32, v[3] as f32)
        }
    }
    [] fn glVertex2s(x: i16, y: i16) {
        vertex(x as f32, y as f32, 0.0, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 2 values.
    [unsafe] fn glVertex2sv(v: *const i16) {
        // SAFETY: 2 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i16, 2>(v) } {
            vertex(v[0] as f32, v[1] as f32, 0.0, 1.0)
        }
    }
    [] fn glVertex3s(x: i16, y: i16, z: i16) {
        vertex(x as f32, y as f32, z as f32, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 3 values.
    [unsafe] fn glVertex3sv(v: *const i16) {
        // SAFETY: 3 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i16, 3>(v) } {
            vertex(v[0] as f32, v[1] as f32, v[2] as f32, 1.0)
        }
    }
    [] fn glVertex4s(x: i16, y: i16, z: i16, w: i16) {
        vertex(x as f32, y as f32, z as f32, w as f32)
    }
    /// # Safety
    /// `v` is null or points to 4 values.
    [unsafe] fn glVertex4sv(v: *const i16) {
        // SAFETY: 4 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i16, 4>(v) } {
            vertex(v[0] as f32, v[1] as f32, v[2] as f32, v[3] as f32)
        }
    }
    [] fn glColor3b(r: i8, g: i8, b: i8) {
        color(r.norm(), g.norm(), b.norm(), 1.0)
    }
    /// # Safety
    /// `v` is null or points to 3 values.
    [unsafe] fn glColor3bv(v: *const i8) {
        // SAFETY: 3 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i8, 3>(v) } {
            color(v[0].norm(), v[1].norm(), v[2].norm(), 1.0)
        }
    }
    [] fn glColor4b(r: i8, g: i8, b: i8, a: i8) {
        color(r.norm(), g.norm(), b.norm(), a.norm())
    }
    /// # Safety
    /// `v` is null or points to 4 values.
    [unsafe] fn glColor4bv(v: *const i8) {
        // SAFETY: 4 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i8, 4>(v) } {
            color(v[0].norm(), v[1].norm(), v[2].norm(), v[3].norm())
        }
    }
    [] fn glColor3d(r: f64, g: f64, b: f64) {
        color(r.norm(), g.norm(), b.norm(), 1.0)
    }
    /// # Safety
    /// `v` is null or points to 3 values.
    [unsafe] fn glColor3dv(v: *const f64) {
        // SAFETY: 3 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<f64, 3>(v) } {
            color(v[0].norm(), v[1].norm(), v[2].norm(), 1.0)
        }
    }
    [] fn glColor4d(r: f64, g: f64, b: f64, a: f64) {
        color(r.norm(), g.norm(), b.norm(), a.norm())
    }
    /// # Safety
    /// `v` is null or points to 4 values.
    [unsafe] fn glColor4dv(v: *const f64) {
        // SAFETY: 4 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<f64, 4>(v) } {
            color(v[0].norm(), v[1].norm(), v[2].norm(), v[3].norm())
        }
    }
    [] fn glColor3f(r: f32, g: f32, b: f32) {
        color(r.norm(), g.norm(), b.norm(), 1.0)
    }
    /// # Safety
    /// `v` is null or points to 3 values.
    [unsafe] fn glColor3fv(v: *const f32) {
        // SAFETY: 3 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<f32, 3>(v) } {
            color(v[0].norm(), v[1].norm(), v[2].norm(), 1.0)
        }
    }
    [] fn glColor4f(r: f32, g: f32, b: f32, a: f32) {
        color(r.norm(), g.norm(), b.norm(), a.norm())
    }
    /// # Safety
    /// `v` is null or points to 4 values.
    [unsafe] fn glColor4fv(v: *const f32) {
        // SAFETY: 4 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<f32, 4>(v) } {
            color(v[0].norm(), v[1].norm(), v[2].norm(), v[3].norm())
        }
    }
    [] fn glColor3i(r: i32, g: i32, b: i32) {
        color(r.norm(), g.norm(), b.norm(), 1.0)
    }
    /// # Safety
    /// `v` is null or points to 3 values.
    [unsafe] fn glColor3iv(v: *const i32) {
        // SAFETY: 3 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i32, 3>(v) } {
            color(v[0].norm(), v[1].norm(), v[2].norm(), 1.0)
        }
    }
    [] fn glColor4i(r: i32, g: i32, b: i32, a: i32) {
        color(r.norm(), g.norm(), b.norm(), a.norm())
    }
    /// # Safety
    /// `v` is null or points to 4 values.
    [unsafe] fn glColor4iv(v: *const i32) {
        // SAFETY: 4 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i32, 4>(v) } {
            color(v[0].norm(), v[1].norm(), v[2].norm(), v[3].norm())
        }
    }
    [] fn glColor3s(r: i16, g: i16, b: i16) {
        color(r.norm(), g.norm(), b.norm(), 1.0)
    }
    /// # Safety
    /// `v` is null or points to 3 values.
    [unsafe] fn glColor3sv(v: *const i16) {
        // SAFETY: 3 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i16, 3>(v) } {
            color(v[0].norm(), v[1].norm(), v[2].norm(), 1.0)
        }
    }
    [] fn glColor4s(r: i16, g: i16, b: i16, a: i16) {
        color(r.norm(), g.norm(), b.norm(), a.norm())
    }
    /// # Safety
    /// `v` is null or points to 4 values.
    [unsafe] fn glColor4sv(v: *const i16) {
        // SAFETY: 4 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i16, 4>(v) } {
            color(v[0].norm(), v[1].norm(), v[2].norm(), v[3].norm())
        }
    }
    [] fn glColor3ub(r: u8, g: u8, b: u8) {
        color(r.norm(), g.norm(), b.norm(), 1.0)
    }
    /// # Safety
    /// `v` is null or points to 3 values.
    [unsafe] fn glColor3ubv(v: *const u8) {
        // SAFETY: 3 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<u8, 3>(v) } {
            color(v[0].norm(), v[1].norm(), v[2].norm(), 1.0)
        }
    }
    [] fn glColor4ub(r: u8, g: u8, b: u8, a: u8) {
        color(r.norm(), g.norm(), b.norm(), a.norm())
    }
    /// # Safety
    /// `v` is null or points to 4 values.
    [unsafe] fn glColor4ubv(v: *const u8) {
        // SAFETY: 4 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<u8, 4>(v) } {
            color(v[0].norm(), v[1].norm(), v[2].norm(), v[3].norm())
        }
    }
    [] fn glColor3ui(r: u32, g: u32, b: u32) {
        color(r.norm(), g.norm(), b.norm(), 1.0)
    }
    /// # Safety
    /// `v` is null or points to 3 values.
    [unsafe] fn glColor3uiv(v: *const u32) {
        // SAFETY: 3 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<u32, 3>(v) } {
            color(v[0].norm(), v[1].norm(), v[2].norm(), 1.0)
        }
    }
    [] fn glColor4ui(r: u32, g: u32, b: u32, a: u32) {
        color(r.norm(), g.norm(), b.norm(), a.norm())
    }
    /// # Safety
    /// `v` is null or points to 4 values.
    [unsafe] fn glColor4uiv(v: *const u32) {
        // SAFETY: 4 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<u32, 4>(v) } {
            color(v[0].norm(), v[1].norm(), v[2].norm(), v[3].norm())
        }
    }
    [] fn glColor3us(r: u16, g: u16, b: u16) {
        color(r.norm(), g.norm(), b.norm(), 1.0)
    }
    /// # Safety
    /// `v` is null or points to 3 values.
    [unsafe] fn glColor3usv(v: *const u16) {
        // SAFETY: 3 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<u16, 3>(v) } {
            color(v[0].norm(), v[1].norm(), v[2].norm(), 1.0)
        }
    }
    [] fn glColor4us(r: u16, g: u16, b: u16, a: u16) {
        color(r.norm(), g.norm(), b.norm(), a.norm())
    }
    /// # Safety
    /// `v` is null or points to 4 values.
    [unsafe] fn glColor4usv(v: *const u16) {
        // SAFETY: 4 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<u16, 4>(v) } {
            color(v[0].norm(), v[1].norm(), v[2].norm(), v[3].norm())
        }
    }
    [] fn glNormal3b(x: i8, y: i8, z: i8) {
        normal(x.norm(), y.norm(), z.norm())
    }
    /// # Safety
    /// `v` is null or points to 3 values.
    [unsafe] fn glNormal3bv(v: *const i8) {
        // SAFETY: 3 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i8, 3>(v) } {
            normal(v[0].norm(), v[1].norm(), v[2].norm())
        }
    }
    [] fn glNormal3d(x: f64, y: f64, z: f64) {
        normal(x.norm(), y.norm(), z.norm())
    }
    /// # Safety
    /// `v` is null or points to 3 values.
    [unsafe] fn glNormal3dv(v: *const f64) {
        // SAFETY: 3 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<f64, 3>(v) } {
            normal(v[0].norm(), v[1].norm(), v[2].norm())
        }
    }
    [] fn glNormal3f(x: f32, y: f32, z: f32) {
        normal(x.norm(), y.norm(), z.norm())
    }
    /// # Safety
    /// `v` is null or points to 3 values.
    [unsafe] fn glNormal3fv(v: *const f32) {
        // SAFETY: 3 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<f32, 3>(v) } {
            normal(v[0].norm(), v[1].norm(), v[2].norm())
        }
    }
    [] fn glNormal3i(x: i32, y: i32, z: i32) {
        normal(x.norm(), y.norm(), z.norm())
    }
    /// # Safety
    /// `v` is null or points to 3 values.
    [unsafe] fn glNormal3iv(v: *const i32) {
        // SAFETY: 3 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i32, 3>(v) } {
            normal(v[0].norm(), v[1].norm(), v[2].norm())
        }
    }
    [] fn glNormal3s(x: i16, y: i16, z: i16) {
        normal(x.norm(), y.norm(), z.norm())
    }
    /// # Safety
    /// `v` is null or points to 3 values.
    [unsafe] fn glNormal3sv(v: *const i16) {
        // SAFETY: 3 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i16, 3>(v) } {
            normal(v[0].norm(), v[1].norm(), v[2].norm())
        }
    }
    [] fn glTexCoord1d(s: f64) {
        tex_coord(s as f32, 0.0, 0.0, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 1 values.
    [unsafe] fn glTexCoord1dv(v: *const f64) {
        // SAFETY: 1 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<f64, 1>(v) } {
            tex_coord(v[0] as f32, 0.0, 0.0, 1.0)
        }
    }
    [] fn glTexCoord2d(s: f64, t: f64) {
        tex_coord(s as f32, t as f32, 0.0, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 2 values.
    [unsafe] fn glTexCoord2dv(v: *const f64) {
        // SAFETY: 2 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<f64, 2>(v) } {
            tex_coord(v[0] as f32, v[1] as f32, 0.0, 1.0)
        }
    }
    [] fn glTexCoord3d(s: f64, t: f64, r: f64) {
        tex_coord(s as f32, t as f32, r as f32, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 3 values.
    [unsafe] fn glTexCoord3dv(v: *const f64) {
        // SAFETY: 3 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<f64, 3>(v) } {
            tex_coord(v[0] as f32, v[1] as f32, v[2] as f32, 1.0)
        }
    }
    [] fn glTexCoord4d(s: f64, t: f64, r: f64, q: f64) {
        tex_coord(s as f32, t as f32, r as f32, q as f32)
    }
    /// # Safety
    /// `v` is null or points to 4 values.
    [unsafe] fn glTexCoord4dv(v: *const f64) {
        // SAFETY: 4 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<f64, 4>(v) } {
            tex_coord(v[0] as f32, v[1] as f32, v[2] as f32, v[3] as f32)
        }
    }
    [] fn glTexCoord1f(s: f32) {
        tex_coord(s, 0.0, 0.0, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 1 values.
    [unsafe] fn glTexCoord1fv(v: *const f32) {
        // SAFETY: 1 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<f32, 1>(v) } {
            tex_coord(v[0], 0.0, 0.0, 1.0)
        }
    }
    [] fn glTexCoord2f(s: f32, t: f32) {
        tex_coord(s, t, 0.0, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 2 values.
    [unsafe] fn glTexCoord2fv(v: *const f32) {
        // SAFETY: 2 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<f32, 2>(v) } {
            tex_coord(v[0], v[1], 0.0, 1.0)
        }
    }
    [] fn glTexCoord3f(s: f32, t: f32, r: f32) {
        tex_coord(s, t, r, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 3 values.
    [unsafe] fn glTexCoord3fv(v: *const f32) {
        // SAFETY: 3 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<f32, 3>(v) } {
            tex_coord(v[0], v[1], v[2], 1.0)
        }
    }
    [] fn glTexCoord4f(s: f32, t: f32, r: f32, q: f32) {
        tex_coord(s, t, r, q)
    }
    /// # Safety
    /// `v` is null or points to 4 values.
    [unsafe] fn glTexCoord4fv(v: *const f32) {
        // SAFETY: 4 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<f32, 4>(v) } {
            tex_coord(v[0], v[1], v[2], v[3])
        }
    }
    [] fn glTexCoord1i(s: i32) {
        tex_coord(s as f32, 0.0, 0.0, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 1 values.
    [unsafe] fn glTexCoord1iv(v: *const i32) {
        // SAFETY: 1 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i32, 1>(v) } {
            tex_coord(v[0] as f32, 0.0, 0.0, 1.0)
        }
    }
    [] fn glTexCoord2i(s: i32, t: i32) {
        tex_coord(s as f32, t as f32, 0.0, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 2 values.
    [unsafe] fn glTexCoord2iv(v: *const i32) {
        // SAFETY: 2 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i32, 2>(v) } {
            tex_coord(v[0] as f32, v[1] as f32, 0.0, 1.0)
        }
    }
    [] fn glTexCoord3i(s: i32, t: i32, r: i32) {
        tex_coord(s as f32, t as f32, r as f32, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 3 values.
    [unsafe] fn glTexCoord3iv(v: *const i32) {
        // SAFETY: 3 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i32, 3>(v) } {
            tex_coord(v[0] as f32, v[1] as f32, v[2] as f32, 1.0)
        }
    }
    [] fn glTexCoord4i(s: i32, t: i32, r: i32, q: i32) {
        tex_coord(s as f32, t as f32, r as f32, q as f32)
    }
    /// # Safety
    /// `v` is null or points to 4 values.
    [unsafe] fn glTexCoord4iv(v: *const i32) {
        // SAFETY: 4 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i32, 4>(v) } {
            tex_coord(v[0] as f32, v[1] as f32, v[2] as f32, v[3] as f32)
        }
    }
    [] fn glTexCoord1s(s: i16) {
        tex_coord(s as f32, 0.0, 0.0, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 1 values.
    [unsafe] fn glTexCoord1sv(v: *const i16) {
        // SAFETY: 1 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i16, 1>(v) } {
            tex_coord(v[0] as f32, 0.0, 0.0, 1.0)
        }
    }
    [] fn glTexCoord2s(s: i16, t: i16) {
        tex_coord(s as f32, t as f32, 0.0, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 2 values.
    [unsafe] fn glTexCoord2sv(v: *const i16) {
        // SAFETY: 2 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i16, 2>(v) } {
            tex_coord(v[0] as f32, v[1] as f32, 0.0, 1.0)
        }
    }
    [] fn glTexCoord3s(s: i16, t: i16, r: i16) {
        tex_coord(s as f32, t as f32, r as f32, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 3 values.
    [unsafe] fn glTexCoord3sv(v: *const i16) {
        // SAFETY: 3 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i16, 3>(v) } {
            tex_coord(v[0] as f32, v[1] as f32, v[2] as f32, 1.0)
        }
    }
    [] fn glTexCoord4s(s: i16, t: i16, r: i16, q: i16) {
        tex_coord(s as f32, t as f32, r as f32, q as f32)
    }
    /// # Safety
    /// `v` is null or points to 4 values.
    [unsafe] fn glTexCoord4sv(v: *const i16) {
        // SAFETY: 4 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i16, 4>(v) } {
            tex_coord(v[0] as f32, v[1] as f32, v[2] as f32, v[3] as f32)
        }
    }
    [] fn glRectd(x1: f64, y1: f64, x2: f64, y2: f64) {
        rect(x1 as f32, y1 as f32, x2 as f32, y2 as f32)
    }
    /// # Safety
    /// `v1` and `v2` are null or point to 2 values each.
    [unsafe] fn glRectdv(v1: *const f64, v2: *const f64) {
        // SAFETY: 2 readable values each by GL's contract; null is ignored.
        if let (Some(a), Some(b)) = unsafe { (read::<f64, 2>(v1), read::<f64, 2>(v2)) } {
            rect(a[0] as f32, a[1] as f32, b[0] as f32, b[1] as f32)
        }
    }
    [] fn glRectf(x1: f32, y1: f32, x2: f32, y2: f32) {
        rect(x1, y1, x2, y2)
    }
    /// # Safety
    /// `v1` and `v2` are null or point to 2 values each.
    [unsafe] fn glRectfv(v1: *const f32, v2: *const f32) {
        // SAFETY: 2 readable values each by GL's contract; null is ignored.
        if let (Some(a), Some(b)) = unsafe { (read::<f32, 2>(v1), read::<f32, 2>(v2)) } {
            rect(a[0], a[1], b[0], b[1])
        }
    }
    [] fn glRecti(x1: i32, y1: i32, x2: i32, y2: i32) {
        rect(x1 as f32, y1 as f32, x2 as f32, y2 as f32)
    }
    /// # Safety
    /// `v1` and `v2` are null or point to 2 values each.
    [unsafe] fn glRectiv(v1: *const i32, v2: *const i32) {
        // SAFETY: 2 readable values each by GL's contract; null is ignored.
        if let (Some(a), Some(b)) = unsafe { (read::<i32, 2>(v1), read::<i32, 2>(v2)) } {
            rect(a[0] as f32, a[1] as f32, b[0] as f32, b[1] as f32)
        }
    }
    [] fn glRects(x1: i16, y1: i16, x2: i16, y2: i16) {
        rect(x1 as f32, y1 as f32, x2 as f32, y2 as f32)
    }
    /// # Safety
    /// `v1` and `v2` are null or point to 2 values each.
    [unsafe] fn glRectsv(v1: *const i16, v2: *const i16) {
        // SAFETY: 2 readable values each by GL's contract; null is ignored.
        if let (Some(a), Some(b)) = unsafe { (read::<i16, 2>(v1), read::<i16, 2>(v2)) } {
            rect(a[0] as f32, a[1] as f32, b[0] as f32, b[1] as f32)
        }
    }
}
