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
