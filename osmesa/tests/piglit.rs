//! piglit, the GL conformance suite Mesa is tested with, on softgl through its
//! EGL face: the GL 1.x groups (`spec@!opengl 1.0` … `1.5`) run by an
//! unmodified piglit (`PIGLIT_PLATFORM=surfaceless_egl`, `LD_LIBRARY_PATH`
//! at `<profile>/egl/`), compared test by test with `piglit_expected.tsv`:
//!
//! - a test expected to pass that does not fails this test, and so does any
//!   crash but those `piglit_notes.tsv` proves are piglit's own on every
//!   surfaceless EGL (printed with that label);
//! - a new pass is printed, to be recorded in the file in the same change
//!   (`SOFTGL_PIGLIT_UPDATE=1` rewrites it from this run).
//!
//! The tests `piglit_notes.tsv` marks `excluded` are left out, each with its
//! reason (`gl-1.0-blend-func`: over 600 s on llvmpipe). Without piglit
//! installed the test prints one `SKIPPED piglit:` line and passes, unless
//! `SOFTGL_REQUIRE_REFERENCES=1`. The results stay in
//! `<target>/tmp/piglit-gl1x/` for `softgl-conformance piglit`.

mod needs;
use needs::{have, Need};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;

const GROUPS: &str = r"spec@!opengl 1\.[0-5]@";

/// `piglit_notes.tsv`: test → (kind, why), for results with causes outside softgl.
fn notes() -> BTreeMap<String, (String, String)> {
    let text = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/piglit_notes.tsv"))
        .expect("tests/piglit_notes.tsv");
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .map(|l| {
            let mut f = l.splitn(3, '\t');
            let (test, kind, why) = (f.next(), f.next(), f.next());
            let (Some(test), Some(kind), Some(why)) = (test, kind, why) else {
                panic!("piglit_notes.tsv: test<TAB>kind<TAB>why: {l}")
            };
            (test.to_string(), (kind.to_string(), why.to_string()))
        })
        .collect()
}

/// A `piglit run -x` pattern matching exactly `test`.
fn exact(test: &str) -> String {
    format!("^{}$", test.replace('.', r"\."))
}

/// `<target>/<profile>/egl`, where build.rs links softgl as `libEGL.so.1` and `libGL.so.1`.
fn egl_dir() -> PathBuf {
    let exe = std::env::current_exe().expect("test executable path");
    let dir = exe
        .parent()
        .and_then(Path::parent)
        .expect("target profile dir")
        .join("egl");
    for name in ["libEGL.so.1", "libGL.so.1"] {
        assert!(
            dir.join(name).exists(),
            "{} is missing: build softgl-osmesa first",
            dir.join(name).display()
        );
    }
    dir
}

fn expected_path() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/piglit_expected.tsv")
}

/// Test name → result, from `piglit_expected.tsv` (`test<TAB>result`, `#` comments).
fn expected() -> BTreeMap<String, String> {
    let text = std::fs::read_to_string(expected_path()).expect("tests/piglit_expected.tsv");
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .map(|l| {
            let (name, result) = l.split_once('\t').expect("test<TAB>result");
            (name.to_string(), result.to_string())
        })
        .collect()
}

