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
    const TRI: &str = "v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl m\nf 1 2 3\n";
    /// Files written, the OBJ rendered, what stderr must say.
    type Case<'a> = (&'a [(&'a str, String)], &'a str, &'a [&'a str]);
    let cases: [Case; 7] = [
        (&[], "absent.obj", &["cannot read", "absent.obj"]),
        (
            &[("bad_vertex.obj", "v 1.0 zero 2.0\nf 1 1 1\n".into())],
            "bad_vertex.obj",
            &["bad_vertex.obj is not a valid OBJ file: position parse error"],
        ),
        (
            &[("bad_face.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n".into())],
            "bad_face.obj",
            &["face vertex index out of bounds"],
        ),
        (
            &[("no_mtl.obj", format!("mtllib gone.mtl\n{TRI}"))],
            "no_mtl.obj",
            &["cannot load the material library", "gone.mtl"],
        ),
        (
            &[
                ("no_tex.mtl", "newmtl m\nKd 1 1 1\nmap_Kd gone.png\n".into()),
                ("no_tex.obj", format!("mtllib no_tex.mtl\n{TRI}")),
            ],
            "no_tex.obj",
            &["cannot load the texture", "gone.png"],
        ),
        (
            &[
                ("bad.png", "not a png at all".into()),
                ("bad_tex.mtl", "newmtl m\nmap_Kd bad.png\n".into()),
                ("bad_tex.obj", format!("mtllib bad_tex.mtl\n{TRI}")),
            ],
            "bad_tex.obj",
            &["cannot load the texture", "bad.png"],
        ),
        (
            &[("empty.obj", "# nothing\nv 0 0 0\n".into())],
            "empty.obj",
            &["empty.obj has no triangles to draw"],
        ),
    ];
    for (files, obj, says) in cases {
        for (name, text) in files {
            std::fs::write(dir.join(name), text).unwrap();
        }
        let (ok, err) = render_err(&dir, obj);
        assert!(!ok, "{obj} rendered");
        assert!(says.iter().all(|s| err.contains(s)), "{obj}: {err}");
        assert!(!err.contains("panicked"), "{obj}: {err}");
        assert!(!dir.join("out.png").exists(), "{obj}: no image is written on an error");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn render_draws_the_textured_tile_framed_and_lit() {
    let dir = scratch("render-tile");
    let path = dir.join("tile.png");
    let model = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/models/tile.obj");
    let out = softgl(&["render", model, "-o", path.to_str().unwrap(), "--size", "160x120"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.contains("(160x120): 2 triangles, 1 textured meshes"), "{stdout}");
    let img = image::open(&path).unwrap().to_rgba8();
    assert_eq!(img.dimensions(), (160, 120));
    let px = |x: u32, y: u32| img.get_pixel(x, y).0;
    // The clear colour (38, 43, 51) wherever the tile is not.
    let background = [38, 43, 51, 255];
    for (x, y) in [(0, 0), (159, 0), (0, 119), (159, 119), (5, 60), (154, 60)] {
        assert_eq!(px(x, y), background, "({x}, {y})");
    }
    // tile.png (4x4): green (30, 200, 40) in the middle 2x2, a red (220, 30, 30)
    // border, a blue (30, 40, 220) top row. The camera looks at the centre of
    // the bounding box, so the middle of the image is the middle of the
    // texture. The tile is lit (MODULATE): each texel's colour scaled by the
    // light, so the checks are on which channel dominates, with margins.
    let dominant = |p: [u8; 4], c: usize| (0..3).all(|k| k == c || u32::from(p[c]) > 2 * u32::from(p[k]) + 40);
    assert!(dominant(px(80, 60), 1), "centre {:?}", px(80, 60));
    // Along the middle row, the tile starts with the red border.
    let left = (0..160).find(|&x| px(x, 60) != background).expect("the tile is drawn");
    assert!((20..70).contains(&left), "left edge at {left}");
    assert!(dominant(px(left + 2, 60), 0), "left border {:?}", px(left + 2, 60));
    // Down the middle column the blue top row shows first (image rows are
    // flipped on upload: the PNG's top row is at v = 1, the top of the tile);
    // LINEAR with REPEAT blends it with the red bottom row right at the edge.
    let top = (0..120).find(|&y| px(80, y) != background).expect("the tile is drawn");
    assert!((0..10).any(|d| dominant(px(80, top + d), 2)), "no blue below row {top}");
    assert!(!(0..10).any(|d| dominant(px(80, top + d), 1)), "green at the top edge");
    std::fs::remove_dir_all(&dir).unwrap();
}
