//! The built-in demo scene: a stencil reflection of spinning cubes on a
//! checkered floor under a gradient sky, with a translucent glass pane,
//! wireframe edges drawn with polygon offset, and points for stars. It uses
//! depth testing, stencil, blending, culling, flat and smooth shading, lines
//! and points — most of what the core does, in one picture.

use crate::context::Context;
use crate::error::GlResult;
use crate::fragment::Backend;
use crate::framebuffer::FramebufferDesc;
use crate::matrix::MatrixMode;
use crate::state::{Capability, ClearMask, Face, PolygonMode, PrimitiveMode, ShadeModel};
use softgl_jit::{BlendFactor, CompareFunc, StencilOp};

/// Renders the demo scene into a new RGBA8 + D24 + S8 context of `width` × `height`,
/// on the back end `SOFTGL_BACKEND` names.
pub fn render(width: u32, height: u32) -> GlResult<Context> {
    render_on(Backend::from_env(), width, height)
}

/// [`render`] on the given back end.
pub fn render_on(backend: Backend, width: u32, height: u32) -> GlResult<Context> {
    let mut gl = Context::new(FramebufferDesc::rgba8_d24s8(width, height))?;
    gl.set_backend(backend);
    gl.clear_color(0.0, 0.0, 0.0, 1.0)?;
    gl.clear(ClearMask::ALL)?;
    sky(&mut gl)?;

    let aspect = f64::from(width) / f64::from(height);
    gl.matrix_mode(MatrixMode::Projection)?;
    gl.load_identity()?;
    gl.frustum(-0.6 * aspect, 0.6 * aspect, -0.6, 0.6, 1.0, 40.0)?;
    gl.matrix_mode(MatrixMode::Modelview)?;
    gl.load_identity()?;
    gl.translate(0.0, -1.2, -7.0)?;
    gl.rotate(18.0, 1.0, 0.0, 0.0)?;
    gl.rotate(-25.0, 0.0, 1.0, 0.0)?;
    gl.enable(Capability::DepthTest)?;
    gl.enable(Capability::CullFace)?;

    // 1. The mirror area of the floor into the stencil buffer only.
    gl.enable(Capability::StencilTest)?;
    gl.stencil_func(CompareFunc::Always, 1, 0xff)?;
    gl.stencil_op(StencilOp::Keep, StencilOp::Keep, StencilOp::Replace)?;
    gl.color_mask(false, false, false, false)?;
    gl.depth_mask(false)?;
    floor_quad(&mut gl, 2.5)?;
    gl.color_mask(true, true, true, true)?;
    gl.depth_mask(true)?;

    // 2. The reflected cubes, only where the mirror is.
    gl.stencil_func(CompareFunc::Equal, 1, 0xff)?;
    gl.stencil_op(StencilOp::Keep, StencilOp::Keep, StencilOp::Keep)?;
    gl.push_matrix()?;
    gl.scale(1.0, -1.0, 1.0)?;
    gl.cull_face(Face::Front)?;
    cubes(&mut gl)?;
    gl.cull_face(Face::Back)?;
    gl.pop_matrix()?;
    gl.disable(Capability::StencilTest)?;

    // 3. The checkered floor, blended over the reflection.
    // Color is blended; the stored alpha is kept (the sky wrote 1), so the
    // picture stays opaque.
    gl.enable(Capability::Blend)?;
    gl.blend_func_separate(
        BlendFactor::SrcAlpha,
        BlendFactor::OneMinusSrcAlpha,
        BlendFactor::Zero,
        BlendFactor::One,
    )?;
    checker_floor(&mut gl)?;
    gl.disable(Capability::Blend)?;

    // 4. The cubes, with their edges drawn as lines pulled forward by polygon offset.
    cubes(&mut gl)?;

    // 5. A translucent pane: blended, depth-tested, not writing depth.
    gl.enable(Capability::Blend)?;
    gl.depth_mask(false)?;
    gl.disable(Capability::CullFace)?;
    gl.shade_model(ShadeModel::Smooth)?;
    gl.begin(PrimitiveMode::Quads)?;
    gl.color4(0.3, 0.8, 1.0, 0.25);
    gl.vertex3(1.6, 0.0, 1.4);
    gl.color4(0.3, 0.8, 1.0, 0.45);
    gl.vertex3(3.0, 0.0, -0.2);
    gl.color4(0.9, 0.9, 1.0, 0.45);
    gl.vertex3(3.0, 2.2, -0.2);
    gl.color4(0.9, 0.9, 1.0, 0.25);
    gl.vertex3(1.6, 2.2, 1.4);
    gl.end()?;
    gl.depth_mask(true)?;
    gl.disable(Capability::Blend)?;
    Ok(gl)
}

/// A vertical gradient and a few stars, drawn without depth writes.
fn sky(gl: &mut Context) -> GlResult {
    gl.matrix_mode(MatrixMode::Projection)?;
    gl.load_identity()?;
    gl.matrix_mode(MatrixMode::Modelview)?;
    gl.load_identity()?;
    gl.depth_mask(false)?;
    gl.begin(PrimitiveMode::Quads)?;
    gl.color3(0.05, 0.05, 0.15);
    gl.vertex2(-1.0, 1.0);
    gl.vertex2(1.0, 1.0);
    gl.color3(0.35, 0.45, 0.7);
    gl.vertex2(1.0, -1.0);
    gl.vertex2(-1.0, -1.0);
    gl.end()?;
    gl.point_size(2.0)?;
    gl.begin(PrimitiveMode::Points)?;
    let mut rng = crate::rng::Rng::new(0x2545_f491);
    for _ in 0..60 {
        let seed = rng.next_u32();
        let x = (seed & 0xffff) as f32 / 32768.0 - 1.0;
        let y = ((seed >> 16) & 0xffff) as f32 / 65536.0 * 0.8 + 0.2;
        let b = 0.6 + 0.4 * y;
        gl.color3(b, b, b * 0.9);
        gl.vertex2(x, y);
    }
    gl.end()?;
    gl.point_size(1.0)?;
    gl.depth_mask(true)
}

