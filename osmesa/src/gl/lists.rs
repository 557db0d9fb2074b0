//! Display lists. A list is the sequence of recorded calls ([`Cmd`](crate::gl_state::Cmd)s) made
//! between `glNewList` and `glEndList`; calls that GL never compiles
//! (queries, client state, pixel packing, list management, `glFinish`) run at
//! once. Draws from client arrays read the arrays when compiled, as in GL.
//!
//! A `glBegin` … `glEnd` made of `glVertex`, `glNormal`, `glColor` and
//! `glTexCoord` calls alone compiles into arrays ([`ImmediateRun`], as Mesa's
//! `vbo_save`), one command replayed as one draw
//! ([`Context::draw_run`]) rather than a boxed closure per call, each
//! replayed through the attribute path. Any other call inside ends the
//! run (which then replays as its calls, [`ImmediateRun`]'s `replay`) and is
//! recorded as usual, as are the calls after it up to `glEnd`; a run left
//! open by `glEndList` replays as its calls too. The semantics are the calls'
//! (the tests below compare the two): current attributes after the list,
//! attributes not set in the run taken when the list runs, errors, a list
//! called between `glBegin` and `glEnd`, `GL_COMPILE_AND_EXECUTE`.
//! lit16list (`osmesa/bench/fill.c`: 800 quad strips of 2002 vertices,
//! `glNormal3f` + `glVertex3f` each, in one list) went from 2.401 G to
//! 2.334 G instructions a frame (callgrind, `osmesa/bench/instructions.sh`),
//! and its compile from 3.2 M `Arc` allocations (one a call) to amortized vector growth.

use super::enums::decode;
use super::{now, rec};
use crate::consts::*;
use crate::gl_state::{Compiling, GlState};
use crate::state::with_gl;
use softgl::context::ImmediateRun;
use softgl::{Context, GlError};
use std::ffi::c_void;
use std::sync::Arc;

/// Records the run being compiled, if any, as one command.
pub(super) fn close_run(list: &mut Compiling) {
    if let Some(run) = list.run.take() {
        list.cmds.push(Arc::new(move |_, gl: &mut Context| {
            // Errors are the context's to record, as for the calls.
            let _ = gl.draw_run(&run);
        }));
    }
}

/// `glBegin(mode)` while a list is compiled: opens a run (and begins under
/// `GL_COMPILE_AND_EXECUTE`). `false` when no list is compiled or the mode
/// is not one (the call is then made or recorded as usual).
pub(super) fn begin_run(mode: GLenum) -> bool {
    with_gl(false, |os, gl| {
        let (Some(list), Ok(mode)) = (os.compiling.as_mut(), decode(mode)) else {
            return false;
        };
        close_run(list);
        list.run = Some(ImmediateRun::new(mode));
        if list.execute {
            let _ = gl.begin(mode);
        }
        true
    })
}

/// `glEnd` while a run is compiled: ends and records it (and ends the
/// primitive under `GL_COMPILE_AND_EXECUTE`). `false` otherwise.
pub(super) fn end_run() -> bool {
    with_gl(false, |os, gl| {
        let Some(list) = os.compiling.as_mut() else {
            return false;
        };
        let Some(run) = list.run.as_mut() else {
            return false;
        };
        run.end();
        close_run(list);
        if list.execute {
            let _ = gl.end();
        }
        true
    })
}

/// A vertex attribute call while a list is compiled: `to_run` adds it to
/// the run being compiled (and `call` runs under `GL_COMPILE_AND_EXECUTE`),
/// or, outside a run, `call` is recorded.
#[cold]
#[inline(never)]
pub(super) fn record_attrib(
    to_run: impl FnOnce(&mut ImmediateRun),
    call: impl Fn(&mut Context) + Send + Sync + 'static,
) {
    with_gl((), |os, gl| match os.compiling.as_mut() {
        Some(Compiling {
            run: Some(run),
            execute,
            ..
        }) => {
            to_run(run);
            if *execute {
                call(gl);
            }
        }
        _ => super::run_or_record(os, gl, Arc::new(move |_, gl: &mut Context| call(gl))),
    })
}

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
            os.compiling = Some(Compiling {
                name: list,
                execute,
                cmds: Vec::new(),
                run: None,
            });
            Ok(())
        })
    }
    [] fn glEndList() {
        now(|os, gl| {
            if gl.inside_begin() {
                return Err(GlError::InvalidOperation);
            }
            let mut c = os.compiling.take().ok_or(GlError::InvalidOperation)?;
            close_run(&mut c);
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
