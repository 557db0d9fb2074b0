//! The rasterizer's threads: a private pool per thread count, made on first
//! use and kept for the process (never the application's global rayon pool).
//! `SOFTGL_THREADS=N` sets a context's default; without it, the cores.

use rayon::prelude::*;
use rayon::ThreadPool;
use std::sync::{Arc, Mutex, OnceLock, PoisonError};

/// Most threads a context may ask for.
pub const MAX_THREADS: usize = 64;

/// The thread count `SOFTGL_THREADS` asks for (1 to [`MAX_THREADS`]), else
/// the number of cores.
pub fn default_threads() -> usize {
    threads_from(std::env::var("SOFTGL_THREADS").ok().as_deref())
}

/// The thread count a `SOFTGL_THREADS` value asks for.
pub fn threads_from(value: Option<&str>) -> usize {
    value
        .and_then(|v| v.trim().parse::<usize>().ok())
        .filter(|&n| n > 0)
        .unwrap_or_else(cores)
        .min(MAX_THREADS)
}

/// The cores this process may run on, asked once: `available_parallelism`
/// reads the cgroup's CPU quota from files, which every context creation
/// would otherwise pay for.
fn cores() -> usize {
    static CORES: OnceLock<usize> = OnceLock::new();
    *CORES.get_or_init(|| std::thread::available_parallelism().map_or(1, usize::from))
}

/// The pools made so far, by thread count.
type Pools = Mutex<Vec<(usize, Arc<ThreadPool>)>>;

/// The private pool of `threads` threads, made on first use; `None` when
/// its threads could not be started.
pub(crate) fn pool(threads: usize) -> Option<Arc<ThreadPool>> {
    static POOLS: OnceLock<Pools> = OnceLock::new();
    let mut pools = POOLS
        .get_or_init(|| Mutex::new(Vec::new()))
        .lock()
        .unwrap_or_else(PoisonError::into_inner);
    if let Some((_, p)) = pools.iter().find(|(n, _)| *n == threads) {
        return Some(Arc::clone(p));
    }
    let p = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .thread_name(|i| format!("softgl-raster-{i}"))
        .build()
        .ok()?;
    let p = Arc::new(p);
    pools.push((threads, Arc::clone(&p)));
    Some(p)
}

/// Runs `f` over `work` on `threads` threads, one item per task; the results
/// in `work`'s order. Without a pool (threads could not be started) the
/// calling thread runs them all.
pub fn run<T: Send, R: Send>(threads: usize, work: Vec<T>, f: impl Fn(T) -> R + Sync + Send) -> Vec<R> {
    match pool(threads) {
        Some(p) => p.install(|| work.into_par_iter().with_max_len(1).map(f).collect()),
        None => work.into_iter().map(f).collect(),
    }
}
