//! Texturing through the Rust API: what a draw carries for enabled,
//! disabled and incomplete units, exact pixels of magnified NEAREST textures
//! under REPLACE and MODULATE, coordinates from `glTexGen` and the texture
//! matrix, and the errors of the unit calls. Expected values are worked out
//! by hand next to each assertion.

mod common;

use softgl::geometry::varying::VaryingLayout;
use softgl::texture::{
    CombineFn, CombineSrc, EnvMode, Filter, InternalFormat, MipFilter, Operand, PixelData, PixelFormat, PixelStore,
    PixelType, TexImageTarget, TexParam, TextureTarget, Wrap,
};
use softgl::{
    Capability, Context, FramebufferDesc, GlError, MatrixMode, PrimitiveMode, TexCoordName, TexEnvParam,
    TexEnvParamName, TexGenMode, TexGenParam, TexGenParamName, VertexArrays,
};

const RED: [u8; 4] = [255, 0, 0, 255];
const GREEN: [u8; 4] = [0, 255, 0, 255];
const BLUE: [u8; 4] = [0, 0, 255, 255];
const WHITE: [u8; 4] = [255, 255, 255, 255];

fn context() -> Context {
    Context::new(FramebufferDesc::rgba8_d24s8(8, 8)).unwrap()
}

/// Uploads `texels` (RGBA8, rows bottom-up) as level 0 of a `w`×`h` 2D
/// texture on the active unit's bound texture.
fn upload_2d(gl: &mut Context, w: i32, h: i32, texels: &[[u8; 4]]) {
    let bytes: Vec<u8> = texels.iter().flatten().copied().collect();
    let pixels = PixelData {
        format: PixelFormat::Rgba,
        ty: PixelType::UnsignedByte,
        store: PixelStore::DEFAULT,
        bytes: &bytes,
    };
    gl.tex_image(TexImageTarget::D2, 0, InternalFormat::Rgba8, [w, h, 1], 0, Some(pixels))
        .unwrap();
}

/// [`upload_2d`], filtered NEAREST both ways, wrap `wrap`.
fn texture_2d(gl: &mut Context, w: i32, h: i32, texels: &[[u8; 4]], wrap: Wrap) {
    upload_2d(gl, w, h, texels);
    let t = TextureTarget::D2;
    gl.tex_parameter(t, TexParam::MinFilter(Filter::Nearest, MipFilter::None))
        .unwrap();
    gl.tex_parameter(t, TexParam::MagFilter(Filter::Nearest)).unwrap();
    gl.tex_parameter(t, TexParam::WrapS(wrap)).unwrap();
    gl.tex_parameter(t, TexParam::WrapT(wrap)).unwrap();
}

/// The 2×2 texture red, green (bottom row), blue, white (top row).
fn checker(gl: &mut Context) {
    texture_2d(gl, 2, 2, &[RED, GREEN, BLUE, WHITE], Wrap::ClampToEdge);
}

/// A context whose unit 0 samples [`checker`].
fn checker_enabled() -> Context {
    let mut gl = context();
    checker(&mut gl);
    gl.enable(Capability::Texture(TextureTarget::D2)).unwrap();
    gl
}

/// A quad over the whole 8×8 window with texture coordinates (0, 0)–(1, 1)
/// on unit 0, counter-clockwise from the bottom left.
fn textured_quad(gl: &mut Context) {
    gl.begin(PrimitiveMode::Quads).unwrap();
    for (x, y) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
        gl.tex_coord2((x + 1.0) / 2.0, (y + 1.0) / 2.0);
        gl.vertex2(x, y);
    }
    gl.end().unwrap();
}

/// The four 4×4 quadrants' colours: bottom left, bottom right, top left, top right.
fn quadrants(gl: &mut Context) -> [[u8; 4]; 4] {
    let fb = gl.framebuffer();
    let q = [(0, 0), (4, 0), (0, 4), (4, 4)].map(|(x0, y0)| {
        let c = fb.pixel(x0, y0).unwrap();
        for y in y0..y0 + 4 {
            for x in x0..x0 + 4 {
                assert_eq!(fb.pixel(x, y), Some(c), "pixel ({x}, {y}) differs within its quadrant");
            }
        }
        c
    });
    q
}

