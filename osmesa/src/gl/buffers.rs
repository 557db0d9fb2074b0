//! Buffer objects (GL 1.5 and `ARB_vertex_buffer_object`'s names) over
//! [`softgl::BufferStore`]: names, bindings, data, mapping, queries, and
//! `glMultiDrawArrays`/`glMultiDrawElements` (GL 1.4, `EXT_multi_draw_arrays`).
//! None is compiled into a display list (GL 1.5 §5.4): each runs at once.
//! The array pointers that name a buffer are `gl::arrays`'.

use super::enums::decode;
use super::get::Val;
use super::{now, outside};
use crate::consts::*;
use crate::gl_state::GlState;
use crate::state::with_gl;
use softgl::{BufferAccess, BufferParamName, BufferTarget, BufferUsage, Context, GlError, GlResult};
use std::ffi::c_void;

/// `glGetBufferPointerv`'s one name.
const GL_BUFFER_MAP_POINTER: GLenum = 0x88BD;

/// The `GL_ARRAY_BUFFER` and `GL_ELEMENT_ARRAY_BUFFER` bindings, as
/// `glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT)` saves them.
pub(super) fn bindings(gl: &Context) -> (u32, u32) {
    let b = gl.buffers();
    (b.binding(BufferTarget::Array), b.binding(BufferTarget::ElementArray))
}

/// Puts back what [`bindings`] saved, after the arrays. A buffer deleted
/// since is not made again: its bindings (and the arrays naming it) revert to 0.
pub(super) fn restore_bindings(os: &mut GlState, gl: &mut Context, (array, element): (u32, u32)) {
    let b = gl.buffers_mut();
    for (t, name) in [(BufferTarget::Array, array), (BufferTarget::ElementArray, element)] {
        b.bind(t, if b.is_buffer(name) { name } else { 0 });
    }
    for a in os.all_arrays_mut() {
        if a.buffer != 0 && !b.is_buffer(a.buffer) {
            (a.buffer, a.ptr) = (0, std::ptr::null());
        }
    }
}

/// The buffer bindings `glGet*` answers: `GL_ARRAY_BUFFER_BINDING`,
/// `GL_ELEMENT_ARRAY_BUFFER_BINDING` and each array's `*_ARRAY_BUFFER_BINDING`.
pub(super) fn value(os: &GlState, gl: &Context, pname: GLenum) -> Option<Val> {
    let name = match pname {
        0x8894 => gl.buffers().binding(BufferTarget::Array),
        0x8895 => gl.buffers().binding(BufferTarget::ElementArray),
        0x8896 => os.vertex.buffer,
        0x8897 => os.normal.buffer,
        0x8898 => os.color.buffer,
        0x8899 => os.index.buffer,
        0x889A => os.tex_coord().buffer,
        0x889B => os.edge_flag.buffer,
        0x889C => os.secondary.buffer,
        0x889D => os.fog_coord.buffer,
        _ => return None,
    };
    Some(Val::I(vec![name.into()]))
}

/// Runs `f` on the buffer state, outside `glBegin`/`glEnd`, returning
/// `fallback` after an error.
fn buffers<T: Copy>(fallback: T, f: impl FnOnce(&mut GlState, &mut Context) -> GlResult<T>) -> T {
    with_gl(None, |os, gl| match outside(gl).and_then(|()| f(os, gl)) {
        Ok(v) => Some(v),
        Err(e) => {
            gl.record_error(e);
            None
        }
    })
    .unwrap_or(fallback)
}

/// `size` bytes at `ptr` (none when `size` is 0).
///
/// # Safety
/// `ptr` is readable for `size` bytes when `size` > 0 (GL's contract).
unsafe fn bytes<'a>(ptr: *const c_void, size: usize) -> &'a [u8] {
    if size == 0 || ptr.is_null() {
        return &[];
    }
    // SAFETY: readable for `size` bytes, by the caller's contract.
    unsafe { std::slice::from_raw_parts(ptr.cast(), size) }
}

fn non_negative(v: isize) -> GlResult<usize> {
    usize::try_from(v).map_err(|_| GlError::InvalidValue)
}

