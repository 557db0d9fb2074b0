//! piglit's GL 1.x groups (`spec@!opengl 1.0` … `1.5`) in the report:
//! softgl's results, from a piglit results directory (the one
//! `osmesa/tests/piglit.rs` leaves in `<target>/tmp/piglit-gl1x/`), beside
//! llvmpipe's three runs (`piglit_gl1x_llvmpipe.tsv`: as shipped with GL 4.5,
//! forced to GL 1.5 without extensions, and GL 1.5 with Mesa's extensions up
//! to 2003), and the tests llvmpipe passes at GL 1.5 + 2003 that softgl does not.

use std::collections::BTreeMap;
use std::fmt::Write;
use std::path::Path;
use std::process::Command;

/// llvmpipe's result per test: `test<TAB>gl45_default<TAB>gl15_noext<TAB>gl15_ext2003`.
pub const LLVMPIPE_TSV: &str = include_str!("../piglit_gl1x_llvmpipe.tsv");

/// Results whose cause lies outside softgl, with the evidence
/// (`test<TAB>kind<TAB>why`; kinds `excluded` and `surfaceless-abort`),
/// the file `osmesa/tests/piglit.rs` runs piglit with.
pub const NOTES_TSV: &str = include_str!("../../osmesa/tests/piglit_notes.tsv");

/// Test → (kind, why) from a notes file.
pub fn notes(tsv: &str) -> BTreeMap<String, (String, String)> {
    tsv.lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .filter_map(|l| {
            let mut f = l.splitn(3, '\t');
            Some((f.next()?.to_string(), (f.next()?.to_string(), f.next()?.to_string())))
        })
        .collect()
}

/// What softgl's result of `test` owes to: piglit itself on surfaceless EGL,
/// an excluded test, or (for a crash) softgl.
fn label(test: &str, ours: &str, notes: &BTreeMap<String, (String, String)>) -> Option<String> {
    match (ours, notes.get(test)) {
        ("crash", Some((kind, why))) if kind == "surfaceless-abort" => Some(format!(
            "piglit's own abort on every surfaceless EGL, llvmpipe too ({why})"
        )),
        ("not run", Some((kind, why))) if kind == "excluded" => Some(format!("not run: {why}")),
        ("crash", _) => Some("softgl crashes here: a bug".to_string()),
        _ => None,
    }
}

/// The llvmpipe columns, in the TSV's order.
const LLVMPIPE_RUNS: [&str; 3] = ["llvmpipe GL 4.5", "llvmpipe GL 1.5", "llvmpipe GL 1.5 + 2003 ext."];

/// Test name → result (`pass`, `fail`, `skip`, `crash`, `warn`, `timeout`,
/// `incomplete`), from `piglit summary csv DIR` (name,time,returncode,result).
pub fn read_results(dir: &Path) -> Result<BTreeMap<String, String>, String> {
    let out = Command::new("piglit")
        .arg("summary")
        .arg("csv")
        .arg(dir)
        .output()
        .map_err(|e| format!("piglit summary csv {}: {e}", dir.display()))?;
    if !out.status.success() {
        return Err(format!(
            "piglit summary csv {}: {}",
            dir.display(),
            String::from_utf8_lossy(&out.stderr)
        ));
    }
    Ok(parse_csv(&String::from_utf8_lossy(&out.stdout)))
}

/// `piglit summary csv` lines to test → result (test names hold no commas
/// at their end, so the last three fields are split off).
pub fn parse_csv(text: &str) -> BTreeMap<String, String> {
    text.lines()
        .filter_map(|l| {
            let mut f = l.rsplitn(4, ',');
            let result = f.next()?;
            let name = f.nth(2)?;
            Some((name.to_string(), result.to_string()))
        })
        .collect()
}

/// llvmpipe's three results per test.
pub fn llvmpipe(tsv: &str) -> BTreeMap<String, [String; 3]> {
    tsv.lines()
        .skip(1)
        .filter_map(|l| {
            let mut f = l.split('\t');
            let name = f.next()?.to_string();
            let r = [f.next()?.to_string(), f.next()?.to_string(), f.next()?.to_string()];
            Some((name, r))
        })
        .collect()
}

