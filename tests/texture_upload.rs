//! Texture objects, uploads and readback through the Rust API, with values
//! computed by hand from the GL 1.5 specification (§3.6–3.8) and, for the
//! precision of each internal format, from Mesa 22.3.6 llvmpipe as probed
//! (`docs/llvmpipe-facts.md` §18).

use softgl::texture::{faces, PixelData, PixelStore, TexImageTarget, TexParam, TexParamName};
use softgl::{
    BaseFormat, Context, Filter, FramebufferDesc, GlError, InternalFormat, MipFilter, PixelFormat, PixelType,
    TexLevelParamName, TextureTarget, Wrap,
};

fn context() -> Context {
    Context::new(FramebufferDesc::rgba8_d24s8(8, 8)).unwrap()
}

fn data(format: PixelFormat, ty: PixelType, store: PixelStore, bytes: &[u8]) -> PixelData<'_> {
    PixelData {
        format,
        ty,
        store,
        bytes,
    }
}

fn packed(alignment: i32) -> PixelStore {
    PixelStore {
        alignment,
        ..PixelStore::default()
    }
}

/// The stored texels of `level` of the texture bound to 2D on unit 0.
fn texels(gl: &Context, level: usize) -> Vec<u8> {
    gl.textures()
        .bound(0, TextureTarget::D2)
        .image(level, 0)
        .expect("image")
        .texels
        .clone()
}

#[test]
fn names_bindings_and_deletion() {
    let mut gl = context();
    assert_eq!(gl.gen_textures(3).unwrap(), [1, 2, 3]);
    assert!(!gl.is_texture(1), "a generated name is a texture once bound");
    gl.bind_texture(TextureTarget::D2, 2).unwrap();
    assert!(gl.is_texture(2));
    assert_eq!(gl.texture_binding(0, TextureTarget::D2), 2);
    assert_eq!(gl.bind_texture(TextureTarget::D1, 2), Err(GlError::InvalidOperation));
    assert_eq!(gl.get_error(), Some(GlError::InvalidOperation));
    // A name never generated is created by binding; gen continues after the largest.
    gl.bind_texture(TextureTarget::Cube, 10).unwrap();
    assert_eq!(gl.gen_textures(1).unwrap(), [11]);
    gl.active_texture(3).unwrap();
    gl.bind_texture(TextureTarget::D2, 2).unwrap();
    assert_eq!(gl.active_texture_unit(), 3);
    gl.delete_textures(&[2, 99, 0]);
    assert!(!gl.is_texture(2));
    assert_eq!(gl.texture_binding(0, TextureTarget::D2), 0);
    assert_eq!(gl.texture_binding(3, TextureTarget::D2), 0);
    assert_eq!(gl.texture_binding(0, TextureTarget::Cube), 10);
    assert_eq!(gl.active_texture(8), Err(GlError::InvalidEnum));
    assert_eq!(gl.gen_textures(-1), Err(GlError::InvalidValue));
    // Deleted names are not reused (Mesa without name reuse).
    assert_eq!(gl.gen_textures(1).unwrap(), [12]);
    assert_eq!(gl.are_textures_resident(&[10, 12]), Ok(vec![true, true]));
    assert_eq!(gl.are_textures_resident(&[10, 2]), Err(GlError::InvalidValue));
}

/// A 3×2 RGB image with 4-byte row alignment: rows of 9 bytes padded to 12.
#[test]
fn rgb_bytes_with_row_padding_expand_to_rgba() {
    let mut gl = context();
    #[rustfmt::skip]
    let bytes = [
        1, 2, 3, 4, 5, 6, 7, 8, 9, 0xEE, 0xEE, 0xEE,
        10, 11, 12, 13, 14, 15, 16, 17, 18,
    ];
    let px = data(PixelFormat::Rgb, PixelType::UnsignedByte, packed(4), &bytes);
    gl.tex_image(TexImageTarget::D2, 0, InternalFormat::Rgb, [3, 2, 1], 0, Some(px))
        .unwrap();
    #[rustfmt::skip]
    assert_eq!(texels(&gl, 0), [
        1, 2, 3, 255, 4, 5, 6, 255, 7, 8, 9, 255,
        10, 11, 12, 255, 13, 14, 15, 255, 16, 17, 18, 255,
    ]);
    // One byte short of the last row: the data cannot hold the image.
    let px = data(PixelFormat::Rgb, PixelType::UnsignedByte, packed(4), &bytes[..20]);
    assert_eq!(
        gl.tex_image(TexImageTarget::D2, 0, InternalFormat::Rgb, [3, 2, 1], 0, Some(px)),
        Err(GlError::InvalidOperation)
    );
}

