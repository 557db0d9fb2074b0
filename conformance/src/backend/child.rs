//! The Mesa references, each in a child process of the harness binary
//! (`softgl-conformance child ...`, hidden), one process per scene: every
//! first frame is a cold start, and a crash costs one scene, not the report.
//! The child writes its result to a file the parent names.

use super::{Backend, Outcome, Timing, Unavailable};
use crate::missing::Missing;
use crate::scenes::{self, Scene};
use std::io::{Read, Write};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::{Duration, Instant};

/// A reference that takes longer than this on one scene has hung.
const CHILD_TIMEOUT: Duration = Duration::from_secs(300);

/// A Mesa renderer.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, clap::ValueEnum)]
pub enum Reference {
    /// OSMesa with `GALLIUM_DRIVER=llvmpipe`: the reference for every metric.
    Llvmpipe,
    /// OSMesa with `GALLIUM_DRIVER=softpipe`: the anchor.
    Softpipe,
    /// lavapipe through Vulkan, for the scenes Vulkan expresses.
    Lavapipe,
}

impl Reference {
    pub fn name(self) -> &'static str {
        match self {
            Reference::Llvmpipe => "llvmpipe",
            Reference::Softpipe => "softpipe",
            Reference::Lavapipe => "lavapipe",
        }
    }
    pub fn parse(s: &str) -> Option<Reference> {
        [Reference::Llvmpipe, Reference::Softpipe, Reference::Lavapipe]
            .into_iter()
            .find(|r| r.name() == s)
    }
    /// What the reference needs installed, and the command that installs it.
    pub fn needs(self) -> Missing {
        match self {
            Reference::Llvmpipe | Reference::Softpipe => {
                Missing::new(super::osmesa::LIBRARY, "apt-get install -y libosmesa6 libosmesa6-dev")
            }
            Reference::Lavapipe => Missing::new(
                "lavapipe (the Vulkan loader libvulkan.so.1 and lvp_icd.x86_64.json)",
                "apt-get install -y libvulkan1 mesa-vulkan-drivers",
            ),
        }
    }

    /// What the driver's renderer string must contain (lavapipe calls its
    /// device "llvmpipe" too).
    fn renderer_mark(self) -> &'static str {
        match self {
            Reference::Llvmpipe | Reference::Lavapipe => "llvmpipe",
            Reference::Softpipe => "softpipe",
        }
    }
}

/// A reference run in child processes.
pub struct External {
    reference: Reference,
    exe: PathBuf,
    name: String,
    /// Mesa's on-disk shader cache directory: each scene runs twice, and the
    /// second (warm) run is reported. `None`: the cache is disabled (cold).
    warm_cache: Option<PathBuf>,
}

static TEMP: AtomicUsize = AtomicUsize::new(0);

impl External {
    pub fn new(reference: Reference, exe: &Path) -> External {
        External {
            reference,
            exe: exe.to_path_buf(),
            name: reference.name().to_string(),
            warm_cache: None,
        }
    }

    /// The reference with Mesa's shader cache on, in `cache` (named
    /// "<reference>-warm"): its first frames show what a warm cache hides.
    pub fn warm(reference: Reference, exe: &Path, cache: &Path) -> External {
        External {
            name: format!("{}-warm", reference.name()),
            warm_cache: Some(cache.to_path_buf()),
            ..External::new(reference, exe)
        }
    }

    pub fn reference(&self) -> Reference {
        self.reference
    }

    /// Starts the driver once and returns its renderer string, or why it
    /// cannot be used: not installed, or installed and broken (a crash, the
    /// wrong driver picked).
    pub fn probe(&self) -> Result<String, Unavailable> {
        match self.run(&["--probe"]) {
            Ok(r) if r.status == Status::Ok => {
                if r.renderer.contains(self.reference.renderer_mark()) {
                    Ok(r.renderer)
                } else {
                    Err(Unavailable::Broken(format!(
                        "asked for {} and got renderer {:?}",
                        self.reference.name(),
                        r.renderer
                    )))
                }
            }
            Ok(r) if r.status == Status::Missing => Err(Unavailable::Missing(self.reference.needs())),
            Ok(r) => Err(Unavailable::Broken(r.message)),
            Err(e) => Err(Unavailable::Broken(e)),
        }
    }

