//! Client vertex arrays: the pointers, `glDrawArrays`, `glDrawElements`,
//! `glArrayElement`. The caller's arrays are read into f32 arrays for softgl
//! at each draw; normals and texture coordinates are accepted and, without
//! lighting and texturing, have no effect on the image.

use super::{enums, missing, os};
use crate::consts::*;
use crate::state::{with_gl, ClientArray, OsContext};
use softgl::{AttribArray, Context, GlError, GlResult, VertexArrays};
use std::ffi::c_void;

fn type_size(ty: GLenum) -> Option<usize> {
    Some(match ty {
        GL_BYTE | GL_UNSIGNED_BYTE => 1,
        GL_SHORT | GL_UNSIGNED_SHORT => 2,
        GL_INT | GL_UNSIGNED_INT | GL_FLOAT => 4,
        GL_DOUBLE => 8,
        _ => return None,
    })
}

/// Element `i` of `a` as floats, integer colours normalised when `normalize`.
///
/// # Safety
/// `a.ptr` holds element `i` (GL's contract for enabled client arrays).
unsafe fn fetch(a: &ClientArray, i: usize, normalize: bool, out: &mut Vec<f32>) {
    let size = type_size(a.ty).unwrap_or(4);
    let n = a.size as usize;
    let stride = if a.stride > 0 { a.stride as usize } else { n * size };
    // SAFETY: element `i` lies at `i * stride` in the caller's array.
    let base = unsafe { a.ptr.add(i * stride) };
    for c in 0..n {
        // SAFETY: component `c` of element `i`, read unaligned.
        let p = unsafe { base.add(c * size) };
        // SAFETY: `p` points at a value of the array's type.
        let v = unsafe {
            match a.ty {
                GL_BYTE => {
                    let v = f32::from(p.cast::<i8>().read_unaligned());
                    if normalize {
                        (2.0 * v + 1.0) / 255.0
                    } else {
                        v
                    }
                }
                GL_UNSIGNED_BYTE => {
                    let v = f32::from(p.read_unaligned());
                    if normalize {
                        v / 255.0
                    } else {
                        v
                    }
                }
                GL_SHORT => {
                    let v = f32::from(p.cast::<i16>().read_unaligned());
                    if normalize {
                        (2.0 * v + 1.0) / 65535.0
                    } else {
                        v
                    }
                }
                GL_UNSIGNED_SHORT => {
                    let v = f32::from(p.cast::<u16>().read_unaligned());
                    if normalize {
                        v / 65535.0
                    } else {
                        v
                    }
                }
                GL_INT => {
                    let v = f64::from(p.cast::<i32>().read_unaligned());
                    (if normalize { (2.0 * v + 1.0) / 4294967295.0 } else { v }) as f32
                }
                GL_UNSIGNED_INT => {
                    let v = f64::from(p.cast::<u32>().read_unaligned());
                    (if normalize { v / 4294967295.0 } else { v }) as f32
                }
                GL_DOUBLE => p.cast::<f64>().read_unaligned() as f32,
                _ => p.cast::<f32>().read_unaligned(),
            }
        };
        out.push(v);
    }
}

/// Draws the vertices `indices` names from the enabled arrays.
fn draw(os: &OsContext, gl: &mut Context, mode: GLenum, indices: &mut dyn Iterator<Item = usize>) -> GlResult {
    let mode = enums::primitive(mode)?;
    if gl.inside_begin() {
        return Err(GlError::InvalidOperation);
    }
    if !os.vertex.enabled || os.vertex.ptr.is_null() {
        return Ok(());
    }
    let color = (os.color.enabled && !os.color.ptr.is_null()).then_some(&os.color);
    let (mut pos, mut col) = (Vec::new(), Vec::new());
    let mut count = 0;
    for i in indices {
        // SAFETY: the enabled arrays hold every element the draw names (GL's contract).
        unsafe {
            fetch(&os.vertex, i, false, &mut pos);
            if let Some(c) = color {
                fetch(c, i, true, &mut col);
            }
        }
        count += 1;
    }
    let arrays = VertexArrays {
        position: AttribArray::new(os.vertex.size as usize, &pos),
        color: color.map(|c| AttribArray::new(c.size as usize, &col)),
    };
    gl.draw_arrays(mode, 0, count, &arrays)
}