#[test]
fn a_disabled_or_incomplete_unit_adds_nothing_to_the_draw() {
    let mut gl = context();
    let plain = VaryingLayout {
        color: true,
        ..VaryingLayout::default()
    };
    let untextured = |gl: &mut Context| {
        let (key, layout) = gl.draw_plan();
        assert_eq!(layout, plain);
        assert_eq!(key.shade.unwrap().tex, [None; 8]);
    };
    untextured(&mut gl);
    // Enabled, but the default texture has no image: incomplete.
    gl.enable(Capability::Texture(TextureTarget::D2)).unwrap();
    untextured(&mut gl);
    // An image but the default minification filter wants mipmaps: still incomplete.
    upload_2d(&mut gl, 2, 2, &[WHITE; 4]);
    untextured(&mut gl);
    // Complete: unit 0 carries 4 slots after the colour, and has a key.
    gl.tex_parameter(TextureTarget::D2, TexParam::MinFilter(Filter::Linear, MipFilter::None))
        .unwrap();
    let (key, layout) = gl.draw_plan();
    assert_eq!(layout, VaryingLayout { tex: 1, ..plain });
    assert_eq!((layout.len(), layout.tex(0)), (8, Some(4)));
    let unit = key.shade.unwrap().tex[0].expect("unit 0 samples");
    assert_eq!(
        (unit.sampler.target, unit.sampler.min),
        (TextureTarget::D2, Filter::Linear)
    );
    assert_eq!(key.shade.unwrap().tex[1..], [None; 7]);
    // Texture generation enabled on a unit that samples nothing changes nothing.
    gl.active_texture(3).unwrap();
    gl.enable(Capability::TexGen(TexCoordName::S)).unwrap();
    assert_eq!(gl.draw_plan().1, VaryingLayout { tex: 1, ..plain });
    // Disabled again: nothing.
    gl.active_texture(0).unwrap();
    gl.disable(Capability::Texture(TextureTarget::D2)).unwrap();
    untextured(&mut gl);
    // No stage reads the colour (colour mask off, no alpha test): nothing either.
    gl.enable(Capability::Texture(TextureTarget::D2)).unwrap();
    gl.color_mask(false, false, false, false).unwrap();
    let (key, layout) = gl.draw_plan();
    assert_eq!(layout.tex, 0);
    assert!(key.shade.is_none_or(|s| s.tex == [None; 8]));
}

#[test]
fn the_first_complete_enabled_target_is_sampled() {
    let mut gl = checker_enabled();
    // An enabled cube map outranks 2D, but an incomplete one is passed over
    // (Mesa's update_ff_texture_state).
    gl.enable(Capability::Texture(TextureTarget::Cube)).unwrap();
    let unit = gl.draw_plan().0.shade.unwrap().tex[0].unwrap();
    assert_eq!(unit.sampler.target, TextureTarget::D2);
    assert!(gl.is_enabled(Capability::Texture(TextureTarget::Cube)));
    // Enables are per unit: unit 1 has none.
    gl.active_texture(1).unwrap();
    assert!(!gl.is_enabled(Capability::Texture(TextureTarget::D2)));
}

#[test]
fn nearest_magnification_replaces_with_the_texels() {
    let mut gl = checker_enabled();
    gl.tex_env(TexEnvParam::Mode(EnvMode::Replace)).unwrap();
    gl.color3(0.2, 0.4, 0.6);
    textured_quad(&mut gl);
    // Pixel x has s = (x + 0.5)/8: texel column 0 for x < 4, 1 from x = 4 on; rows alike.
    assert_eq!(quadrants(&mut gl), [RED, GREEN, BLUE, WHITE]);
}

