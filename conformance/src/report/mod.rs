//! The report: `report.md`, the plots (`error_vs_time.png`, `backends.png`;
//! see [`plot`]), `results.csv` and a diff image for every scene and back end
//! over the scene's tolerance.

mod plot;

use crate::backend::child::{External, Reference};
use crate::backend::{self, Backend, Compiles, Outcome};
use crate::metrics::{diff_image, Metrics};
use crate::run::{run_scene, SceneResult, ANCHOR, REFERENCE};
use crate::scenes::{self, Group};
use indicatif::{ProgressBar, ProgressStyle};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// What to run.
pub struct Options {
    pub out: PathBuf,
    /// Steady-state frames per scene and back end (the median is reported).
    pub runs: usize,
    /// Report sizes (true) or the tests' small ones.
    pub full: bool,
    /// Only these scenes.
    pub only: Option<Vec<String>>,
    /// Also run llvmpipe with Mesa's shader cache warm ("llvmpipe-warm").
    pub warm: bool,
}

/// A back end's availability, as the report states it.
pub struct Availability {
    pub backend: String,
    pub status: Result<String, crate::backend::Unavailable>,
}

/// Checks which back ends are there, saying loudly which are not.
pub fn probe(backends: &[Box<dyn Backend>]) -> Vec<Availability> {
    backends
        .iter()
        .map(|b| {
            let status = b.probe();
            if let Err(e) = &status {
                eprintln!("!!! BACK END MISSING: {}: {e}", b.name());
            }
            Availability {
                backend: b.name().to_string(),
                status,
            }
        })
        .collect()
}

/// Runs everything and writes the report into `opts.out`.
pub fn run(opts: &Options, exe: &Path) -> Result<(), String> {
    // Diff images of an earlier report in the same place would mislead.
    let _ = std::fs::remove_dir_all(opts.out.join("diff"));
    std::fs::create_dir_all(opts.out.join("diff")).map_err(|e| format!("{}: {e}", opts.out.display()))?;
    let mut backends = backend::all(exe);
    // The opt-in dither knob, measured like a back end (report only).
    backends.push(Box::new(backend::softgl::Softgl::dithered()));
    let cache = std::env::temp_dir().join(format!("softgl-conformance-cache-{}", std::process::id()));
    if opts.warm {
        backends.insert(1, Box::new(External::warm(Reference::Llvmpipe, exe, &cache)));
    }
    let available = probe(&backends);
    let scenes: Vec<_> = scenes::all()
        .into_iter()
        .filter(|s| opts.only.as_ref().is_none_or(|o| o.iter().any(|n| n == s.name)))
        .collect();
    let bar = ProgressBar::new(scenes.len() as u64);
    bar.set_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} scenes, {elapsed} [{msg}]").map_err(|e| e.to_string())?,
    );
    let mut results = Vec::new();
    for s in &scenes {
        bar.set_message(s.name);
        results.push(run_scene(s, &mut backends, opts.full, opts.runs));
        bar.inc(1);
    }
    bar.finish_with_message("done");
    let _ = std::fs::remove_dir_all(&cache);
    let names: Vec<String> = backends.iter().map(|b| b.name().to_string()).collect();
    let diffs = write_diffs(&results, &opts.out.join("diff"))?;
    plot::error_vs_time(&results, &names, &opts.out.join("error_vs_time.png"))?;
    plot::backends(&results, &names, &opts.out.join("backends.png"))?;
    std::fs::write(opts.out.join("results.csv"), csv(&results)).map_err(|e| e.to_string())?;
    let mut md = markdown(&results, &names, &available, opts, &diffs);
    if let Some(dir) = crate::piglit::results_dir(exe) {
        md += &crate::piglit::section(&dir)?;
    }
    std::fs::write(opts.out.join("report.md"), &md).map_err(|e| e.to_string())?;
    println!("{}", summary(&results, &names));
    println!("wrote {}", opts.out.join("report.md").display());
    Ok(())
}

fn ms(d: std::time::Duration) -> f64 {
    d.as_secs_f64() * 1e3
}