    fn run(&self, extra: &[&str]) -> Result<ChildResult, String> {
        let out = std::env::temp_dir().join(format!(
            "softgl-conformance-{}-{}.bin",
            std::process::id(),
            TEMP.fetch_add(1, Ordering::Relaxed)
        ));
        let mut cmd = Command::new(&self.exe);
        cmd.arg("child")
            .arg("--backend")
            .arg(self.reference.name())
            .arg("--out")
            .arg(&out)
            .args(extra);
        match &self.warm_cache {
            // Cold first frames: no on-disk shader cache.
            None => cmd.env("MESA_SHADER_CACHE_DISABLE", "true"),
            Some(dir) => cmd
                .env_remove("MESA_SHADER_CACHE_DISABLE")
                .env("MESA_SHADER_CACHE_DIR", dir),
        };
        match self.reference {
            Reference::Llvmpipe => cmd.env("GALLIUM_DRIVER", "llvmpipe"),
            Reference::Softpipe => cmd.env("GALLIUM_DRIVER", "softpipe"),
            Reference::Lavapipe => cmd.env_remove("GALLIUM_DRIVER"),
        };
        let err_path = out.with_extension("stderr");
        let err_file = std::fs::File::create(&err_path).map_err(|e| format!("{}: {e}", err_path.display()))?;
        let mut child = cmd
            .stdout(Stdio::null())
            .stderr(err_file)
            .spawn()
            .map_err(|e| format!("cannot run {}: {e}", self.exe.display()))?;
        let start = Instant::now();
        let status = loop {
            match child.try_wait() {
                Ok(Some(status)) => break Ok(status),
                Ok(None) if start.elapsed() > CHILD_TIMEOUT => {
                    // Our own child, by its handle.
                    let _ = child.kill();
                    let _ = child.wait();
                    break Err(format!("timed out after {} s", CHILD_TIMEOUT.as_secs()));
                }
                Ok(None) => std::thread::sleep(Duration::from_millis(2)),
                Err(e) => break Err(e.to_string()),
            }
        };
        let result = std::fs::read(&out);
        let stderr = std::fs::read_to_string(&err_path).unwrap_or_default();
        let _ = std::fs::remove_file(&out);
        let _ = std::fs::remove_file(&err_path);
        let status = status?;
        match result {
            Ok(bytes) if status.success() => {
                ChildResult::decode(&bytes).ok_or_else(|| "unreadable child result".to_string())
            }
            _ => {
                let tail: String = stderr.lines().rev().take(3).collect::<Vec<_>>().join(" | ");
                Err(format!("child {status}: {tail}"))
            }
        }
    }
}

impl Backend for External {
    fn name(&self) -> &str {
        &self.name
    }

    fn probe(&self) -> Result<String, Unavailable> {
        External::probe(self)
    }