#[test]
fn modulate_multiplies_the_colour_by_the_texels() {
    let mut gl = checker_enabled();
    // MODULATE is the default environment.
    assert_eq!(
        gl.get_tex_env(TexEnvParamName::Mode),
        Ok(TexEnvParam::Mode(EnvMode::Modulate))
    );
    gl.color4(0.2, 0.4, 0.6, 1.0);
    textured_quad(&mut gl);
    // 0.2·255 = 51, 0.4·255 = 102, 0.6·255 = 153; a texel channel of 255 keeps
    // the colour's, one of 0 zeroes it.
    assert_eq!(
        quadrants(&mut gl),
        [[51, 0, 0, 255], [0, 102, 0, 255], [0, 0, 153, 255], [51, 102, 153, 255]]
    );
}

/// A context whose unit `unit` (the active one) samples [`strip`] with REPLACE.
fn strip_on(unit: u32) -> Context {
    let mut gl = context();
    gl.active_texture(unit).unwrap();
    strip(&mut gl);
    gl
}

/// A 4×1 texture red, green, blue, white: s in [k/4, (k+1)/4) samples texel k.
fn strip(gl: &mut Context) {
    texture_2d(gl, 4, 1, &[RED, GREEN, BLUE, WHITE], Wrap::Repeat);
    gl.enable(Capability::Texture(TextureTarget::D2)).unwrap();
    gl.tex_env(TexEnvParam::Mode(EnvMode::Replace)).unwrap();
}

/// A quad over the window with texture coordinates (0, 0) everywhere.
fn quad_without_coordinates(gl: &mut Context) {
    let pos = [-1.0, -1.0, 1.0, -1.0, 1.0, 1.0, -1.0, 1.0];
    let zeros = [0.0f32; 8];
    let arrays = VertexArrays::positions(2, &pos).with_tex_coords(0, 2, &zeros);
    gl.draw_arrays(PrimitiveMode::Quads, 0, 4, &arrays).unwrap();
}

/// Generates S on the active unit in `mode` (object or eye linear) from `plane`.
fn generate_s(gl: &mut Context, mode: TexGenMode, plane: [f32; 4]) {
    gl.tex_gen(TexCoordName::S, TexGenParam::Mode(mode)).unwrap();
    let plane = match mode {
        TexGenMode::ObjectLinear => TexGenParam::ObjectPlane(plane),
        _ => TexGenParam::EyePlane(plane),
    };
    gl.tex_gen(TexCoordName::S, plane).unwrap();
    gl.enable(Capability::TexGen(TexCoordName::S)).unwrap();
}

/// The texels of the bottom row, left to right.
fn row(gl: &mut Context) -> Vec<[u8; 4]> {
    (0..8).map(|x| gl.framebuffer().pixel(x, 0).unwrap()).collect()
}

#[test]
fn object_linear_texgen_replaces_the_given_coordinates() {
    let mut gl = strip_on(0);
    // s = 0.5·x + 0.5 over x in [-1, 1]: pixel x has s = (x + 0.5)/8, texel floor(4s) = x/2.
    generate_s(&mut gl, TexGenMode::ObjectLinear, [0.5, 0.0, 0.0, 0.5]);
    quad_without_coordinates(&mut gl);
    assert_eq!(row(&mut gl), [RED, RED, GREEN, GREEN, BLUE, BLUE, WHITE, WHITE]);
}

#[test]
fn an_eye_plane_is_kept_in_the_eye_coordinates_of_its_modelview() {
    let mut gl = strip_on(0);
    // Given under a translation by -1 in x: the plane (0.25, 0, 0, 0.25) times the
    // inverse translation (+1) is (0.25, 0, 0, 0.5) in eye coordinates.
    gl.translate(-1.0, 0.0, 0.0).unwrap();
    generate_s(&mut gl, TexGenMode::EyeLinear, [0.25, 0.0, 0.0, 0.25]);
    assert_eq!(
        gl.get_tex_gen(TexCoordName::S, TexGenParamName::EyePlane),
        Ok(TexGenParam::EyePlane([0.25, 0.0, 0.0, 0.5]))
    );
    gl.load_identity().unwrap();
    quad_without_coordinates(&mut gl);
    // s = 0.25·x + 0.5 in [0.25, 0.75]: pixel x has s = (x + 0.5)/16 + 0.25, texel 1 then 2.
    assert_eq!(row(&mut gl), [GREEN, GREEN, GREEN, GREEN, BLUE, BLUE, BLUE, BLUE]);
}

