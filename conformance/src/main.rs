//! `softgl-conformance report -o DIR`: every scene on every back end, the
//! report, the plots and the diff images. `list` prints the scenes. (`child`,
//! hidden, is the harness re-run as a Mesa reference; see `backend::child`.)

use clap::{Parser, Subcommand};
use softgl_conformance::{backend, piglit, report, scenes};
use std::path::PathBuf;
use std::process::ExitCode;

/// softgl against Mesa: llvmpipe, softpipe and lavapipe, error against time.
#[derive(Parser, Debug)]
#[command(name = "softgl-conformance")]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Every scene on every back end: report.md, error_vs_time.png,
    /// backends.png, results.csv and diff images.
    Report {
        /// The directory to write into.
        #[arg(short, long)]
        out: PathBuf,
        /// Steady-state frames per scene and back end (the median is reported).
        #[arg(long, default_value_t = 5)]
        runs: usize,
        /// The tests' small sizes instead of the report's.
        #[arg(long)]
        small: bool,
        /// Skip llvmpipe with a warm shader cache (llvmpipe-warm).
        #[arg(long)]
        no_warm: bool,
        /// Only these scenes (comma-separated names; `list` shows them).
        #[arg(long, value_delimiter = ',')]
        scenes: Option<Vec<String>>,
    },
    /// The scenes: name, group, and the reason for the tolerance.
    List,
    /// Markdown: softgl's piglit GL 1.x results in RESULTS_DIR beside llvmpipe's.
    Piglit {
        /// A `piglit run` results directory.
        results: PathBuf,
    },
    /// The pixels where softgl (JIT) differs from llvmpipe on one scene,
    /// window coordinates (y up): what a tolerance's reason cites.
    Diff {
        /// The scene.
        scene: String,
        /// At the report's size (else the tests').
        #[arg(long)]
        full: bool,
        /// At most this many pixels listed.
        #[arg(long, default_value_t = 40)]
        max: usize,
    },
    #[command(hide = true)]
    Child(backend::child::ChildArgs),
}

fn main() -> ExitCode {
    let result = match Cli::parse().command {
        Command::Child(args) => backend::child::child_main(&args),
        Command::List => {
            for s in scenes::all() {
                println!("{:<32} {:<18} {}", s.name, s.group.name(), s.tolerance.reason);
            }
            Ok(())
        }
        Command::Diff { scene, full, max } => std::env::current_exe()
            .map_err(|e| e.to_string())
            .and_then(|exe| report::diff_pixels(&exe, &scene, full, max)),
        Command::Piglit { results } => piglit::section(&results).map(|md| print!("{md}")),
        Command::Report {
            out,
            runs,
            small,
            no_warm,
            scenes,
        } => std::env::current_exe().map_err(|e| e.to_string()).and_then(|exe| {
            let opts = report::Options {
                out,
                runs,
                full: !small,
                only: scenes,
                warm: !no_warm,
            };
            report::run(&opts, &exe)
        }),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("softgl-conformance: {e}");
            ExitCode::FAILURE
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::CommandFactory;

    #[test]
    fn the_command_line_parses() {
        Cli::command().debug_assert();
        let cli = Cli::try_parse_from(["softgl-conformance", "report", "-o", "r", "--small", "--scenes", "a,b"])
            .expect("parses");
        let Command::Report {
            out,
            small,
            scenes,
            runs,
            ..
        } = cli.command
        else {
            panic!("report");
        };
        assert_eq!((out, small, runs), (PathBuf::from("r"), true, 5));
        assert_eq!(scenes, Some(vec!["a".to_string(), "b".to_string()]));
        assert!(
            Cli::try_parse_from(["softgl-conformance", "report"]).is_err(),
            "-o is required"
        );
    }
}
