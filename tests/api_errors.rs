//! The Rust API's GL errors: each rejected call returns the right [`GlError`],
//! `get_error` reports it once (the first error since the last poll wins) and
//! the call changes no state at all — raster state, matrices, stack depths,
//! current attributes and every buffer are compared before and after.

mod common;
use common::count;
use glam::Mat4;
use softgl::{
    BlendFactor, Capability, ClearMask, ColorFormat, CompareFunc, Context, CurrentAttribs, DepthFormat,
    FramebufferDesc, GlError, Indices, MatrixMode, PrimitiveMode, ReadFormat, VertexArrays,
};

const MODES: [MatrixMode; 3] = [MatrixMode::Modelview, MatrixMode::Projection, MatrixMode::Texture];

/// Everything a rejected call must leave alone.
#[derive(Clone, Debug, PartialEq)]
struct Snapshot {
    state: softgl::state::RasterState,
    matrices: [Mat4; 3],
    depths: [usize; 3],
    current: CurrentAttribs,
    color: Vec<u8>,
    depth: Option<softgl::framebuffer::DepthBuffer>,
    stencil: Option<Vec<u8>>,
}

fn snapshot(gl: &mut Context) -> Snapshot {
    let fb = gl.framebuffer();
    let (color, depth, stencil) = (
        fb.color_bytes().to_vec(),
        fb.depth_buffer().cloned(),
        fb.stencil_buffer().map(<[u8]>::to_vec),
    );
    Snapshot {
        state: gl.state().clone(),
        matrices: MODES.map(|m| gl.matrix(m)),
        depths: MODES.map(|m| gl.matrix_depth(m)),
        current: *gl.current(),
        color,
        depth,
        stencil,
    }
}

/// A 16×16 context with non-default state, so "unchanged" is not "initial".
fn context() -> Context {
    let mut gl = Context::new(FramebufferDesc::rgba8_d24s8(16, 16)).unwrap();
    gl.clear_color(0.25, 0.5, 0.75, 1.0).unwrap();
    gl.clear(ClearMask::ALL).unwrap();
    gl.enable(Capability::DepthTest).unwrap();
    gl.depth_func(CompareFunc::Lequal).unwrap();
    gl.viewport(1, 2, 13, 12).unwrap();
    gl.scissor(3, 4, 5, 6).unwrap();
    gl.point_size(2.5).unwrap();
    gl.line_width(3.0).unwrap();
    gl.blend_func(BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha)
        .unwrap();
    for (k, mode) in MODES.into_iter().enumerate() {
        gl.matrix_mode(mode).unwrap();
        gl.translate(k as f32 + 1.0, 2.0, 3.0).unwrap();
    }
    gl.matrix_mode(MatrixMode::Modelview).unwrap();
    gl.color4(0.1, 0.2, 0.3, 0.4);
    assert_eq!(gl.get_error(), None);
    gl
}

/// Runs `call`, which must fail with `expected`, then checks that `get_error`
/// reports it exactly once and that nothing changed.
fn rejects<T>(gl: &mut Context, expected: GlError, call: impl FnOnce(&mut Context) -> Result<T, GlError>) {
    let before = snapshot(gl);
    let r = call(gl);
    assert_eq!(r.err(), Some(expected), "the call's own result");
    assert_eq!(snapshot(gl), before, "a rejected call changed state");
    assert_eq!(gl.get_error(), Some(expected), "get_error after the call");
    assert_eq!(gl.get_error(), None, "get_error reports an error once");
}

#[test]
fn push_beyond_max_depth_is_stack_overflow() {
    for (mode, max) in MODES.into_iter().zip([32, 32, 10]) {
        let mut gl = context();
        gl.matrix_mode(mode).unwrap();
        for depth in 2..=max {
            gl.push_matrix().unwrap();
            assert_eq!(gl.matrix_depth(mode), depth);
        }
        // A top that differs from the one below, to see that nothing moves.
        gl.scale(2.0, 3.0, 4.0).unwrap();
        rejects(&mut gl, GlError::StackOverflow, Context::push_matrix);
        assert_eq!(gl.matrix_depth(mode), max);
        // The other stacks are still at depth 1.
        for other in MODES.into_iter().filter(|&m| m != mode) {
            assert_eq!(gl.matrix_depth(other), 1, "{other:?} while filling {mode:?}");
        }
        // The stack still works: pop then push again.
        gl.pop_matrix().unwrap();
        gl.push_matrix().unwrap();
        assert_eq!(gl.matrix_depth(mode), max);
    }
}

