//! The Rust API's behaviour on exact values: clears, read-back, buffers,
//! matrices, vertex arrays.

use glam::{Mat4, Vec4};
use softgl::{
    Backend, Capability, ClearMask, ColorFormat, Context, DepthFormat, FramebufferDesc, Indices, MatrixMode,
    PrimitiveMode, ReadFormat, VertexArrays,
};

#[test]
fn context_is_send() {
    fn assert_send<T: Send>() {}
    assert_send::<Context>();
}

#[test]
fn only_requested_buffers_are_allocated() {
    let desc = FramebufferDesc {
        width: 4,
        height: 3,
        color: ColorFormat::Rgb565,
        depth_bits: 0,
        stencil_bits: 0,
    };
    let mut gl = Context::new(desc).unwrap();
    let fb = gl.framebuffer();
    assert_eq!(fb.color_bytes().len(), 4 * 3 * 2);
    assert!(fb.depth_buffer().is_none());
    assert!(fb.stencil_buffer().is_none());
    for (bits, format) in [(16, DepthFormat::D16), (24, DepthFormat::D24), (32, DepthFormat::D32)] {
        let desc = FramebufferDesc {
            width: 4,
            height: 3,
            color: ColorFormat::Rgba8,
            depth_bits: bits,
            stencil_bits: 8,
        };
        let mut gl = Context::new(desc).unwrap();
        assert_eq!(gl.framebuffer().depth_format(), Some(format));
        assert_eq!(
            gl.framebuffer().depth_at(3, 2),
            Some(format.max_value()),
            "cleared to 1.0"
        );
        assert_eq!(gl.framebuffer().stencil_buffer().map(<[u8]>::len), Some(12));
    }
}

#[test]
fn clear_honours_scissor_and_masks() {
    let mut gl = Context::new(FramebufferDesc::rgba8_d24s8(8, 8)).unwrap();
    gl.clear_color(0.2, 0.4, 0.6, 0.8).unwrap();
    gl.clear_depth(0.5).unwrap();
    gl.clear_stencil(0xAB).unwrap();
    gl.clear(ClearMask::ALL).unwrap();
    let c = [51, 102, 153, 204];
    assert_eq!(gl.framebuffer().pixel(0, 0), Some(c));
    assert_eq!(gl.framebuffer().depth_at(7, 7), Some(0x80_0000));
    assert_eq!(gl.framebuffer().stencil_at(3, 3), Some(0xAB));

    gl.enable(Capability::ScissorTest).unwrap();
    gl.scissor(2, 3, 3, 2).unwrap();
    gl.color_mask(true, false, true, false).unwrap();
    gl.depth_mask(false).unwrap();
    gl.stencil_mask(0x0F).unwrap();
    gl.clear_color(1.0, 1.0, 1.0, 1.0).unwrap();
    gl.clear_depth(0.0).unwrap();
    gl.clear_stencil(0x00).unwrap();
    gl.clear(ClearMask::ALL).unwrap();
    let fb = gl.framebuffer();
    for y in 0..8 {
        for x in 0..8 {
            let inside = (2..5).contains(&x) && (3..5).contains(&y);
            let want = if inside { [255, 102, 255, 204] } else { c };
            assert_eq!(fb.pixel(x, y), Some(want), "({x}, {y})");
            assert_eq!(fb.depth_at(x, y), Some(0x80_0000), "depth mask off");
            assert_eq!(
                fb.stencil_at(x, y),
                Some(if inside { 0xA0 } else { 0xAB }),
                "({x}, {y})"
            );
        }
    }
}