#[test]
fn the_texture_matrix_transforms_the_coordinates() {
    let mut gl = strip_on(0);
    gl.matrix_mode(MatrixMode::Texture).unwrap();
    // s' = s/2 + 0.5: the right half of the strip spread over the window.
    gl.translate(0.5, 0.0, 0.0).unwrap();
    gl.scale(0.5, 1.0, 1.0).unwrap();
    gl.matrix_mode(MatrixMode::Modelview).unwrap();
    textured_quad(&mut gl);
    // Pixel x: s = (x + 0.5)/8, s' = (x + 0.5)/16 + 0.5, texel 2 for x < 4, 3 after.
    assert_eq!(row(&mut gl), [BLUE, BLUE, BLUE, BLUE, WHITE, WHITE, WHITE, WHITE]);
    // Unit 1's matrix is its own.
    gl.active_texture(1).unwrap();
    assert_eq!(gl.matrix(MatrixMode::Texture), glam::Mat4::IDENTITY);
}

#[test]
fn a_second_unit_reads_its_own_coordinates() {
    let mut gl = strip_on(1);
    gl.begin(PrimitiveMode::Quads).unwrap();
    for (x, y) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
        // Unit 0's coordinates run the other way and are not read.
        gl.tex_coord2((1.0 - x) / 2.0, 0.0);
        gl.multi_tex_coord(1, [(x + 1.0) / 2.0, 0.0, 0.0, 1.0]).unwrap();
        gl.vertex2(x, y);
    }
    gl.end().unwrap();
    assert_eq!(row(&mut gl), [RED, RED, GREEN, GREEN, BLUE, BLUE, WHITE, WHITE]);
    assert_eq!(gl.draw_plan().1.tex, 0b10);
}

#[test]
fn unit_calls_reject_what_gl_rejects() {
    let mut gl = context();
    assert_eq!(gl.tex_env(TexEnvParam::RgbScale(3.0)), Err(GlError::InvalidValue));
    assert_eq!(
        gl.tex_env(TexEnvParam::CombineAlpha(CombineFn::Dot3Rgb)),
        Err(GlError::InvalidEnum)
    );
    assert_eq!(
        gl.tex_env(TexEnvParam::OperandAlpha(0, Operand::SrcColor)),
        Err(GlError::InvalidEnum)
    );
    assert_eq!(
        gl.tex_env(TexEnvParam::SrcRgb(3, CombineSrc::Texture)),
        Err(GlError::InvalidEnum)
    );
    assert_eq!(
        gl.tex_gen(TexCoordName::R, TexGenParam::Mode(TexGenMode::SphereMap)),
        Err(GlError::InvalidEnum)
    );
    assert_eq!(
        gl.tex_gen(TexCoordName::Q, TexGenParam::Mode(TexGenMode::NormalMap)),
        Err(GlError::InvalidEnum)
    );
    assert_eq!(gl.multi_tex_coord(8, [0.0; 4]), Err(GlError::InvalidEnum));
    assert_eq!(gl.client_active_texture(8), Err(GlError::InvalidEnum));
    assert_eq!(gl.get_error(), Some(GlError::InvalidValue), "the first error is kept");
    // Nothing changed.
    assert_eq!(
        gl.get_tex_env(TexEnvParamName::RgbScale),
        Ok(TexEnvParam::RgbScale(1.0))
    );
    assert_eq!(
        gl.get_tex_gen(TexCoordName::R, TexGenParamName::Mode),
        Ok(TexGenParam::Mode(TexGenMode::EyeLinear))
    );
    // The colour is kept clamped, the unit's LOD bias as given.
    gl.tex_env(TexEnvParam::Color([2.0, -1.0, 0.5, 1.0])).unwrap();
    gl.tex_env(TexEnvParam::LodBias(-0.3)).unwrap();
    assert_eq!(
        gl.get_tex_env(TexEnvParamName::Color),
        Ok(TexEnvParam::Color([1.0, 0.0, 0.5, 1.0]))
    );
    assert_eq!(gl.get_tex_env(TexEnvParamName::LodBias), Ok(TexEnvParam::LodBias(-0.3)));
    // Inside begin/end only the coordinates may change.
    gl.begin(PrimitiveMode::Points).unwrap();
    assert_eq!(
        gl.tex_env(TexEnvParam::Mode(EnvMode::Add)),
        Err(GlError::InvalidOperation)
    );
    assert_eq!(gl.multi_tex_coord(2, [1.0, 2.0, 3.0, 4.0]), Ok(()));
    gl.end().unwrap();
    assert_eq!(gl.current().tex_coords[2], glam::Vec4::new(1.0, 2.0, 3.0, 4.0));
    // The texture matrix stack is 10 deep, per unit.
    gl.matrix_mode(MatrixMode::Texture).unwrap();
    for _ in 1..10 {
        gl.push_matrix().unwrap();
    }
    assert_eq!(gl.push_matrix(), Err(GlError::StackOverflow));
    assert_eq!(gl.matrix_depth(MatrixMode::Texture), 10);
    gl.active_texture(1).unwrap();
    assert_eq!(gl.matrix_depth(MatrixMode::Texture), 1);
    gl.client_active_texture(5).unwrap();
    assert_eq!(gl.tex_units().client_active(), 5);
}

