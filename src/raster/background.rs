//! Flushes in the background: a scene that passes its bound in the middle
//! of a frame is rasterized on the pool while the calling thread goes on
//! taking GL calls and recording the next scene. This is llvmpipe's thread
//! model: `LP_NUM_THREADS=N` starts N rasterizer threads beside the
//! application's, which bins scene N+1 while they run scene N
//! (`lp_rast_queue_scene`, `lp_rast.c`: only `LP_NUM_THREADS=0` rasterizes
//! on the calling thread; `ps -L` shows `llvmpipe-0` busy beside the client
//! with `LP_NUM_THREADS=1`; docs/llvmpipe-facts.md). `SOFTGL_THREADS=N`
//! runs tiles on N threads the same way: a background flush on a pool of
//! N - 1 threads (one at least) while the caller records, on N once the
//! caller waits for it ([`Background::join`], `scene::helped`: with two
//! threads the waiting caller's core stayed idle, and MuJoCo's light
//! passes, flushed in the background, ran on one thread), and the flush
//! that ends a frame on N threads, the caller among them, while it waits.
//! A frame of many small primitives is mostly front end (vertex work,
//! set-up, binning: two thirds of `fill.c lit16`), which before ran alone
//! while the tiles waited. `lit16`, medians of 3 interleaved runs: one
//! thread 172 -> 124-128 ms a frame (llvmpipe 147-167), two threads ~167 ->
//! 122-126 (llvmpipe 125-131).
//!
//! The scene and the framebuffer's buffers move to the pool and back: the
//! context keeps a hollow framebuffer of the same size and formats
//! ([`Framebuffer::hollow`]) to record with, and every path that reads or
//! writes pixels (a flush, `glReadPixels`, handing out the buffers, a
//! make-current, a texture write a scene may read, a context's end) first
//! waits for the flush in flight ([`Background::join`]) and gets the real
//! buffers back. At most one flush is in flight, so at most two scenes are
//! held. Tiles still run in recorded order, each owned by one thread, so
//! the bytes are those of a flush made at once.

use super::pool;
use super::scene::Scene;
use crate::framebuffer::Framebuffer;
use softgl_jit::FragmentError;
use std::panic::{catch_unwind, resume_unwind, AssertUnwindSafe};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{sync_channel, Receiver};
use std::sync::Arc;

/// What a background flush hands back: the scene (emptied, kept for the
/// next swap), the framebuffer with its buffers, and how the flush ended
/// (a panic is raised again on the thread that waits for it).
struct Done {
    scene: Scene,
    fb: Framebuffer,
    result: std::thread::Result<Result<(), FragmentError>>,
}

/// A context's flush in flight, if any, and the spare scene the next one
/// swaps in.
#[derive(Debug, Default)]
pub struct Background {
    /// The flush in flight: its buffers come back on the channel; setting
    /// the flag asks it to run on all the threads (the caller waits).
    inflight: Option<(Receiver<Done>, Arc<AtomicBool>)>,
    spare: Option<Scene>,
}

impl Background {
    /// Waits for the flush in flight, if any, and puts its framebuffer
    /// back into `fb`. Returns that flush's first error; a panic in it is
    /// raised again here.
    pub fn join(&mut self, fb: &mut Framebuffer) -> Result<(), FragmentError> {
        self.settle(fb).unwrap_or_else(|panic| resume_unwind(panic))
    }

    /// Lets the flush in flight, if any, take every thread from now on:
    /// the caller will wait for it ([`Background::join`] does this too).
    /// Called for every sample's flush before the first is waited for.
    pub fn hurry(&self) {
        if let Some((_, help)) = &self.inflight {
            help.store(true, Ordering::Release);
        }
    }

    /// [`Background::join`] handing a panic back rather than raising it
    /// (for a context's drop, which must not panic).
    pub fn settle(&mut self, fb: &mut Framebuffer) -> std::thread::Result<Result<(), FragmentError>> {
        let Some((rx, help)) = self.inflight.take() else {
            return Ok(Ok(()));
        };
        // The caller waits: the flush may take the caller's core too.
        help.store(true, Ordering::Release);
        // The job always sends: its flush runs under `catch_unwind`, and
        // the pools live as long as the process.
        let done = rx.recv().expect("a background flush hands its buffers back");
        *fb = done.fb;
        self.spare = Some(done.scene);
        done.result
    }

    /// Flushes `scene` into `fb` on a pool of `threads - 1` threads while
    /// the caller records into a fresh scene (swapped into `scene`), after
    /// the flush before it, whose error it returns. Without a pool it
    /// flushes at once.
    pub fn start(&mut self, scene: &mut Scene, fb: &mut Framebuffer, threads: usize) -> Result<(), FragmentError> {
        let before = self.join(fb);
        // The caller keeps a core for itself: with the flush on all of
        // them, its recording (the critical path) had two thirds of a core,
        // and `lit16` with 16 MiB scenes took 153-193 ms a frame against
        // 122-138 (2 threads, interleaved runs).
        // Until the caller waits for it ([`Background::join`]): then on
        // `threads` (`scene::helped`).
        let all = threads.max(1);
        let threads = threads.saturating_sub(1).max(1);
        let Some(pool) = pool::pool(threads) else {
            return before.and(scene.flush(fb, threads));
        };
        let mut full = scene.swap_out(self.spare.take().unwrap_or_default());
        let mut real = std::mem::replace(fb, fb.hollow());
        let (tx, rx) = sync_channel(1);
        let help = Arc::new(AtomicBool::new(false));
        let asked = Arc::clone(&help);
        pool.spawn(move || {
            // The flush runs its bands on this thread, and on the pool of
            // `all` threads as `scene::helped` says.
            let result = catch_unwind(AssertUnwindSafe(|| full.flush_helped(&mut real, all, Some(&asked))));
            // The receiver is gone only when the context was dropped
            // mid-unwind; the buffers are dropped here then.
            let _ = tx.send(Done {
                scene: full,
                fb: real,
                result,
            });
        });
        self.inflight = Some((rx, help));
        before
    }
}

impl Drop for Background {
    /// Waits for the flush in flight: nothing writes a context's buffers
    /// (lent memory too) after the context is gone.
    fn drop(&mut self) {
        if let Some((rx, help)) = self.inflight.take() {
            help.store(true, Ordering::Release);
            let _ = rx.recv();
        }
    }
}
