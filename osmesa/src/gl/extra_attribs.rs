//! The other commands GL allows between `glBegin` and `glEnd`: `glIndex*`
//! (the current colour index: kept and queryable as `GL_CURRENT_INDEX`,
//! without effect in an RGBA context), `glEdgeFlag*` (drawn by polygon mode
//! `GL_LINE`/`GL_POINT`). The evaluator calls are in `eval.rs`.

use super::attr;

/// Reads one value through `v`, or `None` for a null pointer.
///
/// # Safety
/// `v` is null or points to a readable value.
unsafe fn read1<T: Copy>(v: *const T) -> Option<T> {
    // SAFETY: null or readable by the caller's contract.
    (!v.is_null()).then(|| unsafe { v.read_unaligned() })
}

#[inline]
fn index(c: f32) {
    attr(move |gl| gl.index(c))
}

#[inline]
fn edge_flag(flag: u8) {
    attr(move |gl| gl.edge_flag(flag != 0))
}

exports! {
    [] fn glIndexf(c: f32) {
        index(c)
    }
    [] fn glIndexd(c: f64) {
        index(c as f32)
    }
    [] fn glIndexi(c: i32) {
        index(c as f32)
    }
    [] fn glIndexs(c: i16) {
        index(f32::from(c))
    }
    [] fn glIndexub(c: u8) {
        index(f32::from(c))
    }
    /// # Safety
    /// `c` is null or readable.
    [unsafe] fn glIndexfv(c: *const f32) {
        // SAFETY: readable by GL's contract; null is ignored.
        if let Some(c) = unsafe { read1(c) } {
            index(c)
        }
    }
    /// # Safety
    /// `c` is null or readable.
    [unsafe] fn glIndexdv(c: *const f64) {
        // SAFETY: readable by GL's contract; null is ignored.
        if let Some(c) = unsafe { read1(c) } {
            index(c as f32)
        }
    }
    /// # Safety
    /// `c` is null or readable.
    [unsafe] fn glIndexiv(c: *const i32) {
        // SAFETY: readable by GL's contract; null is ignored.
        if let Some(c) = unsafe { read1(c) } {
            index(c as f32)
        }
    }
    /// # Safety
    /// `c` is null or readable.
    [unsafe] fn glIndexsv(c: *const i16) {
        // SAFETY: readable by GL's contract; null is ignored.
        if let Some(c) = unsafe { read1(c) } {
            index(f32::from(c))
        }
    }
    /// # Safety
    /// `c` is null or readable.
    [unsafe] fn glIndexubv(c: *const u8) {
        // SAFETY: readable by GL's contract; null is ignored.
        if let Some(c) = unsafe { read1(c) } {
            index(f32::from(c))
        }
    }
    [] fn glEdgeFlag(flag: u8) {
        edge_flag(flag)
    }
    /// # Safety
    /// `flag` is null or readable.
    [unsafe] fn glEdgeFlagv(flag: *const u8) {
        // SAFETY: readable by GL's contract; null is ignored.
        if let Some(f) = unsafe { read1(flag) } {
            edge_flag(f)
        }
    }
}
