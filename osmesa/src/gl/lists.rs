//! Display lists. A list is the sequence of recorded calls ([`Cmd`](crate::gl_state::Cmd)s) made
//! between `glNewList` and `glEndList`; calls that GL never compiles
//! (queries, client state, pixel packing, list management, `glFinish`) run at
//! once. Draws from client arrays read the arrays when compiled, as in GL.

use super::{now, rec};
use crate::consts::*;
use crate::gl_state::{Compiling, GlState};
use crate::state::with_gl;
use softgl::{Context, GlError};
use std::ffi::c_void;
use std::sync::Arc;

const GL_COMPILE: GLenum = 0x1300;
const GL_COMPILE_AND_EXECUTE: GLenum = 0x1301;
/// `GL_MAX_LIST_NESTING` (Mesa's 64).
pub const MAX_NESTING: u32 = 64;

/// `GL_LIST_INDEX` and `GL_LIST_MODE` (0 when not compiling).
pub fn compiling_state(os: &GlState) -> (u32, GLenum) {
    os.compiling.as_ref().map_or((0, 0), |c| {
        (c.name, if c.execute { GL_COMPILE_AND_EXECUTE } else { GL_COMPILE })
    })
}

/// Runs list `name` (nothing if it does not exist), `GL_MAX_LIST_NESTING` deep at most.
fn call(os: &mut GlState, gl: &mut Context, name: u32) {
    if os.call_depth >= MAX_NESTING {
        return;
    }
    let Some(cmds) = os.lists.get(&name).cloned() else {
        return;
    };
    os.call_depth += 1;
    for cmd in cmds.iter() {
        cmd(os, gl);
    }
    os.call_depth -= 1;
}

/// Reads `n` list names of `ty` at `lists`.
///
/// # Safety
/// `lists` holds `n` values of `ty` (GL's contract).
unsafe fn names(n: usize, ty: GLenum, lists: *const u8) -> Option<Vec<u32>> {
    let size = match ty {
        GL_BYTE | GL_UNSIGNED_BYTE => 1,
        GL_SHORT | GL_UNSIGNED_SHORT | 0x1407 => 2,        // GL_2_BYTES
        0x1408 => 3,                                       // GL_3_BYTES
        GL_INT | GL_UNSIGNED_INT | GL_FLOAT | 0x1409 => 4, // GL_4_BYTES
        _ => return None,
    };
    // SAFETY: `n` values of `size` bytes, by the caller's contract.
    let bytes = unsafe { std::slice::from_raw_parts(lists, n * size) };
    Some(
        bytes
            .chunks_exact(size)
            .map(|b| match ty {
                GL_BYTE => b[0] as i8 as u32,
                GL_UNSIGNED_BYTE => u32::from(b[0]),
                GL_SHORT => i16::from_ne_bytes([b[0], b[1]]) as u32,
                GL_UNSIGNED_SHORT => u32::from(u16::from_ne_bytes([b[0], b[1]])),
                GL_INT | GL_UNSIGNED_INT => u32::from_ne_bytes([b[0], b[1], b[2], b[3]]),
                GL_FLOAT => f32::from_ne_bytes([b[0], b[1], b[2], b[3]]) as u32,
                // GL_n_BYTES: big-endian unsigned.
                _ => b.iter().fold(0u32, |v, &x| (v << 8) | u32::from(x)),
            })
            .collect(),
    )
}

exports! {
    [] fn glNewList(list: u32, mode: GLenum) {
        now(|os, gl| {
            if gl.inside_begin() {
                return Err(GlError::InvalidOperation);
            }
            if list == 0 {
                return Err(GlError::InvalidValue);
            }
            let execute = match mode {
                GL_COMPILE => false,
                GL_COMPILE_AND_EXECUTE => true,
                _ => return Err(GlError::InvalidEnum),
            };
            if os.compiling.is_some() {
                return Err(GlError::InvalidOperation);
            }
            os.compiling = Some(Compiling { name: list, execute, cmds: Vec::new() });
            Ok(())
        })
    }
    [] fn glEndList() {
        now(|os, gl| {
            if gl.inside_begin() {
                return Err(GlError::InvalidOperation);
            }
            let c = os.compiling.take().ok_or(GlError::InvalidOperation)?;
            os.lists.insert(c.name, Arc::new(c.cmds));
            Ok(())
        })
    }
    [] fn glCallList(list: u32) {
        rec(move |os, gl| {
            call(os, gl, list);
            Ok(())
        })
    }
    /// # Safety
    /// `lists` holds `n` names of `ty` (GL's contract).
    [unsafe] fn glCallLists(n: i32, ty: GLenum, lists: *const c_void) {
        if n < 0 {
            return now(|_, _| Err(GlError::InvalidValue));
        }
        if n > 0 && lists.is_null() {
            return now(|_, _| Err(GlError::InvalidValue));
        }
        // SAFETY: `n` names of `ty`, read now (GL copies them into a list too).
        let Some(names) = (if n == 0 { Some(Vec::new()) } else { unsafe { names(n as usize, ty, lists.cast()) } }) else {
            return now(|_, _| Err(GlError::InvalidEnum));
        };
        rec(move |os, gl| {
            for &name in &names {
                call(os, gl, os.list_base.wrapping_add(name));
            }
            Ok(())
        })
    }
    [] fn glListBase(base: u32) {
        rec(move |os, gl| {
            super::outside(gl)?;
            os.list_base = base;
            Ok(())
        })
    }
    /// `range` unused names in a row, made lists (empty) at once; 0 for none.
    [] fn glGenLists(range: i32) -> u32 {
        with_gl(0, |os, gl| {
            if range < 0 || gl.inside_begin() {
                gl.record_error(if range < 0 { GlError::InvalidValue } else { GlError::InvalidOperation });
                return 0;
            }
            if range == 0 {
                return 0;
            }
            let mut first = 1u32;
            loop {
                let Some(end) = first.checked_add(range as u32) else {
                    gl.record_error(GlError::OutOfMemory);
                    return 0;
                };
                match (first..end).find(|n| os.lists.contains_key(n)) {
                    Some(used) => first = used + 1,
                    None => break,
                }
            }
            for name in first..first + range as u32 {
                os.lists.insert(name, Arc::new(Vec::new()));
            }
            first
        })
    }
    [] fn glDeleteLists(list: u32, range: i32) {
        now(|os, gl| {
            if range < 0 {
                return Err(GlError::InvalidValue);
            }
            if gl.inside_begin() {
                return Err(GlError::InvalidOperation);
            }
            os.lists.retain(|&n, _| n < list || n - list >= range as u32);
            Ok(())
        })
    }
    [] fn glIsList(list: u32) -> u8 {
        with_gl(GL_FALSE, |os, gl| {
            if gl.inside_begin() {
                gl.record_error(GlError::InvalidOperation);
                return GL_FALSE;
            }
            u8::from(os.lists.contains_key(&list))
        })
    }
}
