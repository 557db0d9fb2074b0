//! Entry points of GL 1.x that softgl does not implement yet. Each is
//! exported (so that GLU and PyOpenGL resolve it here, not in another GL
//! library) and records `GL_INVALID_OPERATION` when it runs: compiled into a
//! display list like the command it stands for, or at once for the commands
//! GL never compiles (queries, client arrays). None reads
//! or writes through its pointers, so none is `unsafe`.
//! The README lists them by group.

use super::{missing, missing_now};
use crate::consts::*;
use std::ffi::c_void;

exports! {
    /// Raster position and pixel rectangles (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glPixelTransferf(_pname: GLenum, _param: f32) {
        missing()
    }
    /// Raster position and pixel rectangles (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glPixelTransferi(_pname: GLenum, _param: i32) {
        missing()
    }
    /// Stipple (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glLineStipple(_factor: i32, _pattern: u16) {
        missing()
    }
    /// Stipple (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glPolygonStipple(_mask: *const u8) {
        missing()
    }
    /// Stipple (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glGetPolygonStipple(_mask: *mut u8) {
        missing_now()
    }
    /// Accumulation buffer (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glAccum(_op: GLenum, _value: f32) {
        missing()
    }
    /// Accumulation buffer (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glClearAccum(_r: f32, _g: f32, _b: f32, _a: f32) {
        missing()
    }
    /// Raster position and pixel rectangles (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glRasterPos2f(_x: f32, _y: f32) {
        missing()
    }
    /// Raster position and pixel rectangles (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glRasterPos2fv(_v: *const f32) {
        missing()
    }
    /// Raster position and pixel rectangles (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glRasterPos2d(_x: f64, _y: f64) {
        missing()
    }
    /// Raster position and pixel rectangles (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glRasterPos2dv(_v: *const f64) {
        missing()
    }
    /// Raster position and pixel rectangles (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glRasterPos2i(_x: i32, _y: i32) {
        missing()
    }
    /// Raster position and pixel rectangles (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glRasterPos2iv(_v: *const i32) {
        missing()
    }
    /// Raster position and pixel rectangles (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glRasterPos2s(_x: i16, _y: i16) {
        missing()
    }
    /// Raster position and pixel rectangles (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glRasterPos2sv(_v: *const i16) {
        missing()
    }
    /// Raster position and pixel rectangles (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glRasterPos3f(_x: f32, _y: f32, _z: f32) {
        missing()
    }
    /// Raster position and pixel rectangles (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glRasterPos3fv(_v: *const f32) {
        missing()
    }
    /// Raster position and pixel rectangles (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glRasterPos3d(_x: f64, _y: f64, _z: f64) {
        missing()
    }
    /// Raster position and pixel rectangles (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glRasterPos3dv(_v: *const f64) {
        missing()
    }
    /// Raster position and pixel rectangles (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glRasterPos3i(_x: i32, _y: i32, _z: i32) {
        missing()
    }
    /// Raster position and pixel rectangles (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glRasterPos3iv(_v: *const i32) {
        missing()
    }
    /// Raster position and pixel rectangles (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glRasterPos3s(_x: i16, _y: i16, _z: i16) {
        missing()
    }
    /// Raster position and pixel rectangles (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glRasterPos3sv(_v: *const i16) {
        missing()
    }
    /// Raster position and pixel rectangles (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glRasterPos4f(_x: f32, _y: f32, _z: f32, _w: f32) {
        missing()
    }
    /// Raster position and pixel rectangles (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glRasterPos4fv(_v: *const f32) {
        missing()
    }
    /// Raster position and pixel rectangles (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glRasterPos4d(_x: f64, _y: f64, _z: f64, _w: f64) {
        missing()
    }
    /// Raster position and pixel rectangles (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glRasterPos4dv(_v: *const f64) {
        missing()
    }
    /// Raster position and pixel rectangles (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glRasterPos4i(_x: i32, _y: i32, _z: i32, _w: i32) {
        missing()
    }
    /// Raster position and pixel rectangles (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glRasterPos4iv(_v: *const i32) {
        missing()
    }
    /// Raster position and pixel rectangles (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glRasterPos4s(_x: i16, _y: i16, _z: i16, _w: i16) {
        missing()
    }
    /// Raster position and pixel rectangles (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glRasterPos4sv(_v: *const i16) {
        missing()
    }
    /// Raster position and pixel rectangles (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glDrawPixels(_width: i32, _height: i32, _format: GLenum, _ty: GLenum, _pixels: *const c_void) {
        missing()
    }
    /// Raster position and pixel rectangles (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glCopyPixels(_x: i32, _y: i32, _width: i32, _height: i32, _ty: GLenum) {
        missing()
    }
    /// Raster position and pixel rectangles (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glBitmap(_width: i32, _height: i32, _xorig: f32, _yorig: f32, _xmove: f32, _ymove: f32, _bitmap: *const u8) {
        missing()
    }
    /// Raster position and pixel rectangles (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glPixelZoom(_xfactor: f32, _yfactor: f32) {
        missing()
    }
    /// Raster position and pixel rectangles (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glPixelMapfv(_map: GLenum, _size: i32, _values: *const f32) {
        missing()
    }
    /// Raster position and pixel rectangles (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glPixelMapuiv(_map: GLenum, _size: i32, _values: *const u32) {
        missing()
    }
    /// Raster position and pixel rectangles (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glPixelMapusv(_map: GLenum, _size: i32, _values: *const u16) {
        missing()
    }
    /// Raster position and pixel rectangles (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glGetPixelMapfv(_map: GLenum, _values: *mut f32) {
        missing_now()
    }
    /// Raster position and pixel rectangles (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glGetPixelMapuiv(_map: GLenum, _values: *mut u32) {
        missing_now()
    }
    /// Raster position and pixel rectangles (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glGetPixelMapusv(_map: GLenum, _values: *mut u16) {
        missing_now()
    }
    /// Evaluators (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glMap1f(_target: GLenum, _u1: f32, _u2: f32, _stride: i32, _order: i32, _points: *const f32) {
        missing()
    }
    /// Evaluators (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glMap2f(_target: GLenum, _u1: f32, _u2: f32, _ustride: i32, _uorder: i32, _v1: f32, _v2: f32, _vstride: i32, _vorder: i32, _points: *const f32) {
        missing()
    }
    /// Evaluators (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glMapGrid1f(_un: i32, _u1: f32, _u2: f32) {
        missing()
    }
    /// Evaluators (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glMapGrid2f(_un: i32, _u1: f32, _u2: f32, _vn: i32, _v1: f32, _v2: f32) {
        missing()
    }
    /// Evaluators (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glGetMapfv(_target: GLenum, _query: GLenum, _v: *mut f32) {
        missing_now()
    }
    /// Evaluators (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glMap1d(_target: GLenum, _u1: f64, _u2: f64, _stride: i32, _order: i32, _points: *const f64) {
        missing()
    }
    /// Evaluators (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glMap2d(_target: GLenum, _u1: f64, _u2: f64, _ustride: i32, _uorder: i32, _v1: f64, _v2: f64, _vstride: i32, _vorder: i32, _points: *const f64) {
        missing()
    }
    /// Evaluators (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glMapGrid1d(_un: i32, _u1: f64, _u2: f64) {
        missing()
    }
    /// Evaluators (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glMapGrid2d(_un: i32, _u1: f64, _u2: f64, _vn: i32, _v1: f64, _v2: f64) {
        missing()
    }
    /// Evaluators (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glGetMapdv(_target: GLenum, _query: GLenum, _v: *mut f64) {
        missing_now()
    }
    /// Evaluators (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glGetMapiv(_target: GLenum, _query: GLenum, _v: *mut i32) {
        missing_now()
    }
    /// Colour index (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glIndexMask(_mask: u32) {
        missing()
    }
    /// Colour index (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glClearIndex(_c: f32) {
        missing()
    }
    /// Colour index (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glIndexPointer(_ty: GLenum, _stride: i32, _ptr: *const c_void) {
        missing_now()
    }
}
