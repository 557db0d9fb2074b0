//! GL's rasterization rules, checked on exact pixels. Where llvmpipe's
//! behaviour was measured (docs/llvmpipe-facts.md), the expected pixels are
//! llvmpipe's.

use softgl::{
    BlendFactor, Capability, ClearMask, ColorFormat, CompareFunc, Context, FramebufferDesc, Indices, MatrixMode,
    PrimitiveMode, ShadeModel, StencilOp, VertexArrays,
};

/// A context whose object coordinates are window coordinates (y up).
fn window_ctx(w: u32, h: u32) -> Context {
    let mut gl = Context::new(FramebufferDesc::rgba8_d24s8(w, h)).unwrap();
    gl.matrix_mode(MatrixMode::Projection).unwrap();
    gl.ortho(0.0, f64::from(w), 0.0, f64::from(h), -1.0, 1.0).unwrap();
    gl.matrix_mode(MatrixMode::Modelview).unwrap();
    gl
}

/// Counts coverage in the stencil buffer: every fragment increments it.
fn count_with_stencil(gl: &mut Context) {
    gl.enable(Capability::StencilTest).unwrap();
    gl.stencil_func(CompareFunc::Always, 0, 0xff).unwrap();
    gl.stencil_op(StencilOp::Keep, StencilOp::Keep, StencilOp::Incr)
        .unwrap();
}

fn stencil_grid(gl: &mut Context) -> Vec<Vec<u8>> {
    let fb = gl.framebuffer();
    (0..fb.height())
        .map(|y| (0..fb.width()).map(|x| fb.stencil_at(x, y).unwrap()).collect())
        .collect()
}

/// The lit pixels (stencil > 0) as `(x, y)`, row by row from y = 0.
fn lit(gl: &mut Context) -> Vec<(u32, u32)> {
    let fb = gl.framebuffer();
    let mut v = Vec::new();
    for y in 0..fb.height() {
        for x in 0..fb.width() {
            if fb.stencil_at(x, y).unwrap() > 0 {
                v.push((x, y));
            }
        }
    }
    v
}

fn draw(gl: &mut Context, mode: PrimitiveMode, pts: &[(f32, f32)]) {
    gl.begin(mode).unwrap();
    for &(x, y) in pts {
        gl.vertex2(x, y);
    }
    gl.end().unwrap();
}

/// A fan around `(cx, cy)`: the center, then `n + 1` points on an ellipse
/// of radii `rx`, `ry` starting at angle `phase` (the last repeats the first).
fn fan(cx: f32, cy: f32, rx: f32, ry: f32, n: usize, phase: f32) -> Vec<(f32, f32)> {
    let mut pts = vec![(cx, cy)];
    for i in 0..=n {
        let a = i as f32 / n as f32 * std::f32::consts::TAU + phase;
        pts.push((cx + rx * a.cos(), cy + ry * a.sin()));
    }
    pts
}

fn rect(x0: u32, x1: u32, y0: u32, y1: u32) -> Vec<(u32, u32)> {
    (y0..=y1).flat_map(|y| (x0..=x1).map(move |x| (x, y))).collect()
}

#[test]
fn fan_of_64_covering_the_window_hits_every_pixel_exactly_once() {
    let mut gl = window_ctx(64, 64);
    count_with_stencil(&mut gl);
    let pts = fan(13.37, 41.71, 300.0, 300.0, 64, 0.0);
    draw(&mut gl, PrimitiveMode::TriangleFan, &pts);
    let grid = stencil_grid(&mut gl);
    let ones = grid.iter().flatten().filter(|&&s| s == 1).count();
    assert_eq!(ones, 64 * 64, "every pixel hit exactly once: {grid:?}");
}

#[test]
fn fan_of_64_inside_the_window_hits_no_pixel_twice() {
    let mut gl = window_ctx(64, 64);
    count_with_stencil(&mut gl);
    let pts = fan(29.13, 35.77, 21.3, 17.9, 64, 0.1);
    draw(&mut gl, PrimitiveMode::TriangleFan, &pts);
    let grid = stencil_grid(&mut gl);
    assert_eq!(grid.iter().flatten().copied().max(), Some(1), "no pixel hit twice");
    // The same outline as one polygon covers the same pixels: the shared edges
    // inside the fan neither drop nor add pixels.
    let fan = lit(&mut gl);
    let mut gl2 = window_ctx(64, 64);
    count_with_stencil(&mut gl2);
    draw(&mut gl2, PrimitiveMode::Polygon, &pts[1..pts.len() - 1]);
    let poly = lit(&mut gl2);
    assert!(
        fan.len() > 1000,
        "the fan covers an ellipse of about 1200 pixels, got {}",
        fan.len()
    );
    // A polygon is a fan from its first vertex: other interior edges, same union.
    assert_eq!(fan, poly);
}

