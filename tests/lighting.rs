//! Lighting and user clip planes through the Rust API: what a draw carries,
//! lit pixels against the GL 1.5 formula worked by hand, two-sided
//! selection, normals from arrays, and clip planes cutting exactly.

use softgl::geometry::varying::VaryingLayout;
use softgl::{
    Capability, ColorControl, Context, Face, FramebufferDesc, FrontFace, LightModelParam, LightParam, MaterialParam,
    PrimitiveMode, VertexArrays,
};

fn context() -> Context {
    Context::new(FramebufferDesc::rgba8_d24s8(8, 8)).unwrap()
}

/// A quad over the whole window, counter-clockwise (front-facing).
const QUAD: [f32; 8] = [-1.0, -1.0, 1.0, -1.0, 1.0, 1.0, -1.0, 1.0];

fn quad(gl: &mut Context, ccw: bool) {
    gl.begin(PrimitiveMode::Quads).unwrap();
    let order: [usize; 4] = if ccw { [0, 1, 2, 3] } else { [0, 3, 2, 1] };
    for i in order {
        gl.vertex2(QUAD[2 * i], QUAD[2 * i + 1]);
    }
    gl.end().unwrap();
}

#[test]
fn lighting_adds_varyings_only_for_what_it_produces() {
    let mut gl = context();
    let plain = VaryingLayout {
        color: true,
        ..VaryingLayout::default()
    };
    assert_eq!(gl.draw_plan().1, plain);
    // One-sided, single colour: lighting replaces the colour, adds nothing.
    gl.enable(Capability::Lighting).unwrap();
    assert_eq!(gl.draw_plan().1, plain);
    gl.light_model(LightModelParam::TwoSide(true)).unwrap();
    assert_eq!(
        gl.draw_plan().1,
        VaryingLayout {
            back_color: true,
            ..plain
        }
    );
    gl.light_model(LightModelParam::ColorControl(ColorControl::SeparateSpecular))
        .unwrap();
    assert_eq!(
        gl.draw_plan().1,
        VaryingLayout {
            color: true,
            back_color: true,
            secondary: true,
            back_secondary: true,
            fog: false,
            tex: 0,
            uniform_colors: false,
        }
    );
    // The same state with lighting off carries the colour alone again.
    gl.disable(Capability::Lighting).unwrap();
    assert_eq!(gl.draw_plan().1, plain);
}

#[test]
fn a_lit_quad_has_the_colour_of_the_formula() {
    let mut gl = context();
    gl.enable(Capability::Lighting).unwrap();
    gl.enable(Capability::Light(0)).unwrap();
    // GL's defaults: light 0 white along +z, material ambient 0.2 and
    // diffuse 0.8, model ambient 0.2, normal (0, 0, 1):
    // 0.2·0.2 + 0.8·1·(n·L = 1) = 0.84 → round(0.84 · 255) = 214.
    quad(&mut gl, true);
    assert_eq!(gl.framebuffer().pixel(3, 3), Some([214, 214, 214, 255]));
    // Emission (0.1, 0, 0) and a light at 60° from the normal (n·L = 0.5):
    // r = 0.1 + 0.04 + 0.8·0.5 = 0.54 → 138, g = b = 0.44 → 112.
    gl.material(Face::Front, MaterialParam::Emission([0.1, 0.0, 0.0, 1.0]))
        .unwrap();
    let s = 3f32.sqrt() / 2.0;
    gl.light(0, LightParam::Position([s, 0.0, 0.5, 0.0])).unwrap();
    quad(&mut gl, true);
    assert_eq!(gl.framebuffer().pixel(3, 3), Some([138, 112, 112, 255]));
    // Light 0 off: the scene colour 0.1 + 0.04, 0.04 → 36, 10.
    gl.disable(Capability::Light(0)).unwrap();
    quad(&mut gl, true);
    assert_eq!(gl.framebuffer().pixel(3, 3), Some([36, 10, 10, 255]));
}

