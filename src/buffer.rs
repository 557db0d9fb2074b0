//! Buffer objects (GL 1.5, `ARB_vertex_buffer_object`): named byte stores
//! bound to `GL_ARRAY_BUFFER` and `GL_ELEMENT_ARRAY_BUFFER`, written with
//! `buffer_data`/`buffer_sub_data` or through a mapping, read by vertex
//! array draws (the C ABI keeps which buffer each array pointer names).
//!
//! Names follow GL: `gen` reserves a name, the first `bind` of a name
//! (generated or not) makes its object, `delete` frees it and unbinds it
//! from the targets. Reads past a buffer's end are the caller's to refuse
//! ([`Buffer::bytes`] gives the bytes that exist); see docs/llvmpipe-facts.md
//! for what llvmpipe does with them.

use crate::error::{GlError, GlResult};
use crate::names::Names;

/// The targets a buffer object binds to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BufferTarget {
    /// `GL_ARRAY_BUFFER`: where vertex array pointers point.
    Array,
    /// `GL_ELEMENT_ARRAY_BUFFER`: where `glDrawElements` reads its indices.
    ElementArray,
}

/// `glBufferData`'s usage hint (stored and queried; softgl stores every
/// buffer the same way).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BufferUsage {
    StreamDraw,
    StreamRead,
    StreamCopy,
    StaticDraw,
    StaticRead,
    StaticCopy,
    DynamicDraw,
    DynamicRead,
    DynamicCopy,
}

/// `glMapBuffer`'s access.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BufferAccess {
    ReadOnly,
    WriteOnly,
    ReadWrite,
}

/// What `glGetBufferParameteriv` asks.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BufferParamName {
    Size,
    Usage,
    Access,
    Mapped,
}

/// One buffer object's data store and state.
#[derive(Clone, Debug)]
pub struct Buffer {
    data: Vec<u8>,
    usage: BufferUsage,
    /// GL 1.5's `BUFFER_ACCESS`: `READ_WRITE` until a map sets it.
    access: BufferAccess,
    mapped: bool,
}

impl Default for Buffer {
    fn default() -> Buffer {
        Buffer {
            data: Vec::new(),
            usage: BufferUsage::StaticDraw,
            access: BufferAccess::ReadWrite,
            mapped: false,
        }
    }
}

impl Buffer {
    /// The data store.
    pub fn bytes(&self) -> &[u8] {
        &self.data
    }

    /// The data store's size in bytes.
    pub fn size(&self) -> usize {
        self.data.len()
    }

    pub fn usage(&self) -> BufferUsage {
        self.usage
    }

    pub fn access(&self) -> BufferAccess {
        self.access
    }

    /// Whether `map` mapped it (and `unmap` has not unmapped it yet).
    pub fn mapped(&self) -> bool {
        self.mapped
    }

    /// The value of `name` as `glGetBufferParameteriv` answers it.
    pub fn param(&self, name: BufferParamName) -> i64 {
        use crate::gl_enum::GlEnum;
        match name {
            BufferParamName::Size => self.data.len() as i64,
            BufferParamName::Usage => i64::from(self.usage.to_gl()),
            BufferParamName::Access => i64::from(self.access.to_gl()),
            BufferParamName::Mapped => i64::from(self.mapped),
        }
    }
}

/// The buffer objects of a context and its two bindings.
#[derive(Clone, Debug, Default)]
pub struct BufferStore {
    objects: Names<Buffer>,
    array: u32,
    element_array: u32,
}

impl BufferStore {
    pub fn new() -> BufferStore {
        BufferStore::default()
    }

    /// `glGenBuffers`: `n` names not in use (`None`: none left, [`Names::gen`]).
    pub fn gen(&mut self, n: usize) -> Option<Vec<u32>> {
        self.objects.gen(n)
    }

    /// `glBindBuffer`: binds `name` to `target`, making its object on the
    /// first bind; 0 unbinds.
    pub fn bind(&mut self, target: BufferTarget, name: u32) {
        if name != 0 {
            self.objects.object_or_insert_with(name, Buffer::default);
        }
        *self.binding_mut(target) = name;
    }