#[test]
fn grid_of_quads_with_edges_through_pixel_centers_hits_every_pixel_once() {
    let mut gl = window_ctx(40, 40);
    count_with_stencil(&mut gl);
    gl.begin(PrimitiveMode::Quads).unwrap();
    for i in 0..10 {
        for j in 0..10 {
            let (x0, y0) = (2.5 + 3.0 * i as f32, 4.5 + 3.0 * j as f32);
            gl.vertex2(x0, y0);
            gl.vertex2(x0 + 3.0, y0);
            gl.vertex2(x0 + 3.0, y0 + 3.0);
            gl.vertex2(x0, y0 + 3.0);
        }
    }
    gl.end().unwrap();
    let grid = stencil_grid(&mut gl);
    assert_eq!(grid.iter().flatten().copied().max(), Some(1));
    // Left and bottom edges own the centers on them: x 2.5..32.5 covers 2..=31.
    assert_eq!(lit(&mut gl), rect(2, 31, 4, 33));
}

#[test]
fn additive_blending_counts_shared_edges_once() {
    let mut gl = window_ctx(32, 32);
    gl.enable(Capability::Blend).unwrap();
    gl.blend_func(BlendFactor::One, BlendFactor::One).unwrap();
    gl.color4(1.0 / 255.0, 0.0, 0.0, 0.0);
    // A strip of 30 triangles with vertices on pixel centers and corners.
    let mut pts = Vec::new();
    for i in 0..16 {
        pts.push((1.5 + 2.0 * i as f32, 3.0));
        pts.push((0.5 + 2.0 * i as f32, 29.5));
    }
    draw(&mut gl, PrimitiveMode::TriangleStrip, &pts);
    let fb = gl.framebuffer();
    let mut covered = 0;
    for y in 0..32 {
        for x in 0..32 {
            let r = fb.pixel(x, y).unwrap()[0];
            assert!(r <= 1, "pixel ({x}, {y}) hit {r} times");
            covered += u32::from(r);
        }
    }
    assert!(covered > 700, "the strip covers about 30x26 pixels, got {covered}");
}

#[test]
fn top_left_rule_matches_llvmpipe_on_axis_aligned_edges() {
    // llvmpipe: quad (1.5,1.5)-(5.5,5.5) lights x = 1..=4, y = 1..=4, either winding.
    for ccw in [true, false] {
        let mut gl = window_ctx(10, 8);
        count_with_stencil(&mut gl);
        let mut q = [(1.5, 1.5), (5.5, 1.5), (5.5, 5.5), (1.5, 5.5)];
        if !ccw {
            q.reverse();
        }
        draw(&mut gl, PrimitiveMode::Triangles, &[q[0], q[1], q[2], q[0], q[2], q[3]]);
        assert_eq!(lit(&mut gl), rect(1, 4, 1, 4), "ccw = {ccw}");
    }
}

#[test]
fn top_left_rule_matches_llvmpipe_on_sloped_edges() {
    // Triangle A: the hypotenuse x + y = 9 has the inside at -x: centers on it are out.
    let mut gl = window_ctx(10, 8);
    count_with_stencil(&mut gl);
    draw(&mut gl, PrimitiveMode::Triangles, &[(1.5, 1.5), (7.5, 1.5), (1.5, 7.5)]);
    let expect: Vec<(u32, u32)> = (1..=6).flat_map(|y| (1..=(7 - y)).map(move |x| (x, y))).collect();
    assert_eq!(lit(&mut gl), expect);
    // Triangle B: the inside is at +x: centers on the hypotenuse are in.
    let mut gl = window_ctx(10, 8);
    count_with_stencil(&mut gl);
    draw(&mut gl, PrimitiveMode::Triangles, &[(7.5, 7.5), (1.5, 7.5), (7.5, 1.5)]);
    let expect: Vec<(u32, u32)> = (2..=6).flat_map(|y| ((8 - y)..=6).map(move |x| (x, y))).collect();
    assert_eq!(lit(&mut gl), expect);
}

#[test]
fn vertices_snap_to_nearest_subpixel_with_ties_to_even() {
    // A left edge at 2.5 + d: pixel 2 is in while the snapped edge is <= 2.5.
    for (d, in_) in [
        (1.0 / 1024.0, true),
        (1.0 / 512.0, true),
        (3.0 / 1024.0, false),
        (1.0 / 256.0, false),
    ] {
        let mut gl = window_ctx(8, 4);
        count_with_stencil(&mut gl);
        let x0 = 2.5 + d;
        draw(
            &mut gl,
            PrimitiveMode::Triangles,
            &[(x0, 0.0), (6.0, 0.0), (6.0, 4.0), (x0, 0.0), (6.0, 4.0), (x0, 4.0)],
        );
        assert_eq!(gl.framebuffer().stencil_at(2, 1) == Some(1), in_, "d = {d}");
    }
}

