//! Every scene on every back end, at the tests' small sizes. Fails when
//! softgl is outside a scene's tolerance against its reference (llvmpipe, or
//! the exact oracle of the scenes that have one), when softgl's interpreter
//! and JIT disagree, or when a reference that is installed fails a scene.
//!
//! A reference that is not installed (Mesa's `libOSMesa.so.8` for llvmpipe
//! and softpipe, lavapipe's Vulkan driver) is skipped with one loud line
//! saying how to install it (a failure under `SOFTGL_REQUIRE_REFERENCES=1`,
//! see `softgl_conformance::missing`); what was skipped is summed up once,
//! at the end. Hence a harness of its own (`harness = false`): libtest runs
//! tests in parallel threads and has no "after all tests". It takes libtest's
//! name filters (`cargo test -p softgl-conformance -- stages`), `--exact`,
//! `--skip NAME`, `--list` and `--test-threads N`.

use softgl_conformance::backend::child::{External, Reference};
use softgl_conformance::backend::{self, Backend, Outcome, Unavailable};
use softgl_conformance::missing::{self, Missing};
use softgl_conformance::run::{run_scene, REFERENCE};
use softgl_conformance::scenes::{self, Group};
use std::path::Path;
use std::process::ExitCode;
use std::sync::Mutex;

const EXE: &str = env!("CARGO_BIN_EXE_softgl-conformance");

const GROUPS: [(&str, Group); 10] = [
    ("stages_alone", Group::Stage),
    ("combinations", Group::Combination),
    ("primitives", Group::Primitive),
    ("stiff_and_extreme", Group::Stiff),
    ("timing_scenes_small", Group::Timing),
    ("fog_and_color_sum", Group::Fog),
    ("lighting_and_clip_planes", Group::Lighting),
    ("texturing", Group::Texture),
    ("framebuffer_objects_and_queries", Group::Framebuffer),
    ("bitmaps_and_pixel_paths", Group::Pixels),
];

/// The test that probes the references.
const PROBE: &str = "references_are_installed";

/// What the references' probes found, once for every group.
struct Found {
    /// The references that work.
    present: Vec<Reference>,
    /// Those not installed.
    missing: Vec<(Reference, Missing)>,
    /// Installed and broken: failures.
    broken: Vec<String>,
}

fn probe_references() -> Found {
    let mut found = Found {
        present: Vec::new(),
        missing: Vec::new(),
        broken: Vec::new(),
    };
    for r in [Reference::Llvmpipe, Reference::Softpipe, Reference::Lavapipe] {
        match External::new(r, Path::new(EXE)).probe() {
            Ok(renderer) if renderer.is_empty() => found.broken.push(format!("{}: empty renderer string", r.name())),
            Ok(_) => found.present.push(r),
            Err(Unavailable::Missing(m)) => found.missing.push((r, m)),
            Err(Unavailable::Broken(why)) => found
                .broken
                .push(format!("{} is installed but broken: {why}", r.name())),
        }
    }
    found
}

/// The probe as a test: broken references fail; missing ones are skipped
/// (each with its line), or fail when references are required.
fn references(found: &Found) {
    for (r, m) in &found.missing {
        m.skip(&format!("{} comparison", r.name()));
    }
    assert!(found.broken.is_empty(), "{}", found.broken.join("\n"));
}

/// The back ends to run: softgl's two, and every reference that is there.
fn backends(found: &Found) -> Vec<Box<dyn Backend>> {
    backend::all(Path::new(EXE))
        .into_iter()
        .filter(|b| Reference::parse(b.name()).is_none_or(|r| found.present.contains(&r)))
        .collect()
}

