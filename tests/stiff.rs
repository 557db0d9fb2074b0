//! Stiff and extreme input at the geometry level (DESIGN.md, "Stiff and
//! extreme input"): none of it may panic or write outside the framebuffer, and
//! valid geometry in the same draw must still render exactly.
//!
//! Most tests clear a 32×32 RGBA8+D24+S8 context to grey, then issue ONE draw
//! holding the bad primitives first (red) and a good quad (green) last, and
//! compare every pixel with the image the GL rules give.
//!
//! A write outside a buffer would panic (every buffer access is a checked
//! slice), so "no panic" covers it; the random test also checks that nothing
//! outside the viewport changes, which catches writes that land in the wrong
//! place inside the buffer.

mod common;
use common::count;
use glam::Mat4;
use softgl::{
    Capability, ClearMask, CompareFunc, Context, Face, FramebufferDesc, Indices, MatrixMode, PolygonMode,
    PrimitiveMode, ShadeModel, StencilOp, VertexArrays,
};

const CLEAR: [u8; 4] = [64, 64, 64, 255];
const RED: [u8; 4] = [255, 0, 0, 255];
const GREEN: [u8; 4] = [0, 255, 0, 255];
const C_RED: [f32; 4] = [1.0, 0.0, 0.0, 1.0];
const C_GREEN: [f32; 4] = [0.0, 1.0, 0.0, 1.0];
const NAN: f32 = f32::NAN;
const INF: f32 = f32::INFINITY;

/// A `w` × `h` RGBA8+D24+S8 context cleared to [`CLEAR`], depth 1, stencil 0.
fn context(w: u32, h: u32) -> Context {
    let mut gl = Context::new(FramebufferDesc::rgba8_d24s8(w, h)).unwrap();
    gl.clear_color(0.25, 0.25, 0.25, 1.0).unwrap();
    gl.clear(ClearMask::ALL).unwrap();
    gl
}

/// Loads `m` as the projection and the identity as the modelview.
fn projection(gl: &mut Context, m: impl FnOnce(&mut Context)) {
    gl.matrix_mode(MatrixMode::Projection).unwrap();
    gl.load_identity().unwrap();
    m(gl);
    gl.matrix_mode(MatrixMode::Modelview).unwrap();
    gl.load_identity().unwrap();
}

/// Object coordinates equal window coordinates on a `w` × `h` viewport.
fn window_coords(gl: &mut Context, w: f64, h: f64) {
    projection(gl, |gl| gl.ortho(0.0, w, 0.0, h, -1.0, 1.0).unwrap());
}

/// The vertices of one draw: positions `xyzw` and colors `rgba`.
#[derive(Default)]
struct Batch {
    pos: Vec<f32>,
    col: Vec<f32>,
}

impl Batch {
    fn v(&mut self, p: [f32; 4], c: [f32; 4]) -> &mut Self {
        self.pos.extend_from_slice(&p);
        self.col.extend_from_slice(&c);
        self
    }

    fn tri(&mut self, p: [[f32; 4]; 3], c: [f32; 4]) -> &mut Self {
        for q in p {
            self.v(q, c);
        }
        self
    }

    /// Two triangles covering `[x0, x1] × [y0, y1]` at depth `z`.
    fn quad(&mut self, [x0, y0, x1, y1]: [f32; 4], z: f32, c: [f32; 4]) -> &mut Self {
        self.tri([[x0, y0, z, 1.0], [x1, y0, z, 1.0], [x1, y1, z, 1.0]], c)
            .tri([[x0, y0, z, 1.0], [x1, y1, z, 1.0], [x0, y1, z, 1.0]], c)
    }

    /// The good quad: window `[8, 24)²` of a 32×32 viewport under identity matrices.
    fn good(&mut self) -> &mut Self {
        self.quad([-0.5, -0.5, 0.5, 0.5], 0.0, C_GREEN)
    }

    fn draw(&self, gl: &mut Context, mode: PrimitiveMode) {
        let arrays = VertexArrays::with_colors(4, &self.pos, 4, &self.col);
        gl.draw_arrays(mode, 0, self.pos.len() / 4, &arrays).unwrap();
        assert_eq!(gl.get_error(), None);
    }
}

fn p2(x: f32, y: f32) -> [f32; 4] {
    [x, y, 0.0, 1.0]
}

fn p3(x: f32, y: f32, z: f32) -> [f32; 4] {
    [x, y, z, 1.0]
}

/// Pixel `(x, y)` lies in the good quad's window rectangle `[8, 24)²`.
fn in_good(x: u32, y: u32) -> bool {
    (8..24).contains(&x) && (8..24).contains(&y)
}

/// Compares every pixel with `expected(x, y)` (y up) and reports the mismatches.
#[track_caller]
fn expect_image(gl: &mut Context, what: &str, expected: impl Fn(u32, u32) -> [u8; 4]) {
    let fb = gl.framebuffer();
    assert_eq!(fb.color_bytes().len(), (fb.width() * fb.height() * 4) as usize);
    let mut bad = Vec::new();
    for y in 0..fb.height() {
        for x in 0..fb.width() {
            let (got, want) = (fb.pixel(x, y).unwrap(), expected(x, y));
            if got != want {
                bad.push((x, y, got, want));
            }
        }
    }
    assert!(
        bad.is_empty(),
        "{what}: {} pixels differ, first: {:?}",
        bad.len(),
        &bad[..bad.len().min(8)]
    );
}

/// The image of "the good quad over `red(x, y)` over the clear color".
fn over(red: impl Fn(u32, u32) -> bool) -> impl Fn(u32, u32) -> [u8; 4] {
    move |x, y| {
        if in_good(x, y) {
            GREEN
        } else if red(x, y) {
            RED
        } else {
            CLEAR
        }
    }
}

#[test]
fn w_near_zero_is_a_point_at_infinity() {
    // A, B on the left edge and C = (1, 0, 0, w): for w → 0 (either sign; the
    // part with w < 0 is clipped away at the near plane) C is the point at
    // infinity along +x, so the triangle is the strip between window y = 0
    // and y = 4 across the whole viewport: rows 0..=3.
    for w in [1e-30, -1e-30, 0.0, -0.0, f32::MIN_POSITIVE, 1e-45, -1e-45] {
        let mut gl = context(32, 32);
        let mut b = Batch::default();
        b.tri([p2(-1.0, -1.0), p2(-1.0, -0.75), [1.0, 0.0, 0.0, w]], C_RED)
            .good();
        b.draw(&mut gl, PrimitiveMode::Triangles);
        expect_image(&mut gl, &format!("w = {w:e}"), over(|_, y| y < 4));
    }
}