/// llvmpipe snaps its top-down window y, which can round apart from the
/// bottom-up one (docs/llvmpipe-facts.md 2). Two triangles of the
/// conformance scene `random_20k_depth`, with llvmpipe's counts and the
/// pixel each disputes (measured with Mesa 22.3.6's OSMesa, 2026-11-23).
#[test]
fn vertices_snap_in_llvmpipes_top_down_frame() {
    let cases = [
        // (148.8652 - 0.5) * 256 = 37981.49 bottom-up, but top-down
        // (875.134765625 - 0.5) * 256 = 223906.5 rounds to even: (64, 147) is out.
        (
            [(47.370697, 142.39249), (69.0798, 148.8652), (67.26863, 166.61145)],
            199,
            (64, 147),
            false,
        ),
        // Clipped at x = 1024; the clip vertex's y snaps apart: (1012, 801) is in.
        (
            [(997.6679, 818.7948), (995.8139, 801.3328), (1039.3273, 801.76874)],
            333,
            (1012, 801),
            true,
        ),
    ];
    for (tri, count, (x, y), in_) in cases {
        let mut gl = window_ctx(1024, 1024);
        count_with_stencil(&mut gl);
        draw(&mut gl, PrimitiveMode::Triangles, &tri);
        assert_eq!(lit(&mut gl).len(), count, "{tri:?}");
        assert_eq!(
            gl.framebuffer().stencil_at(x, y) == Some(1),
            in_,
            "{tri:?} at ({x}, {y})"
        );
    }
}

#[test]
fn quads_split_along_v0_v2_and_flat_shading_takes_the_last_vertex() {
    // llvmpipe: red 255 at v0 and v2, 0 at v1 and v3: the diagonal x == y is all 255.
    let mut gl = window_ctx(16, 16);
    gl.begin(PrimitiveMode::Quads).unwrap();
    for (i, (x, y)) in [(0.0, 0.0), (16.0, 0.0), (16.0, 16.0), (0.0, 16.0)]
        .into_iter()
        .enumerate()
    {
        let r = if i % 2 == 0 { 1.0 } else { 0.0 };
        gl.color3(r, 0.0, 0.0);
        gl.vertex2(x, y);
    }
    gl.end().unwrap();
    for i in 0..16 {
        assert_eq!(gl.framebuffer().pixel(i, i).unwrap()[0], 255, "diagonal pixel {i}");
    }
    assert!(gl.framebuffer().pixel(12, 3).unwrap()[0] < 255);

    // Flat shading: quads take v3, polygons v0, triangles v2.
    let cases = [
        (PrimitiveMode::Quads, 3usize),
        (PrimitiveMode::Polygon, 0),
        (PrimitiveMode::TriangleFan, 3),
    ];
    for (mode, provoking) in cases {
        let mut gl = window_ctx(16, 16);
        gl.shade_model(ShadeModel::Flat).unwrap();
        gl.begin(mode).unwrap();
        for (i, (x, y)) in [(0.0, 0.0), (16.0, 0.0), (16.0, 16.0), (0.0, 16.0)]
            .into_iter()
            .enumerate()
        {
            gl.color3(i as f32 / 4.0, 0.0, 0.0);
            gl.vertex2(x, y);
        }
        gl.end().unwrap();
        let want = (provoking as f32 / 4.0 * 255.0).round_ties_even() as u8;
        for (x, y) in [(12, 3), (3, 12)] {
            let got = gl.framebuffer().pixel(x, y).unwrap()[0];
            let want = if mode == PrimitiveMode::TriangleFan && y > x {
                // The fan's first triangle (0, 1, 2) takes v2, its second (0, 2, 3) takes v3.
                want
            } else if mode == PrimitiveMode::TriangleFan {
                (2.0f32 / 4.0 * 255.0).round_ties_even() as u8
            } else {
                want
            };
            assert_eq!(got, want, "{mode:?} at ({x}, {y})");
        }
    }
}

