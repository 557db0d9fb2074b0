//! The current colour under perspective, against llvmpipe's pixels
//! (`tests/llvmpipe/current_color.c` recorded `current_color.txt`): a colour
//! that is not per vertex is a constant in Mesa's fixed-function fragment
//! shader, not interpolated, and Mesa's immediate mode decides what is per
//! vertex by its vertex format (`docs/llvmpipe-facts.md` §20). Each scene
//! makes the C program's calls through softgl, on both back ends.

mod common;

use softgl::{Backend, Capability, Context, FramebufferDesc, MatrixMode, PrimitiveMode, ShadeModel, VertexArrays};

const N: i32 = 32;
const A: [f32; 4] = [0.3, 0.55, 0.7, 0.9];
const B: [f32; 4] = [0.15, 0.45, 0.85, 0.35];

/// The scenes of `current_color.c`, with the pixels softgl may differ by
/// and why (all others are identical).
const SCENES: &[(&str, usize)] = &[
    ("outside", 0),
    ("inside", 0),
    ("again", 0),
    ("flushed", 0),
    ("finished", 0),
    ("many", 0),
    ("flat", 0),
    ("color_sum", 0),
    // A per-vertex colour summed with the current secondary colour: llvmpipe
    // reads the secondary one as a constant, softgl interpolates both (its
    // shading key has one flat flag for the two colours), an ulp off at 9
    // pixels, 1 in a channel.
    ("color_sum_mixed", 9),
    ("arrays_current", 0),
    ("arrays_color", 0),
];

/// The floor quad of half `h` (0 left, 1 right), `c` given per vertex when set.
fn quad(gl: &mut Context, h: usize, c: Option<[f32; 4]>) {
    let x0 = if h == 1 { 0.0 } else { -4.0 };
    let x1 = x0 + 4.0;
    gl.begin(PrimitiveMode::Quads).unwrap();
    for (x, z) in [(x0, -1.5), (x1, -1.5), (x1, -30.0), (x0, -30.0)] {
        if let Some([r, g, b, a]) = c {
            gl.color4(r, g, b, a);
        }
        gl.vertex3(x, -1.0, z);
    }
    gl.end().unwrap();
}

fn color(gl: &mut Context, [r, g, b, a]: [f32; 4]) {
    gl.color4(r, g, b, a);
}

/// The whole floor from client arrays, with a colour array of `A` when `per_vertex`.
fn arrays(gl: &mut Context, per_vertex: bool) {
    let pos = [-4.0, -1.0, -1.5, 4.0, -1.0, -1.5, 4.0, -1.0, -30.0, -4.0, -1.0, -30.0];
    let col: Vec<f32> = (0..16).map(|i| A[i % 4]).collect();
    let a = match per_vertex {
        true => VertexArrays::with_colors(3, &pos, 4, &col),
        false => VertexArrays::positions(3, &pos),
    };
    gl.draw_arrays(PrimitiveMode::Quads, 0, 4, &a).unwrap();
}

fn render(name: &str, backend: Backend) -> Context {
    let mut gl = Context::new(FramebufferDesc::rgba8_d24s8(N as u32, N as u32)).unwrap();
    gl.set_backend(backend);
    gl.viewport(0, 0, N, N).unwrap();
    gl.matrix_mode(MatrixMode::Projection).unwrap();
    gl.frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 40.0).unwrap();
    gl.matrix_mode(MatrixMode::Modelview).unwrap();
    let secondary = |gl: &mut Context| {
        gl.enable(Capability::ColorSum).unwrap();
        gl.secondary_color3(0.2, 0.1, 0.05);
    };
    match name {
        "outside" => {
            color(&mut gl, A);
            quad(&mut gl, 0, None);
            color(&mut gl, B);
            quad(&mut gl, 1, None);
        }
        "inside" => {
            quad(&mut gl, 0, Some(A));
            quad(&mut gl, 1, Some(B));
        }
        "again" | "flushed" | "finished" | "many" => {
            color(&mut gl, B);
            quad(&mut gl, 1, None);
            if name == "many" {
                quad(&mut gl, 1, None);
                quad(&mut gl, 1, None);
            }
            match name {
                "flushed" => gl.load_identity().unwrap(),
                "finished" => gl.flush().unwrap(),
                _ => {}
            }
            color(&mut gl, A);
            quad(&mut gl, 0, None);
        }
        "flat" => {
            gl.shade_model(ShadeModel::Flat).unwrap();
            color(&mut gl, A);
            quad(&mut gl, 0, None);
            quad(&mut gl, 1, Some(B));
        }
        "color_sum" => {
            secondary(&mut gl);
            color(&mut gl, A);
            quad(&mut gl, 0, None);
        }
        "color_sum_mixed" => {
            secondary(&mut gl);
            quad(&mut gl, 0, Some(A));
        }
        "arrays_current" => {
            color(&mut gl, A);
            arrays(&mut gl, false);
        }
        "arrays_color" => arrays(&mut gl, true),
        _ => panic!("unknown scene {name}"),
    }
    gl
}

/// Pixels of the left half (x < 16) and of the right half that differ.
fn differ(got: &[u8], want: &[u8]) -> (usize, usize) {
    assert_eq!(got.len(), want.len());
    let mut halves = (0, 0);
    for (i, (a, b)) in got.chunks(4).zip(want.chunks(4)).enumerate() {
        if a != b {
            match i as i32 % N < N / 2 {
                true => halves.0 += 1,
                false => halves.1 += 1,
            }
        }
    }
    halves
}

fn llvmpipe() -> std::collections::HashMap<String, Vec<u8>> {
    common::hex_scenes(include_str!("llvmpipe/current_color.txt"))
}

#[test]
fn the_recording_tells_constant_from_interpolated() {
    // The left quad, colour A, interpolated by llvmpipe lands 142 pixels an ulp
    // off the constant; so the scenes below can fail.
    let l = llvmpipe();
    assert_eq!(differ(&l["outside"], &l["inside"]), (142, 0));
    for (constant, name) in [
        (false, "again"),
        (true, "flushed"),
        (true, "finished"),
        (true, "many"),
        (true, "flat"),
    ] {
        let want = if constant { (0, 0) } else { (142, 0) };
        assert_eq!(differ(&l[name], &l["outside"]).0, want.0, "{name}");
    }
    let drawn = l["outside"].chunks(4).filter(|p| p[3] != 0).count();
    assert_eq!(drawn, 284);
}

#[test]
fn every_scene_matches_llvmpipe_on_both_back_ends() {
    let l = llvmpipe();
    let mut report = Vec::new();
    for backend in [Backend::Interpreter, Backend::Jit] {
        for &(name, budget) in SCENES {
            let mut gl = render(name, backend);
            let got = gl.framebuffer().color_bytes();
            let (left, right) = differ(got, &l[name]);
            let most = got.iter().zip(&l[name]).map(|(a, b)| a.abs_diff(*b)).max();
            if left + right > budget || most > Some(1) {
                report.push(format!(
                    "{backend:?} {name}: {left} + {right} pixels differ (budget {budget})"
                ));
            }
        }
    }
    assert!(report.is_empty(), "{}", report.join("\n"));
}