#[test]
fn all_w_near_zero_leaves_the_good_quad_exact() {
    // Three vertices with w ≈ 0 are three points at infinity. Where a
    // triangle through such far points lands is checked exactly in
    // `huge_primitives_crossing_the_window_keep_their_shape`; here: no panic,
    // only red or the clear color outside the quad, and the quad exact.
    for w in [1e-30, -1e-30, 0.0] {
        let mut gl = context(32, 32);
        let mut b = Batch::default();
        b.tri([[1.0, 0.0, 0.0, w], [0.0, 1.0, 0.0, w], [-1.0, -1.0, 0.0, w]], C_RED);
        b.tri([[0.0, 0.0, 0.0, w], [0.0, 0.0, 0.0, w], [0.0, 0.0, 0.0, w]], C_RED);
        b.good();
        b.draw(&mut gl, PrimitiveMode::Triangles);
        let fb = gl.framebuffer();
        for y in 0..32 {
            for x in 0..32 {
                let px = fb.pixel(x, y).unwrap();
                if in_good(x, y) {
                    assert_eq!(px, GREEN, "w = {w:e} at ({x}, {y})");
                } else {
                    assert!(px == RED || px == CLEAR, "w = {w:e} at ({x}, {y}): {px:?}");
                }
            }
        }
    }
    // With w = 0 exactly the vertices stay on the plane at infinity and the
    // triangle is dropped; with w < 0 all three are behind the near plane.
    for w in [-1e-30, 0.0] {
        let mut gl = context(32, 32);
        let mut b = Batch::default();
        b.tri([[1.0, 0.0, 0.0, w], [0.0, 1.0, 0.0, w], [-1.0, -1.0, 0.0, w]], C_RED)
            .good();
        b.draw(&mut gl, PrimitiveMode::Triangles);
        expect_image(&mut gl, &format!("all w = {w:e}"), over(|_, _| false));
    }
}

/// `frustum(-1, 1, -1, 1, 1, 10)`: eye `(x, y, z)` projects to ndc `(x, y) / -z`.
fn perspective(gl: &mut Context) {
    projection(gl, |gl| gl.frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 10.0).unwrap());
}

/// The good quad in eye space for [`perspective`]: `±1` at `z = -2`, window `[8, 24)²`.
fn good_eye(b: &mut Batch) {
    b.quad([-1.0, -1.0, 1.0, 1.0], -2.0, C_GREEN);
}

#[test]
fn negative_w_is_clipped_at_the_near_plane() {
    // All three vertices behind the eye (w = -z_eye = -2 < 0): nothing, though
    // dividing by w would put a mirrored triangle in the middle of the window.
    let mut gl = context(32, 32);
    perspective(&mut gl);
    let mut b = Batch::default();
    b.tri([p3(-1.0, -1.0, 2.0), p3(1.0, -1.0, 2.0), p3(0.0, 1.0, 2.0)], C_RED);
    good_eye(&mut b);
    b.draw(&mut gl, PrimitiveMode::Triangles);
    expect_image(&mut gl, "all behind the eye", over(|_, _| false));

    // One vertex behind: a floor y = -1 from z = -4 to z = +4. Its visible part
    // (-4 <= z <= -1) projects to ndc y = 1/z in [-1, -0.25] and spans the full
    // width, so window rows 0..=11 exactly; the part behind the eye would
    // project to the top half (y = +0.25 for the far vertex) and must not.
    let mut gl = context(32, 32);
    perspective(&mut gl);
    let mut b = Batch::default();
    b.tri([p3(-4.0, -1.0, -4.0), p3(4.0, -1.0, -4.0), p3(0.0, -1.0, 4.0)], C_RED);
    good_eye(&mut b);
    b.draw(&mut gl, PrimitiveMode::Triangles);
    expect_image(&mut gl, "one vertex behind the eye", over(|_, y| y < 12));

    // Two vertices behind: the same floor as a wedge from (0, -1, -4). Its
    // visible part is |x_ndc| <= -1 - 4 y_ndc, i.e. |X - 16| < 48 - 4 Y in
    // window coordinates (no pixel center lies on the boundary).
    let mut gl = context(32, 32);
    perspective(&mut gl);
    let mut b = Batch::default();
    b.tri([p3(0.0, -1.0, -4.0), p3(-8.0, -1.0, 4.0), p3(8.0, -1.0, 4.0)], C_RED);
    good_eye(&mut b);
    b.draw(&mut gl, PrimitiveMode::Triangles);
    let wedge = |x: u32, y: u32| (x as f32 + 0.5 - 16.0).abs() < 48.0 - 4.0 * (y as f32 + 0.5);
    expect_image(&mut gl, "two vertices behind the eye", over(wedge));
    // 8 full rows, then 28 + 20 + 12 + 4, less 16 + 16 + 12 + 4 under the quad.
    assert_eq!(count(&mut gl, RED), 256 + 28 + 20 + 12 + 4 - 48);

    // Negative w given directly, with identity matrices: (x, y, z, w) and
    // (-x, -y, -z, -w) are the same projective point, but GL clips against
    // -w <= z <= w, so a triangle with all w < 0 is invisible.
    let mut gl = context(32, 32);
    let mut b = Batch::default();
    b.tri(
        [[1.0, 1.0, 0.0, -1.0], [-3.0, 1.0, 0.0, -1.0], [1.0, -3.0, 0.0, -1.0]],
        C_RED,
    )
    .good();
    b.draw(&mut gl, PrimitiveMode::Triangles);
    expect_image(&mut gl, "all w = -1", over(|_, _| false));
}

/// Three clip-space vertices.
type Triangle = [[f32; 4]; 3];
/// Which pixels a primitive is expected to cover.
type Covers = fn(u32, u32) -> bool;

#[test]
fn huge_coordinates_are_clipped_exactly() {
    for big in [1e38f32, 3e38, f32::MAX] {
        // Strips toward ±infinity along x and y: a triangle with two vertices on
        // one window edge and the third at ±big is, on screen, the 4-pixel strip.
        let cases: [(Triangle, Covers); 4] = [
            ([p2(-1.0, -1.0), p2(-1.0, -0.75), p2(big, -1.0)], |_, y| y < 4),
            ([p2(1.0, 1.0), p2(1.0, 0.75), p2(-big, 1.0)], |_, y| y >= 28),
            ([p2(-1.0, -1.0), p2(-0.75, -1.0), p2(-1.0, big)], |x, _| x < 4),
            ([p2(1.0, 1.0), p2(0.75, 1.0), p2(1.0, -big)], |x, _| x >= 28),
        ];
        for (k, (tri, red)) in cases.into_iter().enumerate() {
            let mut gl = context(32, 32);
            let mut b = Batch::default();
            b.tri(tri, C_RED).good();
            b.draw(&mut gl, PrimitiveMode::Triangles);
            expect_image(&mut gl, &format!("strip {k} to {big:e}"), over(red));
        }

        // Depth ±big: everything of this triangle but a sliver of relative
        // width 1/big at its base is outside the far (near) plane; the sliver
        // rounds to zero area.
        let mut gl = context(32, 32);
        let mut b = Batch::default();
        b.tri([p3(-1.0, -1.0, 0.0), p3(1.0, -1.0, 0.0), p3(-1.0, 1.0, big)], C_RED);
        b.tri([p3(-1.0, -1.0, 0.0), p3(1.0, -1.0, 0.0), p3(-1.0, 1.0, -big)], C_RED);
        b.good();
        b.draw(&mut gl, PrimitiveMode::Triangles);
        expect_image(&mut gl, &format!("z = ±{big:e}"), over(|_, _| false));
    }
}