/// A self-intersecting quad shows which diagonal llvmpipe split it along. Its
/// split depends on how the quad is drawn (Mesa 22.3.6, probed with these
/// vertices; docs/llvmpipe-facts.md §12): v0-v2 in immediate mode and
/// `draw_arrays`, unless flat shading meets a per-vertex colour; v1-v3 always
/// for `draw_elements`.
#[test]
fn bowtie_quads_split_as_llvmpipe_does_for_each_way_of_drawing() {
    const V: [(f32, f32); 4] = [(2.0, 2.0), (2.0, 29.0), (29.0, 4.0), (29.0, 30.0)];
    const COLORS: [[f32; 3]; 4] = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0, 1.0, 0.0]];
    let coverage = |draw: &dyn Fn(&mut Context)| {
        let mut gl = window_ctx(32, 32);
        count_with_stencil(&mut gl);
        draw(&mut gl);
        stencil_grid(&mut gl)
    };
    let split = |t: [usize; 6]| coverage(&|gl| draw(gl, PrimitiveMode::Triangles, &t.map(|i| V[i])));
    let (v0_v2, v1_v3) = (split([0, 1, 2, 0, 2, 3]), split([0, 1, 3, 1, 2, 3]));
    assert_ne!(v0_v2, v1_v3, "the two splits of the bowtie differ");
    let pos: Vec<f32> = V.iter().flat_map(|&(x, y)| [x, y]).collect();
    let col: Vec<f32> = COLORS.concat();
    for shade in [ShadeModel::Smooth, ShadeModel::Flat] {
        for per_vertex in [false, true] {
            let arrays = if per_vertex {
                VertexArrays::with_colors(2, &pos, 3, &col)
            } else {
                VertexArrays::positions(2, &pos)
            };
            let immediate = coverage(&|gl| {
                gl.shade_model(shade).unwrap();
                gl.begin(PrimitiveMode::Quads).unwrap();
                for (&(x, y), [r, g, b]) in V.iter().zip(COLORS) {
                    if per_vertex {
                        gl.color3(r, g, b);
                    }
                    gl.vertex2(x, y);
                }
                gl.end().unwrap();
            });
            let draw_arrays = coverage(&|gl| {
                gl.shade_model(shade).unwrap();
                gl.draw_arrays(PrimitiveMode::Quads, 0, 4, &arrays).unwrap();
            });
            let draw_elements = coverage(&|gl| {
                gl.shade_model(shade).unwrap();
                gl.draw_elements(PrimitiveMode::Quads, Indices::U8(&[0, 1, 2, 3]), &arrays)
                    .unwrap();
            });
            let want = if shade == ShadeModel::Flat && per_vertex {
                &v1_v3
            } else {
                &v0_v2
            };
            let what = format!("{shade:?}, per-vertex colour {per_vertex}");
            assert!(immediate == *want, "begin/end, {what}");
            assert!(draw_arrays == *want, "draw_arrays, {what}");
            assert!(draw_elements == v1_v3, "draw_elements, {what}");
        }
    }
}

#[test]
fn quad_strip_splits_along_v0_v3() {
    // Red 255 at v0 and v3 of the strip's quad: the v0-v3 diagonal is all 255.
    let mut gl = window_ctx(16, 16);
    gl.begin(PrimitiveMode::QuadStrip).unwrap();
    for (i, (x, y)) in [(0.0, 0.0), (16.0, 0.0), (0.0, 16.0), (16.0, 16.0)]
        .into_iter()
        .enumerate()
    {
        let r = if i == 0 || i == 3 { 1.0 } else { 0.0 };
        gl.color3(r, 0.0, 0.0);
        gl.vertex2(x, y);
    }
    gl.end().unwrap();
    for i in 0..16 {
        assert_eq!(gl.framebuffer().pixel(i, i).unwrap()[0], 255, "diagonal pixel {i}");
    }
}

#[test]
fn smooth_colors_are_sampled_at_centers_and_rounded_like_llvmpipe() {
    let mut gl = window_ctx(16, 1);
    let data = [0.0, 0.0, 16.0, 0.0, 16.0, 1.0, 0.0, 1.0];
    let colors = [
        0.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0,
    ];
    gl.draw_arrays(
        PrimitiveMode::Quads,
        0,
        4,
        &VertexArrays::with_colors(2, &data, 4, &colors),
    )
    .unwrap();
    let reds: Vec<u8> = (0..16).map(|x| gl.framebuffer().pixel(x, 0).unwrap()[0]).collect();
    assert_eq!(
        reds,
        [8, 24, 40, 56, 72, 88, 104, 120, 135, 151, 167, 183, 199, 215, 231, 247]
    );
}