#[test]
fn a_complete_texture_reaches_the_fragment_stage() {
    let mut gl = context();
    texture_2d(&mut gl, 2, 2, &[WHITE; 4], Wrap::Repeat);
    gl.color3(0.2, 0.4, 0.6);
    let quad = |gl: &mut Context| {
        gl.begin(PrimitiveMode::Quads).unwrap();
        for (x, y) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
            gl.vertex2(x, y);
        }
        gl.end().unwrap();
    };
    // Disabled: the colour, 0.2·255 = 51, 0.4·255 = 102, 0.6·255 = 153.
    quad(&mut gl);
    assert_eq!(gl.framebuffer().pixel(3, 3), Some([51, 102, 153, 255]));
    // REPLACE with a white RGBA texture: white everywhere.
    gl.enable(Capability::Texture(TextureTarget::D2)).unwrap();
    gl.tex_env(TexEnvParam::Mode(EnvMode::Replace)).unwrap();
    quad(&mut gl);
    assert_eq!(common::count(&mut gl, WHITE), 64);
    // MODULATE by white: the colour again.
    gl.tex_env(TexEnvParam::Mode(EnvMode::Modulate)).unwrap();
    quad(&mut gl);
    assert_eq!(common::count(&mut gl, [51, 102, 153, 255]), 64);
}

