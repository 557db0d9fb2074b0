//! Draws longer than the geometry's vertex batch (256 vertices): the batch
//! keeps vertex 0 once its window has moved on, for the modes that refer
//! back to it (fans, polygons, line loops), and moves the vertices a
//! primitive still needs when it refills. Each mode is checked against the
//! same primitives spelled out one by one, inside the view volume and
//! across its edges (clipped), pixel for pixel.

use softgl::{Context, FramebufferDesc, PrimitiveMode};

/// Vertex `i` of `n` on a ring of radius `r` around `(cx, cy)`, with a colour
/// of its own.
fn ring(i: usize, n: usize, (cx, cy, r): (f32, f32, f32)) -> ([f32; 2], [f32; 4]) {
    let a = i as f32 / n as f32 * std::f32::consts::TAU;
    let c = [
        (i % 7) as f32 / 6.0,
        (i % 11) as f32 / 10.0,
        (i % 13) as f32 / 12.0,
        1.0,
    ];
    ([cx + r * a.cos(), cy + r * a.sin()], c)
}

fn render(mode: PrimitiveMode, vertices: &[([f32; 2], [f32; 4])]) -> Vec<u8> {
    let mut gl = Context::new(FramebufferDesc::rgba8_d24s8(96, 96)).unwrap();
    gl.begin(mode).unwrap();
    for ([x, y], [r, g, b, a]) in vertices {
        gl.color4(*r, *g, *b, *a);
        gl.vertex2(*x, *y);
    }
    gl.end().unwrap();
    gl.framebuffer().color_bytes().to_vec()
}

#[test]
fn long_fans_polygons_and_line_loops_keep_vertex_zero() {
    let n = 700;
    // Centre inside, ring crossing the window's edges; centre outside.
    for (centre, r) in [((0.0, 0.0), 1.2), ((-1.3, 0.2), 1.5), ((0.1, -0.2), 0.8)] {
        let mut fan = vec![([centre.0, centre.1], [1.0, 1.0, 1.0, 1.0])];
        fan.extend((0..n).map(|i| ring(i, n, (centre.0, centre.1, r))));
        let mut triangles = Vec::new();
        for i in 1..fan.len() - 1 {
            triangles.extend([fan[0], fan[i], fan[i + 1]]);
        }
        let spelled = render(PrimitiveMode::Triangles, &triangles);
        assert!(spelled.chunks(4).any(|p| p[3] != 0), "something is drawn");
        assert_eq!(
            render(PrimitiveMode::TriangleFan, &fan),
            spelled,
            "fan around {centre:?}"
        );
        assert_eq!(
            render(PrimitiveMode::Polygon, &fan),
            spelled,
            "polygon around {centre:?}"
        );

        let outline: Vec<_> = (0..n).map(|i| ring(i, n, (centre.0, centre.1, r))).collect();
        let mut lines = Vec::new();
        for i in 0..n {
            lines.extend([outline[i], outline[(i + 1) % n]]);
        }
        assert_eq!(
            render(PrimitiveMode::LineLoop, &outline),
            render(PrimitiveMode::Lines, &lines),
            "line loop around {centre:?}"
        );
    }
}

#[test]
fn long_strips_match_their_triangles() {
    let n = 900;
    // A zig-zag strip across the window and past its edges.
    let strip: Vec<_> = (0..n)
        .map(|i| {
            let x = -1.3 + 2.6 * (i / 2) as f32 / (n / 2) as f32;
            let y = if i % 2 == 0 { -0.7 } else { 0.9 } + (i % 5) as f32 * 0.05;
            ([x, y], ring(i, n, (0.0, 0.0, 1.0)).1)
        })
        .collect();
    let mut triangles = Vec::new();
    for i in 0..n - 2 {
        // Odd triangles of a strip are wound the other way (v1, v0, v2).
        let t = if i % 2 == 0 {
            [i, i + 1, i + 2]
        } else {
            [i + 1, i, i + 2]
        };
        triangles.extend(t.map(|k| strip[k]));
    }
    assert_eq!(
        render(PrimitiveMode::TriangleStrip, &strip),
        render(PrimitiveMode::Triangles, &triangles)
    );
}

/// The vertex window is kept from draw to draw (`batch::Window`): a draw
/// after others of other varying layouts (fog added, colour made uniform,
/// clipped vertices) draws what it draws in a fresh context. (It passes
/// too with the window never reset between layouts: no slot outside a
/// draw's layout is read today; the reset keeps that so.)
#[test]
fn a_draw_after_other_layouts_draws_as_in_a_fresh_context() {
    use softgl::{Capability, ClearMask};
    let n = 300;
    let fan = |centre: (f32, f32), r: f32| {
        let mut v = vec![([centre.0, centre.1], [1.0, 1.0, 1.0, 1.0])];
        v.extend((0..n).map(|i| ring(i, n, (centre.0, centre.1, r))));
        v
    };
    let draw = |gl: &mut Context, vertices: &[([f32; 2], [f32; 4])], fog: bool| {
        match fog {
            true => gl.enable(Capability::Fog).unwrap(),
            false => gl.disable(Capability::Fog).unwrap(),
        }
        gl.begin(PrimitiveMode::TriangleFan).unwrap();
        for ([x, y], [r, g, b, a]) in vertices {
            gl.color4(*r, *g, *b, *a);
            gl.vertex2(*x, *y);
        }
        gl.end().unwrap();
    };
    let draws = [
        (fan((-1.3, 0.2), 1.5), true),
        (fan((0.0, 0.0), 1.2), false),
        (vec![([0.0, 0.0], [0.5, 0.25, 1.0, 1.0]); 40], false),
        (fan((0.1, -0.2), 0.8), true),
    ];
    for (k, (last, fog)) in draws.iter().enumerate() {
        let mut fresh = Context::new(FramebufferDesc::rgba8_d24s8(96, 96)).unwrap();
        draw(&mut fresh, last, *fog);
        let mut gl = Context::new(FramebufferDesc::rgba8_d24s8(96, 96)).unwrap();
        for (v, f) in draws.iter().filter(|d| !std::ptr::eq(*d, &draws[k])) {
            draw(&mut gl, v, *f);
        }
        gl.clear(ClearMask::ALL).unwrap();
        draw(&mut gl, last, *fog);
        assert_eq!(
            gl.framebuffer().color_bytes(),
            fresh.framebuffer().color_bytes(),
            "draw {k} after the others"
        );
    }
}