#[test]
fn pop_at_depth_one_is_stack_underflow() {
    for mode in MODES {
        let mut gl = context();
        gl.matrix_mode(mode).unwrap();
        assert_eq!(gl.matrix_depth(mode), 1);
        rejects(&mut gl, GlError::StackUnderflow, Context::pop_matrix);
        assert_eq!(gl.matrix_depth(mode), 1);
    }
}

#[test]
fn frustum_with_bad_planes_is_invalid_value() {
    let mut gl = context();
    gl.matrix_mode(MatrixMode::Projection).unwrap();
    let bad: [[f64; 6]; 9] = [
        [-1.0, 1.0, -1.0, 1.0, 0.0, 10.0],  // near = 0
        [-1.0, 1.0, -1.0, 1.0, -1.0, 10.0], // near < 0
        [-1.0, 1.0, -1.0, 1.0, 1.0, 0.0],   // far = 0
        [-1.0, 1.0, -1.0, 1.0, 1.0, -10.0], // far < 0
        [1.0, 1.0, -1.0, 1.0, 1.0, 10.0],   // left == right
        [-1.0, 1.0, 2.0, 2.0, 1.0, 10.0],   // bottom == top
        [-1.0, 1.0, -1.0, 1.0, 5.0, 5.0],   // near == far
        [-1.0, 1.0, -1.0, 1.0, -0.0, 10.0], // near = -0
        [0.0, 0.0, 0.0, 0.0, -3.0, -3.0],   // everything wrong at once
    ];
    for [l, r, b, t, n, f] in bad {
        rejects(&mut gl, GlError::InvalidValue, |gl| gl.frustum(l, r, b, t, n, f));
    }
}

#[test]
fn ortho_with_equal_planes_is_invalid_value() {
    let mut gl = context();
    gl.matrix_mode(MatrixMode::Projection).unwrap();
    rejects(&mut gl, GlError::InvalidValue, |gl| {
        gl.ortho(1.0, 1.0, -1.0, 1.0, -1.0, 1.0)
    });
    rejects(&mut gl, GlError::InvalidValue, |gl| {
        gl.ortho(-1.0, 1.0, 3.0, 3.0, -1.0, 1.0)
    });
    rejects(&mut gl, GlError::InvalidValue, |gl| {
        gl.ortho(-1.0, 1.0, -1.0, 1.0, 2.0, 2.0)
    });
    // Negative near and far are fine for ortho.
    let before = gl.matrix(MatrixMode::Projection);
    gl.ortho(-1.0, 1.0, -1.0, 1.0, -5.0, -1.0).unwrap();
    assert_ne!(gl.matrix(MatrixMode::Projection), before);
}

#[test]
fn negative_viewport_and_scissor_sizes_are_invalid_value() {
    let mut gl = context();
    rejects(&mut gl, GlError::InvalidValue, |gl| gl.viewport(0, 0, -1, 4));
    rejects(&mut gl, GlError::InvalidValue, |gl| gl.viewport(0, 0, 4, -1));
    rejects(&mut gl, GlError::InvalidValue, |gl| {
        gl.viewport(0, 0, i32::MIN, i32::MIN)
    });
    rejects(&mut gl, GlError::InvalidValue, |gl| gl.scissor(0, 0, -1, 4));
    rejects(&mut gl, GlError::InvalidValue, |gl| gl.scissor(0, 0, 4, -1));
    rejects(&mut gl, GlError::InvalidValue, |gl| gl.scissor(0, 0, i32::MIN, 0));
    // Zero sizes are valid.
    gl.viewport(0, 0, 0, 0).unwrap();
    gl.scissor(0, 0, 0, 0).unwrap();
    assert_eq!(gl.get_error(), None);
}

