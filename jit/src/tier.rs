//! Tiered compilation: how a key is compiled first, and the one background
//! thread that compiles the optimized tier.
//!
//! A key with texture units takes 0.3–2 ms to compile with the natively
//! sampled texture stage and the backtracking register allocator (figures in
//! [`crate::compile::host_isa_with`]). The draw that meets a new textured key
//! waits only for the quick code: single-pass register allocation, and every
//! unit sampled by the reference sampler through the callout (the code of a
//! key without texturing, about 100 µs). That code samples at the
//! interpreter's speed; the optimized code (native sampling, backtracking) is
//! compiled on one background thread and installed in the specialist when
//! ready, a millisecond or two later, between two batches of a draw.

use crate::compile::RegAlloc;
use crate::key::FragmentKey;
use std::sync::mpsc::{self, Sender};
use std::sync::{Mutex, OnceLock, PoisonError};

/// How a specialist is compiled.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Tier {
    /// Single-pass register allocation and every texture unit through the
    /// callout only: the fastest compile, the slowest texturing.
    Quick,
    /// Native sampling and backtracking register allocation only: what a key
    /// without texture units gets.
    Optimized,
    /// [`Tier::Quick`] now, then [`Tier::Optimized`] on the background thread,
    /// installed when ready: what a key with texture units gets.
    Tiered,
}

impl Tier {
    /// The tier [`crate::Specialist::compile`] uses for `key`: the one
    /// `SOFTGL_JIT_TIER` (`quick`, `optimized` or `tiered`) names, for every key;
    /// else [`Tier::Tiered`] for keys with texture units and [`Tier::Optimized`]
    /// for the others.
    pub fn for_key(key: &FragmentKey) -> Tier {
        static FORCED: OnceLock<Option<Tier>> = OnceLock::new();
        let forced = *FORCED.get_or_init(|| Tier::parse(std::env::var("SOFTGL_JIT_TIER").ok().as_deref()));
        forced.unwrap_or(if key.shade.is_some_and(|s| s.textured()) {
            Tier::Tiered
        } else {
            Tier::Optimized
        })
    }

    /// The tier a `SOFTGL_JIT_TIER` value names, if any.
    pub fn parse(value: Option<&str>) -> Option<Tier> {
        match value?.trim().to_ascii_lowercase().as_str() {
            "quick" => Some(Tier::Quick),
            "optimized" => Some(Tier::Optimized),
            "tiered" => Some(Tier::Tiered),
            _ => None,
        }
    }

    /// The register allocator of the code a specialist of this tier runs first.
    pub fn first(self) -> RegAlloc {
        match self {
            Tier::Quick | Tier::Tiered => RegAlloc::SinglePass,
            Tier::Optimized => RegAlloc::Backtracking,
        }
    }
}

/// Work for the background thread.
pub(crate) type Job = Box<dyn FnOnce() + Send>;

/// Queues `job` on the one background compile thread (started on first use,
/// and again in a child process after a `fork`, which copies no threads),
/// which runs jobs one at a time in the order queued. Gives the job back when
/// the thread cannot be started or has stopped.
pub(crate) fn background(job: Job) -> Result<(), Job> {
    static QUEUE: Mutex<Option<(u32, Sender<Job>)>> = Mutex::new(None);
    let mut queue = QUEUE.lock().unwrap_or_else(PoisonError::into_inner);
    let pid = std::process::id();
    if queue.as_ref().is_none_or(|(started_in, _)| *started_in != pid) {
        let (tx, rx) = mpsc::channel::<Job>();
        let spawned = std::thread::Builder::new()
            .name("softgl-jit-tier2".into())
            .spawn(move || rx.into_iter().for_each(|job| job()));
        *queue = spawned.ok().map(|_| (pid, tx));
    }
    match queue.as_ref() {
        Some((_, tx)) => tx.send(job).map_err(|e| e.0),
        None => Err(job),
    }
}