/// Diff images for every back end over a scene's tolerance; returns their file names.
fn write_diffs(results: &[SceneResult], dir: &Path) -> Result<Vec<String>, String> {
    let mut written = Vec::new();
    for s in results {
        let Some(reference) = s.reference() else { continue };
        for r in &s.results {
            if s.is_reference(&r.backend) || s.within(&r.backend) != Some(false) {
                continue;
            }
            if let Outcome::Rendered { image, .. } = &r.outcome {
                let name = format!("{}-{}.png", s.scene, r.backend);
                diff_image(reference, image, s.tolerance.channel)
                    .save(dir.join(&name))
                    .map_err(|e| e.to_string())?;
                written.push(name);
            }
        }
    }
    Ok(written)
}

fn compiles_text(c: &Compiles) -> String {
    let mut t = format!("{} in {:.2} ms", c.first, ms(c.first_time));
    if c.later > 0 {
        t += &format!(", {} later", c.later);
    }
    if c.failures > 0 {
        t += &format!(", {} failed", c.failures);
    }
    t
}

fn fmt_psnr(p: f64) -> String {
    if p.is_infinite() {
        "inf".into()
    } else {
        format!("{p:.1}")
    }
}

fn csv(results: &[SceneResult]) -> String {
    let mut o = String::from(
        "scene,group,width,height,reference,backend,status,max_diff,pixels_over,pixels_near,near_budget,share_over,mae,psnr,coverage,first_ms,steady_ms,runs,within,jit_compiles_first,jit_compile_ms_first\n",
    );
    for s in results {
        for r in &s.results {
            let (status, first, steady, runs) = match &r.outcome {
                Outcome::Rendered { timing, .. } => ("ok", ms(timing.first), ms(timing.steady), timing.runs),
                Outcome::Unsupported(_) => ("unsupported", 0.0, 0.0, 0),
                Outcome::Failed(_) => ("failed", 0.0, 0.0, 0),
            };
            let m = r.metrics.map_or(",,,,,,,".to_string(), |m| {
                format!(
                    "{},{},{},{},{:.6},{:.6},{},{}",
                    m.max_diff,
                    m.over,
                    m.near,
                    s.tolerance.near(s.full),
                    m.share_over,
                    m.mae,
                    fmt_psnr(m.psnr),
                    m.coverage
                )
            });
            let within = s.within(&r.backend).map_or(String::new(), |w| w.to_string());
            let jit = match &r.outcome {
                Outcome::Rendered { compiles: Some(c), .. } => format!("{},{:.3}", c.first, ms(c.first_time)),
                _ => ",".into(),
            };
            let _ = writeln!(
                o,
                "{},{:?},{},{},{},{},{status},{m},{first:.3},{steady:.3},{runs},{within},{jit}",
                s.scene, s.group, s.size.0, s.size.1, s.reference, r.backend
            );
        }
    }
    o
}

/// Per back end: scenes rendered, identical, within tolerance, anchor met.
struct Tally {
    rendered: usize,
    identical: usize,
    within: usize,
    compared: usize,
    anchor_met: usize,
    anchor_compared: usize,
    coverage_exact: usize,
    unsupported: usize,
    failed: usize,
    first_ms: f64,
    steady_ms: f64,
}

fn tally(results: &[SceneResult], backend: &str) -> Tally {
    let mut t = Tally {
        rendered: 0,
        identical: 0,
        within: 0,
        compared: 0,
        anchor_met: 0,
        anchor_compared: 0,
        coverage_exact: 0,
        unsupported: 0,
        failed: 0,
        first_ms: 0.0,
        steady_ms: 0.0,
    };
    for s in results {
        let Some(r) = s.get(backend) else { continue };
        match &r.outcome {
            Outcome::Rendered { timing, .. } => {
                t.rendered += 1;
                t.first_ms += ms(timing.first);
                t.steady_ms += ms(timing.steady);
            }
            Outcome::Unsupported(_) => t.unsupported += 1,
            Outcome::Failed(_) => t.failed += 1,
        }
        if let Some(m) = r.metrics {
            t.compared += 1;
            t.identical += m.identical() as usize;
            t.coverage_exact += (m.coverage == 0) as usize;
            t.within += (s.within(backend) == Some(true)) as usize;
        }
        if let Some(a) = s.meets_anchor(backend) {
            t.anchor_compared += 1;
            t.anchor_met += a as usize;
        }
    }
    t
}