#[test]
fn nonpositive_point_size_and_line_width_are_invalid_value() {
    let mut gl = context();
    rejects(&mut gl, GlError::InvalidValue, |gl| gl.point_size(0.0));
    rejects(&mut gl, GlError::InvalidValue, |gl| gl.point_size(-1.0));
    rejects(&mut gl, GlError::InvalidValue, |gl| gl.point_size(-0.0));
    rejects(&mut gl, GlError::InvalidValue, |gl| gl.point_size(f32::NAN));
    rejects(&mut gl, GlError::InvalidValue, |gl| gl.line_width(0.0));
    rejects(&mut gl, GlError::InvalidValue, |gl| gl.line_width(-1.0));
    rejects(&mut gl, GlError::InvalidValue, |gl| gl.line_width(f32::NAN));
    assert_eq!(gl.state().point_size, 2.5);
    assert_eq!(gl.state().line_width, 3.0);
}

#[test]
fn src_alpha_saturate_as_destination_is_invalid_enum() {
    let mut gl = context();
    rejects(&mut gl, GlError::InvalidEnum, |gl| {
        gl.blend_func(BlendFactor::One, BlendFactor::SrcAlphaSaturate)
    });
    rejects(&mut gl, GlError::InvalidEnum, |gl| {
        gl.blend_func_separate(
            BlendFactor::One,
            BlendFactor::Zero,
            BlendFactor::One,
            BlendFactor::SrcAlphaSaturate,
        )
    });
    rejects(&mut gl, GlError::InvalidEnum, |gl| {
        gl.blend_func_separate(
            BlendFactor::One,
            BlendFactor::SrcAlphaSaturate,
            BlendFactor::One,
            BlendFactor::Zero,
        )
    });
    // As a source factor it is accepted.
    gl.blend_func(BlendFactor::SrcAlphaSaturate, BlendFactor::One).unwrap();
    assert_eq!(gl.blend_state().src_rgb, BlendFactor::SrcAlphaSaturate);
    assert_eq!(gl.get_error(), None);
}

#[test]
fn first_error_wins_until_polled() {
    let mut gl = context();
    assert_eq!(gl.point_size(0.0), Err(GlError::InvalidValue));
    assert_eq!(gl.pop_matrix(), Err(GlError::StackUnderflow));
    assert_eq!(gl.end(), Err(GlError::InvalidOperation));
    assert_eq!(gl.get_error(), Some(GlError::InvalidValue));
    assert_eq!(gl.get_error(), None);
    // A successful call does not clear a pending error.
    assert_eq!(gl.pop_matrix(), Err(GlError::StackUnderflow));
    gl.point_size(4.0).unwrap();
    assert_eq!(gl.get_error(), Some(GlError::StackUnderflow));
    assert_eq!(gl.get_error(), None);
}

/// A 16×16 context, cleared blue, with identity matrices and full viewport.
fn plain() -> Context {
    let mut gl = Context::new(FramebufferDesc::rgba8_d24s8(16, 16)).unwrap();
    gl.clear_color(0.0, 0.0, 1.0, 1.0).unwrap();
    gl.clear(ClearMask::ALL).unwrap();
    gl
}

const RED: [u8; 4] = [255, 0, 0, 255];
const BLUE: [u8; 4] = [0, 0, 255, 255];

#[test]
fn begin_inside_begin_is_invalid_operation() {
    let mut gl = plain();
    gl.begin(PrimitiveMode::Triangles).unwrap();
    gl.color3(1.0, 0.0, 0.0);
    gl.vertex2(-1.0, -1.0);
    rejects(&mut gl, GlError::InvalidOperation, |gl| gl.begin(PrimitiveMode::Points));
    gl.vertex2(3.0, -1.0);
    gl.vertex2(-1.0, 3.0);
    // The first begin is still open, as Triangles: the three vertices make one triangle.
    gl.end().unwrap();
    assert_eq!(count(&mut gl, RED), 256);
    assert_eq!(gl.get_error(), None);
}