/// Test name → result of a results directory (`piglit summary csv`: name,time,returncode,result).
fn results(dir: &Path) -> BTreeMap<String, String> {
    let out = Command::new("piglit")
        .arg("summary")
        .arg("csv")
        .arg(dir)
        .output()
        .expect("piglit summary csv");
    assert!(
        out.status.success(),
        "piglit summary csv: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout)
        .lines()
        .filter_map(|l| {
            let fields: Vec<&str> = l.rsplitn(4, ',').collect();
            (fields.len() == 4).then(|| (fields[3].to_string(), fields[0].to_string()))
        })
        .collect()
}

/// "spec@!opengl 1.3@foo" → "spec@!opengl 1.3".
fn group(test: &str) -> &str {
    test.rsplit_once('@').map_or(test, |(g, _)| g)
}

/// Pass, fail, skip, crash and other counts per group.
fn summary(results: &BTreeMap<String, String>) -> String {
    let mut groups: BTreeMap<&str, [usize; 5]> = BTreeMap::new();
    for (test, result) in results {
        let column = match result.as_str() {
            "pass" => 0,
            "fail" | "warn" => 1,
            "skip" => 2,
            "crash" => 3,
            _ => 4,
        };
        groups.entry(group(test)).or_default()[column] += 1;
    }
    let mut s = format!(
        "{:<20} {:>5} {:>5} {:>5} {:>5} {:>6}\n",
        "group", "pass", "fail", "skip", "crash", "other"
    );
    for (g, c) in groups {
        s += &format!("{g:<20} {:>5} {:>5} {:>5} {:>5} {:>6}\n", c[0], c[1], c[2], c[3], c[4]);
    }
    s
}

#[test]
fn gl1x_groups_keep_their_passes() {
    if !have("piglit", &[Need::Piglit]) {
        return;
    }
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("piglit-gl1x");
    let _ = std::fs::remove_dir_all(&dir);
    let notes = notes();
    let excluded: Vec<String> = notes
        .iter()
        .filter(|(_, (kind, _))| kind == "excluded")
        .flat_map(|(t, _)| ["-x".to_string(), exact(t)])
        .collect();
    let out = Command::new("piglit")
        .args([
            "run",
            "-p",
            "surfaceless_egl",
            "-j",
            "2",
            "--timeout",
            "60",
            "-t",
            GROUPS,
        ])
        .args(&excluded)
        .args(["opengl".as_ref(), dir.as_os_str()])
        .env("PIGLIT_PLATFORM", "surfaceless_egl")
        .env("PIGLIT_NO_WINDOW", "1")
        .env("LD_LIBRARY_PATH", egl_dir())
        .output()
        .expect("run piglit");
    assert!(
        out.status.success(),
        "piglit run failed: {}\n{}",
        out.status,
        String::from_utf8_lossy(&out.stderr)
    );
    let got = results(&dir);
    println!("piglit GL 1.x on softgl ({}):\n{}", dir.display(), summary(&got));
    if std::env::var("SOFTGL_PIGLIT_UPDATE").as_deref() == Ok("1") {
        let mut text = String::from(
            "# piglit GL 1.x results on softgl (osmesa/tests/piglit.rs; SOFTGL_PIGLIT_UPDATE=1 rewrites)\n",
        );
        for (test, result) in &got {
            text += &format!("{test}\t{result}\n");
        }
        std::fs::write(expected_path(), text).expect("write piglit_expected.tsv");
    }
    let want = expected();
    let mut regressions = Vec::new();
    for (test, was) in &want {
        let now = got.get(test).map_or("missing", String::as_str);
        if was == "pass" && now != "pass" {
            regressions.push(format!("{test}: expected {was}, got {now}"));
        }
    }
    // A crash is a bug (a missing feature is a GL error or a skip), unless
    // piglit itself aborts there on any surfaceless EGL.
    for (test, _) in got.iter().filter(|(_, r)| *r == "crash") {
        match notes.get(test) {
            Some((kind, why)) if kind == "surfaceless-abort" => {
                println!("crash, piglit's own on surfaceless EGL (llvmpipe too): {test}: {why}")
            }
            _ => regressions.push(format!("{test}: crash (softgl's, not piglit's)")),
        }
    }
    for (test, (kind, why)) in notes.iter().filter(|(_, (k, _))| k == "excluded") {
        println!("{kind}: {test}: {why}");
    }
    let new_passes: Vec<&String> = got
        .iter()
        .filter(|(t, r)| *r == "pass" && want.get(*t).is_none_or(|w| w != "pass"))
        .map(|(t, _)| t)
        .collect();
    for t in &new_passes {
        println!("NEW PASS (update tests/piglit_expected.tsv): {t}");
    }
    assert!(
        regressions.is_empty(),
        "{} piglit regressions (results in {}):\n{}",
        regressions.len(),
        dir.display(),
        regressions.join("\n")
    );
}