fn floor_quad(gl: &mut Context, half: f32) -> GlResult {
    gl.begin(PrimitiveMode::Quads)?;
    gl.color4(1.0, 1.0, 1.0, 1.0);
    gl.vertex3(-half, 0.0, half);
    gl.vertex3(half, 0.0, half);
    gl.vertex3(half, 0.0, -half);
    gl.vertex3(-half, 0.0, -half);
    gl.end()
}

/// A 10 × 10 checkerboard; the inner 2.5-unit square is a translucent mirror.
fn checker_floor(gl: &mut Context) -> GlResult {
    gl.shade_model(ShadeModel::Flat)?;
    gl.begin(PrimitiveMode::Quads)?;
    for i in -5..5 {
        for j in -5..5 {
            let (x0, z0) = (i as f32, j as f32);
            let mirror = (-3..3).contains(&i) && (-3..3).contains(&j) && x0.abs() <= 2.5 && z0.abs() <= 2.5;
            let dark = (i + j) % 2 == 0;
            let alpha = if mirror { 0.55 } else { 1.0 };
            let (r, g, b) = if dark { (0.2, 0.22, 0.28) } else { (0.85, 0.83, 0.78) };
            gl.color4(r, g, b, alpha);
            let (x1, z1) = (x0 + 1.0, z0 + 1.0);
            let clip = |v: f32| if mirror { v.clamp(-2.5, 2.5) } else { v };
            gl.vertex3(clip(x0), 0.0, clip(z1));
            gl.vertex3(clip(x1), 0.0, clip(z1));
            gl.vertex3(clip(x1), 0.0, clip(z0));
            gl.vertex3(clip(x0), 0.0, clip(z0));
        }
    }
    gl.end()?;
    gl.shade_model(ShadeModel::Smooth)
}

/// Three cubes standing on the floor, faces smooth-shaded, edges outlined.
fn cubes(gl: &mut Context) -> GlResult {
    let placements = [(-1.3, 0.6, 0.4, 30.0), (0.9, 0.5, -0.9, -20.0), (0.2, 0.35, 1.3, 55.0)];
    for (k, &(x, size, z, angle)) in placements.iter().enumerate() {
        gl.push_matrix()?;
        gl.translate(x, size, z)?;
        gl.rotate(angle, 0.0, 1.0, 0.0)?;
        gl.scale(size, size, size)?;
        cube(gl, k)?;
        gl.enable(Capability::PolygonOffsetLine)?;
        gl.polygon_offset(-1.0, -2.0)?;
        gl.polygon_mode(Face::FrontAndBack, PolygonMode::Line)?;
        gl.color3(0.05, 0.05, 0.05);
        cube_faces(gl, None)?;
        gl.polygon_mode(Face::FrontAndBack, PolygonMode::Fill)?;
        gl.disable(Capability::PolygonOffsetLine)?;
        gl.pop_matrix()?;
    }
    Ok(())
}

const PALETTES: [[[f32; 3]; 2]; 3] = [
    [[0.95, 0.35, 0.2], [0.6, 0.1, 0.1]],
    [[0.25, 0.8, 0.35], [0.05, 0.35, 0.2]],
    [[0.95, 0.8, 0.25], [0.6, 0.35, 0.05]],
];

fn cube(gl: &mut Context, palette: usize) -> GlResult {
    cube_faces(gl, Some(PALETTES[palette % PALETTES.len()]))
}

/// The six faces of the unit cube `[-1, 1]³`, counter-clockwise from outside.
/// With `colors`, each face is shaded from the light to the dark color.
fn cube_faces(gl: &mut Context, colors: Option<[[f32; 3]; 2]>) -> GlResult {
    const FACES: [[[f32; 3]; 4]; 6] = [
        [[-1., -1., 1.], [1., -1., 1.], [1., 1., 1.], [-1., 1., 1.]],
        [[1., -1., -1.], [-1., -1., -1.], [-1., 1., -1.], [1., 1., -1.]],
        [[1., -1., 1.], [1., -1., -1.], [1., 1., -1.], [1., 1., 1.]],
        [[-1., -1., -1.], [-1., -1., 1.], [-1., 1., 1.], [-1., 1., -1.]],
        [[-1., 1., 1.], [1., 1., 1.], [1., 1., -1.], [-1., 1., -1.]],
        [[-1., -1., -1.], [1., -1., -1.], [1., -1., 1.], [-1., -1., 1.]],
    ];
    const SHADE: [f32; 6] = [1.0, 0.55, 0.8, 0.65, 1.0, 0.4];
    gl.begin(PrimitiveMode::Quads)?;
    for (f, face) in FACES.iter().enumerate() {
        for (i, v) in face.iter().enumerate() {
            if let Some([light, dark]) = colors {
                let t = if i < 2 { 0.0 } else { 1.0 };
                let c = [0, 1, 2].map(|k| (dark[k] + (light[k] - dark[k]) * t) * SHADE[f]);
                gl.color3(c[0], c[1], c[2]);
            }
            gl.vertex3(v[0], v[1], v[2]);
        }
    }
    gl.end()
}