#[test]
fn end_without_begin_is_invalid_operation() {
    let mut gl = context();
    rejects(&mut gl, GlError::InvalidOperation, Context::end);
    gl.begin(PrimitiveMode::Points).unwrap();
    gl.end().unwrap();
    rejects(&mut gl, GlError::InvalidOperation, Context::end);
}

#[test]
fn state_calls_between_begin_and_end_are_rejected_and_the_pair_still_draws() {
    let mut gl = plain();
    gl.begin(PrimitiveMode::Triangles).unwrap();
    gl.color3(1.0, 0.0, 0.0);
    gl.vertex2(-1.0, -1.0);
    rejects(&mut gl, GlError::InvalidOperation, |gl| {
        gl.enable(Capability::ScissorTest)
    });
    rejects(&mut gl, GlError::InvalidOperation, |gl| gl.disable(Capability::Dither));
    rejects(&mut gl, GlError::InvalidOperation, |gl| {
        gl.depth_func(CompareFunc::Never)
    });
    rejects(&mut gl, GlError::InvalidOperation, |gl| {
        gl.matrix_mode(MatrixMode::Projection)
    });
    rejects(&mut gl, GlError::InvalidOperation, Context::push_matrix);
    rejects(&mut gl, GlError::InvalidOperation, Context::pop_matrix);
    rejects(&mut gl, GlError::InvalidOperation, Context::load_identity);
    rejects(&mut gl, GlError::InvalidOperation, |gl| gl.translate(5.0, 0.0, 0.0));
    rejects(&mut gl, GlError::InvalidOperation, |gl| gl.scale(0.0, 0.0, 0.0));
    rejects(&mut gl, GlError::InvalidOperation, |gl| gl.rotate(90.0, 0.0, 0.0, 1.0));
    rejects(&mut gl, GlError::InvalidOperation, |gl| gl.load_matrix(&Mat4::ZERO));
    rejects(&mut gl, GlError::InvalidOperation, |gl| gl.mult_matrix(&Mat4::ZERO));
    rejects(&mut gl, GlError::InvalidOperation, |gl| {
        gl.frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 2.0)
    });
    // Inside begin/end the begin/end error wins over the argument error.
    rejects(&mut gl, GlError::InvalidOperation, |gl| {
        gl.frustum(-1.0, 1.0, -1.0, 1.0, -1.0, 2.0)
    });
    rejects(&mut gl, GlError::InvalidOperation, |gl| {
        gl.ortho(-1.0, 1.0, -1.0, 1.0, -1.0, 1.0)
    });
    rejects(&mut gl, GlError::InvalidOperation, |gl| {
        gl.clear_color(1.0, 1.0, 1.0, 1.0)
    });
    rejects(&mut gl, GlError::InvalidOperation, |gl| gl.clear(ClearMask::ALL));
    rejects(&mut gl, GlError::InvalidOperation, |gl| gl.viewport(0, 0, 1, 1));
    rejects(&mut gl, GlError::InvalidOperation, |gl| gl.viewport(0, 0, -1, 1));
    rejects(&mut gl, GlError::InvalidOperation, |gl| gl.point_size(0.0));
    rejects(&mut gl, GlError::InvalidOperation, |gl| {
        gl.blend_func(BlendFactor::Zero, BlendFactor::SrcAlphaSaturate)
    });
    rejects(&mut gl, GlError::InvalidOperation, |gl| {
        gl.color_mask(false, false, false, false)
    });
    rejects(&mut gl, GlError::InvalidOperation, |gl| {
        gl.read_pixels(0, 0, 1, 1, ReadFormat::Rgba8)
    });
    let arrays = VertexArrays::positions(2, &[0.0; 6]);
    rejects(&mut gl, GlError::InvalidOperation, |gl| {
        gl.draw_arrays(PrimitiveMode::Triangles, 0, 3, &arrays)
    });
    gl.vertex2(3.0, -1.0);
    gl.vertex2(-1.0, 3.0);
    gl.end().unwrap();
    // Identity matrices, full viewport, no scissor, color mask all: every pixel red.
    assert_eq!(count(&mut gl, RED), 256);
    assert_eq!(gl.get_error(), None);
}

