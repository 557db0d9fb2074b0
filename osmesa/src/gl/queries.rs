//! Occlusion queries (GL 1.5 and `ARB_occlusion_query`'s names) over
//! [`softgl::QueryStore`]. `glBeginQuery`/`glEndQuery` are compiled into
//! display lists (as Mesa's `dlist.c`); names and results are not (GL 1.5
//! §5.4). A result flushes the scene (every draw made while the query was
//! active is then counted); its availability is llvmpipe's: no the first
//! time after `glEndQuery` (which flushes), yes from then on.

use super::enums::decode;
use super::{now, outside, rec};
use crate::consts::*;
use crate::state::with_gl;
use softgl::{GlError, QueryObjectParam, QueryParam, QueryTarget};

/// `glGetQueryObject*v`: the value of `pname` for query `id`, `None` after an error.
fn object(id: u32, pname: GLenum) -> Option<u64> {
    with_gl(None, |_, gl| {
        let r = outside(gl).and_then(|()| {
            // Mesa checks the name before the parameter (`get_query_object`).
            gl.queries().samples(id)?;
            Ok(match decode::<QueryObjectParam>(pname)? {
                QueryObjectParam::Result => gl.query_result(id)?,
                QueryObjectParam::ResultAvailable => u64::from(gl.query_available(id)?),
            })
        });
        r.map_err(|e| gl.record_error(e)).ok()
    })
}

exports! {
    /// # Safety
    /// `ids` has room for `n` names.
    [unsafe] fn glGenQueries(n: i32, ids: *mut u32) {
        now(|_, gl| {
            outside(gl)?;
            let n = usize::try_from(n).map_err(|_| GlError::InvalidValue)?;
            let names = gl.queries_mut().gen(n).ok_or(GlError::OutOfMemory)?;
            if !ids.is_null() {
                // SAFETY: room for `n` names (GL's contract).
                unsafe { std::ptr::copy_nonoverlapping(names.as_ptr(), ids, n) };
            }
            Ok(())
        })
    }
    /// # Safety
    /// `ids` holds `n` names.
    [unsafe] fn glDeleteQueries(n: i32, ids: *const u32) {
        now(|_, gl| {
            outside(gl)?;
            let n = usize::try_from(n).map_err(|_| GlError::InvalidValue)?;
            if n > 0 && !ids.is_null() {
                // SAFETY: `n` names (GL's contract).
                let names = unsafe { std::slice::from_raw_parts(ids, n) };
                gl.queries_mut().delete(names);
            }
            Ok(())
        })
    }
    [] fn glIsQuery(id: u32) -> u8 {
        with_gl(0, |_, gl| {
            if gl.inside_begin() {
                gl.record_error(GlError::InvalidOperation);
                return 0;
            }
            u8::from(gl.queries().is_query(id))
        })
    }
    [] fn glBeginQuery(target: GLenum, id: u32) {
        rec(move |_, gl| {
            outside(gl)?;
            let target = decode::<QueryTarget>(target)?;
            gl.queries_mut().begin(target, id)
        })
    }
    [] fn glEndQuery(target: GLenum) {
        rec(move |_, gl| {
            outside(gl)?;
            let target = decode::<QueryTarget>(target)?;
            gl.queries_mut().end(target)
        })
    }
    /// # Safety
    /// `params` is null or has room for one value.
    [unsafe] fn glGetQueryiv(target: GLenum, pname: GLenum, params: *mut i32) {
        now(|_, gl| {
            outside(gl)?;
            let target = decode::<QueryTarget>(target)?;
            let pname = decode::<QueryParam>(pname)?;
            let v = gl.queries().param(target, pname);
            if !params.is_null() {
                // SAFETY: room for one value (GL's contract).
                unsafe { *params = v.min(i32::MAX as u64) as i32 };
            }
            Ok(())
        })
    }
    /// # Safety
    /// `params` is null or has room for one value.
    [unsafe] fn glGetQueryObjectiv(id: u32, pname: GLenum, params: *mut i32) {
        if let (Some(v), false) = (object(id, pname), params.is_null()) {
            // SAFETY: room for one value (GL's contract); counts past
            // INT_MAX read as INT_MAX (as Mesa's).
            unsafe { *params = v.min(i32::MAX as u64) as i32 };
        }
    }
    /// # Safety
    /// `params` is null or has room for one value.
    [unsafe] fn glGetQueryObjectuiv(id: u32, pname: GLenum, params: *mut u32) {
        if let (Some(v), false) = (object(id, pname), params.is_null()) {
            // SAFETY: room for one value (GL's contract).
            unsafe { *params = v.min(u64::from(u32::MAX)) as u32 };
        }
    }
    /// # Safety
    /// As [`glGenQueries`].
    [unsafe] fn glGenQueriesARB(n: i32, ids: *mut u32) {
        // SAFETY: the same contract.
        unsafe { glGenQueries(n, ids) }
    }
    /// # Safety
    /// As [`glDeleteQueries`].
    [unsafe] fn glDeleteQueriesARB(n: i32, ids: *const u32) {
        // SAFETY: the same contract.
        unsafe { glDeleteQueries(n, ids) }
    }
    [] fn glIsQueryARB(id: u32) -> u8 {
        glIsQuery(id)
    }
    [] fn glBeginQueryARB(target: GLenum, id: u32) {
        glBeginQuery(target, id)
    }
    [] fn glEndQueryARB(target: GLenum) {
        glEndQuery(target)
    }
    /// # Safety
    /// As [`glGetQueryiv`].
    [unsafe] fn glGetQueryivARB(target: GLenum, pname: GLenum, params: *mut i32) {
        // SAFETY: the same contract.
        unsafe { glGetQueryiv(target, pname, params) }
    }
    /// # Safety
    /// As [`glGetQueryObjectiv`].
    [unsafe] fn glGetQueryObjectivARB(id: u32, pname: GLenum, params: *mut i32) {
        // SAFETY: the same contract.
        unsafe { glGetQueryObjectiv(id, pname, params) }
    }
    /// # Safety
    /// As [`glGetQueryObjectuiv`].
    [unsafe] fn glGetQueryObjectuivARB(id: u32, pname: GLenum, params: *mut u32) {
        // SAFETY: the same contract.
        unsafe { glGetQueryObjectuiv(id, pname, params) }
    }
}
