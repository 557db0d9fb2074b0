//! Occlusion queries (GL 1.5, `ARB_occlusion_query`): named objects that
//! count the fragments passing every per-fragment test (scissor, alpha,
//! stencil, depth: GL 1.5 §4.1.7) between `begin_query` and `end_query`.
//!
//! Rendering is deferred (`raster/scene.rs`): a draw made while a query is
//! active carries the query's counter; its fragment stages count in the
//! specialist ([`FragmentKey::count`](softgl_jit::FragmentKey::count)), each
//! band's thread adds its count to the counter as it leaves the draw, and a
//! query's result is read after the scene is flushed
//! ([`Context::query_result`](crate::Context::query_result) flushes). A
//! draw made with no query active counts nothing and its key has no
//! counting stage: queries cost nothing while none is active.

use crate::error::{GlError, GlResult};
use crate::names::Names;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;

/// The query targets of GL 1.5.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum QueryTarget {
    /// `GL_SAMPLES_PASSED`.
    SamplesPassed,
}

/// `glGetQueryObject*`'s names.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum QueryObjectParam {
    /// `GL_QUERY_RESULT`.
    Result,
    /// `GL_QUERY_RESULT_AVAILABLE`.
    ResultAvailable,
}

/// `glGetQueryiv`'s names.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum QueryParam {
    /// `GL_CURRENT_QUERY`: the active query's name, or 0.
    CurrentQuery,
    /// `GL_QUERY_COUNTER_BITS`: the counter's width.
    CounterBits,
}

/// Bits of a query's counter (llvmpipe's are 64 too: `PIPE_QUERY_OCCLUSION_COUNTER`).
pub const COUNTER_BITS: u32 = 64;

/// One query object.
#[derive(Debug)]
struct Query {
    /// The count so far: draws recorded while it was active add to it when
    /// they are rasterized.
    samples: Arc<AtomicU64>,
    /// Ended, and no flush asked for since ([`QueryStore::available`]).
    pending: bool,
}

/// The query objects of a context and the active one.
#[derive(Debug, Default)]
pub struct QueryStore {
    /// Every name in use: `None` for a name `gen` made and no `begin` used yet
    /// (GL 1.5: `glIsQuery` is false for it, its result an error).
    objects: Names<Query>,
    active: Option<u32>,
}

impl QueryStore {
    pub fn new() -> QueryStore {
        QueryStore::default()
    }

    /// `glGenQueries`: `n` names not in use (`None`: none left, [`Names::gen`]).
    pub fn gen(&mut self, n: usize) -> Option<Vec<u32>> {
        self.objects.gen(n)
    }

    /// `glDeleteQueries`: frees each name; the active query is ended first
    /// (as Mesa does, `queryobj.c`). 0 and unused names are ignored.
    pub fn delete(&mut self, names: &[u32]) {
        for name in names {
            if self.active == Some(*name) {
                self.active = None;
            }
            self.objects.remove(*name);
        }
    }

    /// `glIsQuery`: whether `name` is a query object that has been begun.
    pub fn is_query(&self, name: u32) -> bool {
        self.objects.get(name).is_some()
    }

    /// `glBeginQuery`: starts counting into `name` (made if need be), from 0.
    /// `GL_INVALID_OPERATION` for name 0 or while a query is active.
    pub fn begin(&mut self, _target: QueryTarget, name: u32) -> GlResult {
        if name == 0 || self.active.is_some() {
            return Err(GlError::InvalidOperation);
        }
        let q = self.objects.slot(name);
        // A new counter: draws of an earlier use of the name still waiting
        // to be rasterized add to the old one.
        *q = Some(Query {
            samples: Arc::new(AtomicU64::new(0)),
            pending: false,
        });
        self.active = Some(name);
        Ok(())
    }

    /// `glEndQuery`: `GL_INVALID_OPERATION` when no query is active.
    pub fn end(&mut self, _target: QueryTarget) -> GlResult {
        let name = self.active.take().ok_or(GlError::InvalidOperation)?;
        if let Some(q) = self.objects.get_mut(name) {
            q.pending = true;
        }
        Ok(())
    }

    /// `GL_QUERY_RESULT_AVAILABLE` as llvmpipe answers it
    /// (`llvmpipe_get_query_result` without waiting): the first time after
    /// the end, not yet (the caller flushes: the next answer is yes); then
    /// yes. With the errors of [`QueryStore::samples`].
    pub fn available(&mut self, name: u32) -> GlResult<bool> {
        self.samples(name)?;
        let q = self.objects.get_mut(name);
        let q = q.ok_or(GlError::InvalidOperation)?;
        Ok(!std::mem::replace(&mut q.pending, false))
    }

    /// Marks `name`'s result final (the scene was flushed for it).
    pub fn settled(&mut self, name: u32) {
        if let Some(q) = self.objects.get_mut(name) {
            q.pending = false;
        }
    }

    /// The active query's name.
    pub fn active(&self) -> Option<u32> {
        self.active
    }

    /// The counter draws made now add to: the active query's.
    pub fn counter(&self) -> Option<Arc<AtomicU64>> {
        let q = self.objects.get(self.active?)?;
        Some(q.samples.clone())
    }

    /// `glGetQueryiv`.
    pub fn param(&self, _target: QueryTarget, name: QueryParam) -> u64 {
        match name {
            QueryParam::CurrentQuery => u64::from(self.active.unwrap_or(0)),
            QueryParam::CounterBits => u64::from(COUNTER_BITS),
        }
    }

    /// The count of query `name` so far (complete once the draws made while
    /// it was active are rasterized). `GL_INVALID_OPERATION` for a name that
    /// is not a begun query, or the active one.
    pub fn samples(&self, name: u32) -> GlResult<u64> {
        if self.active == Some(name) {
            return Err(GlError::InvalidOperation);
        }
        let q = self.objects.get(name);
        Ok(q.ok_or(GlError::InvalidOperation)?.samples.load(Ordering::Relaxed))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_and_errors() {
        let mut q = QueryStore::new();
        assert_eq!(q.gen(2), Some(vec![1, 2]));
        assert!(!q.is_query(1), "not a query before its first begin");
        assert_eq!(q.samples(1), Err(GlError::InvalidOperation));
        assert_eq!(q.begin(QueryTarget::SamplesPassed, 0), Err(GlError::InvalidOperation));
        assert_eq!(q.end(QueryTarget::SamplesPassed), Err(GlError::InvalidOperation));
        q.begin(QueryTarget::SamplesPassed, 1).unwrap();
        assert_eq!(q.begin(QueryTarget::SamplesPassed, 2), Err(GlError::InvalidOperation));
        assert_eq!(q.param(QueryTarget::SamplesPassed, QueryParam::CurrentQuery), 1);
        assert_eq!(q.samples(1), Err(GlError::InvalidOperation), "active");
        q.counter().unwrap().fetch_add(7, Ordering::Relaxed);
        q.end(QueryTarget::SamplesPassed).unwrap();
        assert!(q.counter().is_none());
        assert_eq!(q.samples(1), Ok(7));
        assert!(q.is_query(1));
        q.begin(QueryTarget::SamplesPassed, 9).unwrap();
        q.delete(&[9, 1]);
        assert_eq!(q.active(), None, "deleting the active query ends it");
        assert!(!q.is_query(1) && !q.is_query(9));
    }
}