#[test]
fn draw_arrays_past_the_end_is_invalid_value_and_draws_nothing() {
    let mut gl = plain();
    gl.color3(1.0, 0.0, 0.0);
    let pos = [-1.0, -1.0, 3.0, -1.0, -1.0, 3.0, -1.0, -1.0, 3.0, -1.0, -1.0, 3.0];
    let arrays = VertexArrays::positions(2, &pos);
    rejects(&mut gl, GlError::InvalidValue, |gl| {
        gl.draw_arrays(PrimitiveMode::Triangles, 4, 3, &arrays)
    });
    rejects(&mut gl, GlError::InvalidValue, |gl| {
        gl.draw_arrays(PrimitiveMode::Triangles, 0, 7, &arrays)
    });
    rejects(&mut gl, GlError::InvalidValue, |gl| {
        gl.draw_arrays(PrimitiveMode::Triangles, usize::MAX, 2, &arrays)
    });
    rejects(&mut gl, GlError::InvalidValue, |gl| {
        gl.draw_arrays(PrimitiveMode::Triangles, 1, usize::MAX, &arrays)
    });
    // A color array shorter than the positions limits the vertex count.
    let colors = [1.0; 9];
    let with_colors = VertexArrays::with_colors(2, &pos, 3, &colors);
    rejects(&mut gl, GlError::InvalidValue, |gl| {
        gl.draw_arrays(PrimitiveMode::Triangles, 0, 4, &with_colors)
    });
    assert_eq!(count(&mut gl, BLUE), 256);
    // The last valid range draws.
    gl.draw_arrays(PrimitiveMode::Triangles, 3, 3, &arrays).unwrap();
    assert_eq!(count(&mut gl, RED), 256);
    assert_eq!(gl.get_error(), None);
}

#[test]
fn bad_array_sizes_are_invalid_value() {
    let mut gl = plain();
    let data = [0.5f32; 30];
    for size in [0, 1, 5, 6] {
        let arrays = VertexArrays::positions(size, &data);
        rejects(&mut gl, GlError::InvalidValue, |gl| {
            gl.draw_arrays(PrimitiveMode::Points, 0, 3, &arrays)
        });
        rejects(&mut gl, GlError::InvalidValue, |gl| {
            gl.draw_elements(PrimitiveMode::Points, Indices::U8(&[0]), &arrays)
        });
    }
    for size in [2, 5] {
        let arrays = VertexArrays::with_colors(2, &data, size, &data);
        rejects(&mut gl, GlError::InvalidValue, |gl| {
            gl.draw_arrays(PrimitiveMode::Points, 0, 3, &arrays)
        });
    }
    // A stride shorter than the element.
    let mut arrays = VertexArrays::positions(3, &data);
    arrays.position.stride = 2;
    rejects(&mut gl, GlError::InvalidValue, |gl| {
        gl.draw_arrays(PrimitiveMode::Points, 0, 3, &arrays)
    });
    assert_eq!(count(&mut gl, BLUE), 256);
}

#[test]
fn draw_elements_with_an_index_out_of_range_is_invalid_value_and_draws_nothing() {
    let mut gl = plain();
    gl.color3(1.0, 0.0, 0.0);
    let pos = [-1.0, -1.0, 3.0, -1.0, -1.0, 3.0];
    let arrays = VertexArrays::positions(2, &pos);
    // The first triangle is valid; the bad index comes last and still nothing is drawn.
    rejects(&mut gl, GlError::InvalidValue, |gl| {
        gl.draw_elements(PrimitiveMode::Triangles, Indices::U8(&[0, 1, 2, 0, 1, 3]), &arrays)
    });
    rejects(&mut gl, GlError::InvalidValue, |gl| {
        gl.draw_elements(PrimitiveMode::Triangles, Indices::U16(&[0, 1, 2, 0, 1, 65535]), &arrays)
    });
    rejects(&mut gl, GlError::InvalidValue, |gl| {
        gl.draw_elements(PrimitiveMode::Triangles, Indices::U32(&[u32::MAX, 1, 2]), &arrays)
    });
    assert_eq!(count(&mut gl, BLUE), 256);
    gl.draw_elements(PrimitiveMode::Triangles, Indices::U32(&[2, 0, 1]), &arrays)
        .unwrap();
    assert_eq!(count(&mut gl, RED), 256);
    assert_eq!(gl.get_error(), None);
}

