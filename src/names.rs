//! GL object names (`glGen*`, `glBind*`, `glDelete*`, `glIs*`): one
//! allocator for every kind of object softgl keeps (textures, buffers,
//! queries, framebuffers, renderbuffers).
//!
//! The rule is Mesa's (`_mesa_HashFindFreeKeyBlock`, `src/mesa/main/hash.c`):
//! `glGen*` hands out the `n` names after the largest name ever used, by a
//! `glGen*` or by binding a name never generated; deleted names are not
//! reused (Mesa reuses them only under driconf's `force_gl_names_reuse`,
//! off by default). When that block would reach 2^32 − 1, the first run of
//! `n` free names from 1 is taken, and with none the call fails
//! (`GL_OUT_OF_MEMORY` in the callers).

use std::collections::HashMap;

/// Names per `glGen*` call beyond which it fails with `GL_OUT_OF_MEMORY`
/// rather than try to allocate tables of gigabytes (Mesa would try).
pub const MAX_GEN: usize = 1 << 24;

/// The largest name handed out (Mesa's `~0 - 1`).
const LAST: u32 = u32::MAX - 1;

/// The objects of one kind by name. A name is *reserved* once generated or
/// bound; its object (`Some`) exists once bound (GL's `glIs*` asks that).
#[derive(Clone, Debug)]
pub struct Names<T> {
    objects: HashMap<u32, Option<T>>,
    /// The largest name ever reserved.
    max: u32,
}

impl<T> Default for Names<T> {
    fn default() -> Self {
        Names {
            objects: HashMap::new(),
            max: 0,
        }
    }
}

impl<T> Names<T> {
    pub fn new() -> Names<T> {
        Names::default()
    }

    /// `glGen*`: `n` names not in use, reserved without objects; `None` when
    /// there is no block of `n` free names (or `n` is beyond [`MAX_GEN`]).
    pub fn gen(&mut self, n: usize) -> Option<Vec<u32>> {
        if n > MAX_GEN {
            return None;
        }
        let count = n as u32;
        let first = if LAST - count > self.max {
            self.max + 1
        } else {
            self.free_block(count)?
        };
        let names: Vec<u32> = (first..first + count).collect();
        for &name in &names {
            self.objects.insert(name, None);
        }
        self.max = self.max.max(first + count - 1);
        Some(names)
    }

    /// The first run of `count` names from 1 that none uses.
    fn free_block(&self, count: u32) -> Option<u32> {
        let mut used: Vec<u32> = self.objects.keys().copied().collect();
        used.sort_unstable();
        let mut start = 1u32;
        for name in used.into_iter().chain([LAST]) {
            if name.saturating_sub(start) >= count {
                return Some(start);
            }
            start = name.saturating_add(1);
        }
        None
    }

    /// The slot of `name` (not 0), reserving the name: `glBind*` makes the
    /// object in it on first bind.
    pub fn slot(&mut self, name: u32) -> &mut Option<T> {
        self.max = self.max.max(name);
        self.objects.entry(name).or_insert(None)
    }

    /// The object of `name`, made with `make` if there is none yet.
    pub fn object_or_insert_with(&mut self, name: u32, make: impl FnOnce() -> T) -> &mut T {
        self.slot(name).get_or_insert_with(make)
    }

    /// Whether `name` is reserved (generated or bound, not deleted).
    pub fn is_reserved(&self, name: u32) -> bool {
        name != 0 && self.objects.contains_key(&name)
    }

    /// The object of `name`, if it has been bound.
    pub fn get(&self, name: u32) -> Option<&T> {
        self.objects.get(&name)?.as_ref()
    }

    pub fn get_mut(&mut self, name: u32) -> Option<&mut T> {
        self.objects.get_mut(&name)?.as_mut()
    }

    /// `glDelete*` of one name: frees it; whether it was reserved.
    pub fn remove(&mut self, name: u32) -> bool {
        self.objects.remove(&name).is_some()
    }

    /// Every object made so far, by name.
    pub fn iter(&self) -> impl Iterator<Item = (u32, &T)> {
        self.objects.iter().filter_map(|(&n, o)| Some((n, o.as_ref()?)))
    }

    pub fn iter_mut(&mut self) -> impl Iterator<Item = (u32, &mut T)> {
        self.objects.iter_mut().filter_map(|(&n, o)| Some((n, o.as_mut()?)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn blocks_follow_the_largest_name_ever_used() {
        let mut names: Names<()> = Names::new();
        assert_eq!(names.gen(3), Some(vec![1, 2, 3]));
        names.object_or_insert_with(10, || ());
        assert_eq!(names.gen(2), Some(vec![11, 12]));
        assert!(names.remove(12));
        assert!(!names.remove(12));
        assert_eq!(names.gen(1), Some(vec![13]), "deleted names are not reused");
        assert_eq!(names.gen(0), Some(vec![]));
        assert!(names.is_reserved(11) && names.get(11).is_none());
        assert_eq!(names.get(10), Some(&()));
        assert!(!names.is_reserved(0));
    }

    #[test]
    fn near_the_last_name_the_first_free_run_is_taken() {
        let mut names: Names<()> = Names::new();
        names.object_or_insert_with(2, || ());
        names.object_or_insert_with(5, || ());
        names.object_or_insert_with(LAST - 1, || ());
        assert_eq!(names.gen(2), Some(vec![3, 4]));
        assert_eq!(names.gen(2), Some(vec![6, 7]));
        assert_eq!(names.gen(1), Some(vec![1]));
        assert_eq!(names.gen(MAX_GEN + 1), None);
    }
}