#[test]
fn depth_values_match_llvmpipe_z24() {
    for (z_ndc, want) in [
        (0.0f32, 0x80_0000u32),
        (-0.5, 0x40_0000),
        (0.5, 0xBF_FFFF),
        (1.0, 0xFF_FFFF),
    ] {
        let mut gl = window_ctx(4, 4);
        gl.enable(Capability::DepthTest).unwrap();
        gl.depth_func(CompareFunc::Always).unwrap();
        gl.begin(PrimitiveMode::Quads).unwrap();
        // ortho(-1, 1) near/far: window z = (-z_eye + 1) / 2.
        for (x, y) in [(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (0.0, 4.0)] {
            gl.vertex3(x, y, -z_ndc);
        }
        gl.end().unwrap();
        assert_eq!(gl.framebuffer().depth_at(1, 1), Some(want), "z_ndc = {z_ndc}");
    }
}

#[test]
fn thin_lines_follow_diamond_exit_like_llvmpipe() {
    type Case = ((f32, f32), (f32, f32), Vec<(u32, u32)>);
    let cases: [Case; 7] = [
        ((0.5, 0.5), (8.5, 0.5), rect(0, 7, 0, 0)),
        ((8.5, 0.5), (0.5, 0.5), rect(1, 8, 0, 0)),
        ((1.5, 1.5), (1.5, 7.5), rect(1, 1, 1, 6)),
        ((1.5, 7.5), (1.5, 1.5), rect(1, 1, 2, 7)),
        ((0.5, 0.5), (7.5, 7.5), (0..=6).map(|i| (i, i)).collect()),
        (
            (0.0, 0.0),
            (8.0, 3.0),
            [rect(0, 2, 0, 0), rect(3, 4, 1, 1), rect(5, 7, 2, 2)].concat(),
        ),
        ((0.3, 0.5), (8.7, 0.5), rect(0, 7, 0, 0)),
    ];
    for (a, b, want) in cases {
        let mut gl = window_ctx(10, 10);
        count_with_stencil(&mut gl);
        draw(&mut gl, PrimitiveMode::Lines, &[a, b]);
        assert_eq!(lit(&mut gl), want, "line {a:?} -> {b:?}");
    }
    // A zero-length line and one that never leaves its start diamond draw nothing.
    for (a, b) in [((3.5, 3.5), (3.5, 3.5)), ((0.2, 0.5), (0.8, 0.5))] {
        let mut gl = window_ctx(10, 10);
        count_with_stencil(&mut gl);
        draw(&mut gl, PrimitiveMode::Lines, &[a, b]);
        assert!(lit(&mut gl).is_empty(), "line {a:?} -> {b:?}");
    }
}

#[test]
fn wide_lines_are_parallelograms_like_llvmpipe() {
    let cases = [
        (3.0, (1.5, 4.5), (9.5, 4.5), rect(1, 8, 3, 5)),
        (3.0, (1.0, 4.0), (9.0, 4.0), rect(1, 8, 2, 4)),
        (2.0, (1.5, 4.5), (9.5, 4.5), rect(1, 8, 3, 4)),
        (3.0, (4.5, 1.5), (4.5, 8.5), rect(3, 5, 1, 7)),
    ];
    for (width, a, b, want) in cases {
        let mut gl = window_ctx(12, 12);
        count_with_stencil(&mut gl);
        gl.line_width(width).unwrap();
        draw(&mut gl, PrimitiveMode::Lines, &[a, b]);
        assert_eq!(lit(&mut gl), want, "width {width} {a:?} -> {b:?}");
    }
}

#[test]
fn points_cover_llvmpipe_squares() {
    let cases = [
        ((4.5, 4.5), 1.0, rect(4, 4, 4, 4)),
        ((4.5, 4.5), 2.0, rect(4, 5, 4, 5)),
        ((4.5, 4.5), 3.0, rect(3, 5, 3, 5)),
        ((4.5, 4.5), 4.0, rect(3, 6, 3, 6)),
        ((4.0, 4.0), 1.0, rect(4, 4, 4, 4)),
        ((4.0, 4.0), 2.0, rect(3, 4, 3, 4)),
        ((4.0, 4.0), 4.0, rect(2, 5, 2, 5)),
        ((4.25, 4.75), 2.0, rect(3, 4, 4, 5)),
        ((4.5, 4.5), 2.5, rect(4, 5, 4, 5)),
    ];
    for ((x, y), size, want) in cases {
        let mut gl = window_ctx(10, 10);
        count_with_stencil(&mut gl);
        gl.point_size(size).unwrap();
        draw(&mut gl, PrimitiveMode::Points, &[(x, y)]);
        assert_eq!(lit(&mut gl), want, "point at ({x}, {y}) size {size}");
    }
}

#[test]
fn every_primitive_mode_draws_the_expected_fragment_count() {
    let square = [(1.0, 1.0), (9.0, 1.0), (9.0, 9.0), (1.0, 9.0)];
    let cases = [
        (PrimitiveMode::Points, 4),
        (PrimitiveMode::Lines, 8 + 8),
        (PrimitiveMode::LineStrip, 8 * 3),
        (PrimitiveMode::LineLoop, 8 * 4),
        (PrimitiveMode::Triangles, 36),
        (PrimitiveMode::TriangleStrip, 8 * 8),
        (PrimitiveMode::TriangleFan, 8 * 8),
        (PrimitiveMode::Quads, 64),
        (PrimitiveMode::QuadStrip, 36),
        (PrimitiveMode::Polygon, 64),
    ];
    for (mode, want) in cases {
        let mut gl = window_ctx(12, 12);
        count_with_stencil(&mut gl);
        let pts: Vec<(f32, f32)> = match mode {
            // A strip and a quad strip zig-zag: order the square's corners for them.
            PrimitiveMode::TriangleStrip | PrimitiveMode::QuadStrip => vec![square[0], square[1], square[3], square[2]],
            _ => square.to_vec(),
        };
        draw(&mut gl, mode, &pts);
        let count: u32 = stencil_grid(&mut gl).iter().flatten().map(|&s| u32::from(s)).sum();
        let want = match mode {
            // The quad strip's one quad is the full square.
            PrimitiveMode::QuadStrip => 64,
            _ => want,
        };
        assert_eq!(count, want, "{mode:?}");
    }
}

/// RGB 5-6-5 as llvmpipe stores it (docs/llvmpipe-facts.md §13): fragments
/// and scissored clears truncate the unorm8 value to its high bits, a
/// whole-buffer clear rounds `c * max` half up, and `GL_DITHER` dithers only
/// when the opt-in knob is on.
#[test]
fn rgb565_truncates_like_llvmpipe_and_dithers_only_when_asked() {
    let desc = FramebufferDesc {
        color: ColorFormat::Rgb565,
        depth_bits: 0,
        stencil_bits: 0,
        ..FramebufferDesc::rgba8_d24s8(8, 8)
    };
    let stored = |gl: &mut Context, x: u32, y: u32| {
        let i = (y * 8 + x) as usize * 2;
        let b = gl.framebuffer().color_bytes();
        let v = u16::from_le_bytes([b[i], b[i + 1]]);
        (v >> 11, (v >> 5) & 63, v & 31)
    };
    let mut gl = Context::new(desc).unwrap();
    // (0.1, 0.2, 0.3): unorm8 (26, 51, 76) truncates to (3, 12, 9); c * max
    // is (3.1, 12.6, 9.3), which rounds to (3, 13, 9).
    gl.clear_color(0.1, 0.2, 0.3, 1.0).unwrap();
    gl.clear(ClearMask::COLOR).unwrap();
    assert_eq!(stored(&mut gl, 5, 5), (3, 13, 9), "whole-buffer clear");
    gl.enable(Capability::ScissorTest).unwrap();
    gl.scissor(0, 0, 4, 8).unwrap();
    gl.clear(ClearMask::COLOR).unwrap();
    gl.disable(Capability::ScissorTest).unwrap();
    assert_eq!(
        (stored(&mut gl, 1, 1), stored(&mut gl, 5, 1)),
        ((3, 12, 9), (3, 13, 9)),
        "scissored clear"
    );
    gl.color3(0.1, 0.2, 0.3);
    draw(
        &mut gl,
        PrimitiveMode::Triangles,
        &[(0.0, -1.0), (1.0, -1.0), (1.0, 1.0)],
    );
    assert_eq!(stored(&mut gl, 7, 0), (3, 12, 9), "a fragment");

    // Red byte 4 is 0.49 of a 5-bit step: truncated it is 0; the ordered
    // dither stores 1 where the Bayer entry is 8 or more (16 b + 7 >= 255 - 124).
    let full = [
        (-1.0, -1.0),
        (1.0, -1.0),
        (1.0, 1.0),
        (-1.0, -1.0),
        (1.0, 1.0),
        (-1.0, 1.0),
    ];
    let reds = |gl: &mut Context| {
        gl.color3(4.0 / 255.0, 0.0, 0.0);
        draw(gl, PrimitiveMode::Triangles, &full);
        (0..64).map(|i| stored(gl, i % 8, i / 8).0).sum::<u16>()
    };
    assert!(gl.state().dither, "GL_DITHER is on by default");
    assert_eq!(reds(&mut gl), 0, "GL_DITHER alone changes nothing");
    gl.set_ordered_dither(true);
    assert_eq!(reds(&mut gl), 32, "half of each 4x4 block dithers up");
    gl.disable(Capability::Dither).unwrap();
    assert_eq!(reds(&mut gl), 0, "the knob without GL_DITHER");
}

#[test]
fn rgb565_and_bgra_framebuffers_render() {
    for color in [ColorFormat::Rgb565, ColorFormat::Bgra8, ColorFormat::Rgb8] {
        let desc = FramebufferDesc {
            width: 8,
            height: 8,
            color,
            depth_bits: 16,
            stencil_bits: 0,
        };
        let mut gl = Context::new(desc).unwrap();
        gl.clear_color(0.0, 0.0, 1.0, 1.0).unwrap();
        gl.clear(ClearMask::ALL).unwrap();
        gl.color3(1.0, 0.0, 0.0);
        draw(
            &mut gl,
            PrimitiveMode::Triangles,
            &[(-1.0, -1.0), (0.0, -1.0), (0.0, 1.0)],
        );
        let fb = gl.framebuffer();
        assert_eq!(fb.pixel(0, 7), Some([0, 0, 255, 255]), "{color:?} clear");
        assert_eq!(fb.pixel(3, 1), Some([255, 0, 0, 255]), "{color:?} drawn");
    }
}

#[test]
fn long_strips_fans_and_loops_span_vertex_batches_without_gaps() {
    // 1000 vertices: four batches of 256. A fan of 998 triangles covering the
    // window still hits every pixel exactly once.
    let mut gl = window_ctx(48, 48);
    count_with_stencil(&mut gl);
    let pts = fan(20.3, 25.9, 200.0, 200.0, 998, 0.0);
    draw(&mut gl, PrimitiveMode::TriangleFan, &pts);
    assert!(
        stencil_grid(&mut gl).iter().flatten().all(|&s| s == 1),
        "fan across batches"
    );

    // A strip of 999 triangles zig-zagging over the window, same rule.
    let mut gl = window_ctx(48, 48);
    count_with_stencil(&mut gl);
    let strip: Vec<(f32, f32)> = (0..1001)
        .map(|i| {
            (
                -1.0 + 50.0 * (i / 2) as f32 / 500.0,
                if i % 2 == 0 { -1.0 } else { 49.0 },
            )
        })
        .collect();
    draw(&mut gl, PrimitiveMode::TriangleStrip, &strip);
    assert!(
        stencil_grid(&mut gl).iter().flatten().all(|&s| s == 1),
        "strip across batches"
    );

    // A line loop of 600 vertices on a circle closes back to vertex 0: the
    // closing segment from vertex 599 to vertex 0 is drawn like any other.
    let mut gl = window_ctx(48, 48);
    count_with_stencil(&mut gl);
    let ring: Vec<(f32, f32)> = (0..600)
        .map(|i| {
            let a = i as f32 / 600.0 * std::f32::consts::TAU;
            (24.0 + 20.0 * a.cos(), 24.0 + 20.0 * a.sin())
        })
        .collect();
    draw(&mut gl, PrimitiveMode::LineLoop, &ring);
    let loop_pixels = lit(&mut gl);
    let mut gl = window_ctx(48, 48);
    count_with_stencil(&mut gl);
    let mut closed = ring.clone();
    closed.push(ring[0]);
    draw(&mut gl, PrimitiveMode::LineStrip, &closed);
    assert_eq!(loop_pixels, lit(&mut gl));
    // An 8-connected ring of radius r has about 4·√2·r = 113 pixels.
    assert!(
        (100..=125).contains(&loop_pixels.len()),
        "ring of radius 20: {} pixels",
        loop_pixels.len()
    );
}

#[test]
fn point_sizes_round_like_llvmpipe() {
    // llvmpipe: n = (rint(size * 256) + 127) >> 8, so 5.50098 is still 5 wide.
    for (size, width) in [
        (5.50098f32, 5u32),
        (5.503, 6),
        (2.5, 2),
        (2.9, 3),
        (0.2, 1),
        (1000.0, 255),
    ] {
        let mut gl = window_ctx(300, 1);
        count_with_stencil(&mut gl);
        gl.point_size(size).unwrap();
        draw(&mut gl, PrimitiveMode::Points, &[(150.0, 0.5)]);
        assert_eq!(lit(&mut gl).len() as u32, width, "size {size}");
    }
}

#[test]
fn polygon_offset_units_are_two_depth_steps_like_llvmpipe() {
    // A flat quad at window depth 0.45, then the same quad with offset (0, -1):
    // llvmpipe stores base - 2 (units are twice the minimum resolvable step).
    let mut gl = window_ctx(4, 4);
    gl.enable(Capability::DepthTest).unwrap();
    gl.depth_func(CompareFunc::Always).unwrap();
    let quad = |gl: &mut Context| {
        gl.begin(PrimitiveMode::Quads).unwrap();
        for (x, y) in [(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (0.0, 4.0)] {
            gl.vertex3(x, y, 0.1);
        }
        gl.end().unwrap();
    };
    quad(&mut gl);
    let base = gl.framebuffer().depth_at(1, 1).unwrap();
    assert_eq!(base, 0x73_3332, "window z 0.45, as llvmpipe stores it");
    gl.enable(Capability::PolygonOffsetFill).unwrap();
    gl.polygon_offset(0.0, -1.0).unwrap();
    quad(&mut gl);
    assert_eq!(gl.framebuffer().depth_at(1, 1), Some(base - 2));
    // An infinite offset saturates like a huge finite one.
    gl.polygon_offset(0.0, f32::INFINITY).unwrap();
    quad(&mut gl);
    assert_eq!(gl.framebuffer().depth_at(1, 1), Some(0xFF_FFFF));
}

#[test]
fn wide_points_and_lines_may_reach_past_the_viewport() {
    // llvmpipe bounds points and lines by the framebuffer, not the viewport:
    // a 5-pixel point at the viewport's corner covers pixels outside it.
    let mut gl = window_ctx(16, 16);
    count_with_stencil(&mut gl);
    gl.viewport(4, 4, 8, 8).unwrap();
    gl.point_size(5.0).unwrap();
    // Window (4.5, 4.5): NDC of the viewport's lower-left pixel center.
    gl.matrix_mode(MatrixMode::Projection).unwrap();
    gl.load_identity().unwrap();
    gl.matrix_mode(MatrixMode::Modelview).unwrap();
    draw(&mut gl, PrimitiveMode::Points, &[(-1.0 + 0.5 / 4.0, -1.0 + 0.5 / 4.0)]);
    assert_eq!(lit(&mut gl), rect(2, 6, 2, 6));
    // A point whose center is outside the view volume is dropped entirely.
    let mut gl = window_ctx(16, 16);
    count_with_stencil(&mut gl);
    gl.viewport(4, 4, 8, 8).unwrap();
    gl.point_size(5.0).unwrap();
    gl.matrix_mode(MatrixMode::Projection).unwrap();
    gl.load_identity().unwrap();
    gl.matrix_mode(MatrixMode::Modelview).unwrap();
    draw(&mut gl, PrimitiveMode::Points, &[(-1.05, 0.0)]);
    assert!(lit(&mut gl).is_empty());
}

#[test]
#[allow(
    clippy::excessive_precision,
    reason = "the coordinates as printed with %.9g for llvmpipe, bit-exact in f32"
)]
fn interpolated_depth_matches_llvmpipe_bits() {
    // One triangle rendered by Mesa 22.3.6 llvmpipe (OSMesa, Z24, ortho
    // 0..128, depth ALWAYS): every covered pixel's depth and red, to the bit.
    let mut gl = Context::new(FramebufferDesc::rgba8_d24s8(128, 128)).unwrap();
    gl.matrix_mode(MatrixMode::Projection).unwrap();
    gl.ortho(0.0, 128.0, 0.0, 128.0, -1.0, 1.0).unwrap();
    gl.matrix_mode(MatrixMode::Modelview).unwrap();
    gl.enable(Capability::DepthTest).unwrap();
    gl.depth_func(CompareFunc::Always).unwrap();
    let v = [
        [13.9502296f32, 72.2624359, -0.545780659],
        [24.9592934, 66.4730301, 0.770843029],
        [13.7014933, 77.9293213, 0.29104507],
    ];
    gl.begin(PrimitiveMode::Triangles).unwrap();
    for (i, p) in v.iter().enumerate() {
        gl.color4(0.3 * i as f32, 0.5, 0.2, 1.0);
        gl.vertex3(p[0], p[1], p[2]);
    }
    gl.end().unwrap();
    let fb = gl.framebuffer();
    let covered = (0..128u32)
        .flat_map(|y| (0..128u32).map(move |x| (x, y)))
        .filter(|&(x, y)| fb.pixel(x, y).unwrap()[3] > 0);
    assert_eq!(covered.count(), LLVMPIPE_TRIANGLE.len());
    for (x, y, depth, red) in LLVMPIPE_TRIANGLE {
        assert_eq!(
            (fb.depth_at(x, y), fb.pixel(x, y).map(|p| p[0])),
            (Some(depth), Some(red)),
            "({x}, {y})"
        );
    }
}