#[test]
fn invalid_framebuffer_descriptions_are_invalid_value() {
    let ok = FramebufferDesc::rgba8_d24s8(4, 4);
    let bad = [
        FramebufferDesc { width: 0, ..ok },
        FramebufferDesc { height: 0, ..ok },
        FramebufferDesc { width: 16385, ..ok },
        FramebufferDesc { height: 16385, ..ok },
        FramebufferDesc { width: u32::MAX, ..ok },
        FramebufferDesc { depth_bits: 8, ..ok },
        FramebufferDesc { depth_bits: 1, ..ok },
        FramebufferDesc { depth_bits: 33, ..ok },
        FramebufferDesc { stencil_bits: 4, ..ok },
        FramebufferDesc { stencil_bits: 16, ..ok },
        FramebufferDesc { stencil_bits: 1, ..ok },
    ];
    for desc in bad {
        assert_eq!(Context::new(desc).err(), Some(GlError::InvalidValue), "{desc:?}");
    }
    // The limits themselves are accepted, and every valid buffer combination.
    for desc in [
        FramebufferDesc {
            width: 16384,
            height: 1,
            ..ok
        },
        FramebufferDesc {
            width: 1,
            height: 16384,
            ..ok
        },
    ] {
        assert!(Context::new(desc).is_ok(), "{desc:?}");
    }
    for color in [
        ColorFormat::Rgba8,
        ColorFormat::Bgra8,
        ColorFormat::Rgb8,
        ColorFormat::Rgb565,
    ] {
        for (depth_bits, format) in [
            (0, None),
            (16, Some(DepthFormat::D16)),
            (24, Some(DepthFormat::D24)),
            (32, Some(DepthFormat::D32)),
        ] {
            for stencil_bits in [0, 8] {
                let desc = FramebufferDesc {
                    width: 2,
                    height: 3,
                    color,
                    depth_bits,
                    stencil_bits,
                };
                let mut gl = Context::new(desc).unwrap();
                assert_eq!(gl.framebuffer().depth_format(), format);
                assert_eq!(gl.framebuffer().has_stencil(), stencil_bits == 8);
            }
        }
    }
}

#[test]
fn read_pixels_with_a_negative_size_is_invalid_value() {
    let mut gl = context();
    rejects(&mut gl, GlError::InvalidValue, |gl| {
        gl.read_pixels(0, 0, -1, 1, ReadFormat::Rgba8)
    });
    rejects(&mut gl, GlError::InvalidValue, |gl| {
        gl.read_pixels(0, 0, 1, -1, ReadFormat::Rgb8)
    });
    rejects(&mut gl, GlError::InvalidValue, |gl| {
        gl.read_pixels(0, 0, i32::MIN, 1, ReadFormat::Bgra8)
    });
    rejects(&mut gl, GlError::InvalidValue, |gl| gl.read_pixels_f32(0, 0, -1, 1));
    // Zero sizes read nothing; rectangles partly outside read zeros there.
    assert_eq!(gl.read_pixels(0, 0, 0, 5, ReadFormat::Rgba8), Ok(vec![]));
    let px = gl.read_pixels(-1, 0, 2, 1, ReadFormat::Rgba8).unwrap();
    assert_eq!(px, vec![0, 0, 0, 0, 64, 128, 191, 255]);
    assert_eq!(gl.get_error(), None);
}
