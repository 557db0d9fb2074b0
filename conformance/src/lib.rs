//! softgl against Mesa: the same scenes rendered by softgl (interpreter and
//! JIT), by Mesa's OSMesa with llvmpipe and softpipe, and by lavapipe; how far
//! each lands from the scene's reference (llvmpipe, or an exact oracle where
//! Mesa is known to be wrong), and how long each takes.
//!
//! - [`call`]: the GL-shaped interface every back end replays;
//! - [`scenes`]: the scenes, each with its tolerance and the reason (and
//!   [`scenes::oracle`], the exact answers; [`scenes::glu`], the mipmaps
//!   `gluBuild2DMipmaps` makes);
//! - [`backend`]: softgl in process, the references in child processes;
//! - [`metrics`]: distances between images;
//! - [`missing`]: what a check does when a reference is not installed;
//! - [`run`]: one scene on every back end, compared;
//! - [`report`]: `report.md`, `error_vs_time.png`, `backends.png` and diff images;
//! - [`piglit`]: piglit's GL 1.x groups on softgl beside llvmpipe.

pub mod backend;
pub mod call;
pub mod metrics;
pub mod missing;
pub mod piglit;
pub mod report;
pub mod run;
pub mod scenes;
