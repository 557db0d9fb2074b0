//! What a test does when a reference it compares with is not installed
//! (Mesa's OSMesa, lavapipe, a C compiler, GLU, PyOpenGL): it prints one loud
//! line naming what is missing and the command that installs it, and passes —
//! unless `SOFTGL_REQUIRE_REFERENCES=1` (CI sets it), where the same line is a
//! failure. A reference that is found and answers wrongly fails either way:
//! a skip is only for "not installed".
//!
//! The one place that decides; std only, so that `osmesa/tests/clients.rs`
//! includes this file as a module of its own (`#[path]`) without depending on
//! this crate.

use std::io::Write;

/// The environment variable that turns every skip into a failure.
pub const REQUIRE: &str = "SOFTGL_REQUIRE_REFERENCES";

/// Whether missing references fail (`SOFTGL_REQUIRE_REFERENCES=1`).
pub fn required() -> bool {
    std::env::var(REQUIRE).is_ok_and(|v| v == "1")
}

/// A reference a check needs that this machine does not have.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Missing {
    /// What is not there ("libOSMesa.so.8").
    pub what: String,
    /// The command that provides it.
    pub install: &'static str,
}

impl Missing {
    pub fn new(what: impl Into<String>, install: &'static str) -> Missing {
        Missing {
            what: what.into(),
            install,
        }
    }

    /// `SKIPPED <check>: <what> not found — <install>`.
    pub fn line(&self, check: &str) -> String {
        format!("SKIPPED {check}: {} not found — {}", self.what, self.install)
    }

    /// Skips `check`: prints its line on stderr, past the test harness's
    /// output capture (which only takes `print!`/`eprint!`), and returns it.
    /// Under `SOFTGL_REQUIRE_REFERENCES=1`, panics with the line instead.
    pub fn skip(&self, check: &str) -> String {
        let line = self.line(check);
        if required() {
            panic!("{line} ({REQUIRE}=1: a missing reference is a failure)");
        }
        let _ = writeln!(std::io::stderr(), "{line}");
        line
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_line_names_what_is_missing_and_how_to_install_it() {
        let m = Missing::new("libOSMesa.so.8", "apt-get install -y libosmesa6 libosmesa6-dev");
        assert_eq!(
            m.line("llvmpipe comparison"),
            "SKIPPED llvmpipe comparison: libOSMesa.so.8 not found — apt-get install -y libosmesa6 libosmesa6-dev"
        );
    }
}