/// With vertices at ±`big`: a triangle around the whole window (all 1024
/// pixels); one whose edge is the window's diagonal (the 496 pixels strictly
/// above it: the diagonal is a right edge there, owning no centers); and the
/// line along that diagonal (x-major by the tie rule: the 32 pixels (i, i)).
fn crossing_primitives(big: f32) {
    let mut gl = context(32, 32);
    let mut b = Batch::default();
    b.tri([p2(-big, -big), p2(big, -big), p2(0.0, big)], C_RED).good();
    b.draw(&mut gl, PrimitiveMode::Triangles);
    expect_image(&mut gl, &format!("cover with {big:e}"), over(|_, _| true));

    let mut gl = context(32, 32);
    let mut b = Batch::default();
    b.tri([p2(-big, -big), p2(big, big), p2(-big, big)], C_RED);
    b.draw(&mut gl, PrimitiveMode::Triangles);
    expect_image(&mut gl, &format!("upper-left half with {big:e}"), |x, y| {
        if y > x {
            RED
        } else {
            CLEAR
        }
    });

    let mut gl = context(32, 32);
    let mut b = Batch::default();
    b.v(p2(-big, -big), C_RED).v(p2(big, big), C_RED);
    b.draw(&mut gl, PrimitiveMode::Lines);
    expect_image(&mut gl, &format!("diagonal line with {big:e}"), |x, y| {
        if x == y {
            RED
        } else {
            CLEAR
        }
    });
}

#[test]
fn large_primitives_crossing_the_window_keep_their_shape() {
    for big in [1e6, 1e12, 1e18, 1e20] {
        crossing_primitives(big);
    }
}

/// Vertices beyond ~1e21, where one f64 interpolation `a + (b - a) * t`
/// errs by more than a guard band (ulp(1e21) ≈ 1.3e5) and once cost the
/// lower half of the window (512 of 1024 pixels), the diagonal triangle (0 of
/// 496) or line (0 of 32): src/geometry/clip.rs now brings them in through
/// nested guard bands (`GUARD_LEVELS`), so each shape is exact. Three vertices
/// at w = 1e-30 are the same case (once 384 of 768 pixels).
#[test]
fn huge_primitives_crossing_the_window_keep_their_shape() {
    for big in [1e21, 1e30, 1e38, 3e38, f32::MAX] {
        crossing_primitives(big);
    }
    let mut gl = context(32, 32);
    let mut b = Batch::default();
    let w = 1e-30;
    b.tri([[1.0, 0.0, 0.0, w], [0.0, 1.0, 0.0, w], [-1.0, -1.0, 0.0, w]], C_RED)
        .good();
    b.draw(&mut gl, PrimitiveMode::Triangles);
    expect_image(&mut gl, "three points at infinity", over(|_, _| true));
}

#[test]
fn coordinates_overflowing_in_the_transform_drop_their_primitive() {
    // 3e38 × 10 overflows to infinity in the modelview transform: the vertex is
    // not finite, so its triangle is dropped; the good quad (scaled back) renders.
    let mut gl = context(32, 32);
    gl.scale(10.0, 10.0, 1.0).unwrap();
    let mut b = Batch::default();
    b.tri([p2(-0.1, -0.1), p2(3e38, -0.1), p2(-0.1, 0.3)], C_RED);
    b.quad([-0.05, -0.05, 0.05, 0.05], 0.0, C_GREEN);
    b.draw(&mut gl, PrimitiveMode::Triangles);
    expect_image(&mut gl, "overflow to inf", over(|_, _| false));
}

#[test]
fn nan_and_inf_positions_drop_the_primitive() {
    // Each bad triangle would cover the whole window if its bad coordinate
    // were a number; non-finite clip coordinates drop the whole primitive.
    let full = [p2(-1.0, -1.0), p2(3.0, -1.0), p2(-1.0, 3.0)];
    for bad in [NAN, INF, -INF] {
        for comp in 0..4 {
            for vert in 0..3 {
                let mut gl = context(32, 32);
                let mut tri = full;
                tri[vert][comp] = bad;
                let mut b = Batch::default();
                b.tri(tri, C_RED).good();
                b.draw(&mut gl, PrimitiveMode::Triangles);
                expect_image(
                    &mut gl,
                    &format!("{bad} in vertex {vert} component {comp}"),
                    over(|_, _| false),
                );
            }
        }
    }

    // In a strip, a NaN vertex drops the three triangles that use it and
    // nothing else. Vertices: 0 (-1,-1) 1 (-1,1) 2 NaN 3 (0,1) 4 (0,-1) 5 (1,1):
    // only triangle 4-3-5 remains: window (16, 0) (16, 32) (32, 32), the part
    // of the right half above the line from (16, 0) to (32, 32).
    let mut gl = context(32, 32);
    let mut b = Batch::default();
    for p in [
        p2(-1.0, -1.0),
        p2(-1.0, 1.0),
        p2(NAN, 0.0),
        p2(0.0, 1.0),
        p2(0.0, -1.0),
        p2(1.0, 1.0),
    ] {
        b.v(p, C_RED);
    }
    b.draw(&mut gl, PrimitiveMode::TriangleStrip);
    // Pixel centers with x > 16 and y > 2 (x - 16): none lies on the slanted edge.
    let right = |x: u32, y: u32| x >= 16 && (y as f32 + 0.5) > 2.0 * (x as f32 + 0.5 - 16.0);
    expect_image(&mut gl, "strip with a NaN vertex", |x, y| {
        if right(x, y) {
            RED
        } else {
            CLEAR
        }
    });
}

#[test]
fn nan_and_inf_colors_render_as_clamped_values() {
    // Vertex colors are clamped to [0, 1] at the start of geometry (glam's
    // clamp, where NaN becomes the lower bound): NaN renders as 0, +Inf as 1,
    // -Inf as 0, and the primitive is drawn. Check that against the same draw
    // with those values written out, smooth and flat.
    let bad = [[1.0, NAN, 0.5, 1.0], [NAN, 1.0, INF, 1.0], [0.2, -INF, NAN, NAN]];
    let clean = [[1.0, 0.0, 0.5, 1.0], [0.0, 1.0, 1.0, 1.0], [0.2, 0.0, 0.0, 0.0]];
    let tri = [p2(-1.0, -1.0), p2(1.0, -1.0), p2(-1.0, 1.0)];
    for shade in [ShadeModel::Smooth, ShadeModel::Flat] {
        let render = |colors: [[f32; 4]; 3]| {
            let mut gl = context(32, 32);
            gl.shade_model(shade).unwrap();
            let mut b = Batch::default();
            for k in 0..3 {
                b.v(tri[k], colors[k]);
            }
            b.good();
            b.draw(&mut gl, PrimitiveMode::Triangles);
            gl
        };
        let (mut got, mut want) = (render(bad), render(clean));
        assert_eq!(
            got.framebuffer().color_bytes(),
            want.framebuffer().color_bytes(),
            "{shade:?}"
        );
        // And the triangle was drawn: window pixel (1, 1) is inside it.
        assert_ne!(got.framebuffer().pixel(1, 1), Some(CLEAR), "{shade:?}");
        let before = got.framebuffer().clone();
        expect_image(&mut got, "quad after NaN colors", |x, y| {
            if in_good(x, y) {
                GREEN
            } else {
                before.pixel(x, y).unwrap()
            }
        });
    }
    // Uniform NaN colors: every channel 0, alpha included.
    let mut gl = context(32, 32);
    let mut b = Batch::default();
    b.tri([p2(-1.0, -1.0), p2(3.0, -1.0), p2(-1.0, 3.0)], [NAN; 4]).good();
    b.draw(&mut gl, PrimitiveMode::Triangles);
    expect_image(
        &mut gl,
        "all-NaN color",
        |x, y| if in_good(x, y) { GREEN } else { [0; 4] },
    );
}