/// "spec@!opengl 1.3@foo" → "spec@!opengl 1.3".
fn group(test: &str) -> &str {
    test.rsplit_once('@').map_or(test, |(g, _)| g)
}

/// Pass, fail (with warn), skip, crash, other (timeout, incomplete, not run).
#[derive(Clone, Copy, Default)]
struct Counts([usize; 5]);

impl Counts {
    fn add(&mut self, result: &str) {
        let i = match result {
            "pass" => 0,
            "fail" | "warn" => 1,
            "skip" => 2,
            "crash" => 3,
            _ => 4,
        };
        self.0[i] += 1;
    }

    /// `pass / fail / skip / crash`, and the others when there are some.
    fn cell(&self) -> String {
        let [p, f, s, c, o] = self.0;
        let other = if o > 0 { format!(" (+{o})") } else { String::new() };
        format!("{p} / {f} / {s} / {c}{other}")
    }
}

/// The markdown section: counts per group, then llvmpipe's passes softgl lacks.
/// Every test of the TSV is counted; one softgl did not run is "not run" (other).
pub fn markdown(softgl: &BTreeMap<String, String>, tsv: &str, notes_tsv: &str) -> String {
    let llvm = llvmpipe(tsv);
    let notes = notes(notes_tsv);
    let mut groups: BTreeMap<&str, (Counts, [Counts; 3])> = BTreeMap::new();
    let mut total = (Counts::default(), [Counts::default(); 3]);
    for (test, runs) in &llvm {
        let ours = softgl.get(test).map_or("not run", String::as_str);
        let g = groups.entry(group(test)).or_default();
        for (counts, llvm_counts) in [(&mut g.0, &mut g.1), (&mut total.0, &mut total.1)] {
            counts.add(ours);
            for (c, r) in llvm_counts.iter_mut().zip(runs) {
                c.add(r);
            }
        }
    }
    let mut o = String::new();
    let _ = writeln!(o, "## piglit, GL 1.x groups\n");
    let _ = writeln!(
        o,
        "Each cell: pass / fail / skip / crash, (+N) timeouts, incomplete or not run (`warn` counts as fail). \
         softgl runs through its EGL face (`PIGLIT_PLATFORM=surfaceless_egl`, `PIGLIT_NO_WINDOW=1`); \
         the tests listed below as not run are excluded, and the crashes labelled piglit's own happen on \
         every surfaceless implementation (`osmesa/tests/piglit_notes.tsv` holds the evidence).\n"
    );
    let _ = writeln!(o, "| group | softgl | {} |", LLVMPIPE_RUNS.join(" | "));
    let _ = writeln!(o, "|---|---|---|---|---|");
    let rows = groups.iter().map(|(g, c)| (*g, c)).chain([("total", &total)]);
    for (name, (ours, theirs)) in rows {
        let cells: Vec<String> = theirs.iter().map(Counts::cell).collect();
        let _ = writeln!(o, "| {name} | {} | {} |", ours.cell(), cells.join(" | "));
    }
    let missing: Vec<(&String, &str)> = llvm
        .iter()
        .filter(|(t, r)| r[2] == "pass" && softgl.get(*t).is_none_or(|s| s != "pass"))
        .map(|(t, _)| (t, softgl.get(t).map_or("not run", String::as_str)))
        .collect();
    let _ = writeln!(
        o,
        "\n### Passing on llvmpipe at GL 1.5 + 2003 extensions, not on softgl ({})\n",
        missing.len()
    );
    for (test, ours) in missing {
        let why = label(test, ours, &notes).map(|w| format!(": {w}")).unwrap_or_default();
        let _ = writeln!(o, "- `{test}`: {ours}{why}");
    }
    let odd: Vec<(&String, String)> = llvm
        .keys()
        .filter_map(|t| {
            let ours = softgl.get(t).map_or("not run", String::as_str);
            matches!(ours, "crash" | "not run").then(|| (t, label(t, ours, &notes).unwrap_or_default()))
        })
        .collect();
    let _ = writeln!(o, "\n### softgl's crashes and tests not run ({})\n", odd.len());
    for (test, why) in odd {
        let _ = writeln!(o, "- `{test}`: {why}");
    }
    o
}