#[test]
fn two_sided_lighting_lights_back_faces_with_the_back_material() {
    let mut gl = context();
    gl.enable(Capability::Lighting).unwrap();
    gl.enable(Capability::Light(0)).unwrap();
    gl.light(0, LightParam::Position([0.0, 0.0, -1.0, 0.0])).unwrap();
    gl.material(Face::Back, MaterialParam::Diffuse([0.0, 1.0, 0.0, 1.0]))
        .unwrap();
    // One-sided: the back face uses the front material and its own normal,
    // which faces away from the light: ambient only, 0.04 → 10.
    quad(&mut gl, false);
    assert_eq!(gl.framebuffer().pixel(3, 3), Some([10, 10, 10, 255]));
    // Two-sided: the reversed normal faces the light; back diffuse green:
    // (0.04, 0.04 + 1, 0.04) → (10, 255, 10).
    gl.light_model(LightModelParam::TwoSide(true)).unwrap();
    quad(&mut gl, false);
    assert_eq!(gl.framebuffer().pixel(3, 3), Some([10, 255, 10, 255]));
    // The front face of the same state is unlit by this light.
    quad(&mut gl, true);
    assert_eq!(gl.framebuffer().pixel(3, 3), Some([10, 10, 10, 255]));
    // With GL_CW as the front, the clockwise quad is the front again.
    gl.front_face(FrontFace::Cw).unwrap();
    quad(&mut gl, false);
    assert_eq!(gl.framebuffer().pixel(3, 3), Some([10, 10, 10, 255]));
}

#[test]
fn normals_from_an_array_light_like_immediate_normals() {
    let normals: Vec<f32> = [[0.0, 0.0, 1.0], [0.6, 0.0, 0.8], [0.0, 0.6, 0.8], [-0.6, 0.0, 0.8]].concat();
    let pos: Vec<f32> = QUAD.to_vec();
    let draw = |immediate: bool| {
        let mut gl = context();
        gl.enable(Capability::Lighting).unwrap();
        gl.enable(Capability::Light(0)).unwrap();
        gl.light(0, LightParam::Position([0.3, 0.2, 1.0, 0.0])).unwrap();
        if immediate {
            gl.begin(PrimitiveMode::Quads).unwrap();
            for i in 0..4 {
                gl.normal3(normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]);
                gl.vertex2(pos[2 * i], pos[2 * i + 1]);
            }
            gl.end().unwrap();
        } else {
            let arrays = VertexArrays::positions(2, &pos).with_normals(&normals);
            gl.draw_arrays(PrimitiveMode::Quads, 0, 4, &arrays).unwrap();
        }
        gl.read_pixels(0, 0, 8, 8, softgl::ReadFormat::Rgba8).unwrap()
    };
    let (a, b) = (draw(true), draw(false));
    assert_eq!(a, b);
    // The normals differ per vertex: so do the pixels.
    assert_ne!(a[..4], a[a.len() - 4..]);
}

