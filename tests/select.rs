//! Selection and feedback through the Rust API (`src/select.rs`): hit
//! records, feedback tokens and values, overflow, the name stack's errors,
//! and nothing rasterized. (`osmesa/tests/clients.rs`'s
//! `selection_and_feedback_match_mesa` compares the C ABI with llvmpipe.)

use softgl::select::{FeedbackType, ModeOutput, RenderMode, MAX_NAME_STACK_DEPTH};
use softgl::{Context, FramebufferDesc, GlError, PrimitiveMode, ReadFormat};

fn ctx() -> Context {
    Context::new(FramebufferDesc::rgba8_d24s8(16, 16)).unwrap()
}

fn draw(gl: &mut Context, mode: PrimitiveMode, v: &[[f32; 3]]) {
    gl.begin(mode).unwrap();
    for p in v {
        gl.vertex3(p[0], p[1], p[2]);
    }
    gl.end().unwrap();
}

#[test]
fn select_records_names_and_depths_and_draws_nothing() {
    let mut gl = ctx();
    gl.select_buffer(64).unwrap();
    assert_eq!(gl.render_mode(RenderMode::Select).unwrap(), (0, ModeOutput::None));
    gl.init_names().unwrap();
    gl.push_name(7).unwrap();
    // Window z = (z + 1) / 2 with the identity projection.
    draw(
        &mut gl,
        PrimitiveMode::Triangles,
        &[[-0.5, -0.5, 0.0], [0.5, -0.5, 0.0], [0.0, 0.5, -1.0]],
    );
    gl.push_name(8).unwrap();
    draw(&mut gl, PrimitiveMode::Points, &[[3.0, 0.0, 0.0]]); // outside: no hit
    gl.load_name(9).unwrap();
    draw(&mut gl, PrimitiveMode::Points, &[[0.0, 0.0, 1.0]]);
    let (hits, out) = gl.render_mode(RenderMode::Render).unwrap();
    assert_eq!(hits, 2);
    // z 0.5 scales to 2^31 in f32; z 1 to 2^32, which C's conversion wraps to 0 (as on Mesa).
    assert_eq!(out, ModeOutput::Select(vec![1, 0, 1 << 31, 7, 2, 0, 0, 7, 9]));
    assert_eq!(gl.render_mode_state().select.names.len(), 0);
    let pixels = gl.read_pixels(0, 0, 16, 16, ReadFormat::Rgba8).unwrap();
    assert!(pixels.chunks_exact(4).all(|p| p == [0, 0, 0, 0]));
}

#[test]
fn select_overflow_returns_minus_one_and_keeps_what_fits() {
    let mut gl = ctx();
    gl.select_buffer(5).unwrap();
    gl.render_mode(RenderMode::Select).unwrap();
    gl.init_names().unwrap();
    gl.push_name(1).unwrap();
    draw(&mut gl, PrimitiveMode::Points, &[[0.0, 0.0, -1.0]]);
    gl.load_name(2).unwrap();
    draw(&mut gl, PrimitiveMode::Points, &[[0.0, 0.0, -1.0]]);
    let (hits, out) = gl.render_mode(RenderMode::Render).unwrap();
    assert_eq!((hits, out), (-1, ModeOutput::Select(vec![1, 0, 0, 1, 1])));
}

#[test]
fn name_stack_errors_and_calls_outside_select_mode() {
    let mut gl = ctx();
    // Outside select mode: ignored, no error.
    gl.pop_name().unwrap();
    gl.load_name(1).unwrap();
    gl.push_name(1).unwrap();
    assert_eq!(gl.render_mode_state().select.names.len(), 0);
    assert_eq!(gl.select_buffer(-1), Err(GlError::InvalidValue));
    assert_eq!(gl.get_error(), Some(GlError::InvalidValue));
    // Entering without a buffer: the mode changes, the error is recorded.
    assert_eq!(gl.render_mode(RenderMode::Select), Ok((0, ModeOutput::None)));
    assert_eq!(gl.get_error(), Some(GlError::InvalidOperation));
    assert_eq!(gl.select_buffer(4), Err(GlError::InvalidOperation));
    assert_eq!(gl.load_name(1), Err(GlError::InvalidOperation));
    assert_eq!(gl.pop_name(), Err(GlError::StackUnderflow));
    for i in 0..MAX_NAME_STACK_DEPTH as u32 {
        gl.push_name(i).unwrap();
    }
    assert_eq!(gl.push_name(99), Err(GlError::StackOverflow));
    assert_eq!(gl.render_mode_state().select.names.len(), 64);
    gl.render_mode(RenderMode::Render).unwrap();
    gl.get_error();
    gl.begin(PrimitiveMode::Points).unwrap();
    assert_eq!(gl.render_mode(RenderMode::Select), Err(GlError::InvalidOperation));
    assert_eq!(gl.render_mode_state().mode, RenderMode::Render);
}

#[test]
fn feedback_writes_tokens_window_coordinates_colours_and_pass_through() {
    let mut gl = ctx();
    assert_eq!(gl.feedback_buffer(-1, FeedbackType::D2), Err(GlError::InvalidValue));
    gl.feedback_buffer(100, FeedbackType::D3Color).unwrap();
    gl.render_mode(RenderMode::Feedback).unwrap();
    assert_eq!(
        gl.feedback_buffer(100, FeedbackType::D2),
        Err(GlError::InvalidOperation)
    );
    gl.pass_through(5.0).unwrap();
    gl.color4(1.0, 0.5, 0.25, 1.0);
    draw(&mut gl, PrimitiveMode::Points, &[[0.0, 0.0, 0.0], [5.0, 0.0, 0.0]]);
    // Clipped at x = 1: window x 16.
    draw(&mut gl, PrimitiveMode::Lines, &[[0.0, 0.5, 0.0], [3.0, 0.5, 0.0]]);
    let (n, out) = gl.render_mode(RenderMode::Render).unwrap();
    let c = [1.0, 0.5, 0.25, 1.0];
    let mut want = vec![1792.0, 5.0, 1793.0, 8.0, 8.0, 0.5];
    want.extend(c);
    want.extend([1794.0, 8.0, 12.0, 0.5]);
    want.extend(c);
    want.extend([16.0, 12.0, 0.5]);
    want.extend(c);
    assert_eq!(n, want.len() as i32);
    assert_eq!(out, ModeOutput::Feedback(want));
}

#[test]
fn feedback_culls_and_overflows() {
    let mut gl = ctx();
    gl.enable(softgl::Capability::CullFace).unwrap();
    gl.feedback_buffer(3, FeedbackType::D2).unwrap();
    gl.render_mode(RenderMode::Feedback).unwrap();
    // Clockwise: culled.
    draw(
        &mut gl,
        PrimitiveMode::Triangles,
        &[[0.0, 0.0, 0.0], [0.0, 0.5, 0.0], [0.5, 0.0, 0.0]],
    );
    assert_eq!(gl.render_mode_state().feedback.count, 0);
    draw(
        &mut gl,
        PrimitiveMode::Triangles,
        &[[0.0, 0.0, 0.0], [0.5, 0.0, 0.0], [0.0, 0.5, 0.0]],
    );
    let (n, out) = gl.render_mode(RenderMode::Render).unwrap();
    assert_eq!((n, out), (-1, ModeOutput::Feedback(vec![1795.0, 3.0, 8.0])));
}