/// Sets a client array pointer after checking its arguments.
fn pointer(
    which: fn(&mut OsContext) -> &mut ClientArray,
    sizes: &[i32],
    size: i32,
    ty: GLenum,
    types: &[GLenum],
    stride: i32,
    ptr: *const c_void,
) {
    os(|os, _| {
        if !types.contains(&ty) {
            return Err(GlError::InvalidEnum);
        }
        if !sizes.contains(&size) || stride < 0 {
            return Err(GlError::InvalidValue);
        }
        let a = which(os);
        (a.size, a.ty, a.stride, a.ptr) = (size, ty, stride, ptr.cast());
        Ok(())
    })
}

fn client_state(array: GLenum, on: bool) {
    os(|os, _| {
        let a = match array {
            GL_VERTEX_ARRAY => &mut os.vertex,
            GL_COLOR_ARRAY => &mut os.color,
            GL_NORMAL_ARRAY => &mut os.normal,
            GL_TEXTURE_COORD_ARRAY => &mut os.tex_coord,
            // Colour-index and edge-flag arrays do not exist in softgl yet.
            GL_INDEX_ARRAY | GL_EDGE_FLAG_ARRAY if on => return Err(GlError::InvalidOperation),
            GL_INDEX_ARRAY | GL_EDGE_FLAG_ARRAY => return Ok(()),
            _ => return Err(GlError::InvalidEnum),
        };
        a.enabled = on;
        Ok(())
    })
}

const ALL_TYPES: [GLenum; 4] = [GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE];
const COLOR_TYPES: [GLenum; 8] = [
    GL_BYTE,
    GL_UNSIGNED_BYTE,
    GL_SHORT,
    GL_UNSIGNED_SHORT,
    GL_INT,
    GL_UNSIGNED_INT,
    GL_FLOAT,
    GL_DOUBLE,
];
const NORMAL_TYPES: [GLenum; 5] = [GL_BYTE, GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE];