#[test]
fn read_pixels_in_every_format() {
    let mut gl = Context::new(FramebufferDesc::rgba8_d24s8(3, 2)).unwrap();
    gl.clear_color(1.0, 0.5, 0.0, 0.25).unwrap();
    gl.clear(ClearMask::COLOR).unwrap();
    let px = [255u8, 128, 0, 64];
    assert_eq!(gl.read_pixels(0, 0, 3, 2, ReadFormat::Rgba8).unwrap(), px.repeat(6));
    assert_eq!(
        gl.read_pixels(1, 1, 2, 1, ReadFormat::Rgb8).unwrap(),
        [255, 128, 0].repeat(2)
    );
    assert_eq!(
        gl.read_pixels(0, 0, 1, 1, ReadFormat::Bgra8).unwrap(),
        [0, 128, 255, 64]
    );
    let f = gl.read_pixels_f32(2, 1, 1, 1).unwrap();
    assert_eq!(f, vec![[1.0, 128.0 / 255.0, 0.0, 64.0 / 255.0]]);
    // Outside the framebuffer reads as zero.
    assert_eq!(
        gl.read_pixels(2, 1, 2, 1, ReadFormat::Rgba8).unwrap(),
        [px.to_vec(), vec![0; 4]].concat()
    );
    // The image is top row first.
    let img = gl.framebuffer().to_rgba_image();
    assert_eq!((img.width(), img.height()), (3, 2));
    assert_eq!(img.get_pixel(0, 0).0, px);
}

#[test]
fn matrix_calls_build_gls_matrices() {
    let mut gl = Context::new(FramebufferDesc::rgba8_d24s8(4, 4)).unwrap();
    gl.translate(1.0, 2.0, 3.0).unwrap();
    gl.scale(2.0, 2.0, 2.0).unwrap();
    let p = gl.matrix(MatrixMode::Modelview) * Vec4::new(1.0, 1.0, 1.0, 1.0);
    assert_eq!(p, Vec4::new(3.0, 4.0, 5.0, 1.0));
    gl.load_identity().unwrap();
    gl.rotate(90.0, 0.0, 0.0, 1.0).unwrap();
    let p = gl.matrix(MatrixMode::Modelview) * Vec4::new(1.0, 0.0, 0.0, 1.0);
    assert!((p - Vec4::new(0.0, 1.0, 0.0, 1.0)).abs().max_element() < 1e-6, "{p}");
    gl.matrix_mode(MatrixMode::Projection).unwrap();
    gl.frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 3.0).unwrap();
    // The near plane maps to z = -1, the far plane to z = +1.
    let m = gl.matrix(MatrixMode::Projection);
    let near = m * Vec4::new(0.0, 0.0, -1.0, 1.0);
    let far = m * Vec4::new(0.0, 0.0, -3.0, 1.0);
    assert!((near.z / near.w + 1.0).abs() < 1e-6 && (far.z / far.w - 1.0).abs() < 1e-6);
    gl.load_identity().unwrap();
    gl.ortho(0.0, 4.0, 0.0, 2.0, -1.0, 1.0).unwrap();
    let p = gl.matrix(MatrixMode::Projection) * Vec4::new(4.0, 2.0, 0.0, 1.0);
    assert_eq!(p, Vec4::new(1.0, 1.0, 0.0, 1.0));
    gl.push_matrix().unwrap();
    gl.load_matrix(&Mat4::ZERO).unwrap();
    assert_eq!(gl.matrix_depth(MatrixMode::Projection), 2);
    gl.pop_matrix().unwrap();
    assert_eq!(
        gl.matrix(MatrixMode::Projection) * Vec4::new(4.0, 2.0, 0.0, 1.0),
        Vec4::new(1.0, 1.0, 0.0, 1.0)
    );
}

