//! The back ends. Each renders a [`Scene`] to an image and times it.
//!
//! softgl runs in process. Mesa's drivers run in a child process of the
//! harness each (OSMesa picks its Gallium driver when it loads, and a crash
//! in a reference must not take the report down): see [`child`].

pub mod child;
pub mod osmesa;
pub mod softgl;
pub mod vulkan;

use crate::missing::Missing;
use crate::scenes::Scene;
use image::RgbaImage;
use std::time::Duration;

/// How long a scene took on a back end.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Timing {
    /// The first frame in a fresh context: includes every compile the back
    /// end does (Mesa's on-disk shader cache is disabled).
    pub first: Duration,
    /// The median of the frames after the first (equal to `first` when no
    /// further frames ran).
    pub steady: Duration,
    /// Frames in the median.
    pub runs: usize,
}

/// What softgl's JIT compiled for a scene (its specialist cache counters).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Compiles {
    /// Specialists compiled in the first frame.
    pub first: u64,
    /// Specialists compiled in all later frames (0 when the cache holds them all).
    pub later: u64,
    /// Keys that failed to compile and ran on the interpreter.
    pub failures: u64,
    /// Time spent compiling in the first frame.
    pub first_time: Duration,
}

/// What a back end made of a scene.
#[derive(Clone, Debug)]
pub enum Outcome {
    Rendered {
        image: RgbaImage,
        timing: Timing,
        /// softgl's JIT only.
        compiles: Option<Compiles>,
    },
    /// The scene uses something this back end cannot express.
    Unsupported(String),
    /// The back end failed or crashed on the scene.
    Failed(String),
}

/// One renderer the harness compares.
pub trait Backend {
    /// A short name for tables ("llvmpipe", "softgl-jit").
    fn name(&self) -> &str;
    /// Renders `scene` at its report (`full`) or test size: one first frame,
    /// then `runs` more for the steady-state median.
    fn render(&mut self, scene: &Scene, full: bool, runs: usize) -> Outcome;
    /// Whether the back end is there: what it calls itself, or why not.
    fn probe(&self) -> Result<String, Unavailable>;
}

/// Why a back end cannot render.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Unavailable {
    /// Not installed: the checks that need it are skipped (failed under
    /// `SOFTGL_REQUIRE_REFERENCES=1`; see [`crate::missing`]).
    Missing(Missing),
    /// Installed, but it does not work (a crash, the wrong driver): a failure.
    Broken(String),
}

impl std::fmt::Display for Unavailable {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Unavailable::Missing(m) => write!(f, "{} not found — {}", m.what, m.install),
            Unavailable::Broken(why) => f.write_str(why),
        }
    }
}

/// The median of `t` (empty: zero).
impl Timing {
    /// The first frame and the median of the `runs` frames after it in `times`.
    pub fn measured(first: Duration, mut times: Vec<Duration>, runs: usize) -> Timing {
        let steady = if runs == 0 { first } else { median(&mut times) };
        Timing { first, steady, runs }
    }
}

/// The median of `t` (zero when empty).
pub fn median(t: &mut [Duration]) -> Duration {
    t.sort();
    t.get(t.len() / 2).copied().unwrap_or_default()
}

/// Every back end, the reference (llvmpipe) first. `exe` is the harness
/// binary, re-run as the child for Mesa's drivers.
pub fn all(exe: &std::path::Path) -> Vec<Box<dyn Backend>> {
    vec![
        Box::new(child::External::new(child::Reference::Llvmpipe, exe)),
        Box::new(child::External::new(child::Reference::Softpipe, exe)),
        Box::new(child::External::new(child::Reference::Lavapipe, exe)),
        Box::new(softgl::Softgl::new(::softgl::Backend::Interpreter)),
        Box::new(softgl::Softgl::new(::softgl::Backend::Jit)),
    ]
}
