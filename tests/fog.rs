//! Fog and the colour sum through the Rust API: pixels against values
//! computed here from GL 1.5 §3.10's formulas, the layout and key they make,
//! and fog values that never compile a specialist.

use softgl::{
    Backend, Capability, Context, FogCoordSrc, FogMode, FogParam, FramebufferDesc, GlError, MatrixMode, PrimitiveMode,
    VertexArrays,
};

fn context(backend: Backend) -> Context {
    let mut gl = Context::new(FramebufferDesc::rgba8_d24s8(8, 8)).unwrap();
    gl.set_backend(backend);
    gl.matrix_mode(MatrixMode::Projection).unwrap();
    gl.ortho(0.0, 8.0, 0.0, 8.0, -1.0, 1.0).unwrap();
    gl.matrix_mode(MatrixMode::Modelview).unwrap();
    gl
}

/// A full-window quad at eye depth `z` in `color`.
fn quad(gl: &mut Context, z: f32, color: [f32; 4]) {
    gl.begin(PrimitiveMode::Quads).unwrap();
    gl.color4(color[0], color[1], color[2], color[3]);
    for (x, y) in [(0.0, 0.0), (8.0, 0.0), (8.0, 8.0), (0.0, 8.0)] {
        gl.vertex3(x, y, z);
    }
    gl.end().unwrap();
}

/// `c · 255` rounded, the spec's conversion of a colour in [0, 1].
fn unorm(c: f64) -> u8 {
    (c.clamp(0.0, 1.0) * 255.0).round() as u8
}

/// The spec's fogged channel: `f·c + (1 − f)·fog`.
fn fogged(f: f64, c: f64, fog: f64) -> u8 {
    unorm(f * c + (1.0 - f) * fog)
}

fn fog_on(gl: &mut Context, mode: FogMode) {
    gl.enable(Capability::Fog).unwrap();
    gl.fog(FogParam::Mode(mode)).unwrap();
    gl.fog(FogParam::Color([0.0, 0.0, 1.0, 0.0])).unwrap();
}

#[test]
fn each_fog_mode_matches_the_spec_formula() {
    for backend in [Backend::Interpreter, Backend::Jit] {
        // Eye depth 0.25 (ortho: z_eye is the vertex z), red fogged towards blue.
        let c = 0.25f64;
        let cases: [(FogMode, f64); 3] = [
            (FogMode::Linear, (1.0 - c) / (1.0 - 0.0)),
            (FogMode::Exp, (-2.0 * c).exp()),
            (FogMode::Exp2, (-(2.0 * c) * (2.0 * c)).exp()),
        ];
        for (mode, f) in cases {
            let mut gl = context(backend);
            fog_on(&mut gl, mode);
            gl.fog(FogParam::Start(0.0)).unwrap();
            gl.fog(FogParam::End(1.0)).unwrap();
            gl.fog(FogParam::Density(2.0)).unwrap();
            quad(&mut gl, -0.25, [1.0, 0.0, 0.0, 0.6]);
            let want = [fogged(f, 1.0, 0.0), 0, fogged(f, 0.0, 1.0), unorm(0.6)];
            assert_eq!(gl.framebuffer().pixel(3, 3), Some(want), "{mode:?} on {backend:?}");
        }
    }
}

#[test]
fn the_fog_coordinate_source_picks_glfogcoord() {
    let mut gl = context(Backend::Jit);
    fog_on(&mut gl, FogMode::Linear);
    gl.fog(FogParam::CoordSrc(FogCoordSrc::FogCoord)).unwrap();
    gl.fog_coord(-0.4); // |c| is used, as Mesa's ffvertex_prog does
    quad(&mut gl, 0.9, [1.0, 0.0, 0.0, 1.0]);
    assert_eq!(
        gl.framebuffer().pixel(1, 6),
        Some([fogged(0.6, 1.0, 0.0), 0, fogged(0.6, 0.0, 1.0), 255])
    );
    // An array of fog coordinates per vertex: constant 0.8 here.
    let pos = [0.0, 0.0, 8.0, 0.0, 8.0, 8.0, 0.0, 8.0];
    let fog = [0.8f32; 4];
    let arrays = VertexArrays {
        fog_coord: Some(softgl::AttribArray::new(1, &fog)),
        ..VertexArrays::positions(2, &pos)
    };
    gl.color3(0.0, 1.0, 0.0);
    gl.draw_arrays(PrimitiveMode::Quads, 0, 4, &arrays).unwrap();
    assert_eq!(
        gl.framebuffer().pixel(4, 4),
        Some([0, fogged(0.2, 1.0, 0.0), fogged(0.2, 0.0, 1.0), 255])
    );
}