#[test]
fn zero_area_and_collinear_triangles_draw_nothing() {
    let mut gl = context(32, 32);
    window_coords(&mut gl, 32.0, 32.0);
    let mut b = Batch::default();
    let degenerate = [
        [p2(10.5, 10.5), p2(10.5, 10.5), p2(10.5, 10.5)], // one point, on a pixel center
        [p2(0.0, 0.0), p2(16.0, 16.0), p2(32.0, 32.0)],   // collinear diagonal
        [p2(0.0, 4.5), p2(32.0, 4.5), p2(16.0, 4.5)],     // along a row of centers
        [p2(4.5, 0.0), p2(4.5, 32.0), p2(4.5, 16.0)],     // along a column of centers
        [p2(0.0, 0.0), p2(32.0, 32.0), p2(0.0, 0.0)],     // two equal vertices
        // Not collinear in f32, but zero area once snapped to 1/256 pixel.
        [p2(0.0, 0.0), p2(32.0, 32.0), p2(16.0, 16.0 + 1.0 / 1024.0)],
        [p2(-1e6, 20.5), p2(1e6, 20.5), p2(0.0, 20.5)], // collinear, clipped to the guard band
    ];
    for t in degenerate {
        b.tri(t, C_RED);
    }
    b.quad([8.0, 8.0, 24.0, 24.0], 0.0, C_GREEN);
    b.draw(&mut gl, PrimitiveMode::Triangles);
    expect_image(&mut gl, "degenerate triangles", over(|_, _| false));

    // The same vertices as strips, fans and polygons: still nothing.
    for mode in [
        PrimitiveMode::TriangleStrip,
        PrimitiveMode::TriangleFan,
        PrimitiveMode::Polygon,
    ] {
        let mut gl = context(32, 32);
        window_coords(&mut gl, 32.0, 32.0);
        let mut b = Batch::default();
        for x in [0.0, 8.0, 16.0, 24.0, 32.0] {
            b.v(p2(x, x), C_RED);
        }
        b.draw(&mut gl, mode);
        expect_image(&mut gl, &format!("collinear {mode:?}"), |_, _| CLEAR);
    }
}

#[test]
fn sliver_triangles_cover_exactly_the_centers_inside() {
    // Window coordinates, all multiples of 1/256 so that snapping is exact.
    struct Case {
        name: &'static str,
        tri: Triangle,
        covers: Covers,
        pixels: usize,
    }
    let cases = [
        // Between y = 10.375 + x/128 and y = 10.625: row 10 (center 10.5) for
        // centers x + 0.5 < 16.
        Case {
            name: "horizontal sliver",
            tri: [p2(0.0, 10.375), p2(32.0, 10.625), p2(0.0, 10.625)],
            covers: |x, y| y == 10 && x < 16,
            pixels: 16,
        },
        Case {
            name: "horizontal sliver, clockwise",
            tri: [p2(0.0, 10.375), p2(0.0, 10.625), p2(32.0, 10.625)],
            covers: |x, y| y == 10 && x < 16,
            pixels: 16,
        },
        // A wedge below the diagonal (0,0)-(32,32), 1/4 pixel wide at its end.
        // The diagonal passes through the 32 centers (i+0.5, i+0.5) and is this
        // triangle's left edge, which owns them; no other center is inside.
        Case {
            name: "wedge owning the diagonal",
            tri: [p2(0.0, 0.0), p2(32.0, 31.75), p2(32.0, 32.0)],
            covers: |x, y| x == y,
            pixels: 32,
        },
        Case {
            name: "wedge owning the diagonal, clockwise",
            tri: [p2(32.0, 32.0), p2(32.0, 31.75), p2(0.0, 0.0)],
            covers: |x, y| x == y,
            pixels: 32,
        },
        // The mirror wedge above the diagonal: there the diagonal is a right
        // edge, which owns none of its centers.
        Case {
            name: "wedge not owning the diagonal",
            tri: [p2(0.0, 0.0), p2(32.0, 32.0), p2(31.75, 32.0)],
            covers: |_, _| false,
            pixels: 0,
        },
        // Thinner than the sub-pixel grid between two rows of centers.
        Case {
            name: "sub-pixel sliver",
            tri: [
                p2(0.0, 20.75),
                p2(32.0, 20.75 + 1.0 / 256.0),
                p2(0.0, 20.75 + 1.0 / 256.0),
            ],
            covers: |_, _| false,
            pixels: 0,
        },
        // A needle crossing the window diagonally, 1/8 pixel wide at its base:
        // it covers a center only where it passes within 1/16 of one, i.e. at
        // the centers (i+0.5, i+0.5) it contains: the base edge from (0, 0.125)
        // to (0.125, 0) passes below (0.5, 0.5); the tip is at (32, 32).
        Case {
            name: "diagonal needle",
            tri: [p2(0.125, 0.0), p2(32.0, 32.0), p2(0.0, 0.125)],
            covers: |x, y| x == y,
            pixels: 32,
        },
    ];
    for case in cases {
        let mut gl = context(32, 32);
        window_coords(&mut gl, 32.0, 32.0);
        let mut b = Batch::default();
        b.tri(case.tri, C_RED);
        b.draw(&mut gl, PrimitiveMode::Triangles);
        expect_image(&mut gl, case.name, |x, y| if (case.covers)(x, y) { RED } else { CLEAR });
        assert_eq!(count(&mut gl, RED), case.pixels, "{}", case.name);

        // And with the good quad after it in the same draw.
        let mut gl = context(32, 32);
        window_coords(&mut gl, 32.0, 32.0);
        let mut b = Batch::default();
        b.tri(case.tri, C_RED).quad([8.0, 8.0, 24.0, 24.0], 0.0, C_GREEN);
        b.draw(&mut gl, PrimitiveMode::Triangles);
        expect_image(&mut gl, case.name, over(case.covers));
    }

    // The two wedges sharing the diagonal, in one draw: each diagonal pixel once.
    let mut gl = context(32, 32);
    window_coords(&mut gl, 32.0, 32.0);
    gl.enable(Capability::StencilTest).unwrap();
    gl.stencil_op(StencilOp::Keep, StencilOp::Keep, StencilOp::Incr)
        .unwrap();
    let mut b = Batch::default();
    b.tri([p2(0.0, 0.0), p2(32.0, 31.75), p2(32.0, 32.0)], C_RED);
    b.tri([p2(0.0, 0.0), p2(32.0, 32.0), p2(31.75, 32.0)], C_RED);
    b.draw(&mut gl, PrimitiveMode::Triangles);
    for y in 0..32 {
        for x in 0..32 {
            let want = u8::from(x == y);
            assert_eq!(gl.framebuffer().stencil_at(x, y), Some(want), "({x}, {y})");
        }
    }
}

