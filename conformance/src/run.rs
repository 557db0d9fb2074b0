//! One scene on every back end, each compared with the scene's reference:
//! llvmpipe, or the scene's exact oracle when it has one.

use crate::backend::{Backend, Outcome};
use crate::call::Rec;
use crate::metrics::{compare, Metrics};
use crate::scenes::{Group, Scene, Tolerance};
use image::RgbaImage;

/// The name of the reference back end.
pub const REFERENCE: &str = "llvmpipe";
/// The reference of scenes with an exact oracle (not a back end).
pub const ORACLE: &str = "oracle";
/// The anchor: softgl should land no farther from the reference than this.
pub const ANCHOR: &str = "softpipe";

/// One back end's result on one scene.
#[derive(Clone, Debug)]
pub struct BackendResult {
    pub backend: String,
    pub outcome: Outcome,
    /// Against the reference (`None` if either did not render, or sizes differ).
    pub metrics: Option<Metrics>,
}

/// A scene on every back end.
#[derive(Clone, Debug)]
pub struct SceneResult {
    pub scene: &'static str,
    pub group: Group,
    pub tolerance: Tolerance,
    pub size: (u32, u32),
    /// The report's size (true) or the tests'.
    pub full: bool,
    /// What the metrics are against: [`REFERENCE`] or [`ORACLE`].
    pub reference: &'static str,
    /// The oracle's image, for scenes that have one.
    pub oracle: Option<RgbaImage>,
    pub results: Vec<BackendResult>,
}

impl SceneResult {
    pub fn get(&self, backend: &str) -> Option<&BackendResult> {
        self.results.iter().find(|r| r.backend == backend)
    }

    /// The image every back end is compared with.
    pub fn reference(&self) -> Option<&RgbaImage> {
        if let Some(o) = &self.oracle {
            return Some(o);
        }
        match &self.get(REFERENCE)?.outcome {
            Outcome::Rendered { image, .. } => Some(image),
            _ => None,
        }
    }

    /// Whether `backend` is what the others are compared with.
    pub fn is_reference(&self, backend: &str) -> bool {
        backend == self.reference
    }

    /// Whether `backend` is within the scene's tolerance (`None`: not compared).
    pub fn within(&self, backend: &str) -> Option<bool> {
        self.get(backend)?.metrics?;
        Some(self.check(backend).is_ok())
    }

    /// `Ok` when `backend` is within the scene's tolerance; else what is over
    /// (or that it was not compared).
    pub fn check(&self, backend: &str) -> Result<(), String> {
        let Some(m) = self.get(backend).and_then(|r| r.metrics) else {
            return Err(format!("not compared with {}", self.reference));
        };
        let t = &self.tolerance;
        let near = t.near(self.full);
        let mut over = Vec::new();
        if m.share_over > t.share_over {
            over.push(format!(
                "{} pixels over ±{} ({:.5} > {:.5} of all), max diff {}",
                m.over, t.channel, m.share_over, t.share_over, m.max_diff
            ));
        }
        if m.near > near {
            over.push(format!("{} pixels 1..={} off (budget {near})", m.near, t.channel));
        }
        if m.coverage > t.coverage {
            over.push(format!("coverage {} > {}", m.coverage, t.coverage));
        }
        if over.is_empty() {
            Ok(())
        } else {
            Err(format!(
                "over tolerance against {}: {}",
                self.reference,
                over.join(", ")
            ))
        }
    }

    /// Whether `backend` lands no farther from the reference than softpipe
    /// does (mean absolute error and coverage both no larger).
    pub fn meets_anchor(&self, backend: &str) -> Option<bool> {
        let m = self.get(backend)?.metrics?;
        let a = self.get(ANCHOR)?.metrics?;
        Some(m.mae <= a.mae + 1e-12 && m.coverage <= a.coverage)
    }
}

/// Renders `scene` on every back end (llvmpipe among them) and compares
/// each with the scene's reference.
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
    let mut result = SceneResult {
        scene: scene.name,
        group: scene.group,
        tolerance: scene.tolerance,
        size: (rec.width, rec.height),
        full,
        reference: if scene.oracle.is_some() { ORACLE } else { REFERENCE },
        oracle: scene.oracle.map(|o| o(scene.size(full))),
        results: Vec::new(),
    };
    if let Some(reference) = result.reference().cloned().or_else(|| {
        results
            .iter()
            .find(|r| r.backend == REFERENCE)
            .and_then(|r| match &r.outcome {
                Outcome::Rendered { image, .. } => Some(image.clone()),
                _ => None,
            })
    }) {
        for r in &mut results {
            if let Outcome::Rendered { image, .. } = &r.outcome {
                r.metrics = compare(&reference, image, background, scene.tolerance.channel);
            }
        }
    }
    result.results = results;
    result
}