/// The results directory for the report: `SOFTGL_PIGLIT_RESULTS`, else the
/// one `osmesa/tests/piglit.rs` left in `<target>/tmp/piglit-gl1x` (the
/// target directory of `exe`, `<target>/<profile>/softgl-conformance`), if any.
pub fn results_dir(exe: &Path) -> Option<std::path::PathBuf> {
    if let Some(dir) = std::env::var_os("SOFTGL_PIGLIT_RESULTS") {
        return Some(dir.into());
    }
    let dir = exe.parent()?.parent()?.join("tmp/piglit-gl1x");
    dir.join("metadata.json").exists().then_some(dir)
}

/// The section for the results in `dir`.
pub fn section(dir: &Path) -> Result<String, String> {
    Ok(markdown(&read_results(dir)?, LLVMPIPE_TSV, NOTES_TSV))
}

#[cfg(test)]
mod tests {
    use super::*;

    const TSV: &str = "test\ta\tb\tc\n\
        spec@!opengl 1.0@x\tpass\tpass\tpass\n\
        spec@!opengl 1.0@y\tpass\tskip\tpass\n\
        spec@!opengl 1.1@z\tcrash\tcrash\tcrash\n\
        spec@!opengl 1.1@w\ttimeout\ttimeout\ttimeout\n";

    #[test]
    fn csv_lines_give_each_test_its_result() {
        let r = parse_csv("spec@!opengl 1.0@x,0.5,0,pass\nspec@!opengl 1.1@read-front samples=2,1.0,-6,crash\n");
        assert_eq!(r.len(), 2);
        assert_eq!(r["spec@!opengl 1.1@read-front samples=2"], "crash");
    }

    #[test]
    fn the_table_counts_each_group_and_lists_what_llvmpipe_passes() {
        let ours =
            parse_csv("spec@!opengl 1.0@x,0,0,pass\nspec@!opengl 1.0@y,0,1,fail\nspec@!opengl 1.1@z,0,-6,crash\n");
        let notes = "# c\nspec@!opengl 1.1@z\tsurfaceless-abort\tneeds a window\nspec@!opengl 1.1@w\texcluded\tslow\n";
        let md = markdown(&ours, TSV, notes);
        assert!(
            md.contains("| spec@!opengl 1.0 | 1 / 1 / 0 / 0 | 2 / 0 / 0 / 0 | 1 / 0 / 1 / 0 | 2 / 0 / 0 / 0 |"),
            "{md}"
        );
        assert!(
            md.contains("| spec@!opengl 1.1 | 0 / 0 / 0 / 1 (+1) | 0 / 0 / 0 / 1 (+1) |"),
            "{md}"
        );
        assert!(md.contains("| total | 1 / 1 / 0 / 1 (+1) |"), "{md}");
        assert!(md.contains("not on softgl (1)"), "{md}");
        assert!(md.contains("- `spec@!opengl 1.0@y`: fail"), "{md}");
        assert!(md.contains("crashes and tests not run (2)"), "{md}");
        assert!(
            md.contains(
                "- `spec@!opengl 1.1@z`: piglit's own abort on every surfaceless EGL, llvmpipe too (needs a window)"
            ),
            "{md}"
        );
        assert!(md.contains("- `spec@!opengl 1.1@w`: not run: slow"), "{md}");
        let unlisted = markdown(&parse_csv("spec@!opengl 1.0@x,0,-6,crash\n"), TSV, notes);
        assert!(
            unlisted.contains("- `spec@!opengl 1.0@x`: softgl crashes here: a bug"),
            "{unlisted}"
        );
    }

    #[test]
    fn every_note_names_a_gl1x_test_and_a_known_kind() {
        let l = llvmpipe(LLVMPIPE_TSV);
        let n = notes(NOTES_TSV);
        assert_eq!(n.len(), 11);
        for (test, (kind, _)) in &n {
            assert!(l.contains_key(test), "{test}");
            assert!(kind == "excluded" || kind == "surfaceless-abort", "{kind}");
        }
    }

    #[test]
    fn the_kept_tsv_has_every_gl1x_test() {
        let l = llvmpipe(LLVMPIPE_TSV);
        assert_eq!(l.len(), 373);
        assert_eq!(l.values().filter(|r| r[2] == "pass").count(), 205);
    }
}
