//! `GL_EXT_vertex_array`: the pointer functions of the extension GL 1.1
//! made core, with the element `count` the core ones dropped (ignored, as
//! Mesa's `_mesa_VertexPointerEXT` … in `main/varray.c` ignore it).
//! `glArrayElementEXT`, `glDrawArraysEXT` and `glGetPointervEXT` have the
//! core functions' signatures and resolve to them (`extensions.rs`).

use super::*;
use crate::consts::GLenum;
use std::ffi::c_void;

exports! {
    /// # Safety
    /// As `glVertexPointer`.
    [unsafe] fn glVertexPointerEXT(size: i32, ty: GLenum, stride: i32, _count: i32, ptr: *const c_void) {
        // SAFETY: the same contract.
        unsafe { glVertexPointer(size, ty, stride, ptr) }
    }
    /// # Safety
    /// As `glNormalPointer`.
    [unsafe] fn glNormalPointerEXT(ty: GLenum, stride: i32, _count: i32, ptr: *const c_void) {
        // SAFETY: the same contract.
        unsafe { glNormalPointer(ty, stride, ptr) }
    }
    /// # Safety
    /// As `glColorPointer`.
    [unsafe] fn glColorPointerEXT(size: i32, ty: GLenum, stride: i32, _count: i32, ptr: *const c_void) {
        // SAFETY: the same contract.
        unsafe { glColorPointer(size, ty, stride, ptr) }
    }
    /// # Safety
    /// As `glIndexPointer`.
    [unsafe] fn glIndexPointerEXT(ty: GLenum, stride: i32, _count: i32, ptr: *const c_void) {
        // SAFETY: the same contract.
        unsafe { glIndexPointer(ty, stride, ptr) }
    }
    /// # Safety
    /// As `glTexCoordPointer`.
    [unsafe] fn glTexCoordPointerEXT(size: i32, ty: GLenum, stride: i32, _count: i32, ptr: *const c_void) {
        // SAFETY: the same contract.
        unsafe { glTexCoordPointer(size, ty, stride, ptr) }
    }
    /// # Safety
    /// As `glEdgeFlagPointer`.
    [unsafe] fn glEdgeFlagPointerEXT(stride: i32, _count: i32, ptr: *const u8) {
        // SAFETY: the same contract.
        unsafe { glEdgeFlagPointer(stride, ptr.cast()) }
    }
}