fn check_group(group: Group, found: &Found) {
    let mut backends = backends(found);
    let llvmpipe = found.present.contains(&Reference::Llvmpipe);
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
        // Without llvmpipe only the scenes with an exact oracle are judged.
        if llvmpipe || r.reference != REFERENCE {
            for softgl in ["softgl-interp", "softgl-jit"] {
                if let Err(why) = r.check(softgl) {
                    problems.push(format!("{}: {softgl} {why}", r.scene));
                }
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

/// libtest's command line, as far as this harness needs it.
struct Args {
    filters: Vec<String>,
    skip: Vec<String>,
    exact: bool,
    list: bool,
    ignored: bool,
    threads: usize,
}

fn args() -> Args {
    let mut a = Args {
        filters: Vec::new(),
        skip: Vec::new(),
        exact: false,
        list: false,
        ignored: false,
        threads: std::env::var("RUST_TEST_THREADS")
            .ok()
            .and_then(|n| n.parse().ok())
            .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get())),
    };
    let mut it = std::env::args().skip(1);
    while let Some(arg) = it.next() {
        match arg.as_str() {
            "--exact" => a.exact = true,
            "--list" => a.list = true,
            "--ignored" => a.ignored = true,
            "--skip" => a.skip.extend(it.next()),
            "--test-threads" => a.threads = it.next().and_then(|n| n.parse().ok()).unwrap_or(a.threads),
            // Options with a value that change nothing here.
            "--format" | "--color" | "--logfile" | "-Z" | "--shuffle-seed" => {
                it.next();
            }
            _ if arg.starts_with('-') => {}
            _ => a.filters.push(arg),
        }
    }
    a
}

impl Args {
    fn selects(&self, name: &str) -> bool {
        let hit = |f: &String| {
            if self.exact {
                name == f
            } else {
                name.contains(f.as_str())
            }
        };
        !self.ignored && (self.filters.is_empty() || self.filters.iter().any(hit)) && !self.skip.iter().any(hit)
    }
}

fn main() -> ExitCode {
    let args = args();
    let names: Vec<&str> = std::iter::once(PROBE).chain(GROUPS.map(|g| g.0)).collect();
    if args.list {
        for n in &names {
            println!("{n}: test");
        }
        return ExitCode::SUCCESS;
    }
    let selected: Vec<&str> = names.into_iter().filter(|n| args.selects(n)).collect();
    println!("\nrunning {} tests", selected.len());
    if selected.is_empty() {
        return ExitCode::SUCCESS;
    }
    let found = probe_references();
    let queue = Mutex::new(selected.clone());
    let failures = Mutex::new(Vec::new());
    std::thread::scope(|s| {
        for _ in 0..args.threads.clamp(1, selected.len()) {
            s.spawn(|| {
                while let Some(name) = queue.lock().expect("queue").pop() {
                    let run = std::panic::catch_unwind(|| match GROUPS.iter().find(|g| g.0 == name) {
                        Some(&(_, group)) => check_group(group, &found),
                        None => references(&found),
                    });
                    println!("test {name} ... {}", if run.is_ok() { "ok" } else { "FAILED" });
                    if run.is_err() {
                        failures.lock().expect("failures").push(name);
                    }
                }
            });
        }
    });
    let failures = failures.into_inner().expect("failures");
    println!("\n{}", summary(&found, selected.len(), &failures));
    if failures.is_empty() {
        ExitCode::SUCCESS
    } else {
        ExitCode::FAILURE
    }
}

/// The end of the run: libtest's result line, then every skip again.
fn summary(found: &Found, run: usize, failures: &[&str]) -> String {
    let mut o = String::new();
    if !failures.is_empty() {
        o += &format!(
            "failures (their messages are above):\n    {}\n\n",
            failures.join("\n    ")
        );
    }
    o += &format!(
        "test result: {}. {} passed; {} failed; {} references {}",
        if failures.is_empty() { "ok" } else { "FAILED" },
        run - failures.len(),
        failures.len(),
        found.missing.len(),
        if missing::required() {
            "missing (a failure under SOFTGL_REQUIRE_REFERENCES=1)"
        } else {
            "skipped"
        }
    );
    if found.missing.is_empty() {
        o += " (llvmpipe, softpipe and lavapipe all compared)";
    } else {
        let scenes = scenes::all();
        let oracle = scenes.iter().filter(|s| s.oracle.is_some()).count();
        o += "\nNot installed:";
        for (r, m) in &found.missing {
            o += &format!("\n    {}", m.line(&format!("{} comparison", r.name())));
        }
        if found.missing.iter().any(|(r, _)| *r == Reference::Llvmpipe) {
            o += &format!(
                "\n    without llvmpipe, softgl was judged on interpreter = JIT and on the scenes with an exact \
                 oracle ({oracle}); {} scenes were not compared with llvmpipe",
                scenes.len() - oracle
            );
        }
    }
    o
}