/// Texture coordinate scenes rendered by Mesa 22.3.6 llvmpipe
/// (`tests/llvmpipe/texgen.c`, which documents the keys) into
/// `tests/llvmpipe/texgen.txt`; [`replay`] draws the same through softgl.
/// Each is a bumpy grid textured NEAREST with a 16×16 random texture, so a
/// pixel's colour names the texel its coordinates fall in. The budget after
/// the name is the number of pixels allowed to differ (0: identical).
const SCENES: &[(&str, usize)] = &[
    ("plain rot=20", 0),
    ("obj gen_s=obj gen_t=obj os=0.5,0.25,0,0.5 ot=0,0.5,0.5,0.5 rot=20", 0),
    (
        "eye gen_s=eye gen_t=eye es=0.5,0,0.25,0.5 et=0,0.5,0,0.5 spec=30 rot=20",
        0,
    ),
    (
        "eye_q gen_s=eye gen_q=eye es=1,0,0,0.5 eq=0,0,-0.5,0 spec=-15 rot=35",
        0,
    ),
    ("sphere gen_s=sphere gen_t=sphere rot=25", 0),
    ("sphere_lit gen_s=sphere gen_t=sphere rot=25 light=1 env=modulate", 0),
    ("reflect gen_s=reflect gen_t=reflect gen_r=reflect rot=40", 0),
    ("normal gen_s=normal gen_t=normal rot=40", 0),
    ("matrix tm_rot=30 tm_scale=1.5 tm_tx=0.25 rot=10", 0),
    ("matrix_gen gen_s=obj os=0.25,0.5,0,0 tm_rot=-20 tm_scale=2 rot=10", 0),
    ("unit3 unit=3 gen_t=eye et=0,1,0,0 rot=15", 0),
    ("points prim=points gen_s=sphere gen_t=sphere rot=25", 0),
    (
        "lines prim=lines gen_s=obj gen_t=eye os=0.5,0,0,0.5 et=0,0.5,0,0.5 rot=25",
        0,
    ),
    // Eight times finer: 128 texel columns across the grid, so that a
    // coordinate an ulp off shows wherever it lands on a texel boundary.
    (
        "fine_sphere gen_s=sphere gen_t=sphere tm_scale=8 rot=25 light=1 env=modulate",
        0,
    ),
    (
        "fine_eye gen_s=eye gen_t=eye es=0.5,0,0.25,0.5 et=0,0.5,0,0.5 spec=30 tm_scale=8 rot=20",
        0,
    ),
    (
        "fine_reflect gen_s=reflect gen_t=reflect tm_rot=10 tm_scale=8 rot=40",
        0,
    ),
    ("fine_plain tm_scale=8 rot=50", 0),
    // The grid through the near plane: coordinates clipped with the colours.
    ("near_clip tz=-1.2 rot=35 tm_scale=4", 0),
    (
        "near_clip_sphere gen_s=sphere gen_t=sphere tz=-1.2 rot=35 tm_scale=4",
        0,
    ),
    // Client arrays, the coordinates of unit 2 through glClientActiveTexture.
    ("arrays arrays=1 unit=2 gen_t=obj ot=0,0.5,0.5,0.5 rot=20 tm_scale=4", 0),
];

/// Scene side in pixels (`N` of texgen.c).
const SCENE_N: u32 = 32;

/// The `key=value` words of a scene line.
fn scene_keys(line: &str) -> std::collections::HashMap<&str, &str> {
    line.split_whitespace()
        .skip(1)
        .filter_map(|w| w.split_once('='))
        .collect()
}