/// `glDeleteBuffers` for one context: the store unbinds the targets; the
/// arrays that name a deleted buffer revert to no array (pointer null), so
/// that their offsets are never read as addresses.
fn delete(os: &mut GlState, gl: &mut Context, names: &[u32]) {
    gl.buffers_mut().delete(names);
    for a in os.all_arrays_mut() {
        if a.buffer != 0 && names.contains(&a.buffer) {
            (a.buffer, a.ptr) = (0, std::ptr::null());
        }
    }
}

exports! {
    /// # Safety
    /// `names` has room for `n` names.
    [unsafe] fn glGenBuffers(n: i32, names: *mut u32) {
        buffers((), |_, gl| {
            let n = usize::try_from(n).map_err(|_| GlError::InvalidValue)?;
            let new = gl.buffers_mut().gen(n).ok_or(GlError::OutOfMemory)?;
            if !names.is_null() {
                // SAFETY: room for `n` names, by GL's contract.
                unsafe { std::ptr::copy_nonoverlapping(new.as_ptr(), names, n) };
            }
            Ok(())
        })
    }
    /// # Safety
    /// `names` holds `n` names.
    [unsafe] fn glDeleteBuffers(n: i32, names: *const u32) {
        buffers((), |os, gl| {
            let n = usize::try_from(n).map_err(|_| GlError::InvalidValue)?;
            if names.is_null() || n == 0 {
                return Ok(());
            }
            // SAFETY: `n` names, by GL's contract.
            let names = unsafe { std::slice::from_raw_parts(names, n) };
            delete(os, gl, names);
            Ok(())
        })
    }
    [] fn glIsBuffer(name: u32) -> u8 {
        buffers(0, |_, gl| Ok(u8::from(gl.buffers().is_buffer(name))))
    }
    [] fn glBindBuffer(target: GLenum, name: u32) {
        buffers((), |_, gl| {
            let target = decode::<BufferTarget>(target)?;
            gl.buffers_mut().bind(target, name);
            Ok(())
        })
    }
    /// # Safety
    /// `data` is null or readable for `size` bytes.
    [unsafe] fn glBufferData(target: GLenum, size: isize, data: *const c_void, usage: GLenum) {
        buffers((), |_, gl| {
            let target = decode::<BufferTarget>(target)?;
            gl.buffers().bound(target)?;
            let size = non_negative(size)?;
            let usage = decode::<BufferUsage>(usage)?;
            // SAFETY: readable for `size` bytes when not null (GL's contract).
            let data = (!data.is_null()).then(|| unsafe { bytes(data, size) });
            gl.buffers_mut().data(target, size, data, usage)
        })
    }
    /// # Safety
    /// `data` is readable for `size` bytes.
    [unsafe] fn glBufferSubData(target: GLenum, offset: isize, size: isize, data: *const c_void) {
        buffers((), |_, gl| {
            let target = decode::<BufferTarget>(target)?;
            gl.buffers().bound(target)?;
            let (offset, size) = (non_negative(offset)?, non_negative(size)?);
            if size > 0 && data.is_null() {
                return Err(GlError::InvalidValue);
            }
            // SAFETY: readable for `size` bytes (GL's contract).
            gl.buffers_mut().sub_data(target, offset, unsafe { bytes(data, size) })
        })
    }
    /// # Safety
    /// `data` is writable for `size` bytes.
    [unsafe] fn glGetBufferSubData(target: GLenum, offset: isize, size: isize, data: *mut c_void) {
        buffers((), |_, gl| {
            let target = decode::<BufferTarget>(target)?;
            gl.buffers().bound(target)?;
            let (offset, size) = (non_negative(offset)?, non_negative(size)?);
            let src = gl.buffers().get_sub_data(target, offset, size)?;
            if !data.is_null() {
                // SAFETY: writable for `size` bytes (GL's contract).
                unsafe { std::ptr::copy_nonoverlapping(src.as_ptr(), data.cast::<u8>(), src.len()) };
            }
            Ok(())
        })
    }
    /// The bound buffer's data store until `glUnmapBuffer` (or a
    /// `glBufferData`/`glDeleteBuffers` of it); `NULL` after an error.
    [] fn glMapBuffer(target: GLenum, access: GLenum) -> *mut c_void {
        buffers(std::ptr::null_mut(), |_, gl| {
            let target = decode::<BufferTarget>(target)?;
            let access = decode::<BufferAccess>(access)?;
            Ok(gl.buffers_mut().map(target, access)?.as_mut_ptr().cast())
        })
    }
    [] fn glUnmapBuffer(target: GLenum) -> u8 {
        buffers(0, |_, gl| {
            let target = decode::<BufferTarget>(target)?;
            Ok(u8::from(gl.buffers_mut().unmap(target)?))
        })
    }
    /// # Safety
    /// `params` is null or has room for one value.
    [unsafe] fn glGetBufferParameteriv(target: GLenum, pname: GLenum, params: *mut i32) {
        buffers((), |_, gl| {
            let target = decode::<BufferTarget>(target)?;
            let pname = decode::<BufferParamName>(pname)?;
            let v = gl.buffers().bound(target)?.param(pname);
            if !params.is_null() {
                // SAFETY: room for one value (GL's contract).
                unsafe { *params = v.clamp(i32::MIN.into(), i32::MAX.into()) as i32 };
            }
            Ok(())
        })
    }
    /// # Safety
    /// `params` is null or has room for one pointer.
    [unsafe] fn glGetBufferPointerv(target: GLenum, pname: GLenum, params: *mut *mut c_void) {
        buffers((), |_, gl| {
            let target = decode::<BufferTarget>(target)?;
            if pname != GL_BUFFER_MAP_POINTER {
                return Err(GlError::InvalidEnum);
            }
            let p = match gl.buffers_mut().mapping(target)? {
                Some(m) => m.as_mut_ptr().cast(),
                None => std::ptr::null_mut(),
            };
            if !params.is_null() {
                // SAFETY: room for one pointer (GL's contract).
                unsafe { *params = p };
            }
            Ok(())
        })
    }
    /// # Safety
    /// As [`glGenBuffers`].
    [unsafe] fn glGenBuffersARB(n: i32, names: *mut u32) {
        // SAFETY: the same contract.
        unsafe { glGenBuffers(n, names) }
    }
    /// # Safety
    /// As [`glDeleteBuffers`].
    [unsafe] fn glDeleteBuffersARB(n: i32, names: *const u32) {
        // SAFETY: the same contract.
        unsafe { glDeleteBuffers(n, names) }
    }
    [] fn glIsBufferARB(name: u32) -> u8 {
        glIsBuffer(name)
    }
    [] fn glBindBufferARB(target: GLenum, name: u32) {
        glBindBuffer(target, name)
    }
    /// # Safety
    /// As [`glBufferData`].
    [unsafe] fn glBufferDataARB(target: GLenum, size: isize, data: *const c_void, usage: GLenum) {
        // SAFETY: the same contract.
        unsafe { glBufferData(target, size, data, usage) }
    }
    /// # Safety
    /// As [`glBufferSubData`].
    [unsafe] fn glBufferSubDataARB(target: GLenum, offset: isize, size: isize, data: *const c_void) {
        // SAFETY: the same contract.
        unsafe { glBufferSubData(target, offset, size, data) }
    }
    /// # Safety
    /// As [`glGetBufferSubData`].
    [unsafe] fn glGetBufferSubDataARB(target: GLenum, offset: isize, size: isize, data: *mut c_void) {
        // SAFETY: the same contract.
        unsafe { glGetBufferSubData(target, offset, size, data) }
    }
    [] fn glMapBufferARB(target: GLenum, access: GLenum) -> *mut c_void {
        glMapBuffer(target, access)
    }
    [] fn glUnmapBufferARB(target: GLenum) -> u8 {
        glUnmapBuffer(target)
    }
    /// # Safety
    /// As [`glGetBufferParameteriv`].
    [unsafe] fn glGetBufferParameterivARB(target: GLenum, pname: GLenum, params: *mut i32) {
        // SAFETY: the same contract.
        unsafe { glGetBufferParameteriv(target, pname, params) }
    }
    /// # Safety
    /// As [`glGetBufferPointerv`].
    [unsafe] fn glGetBufferPointervARB(target: GLenum, pname: GLenum, params: *mut *mut c_void) {
        // SAFETY: the same contract.
        unsafe { glGetBufferPointerv(target, pname, params) }
    }
    /// `glDrawArrays` for each of `primcount` (first, count) pairs.
    ///
    /// # Safety
    /// `first` and `count` hold `primcount` values.
    [unsafe] fn glMultiDrawArrays(mode: GLenum, first: *const i32, count: *const i32, primcount: i32) {
        if primcount < 0 {
            return now(|_, _| Err(GlError::InvalidValue));
        }
        if primcount == 0 || first.is_null() || count.is_null() {
            return;
        }
        // SAFETY: `primcount` values in `count` (GL's contract).
        let counts = unsafe { std::slice::from_raw_parts(count, primcount as usize) };
        // Mesa's `_mesa_validate_MultiDrawArrays`: the mode, then every
        // count, before anything is drawn (a negative one draws nothing).
        if let Some(e) = multi_draw_error(mode, None, counts) {
            return now(|_, _| Err(e));
        }
        for k in 0..primcount as usize {
            // SAFETY: `primcount` values in each array (GL's contract).
            let (f, c) = unsafe { (first.add(k).read(), count.add(k).read()) };
            super::arrays::glDrawArrays(mode, f, c);
        }
    }
    /// `glDrawElements` for each of `primcount` (count, indices) pairs.
    ///
    /// # Safety
    /// `count` and `indices` hold `primcount` values; each `indices[k]` is
    /// as `glDrawElements`' `indices`.
    [unsafe] fn glMultiDrawElements(mode: GLenum, count: *const i32, ty: GLenum, indices: *const *const c_void, primcount: i32) {
        if primcount < 0 {
            return now(|_, _| Err(GlError::InvalidValue));
        }
        if primcount == 0 || count.is_null() || indices.is_null() {
            return;
        }
        // SAFETY: `primcount` values in `count` (GL's contract).
        let counts = unsafe { std::slice::from_raw_parts(count, primcount as usize) };
        // Mesa's `_mesa_validate_MultiDrawElements`: mode, type, then every count.
        if let Some(e) = multi_draw_error(mode, Some(ty), counts) {
            return now(|_, _| Err(e));
        }
        for k in 0..primcount as usize {
            // SAFETY: `primcount` values in each array; each draw as glDrawElements (GL's contract).
            unsafe { super::arrays::glDrawElements(mode, count.add(k).read(), ty, indices.add(k).read()) };
        }
    }
    /// # Safety
    /// As [`glMultiDrawArrays`].
    [unsafe] fn glMultiDrawArraysEXT(mode: GLenum, first: *const i32, count: *const i32, primcount: i32) {
        // SAFETY: the same contract.
        unsafe { glMultiDrawArrays(mode, first, count, primcount) }
    }
    /// # Safety
    /// As [`glMultiDrawElements`].
    [unsafe] fn glMultiDrawElementsEXT(mode: GLenum, count: *const i32, ty: GLenum, indices: *const *const c_void, primcount: i32) {
        // SAFETY: the same contract.
        unsafe { glMultiDrawElements(mode, count, ty, indices, primcount) }
    }
}

/// The error of a `glMultiDraw*` call before it draws anything, in Mesa's
/// order (`main/draw.c`): a mode that is no primitive `GL_INVALID_ENUM`, an
/// index type that is none (elements) `GL_INVALID_ENUM`, then any negative
/// count `GL_INVALID_VALUE` (the whole call is ignored, GL 4.5 §2.3.1).
fn multi_draw_error(mode: GLenum, ty: Option<GLenum>, counts: &[i32]) -> Option<GlError> {
    const GL_POLYGON: GLenum = 0x0009;
    const INDEX_TYPES: [GLenum; 3] = [0x1401, 0x1403, 0x1405]; // UNSIGNED_BYTE, _SHORT, _INT
    if mode > GL_POLYGON || ty.is_some_and(|t| !INDEX_TYPES.contains(&t)) {
        return Some(GlError::InvalidEnum);
    }
    counts.iter().any(|&c| c < 0).then_some(GlError::InvalidValue)
}