/// Each unsized base format from RGBA bytes: L, I take red; A takes alpha (GL 1.5 table 3.15).
#[test]
fn base_formats_expand_to_rgba_texels() {
    let rgba = [10u8, 20, 30, 40, 50, 60, 70, 80];
    let cases: [(InternalFormat, [u8; 8]); 6] = [
        (InternalFormat::Rgba, [10, 20, 30, 40, 50, 60, 70, 80]),
        (InternalFormat::Rgb, [10, 20, 30, 255, 50, 60, 70, 255]),
        (InternalFormat::Luminance, [10, 10, 10, 255, 50, 50, 50, 255]),
        (InternalFormat::LuminanceAlpha, [10, 10, 10, 40, 50, 50, 50, 80]),
        (InternalFormat::Alpha, [0, 0, 0, 40, 0, 0, 0, 80]),
        (InternalFormat::Intensity, [10, 10, 10, 10, 50, 50, 50, 50]),
    ];
    for (internal, want) in cases {
        let mut gl = context();
        let px = data(PixelFormat::Rgba, PixelType::UnsignedByte, packed(4), &rgba);
        gl.tex_image(TexImageTarget::D2, 0, internal, [2, 1, 1], 0, Some(px))
            .unwrap();
        assert_eq!(texels(&gl, 0), want, "{internal:?}");
    }
}

/// Client formats with fewer components: missing colour is 0, missing alpha 1;
/// luminance fills R, G and B.
#[test]
fn client_formats_fill_missing_components() {
    let cases: [(PixelFormat, &[u8], [u8; 4]); 8] = [
        (PixelFormat::Luminance, &[77], [77, 77, 77, 255]),
        (PixelFormat::LuminanceAlpha, &[77, 9], [77, 77, 77, 9]),
        (PixelFormat::Alpha, &[9], [0, 0, 0, 9]),
        (PixelFormat::Red, &[5], [5, 0, 0, 255]),
        (PixelFormat::Green, &[5], [0, 5, 0, 255]),
        (PixelFormat::Blue, &[5], [0, 0, 5, 255]),
        (PixelFormat::Bgr, &[1, 2, 3], [3, 2, 1, 255]),
        (PixelFormat::Bgra, &[1, 2, 3, 4], [3, 2, 1, 4]),
    ];
    for (format, bytes, want) in cases {
        let mut gl = context();
        let px = data(format, PixelType::UnsignedByte, packed(1), bytes);
        gl.tex_image(TexImageTarget::D2, 0, InternalFormat::Rgba8, [1, 1, 1], 0, Some(px))
            .unwrap();
        assert_eq!(texels(&gl, 0), want, "{format:?}");
    }
}

/// ROW_LENGTH, SKIP_ROWS and SKIP_PIXELS pick a 2×2 window out of a 4-wide luminance image.
#[test]
fn row_length_and_skips_select_a_window() {
    let mut gl = context();
    let bytes: Vec<u8> = (0..16).collect();
    let store = PixelStore {
        row_length: 4,
        skip_rows: 1,
        skip_pixels: 2,
        alignment: 1,
        ..PixelStore::default()
    };
    let px = data(PixelFormat::Luminance, PixelType::UnsignedByte, store, &bytes);
    gl.tex_image(
        TexImageTarget::D2,
        0,
        InternalFormat::Luminance8,
        [2, 2, 1],
        0,
        Some(px),
    )
    .unwrap();
    let l: Vec<u8> = texels(&gl, 0).chunks(4).map(|t| t[0]).collect();
    assert_eq!(l, [6, 7, 10, 11]);
}