/// Draws the scene `line` into a new context, as texgen.c does.
fn replay(line: &str) -> Context {
    let k = scene_keys(line);
    let f = |key: &str, def: f32| k.get(key).map_or(def, |v| v.parse().unwrap());
    let mut gl = Context::new(FramebufferDesc::rgba8_d24s8(SCENE_N, SCENE_N)).unwrap();
    let unit = f("unit", 0.0) as u32;
    gl.active_texture(unit).unwrap();
    // texgen.c's LCG, alpha 255.
    let mut rnd: u32 = 12345;
    let mut texels = [[0u8; 4]; 256];
    for t in texels.iter_mut() {
        for c in t.iter_mut() {
            rnd = rnd.wrapping_mul(1_103_515_245).wrapping_add(12345);
            *c = (rnd >> 16) as u8;
        }
        t[3] = 255;
    }
    texture_2d(&mut gl, 16, 16, &texels, Wrap::Repeat);
    gl.enable(Capability::Texture(TextureTarget::D2)).unwrap();
    let env = match k.get("env") {
        Some(&"modulate") => EnvMode::Modulate,
        _ => EnvMode::Replace,
    };
    gl.tex_env(TexEnvParam::Mode(env)).unwrap();
    gl.matrix_mode(MatrixMode::Projection).unwrap();
    gl.frustum(-0.5, 0.5, -0.5, 0.5, 1.0, 10.0).unwrap();
    gl.matrix_mode(MatrixMode::Modelview).unwrap();
    gl.translate(0.25, 0.0, -1.0).unwrap();
    gl.rotate(f("spec", 0.0), 0.0, 1.0, 0.0).unwrap();
    for (c, name) in TexCoordName::ALL.into_iter().zip(["s", "t", "r", "q"]) {
        let Some(mode) = k.get(format!("gen_{name}").as_str()) else {
            continue;
        };
        let mode = match *mode {
            "obj" => TexGenMode::ObjectLinear,
            "eye" => TexGenMode::EyeLinear,
            "sphere" => TexGenMode::SphereMap,
            "reflect" => TexGenMode::ReflectionMap,
            _ => TexGenMode::NormalMap,
        };
        gl.tex_gen(c, TexGenParam::Mode(mode)).unwrap();
        let plane = |key: String| {
            k.get(key.as_str()).map(|v| {
                let p: Vec<f32> = v.split(',').map(|x| x.parse().unwrap()).collect();
                [p[0], p[1], p[2], p[3]]
            })
        };
        if let Some(p) = plane(format!("o{name}")) {
            gl.tex_gen(c, TexGenParam::ObjectPlane(p)).unwrap();
        }
        if let Some(p) = plane(format!("e{name}")) {
            gl.tex_gen(c, TexGenParam::EyePlane(p)).unwrap();
        }
        gl.enable(Capability::TexGen(c)).unwrap();
    }
    gl.matrix_mode(MatrixMode::Texture).unwrap();
    gl.translate(f("tm_tx", 0.0), 0.0, 0.0).unwrap();
    gl.rotate(f("tm_rot", 0.0), 0.0, 0.0, 1.0).unwrap();
    let sc = f("tm_scale", 1.0);
    gl.scale(sc, sc, 1.0).unwrap();
    gl.matrix_mode(MatrixMode::Modelview).unwrap();
    gl.load_identity().unwrap();
    gl.translate(0.0, 0.0, f("tz", -2.5)).unwrap();
    gl.rotate(f("rot", 0.0), 1.0, 0.5, 0.25).unwrap();
    gl.enable(Capability::Normalize).unwrap();
    gl.enable(Capability::DepthTest).unwrap();
    if f("light", 0.0) != 0.0 {
        gl.enable(Capability::Lighting).unwrap();
        gl.enable(Capability::Light(0)).unwrap();
    }
    gl.color4(0.75, 0.5, 1.0, 1.0);
    gl.point_size(2.0).unwrap();
    let vertex = |gl: &mut Context, i: i32, j: i32| {
        let (x, y) = (-1.0 + i as f32 / 4.0, -1.0 + j as f32 / 4.0);
        gl.normal3(-x / 2.0, y / 2.0, 1.0);
        gl.multi_tex_coord(unit, [(x + 1.0) / 2.0, (y + 1.0) / 2.0, 0.0, 1.0])
            .unwrap();
        gl.vertex3(x, y, (x * x - y * y) / 4.0);
    };
    match k.get("prim").copied().unwrap_or("tris") {
        "points" => {
            gl.begin(PrimitiveMode::Points).unwrap();
            for j in 0..=8 {
                for i in 0..=8 {
                    vertex(&mut gl, i, j);
                }
            }
            gl.end().unwrap();
        }
        "lines" => {
            for j in 0..=8 {
                gl.begin(PrimitiveMode::LineStrip).unwrap();
                for i in 0..=8 {
                    vertex(&mut gl, i, j);
                }
                gl.end().unwrap();
            }
        }
        _ if f("arrays", 0.0) != 0.0 => {
            let (mut pos, mut nrm, mut tc) = (Vec::new(), Vec::new(), Vec::new());
            for (i, j) in (0..8).flat_map(|j| (0..8).map(move |i| (i, j))) {
                for (di, dj) in [(0, 0), (1, 0), (1, 1), (0, 0), (1, 1), (0, 1)] {
                    let (x, y) = (-1.0 + (i + di) as f32 / 4.0, -1.0 + (j + dj) as f32 / 4.0);
                    pos.extend([x, y, (x * x - y * y) / 4.0]);
                    nrm.extend([-x / 2.0, y / 2.0, 1.0]);
                    tc.extend([(x + 1.0) / 2.0, (y + 1.0) / 2.0]);
                }
            }
            gl.client_active_texture(unit).unwrap();
            let unit = gl.tex_units().client_active();
            let arrays = VertexArrays {
                normal: Some(softgl::AttribArray::new(3, &nrm)),
                ..VertexArrays::positions(3, &pos).with_tex_coords(unit, 2, &tc)
            };
            gl.draw_arrays(PrimitiveMode::Triangles, 0, pos.len() / 3, &arrays)
                .unwrap();
        }
        _ => {
            gl.begin(PrimitiveMode::Triangles).unwrap();
            for j in 0..8 {
                for i in 0..8 {
                    for (di, dj) in [(0, 0), (1, 0), (1, 1), (0, 0), (1, 1), (0, 1)] {
                        vertex(&mut gl, i + di, j + dj);
                    }
                }
            }
            gl.end().unwrap();
        }
    }
    gl
}