#[test]
fn one_by_one_framebuffer() {
    let mut gl = context(1, 1);
    let mut b = Batch::default();
    b.tri([p2(NAN, 0.0), p2(1.0, 1.0), p2(0.0, 1.0)], C_RED)
        .tri([[1.0, 0.0, 0.0, 0.0], p2(-1.0, -1.0), p2(-1.0, 1.0)], C_RED) // to infinity along +x
        .tri([p2(-3e38, -3e38), p2(3e38, -3e38), p2(0.0, 3e38)], C_RED)
        .tri([p2(-1.0, -1.0), p2(3.0, -1.0), p2(-1.0, 3.0)], C_GREEN);
    b.draw(&mut gl, PrimitiveMode::Triangles);
    assert_eq!(gl.framebuffer().pixel(0, 0), Some(GREEN));

    // A triangle that misses the only pixel center draws nothing.
    let mut gl = context(1, 1);
    let mut b = Batch::default();
    b.tri([p2(0.1, 0.1), p2(1.0, 0.1), p2(0.1, 1.0)], C_RED);
    b.draw(&mut gl, PrimitiveMode::Triangles);
    assert_eq!(gl.framebuffer().pixel(0, 0), Some(CLEAR));

    // Points and lines of every size through the center.
    for size in [1.0, 2.0, 1000.0] {
        let mut gl = context(1, 1);
        gl.point_size(size).unwrap();
        let mut b = Batch::default();
        b.v(p2(NAN, NAN), C_RED).v(p2(0.0, 0.0), C_GREEN);
        b.draw(&mut gl, PrimitiveMode::Points);
        assert_eq!(gl.framebuffer().pixel(0, 0), Some(GREEN), "point size {size}");

        let mut gl = context(1, 1);
        gl.line_width(size).unwrap();
        let mut b = Batch::default();
        b.v(p2(-1.0, 0.0), C_GREEN).v(p2(1.0, 0.0), C_GREEN);
        b.draw(&mut gl, PrimitiveMode::Lines);
        assert_eq!(gl.framebuffer().pixel(0, 0), Some(GREEN), "line width {size}");
    }
}

#[test]
fn viewport_8192_on_small_and_one_pixel_framebuffers() {
    // Window = (ndc + 1) × 4096: the lower-left half-triangle covers the whole
    // 32×32 framebuffer; the quad at window [8, 24)² has ndc (w / 4096 - 1).
    let lo = 8.0 / 4096.0 - 1.0;
    let hi = 24.0 / 4096.0 - 1.0;
    let mut gl = context(32, 32);
    gl.viewport(0, 0, 8192, 8192).unwrap();
    let mut b = Batch::default();
    b.tri([p2(-1.0, -1.0), p2(1.0, -1.0), p2(-1.0, 1.0)], C_RED);
    b.quad([lo, lo, hi, hi], 0.0, C_GREEN);
    b.draw(&mut gl, PrimitiveMode::Triangles);
    expect_image(&mut gl, "8192 viewport", over(|_, _| true));

    let mut gl = context(1, 1);
    gl.viewport(0, 0, 8192, 8192).unwrap();
    let mut b = Batch::default();
    b.tri([p2(-1.0, -1.0), p2(1.0, -1.0), p2(-1.0, 1.0)], C_RED);
    b.quad([-1.0, -1.0, 1.0 / 4096.0 - 1.0, 1.0 / 4096.0 - 1.0], 0.0, C_GREEN);
    b.draw(&mut gl, PrimitiveMode::Triangles);
    assert_eq!(gl.framebuffer().pixel(0, 0), Some(GREEN));

    // Sizes above the maximum are clamped to 16384 (window = (ndc + 1) × 8192).
    let mut gl = context(32, 32);
    gl.viewport(0, 0, i32::MAX, i32::MAX).unwrap();
    assert_eq!((gl.state().viewport.width, gl.state().viewport.height), (16384, 16384));
    let (lo, hi) = (8.0 / 8192.0 - 1.0, 24.0 / 8192.0 - 1.0);
    let mut b = Batch::default();
    b.tri([p2(-1.0, -1.0), p2(1.0, -1.0), p2(-1.0, 1.0)], C_RED);
    b.quad([lo, lo, hi, hi], 0.0, C_GREEN);
    b.draw(&mut gl, PrimitiveMode::Triangles);
    expect_image(&mut gl, "clamped viewport", over(|_, _| true));
}

#[test]
fn huge_viewport_offsets() {
    // Far off to the lower left: nothing reaches the framebuffer.
    for (x, y, w, h) in [
        (-1_000_000, 0, 32, 32),
        (-1_000_000, -1_000_000, i32::MAX, i32::MAX), // width clamped to 16384: still left of 0
        (i32::MIN, i32::MIN, 16384, 16384),
        (i32::MAX - 16, i32::MAX - 16, 32, 32),
        (i32::MAX, 0, i32::MAX, 32),
    ] {
        let mut gl = context(32, 32);
        gl.viewport(x, y, w, h).unwrap();
        let mut b = Batch::default();
        b.tri([p2(-1.0, -1.0), p2(3.0, -1.0), p2(-1.0, 3.0)], C_RED);
        b.v(p2(0.0, 0.0), C_RED);
        b.draw(&mut gl, PrimitiveMode::Triangles);
        gl.point_size(1000.0).unwrap();
        b.draw(&mut gl, PrimitiveMode::Points);
        expect_image(&mut gl, &format!("viewport at ({x}, {y})"), |_, _| CLEAR);
    }

    // A 16384-wide viewport centered on window x = 16 (x offset -8176): window
    // x = ndc × 8192 + 16, so the quad at ndc x = ±8/8192 lands on [8, 24).
    let mut gl = context(32, 32);
    gl.viewport(-8176, 0, 16384, 32).unwrap();
    let d = 8.0 / 8192.0;
    let mut b = Batch::default();
    b.tri([p2(-1.0, -1.0), p2(3.0, -1.0), p2(-1.0, 3.0)], C_RED);
    b.quad([-d, -0.5, d, 0.5], 0.0, C_GREEN);
    b.draw(&mut gl, PrimitiveMode::Triangles);
    expect_image(&mut gl, "viewport offset -8176", over(|_, _| true));
}

#[test]
fn extreme_near_far_ratios_keep_depth_order() {
    struct Setup {
        near: f64,
        far: f64,
        /// Eye z and half-size of a quad covering the window.
        back: (f32, f32),
        /// Eye z and half-size of a quad covering window [8, 24)².
        front: (f32, f32),
    }
    let setups = [
        // n / f = 1e-7: ndc z = 1 + 2e-7 / z_eye; both quads still distinct in D24.
        Setup {
            near: 1e-7,
            far: 1.0,
            back: (-0.5, 1.0),
            front: (-1e-3, 5e-4),
        },
        // f / n = 1e7: ndc z = 1 + 2 / z_eye.
        Setup {
            near: 1.0,
            far: 1e7,
            back: (-1e6, 2e6),
            front: (-2.0, 1.0),
        },
    ];
    for s in setups {
        for front_first in [true, false] {
            let mut gl = context(32, 32);
            let n = s.near;
            projection(&mut gl, |gl| gl.frustum(-n, n, -n, n, n, s.far).unwrap());
            gl.enable(Capability::DepthTest).unwrap();
            let mut b = Batch::default();
            // Between the eye and the near plane, and behind the eye: clipped away.
            let z_in = (n / 2.0) as f32;
            b.tri(
                [p3(-z_in, -z_in, -z_in), p3(z_in, -z_in, -z_in), p3(0.0, z_in, -z_in)],
                [0.0, 0.0, 1.0, 1.0],
            );
            b.tri(
                [p3(-1.0, -1.0, 1.0), p3(1.0, -1.0, 1.0), p3(0.0, 1.0, 1.0)],
                [0.0, 0.0, 1.0, 1.0],
            );
            let (bz, bs) = s.back;
            let (fz, fs) = s.front;
            if front_first {
                b.quad([-fs, -fs, fs, fs], fz, C_GREEN)
                    .quad([-bs, -bs, bs, bs], bz, C_RED);
            } else {
                b.quad([-bs, -bs, bs, bs], bz, C_RED)
                    .quad([-fs, -fs, fs, fs], fz, C_GREEN);
            }
            b.draw(&mut gl, PrimitiveMode::Triangles);
            let what = format!("near {} far {} front first {front_first}", s.near, s.far);
            expect_image(&mut gl, &what, over(|_, _| true));
            let fb = gl.framebuffer();
            let (d_front, d_back) = (fb.depth_at(16, 16).unwrap(), fb.depth_at(0, 0).unwrap());
            assert!(
                d_front < d_back && d_back < 0xff_ffff,
                "{what}: depths {d_front} {d_back}"
            );
        }
    }
}