#[test]
fn parameters_round_trip_and_bad_values_are_errors() {
    let mut gl = context();
    let t = TextureTarget::D2;
    assert_eq!(
        gl.get_tex_parameter(t, TexParamName::MinFilter),
        Ok(TexParam::MinFilter(Filter::Nearest, MipFilter::Linear))
    );
    assert_eq!(
        gl.get_tex_parameter(t, TexParamName::MagFilter),
        Ok(TexParam::MagFilter(Filter::Linear))
    );
    assert_eq!(
        gl.get_tex_parameter(t, TexParamName::MaxLevel),
        Ok(TexParam::MaxLevel(1000))
    );
    assert_eq!(
        gl.get_tex_parameter(t, TexParamName::MinLod),
        Ok(TexParam::MinLod(-1000.0))
    );
    gl.tex_parameter(t, TexParam::WrapT(Wrap::ClampToEdge)).unwrap();
    assert_eq!(
        gl.get_tex_parameter(t, TexParamName::WrapT),
        Ok(TexParam::WrapT(Wrap::ClampToEdge))
    );
    gl.tex_parameter(t, TexParam::Priority(3.0)).unwrap();
    assert_eq!(
        gl.get_tex_parameter(t, TexParamName::Priority),
        Ok(TexParam::Priority(1.0))
    );
    assert_eq!(gl.tex_parameter(t, TexParam::BaseLevel(-1)), Err(GlError::InvalidValue));
    assert_eq!(gl.tex_parameter(t, TexParam::MaxLevel(-1)), Err(GlError::InvalidValue));
    assert_eq!(gl.tex_parameter(t, TexParam::Resident(true)), Err(GlError::InvalidEnum));
    assert_eq!(
        gl.get_tex_parameter(t, TexParamName::Resident),
        Ok(TexParam::Resident(true))
    );
}

fn upload_rgba(gl: &mut Context, level: i32, size: [i32; 2], value: u8) {
    let n = (size[0] * size[1]) as usize * 4;
    let bytes = vec![value; n];
    let px = data(PixelFormat::Rgba, PixelType::UnsignedByte, packed(1), &bytes);
    gl.tex_image(
        TexImageTarget::D2,
        level,
        InternalFormat::Rgba8,
        [size[0], size[1], 1],
        0,
        Some(px),
    )
    .unwrap();
}

#[test]
fn completeness_needs_every_level_the_filter_samples() {
    let mut gl = context();
    assert!(gl.textures().sampling(0, TextureTarget::D2).is_none(), "no image");
    upload_rgba(&mut gl, 0, [4, 2], 1);
    // The default minification filter is NEAREST_MIPMAP_LINEAR: levels 1 (2×1) and 2 (1×1) are missing.
    assert!(gl.textures().sampling(0, TextureTarget::D2).is_none());
    upload_rgba(&mut gl, 1, [2, 1], 2);
    assert!(gl.textures().sampling(0, TextureTarget::D2).is_none());
    // A wrong size at level 2 keeps it incomplete.
    upload_rgba(&mut gl, 2, [2, 1], 3);
    assert!(gl.textures().sampling(0, TextureTarget::D2).is_none());
    upload_rgba(&mut gl, 2, [1, 1], 3);
    let s = gl.textures().sampling(0, TextureTarget::D2).expect("complete");
    assert_eq!((s.base_level, s.max_level, s.images.len()), (0, 2, 3));
    assert_eq!(s.images[1].texels, [2; 8]);
    assert_eq!(s.key.wrap, [Wrap::Repeat; 3]);
    assert_eq!(s.base, BaseFormat::Rgba);
    // MAX_LEVEL 1 needs levels 0 and 1 only.
    gl.tex_parameter(TextureTarget::D2, TexParam::MaxLevel(1)).unwrap();
    upload_rgba(&mut gl, 2, [2, 2], 3);
    assert_eq!(gl.textures().sampling(0, TextureTarget::D2).unwrap().max_level, 1);
    // A level of another internal format makes it incomplete.
    let px = data(PixelFormat::Rgba, PixelType::UnsignedByte, packed(1), &[0; 8]);
    gl.tex_image(TexImageTarget::D2, 1, InternalFormat::Rgb8, [2, 1, 1], 0, Some(px))
        .unwrap();
    assert!(gl.textures().sampling(0, TextureTarget::D2).is_none());
    // Without mipmaps only the base level counts.
    gl.tex_parameter(TextureTarget::D2, TexParam::MinFilter(Filter::Linear, MipFilter::None))
        .unwrap();
    assert_eq!(gl.textures().sampling(0, TextureTarget::D2).unwrap().max_level, 1);
    // BASE_LEVEL above MAX_LEVEL: incomplete.
    gl.tex_parameter(TextureTarget::D2, TexParam::BaseLevel(2)).unwrap();
    assert!(gl.textures().sampling(0, TextureTarget::D2).is_none());
    assert_eq!(faces(TextureTarget::Cube), 6);
}