    /// The name bound to `target` (0 for none).
    pub fn binding(&self, target: BufferTarget) -> u32 {
        match target {
            BufferTarget::Array => self.array,
            BufferTarget::ElementArray => self.element_array,
        }
    }

    fn binding_mut(&mut self, target: BufferTarget) -> &mut u32 {
        match target {
            BufferTarget::Array => &mut self.array,
            BufferTarget::ElementArray => &mut self.element_array,
        }
    }

    /// `glDeleteBuffers`: frees each name (0 and unused names are ignored)
    /// and unbinds it from the targets. The caller unbinds it from the
    /// vertex arrays that name it.
    pub fn delete(&mut self, names: &[u32]) {
        for &name in names {
            if name == 0 {
                continue;
            }
            self.objects.remove(name);
            for t in [BufferTarget::Array, BufferTarget::ElementArray] {
                if self.binding(t) == name {
                    *self.binding_mut(t) = 0;
                }
            }
        }
    }

    /// `glIsBuffer`: whether `name` has an object (a name only generated has none).
    pub fn is_buffer(&self, name: u32) -> bool {
        self.objects.get(name).is_some()
    }

    /// The object called `name`.
    pub fn get(&self, name: u32) -> Option<&Buffer> {
        self.objects.get(name)
    }

    /// The object bound to `target`; `GL_INVALID_OPERATION` when none is
    /// (GL's error for every buffer command on target 0).
    pub fn bound(&self, target: BufferTarget) -> GlResult<&Buffer> {
        self.get(self.binding(target)).ok_or(GlError::InvalidOperation)
    }

    fn bound_mut(&mut self, target: BufferTarget) -> GlResult<&mut Buffer> {
        let name = self.binding(target);
        self.objects.get_mut(name).ok_or(GlError::InvalidOperation)
    }

    /// `glBufferData`: a new data store of `size` bytes, `data`'s bytes or
    /// zeros; unmaps the buffer if it was mapped.
    pub fn data(&mut self, target: BufferTarget, size: usize, data: Option<&[u8]>, usage: BufferUsage) -> GlResult {
        let b = self.bound_mut(target)?;
        let mut store = Vec::new();
        store.try_reserve_exact(size).map_err(|_| GlError::OutOfMemory)?;
        if let Some(d) = data {
            store.extend_from_slice(&d[..size.min(d.len())]);
        }
        store.resize(size, 0);
        *b = Buffer {
            data: store,
            usage,
            access: BufferAccess::ReadWrite,
            mapped: false,
        };
        Ok(())
    }

    /// `glBufferSubData`: `data` at `offset`. `GL_INVALID_VALUE` when it
    /// does not fit, `GL_INVALID_OPERATION` while mapped.
    pub fn sub_data(&mut self, target: BufferTarget, offset: usize, data: &[u8]) -> GlResult {
        let b = self.bound_mut(target)?;
        let end = offset.checked_add(data.len()).ok_or(GlError::InvalidValue)?;
        if end > b.data.len() {
            return Err(GlError::InvalidValue);
        }
        if b.mapped {
            return Err(GlError::InvalidOperation);
        }
        b.data[offset..end].copy_from_slice(data);
        Ok(())
    }

    /// `glGetBufferSubData`: the bytes `offset..offset + size`, with the
    /// errors of [`BufferStore::sub_data`].
    pub fn get_sub_data(&self, target: BufferTarget, offset: usize, size: usize) -> GlResult<&[u8]> {
        let b = self.bound(target)?;
        let end = offset.checked_add(size).ok_or(GlError::InvalidValue)?;
        if end > b.data.len() {
            return Err(GlError::InvalidValue);
        }
        if b.mapped {
            return Err(GlError::InvalidOperation);
        }
        Ok(&b.data[offset..end])
    }

