//! Every scene on every back end, at the tests' small sizes. Fails when
//! softgl is outside a scene's tolerance against llvmpipe, when softgl's
//! interpreter and JIT disagree, or when a reference that CI installs
//! (OSMesa llvmpipe and softpipe, lavapipe) is missing or fails.

use softgl_conformance::backend::child::{External, Reference};
use softgl_conformance::backend::{self, Outcome};
use softgl_conformance::run::run_scene;
use softgl_conformance::scenes::{self, Group};
use std::path::Path;

const EXE: &str = env!("CARGO_BIN_EXE_softgl-conformance");

#[test]
fn every_reference_is_installed() {
    for r in [Reference::Llvmpipe, Reference::Softpipe, Reference::Lavapipe] {
        match External::new(r, Path::new(EXE)).probe() {
            Ok(renderer) => assert!(!renderer.is_empty(), "{}: empty renderer string", r.name()),
            Err(e) => panic!(
                "{} is missing: {e}\n(.ci/run installs libosmesa6 and mesa-vulkan-drivers; install them)",
                r.name()
            ),
        }
    }
}

fn check_group(group: Group) {
    let mut backends = backend::all(Path::new(EXE));
    let mut problems = Vec::new();
    let scenes: Vec<_> = scenes::all().into_iter().filter(|s| s.group == group).collect();
    assert!(!scenes.is_empty());
    for scene in &scenes {
        let r = run_scene(scene, &mut backends, false, 0);
        for b in &r.results {
            match &b.outcome {
                Outcome::Failed(why) => problems.push(format!("{}: {} failed: {why}", r.scene, b.backend)),
                Outcome::Unsupported(why) if b.backend != "lavapipe" => {
                    problems.push(format!("{}: {} unsupported: {why}", r.scene, b.backend))
                }
                _ => {}
            }
        }
        for softgl in ["softgl-interp", "softgl-jit"] {
            match (r.within(softgl), r.get(softgl).and_then(|b| b.metrics)) {
                (Some(true), _) => {}
                (Some(false), Some(m)) => problems.push(format!(
                    "{}: {softgl} over tolerance: {} pixels over ±{} ({:.5} > {:.5}), coverage {} > {}, max diff {}",
                    r.scene,
                    m.over,
                    r.tolerance.channel,
                    m.share_over,
                    r.tolerance.share_over,
                    m.coverage,
                    r.tolerance.coverage,
                    m.max_diff
                )),
                _ => problems.push(format!("{}: {softgl} not compared with llvmpipe", r.scene)),
            }
        }
        let image = |name: &str| match r.get(name).map(|b| &b.outcome) {
            Some(Outcome::Rendered { image, .. }) => Some(image.clone()),
            _ => None,
        };
        if image("softgl-interp") != image("softgl-jit") {
            problems.push(format!("{}: softgl's interpreter and JIT images differ", r.scene));
        }
    }
    assert!(
        problems.is_empty(),
        "{} problems:\n{}",
        problems.len(),
        problems.join("\n")
    );
}

#[test]
fn stages_alone() {
    check_group(Group::Stage);
}

#[test]
fn combinations() {
    check_group(Group::Combination);
}

#[test]
fn primitives() {
    check_group(Group::Primitive);
}

#[test]
fn stiff_and_extreme() {
    check_group(Group::Stiff);
}

#[test]
fn timing_scenes_small() {
    check_group(Group::Timing);
}