#[test]
fn level_parameters_report_llvmpipe_sizes() {
    let mut gl = context();
    let px = data(PixelFormat::Rgba, PixelType::UnsignedByte, packed(4), &[0; 4 * 6]);
    gl.tex_image(TexImageTarget::D2, 0, InternalFormat::Rgb5A1, [3, 2, 1], 0, Some(px))
        .unwrap();
    let q = |gl: &mut Context, n| gl.get_tex_level_parameter(TexImageTarget::D2, 0, n).unwrap();
    assert_eq!(q(&mut gl, TexLevelParamName::Width), 3);
    assert_eq!(q(&mut gl, TexLevelParamName::Height), 2);
    assert_eq!(q(&mut gl, TexLevelParamName::Depth), 1);
    assert_eq!(q(&mut gl, TexLevelParamName::InternalFormat), 0x8057);
    assert_eq!(q(&mut gl, TexLevelParamName::RedSize), 5);
    assert_eq!(q(&mut gl, TexLevelParamName::AlphaSize), 1);
    assert_eq!(q(&mut gl, TexLevelParamName::LuminanceSize), 0);
    // A missing level: zeros, internal format GL_RGBA.
    let q1 = |gl: &mut Context, n| gl.get_tex_level_parameter(TexImageTarget::D2, 1, n).unwrap();
    assert_eq!(q1(&mut gl, TexLevelParamName::Width), 0);
    assert_eq!(q1(&mut gl, TexLevelParamName::InternalFormat), 0x1908);
}

/// Reads back every level of the 2D texture on unit 0 as RGBA bytes.
fn levels_rgba(gl: &mut Context, target: TexImageTarget, sizes: &[usize]) -> Vec<Vec<u8>> {
    sizes
        .iter()
        .enumerate()
        .map(|(level, &texels)| {
            let mut out = vec![0; texels * 4];
            gl.get_tex_image(
                target,
                level as i32,
                PixelFormat::Rgba,
                PixelType::UnsignedByte,
                &packed(1),
                &mut out,
            )
            .unwrap();
            out
        })
        .collect()
}

/// `glGenerateMipmap` of a 5×3 RGBA8 image: llvmpipe blits each level
/// bilinearly at `(i + 0.5) / size` (not a box filter), with its 8-bit
/// lerp. The expected levels are Mesa 22.3.6 llvmpipe's (`probe: mip.c`).
#[test]
fn generated_mipmaps_of_an_odd_size_equal_llvmpipes() {
    #[rustfmt::skip]
    let base = [
        238, 63, 28, 233, 228, 10, 104, 229, 222, 147, 141, 56, 156, 125, 189, 215, 91, 9, 212, 231,
        226, 51, 68, 63, 74, 140, 196, 161, 144, 214, 184, 184, 220, 97, 95, 209, 142, 40, 190, 89,
        14, 170, 80, 27, 80, 138, 106, 54, 41, 230, 112, 223, 85, 119, 186, 220, 68, 109, 67, 187,
    ];
    let mut gl = context();
    let px = data(PixelFormat::Rgba, PixelType::UnsignedByte, packed(1), &base);
    gl.tex_image(TexImageTarget::D2, 0, InternalFormat::Rgba8, [5, 3, 1], 0, Some(px))
        .unwrap();
    gl.generate_mipmap(TextureTarget::D2).unwrap();
    let levels = levels_rgba(&mut gl, TexImageTarget::D2, &[15, 2, 1]);
    assert_eq!(levels[1], [112, 118, 164, 137, 201, 83, 119, 179]);
    assert_eq!(levels[2], [157, 101, 142, 158]);
    // Level 3 does not exist: the chain ends at 1×1.
    assert_eq!(
        gl.get_tex_level_parameter(TexImageTarget::D2, 3, TexLevelParamName::Width),
        Ok(0)
    );
    assert!(gl.textures().sampling(0, TextureTarget::D2).is_some());
}

