//! The `softgl` command, run as a user would.

use std::process::Command;

fn softgl(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_softgl"))
        .args(args)
        .output()
        .expect("the softgl binary runs")
}

#[test]
fn demo_writes_a_png_of_the_asked_size() {
    let dir = std::env::temp_dir().join(format!("softgl-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("demo.png");
    let out = softgl(&["demo", "-o", path.to_str().unwrap(), "--size", "320x200"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let img = image::open(&path).unwrap().to_rgba8();
    assert_eq!(img.dimensions(), (320, 200));
    // The scene is opaque and not one colour: sky, floor and cubes.
    assert!(img.pixels().all(|p| p.0[3] == 255));
    let distinct: std::collections::HashSet<[u8; 4]> = img.pixels().map(|p| p.0).collect();
    assert!(distinct.len() > 1000, "{} distinct colours", distinct.len());
    // The same as the library renders.
    let lib = softgl::demo::render(320, 200).unwrap().framebuffer().to_rgba_image();
    assert_eq!(img, lib);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn bad_sizes_are_refused_with_a_clear_message() {
    for size in ["0x10", "10x0", "16385x10", "abc", "10", "10x10x10", "-5x10"] {
        let out = softgl(&["demo", "-o", "/dev/null", &format!("--size={size}")]);
        assert!(!out.status.success(), "size {size} accepted");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains("WIDTHxHEIGHT"), "size {size}: {err}");
    }
}

#[test]
fn an_unwritable_path_is_reported() {
    let out = softgl(&["demo", "-o", "/nonexistent-dir/x/demo.png", "--size", "8x8"]);
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("cannot write /nonexistent-dir/x/demo.png"), "{err}");
}

/// A scratch directory of this test process.
fn scratch(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("softgl-cli-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// `softgl render` on `obj` in `dir`; its exit status and stderr.
fn render_err(dir: &std::path::Path, obj: &str) -> (bool, String) {
    let out = softgl(&[
        "render",
        dir.join(obj).to_str().unwrap(),
        "-o",
        dir.join("out.png").to_str().unwrap(),
        "--size",
        "16x16",
    ]);
    (out.status.success(), String::from_utf8_lossy(&out.stderr).into_owned())
}

#[test]
fn render_reports_missing_and_malformed_files_by_name() {
    let dir = scratch("render-errors");
    let write = |name: &str, text: &[u8]| std::fs::write(dir.join(name), text).unwrap();
    let (ok, err) = render_err(&dir, "absent.obj");
    assert!(!ok);
    assert!(err.contains("cannot read") && err.contains("absent.obj"), "{err}");

    write("bad_vertex.obj", b"v 1.0 zero 2.0\nf 1 1 1\n");
    let (ok, err) = render_err(&dir, "bad_vertex.obj");
    assert!(!ok);
    assert!(
        err.contains("bad_vertex.obj is not a valid OBJ file: position parse error"),
        "{err}"
    );

    write("bad_face.obj", b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
    let (ok, err) = render_err(&dir, "bad_face.obj");
    assert!(!ok);
    assert!(err.contains("face vertex index out of bounds"), "{err}");

    write(
        "no_mtl.obj",
        b"mtllib gone.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl m\nf 1 2 3\n",
    );
    let (ok, err) = render_err(&dir, "no_mtl.obj");
    assert!(!ok);
    assert!(
        err.contains("cannot load the material library") && err.contains("gone.mtl"),
        "{err}"
    );

    write("no_tex.mtl", b"newmtl m\nKd 1 1 1\nmap_Kd gone.png\n");
    write(
        "no_tex.obj",
        b"mtllib no_tex.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl m\nf 1 2 3\n",
    );
    let (ok, err) = render_err(&dir, "no_tex.obj");
    assert!(!ok);
    assert!(
        err.contains("cannot load the texture") && err.contains("gone.png"),
        "{err}"
    );

    write("bad.png", b"not a png at all");
    write("bad_tex.mtl", b"newmtl m\nmap_Kd bad.png\n");
    write(
        "bad_tex.obj",
        b"mtllib bad_tex.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl m\nf 1 2 3\n",
    );
    let (ok, err) = render_err(&dir, "bad_tex.obj");
    assert!(!ok);
    assert!(
        err.contains("cannot load the texture") && err.contains("bad.png"),
        "{err}"
    );

    write("empty.obj", b"# nothing\nv 0 0 0\n");
    let (ok, err) = render_err(&dir, "empty.obj");
    assert!(!ok);
    assert!(err.contains("empty.obj has no triangles to draw"), "{err}");

    assert!(!err.contains("panicked"));
    assert!(!dir.join("out.png").exists(), "no image is written on an error");
    std::fs::remove_dir_all(&dir).unwrap();
}
