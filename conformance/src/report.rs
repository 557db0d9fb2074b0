//! The report: `report.md`, `error_vs_time.png`, `results.csv` and a diff
//! image for every scene and back end over the scene's tolerance.

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
    pub status: Result<String, String>,
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
    plot(&results, &names, &opts.out.join("error_vs_time.png"))?;
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
            if r.backend == REFERENCE || s.within(&r.backend) != Some(false) {
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
        "scene,group,width,height,backend,status,max_diff,pixels_over,share_over,mae,psnr,coverage,first_ms,steady_ms,runs,within,jit_compiles_first,jit_compile_ms_first\n",
    );
    for s in results {
        for r in &s.results {
            let (status, first, steady, runs) = match &r.outcome {
                Outcome::Rendered { timing, .. } => ("ok", ms(timing.first), ms(timing.steady), timing.runs),
                Outcome::Unsupported(_) => ("unsupported", 0.0, 0.0, 0),
                Outcome::Failed(_) => ("failed", 0.0, 0.0, 0),
            };
            let m = r.metrics.map_or(",,,,,".to_string(), |m| {
                format!(
                    "{},{},{:.6},{:.6},{},{}",
                    m.max_diff,
                    m.over,
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
                "{},{:?},{},{},{},{status},{m},{first:.3},{steady:.3},{runs},{within},{jit}",
                s.scene, s.group, s.size.0, s.size.1, r.backend
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
        "| back end | rendered | identical to llvmpipe | within tolerance | coverage exact | no farther than softpipe | failed | unsupported | first frames (sum) | steady frames (sum) |"
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
    o
}

fn cell(s: &SceneResult, backend: &str) -> String {
    let Some(r) = s.get(backend) else { return "-".into() };
    match (&r.outcome, r.metrics) {
        (Outcome::Unsupported(_), _) => "n/a".into(),
        (Outcome::Failed(_), _) => "**FAILED**".into(),
        (Outcome::Rendered { timing, .. }, Some(m)) => {
            let mark = if backend == REFERENCE {
                ""
            } else if m.identical() {
                "= "
            } else if s.within(backend) == Some(true) {
                "~ "
            } else {
                "**X** "
            };
            if backend == REFERENCE {
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
        "Every scene rendered by every back end and compared with Mesa's **llvmpipe** (the reference). \
         softgl's bar: within each scene's tolerance, no farther from llvmpipe than **softpipe** is \
         (mean absolute error and coverage), and triangle coverage exactly llvmpipe's.\n"
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
    let _ = writeln!(o, "![error against run time](error_vs_time.png)\n");
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
         `=` identical to llvmpipe, `~` within the scene's tolerance, **X** over it, n/a: the back end cannot \
         express the scene. The llvmpipe column shows its own time.\n"
    );
    let _ = writeln!(o, "| scene | {} |", names.join(" | "));
    let _ = writeln!(o, "|---|{}", "---|".repeat(names.len()));
    for s in results {
        let cells: Vec<String> = names.iter().map(|n| cell(s, n)).collect();
        let _ = writeln!(o, "| {} | {} |", s.scene, cells.join(" | "));
    }
    let groups = [
        Group::Stage,
        Group::Combination,
        Group::Primitive,
        Group::Stiff,
        Group::Timing,
    ];
    let _ = writeln!(o, "\n## Per scene and back end\n");
    for g in groups {
        let _ = writeln!(o, "### {}\n", g.name());
        for s in results.iter().filter(|s| s.group == g) {
            let t = &s.tolerance;
            let _ = writeln!(
                o,
                "**{}** ({}x{}). Tolerance: channel ±{}, {:.3}% of pixels over, {} coverage. {}\n",
                s.scene,
                s.size.0,
                s.size.1,
                t.channel,
                t.share_over * 100.0,
                t.coverage,
                t.reason
            );
            let _ = writeln!(
                o,
                "| back end | max diff | pixels over | MAE | PSNR dB | coverage | first ms | steady ms | JIT compiles | verdict |"
            );
            let _ = writeln!(o, "|---|---|---|---|---|---|---|---|---|---|");
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
                    Outcome::Rendered { .. } if r.backend == REFERENCE => "reference".into(),
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
                    "| {} | {} | {} | {} | {} | {} | {first} | {steady} | {compiles} | {verdict} |",
                    r.backend,
                    m(&|m| m.max_diff.to_string()),
                    m(&|m| format!("{} ({:.3}%)", m.over, m.share_over * 100.0)),
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
        "## Diff images\n\n{} written to `diff/` (llvmpipe, the back end, their difference x16; red: over tolerance).",
        diffs.len()
    );
    o
}

/// The system font the plot's labels use, if installed (Debian: fonts-dejavu-core).
const FONT: &str = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

/// One point per scene and back end: error (MAE against llvmpipe, log) over
/// steady frame time (log). Identical images sit on the bottom line, where
/// llvmpipe's own times are drawn in black.
fn plot(results: &[SceneResult], names: &[String], path: &Path) -> Result<(), String> {
    use plotters::prelude::*;
    let labels = match std::fs::read(FONT) {
        Ok(bytes) => {
            plotters::style::register_font("sans-serif", FontStyle::Normal, Box::leak(bytes.into_boxed_slice())).is_ok()
        }
        Err(_) => false,
    };
    if !labels {
        eprintln!("note: {FONT} not found; error_vs_time.png has no labels");
    }
    const FLOOR: f64 = 1e-4;
    let points: Vec<(usize, f64, f64)> = results
        .iter()
        .flat_map(|s| {
            s.results.iter().filter_map(|r| match (&r.outcome, r.metrics) {
                (Outcome::Rendered { timing, .. }, Some(m)) => {
                    let i = names.iter().position(|n| *n == r.backend)?;
                    Some((i, ms(timing.steady).max(1e-3), m.mae.max(FLOOR)))
                }
                _ => None,
            })
        })
        .collect();
    let tmax = points.iter().map(|p| p.1).fold(1.0, f64::max) * 2.0;
    let tmin = points.iter().map(|p| p.1).fold(tmax, f64::min) / 2.0;
    let emax = points.iter().map(|p| p.2).fold(1.0, f64::max) * 2.0;
    let root = BitMapBackend::new(path, (1000, 700)).into_drawing_area();
    let err = |e: &dyn std::fmt::Display| e.to_string();
    root.fill(&WHITE).map_err(|e| err(&e))?;
    let mut builder = ChartBuilder::on(&root);
    builder.margin(20);
    if labels {
        builder
            .caption("error against llvmpipe vs steady frame time", ("sans-serif", 24))
            .x_label_area_size(45)
            .y_label_area_size(70);
    }
    let mut chart = builder
        .build_cartesian_2d((tmin..tmax).log_scale(), (FLOOR / 2.0..emax).log_scale())
        .map_err(|e| err(&e))?;
    if labels {
        chart
            .configure_mesh()
            .x_desc("steady frame time, ms (log)")
            .y_desc("mean abs. error per channel (log; identical at bottom)")
            .draw()
            .map_err(|e| err(&e))?;
    } else {
        chart
            .configure_mesh()
            .disable_x_mesh()
            .disable_y_mesh()
            .x_labels(0)
            .y_labels(0)
            .draw()
            .map_err(|e| err(&e))?;
    }
    let colors = [RED, BLUE, GREEN, MAGENTA, CYAN, BLACK];
    for (i, name) in names.iter().enumerate() {
        // The reference is identical to itself: its times sit on the bottom line, in black.
        let color = if name == REFERENCE {
            BLACK
        } else {
            colors[i % colors.len()]
        };
        let series = chart
            .draw_series(
                points
                    .iter()
                    .filter(|p| p.0 == i)
                    .map(|p| Circle::new((p.1, p.2), 4, color.filled())),
            )
            .map_err(|e| err(&e))?;
        if labels {
            series
                .label(name.as_str())
                .legend(move |(x, y)| Circle::new((x, y), 4, color.filled()));
        }
    }
    if labels {
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .draw()
            .map_err(|e| err(&e))?;
    }
    root.present().map_err(|e| err(&e))?;
    Ok(())
}
