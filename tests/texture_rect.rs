//! Rectangle textures (`GL_ARB_texture_rectangle`) through the Rust API: the
//! target's defaults, limits and errors (GL's, as Mesa 22.3.6 gives them:
//! `docs/llvmpipe-facts.md` §46), the enable priority, and exact pixels of
//! NEAREST sampling at unnormalized coordinates, worked out by hand. The C
//! client `osmesa/tests/c/texrect.c` compares the same against llvmpipe.

use softgl::texture::{PixelData, TexImageTarget, TexLevelParamName, TexParam, TexParamName};
use softgl::{
    Backend, Capability, Context, EnvMode, Filter, FramebufferDesc, GlError, InternalFormat, MipFilter, PrimitiveMode,
    TexEnvParam, TextureTarget, Wrap,
};

const R: TextureTarget = TextureTarget::Rect;

fn context(w: u32, h: u32) -> Context {
    Context::new(FramebufferDesc::rgba8_d24s8(w, h)).unwrap()
}

fn rgba(bytes: &[u8]) -> PixelData<'_> {
    PixelData::rgba8(bytes)
}

/// A `w`×`h` rectangle whose texel (x, y) is `[x, y, 7, 255]`.
fn coded(w: i32, h: i32) -> Vec<u8> {
    (0..h)
        .flat_map(|y| (0..w).flat_map(move |x| [x as u8, y as u8, 7, 255]))
        .collect()
}

#[test]
fn defaults_limits_and_errors_are_gls() {
    let mut gl = context(8, 8);
    let p = |gl: &mut Context, n| gl.get_tex_parameter(R, n).unwrap();
    assert_eq!(p(&mut gl, TexParamName::WrapS), TexParam::WrapS(Wrap::ClampToEdge));
    assert_eq!(p(&mut gl, TexParamName::WrapR), TexParam::WrapR(Wrap::ClampToEdge));
    assert_eq!(
        p(&mut gl, TexParamName::MinFilter),
        TexParam::MinFilter(Filter::Linear, MipFilter::None)
    );
    assert_eq!(p(&mut gl, TexParamName::MaxLevel), TexParam::MaxLevel(1000));
    assert_eq!(softgl::texture::api::MAX_RECTANGLE_TEXTURE_SIZE, 4096);

    let img = coded(37, 19);
    let t = TexImageTarget::Rect;
    gl.tex_image(t, 0, InternalFormat::Rgba8, [37, 19, 1], 0, Some(rgba(&img)))
        .unwrap();
    let level = |gl: &mut Context, l, n| gl.get_tex_level_parameter(t, l, n);
    assert_eq!(level(&mut gl, 0, TexLevelParamName::Width), Ok(37));
    assert_eq!(level(&mut gl, 0, TexLevelParamName::Height), Ok(19));
    // Level 0 only, no border, up to the maximum size.
    assert_eq!(level(&mut gl, 1, TexLevelParamName::Width), Err(GlError::InvalidValue));
    let e = |gl: &mut Context, level, size: [i32; 3], border| {
        gl.tex_image(t, level, InternalFormat::Rgba8, size, border, None)
    };
    assert_eq!(e(&mut gl, 1, [8, 8, 1], 0), Err(GlError::InvalidValue));
    assert_eq!(e(&mut gl, 0, [8, 8, 1], 1), Err(GlError::InvalidValue));
    assert_eq!(e(&mut gl, 0, [4097, 8, 1], 0), Err(GlError::InvalidValue));
    assert_eq!(e(&mut gl, 0, [4096, 1, 1], 0), Ok(()));
    // A proxy too large is cleared, not an error.
    let proxy = TexImageTarget::Proxy(R);
    gl.tex_image(proxy, 0, InternalFormat::Rgba8, [5000, 3, 1], 0, None)
        .unwrap();
    assert_eq!(gl.get_tex_level_parameter(proxy, 0, TexLevelParamName::Width), Ok(0));
    gl.tex_image(proxy, 0, InternalFormat::Rgba8, [4096, 3, 1], 0, None)
        .unwrap();
    assert_eq!(gl.get_tex_level_parameter(proxy, 0, TexLevelParamName::Width), Ok(4096));

    // Parameters: clamps only, no mipmap filter, base level 0, max level 0
    // (or the value it has).
    let set = |gl: &mut Context, v| gl.tex_parameter(R, v);
    assert_eq!(set(&mut gl, TexParam::WrapS(Wrap::Repeat)), Err(GlError::InvalidEnum));
    assert_eq!(
        set(&mut gl, TexParam::WrapT(Wrap::MirroredRepeat)),
        Err(GlError::InvalidEnum)
    );
    assert_eq!(set(&mut gl, TexParam::WrapR(Wrap::Repeat)), Err(GlError::InvalidEnum));
    assert_eq!(set(&mut gl, TexParam::WrapS(Wrap::Clamp)), Ok(()));
    assert_eq!(set(&mut gl, TexParam::WrapT(Wrap::ClampToBorder)), Ok(()));
    assert_eq!(
        set(&mut gl, TexParam::MinFilter(Filter::Linear, MipFilter::Linear)),
        Err(GlError::InvalidEnum)
    );
    assert_eq!(
        set(&mut gl, TexParam::MinFilter(Filter::Nearest, MipFilter::None)),
        Ok(())
    );
    assert_eq!(set(&mut gl, TexParam::BaseLevel(1)), Err(GlError::InvalidOperation));
    assert_eq!(set(&mut gl, TexParam::BaseLevel(-1)), Err(GlError::InvalidOperation));
    assert_eq!(set(&mut gl, TexParam::BaseLevel(0)), Ok(()));
    assert_eq!(set(&mut gl, TexParam::MaxLevel(1000)), Ok(()));
    assert_eq!(set(&mut gl, TexParam::MaxLevel(1)), Err(GlError::InvalidValue));
    assert_eq!(set(&mut gl, TexParam::MaxLevel(0)), Ok(()));
    assert_eq!(set(&mut gl, TexParam::MaxLevel(1000)), Err(GlError::InvalidValue));
    assert_eq!(set(&mut gl, TexParam::GenerateMipmap(true)), Ok(()));
    assert_eq!(gl.generate_mipmap(R), Err(GlError::InvalidEnum));
    // The 2D target keeps its own rules.
    assert_eq!(
        gl.tex_parameter(TextureTarget::D2, TexParam::WrapS(Wrap::Repeat)),
        Ok(())
    );
}

