//! Client vertex arrays: the pointers, `glDrawArrays`, `glDrawElements`,
//! `glArrayElement`. The caller's arrays are read into f32 arrays for softgl
//! at each draw (positions, colours, normals, each unit's texture
//! coordinates, …); edge flags
//! (`glEdgeFlagPointer`) pick the edges polygon mode `GL_LINE`/`GL_POINT` draws.

use super::enums::decode;
use super::{now, outside, run_or_record};
use crate::consts::*;
use crate::gl_state::{ClientArray, Cmd, GlState, MAX_UNITS};
use softgl::{
    AttribArray, BufferStore, BufferTarget, Context, GlError, GlResult, Indices, PrimitiveMode, VertexArrays,
};
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

/// An enabled array, ready to read: a client array, or one in a buffer
/// object with the bytes it may read.
#[derive(Clone, Copy)]
struct Source {
    /// The array, its `ptr` resolved to an address.
    a: ClientArray,
    /// How many bytes from `a.ptr` exist: `usize::MAX` for client memory
    /// (GL's contract bounds it), the rest of the buffer for a buffer object.
    limit: usize,
}

/// The array `a` as a [`Source`] if it is enabled and names memory;
/// `GL_INVALID_OPERATION` if it reads a mapped buffer (GL 1.5 §2.9.3).
fn source(a: &ClientArray, buffers: &BufferStore) -> GlResult<Option<Source>> {
    if !a.enabled {
        return Ok(None);
    }
    if a.buffer == 0 {
        return Ok((!a.ptr.is_null()).then_some(Source {
            a: *a,
            limit: usize::MAX,
        }));
    }
    // A deleted buffer's arrays were reset to 0 (`gl::buffers`), so the name has an object.
    let Some(b) = buffers.get(a.buffer) else {
        return Ok(None);
    };
    if b.mapped() {
        return Err(GlError::InvalidOperation);
    }
    let offset = a.ptr as usize;
    let bytes = b.bytes();
    Ok(Some(Source {
        a: ClientArray {
            ptr: bytes.as_ptr().wrapping_add(offset.min(bytes.len())),
            ..*a
        },
        limit: bytes.len().saturating_sub(offset),
    }))
}

/// `n` zeros: an element past its buffer's end. Out of the element loop's way.
#[cold]
#[inline(never)]
fn zeros(n: usize, out: &mut Vec<f32>) {
    out.extend(std::iter::repeat_n(0.0, n));
}