    /// `glMapBuffer`: the data store, to read or write until `unmap`.
    /// `GL_INVALID_OPERATION` if already mapped. The store does not move
    /// while mapped (only `data` replaces it, and it unmaps first).
    pub fn map(&mut self, target: BufferTarget, access: BufferAccess) -> GlResult<&mut [u8]> {
        let b = self.bound_mut(target)?;
        if b.mapped {
            return Err(GlError::InvalidOperation);
        }
        b.mapped = true;
        b.access = access;
        Ok(&mut b.data)
    }

    /// The data store of a mapped buffer (`glGetBufferPointerv`); `None` when not mapped.
    pub fn mapping(&mut self, target: BufferTarget) -> GlResult<Option<&mut [u8]>> {
        let b = self.bound_mut(target)?;
        Ok(if b.mapped { Some(&mut b.data) } else { None })
    }

    /// `glUnmapBuffer`: `GL_INVALID_OPERATION` if not mapped. The store is
    /// never corrupted, so it returns `true` (GL's `GL_TRUE`).
    pub fn unmap(&mut self, target: BufferTarget) -> GlResult<bool> {
        let b = self.bound_mut(target)?;
        if !b.mapped {
            return Err(GlError::InvalidOperation);
        }
        b.mapped = false;
        b.access = BufferAccess::ReadWrite;
        Ok(true)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_objects_and_bindings() {
        let mut s = BufferStore::new();
        assert_eq!(s.gen(3), Some(vec![1, 2, 3]));
        assert!(!s.is_buffer(1), "a generated name has no object before its first bind");
        s.bind(BufferTarget::Array, 2);
        assert!(s.is_buffer(2));
        s.bind(BufferTarget::ElementArray, 7);
        assert!(s.is_buffer(7), "binding an unused name makes its object");
        assert_eq!(s.gen(2), Some(vec![8, 9]), "Mesa's names follow the largest one used");
        s.delete(&[2, 7, 0, 100]);
        assert_eq!(
            (s.binding(BufferTarget::Array), s.binding(BufferTarget::ElementArray)),
            (0, 0)
        );
        assert!(!s.is_buffer(2));
    }

    #[test]
    fn data_sub_data_and_map() {
        let mut s = BufferStore::new();
        assert_eq!(
            s.data(BufferTarget::Array, 4, None, BufferUsage::StreamDraw),
            Err(GlError::InvalidOperation)
        );
        s.bind(BufferTarget::Array, 1);
        s.data(
            BufferTarget::Array,
            6,
            Some(&[1, 2, 3, 4, 5, 6]),
            BufferUsage::DynamicDraw,
        )
        .unwrap();
        s.sub_data(BufferTarget::Array, 4, &[9, 9]).unwrap();
        assert_eq!(s.sub_data(BufferTarget::Array, 5, &[9, 9]), Err(GlError::InvalidValue));
        assert_eq!(s.get_sub_data(BufferTarget::Array, 2, 4).unwrap(), [3, 4, 9, 9]);
        s.map(BufferTarget::Array, BufferAccess::WriteOnly).unwrap()[0] = 42;
        assert_eq!(
            s.map(BufferTarget::Array, BufferAccess::WriteOnly).err(),
            Some(GlError::InvalidOperation)
        );
        assert_eq!(s.sub_data(BufferTarget::Array, 0, &[1]), Err(GlError::InvalidOperation));
        let b = s.bound(BufferTarget::Array).unwrap();
        assert_eq!(
            (b.mapped(), b.access(), b.param(BufferParamName::Mapped)),
            (true, BufferAccess::WriteOnly, 1)
        );
        assert_eq!(s.unmap(BufferTarget::Array), Ok(true));
        assert_eq!(s.unmap(BufferTarget::Array), Err(GlError::InvalidOperation));
        assert_eq!(s.get_sub_data(BufferTarget::Array, 0, 1).unwrap(), [42]);
        s.map(BufferTarget::Array, BufferAccess::ReadOnly).unwrap();
        s.data(BufferTarget::Array, 2, None, BufferUsage::StaticRead).unwrap();
        let b = s.bound(BufferTarget::Array).unwrap();
        assert_eq!(
            (b.mapped(), b.bytes(), b.usage()),
            (false, &[0u8, 0][..], BufferUsage::StaticRead)
        );
    }
}