/// `(x, y, depth, red)` of every pixel llvmpipe covered, read back from its
/// buffers, for `interpolated_depth_matches_llvmpipe_bits`.
const LLVMPIPE_TRIANGLE: [(u32, u32, u32, u8); 30] = [
    (23, 67, 0x2e7874, 74),
    (21, 68, 0x4e1fa6, 58),
    (22, 68, 0x34476f, 80),
    (19, 69, 0x6dc6da, 43),
    (20, 69, 0x53eea2, 65),
    (21, 69, 0x3a166a, 86),
    (17, 70, 0x8d6e0c, 28),
    (18, 70, 0x7395d4, 49),
    (19, 70, 0x59bd9c, 71),
    (20, 70, 0x3fe565, 93),
    (15, 71, 0xad153f, 12),
    (16, 71, 0x933d07, 34),
    (17, 71, 0x7964d0, 56),
    (18, 71, 0x5f8c98, 77),
    (19, 71, 0x45b460, 99),
    (14, 72, 0xb2e43a, 19),
    (15, 72, 0x990c02, 40),
    (16, 72, 0x7f33ca, 62),
    (17, 72, 0x655b92, 83),
    (18, 72, 0x4b835a, 105),
    (14, 73, 0x9edafd, 46),
    (15, 73, 0x8502c5, 68),
    (16, 73, 0x6b2a8e, 90),
    (17, 73, 0x515256, 111),
    (14, 74, 0x8ad1c0, 74),
    (15, 74, 0x70f988, 96),
    (16, 74, 0x572150, 118),
    (14, 75, 0x76c884, 102),
    (15, 75, 0x5cf04c, 124),
    (14, 76, 0x62bf46, 130),
];