    fn render(&mut self, scene: &Scene, full: bool, runs: usize) -> Outcome {
        let runs_s = runs.to_string();
        let mut args = vec!["--scene", scene.name, "--runs", &runs_s];
        if full {
            args.push("--full");
        }
        if self.warm_cache.is_some() {
            // Fills the cache; the run below is the warm one.
            let _ = self.run(&args);
        }
        match self.run(&args) {
            Err(e) => Outcome::Failed(e),
            Ok(r) => match r.status {
                Status::Ok if !r.renderer.contains(self.reference.renderer_mark()) => Outcome::Failed(format!(
                    "asked for {} and got renderer {:?}",
                    self.reference.name(),
                    r.renderer
                )),
                Status::Ok => match image::RgbaImage::from_raw(r.width, r.height, r.pixels) {
                    Some(image) => Outcome::Rendered {
                        image,
                        timing: r.timing,
                        compiles: None,
                    },
                    None => Outcome::Failed("child image has the wrong size".into()),
                },
                Status::Unsupported => Outcome::Unsupported(r.message),
                Status::Missing => Outcome::Failed(format!("{} not installed: {}", self.reference.name(), r.message)),
                Status::Failed => Outcome::Failed(r.message),
            },
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Status {
    Ok,
    Unsupported,
    Failed,
    /// The driver is not installed (only `--probe` says so).
    Missing,
}

/// What a child sends back.
struct ChildResult {
    status: Status,
    message: String,
    renderer: String,
    width: u32,
    height: u32,
    timing: Timing,
    pixels: Vec<u8>,
}

impl ChildResult {
    fn from_outcome(o: Outcome, renderer: String) -> ChildResult {
        let (status, message, image, timing) = match o {
            Outcome::Rendered { image, timing, .. } => (Status::Ok, String::new(), Some(image), timing),
            Outcome::Unsupported(m) => (Status::Unsupported, m, None, zero_timing()),
            Outcome::Failed(m) => (Status::Failed, m, None, zero_timing()),
        };
        let (width, height, pixels) = image.map_or((0, 0, Vec::new()), |i| (i.width(), i.height(), i.into_raw()));
        ChildResult {
            status,
            message,
            renderer,
            width,
            height,
            timing,
            pixels,
        }
    }

    fn encode(&self) -> Vec<u8> {
        let mut b = Vec::new();
        b.push(match self.status {
            Status::Ok => 0,
            Status::Unsupported => 1,
            Status::Failed => 2,
            Status::Missing => 3,
        });
        for s in [&self.message, &self.renderer] {
            b.extend((s.len() as u32).to_le_bytes());
            b.extend(s.as_bytes());
        }
        b.extend(self.width.to_le_bytes());
        b.extend(self.height.to_le_bytes());
        b.extend((self.timing.first.as_nanos() as u64).to_le_bytes());
        b.extend((self.timing.steady.as_nanos() as u64).to_le_bytes());
        b.extend((self.timing.runs as u32).to_le_bytes());
        b.extend(&self.pixels);
        b
    }

    fn decode(mut b: &[u8]) -> Option<ChildResult> {
        fn take<'a>(b: &mut &'a [u8], n: usize) -> Option<&'a [u8]> {
            let (h, t) = (b.get(..n)?, b.get(n..)?);
            *b = t;
            Some(h)
        }
        let u32_ = |b: &mut &[u8]| take(b, 4).map(|s| u32::from_le_bytes(s.try_into().expect("4 bytes")));
        let u64_ = |b: &mut &[u8]| take(b, 8).map(|s| u64::from_le_bytes(s.try_into().expect("8 bytes")));
        let status = match take(&mut b, 1)?[0] {
            0 => Status::Ok,
            1 => Status::Unsupported,
            3 => Status::Missing,
            _ => Status::Failed,
        };
        let mut strings = Vec::new();
        for _ in 0..2 {
            let n = u32_(&mut b)? as usize;
            strings.push(String::from_utf8_lossy(take(&mut b, n)?).into_owned());
        }
        let (width, height) = (u32_(&mut b)?, u32_(&mut b)?);
        let first = Duration::from_nanos(u64_(&mut b)?);
        let steady = Duration::from_nanos(u64_(&mut b)?);
        let runs = u32_(&mut b)? as usize;
        let mut pixels = Vec::new();
        b.read_to_end(&mut pixels).ok()?;
        let renderer = strings.pop()?;
        let message = strings.pop()?;
        Some(ChildResult {
            status,
            message,
            renderer,
            width,
            height,
            timing: Timing { first, steady, runs },
            pixels,
        })
    }
}

fn zero_timing() -> Timing {
    Timing {
        first: Duration::ZERO,
        steady: Duration::ZERO,
        runs: 0,
    }
}

/// The child's command line (`softgl-conformance child ...`, run by
/// [`External`]).
#[derive(clap::Args, Debug)]
pub struct ChildArgs {
    /// The reference to run.
    #[arg(long)]
    backend: Reference,
    /// Where the result goes.
    #[arg(long)]
    out: PathBuf,
    /// Only start the driver and say what it is (or that it is missing).
    #[arg(long, conflicts_with = "scene")]
    probe: bool,
    /// The scene to render.
    #[arg(long, required_unless_present = "probe")]
    scene: Option<String>,
    /// At the report's size (else the tests').
    #[arg(long)]
    full: bool,
    /// Steady-state frames after the first.
    #[arg(long, default_value_t = 0)]
    runs: usize,
}

/// The child's side: renders and writes its result to `--out`.
pub fn child_main(args: &ChildArgs) -> Result<(), String> {
    let (reference, out) = (args.backend, &args.out);
    let result = if args.probe {
        match installed(reference) {
            Err(Unavailable::Missing(m)) => ChildResult {
                status: Status::Missing,
                ..ChildResult::from_outcome(Outcome::Failed(m.what), String::new())
            },
            Err(Unavailable::Broken(why)) => ChildResult::from_outcome(Outcome::Failed(why), String::new()),
            Ok(()) => {
                let scene = scenes::by_name("clear").expect("the clear scene exists");
                let (outcome, renderer) = run_reference(reference, &scene, false, 0);
                ChildResult::from_outcome(outcome, renderer)
            }
        }
    } else {
        let name = args.scene.as_deref().unwrap_or_default();
        let scene = scenes::by_name(name).ok_or_else(|| format!("no scene {name}"))?;
        let (outcome, renderer) = run_reference(reference, &scene, args.full, args.runs);
        ChildResult::from_outcome(outcome, renderer)
    };
    let bytes = result.encode();
    let mut f = std::fs::File::create(out).map_err(|e| format!("{}: {e}", out.display()))?;
    f.write_all(&bytes).map_err(|e| format!("{}: {e}", out.display()))
}

/// Whether the driver is installed (`libOSMesa.so.8` loads; Vulkan has a
/// lavapipe device).
fn installed(reference: Reference) -> Result<(), Unavailable> {
    match reference {
        Reference::Llvmpipe | Reference::Softpipe => super::osmesa::OsMesa::load()
            .map(drop)
            .map_err(|_| Unavailable::Missing(reference.needs())),
        Reference::Lavapipe => super::vulkan::installed(),
    }
}

fn run_reference(reference: Reference, scene: &Scene, full: bool, runs: usize) -> (Outcome, String) {
    let rec = scene.record(full);
    match reference {
        Reference::Llvmpipe | Reference::Softpipe => match super::osmesa::OsMesa::load() {
            Ok(mesa) => super::osmesa::render(&mesa, &rec, runs),
            Err(e) => (Outcome::Failed(e), String::new()),
        },
        Reference::Lavapipe => super::vulkan::render(&rec, runs),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn child_results_survive_the_file() {
        let image = image::RgbaImage::from_fn(3, 2, |x, y| image::Rgba([x as u8, y as u8, 7, 255]));
        let timing = Timing {
            first: Duration::from_micros(1500),
            steady: Duration::from_nanos(999),
            runs: 5,
        };
        let sent = ChildResult::from_outcome(
            Outcome::Rendered {
                image: image.clone(),
                timing,
                compiles: None,
            },
            "llvmpipe (LLVM 15.0.6, 256 bits)".into(),
        );
        let got = ChildResult::decode(&sent.encode()).expect("decodes");
        assert_eq!(got.status, Status::Ok);
        assert_eq!(got.renderer, "llvmpipe (LLVM 15.0.6, 256 bits)");
        assert_eq!((got.width, got.height), (3, 2));
        assert_eq!(got.timing, timing);
        assert_eq!(got.pixels, image.into_raw());

        let sent = ChildResult::from_outcome(Outcome::Unsupported("lines".into()), String::new());
        let got = ChildResult::decode(&sent.encode()).expect("decodes");
        assert_eq!((got.status, got.message.as_str()), (Status::Unsupported, "lines"));
        assert!(ChildResult::decode(&[0, 9, 0]).is_none(), "a truncated file is refused");
    }
}