#[test]
fn the_colour_sum_adds_the_secondary_colour() {
    for backend in [Backend::Interpreter, Backend::Jit] {
        let mut gl = context(backend);
        gl.secondary_color3(0.4, 0.25, 0.2);
        quad(&mut gl, 0.0, [0.2, 0.32, 0.4, 0.6]);
        assert_eq!(gl.framebuffer().pixel(2, 2), Some([51, 82, 102, 153]), "sum off");
        gl.enable(Capability::ColorSum).unwrap();
        quad(&mut gl, 0.0, [0.2, 0.32, 0.4, 0.6]);
        // RGB summed, alpha the primary's.
        assert_eq!(
            gl.framebuffer().pixel(2, 2),
            Some([unorm(0.6), unorm(0.57), unorm(0.6), 153])
        );
        // The sum saturates when it becomes a byte.
        gl.secondary_color3(1.0, 1.0, 1.0);
        quad(&mut gl, 0.0, [0.2, 0.32, 0.4, 0.6]);
        assert_eq!(gl.framebuffer().pixel(2, 2), Some([255, 255, 255, 153]));
    }
}

#[test]
fn fog_and_secondary_colour_enter_the_layout_only_when_on() {
    let mut gl = context(Backend::Jit);
    let (_, plain) = gl.draw_plan();
    assert_eq!((plain.secondary(), plain.fog()), (None, None));
    gl.enable(Capability::Fog).unwrap();
    gl.enable(Capability::ColorSum).unwrap();
    let (_, both) = gl.draw_plan();
    assert_eq!(
        (both.color(), both.secondary(), both.fog(), both.len()),
        (Some(0), Some(4), Some(8), 9)
    );
}

#[test]
fn changing_fog_values_compiles_nothing() {
    let cases: [(FogMode, &[FogParam]); 2] = [
        (
            FogMode::Linear,
            &[
                FogParam::Start(-1.0),
                FogParam::End(3.0),
                FogParam::Color([0.0, 1.0, 0.0, 1.0]),
            ],
        ),
        (
            FogMode::Exp,
            &[FogParam::Density(0.5), FogParam::Color([1.0, 1.0, 0.0, 1.0])],
        ),
    ];
    for (mode, params) in cases {
        let mut gl = context(Backend::Jit);
        fog_on(&mut gl, mode);
        quad(&mut gl, -0.5, [1.0, 0.0, 0.0, 1.0]);
        let misses = gl.specialist_stats().misses;
        let mut last = gl.framebuffer().pixel(0, 0);
        for p in params {
            gl.fog(*p).unwrap();
            quad(&mut gl, -0.5, [1.0, 0.0, 0.0, 1.0]);
            let now = gl.framebuffer().pixel(0, 0);
            assert_ne!(now, last, "{p:?} changed the image");
            last = now;
        }
        assert_eq!(gl.specialist_stats().misses, misses, "{mode:?}");
    }
}

#[test]
fn bad_fog_values_are_errors_that_change_nothing() {
    let mut gl = context(Backend::Jit);
    assert_eq!(gl.fog(FogParam::Density(-1.0)), Err(GlError::InvalidValue));
    assert_eq!(gl.get_error(), Some(GlError::InvalidValue));
    assert_eq!(gl.fog_state().density, 1.0);
    gl.begin(PrimitiveMode::Points).unwrap();
    assert_eq!(gl.fog(FogParam::Start(2.0)), Err(GlError::InvalidOperation));
    gl.end().unwrap();
    assert_eq!(gl.fog_state().start, 0.0);
}