/// A few lines for the terminal and the README.
pub fn summary(results: &[SceneResult], names: &[String]) -> String {
    let mut o = String::new();
    let _ = writeln!(
        o,
        "| back end | rendered | identical to the reference | within tolerance | coverage exact | no farther than softpipe | failed | unsupported | first frames (sum) | steady frames (sum) |"
    );
    let _ = writeln!(o, "|---|---|---|---|---|---|---|---|---|---|");
    for n in names {
        let t = tally(results, n);
        let _ = writeln!(
            o,
            "| {n} | {} | {}/{} | {}/{} | {}/{} | {}/{} | {} | {} | {:.0} ms | {:.0} ms |",
            t.rendered,
            t.identical,
            t.compared,
            t.within,
            t.compared,
            t.coverage_exact,
            t.compared,
            t.anchor_met,
            t.anchor_compared,
            t.failed,
            t.unsupported,
            t.first_ms,
            t.steady_ms
        );
    }
    let _ = writeln!(
        o,
        "\nTimes: softgl rasterizes on {} threads (`SOFTGL_THREADS`); llvmpipe and softpipe run as Mesa sets them (`LP_NUM_THREADS`: {}).",
        softgl::raster::pool::default_threads(),
        std::env::var("LP_NUM_THREADS").unwrap_or_else(|_| "unset, the cores".to_string())
    );
    o
}

fn cell(s: &SceneResult, backend: &str) -> String {
    let Some(r) = s.get(backend) else { return "-".into() };
    match (&r.outcome, r.metrics) {
        (Outcome::Unsupported(_), _) => "n/a".into(),
        (Outcome::Failed(_), _) => "**FAILED**".into(),
        (Outcome::Rendered { timing, .. }, Some(m)) => {
            let mark = if s.is_reference(backend) {
                ""
            } else if m.identical() {
                "= "
            } else if s.within(backend) == Some(true) {
                "~ "
            } else {
                "**X** "
            };
            if s.is_reference(backend) {
                format!("{:.2} ms", ms(timing.steady))
            } else {
                format!("{mark}{:.3} / {} / {:.2} ms", m.mae, m.coverage, ms(timing.steady))
            }
        }
        (Outcome::Rendered { timing, .. }, None) => format!("(no reference) {:.2} ms", ms(timing.steady)),
    }
}