exports! {
    /// # Safety
    /// `ptr` stays valid while drawing reads it (GL's contract).
    [unsafe] fn glVertexPointer(size: i32, ty: GLenum, stride: i32, ptr: *const c_void) {
        pointer(|o| &mut o.vertex, &[2, 3, 4], size, ty, &ALL_TYPES, stride, ptr)
    }
    /// # Safety
    /// `ptr` stays valid while drawing reads it (GL's contract).
    [unsafe] fn glColorPointer(size: i32, ty: GLenum, stride: i32, ptr: *const c_void) {
        pointer(|o| &mut o.color, &[3, 4], size, ty, &COLOR_TYPES, stride, ptr)
    }
    /// # Safety
    /// `ptr` stays valid while drawing reads it (GL's contract).
    [unsafe] fn glNormalPointer(ty: GLenum, stride: i32, ptr: *const c_void) {
        pointer(|o| &mut o.normal, &[3], 3, ty, &NORMAL_TYPES, stride, ptr)
    }
    /// # Safety
    /// `ptr` stays valid while drawing reads it (GL's contract).
    [unsafe] fn glTexCoordPointer(size: i32, ty: GLenum, stride: i32, ptr: *const c_void) {
        pointer(|o| &mut o.tex_coord, &[1, 2, 3, 4], size, ty, &ALL_TYPES, stride, ptr)
    }
    [] fn glEnableClientState(array: GLenum) {
        client_state(array, true)
    }
    [] fn glDisableClientState(array: GLenum) {
        client_state(array, false)
    }
    [] fn glDrawArrays(mode: GLenum, first: i32, count: i32) {
        os(|os, gl| {
            if first < 0 || count < 0 {
                enums::primitive(mode)?;
                return Err(GlError::InvalidValue);
            }
            draw(os, gl, mode, &mut (first as usize..first as usize + count as usize))
        })
    }
    /// # Safety
    /// `indices` points to `count` indices of `ty` (GL's contract).
    [unsafe] fn glDrawElements(mode: GLenum, count: i32, ty: GLenum, indices: *const c_void) {
        os(|os, gl| {
            enums::primitive(mode)?;
            if count < 0 {
                return Err(GlError::InvalidValue);
            }
            let size = match ty {
                GL_UNSIGNED_BYTE => 1,
                GL_UNSIGNED_SHORT => 2,
                GL_UNSIGNED_INT => 4,
                _ => return Err(GlError::InvalidEnum),
            };
            if indices.is_null() {
                return if count == 0 { Ok(()) } else { Err(GlError::InvalidValue) };
            }
            let p = indices.cast::<u8>();
            let mut it = (0..count as usize).map(|k| {
                // SAFETY: `count` indices of `ty` at `indices`, by GL's contract.
                unsafe {
                    let q = p.add(k * size);
                    match size {
                        1 => usize::from(q.read()),
                        2 => usize::from(q.cast::<u16>().read_unaligned()),
                        _ => q.cast::<u32>().read_unaligned() as usize,
                    }
                }
            });
            draw(os, gl, mode, &mut it)
        })
    }
    /// GL 1.2's `glDrawElements` with an index range hint: indices outside
    /// `start..=end` are drawn all the same (GL leaves them undefined).
    ///
    /// # Safety
    /// `indices` points to `count` indices of `ty` (GL's contract).
    [unsafe] fn glDrawRangeElements(mode: GLenum, start: u32, end: u32, count: i32, ty: GLenum, indices: *const c_void) {
        if end < start {
            return super::checked(|_| Err(GlError::InvalidValue));
        }
        // SAFETY: the same contract as glDrawElements, passed on.
        unsafe { glDrawElements(mode, count, ty, indices) }
    }
    [] fn glArrayElement(i: i32) {
        with_gl((), |os, gl| {
            if i < 0 {
                return gl.record_error(GlError::InvalidValue);
            }
            let i = i as usize;
            let mut v = Vec::with_capacity(4);
            // SAFETY: the enabled arrays hold element `i` (GL's contract).
            unsafe {
                if os.color.enabled && !os.color.ptr.is_null() {
                    fetch(&os.color, i, true, &mut v);
                    gl.color4(v[0], v[1], v[2], v.get(3).copied().unwrap_or(1.0));
                    v.clear();
                }
                if os.normal.enabled && !os.normal.ptr.is_null() {
                    fetch(&os.normal, i, true, &mut v);
                    gl.normal3(v[0], v[1], v[2]);
                    v.clear();
                }
                if os.tex_coord.enabled && !os.tex_coord.ptr.is_null() {
                    fetch(&os.tex_coord, i, false, &mut v);
                    v.resize(4, 0.0);
                    if os.tex_coord.size < 4 {
                        v[3] = 1.0;
                    }
                    gl.tex_coord4(v[0], v[1], v[2], v[3]);
                    v.clear();
                }
                if os.vertex.enabled && !os.vertex.ptr.is_null() {
                    fetch(&os.vertex, i, false, &mut v);
                    v.resize(4, 0.0);
                    if os.vertex.size < 4 {
                        v[3] = 1.0;
                    }
                    gl.vertex4(v[0], v[1], v[2], v[3]);
                }
            }
        })
    }
    /// # Safety
    /// `params` is null or writable.
    [unsafe] fn glGetPointerv(pname: GLenum, params: *mut *mut c_void) {
        os(|os, _| {
            let p = match pname {
                GL_VERTEX_ARRAY_POINTER => os.vertex.ptr,
                GL_COLOR_ARRAY_POINTER => os.color.ptr,
                GL_NORMAL_ARRAY_POINTER => os.normal.ptr,
                GL_TEXTURE_COORD_ARRAY_POINTER => os.tex_coord.ptr,
                _ => return Err(GlError::InvalidEnum),
            };
            if !params.is_null() {
                // SAFETY: non-null and writable by GL's contract.
                unsafe { *params = p.cast_mut().cast() };
            }
            Ok(())
        })
    }
    /// Not in softgl yet: `GL_INVALID_OPERATION`.
    ///
    /// # Safety
    /// Reads nothing.
    [unsafe] fn glInterleavedArrays(_format: GLenum, _stride: i32, _ptr: *const c_void) {
        missing()
    }
}