#[test]
fn the_rectangle_outranks_2d_and_yields_to_3d() {
    let mut gl = context(4, 4);
    let one = [9u8, 9, 9, 255];
    gl.tex_image(
        TexImageTarget::D2,
        0,
        InternalFormat::Rgba8,
        [1, 1, 1],
        0,
        Some(rgba(&one)),
    )
    .unwrap();
    gl.tex_parameter(TextureTarget::D2, TexParam::MinFilter(Filter::Nearest, MipFilter::None))
        .unwrap();
    let img = coded(3, 2);
    gl.tex_image(
        TexImageTarget::Rect,
        0,
        InternalFormat::Rgba8,
        [3, 2, 1],
        0,
        Some(rgba(&img)),
    )
    .unwrap();
    gl.enable(Capability::Texture(TextureTarget::D2)).unwrap();
    gl.enable(Capability::Texture(R)).unwrap();
    let target = |gl: &mut Context| gl.draw_plan().0.shade.unwrap().tex[0].unwrap().sampler.target;
    assert_eq!(target(&mut gl), R);
    gl.tex_image(
        TexImageTarget::D3,
        0,
        InternalFormat::Rgba8,
        [1, 1, 1],
        0,
        Some(rgba(&one)),
    )
    .unwrap();
    gl.tex_parameter(TextureTarget::D3, TexParam::MinFilter(Filter::Nearest, MipFilter::None))
        .unwrap();
    gl.enable(Capability::Texture(TextureTarget::D3)).unwrap();
    assert_eq!(target(&mut gl), TextureTarget::D3);
    gl.disable(Capability::Texture(TextureTarget::D3)).unwrap();
    assert_eq!(target(&mut gl), R);
    assert!(gl.is_enabled(Capability::Texture(R)));
}

/// A 5×3 rectangle drawn NEAREST over a 10×6 window with coordinates
/// (0, 0)–(5, 3): pixel (x, y) has s = (x + 0.5)/2, t = (y + 0.5)/2, so
/// texel (x/2, y/2); the same quad with coordinates (−2, −1)–(7, 4) clamps
/// to the edge texels.
#[test]
fn nearest_samples_at_unnormalized_coordinates() {
    for backend in [Backend::Interpreter, Backend::Jit] {
        let jit = backend == Backend::Jit;
        let mut gl = context(10, 6);
        gl.set_backend(backend);
        let img = coded(5, 3);
        gl.tex_image(
            TexImageTarget::Rect,
            0,
            InternalFormat::Rgba8,
            [5, 3, 1],
            0,
            Some(rgba(&img)),
        )
        .unwrap();
        gl.tex_parameter(R, TexParam::MinFilter(Filter::Nearest, MipFilter::None))
            .unwrap();
        gl.tex_parameter(R, TexParam::MagFilter(Filter::Nearest)).unwrap();
        gl.enable(Capability::Texture(R)).unwrap();
        gl.tex_env(TexEnvParam::Mode(EnvMode::Replace)).unwrap();
        let quad = |gl: &mut Context, s: [f32; 2], t: [f32; 2]| {
            gl.begin(PrimitiveMode::Quads).unwrap();
            for (x, y) in [(0, 0), (1, 0), (1, 1), (0, 1)] {
                gl.tex_coord2(s[x], t[y]);
                gl.vertex2([-1.0, 1.0][x], [-1.0, 1.0][y]);
            }
            gl.end().unwrap();
        };
        quad(&mut gl, [0.0, 5.0], [0.0, 3.0]);
        for y in 0..6 {
            for x in 0..10 {
                let want = [(x / 2) as u8, (y / 2) as u8, 7, 255];
                assert_eq!(gl.framebuffer().pixel(x, y), Some(want), "jit {jit}: ({x}, {y})");
            }
        }
        // s from −2 to 7 over 10 pixels: s = −2 + 0.9·(x + 0.5), clamped to texels 0..=4.
        quad(&mut gl, [-2.0, 7.0], [-1.0, 4.0]);
        for y in 0..6 {
            for x in 0..10 {
                let s = -2.0 + 0.9 * (x as f32 + 0.5);
                let t = -1.0 + (5.0 / 6.0) * (y as f32 + 0.5);
                let want = [s.floor().clamp(0.0, 4.0) as u8, t.floor().clamp(0.0, 2.0) as u8, 7, 255];
                assert_eq!(
                    gl.framebuffer().pixel(x, y),
                    Some(want),
                    "jit {jit}: clamped ({x}, {y})"
                );
            }
        }
    }
}