#[test]
fn a_clip_plane_keeps_exactly_one_half() {
    let mut gl = context();
    gl.color3(1.0, 1.0, 1.0);
    // x ≥ 0 (identity modelview and projection): the left half goes.
    gl.clip_plane(0, [1.0, 0.0, 0.0, 0.0]).unwrap();
    gl.enable(Capability::ClipPlane(0)).unwrap();
    quad(&mut gl, true);
    let covered = |gl: &mut Context| -> Vec<usize> {
        (0..8)
            .map(|x| {
                (0..8)
                    .filter(|&y| gl.framebuffer().pixel(x, y) == Some([255; 4]))
                    .count()
            })
            .collect()
    };
    assert_eq!(covered(&mut gl), [0, 0, 0, 0, 8, 8, 8, 8]);
    assert_eq!(gl.get_clip_plane(0), Ok([1.0, 0.0, 0.0, 0.0]));
    // A plane given under a translation is kept in eye coordinates:
    // x_obj = x_eye + 0.5 ≥ 0 keeps x_eye ≥ -0.5: two more columns.
    let mut gl = context();
    gl.color3(1.0, 1.0, 1.0);
    gl.translate(-0.5, 0.0, 0.0).unwrap();
    gl.clip_plane(1, [1.0, 0.0, 0.0, 0.0]).unwrap();
    gl.load_identity().unwrap();
    gl.enable(Capability::ClipPlane(1)).unwrap();
    assert_eq!(gl.get_clip_plane(1), Ok([1.0, 0.0, 0.0, 0.5]));
    quad(&mut gl, true);
    assert_eq!(covered(&mut gl), [0, 0, 8, 8, 8, 8, 8, 8]);
    // Disabled, it cuts nothing.
    gl.disable(Capability::ClipPlane(1)).unwrap();
    quad(&mut gl, true);
    assert_eq!(covered(&mut gl), [8; 8]);
}

#[test]
fn lines_and_points_are_clipped_by_user_planes() {
    let mut gl = context();
    gl.color3(1.0, 1.0, 1.0);
    gl.clip_plane(0, [0.0, -1.0, 0.0, 0.0]).unwrap(); // keep y ≤ 0
    gl.enable(Capability::ClipPlane(0)).unwrap();
    gl.begin(PrimitiveMode::Lines).unwrap();
    gl.vertex2(0.125, -1.0);
    gl.vertex2(0.125, 1.0);
    gl.end().unwrap();
    let column: Vec<bool> = (0..8).map(|y| gl.framebuffer().pixel(4, y) == Some([255; 4])).collect();
    assert_eq!(column, [true, true, true, true, false, false, false, false]);
    gl.begin(PrimitiveMode::Points).unwrap();
    gl.vertex2(-0.625, 0.625); // outside: dropped
    gl.vertex2(-0.625, -0.625); // inside
    gl.end().unwrap();
    assert_eq!(gl.framebuffer().pixel(1, 6), Some([0, 0, 0, 0]));
    assert_eq!(gl.framebuffer().pixel(1, 1), Some([255; 4]));
}

#[test]
fn lit_flat_quads_split_along_v1_v3_as_llvmpipe() {
    // A bowtie quad (docs/llvmpipe-facts.md §12): lit colours are vertex
    // outputs, so flat shading sends it down llvmpipe's v1-v3 split.
    let v = [[2.0f32, 2.0], [2.0, 29.0], [29.0, 4.0], [29.0, 30.0]];
    let draw = |order: &[usize], mode: PrimitiveMode| {
        let mut gl = Context::new(FramebufferDesc::rgba8_d24s8(32, 32)).unwrap();
        gl.matrix_mode(softgl::MatrixMode::Projection).unwrap();
        gl.ortho(0.0, 32.0, 0.0, 32.0, -1.0, 1.0).unwrap();
        gl.shade_model(softgl::ShadeModel::Flat).unwrap();
        gl.enable(Capability::Lighting).unwrap();
        gl.enable(Capability::Light(0)).unwrap();
        gl.begin(mode).unwrap();
        for &i in order {
            gl.vertex2(v[i][0], v[i][1]);
        }
        gl.end().unwrap();
        gl.read_pixels(0, 0, 32, 32, softgl::ReadFormat::Rgba8).unwrap()
    };
    let as_quad = draw(&[0, 1, 2, 3], PrimitiveMode::Quads);
    assert_eq!(as_quad, draw(&[0, 1, 3, 1, 2, 3], PrimitiveMode::Triangles));
    assert_ne!(as_quad, draw(&[0, 1, 2, 0, 2, 3], PrimitiveMode::Triangles));
    let covered = as_quad.chunks_exact(4).filter(|p| p[0] != 0).count();
    assert_eq!(covered, 534, "llvmpipe's count");
}