/// A 7×1 row: level 1 is 3×1, sampled at 7/6 · (i + 0.5) − 0.5.
#[test]
fn generated_mipmaps_of_a_row() {
    let base = [
        169, 8, 23, 214, 192, 246, 123, 8, 97, 112, 217, 45, 201, 18, 114, 91, 36, 126, 194, 226, 218, 177, 178, 4,
        158, 32, 128, 116,
    ];
    let mut gl = context();
    let px = data(PixelFormat::Rgba, PixelType::UnsignedByte, packed(1), &base);
    gl.tex_parameter(TextureTarget::D2, TexParam::GenerateMipmap(true))
        .unwrap();
    // GL_GENERATE_MIPMAP: the upload of the base level builds the chain.
    gl.tex_image(TexImageTarget::D2, 0, InternalFormat::Rgba8, [7, 1, 1], 0, Some(px))
        .unwrap();
    let levels = levels_rgba(&mut gl, TexImageTarget::D2, &[7, 3, 1]);
    assert_eq!(levels[1], [184, 167, 90, 76, 201, 18, 114, 91, 198, 129, 161, 41]);
    assert_eq!(levels[2], [201, 18, 114, 91]);
}

/// RGBA4: uploads round to 4 bits ((v·15 + 127) / 255), levels are blitted
/// from the 8-bit expansion and rounded back to 4 bits (Mesa llvmpipe's values).
#[test]
fn rgba4_uploads_and_mipmaps_quantize_like_llvmpipe() {
    #[rustfmt::skip]
    let base = [
        225, 243, 166, 236, 193, 244, 57, 67, 6, 192, 155, 98, 157, 227, 58, 211, 97, 239, 195, 83, 107, 208, 79,
        150, 31, 238, 77, 189, 243, 5, 45, 151, 254, 196, 209, 155, 69, 39, 180, 162, 196, 148, 216, 100, 62,
        184, 113, 185, 196, 31, 83, 139, 8, 149, 28, 158, 95, 64, 33, 255, 151, 122, 26, 77,
    ];
    let mut gl = context();
    let px = data(PixelFormat::Rgba, PixelType::UnsignedByte, packed(1), &base);
    gl.tex_image(TexImageTarget::D2, 0, InternalFormat::Rgba4, [4, 4, 1], 0, Some(px))
        .unwrap();
    gl.generate_mipmap(TextureTarget::D2).unwrap();
    let levels = levels_rgba(&mut gl, TexImageTarget::D2, &[16, 4, 1]);
    #[rustfmt::skip]
    assert_eq!(levels[0], [
        221, 238, 170, 238, 187, 238, 51, 68, 0, 187, 153, 102, 153, 221, 51, 204, 102, 238, 187, 85, 102, 204,
        85, 153, 34, 238, 85, 187, 238, 0, 51, 153, 255, 204, 204, 153, 68, 34, 187, 170, 204, 153, 221, 102, 68,
        187, 119, 187, 204, 34, 85, 136, 0, 153, 34, 153, 102, 68, 34, 255, 153, 119, 34, 85,
    ]);
    assert_eq!(
        levels[1],
        [153, 238, 119, 136, 102, 170, 85, 170, 136, 102, 136, 153, 136, 136, 102, 153]
    );
    assert_eq!(levels[2], [136, 170, 119, 153]);
}

/// A 3×3×3 volume reduces to one texel, trilinear at the centre (llvmpipe's value).
#[test]
fn generated_mipmaps_of_a_volume() {
    #[rustfmt::skip]
    let base = [
        0, 41, 65, 70, 111, 105, 205, 233, 157, 35, 192, 65, 116, 112, 29, 61, 233, 86, 161, 210, 12, 228, 176,
        115, 208, 17, 0, 79, 155, 85, 7, 78, 140, 5, 37, 201, 144, 111, 146, 11, 36, 185, 5, 140, 231, 122, 41,
        231, 231, 21, 193, 161, 168, 218, 149, 152, 243, 219, 36, 76, 101, 142, 8, 209, 179, 39, 39, 144, 190,
        179, 158, 193, 90, 244, 110, 169, 222, 0, 228, 147, 107, 152, 202, 143, 253, 73, 80, 237, 51, 68, 183,
        119, 222, 254, 195, 114, 75, 136, 222, 83, 81, 171, 12, 66, 25, 203, 146, 79,
    ];
    let mut gl = context();
    let px = data(PixelFormat::Rgba, PixelType::UnsignedByte, packed(1), &base);
    gl.tex_image(TexImageTarget::D3, 0, InternalFormat::Rgba8, [3, 3, 3], 0, Some(px))
        .unwrap();
    gl.generate_mipmap(TextureTarget::D3).unwrap();
    let levels = levels_rgba(&mut gl, TexImageTarget::D3, &[27, 1]);
    assert_eq!(levels[1], [168, 218, 149, 152]);
}