#[test]
fn zero_length_lines_and_points_at_nan() {
    for width in [1.0, 5.0] {
        let mut gl = context(32, 32);
        window_coords(&mut gl, 32.0, 32.0);
        gl.line_width(width).unwrap();
        let mut b = Batch::default();
        b.v(p2(10.0, 10.0), C_RED).v(p2(10.0, 10.0), C_RED); // zero length, on a pixel corner
        b.v(p2(12.5, 12.5), C_RED).v(p2(12.5, 12.5), C_RED); // zero length, on a pixel center
        b.v(p2(NAN, 5.0), C_RED).v(p2(20.0, 5.0), C_RED);
        b.v(p2(5.0, 3.0), C_RED).v(p2(INF, 3.0), C_RED);
        b.v(p2(5.0, -INF), C_RED).v(p2(5.0, 30.0), C_RED);
        b.v(p2(4.0, 20.25), C_GREEN).v(p2(28.0, 20.25), C_GREEN);
        b.draw(&mut gl, PrimitiveMode::Lines);
        // Width 1: diamond exit puts row 20, columns 4..=27 (the end point
        // (28, 20.25) is on no diamond's inside). Width 5: the parallelogram
        // y in [17.75, 22.75] from x = 4 to 28: rows 18..=22, columns 4..=27.
        let rows = if width == 1.0 { 20..=20 } else { 18..=22 };
        expect_image(&mut gl, &format!("lines of width {width}"), |x, y| {
            if rows.contains(&y) && (4..28).contains(&x) {
                GREEN
            } else {
                CLEAR
            }
        });
    }

    // A NaN vertex in a strip drops the two segments that touch it.
    let mut gl = context(32, 32);
    window_coords(&mut gl, 32.0, 32.0);
    let mut b = Batch::default();
    b.v(p2(2.0, 2.0), C_RED)
        .v(p2(NAN, NAN), C_RED)
        .v(p2(30.0, 2.0), C_GREEN)
        .v(p2(30.0, 30.0), C_GREEN);
    b.draw(&mut gl, PrimitiveMode::LineStrip);
    // x = 30 is a pixel boundary: the line belongs to column 29, rows 2..=29.
    expect_image(&mut gl, "line strip with NaN", |x, y| {
        if x == 29 && (2..30).contains(&y) {
            GREEN
        } else {
            CLEAR
        }
    });

    // Points at NaN and infinity are dropped; a good point after them is drawn.
    for size in [1.0, 3.0] {
        let mut gl = context(32, 32);
        window_coords(&mut gl, 32.0, 32.0);
        gl.point_size(size).unwrap();
        let mut b = Batch::default();
        for p in [
            p2(NAN, NAN),
            p2(NAN, 5.0),
            p2(INF, 5.0),
            p2(5.0, -INF),
            [5.0, 5.0, 0.0, NAN],
            [5.0, 5.0, 0.0, 0.0],
        ] {
            b.v(p, C_RED);
        }
        b.v(p2(16.5, 16.5), C_GREEN);
        b.draw(&mut gl, PrimitiveMode::Points);
        let r = if size == 1.0 { 16..=16 } else { 15..=17 };
        expect_image(&mut gl, &format!("points of size {size}"), |x, y| {
            if r.contains(&x) && r.contains(&y) {
                GREEN
            } else {
                CLEAR
            }
        });
    }
}

#[test]
fn huge_line_widths_and_point_sizes_clamp_to_255() {
    // On 300×300, a 255-pixel point at (150, 150) covers the centers in
    // (150 - 127.5, 150 + 127.5]: pixels 23..=277 on each axis.
    for size in [1000.0, f32::MAX, INF, 255.0] {
        let mut gl = context(300, 300);
        window_coords(&mut gl, 300.0, 300.0);
        gl.point_size(size).unwrap();
        assert_eq!(gl.state().point_size, size, "the state keeps what was asked");
        let mut b = Batch::default();
        b.v(p2(NAN, 150.0), C_RED).v(p2(150.0, 150.0), C_GREEN);
        b.draw(&mut gl, PrimitiveMode::Points);
        let r = 23..=277;
        expect_image(&mut gl, &format!("point size {size}"), |x, y| {
            if r.contains(&x) && r.contains(&y) {
                GREEN
            } else {
                CLEAR
            }
        });
        assert_eq!(count(&mut gl, GREEN), 255 * 255);
    }

    // A 255-pixel horizontal line from x = 0 to 300 at y = 150: the
    // parallelogram y in [22.5, 277.5]; its bottom edge owns row 22's
    // centers, its top edge does not own row 277's: rows 22..=276.
    for width in [1000.0, f32::MAX, INF] {
        let mut gl = context(300, 300);
        window_coords(&mut gl, 300.0, 300.0);
        gl.line_width(width).unwrap();
        let mut b = Batch::default();
        b.v(p2(0.0, 150.0), C_GREEN).v(p2(300.0, 150.0), C_GREEN);
        b.draw(&mut gl, PrimitiveMode::Lines);
        expect_image(&mut gl, &format!("line width {width}"), |_, y| {
            if (22..277).contains(&y) {
                GREEN
            } else {
                CLEAR
            }
        });
        assert_eq!(count(&mut gl, GREEN), 255 * 300);

        // Vertical: the parallelogram x in [22.5, 277.5]; its left edge owns
        // column 22's centers, its right edge does not own column 277's.
        let mut gl = context(300, 300);
        window_coords(&mut gl, 300.0, 300.0);
        gl.line_width(width).unwrap();
        let mut b = Batch::default();
        b.v(p2(150.0, 0.0), C_GREEN).v(p2(150.0, 300.0), C_GREEN);
        b.draw(&mut gl, PrimitiveMode::Lines);
        expect_image(&mut gl, &format!("vertical line width {width}"), |x, _| {
            if (22..277).contains(&x) {
                GREEN
            } else {
                CLEAR
            }
        });
    }
}

/// Stencil values over the whole 32×32 framebuffer, checked against `want(x, y)`.
#[track_caller]
fn expect_stencil(gl: &mut Context, what: &str, want: impl Fn(u32, u32) -> u8) {
    for y in 0..32 {
        for x in 0..32 {
            assert_eq!(
                gl.framebuffer().stencil_at(x, y),
                Some(want(x, y)),
                "{what} at ({x}, {y})"
            );
        }
    }
}