#[test]
fn draw_elements_with_each_index_type_matches_draw_arrays() {
    let pos = [-1.0f32, -1.0, 1.0, -1.0, 1.0, 1.0, -1.0, 1.0];
    let col = [
        1.0f32, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0,
    ];
    let arrays = VertexArrays::with_colors(2, &pos, 4, &col);
    let render = |draw: &dyn Fn(&mut Context)| {
        let mut gl = Context::new(FramebufferDesc::rgba8_d24s8(16, 16)).unwrap();
        draw(&mut gl);
        gl.framebuffer().color_bytes().to_vec()
    };
    let reference = render(&|gl| gl.draw_arrays(PrimitiveMode::TriangleFan, 0, 4, &arrays).unwrap());
    assert!(reference.chunks(4).all(|p| p[3] == 255), "the fan covers the window");
    let order = [0u32, 1, 2, 3];
    let by_u8 = render(&|gl| {
        let idx = order.map(|i| i as u8);
        gl.draw_elements(PrimitiveMode::TriangleFan, Indices::U8(&idx), &arrays)
            .unwrap()
    });
    let by_u16 = render(&|gl| {
        let idx = order.map(|i| i as u16);
        gl.draw_elements(PrimitiveMode::TriangleFan, Indices::U16(&idx), &arrays)
            .unwrap()
    });
    let by_u32 = render(&|gl| {
        gl.draw_elements(PrimitiveMode::TriangleFan, Indices::U32(&order), &arrays)
            .unwrap()
    });
    assert_eq!(by_u8, reference);
    assert_eq!(by_u16, reference);
    assert_eq!(by_u32, reference);
    // Immediate mode gives the same pixels too.
    let immediate = render(&|gl| {
        gl.begin(PrimitiveMode::TriangleFan).unwrap();
        for i in 0..4 {
            gl.color4(col[4 * i], col[4 * i + 1], col[4 * i + 2], col[4 * i + 3]);
            gl.vertex2(pos[2 * i], pos[2 * i + 1]);
        }
        gl.end().unwrap();
    });
    assert_eq!(immediate, reference);
}

#[test]
fn viewport_and_depth_range_place_geometry() {
    let mut gl = Context::new(FramebufferDesc::rgba8_d24s8(8, 8)).unwrap();
    gl.viewport(4, 0, 4, 4).unwrap();
    gl.depth_range(0.25, 0.75).unwrap();
    gl.enable(Capability::DepthTest).unwrap();
    gl.begin(PrimitiveMode::Quads).unwrap();
    for (x, y) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
        gl.vertex3(x, y, 0.0);
    }
    gl.end().unwrap();
    let fb = gl.framebuffer();
    for y in 0..8 {
        for x in 0..8 {
            let inside = x >= 4 && y < 4;
            assert_eq!(fb.pixel(x, y).unwrap()[3] == 255, inside, "({x}, {y})");
            // Window z 0.5 in the middle of the range.
            assert_eq!(fb.depth_at(x, y), Some(if inside { 0x80_0000 } else { 0xFF_FFFF }));
        }
    }
}

#[test]
fn specialists_are_compiled_once_per_state_and_counted() {
    let mut gl = Context::new(FramebufferDesc::rgba8_d24s8(16, 16)).unwrap();
    gl.set_backend(Backend::Jit);
    let tri = [-1.0f32, -1.0, 0.0, 3.0, -1.0, 0.0, -1.0, 3.0, 0.0];
    let arrays = VertexArrays::positions(3, &tri);
    let draw = |gl: &mut Context| gl.draw_arrays(PrimitiveMode::Triangles, 0, 3, &arrays).unwrap();
    draw(&mut gl);
    draw(&mut gl);
    gl.enable(Capability::DepthTest).unwrap();
    draw(&mut gl);
    gl.disable(Capability::DepthTest).unwrap();
    draw(&mut gl);
    let s = gl.specialist_stats();
    assert_eq!((s.misses, s.hits, s.evictions, s.failures, s.resident), (2, 2, 0, 0, 2));
    gl.set_specialist_capacity(1);
    assert_eq!(gl.specialist_stats().evictions, 1);

    // The interpreter never touches the cache.
    let mut gl = Context::new(FramebufferDesc::rgba8_d24s8(16, 16)).unwrap();
    gl.set_backend(Backend::Interpreter);
    draw(&mut gl);
    assert_eq!(gl.specialist_stats().misses, 0);
    assert_eq!(gl.framebuffer().pixel(8, 8), Some([255, 255, 255, 255]));
}

#[test]
fn softgl_backend_chooses_the_back_end() {
    assert_eq!(Backend::parse(Some("interp")), Backend::Interpreter);
    assert_eq!(Backend::parse(Some("interpreter")), Backend::Interpreter);
    assert_eq!(Backend::parse(Some("jit")), Backend::Jit);
    assert_eq!(Backend::parse(None), Backend::Jit, "the JIT is the default");
    assert_eq!(
        Backend::parse(Some("llvm")),
        Backend::Jit,
        "an unknown name keeps the default"
    );
}
