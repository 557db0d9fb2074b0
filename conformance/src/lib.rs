//! softgl against Mesa: the same scenes rendered by softgl (interpreter and
//! JIT), by Mesa's OSMesa with llvmpipe and softpipe, and by lavapipe; how far
//! each lands from llvmpipe, and how long each takes.
//!
//! - [`call`]: the GL-shaped interface every back end replays;
//! - [`scenes`]: the scenes, each with its tolerance and the reason;
//! - [`backend`]: softgl in process, the references in child processes;
//! - [`metrics`]: distances between images;
//! - [`run`]: one scene on every back end, compared;
//! - [`report`]: `report.md`, `error_vs_time.png` and diff images;
//! - [`piglit`]: piglit's GL 1.x groups on softgl beside llvmpipe.

pub mod backend;
pub mod call;
pub mod metrics;
pub mod piglit;
pub mod report;
pub mod run;
pub mod scenes;