#[test]
fn stencil_wraps_through_a_draw() {
    let mut gl = context(32, 32);
    gl.clear_stencil(255).unwrap();
    gl.clear(ClearMask::STENCIL).unwrap();
    gl.enable(Capability::StencilTest).unwrap();
    gl.stencil_func(CompareFunc::Always, 0, 0xff).unwrap();
    let full = || {
        let mut b = Batch::default();
        b.tri([p2(-1.0, -1.0), p2(3.0, -1.0), p2(-1.0, 3.0)], C_RED);
        b
    };
    let mut good = Batch::default();
    good.good();

    // IncrWrap at 255 gives 0 where the quad is.
    gl.stencil_op(StencilOp::Keep, StencilOp::Keep, StencilOp::IncrWrap)
        .unwrap();
    good.draw(&mut gl, PrimitiveMode::Triangles);
    expect_stencil(&mut gl, "IncrWrap", |x, y| if in_good(x, y) { 0 } else { 255 });

    // DecrWrap over everything: 0 → 255, 255 → 254.
    gl.stencil_op(StencilOp::Keep, StencilOp::Keep, StencilOp::DecrWrap)
        .unwrap();
    full().draw(&mut gl, PrimitiveMode::Triangles);
    expect_stencil(&mut gl, "DecrWrap", |x, y| if in_good(x, y) { 255 } else { 254 });

    // Saturating Incr stays at 255; Decr twice takes 255 to 253 and 254 to 252.
    gl.stencil_op(StencilOp::Keep, StencilOp::Keep, StencilOp::Incr)
        .unwrap();
    full().draw(&mut gl, PrimitiveMode::Triangles);
    full().draw(&mut gl, PrimitiveMode::Triangles);
    expect_stencil(&mut gl, "Incr", |_, _| 255);
    gl.clear_stencil(0).unwrap();
    gl.clear(ClearMask::STENCIL).unwrap();
    gl.stencil_op(StencilOp::Keep, StencilOp::Keep, StencilOp::Decr)
        .unwrap();
    full().draw(&mut gl, PrimitiveMode::Triangles);
    expect_stencil(&mut gl, "Decr at 0", |_, _| 0);

    // 256 IncrWrap passes over the quad come back to where they started.
    gl.stencil_op(StencilOp::Keep, StencilOp::Keep, StencilOp::IncrWrap)
        .unwrap();
    for _ in 0..256 {
        good.draw(&mut gl, PrimitiveMode::Triangles);
    }
    expect_stencil(&mut gl, "256 IncrWrap", |_, _| 0);
    good.draw(&mut gl, PrimitiveMode::Triangles);
    expect_stencil(&mut gl, "257 IncrWrap", |x, y| u8::from(in_good(x, y)));

    // References outside [0, 255] are clamped: -5 replaces with 0, 300 with 255.
    gl.stencil_op(StencilOp::Keep, StencilOp::Keep, StencilOp::Replace)
        .unwrap();
    gl.stencil_func(CompareFunc::Always, 300, 0xff).unwrap();
    good.draw(&mut gl, PrimitiveMode::Triangles);
    expect_stencil(&mut gl, "Replace 300", |x, y| if in_good(x, y) { 255 } else { 0 });

    // And the wrapped values test as stored: draw red only where stencil == 255.
    gl.clear(ClearMask::COLOR).unwrap();
    gl.stencil_op(StencilOp::Keep, StencilOp::Keep, StencilOp::Keep)
        .unwrap();
    gl.stencil_func(CompareFunc::Equal, 255, 0xff).unwrap();
    full().draw(&mut gl, PrimitiveMode::Triangles);
    expect_image(
        &mut gl,
        "stencil Equal 255",
        |x, y| if in_good(x, y) { RED } else { CLEAR },
    );
    gl.stencil_func(CompareFunc::Always, -5, 0xff).unwrap();
    gl.stencil_op(StencilOp::Keep, StencilOp::Keep, StencilOp::Replace)
        .unwrap();
    full().draw(&mut gl, PrimitiveMode::Triangles);
    expect_stencil(&mut gl, "Replace -5", |_, _| 0);
}

#[test]
fn polygon_offset_extremes() {
    // Depth at window z 0.5 in D24: rint(0.5 × 0xffffff) = 8388608 (ties to even).
    const MID: u32 = 8_388_608;
    const FAR: u32 = 0xff_ffff;
    // (factor, units, tilted, stored depth at (16, 16) or None when the quad fails Less).
    let cases: [(f32, f32, bool, Option<u32>); 12] = [
        (0.0, 1e30, false, None),
        (0.0, -1e30, false, Some(0)),
        (0.0, f32::MAX, false, None),
        (0.0, -f32::MAX, false, Some(0)),
        (1e30, 0.0, true, None),
        (-1e30, 0.0, true, Some(0)),
        (1e30, 0.0, false, Some(MID)), // flat: factor × 0 slope
        (NAN, 0.0, false, Some(MID)),
        (0.0, NAN, false, Some(MID)),
        (NAN, NAN, true, Some(MID)),
        (1e30, NAN, true, Some(MID)),
        (-1e30, NAN, true, Some(MID)),
    ];
    for (factor, units, tilted, want) in cases {
        for mode in [PolygonMode::Fill, PolygonMode::Line] {
            let mut gl = context(32, 32);
            gl.enable(Capability::DepthTest).unwrap();
            gl.enable(Capability::PolygonOffsetFill).unwrap();
            gl.enable(Capability::PolygonOffsetLine).unwrap();
            gl.polygon_mode(Face::FrontAndBack, mode).unwrap();
            gl.polygon_offset(factor, units).unwrap();
            // Tilted: ndc z from -0.5 at x = -0.5 to 0.5 at x = 0.5 (0 at the center column 16).
            let z = |x: f32| if tilted { x } else { 0.0 };
            let mut b = Batch::default();
            b.tri(
                [p3(-0.5, -0.5, z(-0.5)), p3(0.5, -0.5, z(0.5)), p3(0.5, 0.5, z(0.5))],
                C_GREEN,
            );
            b.tri(
                [p3(-0.5, -0.5, z(-0.5)), p3(0.5, 0.5, z(0.5)), p3(-0.5, 0.5, z(-0.5))],
                C_GREEN,
            );
            b.draw(&mut gl, PrimitiveMode::Triangles);
            let what = format!("offset ({factor:e}, {units:e}) tilted {tilted} {mode:?}");
            match mode {
                PolygonMode::Fill => {
                    let drawn = want.is_some();
                    expect_image(
                        &mut gl,
                        &what,
                        |x, y| if drawn && in_good(x, y) { GREEN } else { CLEAR },
                    );
                    if !tilted || want != Some(MID) {
                        assert_eq!(gl.framebuffer().depth_at(16, 16), Some(want.unwrap_or(FAR)), "{what}");
                    }
                }
                _ => {
                    // Outlines: drawn (some green pixels) exactly when the fill is.
                    let green = count(&mut gl, GREEN);
                    assert_eq!(green > 0, want.is_some(), "{what}: {green} green pixels");
                    assert_eq!(count(&mut gl, CLEAR) + green, 1024, "{what}");
                }
            }
        }
    }
}

/// softgl's deterministic generator, with the stiff values drawn from it.
struct XorShift(softgl::rng::Rng);

impl XorShift {
    fn next(&mut self) -> u64 {
        self.0.next_u64()
    }

    fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }

    fn unit(&mut self) -> f32 {
        (self.next() >> 40) as f32 / (1u64 << 24) as f32
    }

    fn sign(&mut self) -> f32 {
        if self.next() & 1 == 0 {
            1.0
        } else {
            -1.0
        }
    }

    /// A coordinate: mostly ordinary, often extreme or not a number.
    fn coord(&mut self) -> f32 {
        let s = self.sign();
        match self.below(16) {
            0 => NAN,
            1 => s * INF,
            2 => s * 1e38 * (1.0 + self.unit()),
            3 => s * 3e38,
            4 => s * f32::MAX,
            5 => s * 1e-30,
            6 => s * 1e-45,
            7 => 0.0,
            8 => s * 1e6 * self.unit(),
            _ => s * 3.0 * self.unit(),
        }
    }

    /// A w: either sign, near zero, or not a number.
    fn w(&mut self) -> f32 {
        let s = self.sign();
        match self.below(10) {
            0 => s * 1e-30,
            1 => 0.0,
            2 => NAN,
            3 => s * INF,
            4 => s * 1e38,
            5 | 6 => 1.0,
            _ => s * 2.0 * self.unit(),
        }
    }

    fn color(&mut self) -> f32 {
        match self.below(12) {
            0 => NAN,
            1 => INF,
            2 => -INF,
            3 => -5.0,
            _ => self.unit(),
        }
    }

    fn matrix(&mut self) -> Mat4 {
        match self.below(6) {
            0 => Mat4::from_cols_array(&[0.0; 16].map(|_: f32| self.coord())),
            1 => Mat4::from_scale(glam::Vec3::splat(1e30)),
            2 => Mat4::from_cols_array(&[NAN; 16]),
            _ => Mat4::IDENTITY,
        }
    }
}

#[test]
fn random_extreme_triangles_do_not_poison_later_frames() {
    const VP: (i32, i32, i32, i32) = (6, 5, 17, 19);
    let inside_vp = |x: u32, y: u32| {
        (VP.0 as u32..(VP.0 + VP.2) as u32).contains(&x) && (VP.1 as u32..(VP.1 + VP.3) as u32).contains(&y)
    };
    let mut gl = context(32, 32);
    gl.viewport(VP.0, VP.1, VP.2, VP.3).unwrap();
    let mut rng = XorShift(softgl::rng::Rng::new(0x9e37_79b9));
    // 3000 vertices (1000 triangles' worth) in 10 draws of 300, each under
    // different state; 300 crosses the geometry's 256-vertex batches. Odd
    // draws go through draw_elements with random indices.
    let mut drawn = 0;
    for draw in 0..10 {
        // Wide points and lines may reach past the viewport (as in llvmpipe and
        // as GL allows); each draw starts from a clear frame to check the rest.
        gl.clear(ClearMask::ALL).unwrap();
        let mode = PrimitiveMode::ALL[rng.below(10) as usize];
        let wide = matches!(
            mode,
            PrimitiveMode::Points | PrimitiveMode::Lines | PrimitiveMode::LineStrip | PrimitiveMode::LineLoop
        );
        let poly = [PolygonMode::Fill, PolygonMode::Line, PolygonMode::Point][rng.below(3) as usize];
        gl.polygon_mode(Face::FrontAndBack, poly).unwrap();
        gl.point_size([1.0, 3.0, 1000.0][rng.below(3) as usize]).unwrap();
        gl.line_width([1.0, 2.0, 1000.0][rng.below(3) as usize]).unwrap();
        gl.polygon_offset(rng.coord(), rng.coord()).unwrap();
        for cap in [
            Capability::DepthTest,
            Capability::StencilTest,
            Capability::Blend,
            Capability::CullFace,
            Capability::PolygonOffsetFill,
            Capability::PolygonOffsetLine,
            Capability::PolygonOffsetPoint,
            Capability::ColorLogicOp,
        ] {
            if rng.below(2) == 0 {
                gl.enable(cap).unwrap();
            } else {
                gl.disable(cap).unwrap();
            }
        }
        gl.stencil_op(StencilOp::IncrWrap, StencilOp::DecrWrap, StencilOp::Invert)
            .unwrap();
        gl.shade_model(if draw % 2 == 0 {
            ShadeModel::Smooth
        } else {
            ShadeModel::Flat
        })
        .unwrap();
        let m = rng.matrix();
        projection(&mut gl, |gl| gl.load_matrix(&m).unwrap());
        if draw % 3 == 0 {
            gl.frustum(-1.0, 1.0, -1.0, 1.0, 1e-7, 1e7).unwrap();
        }
        let mut b = Batch::default();
        for _ in 0..300 {
            let p = [rng.coord(), rng.coord(), rng.coord(), rng.w()];
            let c = [rng.color(), rng.color(), rng.color(), rng.color()];
            b.v(p, c);
        }
        if draw % 2 == 0 {
            b.draw(&mut gl, mode);
        } else {
            let indices: Vec<u16> = (0..300).map(|_| rng.below(300) as u16).collect();
            let arrays = VertexArrays::with_colors(4, &b.pos, 4, &b.col);
            gl.draw_elements(mode, Indices::U16(&indices), &arrays).unwrap();
            assert_eq!(gl.get_error(), None);
        }
        let fb = gl.framebuffer();
        assert_eq!((fb.width(), fb.height(), fb.color_bytes().len()), (32, 32, 32 * 32 * 4));
        drawn += (0..32 * 32).filter(|i| fb.pixel(i % 32, i / 32) != Some(CLEAR)).count();
        for y in 0..32 {
            for x in 0..32 {
                if !inside_vp(x, y) && !wide {
                    assert_eq!(fb.pixel(x, y), Some(CLEAR), "draw {draw} ({mode:?}) wrote ({x}, {y})");
                    assert_eq!(
                        fb.stencil_at(x, y),
                        Some(0),
                        "draw {draw} ({mode:?}) stencil at ({x}, {y})"
                    );
                    assert_eq!(
                        fb.depth_at(x, y),
                        Some(0xff_ffff),
                        "draw {draw} ({mode:?}) depth at ({x}, {y})"
                    );
                }
            }
        }
    }

    // The random draws did rasterize something inside the viewport.
    assert!(drawn > 0, "no random primitive reached the framebuffer");

    // A fresh frame: default state back, clear, one good quad: exact.
    gl.viewport(0, 0, 32, 32).unwrap();
    for cap in [
        Capability::DepthTest,
        Capability::StencilTest,
        Capability::Blend,
        Capability::CullFace,
        Capability::PolygonOffsetFill,
        Capability::PolygonOffsetLine,
        Capability::PolygonOffsetPoint,
        Capability::ColorLogicOp,
    ] {
        gl.disable(cap).unwrap();
    }
    gl.polygon_mode(Face::FrontAndBack, PolygonMode::Fill).unwrap();
    projection(&mut gl, |_| ());
    gl.clear(ClearMask::ALL).unwrap();
    let mut b = Batch::default();
    b.good();
    b.draw(&mut gl, PrimitiveMode::Triangles);
    expect_image(&mut gl, "frame after the random draws", over(|_, _| false));
    let fb = gl.framebuffer();
    assert!(fb.stencil_buffer().unwrap().iter().all(|&s| s == 0));
    for y in 0..32 {
        for x in 0..32 {
            assert_eq!(fb.depth_at(x, y), Some(0xff_ffff));
        }
    }
    // And with depth testing: the quad writes depth 0.5 exactly.
    gl.enable(Capability::DepthTest).unwrap();
    gl.clear(ClearMask::ALL).unwrap();
    b.draw(&mut gl, PrimitiveMode::Triangles);
    expect_image(&mut gl, "depth-tested frame after the random draws", over(|_, _| false));
    assert_eq!(gl.framebuffer().depth_at(16, 16), Some(8_388_608));
    assert_eq!(gl.framebuffer().depth_at(0, 0), Some(0xff_ffff));
}