/// llvmpipe's pixels of each scene (RGBA bytes, bottom row first), by name.
fn llvmpipe_scenes() -> std::collections::HashMap<String, Vec<u8>> {
    common::hex_scenes(include_str!("llvmpipe/texgen.txt"))
}

#[test]
fn texture_coordinates_match_llvmpipe() {
    let reference = llvmpipe_scenes();
    let mut report = Vec::new();
    for &(line, budget) in SCENES {
        let name = line.split_whitespace().next().unwrap();
        let want = reference
            .get(name)
            .unwrap_or_else(|| panic!("{name} missing from texgen.txt"));
        let mut gl = replay(line);
        let got = gl.framebuffer().color_bytes();
        assert_eq!(got.len(), want.len());
        let differ = got.chunks(4).zip(want.chunks(4)).filter(|(a, b)| a != b).count();
        // Every scene must draw: a blank image would pass trivially.
        let drawn = want.chunks(4).filter(|p| p[3] != 0).count();
        assert!(drawn > 100, "{name}: llvmpipe drew only {drawn} pixels");
        report.push(format!(
            "{name}: {differ} of {drawn} drawn pixels differ (budget {budget})"
        ));
        if differ > budget {
            panic!("{}", report.join("\n"));
        }
    }
    println!("{}", report.join("\n"));
}

/// Re-renders every scene with llvmpipe: needs gcc and Mesa's libOSMesa.
#[test]
#[ignore]
fn regenerate() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/llvmpipe");
    let (exe, scenes) = (
        std::env::temp_dir().join("softgl-texgen-probe"),
        std::env::temp_dir().join("softgl-texgen-scenes"),
    );
    let lines: String = SCENES.iter().map(|(l, _)| format!("{l}\n")).collect();
    std::fs::write(&scenes, lines).expect("write the scene lines");
    let mut gcc = std::process::Command::new("gcc");
    gcc.arg("-O1")
        .arg("-o")
        .arg(&exe)
        .arg(dir.join("texgen.c"))
        .arg("-lOSMesa");
    assert!(gcc.status().expect("gcc runs").success());
    let input = std::fs::File::open(&scenes).expect("the scene lines");
    let out = std::process::Command::new(&exe)
        .env("LP_NUM_THREADS", "1")
        .stdin(input)
        .output()
        .expect("the probe runs");
    assert!(out.status.success());
    std::fs::write(dir.join("texgen.txt"), out.stdout).expect("write texgen.txt");
}

#[test]
fn non_finite_coordinates_still_draw() {
    for (s, q) in [
        (f32::INFINITY, 1.0),
        (f32::NAN, 1.0),
        (1e30, 1.0),
        (0.5, 0.0),
        (-1e6, 1e-30),
    ] {
        let mut gl = strip_on(0);
        gl.begin(PrimitiveMode::Quads).unwrap();
        for (x, y) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
            gl.tex_coord4(s, 0.5, 0.0, q);
            gl.vertex2(x, y);
        }
        gl.end().unwrap();
        // The quad covers the window whatever its coordinates, and samples
        // texel 0 (red) everywhere: measured with llvmpipe for each case.
        assert_eq!(common::count(&mut gl, RED), 64, "s = {s}, q = {q}");
    }
}
