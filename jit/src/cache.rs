//! The specialist cache: the most recently used specialists, keyed by [`FragmentKey`].

use crate::key::FragmentKey;
use crate::specialist::{Specialist, SpecialistError};
use crate::tier::Tier;
use lru::LruCache;
use std::num::NonZeroUsize;
use std::sync::Arc;
use std::time::{Duration, Instant};

/// Specialists kept when neither the API nor `SOFTGL_SPECIALISTS` says
/// otherwise: llvmpipe keeps 1024 shader variants a context
/// (`LP_MAX_SHADER_VARIANTS`, `lp_limits.h`; facts §22). With 64, a frame of
/// 256 states recompiled every state every frame (318 ms against 62 ms).
pub const DEFAULT_CAPACITY: usize = 1024;

/// Compile times kept for the median: the most recent ones.
const MEDIAN_WINDOW: usize = 4096;

/// What the cache has done so far.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct CacheStats {
    /// Lookups that found the key (compiled or known to fail).
    pub hits: u64,
    /// Lookups that had to compile.
    pub misses: u64,
    /// Specialists dropped (and their code freed) to make room.
    pub evictions: u64,
    /// Keys that failed to compile: their draws ran on the interpreter.
    pub failures: u64,
    /// Specialists held now.
    pub resident: usize,
    pub capacity: usize,
    /// Optimized code installed by the background thread in specialists of
    /// this cache ([`crate::Tier::Tiered`]), resident or evicted since.
    pub upgrades: u64,
    /// Time draws waited for compiles, in all (for a tiered key, its quick
    /// compile: the optimized one runs on the background thread).
    pub total_compile: Duration,
    /// Median time a draw waited for one compile (over the last 4096), if any happened.
    pub median_compile: Option<Duration>,
}

/// An LRU cache of specialists. A key that failed to compile is remembered as
/// failed (so it is not compiled again on every draw) until it is evicted.
pub struct SpecialistCache {
    lru: LruCache<FragmentKey, Option<Arc<Specialist>>>,
    stats: CacheStats,
    compile_ns: Vec<u64>,
    compiler: Compiler,
    /// A tier every key is compiled in, else each key's own ([`Tier::for_key`]).
    tier: Option<Tier>,
    /// The key asked for last and its entry: draw after draw asks for the
    /// same key, and comparing it is cheaper than hashing it (1.6 k of the
    /// 10 k instructions of a culled `glBegin`/`glEnd` quad went to the hash
    /// and the LRU look-up). Cleared at every eviction.
    last: Option<(FragmentKey, Option<Arc<Specialist>>)>,
}

/// How a cache makes a specialist from a key.
pub type Compiler = fn(&FragmentKey) -> Result<Specialist, SpecialistError>;

impl SpecialistCache {
    /// A cache holding at most `capacity` specialists (at least one).
    pub fn new(capacity: usize) -> SpecialistCache {
        SpecialistCache::with_compiler(capacity, Specialist::compile)
    }

    /// A cache that makes specialists with `compiler` (tests use it to make
    /// compiles fail; the normal one is [`Specialist::compile`]).
    pub fn with_compiler(capacity: usize, compiler: Compiler) -> SpecialistCache {
        let cap = NonZeroUsize::new(capacity).unwrap_or(NonZeroUsize::MIN);
        SpecialistCache {
            lru: LruCache::new(cap),
            stats: CacheStats {
                capacity: cap.get(),
                ..CacheStats::default()
            },
            compile_ns: Vec::new(),
            compiler,
            tier: None,
            last: None,
        }
    }

    /// Compiles every key from now on in `tier` (`None`: each key's own,
    /// [`Tier::for_key`]); tests use [`Tier::Optimized`] to check the code
    /// a draw runs once its upgrade is in. Specialists already held stay.
    pub fn set_tier(&mut self, tier: Option<Tier>) {
        self.tier = tier;
    }

    /// A cache of `SOFTGL_SPECIALISTS` specialists, else [`DEFAULT_CAPACITY`].
    pub fn from_env() -> SpecialistCache {
        SpecialistCache::new(capacity_from(std::env::var("SOFTGL_SPECIALISTS").ok().as_deref()))
    }

    /// Changes the capacity; specialists beyond it are evicted, least recent first.
    pub fn set_capacity(&mut self, capacity: usize) {
        let cap = NonZeroUsize::new(capacity).unwrap_or(NonZeroUsize::MIN);
        while self.lru.len() > cap.get() {
            if let Some((_, evicted)) = self.lru.pop_lru() {
                self.evict(evicted);
            }
        }
        self.lru.resize(cap);
        self.stats.capacity = cap.get();
    }

    /// Counts `evicted`'s leaving, and frees it.
    fn evict(&mut self, evicted: Option<Arc<Specialist>>) {
        self.last = None;
        self.stats.evictions += 1;
        self.stats.upgrades += u64::from(evicted.as_deref().is_some_and(Specialist::is_upgraded));
    }

    /// The specialist for `key` (a normalized, valid key), compiling it on a miss;
    /// `None` when it cannot be compiled. Shared: a deferred draw keeps its
    /// specialist alive (and its code mapped) after an eviction.
    pub fn get(&mut self, key: &FragmentKey) -> Option<&Arc<Specialist>> {
        // The most recent entry already: no hash, and the LRU order stays.
        if self.last.as_ref().is_some_and(|(k, _)| k == key) {
            self.stats.hits += 1;
            return self.last.as_ref().and_then(|(_, s)| s.as_ref());
        }
        if self.lru.contains(key) {
            self.stats.hits += 1;
        } else {
            self.stats.misses += 1;
            let start = Instant::now();
            let compiled = match self.tier {
                Some(tier) => Specialist::compile_tier(key, tier),
                None => (self.compiler)(key),
            }
            .ok()
            .map(Arc::new);
            let took = start.elapsed();
            self.stats.total_compile += took;
            let ns = took.as_nanos() as u64;
            if self.compile_ns.len() < MEDIAN_WINDOW {
                self.compile_ns.push(ns);
            } else {
                self.compile_ns[(self.stats.misses as usize) % MEDIAN_WINDOW] = ns;
            }
            if compiled.is_none() {
                self.stats.failures += 1;
            }
            if let Some((k, evicted)) = self.lru.push(*key, compiled) {
                if k != *key {
                    self.evict(evicted);
                }
            }
        }
        let entry = self.lru.get(key).cloned().flatten();
        self.last = Some((*key, entry));
        self.last.as_ref().and_then(|(_, s)| s.as_ref())
    }

    /// The counters, with the median compile time.
    pub fn stats(&self) -> CacheStats {
        let mut ns = self.compile_ns.clone();
        ns.sort_unstable();
        let upgraded = self
            .lru
            .iter()
            .filter(|(_, s)| s.as_deref().is_some_and(Specialist::is_upgraded));
        CacheStats {
            resident: self.lru.len(),
            upgrades: self.stats.upgrades + upgraded.count() as u64,
            median_compile: ns.get(ns.len() / 2).map(|&n| Duration::from_nanos(n)),
            ..self.stats.clone()
        }
    }
}

/// The capacity a `SOFTGL_SPECIALISTS` value asks for: a positive integer, else
/// [`DEFAULT_CAPACITY`].
pub fn capacity_from(value: Option<&str>) -> usize {
    value
        .and_then(|v| v.trim().parse().ok())
        .filter(|&n: &usize| n > 0)
        .unwrap_or(DEFAULT_CAPACITY)
}

impl std::fmt::Debug for SpecialistCache {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("SpecialistCache").field("stats", &self.stats()).finish()
    }
}