fn markdown(
    results: &[SceneResult],
    names: &[String],
    available: &[Availability],
    opts: &Options,
    diffs: &[String],
) -> String {
    let mut o = String::new();
    let _ = writeln!(o, "# softgl conformance against Mesa\n");
    let _ = writeln!(
        o,
        "Every scene rendered by every back end and compared with its reference: Mesa's **llvmpipe**, \
         except for the {} scenes with an **exact oracle** (triangles whose exact image Mesa's f32 clippers \
         miss), where every back end, llvmpipe too, is compared with the exact image. softgl's bar: within each \
         scene's tolerance (pixels over it, pixels within it but not equal, coverage: each a measured budget), \
         no farther from the reference than **softpipe** is (mean absolute error and coverage), and triangle \
         coverage exactly the reference's.\n",
        results.iter().filter(|s| s.oracle.is_some()).count()
    );
    let _ = writeln!(
        o,
        "Sizes: {}. Timing: the first frame in a fresh context (Mesa with `MESA_SHADER_CACHE_DISABLE=true`, \
         so it includes every LLVM compile: cold), then the median of {} further frames (steady). Each Mesa \
         scene runs in its own child process. A frame is every call of the scene, `glFinish` and the read-back. \
         `llvmpipe-warm` (when present) is llvmpipe with Mesa's on-disk shader cache on and already filled by an \
         earlier run of the same scene: its first frame is what users with a warm cache see.\n",
        if opts.full {
            "the report's (mostly 256x256; the timing scenes 1024x1024 with 20k triangles)"
        } else {
            "the tests' small ones"
        },
        opts.runs
    );
    let sh = |cmd: &str, args: &[&str]| {
        std::process::Command::new(cmd)
            .args(args)
            .output()
            .ok()
            .filter(|o| o.status.success())
            .map(|o| String::from_utf8_lossy(&o.stdout).trim().to_string())
            .unwrap_or_else(|| "unknown".into())
    };
    let _ = writeln!(
        o,
        "Generated {} at commit {} on {} ({} CPUs).\n",
        sh("date", &["-u", "+%Y-%m-%d %H:%M UTC"]),
        sh("git", &["rev-parse", "--short", "HEAD"]),
        sh("uname", &["-sr"]),
        std::thread::available_parallelism().map_or(0, |n| n.get())
    );
    let _ = writeln!(o, "## Back ends\n\n| back end | status |\n|---|---|");
    for a in available {
        let status = match &a.status {
            Ok(r) => format!("ok: {r}"),
            Err(e) => format!("**MISSING**: {e}"),
        };
        let _ = writeln!(o, "| {} | {status} |", a.backend);
    }
    let _ = writeln!(o, "\n## Summary\n\n{}", summary(results, names));
    let all: Vec<Compiles> = results
        .iter()
        .flat_map(|s| &s.results)
        .filter_map(|r| match &r.outcome {
            Outcome::Rendered { compiles, .. } => *compiles,
            _ => None,
        })
        .collect();
    if !all.is_empty() {
        let _ = writeln!(
            o,
            "softgl-jit compiled {} specialists in the first frames, in {:.1} ms in all ({} failed and ran on the \
             interpreter); later frames compiled {}.\n",
            all.iter().map(|c| c.first).sum::<u64>(),
            all.iter().map(|c| ms(c.first_time)).sum::<f64>(),
            all.iter().map(|c| c.failures).sum::<u64>(),
            all.iter().map(|c| c.later).sum::<u64>()
        );
    }
    let _ = writeln!(
        o,
        "## Error against time\n\nOne point per scene and back end: the error against the scene's reference \
         (log) over the steady frame time (log). Images identical to the reference sit on the dashed floor. \
         Each back end has its own colour (Okabe–Ito) and marker; `llvmpipe-warm` is drawn in outline.\n\n\
         ![error against run time, per scene](error_vs_time.png)\n\n\
         One point per back end: the sum of its steady frame times against the median (filled) and worst \
         (outline) of its per-scene errors.\n\n\
         ![total time against median and worst error, per back end](backends.png)\n\n\
         | back end | scenes | steady frames (sum) | median MAE | worst MAE |\n|---|---|---|---|---|"
    );
    for p in plot::backend_points(results, names) {
        let _ = writeln!(
            o,
            "| {} | {} | {:.1} ms | {:.4} | {:.4} |",
            p.name, p.scenes, p.total_ms, p.median, p.worst
        );
    }
    let _ = writeln!(o);
    for s in results.iter().filter(|s| s.oracle.is_some()) {
        let _ = writeln!(
            o,
            "**{}** against its exact oracle ({}x{}): {}.\n",
            s.scene,
            s.size.0,
            s.size.1,
            s.results
                .iter()
                .filter_map(|r| r.metrics.map(|m| format!(
                    "{} {} pixels off (max {}), {} coverage",
                    r.backend,
                    m.over + m.near,
                    m.max_diff,
                    m.coverage
                )))
                .collect::<Vec<_>>()
                .join("; ")
        );
    }
    let off: Vec<String> = results
        .iter()
        .flat_map(|s| {
            names
                .iter()
                .filter(|n| n.starts_with("softgl") && s.within(n) == Some(false))
                .map(|n| format!("`{}` ({n})", s.scene))
                .collect::<Vec<_>>()
        })
        .collect();
    let _ = writeln!(
        o,
        "softgl scenes over tolerance: {}\n",
        if off.is_empty() { "none".into() } else { off.join(", ") }
    );
    let _ = writeln!(
        o,
        "## At a glance\n\nEach cell: mean absolute error per channel / coverage mismatches / steady frame time. \
         `=` identical to the reference, `~` within the scene's tolerance, **X** over it, n/a: the back end \
         cannot express the scene. Where llvmpipe is the reference its column shows its own time.\n"
    );
    let _ = writeln!(o, "| scene | {} |", names.join(" | "));
    let _ = writeln!(o, "|---|{}", "---|".repeat(names.len()));
    for s in results {
        let cells: Vec<String> = names.iter().map(|n| cell(s, n)).collect();
        let _ = writeln!(o, "| {} | {} |", s.scene, cells.join(" | "));
    }
    let _ = writeln!(o, "\n## Per scene and back end\n");
    for g in Group::ALL {
        let _ = writeln!(o, "### {}\n", g.name());
        for s in results.iter().filter(|s| s.group == g) {
            let t = &s.tolerance;
            let _ = writeln!(
                o,
                "**{}** ({}x{}). Reference: {}. Tolerance: channel ±{}, {:.3}% of pixels over, {} pixels within \
                 ±{} but not equal, {} coverage. {}\n",
                s.scene,
                s.size.0,
                s.size.1,
                if s.oracle.is_some() {
                    "the exact oracle"
                } else {
                    REFERENCE
                },
                t.channel,
                t.share_over * 100.0,
                t.near(s.full),
                t.channel,
                t.coverage,
                t.reason
            );
            let _ = writeln!(
                o,
                "| back end | max diff | pixels over | pixels within, not equal | MAE | PSNR dB | coverage | first ms | steady ms | JIT compiles | verdict |"
            );
            let _ = writeln!(o, "|---|---|---|---|---|---|---|---|---|---|---|");
            for r in &s.results {
                let (first, steady) = match &r.outcome {
                    Outcome::Rendered { timing, .. } => {
                        (format!("{:.2}", ms(timing.first)), format!("{:.2}", ms(timing.steady)))
                    }
                    _ => ("-".into(), "-".into()),
                };
                let m = |f: &dyn Fn(&Metrics) -> String| r.metrics.as_ref().map_or("-".into(), f);
                let verdict = match &r.outcome {
                    Outcome::Unsupported(why) => format!("n/a: {why}"),
                    Outcome::Failed(why) => format!("**FAILED**: {why}"),
                    Outcome::Rendered { .. } if s.is_reference(&r.backend) => "reference".into(),
                    Outcome::Rendered { .. } => {
                        let mut v = match s.within(&r.backend) {
                            Some(true) => "within".to_string(),
                            Some(false) => format!("**over** ([diff](diff/{}-{}.png))", s.scene, r.backend),
                            None => "not compared".into(),
                        };
                        if r.backend != ANCHOR {
                            if let Some(a) = s.meets_anchor(&r.backend) {
                                v += if a { ", ≤ softpipe" } else { ", farther than softpipe" };
                            }
                        }
                        v
                    }
                };
                let compiles = match &r.outcome {
                    Outcome::Rendered { compiles: Some(c), .. } => compiles_text(c),
                    _ => "-".into(),
                };
                let _ = writeln!(
                    o,
                    "| {} | {} | {} | {} | {} | {} | {} | {first} | {steady} | {compiles} | {verdict} |",
                    r.backend,
                    m(&|m| m.max_diff.to_string()),
                    m(&|m| format!("{} ({:.3}%)", m.over, m.share_over * 100.0)),
                    m(&|m| m.near.to_string()),
                    m(&|m| format!("{:.4}", m.mae)),
                    m(&|m| fmt_psnr(m.psnr)),
                    m(&|m| m.coverage.to_string()),
                );
            }
            let _ = writeln!(o);
        }
    }
    let _ = writeln!(
        o,
        "## Diff images\n\n{} written to `diff/` (the reference, the back end, their difference x16; red: over tolerance).",
        diffs.len()
    );
    o
}

/// Prints the pixels where softgl's JIT differs from llvmpipe on `scene`
/// (window coordinates, y up), at most `max` of them, and their count.
pub fn diff_pixels(exe: &Path, scene: &str, full: bool, max: usize) -> Result<(), String> {
    let s = scenes::by_name(scene).ok_or_else(|| format!("no scene {scene}"))?;
    let mut mesa = External::new(Reference::Llvmpipe, exe);
    let mut jit = backend::softgl::Softgl::new(softgl::Backend::Jit);
    let image = |o: Outcome| match o {
        Outcome::Rendered { image, .. } => Ok(image),
        other => Err(format!("{other:?}")),
    };
    let reference = image(mesa.render(&s, full, 0))?;
    let got = image(jit.render(&s, full, 0))?;
    let h = reference.height();
    let mut n = 0;
    for (x, y, p) in reference.enumerate_pixels() {
        let q = got.get_pixel(x, y);
        if p != q {
            if n < max {
                println!("({x}, {}) llvmpipe {:?} softgl {:?}", h - 1 - y, p.0, q.0);
            }
            n += 1;
        }
    }
    println!("{n} pixels differ");
    Ok(())
}
