//! One scene on every back end, each compared with llvmpipe.

use crate::backend::{Backend, Outcome};
use crate::call::Rec;
use crate::metrics::{compare, Metrics};
use crate::scenes::{Group, Scene, Tolerance};

/// The name of the reference back end.
pub const REFERENCE: &str = "llvmpipe";
/// The anchor: softgl should land no farther from llvmpipe than this.
pub const ANCHOR: &str = "softpipe";

/// One back end's result on one scene.
#[derive(Clone, Debug)]
pub struct BackendResult {
    pub backend: String,
    pub outcome: Outcome,
    /// Against llvmpipe (`None` if either did not render, or sizes differ).
    pub metrics: Option<Metrics>,
}

/// A scene on every back end.
#[derive(Clone, Debug)]
pub struct SceneResult {
    pub scene: &'static str,
    pub group: Group,
    pub tolerance: Tolerance,
    pub size: (u32, u32),
    pub results: Vec<BackendResult>,
}

impl SceneResult {
    pub fn get(&self, backend: &str) -> Option<&BackendResult> {
        self.results.iter().find(|r| r.backend == backend)
    }

    pub fn reference(&self) -> Option<&image::RgbaImage> {
        match &self.get(REFERENCE)?.outcome {
            Outcome::Rendered { image, .. } => Some(image),
            _ => None,
        }
    }

    /// Whether `backend` is within the scene's tolerance (`None`: not compared).
    pub fn within(&self, backend: &str) -> Option<bool> {
        let m = self.get(backend)?.metrics?;
        Some(within(&m, &self.tolerance))
    }

    /// Whether `backend` lands no farther from llvmpipe than softpipe does
    /// (mean absolute error and coverage both no larger).
    pub fn meets_anchor(&self, backend: &str) -> Option<bool> {
        let m = self.get(backend)?.metrics?;
        let a = self.get(ANCHOR)?.metrics?;
        Some(m.mae <= a.mae + 1e-12 && m.coverage <= a.coverage)
    }
}

/// The tolerance test softgl must pass.
pub fn within(m: &Metrics, t: &Tolerance) -> bool {
    m.share_over <= t.share_over && m.coverage <= t.coverage
}

/// Renders `scene` on every back end (llvmpipe among them) and compares.
pub fn run_scene(scene: &Scene, backends: &mut [Box<dyn Backend>], full: bool, runs: usize) -> SceneResult {
    let rec = scene.record(full);
    let background = Rec::background(&rec.calls);
    let mut results: Vec<BackendResult> = backends
        .iter_mut()
        .map(|b| BackendResult {
            backend: b.name().to_string(),
            outcome: b.render(scene, full, runs),
            metrics: None,
        })
        .collect();
    let reference = results
        .iter()
        .find(|r| r.backend == REFERENCE)
        .and_then(|r| match &r.outcome {
            Outcome::Rendered { image, .. } => Some(image.clone()),
            _ => None,
        });
    if let Some(reference) = reference {
        for r in &mut results {
            if let Outcome::Rendered { image, .. } = &r.outcome {
                r.metrics = compare(&reference, image, background, scene.tolerance.channel);
            }
        }
    }
    SceneResult {
        scene: scene.name,
        group: scene.group,
        tolerance: scene.tolerance,
        size: (rec.width, rec.height),
        results,
    }
}