/// Element `i` of `s` as floats, integer colours normalised when
/// `normalize`. An element that does not lie wholly inside its buffer
/// object reads as zeros, as llvmpipe reads it (docs/llvmpipe-facts.md §24).
///
/// # Safety
/// `s.a.ptr` holds element `i` when `s.limit` is `usize::MAX` (GL's
/// contract for enabled client arrays); otherwise `s.limit` bytes exist there.
#[inline(always)]
unsafe fn fetch(s: &Source, i: usize, normalize: bool, out: &mut Vec<f32>) {
    let a = &s.a;
    let size = type_size(a.ty).unwrap_or(4);
    let n = a.size as usize;
    let stride = if a.stride > 0 { a.stride as usize } else { n * size };
    if s.limit != usize::MAX {
        let end = i.checked_mul(stride).and_then(|o| o.checked_add(n * size));
        if end.is_none_or(|e| e > s.limit) {
            return zeros(n, out);
        }
    }
    // SAFETY: element `i` lies at `i * stride` in the caller's array.
    let base = unsafe { a.ptr.add(i * stride) };
    if a.ty == GL_FLOAT {
        // The common type, its components copied as they are, without the
        // per-component match below. With each array reserved once
        // (`gather`), the thrash frame's element fetch went from about 105
        // instructions to 55 (callgrind, 460,800 calls).
        match n {
            // SAFETY: the element's 2 components, f32s read unaligned.
            2 => out.extend_from_slice(&unsafe { base.cast::<[f32; 2]>().read_unaligned() }),
            // SAFETY: the element's 3 components, f32s read unaligned.
            3 => out.extend_from_slice(&unsafe { base.cast::<[f32; 3]>().read_unaligned() }),
            // SAFETY: the element's 4 components, f32s read unaligned.
            4 => out.extend_from_slice(&unsafe { base.cast::<[f32; 4]>().read_unaligned() }),
            _ => {
                for c in 0..n {
                    // SAFETY: component `c` of element `i`, an f32 read unaligned.
                    out.push(unsafe { base.add(c * 4).cast::<f32>().read_unaligned() });
                }
            }
        }
        return;
    }
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

/// The vertices a draw names, read from the enabled arrays when the draw is
/// issued (GL reads them then too when it compiles a draw into a list).
struct Fetched {
    mode: PrimitiveMode,
    count: usize,
    pos_size: usize,
    pos: Vec<f32>,
    color: Option<(usize, Vec<f32>)>,
    /// The edge flags, 0 or not (`glEdgeFlagPointer`).
    edge_flag: Option<Vec<f32>>,
    normal: Option<Vec<f32>>,
    secondary: Option<Vec<f32>>,
    fog_coord: Option<Vec<f32>>,
    /// Each unit's coordinates: size and values.
    tex_coords: [Option<(usize, Vec<f32>)>; MAX_UNITS],
}

/// Reads the vertices `indices` names; `None` without a vertex array (GL
/// then draws nothing). `GL_INVALID_OPERATION` if an array it reads is in a
/// mapped buffer.
fn gather(
    os: &GlState,
    buffers: &BufferStore,
    mode: GLenum,
    indices: &mut dyn Iterator<Item = usize>,
) -> GlResult<Option<Fetched>> {
    let mode = decode::<PrimitiveMode>(mode)?;
    let color = source(&os.color, buffers)?;
    let edge_flag = source(&os.edge_flag, buffers)?;
    let normal = source(&os.normal, buffers)?;
    let secondary = source(&os.secondary, buffers)?;
    let fog_coord = source(&os.fog_coord, buffers)?;
    let mut tex: [Option<Source>; MAX_UNITS] = [None; MAX_UNITS];
    for (t, a) in tex.iter_mut().zip(&os.tex_coords) {
        *t = source(a, buffers)?;
    }
    let Some(vertex) = source(&os.vertex, buffers)? else {
        return Ok(None);
    };
    let (mut pos, mut col, mut nrm) = (Vec::new(), Vec::new(), Vec::new());
    let (mut sec, mut fog, mut edges) = (Vec::new(), Vec::new(), Vec::new());
    let mut coords: [Vec<f32>; MAX_UNITS] = Default::default();
    // Each array's values allocated once (a growing `Vec` reallocates
    // several times for a draw's vertices).
    let hint = indices.size_hint().0;
    let reserve = |v: &mut Vec<f32>, a: Option<&Source>| {
        if let Some(s) = a {
            v.reserve(hint * s.a.size.max(0) as usize);
        }
    };
    reserve(&mut pos, Some(&vertex));
    reserve(&mut col, color.as_ref());
    reserve(&mut edges, edge_flag.as_ref());
    reserve(&mut nrm, normal.as_ref());
    reserve(&mut sec, secondary.as_ref());
    reserve(&mut fog, fog_coord.as_ref());
    for (v, a) in coords.iter_mut().zip(&tex) {
        reserve(v, a.as_ref());
    }
    // (Untextured draws skip the units' loop at every vertex: with the
    // reservations above, `draw`'s own instructions over 6 thrash frames
    // went from 16.0 M to 6.1 M.)
    let any_tex = tex.iter().any(Option::is_some);
    let mut count = 0;
    for i in indices {
        // SAFETY: the enabled client arrays hold every element the draw
        // names (GL's contract); buffer objects' reads are bounded by `fetch`.
        unsafe {
            fetch(&vertex, i, false, &mut pos);
            if let Some(c) = &color {
                fetch(c, i, true, &mut col);
            }
            if let Some(e) = &edge_flag {
                fetch(e, i, false, &mut edges);
            }
            if let Some(n) = &normal {
                fetch(n, i, true, &mut nrm);
            }
            if let Some(c) = &secondary {
                fetch(c, i, true, &mut sec);
            }
            if let Some(c) = &fog_coord {
                fetch(c, i, false, &mut fog);
            }
            if any_tex {
                for (a, out) in tex.iter().zip(coords.iter_mut()) {
                    if let Some(a) = a {
                        fetch(a, i, false, out);
                    }
                }
            }
        }
        count += 1;
    }
    Ok(Some(Fetched {
        mode,
        count,
        pos_size: vertex.a.size as usize,
        pos,
        color: color.map(|c| (c.a.size as usize, col)),
        edge_flag: edge_flag.map(|_| edges),
        normal: normal.map(|_| nrm),
        secondary: secondary.map(|_| sec),
        fog_coord: fog_coord.map(|_| fog),
        tex_coords: std::array::from_fn(|u| tex[u].map(|a| (a.a.size as usize, std::mem::take(&mut coords[u])))),
    }))
}

/// Draws (or records, in a display list) the vertices `indices` names; `indexed`
/// for glDrawElements, whose quads llvmpipe splits differently (docs/llvmpipe-facts.md §12).
fn draw(
    os: &mut GlState,
    gl: &mut Context,
    (mode, indexed): (GLenum, bool),
    indices: &mut dyn Iterator<Item = usize>,
) -> GlResult {
    let Some(f) = gather(os, gl.buffers(), mode, indices)? else {
        // Without a vertex array GL draws nothing, but the draw is still a
        // draw: between glBegin and glEnd (now, or when a list holding it
        // runs) it is GL_INVALID_OPERATION.
        let cmd: Cmd = std::sync::Arc::new(|_: &mut GlState, gl: &mut Context| {
            if gl.inside_begin() {
                gl.record_error(GlError::InvalidOperation);
            }
        });
        run_or_record(os, gl, cmd);
        return Ok(());
    };
    let f = std::sync::Arc::new(f);
    let make = |indexed: bool| -> Cmd {
        let f = f.clone();
        std::sync::Arc::new(move |_: &mut GlState, gl: &mut Context| {
            let arrays = VertexArrays {
                position: AttribArray::new(f.pos_size, &f.pos),
                color: f.color.as_ref().map(|(size, c)| AttribArray::new(*size, c)),
                edge_flag: f.edge_flag.as_ref().map(|e| AttribArray::new(1, e)),
                normal: f.normal.as_ref().map(|n| AttribArray::new(3, n)),
                secondary: f.secondary.as_ref().map(|c| AttribArray::new(3, c)),
                fog_coord: f.fog_coord.as_ref().map(|c| AttribArray::new(1, c)),
                tex_coords: std::array::from_fn(|u| {
                    f.tex_coords[u].as_ref().map(|(size, c)| AttribArray::new(*size, c))
                }),
            };
            // The context records its own errors (inside begin/end, …).
            let _ = if indexed {
                let order: Vec<u32> = (0..f.count as u32).collect();
                gl.draw_elements(f.mode, Indices::U32(&order), &arrays)
            } else {
                gl.draw_arrays(f.mode, 0, f.count, &arrays)
            };
        })
    };
    // Mesa compiles a draw into a list as indexed vertices (`vbo/vbo_save_api.c`,
    // `compile_vertex_list`), so a list replays it on the glDrawElements path
    // (its quads split as §12 says); GL_COMPILE_AND_EXECUTE runs the draw itself.
    let execute = os.compiling.as_mut().map(|l| std::mem::replace(&mut l.execute, false));
    run_or_record(os, gl, make(indexed || execute.is_some()));
    if let Some(execute) = execute {
        if let Some(l) = os.compiling.as_mut() {
            l.execute = execute;
        }
        if execute {
            make(indexed)(os, gl);
        }
    }
    Ok(())
}

/// The `count` indices of `size` bytes at byte `offset` of element buffer
/// `name`. As llvmpipe (docs/llvmpipe-facts.md §24): the indices start at
/// index `offset / size`, and an index past the buffer's end reads as 0.
/// `GL_INVALID_OPERATION` if the buffer is mapped.
fn buffer_indices(buffers: &BufferStore, name: u32, offset: usize, count: usize, size: usize) -> GlResult<Vec<usize>> {
    let b = buffers.get(name).ok_or(GlError::InvalidOperation)?;
    if b.mapped() {
        return Err(GlError::InvalidOperation);
    }
    let bytes = b.bytes();
    let first = offset / size;
    Ok((0..count)
        .map(|k| {
            let at = first.saturating_add(k).saturating_mul(size);
            match bytes.get(at..at.saturating_add(size)) {
                Some(&[v]) => usize::from(v),
                Some(&[a, b]) => usize::from(u16::from_ne_bytes([a, b])),
                Some(&[a, b, c, d]) => u32::from_ne_bytes([a, b, c, d]) as usize,
                _ => 0,
            }
        })
        .collect())
}

/// Sets a client array pointer after checking its arguments.
pub(super) fn pointer(
    which: fn(&mut GlState) -> &mut ClientArray,
    sizes: &[i32],
    size: i32,
    ty: GLenum,
    types: &[GLenum],
    stride: i32,
    ptr: *const c_void,
) {
    now(|os, gl| {
        outside(gl)?;
        if !types.contains(&ty) {
            return Err(GlError::InvalidEnum);
        }
        if !sizes.contains(&size) || stride < 0 {
            return Err(GlError::InvalidValue);
        }
        let buffer = gl.buffers().binding(BufferTarget::Array);
        let a = which(os);
        (a.size, a.ty, a.stride, a.ptr, a.buffer) = (size, ty, stride, ptr.cast(), buffer);
        Ok(())
    })
}

fn client_state(array: GLenum, on: bool) {
    now(|os, gl| {
        outside(gl)?;
        let a = os.array_mut(array).ok_or(GlError::InvalidEnum)?;
        a.enabled = on;
        Ok(())
    })
}

pub(super) const ALL_TYPES: [GLenum; 4] = [GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE];
pub(super) const COLOR_TYPES: [GLenum; 8] = [
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
        pointer(|o| &mut o.tex_coords[o.client_active], &[1, 2, 3, 4], size, ty, &ALL_TYPES, stride, ptr)
    }
    /// # Safety
    /// `ptr` stays valid while drawing reads it (GL's contract).
    [unsafe] fn glEdgeFlagPointer(stride: i32, ptr: *const c_void) {
        pointer(|o| &mut o.edge_flag, &[1], 1, GL_UNSIGNED_BYTE, &[GL_UNSIGNED_BYTE], stride, ptr)
    }
    /// Kept and queried; an RGBA context draws without colour indices.
    ///
    /// # Safety
    /// `ptr` stays valid while drawing reads it (GL's contract).
    [unsafe] fn glIndexPointer(ty: GLenum, stride: i32, ptr: *const c_void) {
        let types = [GL_UNSIGNED_BYTE, GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE];
        pointer(|o| &mut o.index, &[1], 1, ty, &types, stride, ptr)
    }
    [] fn glEnableClientState(array: GLenum) {
        client_state(array, true)
    }
    [] fn glDisableClientState(array: GLenum) {
        client_state(array, false)
    }
    [] fn glDrawArrays(mode: GLenum, first: i32, count: i32) {
        now(|os, gl| {
            if first < 0 || count < 0 {
                decode::<PrimitiveMode>(mode)?;
                return Err(GlError::InvalidValue);
            }
            draw(os, gl, (mode, false), &mut (first as usize..first as usize + count as usize))
        })
    }
    /// # Safety
    /// `indices` points to `count` indices of `ty` (GL's contract).
    [unsafe] fn glDrawElements(mode: GLenum, count: i32, ty: GLenum, indices: *const c_void) {
        now(|os, gl| {
            decode::<PrimitiveMode>(mode)?;
            if count < 0 {
                return Err(GlError::InvalidValue);
            }
            let size = match ty {
                GL_UNSIGNED_BYTE => 1,
                GL_UNSIGNED_SHORT => 2,
                GL_UNSIGNED_INT => 4,
                _ => return Err(GlError::InvalidEnum),
            };
            let element = gl.buffers().binding(BufferTarget::ElementArray);
            if element != 0 {
                let order = buffer_indices(gl.buffers(), element, indices as usize, count as usize, size)?;
                return draw(os, gl, (mode, true), &mut order.into_iter());
            }
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
            draw(os, gl, (mode, true), &mut it)
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
        now(|os, gl| {
            if i < 0 {
                return Err(GlError::InvalidValue);
            }
            let i = i as usize;
            // Read now (GL's rule for lists too), applied by the command.
            let buffers = gl.buffers();
            let read = |a: &ClientArray, normalize: bool| -> GlResult<Option<Vec<f32>>> {
                let Some(s) = source(a, buffers)? else {
                    return Ok(None);
                };
                let mut v = Vec::with_capacity(4);
                // SAFETY: the enabled client arrays hold element `i` (GL's
                // contract); buffer objects' reads are bounded by `fetch`.
                unsafe { fetch(&s, i, normalize, &mut v) };
                Ok(Some(v))
            };
            let pad = |mut v: Vec<f32>, size: i32| -> [f32; 4] {
                v.resize(4, 0.0);
                if size < 4 {
                    v[3] = 1.0;
                }
                [v[0], v[1], v[2], v[3]]
            };
            let color = read(&os.color, true)?.map(|v| pad(v, os.color.size));
            let normal = read(&os.normal, true)?;
            let mut tex: Vec<Option<[f32; 4]>> = Vec::with_capacity(MAX_UNITS);
            for a in &os.tex_coords {
                tex.push(read(a, false)?.map(|v| pad(v, a.size)));
            }
            let edge_flag = read(&os.edge_flag, false)?.map(|v| v[0] != 0.0);
            let vertex = read(&os.vertex, false)?.map(|v| pad(v, os.vertex.size));
            let cmd: Cmd = std::sync::Arc::new(move |_: &mut GlState, gl: &mut Context| {
                if let Some([r, g, b, a]) = color {
                    gl.color4(r, g, b, a);
                }
                if let Some(n) = &normal {
                    gl.normal3(n[0], n[1], n[2]);
                }
                for (unit, c) in tex.iter().enumerate() {
                    if let Some(c) = c {
                        let _ = gl.multi_tex_coord(unit as u32, *c);
                    }
                }
                if let Some(e) = edge_flag {
                    gl.edge_flag(e);
                }
                if let Some([x, y, z, w]) = vertex {
                    gl.vertex4(x, y, z, w);
                }
            });
            run_or_record(os, gl, cmd);
            Ok(())
        })
    }
    /// # Safety
    /// `params` is null or writable.
    [unsafe] fn glGetPointerv(pname: GLenum, params: *mut *mut c_void) {
        now(|os, gl| {
            outside(gl)?;
            let p = match pname {
                GL_VERTEX_ARRAY_POINTER => os.vertex.ptr,
                GL_COLOR_ARRAY_POINTER => os.color.ptr,
                GL_NORMAL_ARRAY_POINTER => os.normal.ptr,
                GL_TEXTURE_COORD_ARRAY_POINTER => os.tex_coord().ptr,
                GL_EDGE_FLAG_ARRAY_POINTER => os.edge_flag.ptr,
                0x8091 => os.index.ptr, // GL_INDEX_ARRAY_POINTER
                0x845D => os.secondary.ptr, // GL_SECONDARY_COLOR_ARRAY_POINTER
                0x8456 => os.fog_coord.ptr, // GL_FOG_COORD_ARRAY_POINTER
                super::select::GL_SELECTION_BUFFER_POINTER => os.mode_buffers.select.cast_const().cast(),
                super::select::GL_FEEDBACK_BUFFER_POINTER => os.mode_buffers.feedback.cast_const().cast(),
                _ => return Err(GlError::InvalidEnum),
            };
            if !params.is_null() {
                // SAFETY: non-null and writable by GL's contract.
                unsafe { *params = p.cast_mut().cast() };
            }
            Ok(())
        })
    }
    /// Sets and enables the arrays of one of GL's 14 interleaved layouts
    /// (texture coordinates, colour, normal, position, in that order).
    ///
    /// # Safety
    /// `ptr` stays valid while drawing reads it (GL's contract).
    [unsafe] fn glInterleavedArrays(format: GLenum, stride: i32, ptr: *const c_void) {
        now(|os, gl| {
            if gl.inside_begin() {
                return Err(GlError::InvalidOperation);
            }
            let layout = interleaved(format).ok_or(GlError::InvalidEnum)?;
            if stride < 0 {
                return Err(GlError::InvalidValue);
            }
            let (t, c, n, v) = layout;
            let f = std::mem::size_of::<f32>();
            // Byte sizes of each part: floats, except C4UB's 4 bytes.
            let c_bytes = match c {
                Some((_, GL_UNSIGNED_BYTE)) => 4,
                Some((size, _)) => size as usize * f,
                None => 0,
            };
            let total = t as usize * f + c_bytes + if n { 3 * f } else { 0 } + v as usize * f;
            let stride = if stride == 0 { total as i32 } else { stride };
            let base = ptr.cast::<u8>();
            let buffer = gl.buffers().binding(BufferTarget::Array);
            let mut at = 0usize;
            let mut set = |a: &mut ClientArray, size: i32, ty: GLenum, on: bool, bytes: usize| {
                a.enabled = on;
                if on {
                    (a.size, a.ty, a.stride, a.ptr) = (size, ty, stride, base.wrapping_add(at));
                    a.buffer = buffer;
                    at += bytes;
                }
            };
            let unit = os.client_active;
            set(&mut os.tex_coords[unit], t, GL_FLOAT, t > 0, t as usize * f);
            let (cs, ct) = c.unwrap_or((4, GL_FLOAT));
            set(&mut os.color, cs, ct, c.is_some(), c_bytes);
            set(&mut os.normal, 3, GL_FLOAT, n, 3 * f);
            set(&mut os.vertex, v, GL_FLOAT, true, v as usize * f);
            Ok(())
        })
    }
}

/// The parts of an interleaved layout: texture coordinate size (0 for none),
/// colour size and type, whether there is a normal, position size.
type Interleaved = (i32, Option<(i32, GLenum)>, bool, i32);

fn interleaved(format: GLenum) -> Option<Interleaved> {
    const C4UB: Option<(i32, GLenum)> = Some((4, GL_UNSIGNED_BYTE));
    const C3F: Option<(i32, GLenum)> = Some((3, GL_FLOAT));
    const C4F: Option<(i32, GLenum)> = Some((4, GL_FLOAT));
    Some(match format {
        0x2A20 => (0, None, false, 2), // GL_V2F
        0x2A21 => (0, None, false, 3), // GL_V3F
        0x2A22 => (0, C4UB, false, 2), // GL_C4UB_V2F
        0x2A23 => (0, C4UB, false, 3), // GL_C4UB_V3F
        0x2A24 => (0, C3F, false, 3),  // GL_C3F_V3F
        0x2A25 => (0, None, true, 3),  // GL_N3F_V3F
        0x2A26 => (0, C4F, true, 3),   // GL_C4F_N3F_V3F
        0x2A27 => (2, None, false, 3), // GL_T2F_V3F
        0x2A28 => (4, None, false, 4), // GL_T4F_V4F
        0x2A29 => (2, C4UB, false, 3), // GL_T2F_C4UB_V3F
        0x2A2A => (2, C3F, false, 3),  // GL_T2F_C3F_V3F
        0x2A2B => (2, None, true, 3),  // GL_T2F_N3F_V3F
        0x2A2C => (2, C4F, true, 3),   // GL_T2F_C4F_N3F_V3F
        0x2A2D => (4, C4F, true, 4),   // GL_T4F_C4F_N3F_V4F
        _ => return None,
    })
}
