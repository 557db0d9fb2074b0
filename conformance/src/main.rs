//! `softgl-conformance report -o DIR`: every scene on every back end, the
//! report, the plot and the diff images. (`child` is the harness re-run as a
//! Mesa reference; see `backend::child`.)

use softgl_conformance::{backend, piglit, report, scenes};
use std::path::PathBuf;
use std::process::ExitCode;

const USAGE: &str = "usage: softgl-conformance report -o DIR [--runs N] [--small] [--no-warm] [--scenes a,b,...]
       softgl-conformance list
       softgl-conformance piglit RESULTS_DIR   (markdown: softgl's piglit GL 1.x results beside llvmpipe's)";

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let result = match args.first().map(String::as_str) {
        Some("child") => backend::child::child_main(&args[1..]),
        Some("list") => {
            for s in scenes::all() {
                println!("{:<32} {:<18} {}", s.name, s.group.name(), s.tolerance.reason);
            }
            Ok(())
        }
        Some("report") => report_main(&args[1..]),
        Some("piglit") if args.len() == 2 => piglit::section(args[1].as_ref()).map(|md| print!("{md}")),
        _ => Err(USAGE.to_string()),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("softgl-conformance: {e}");
            ExitCode::FAILURE
        }
    }
}

fn report_main(args: &[String]) -> Result<(), String> {
    let mut opts = report::Options {
        out: PathBuf::new(),
        runs: 5,
        full: true,
        only: None,
        warm: true,
    };
    let mut it = args.iter();
    while let Some(a) = it.next() {
        match a.as_str() {
            "-o" | "--out" => opts.out = it.next().ok_or(USAGE)?.into(),
            "--runs" => opts.runs = it.next().and_then(|r| r.parse().ok()).ok_or("--runs takes a number")?,
            "--small" => opts.full = false,
            "--no-warm" => opts.warm = false,
            "--scenes" => opts.only = Some(it.next().ok_or(USAGE)?.split(',').map(String::from).collect()),
            _ => return Err(format!("unknown argument {a}\n{USAGE}")),
        }
    }
    if opts.out.as_os_str().is_empty() {
        return Err(USAGE.into());
    }
    let exe = std::env::current_exe().map_err(|e| e.to_string())?;
    report::run(&opts, &exe)
}
