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
        .to_vec()
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
    let view = s.texture_ref(0.0);
    assert_eq!((view.base_level, view.max_level, view.images.len()), (0, 2, 3));
    assert_eq!(s.images[1].texels, [2; 8]);
    assert_eq!(s.key.wrap, [Wrap::Repeat; 3]);
    assert_eq!(s.base, BaseFormat::Rgba);
    // MAX_LEVEL 1 needs levels 0 and 1 only.
    gl.tex_parameter(TextureTarget::D2, TexParam::MaxLevel(1)).unwrap();
    upload_rgba(&mut gl, 2, [2, 2], 3);
    assert_eq!(
        gl.textures()
            .sampling(0, TextureTarget::D2)
            .unwrap()
            .texture_ref(0.0)
            .max_level,
        1
    );
    // A level of another internal format makes it incomplete.
    let px = data(PixelFormat::Rgba, PixelType::UnsignedByte, packed(1), &[0; 8]);
    gl.tex_image(TexImageTarget::D2, 1, InternalFormat::Rgb8, [2, 1, 1], 0, Some(px))
        .unwrap();
    assert!(gl.textures().sampling(0, TextureTarget::D2).is_none());
    // Without mipmaps only the base level counts, and only it is handed to the sampler.
    gl.tex_parameter(TextureTarget::D2, TexParam::MinFilter(Filter::Linear, MipFilter::None))
        .unwrap();
    assert_eq!(
        gl.textures()
            .sampling(0, TextureTarget::D2)
            .unwrap()
            .texture_ref(0.0)
            .max_level,
        0
    );
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
    assert_eq!(q(&mut gl, TexLevelParamName::StencilSize), 0);
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

/// Uploads `base` (RGBA bytes) as level 0 of `target`, builds the mipmaps
/// (`glGenerateMipmap`, or `GL_GENERATE_MIPMAP` set before the upload) and
/// reads back the levels of `sizes` texels.
fn mipmaps(
    target: TexImageTarget,
    internal: InternalFormat,
    size: [i32; 3],
    base: &[u8],
    by_param: bool,
    sizes: &[usize],
) -> Vec<Vec<u8>> {
    let mut gl = context();
    let tt = target.texture_target();
    if by_param {
        gl.tex_parameter(tt, TexParam::GenerateMipmap(true)).unwrap();
    }
    let px = data(PixelFormat::Rgba, PixelType::UnsignedByte, packed(1), base);
    gl.tex_image(target, 0, internal, size, 0, Some(px)).unwrap();
    if !by_param {
        gl.generate_mipmap(tt).unwrap();
    }
    levels_rgba(&mut gl, target, sizes)
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
    // The fourth level read back is level 3, which does not exist: the chain ends at 1×1.
    let levels = mipmaps(
        TexImageTarget::D2,
        InternalFormat::Rgba8,
        [5, 3, 1],
        &base,
        false,
        &[15, 2, 1, 1],
    );
    assert_eq!(levels[1], [112, 118, 164, 137, 201, 83, 119, 179]);
    assert_eq!(levels[2], [157, 101, 142, 158]);
    assert_eq!(levels[3], [0; 4]);
}

/// A 7×1 row: level 1 is 3×1, sampled at 7/6 · (i + 0.5) − 0.5.
#[test]
fn generated_mipmaps_of_a_row() {
    let base = [
        169, 8, 23, 214, 192, 246, 123, 8, 97, 112, 217, 45, 201, 18, 114, 91, 36, 126, 194, 226, 218, 177, 178, 4,
        158, 32, 128, 116,
    ];
    // GL_GENERATE_MIPMAP: the upload of the base level builds the chain.
    let levels = mipmaps(
        TexImageTarget::D2,
        InternalFormat::Rgba8,
        [7, 1, 1],
        &base,
        true,
        &[7, 3, 1],
    );
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
    let levels = mipmaps(
        TexImageTarget::D2,
        InternalFormat::Rgba4,
        [4, 4, 1],
        &base,
        false,
        &[16, 4, 1],
    );
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
    let levels = mipmaps(
        TexImageTarget::D3,
        InternalFormat::Rgba8,
        [3, 3, 3],
        &base,
        false,
        &[27, 1],
    );
    assert_eq!(levels[1], [168, 218, 149, 152]);
}

/// The first texel of a 1×1 RGBA8 upload of `bytes` as `format`/`ty`.
fn one_texel(format: PixelFormat, ty: PixelType, swap: bool, bytes: &[u8]) -> Vec<u8> {
    let mut gl = context();
    let store = PixelStore {
        swap_bytes: swap,
        alignment: 1,
        ..PixelStore::default()
    };
    gl.tex_image(
        TexImageTarget::D2,
        0,
        InternalFormat::Rgba8,
        [1, 1, 1],
        0,
        Some(data(format, ty, store, bytes)),
    )
    .unwrap();
    texels(&gl, 0)
}

/// Each packed type's fields (GL 1.5 tables 3.8–3.11), first field to the
/// first component; fields widened to 8 bits by bit replication, 10-bit
/// fields narrowed by rounding ((x · 255 + 511) / 1023), as Mesa's
/// `_mesa_unorm_to_unorm`.
#[test]
#[expect(
    clippy::unusual_byte_groupings,
    reason = "binary literals grouped by the packed fields"
)]
fn packed_types_unpack_their_fields() {
    use PixelFormat::{Bgra, Rgb, Rgba};
    use PixelType as T;
    let u16b = |v: u16| v.to_ne_bytes().to_vec();
    let u32b = |v: u32| v.to_ne_bytes().to_vec();
    let cases: Vec<(PixelFormat, PixelType, Vec<u8>, [u8; 4])> = vec![
        // 3-3-2: R = 7, G = 0, B = 3 → 255, 0, 255.
        (Rgb, T::UnsignedByte332, vec![0b111_000_11], [255, 0, 255, 255]),
        // R = 1 (3 bits) → 36 + 1 >> 1 = 36; G = 2 → 73; B = 1 (2 bits) → 85.
        (Rgb, T::UnsignedByte332, vec![0b001_010_01], [36, 73, 85, 255]),
        // 2-3-3 REV: R in the low 3 bits.
        (Rgb, T::UnsignedByte233Rev, vec![0b01_010_001], [36, 73, 85, 255]),
        // 5-6-5: R = 1 → 8, G = 1 → 4, B = 31 → 255.
        (Rgb, T::UnsignedShort565, u16b(0b00001_000001_11111), [8, 4, 255, 255]),
        (
            Rgb,
            T::UnsignedShort565Rev,
            u16b(0b11111_000001_00001),
            [8, 4, 255, 255],
        ),
        // 4-4-4-4: 0x1234 → 17, 34, 51, 68; REV reads from the low nibble.
        (Rgba, T::UnsignedShort4444, u16b(0x1234), [17, 34, 51, 68]),
        (Rgba, T::UnsignedShort4444Rev, u16b(0x1234), [68, 51, 34, 17]),
        // BGRA: the first field is blue.
        (Bgra, T::UnsignedShort4444, u16b(0x1234), [51, 34, 17, 68]),
        // 5-5-5-1: R = 1, G = 2, B = 3, A = 1 → 8, 16, 24, 255.
        (
            Rgba,
            T::UnsignedShort5551,
            u16b(0b00001_00010_00011_1),
            [8, 16, 24, 255],
        ),
        (
            Rgba,
            T::UnsignedShort1555Rev,
            u16b(0b1_00011_00010_00001),
            [8, 16, 24, 255],
        ),
        (Rgba, T::UnsignedInt8888, u32b(0x1122_3344), [0x11, 0x22, 0x33, 0x44]),
        (Rgba, T::UnsignedInt8888Rev, u32b(0x1122_3344), [0x44, 0x33, 0x22, 0x11]),
        // 10-10-10-2: R = 1023 → 255, G = 512 → (512 · 255 + 511) / 1023 = 128, B = 1 → 0, A = 2 → 170.
        (
            Rgba,
            T::UnsignedInt1010102,
            u32b(1023 << 22 | 512 << 12 | 1 << 2 | 2),
            [255, 128, 0, 170],
        ),
        (
            Rgba,
            T::UnsignedInt2101010Rev,
            u32b(2 << 30 | 1 << 20 | 512 << 10 | 1023),
            [255, 128, 0, 170],
        ),
    ];
    for (format, ty, bytes, want) in cases {
        assert_eq!(
            one_texel(format, ty, false, &bytes),
            want,
            "{format:?} {ty:?} {bytes:?}"
        );
    }
    // SWAP_BYTES reverses each 2- or 4-byte element.
    assert_eq!(
        one_texel(Rgba, T::UnsignedShort4444, true, &0x3412u16.to_ne_bytes()),
        [17, 34, 51, 68]
    );
    assert_eq!(
        one_texel(Rgba, T::UnsignedInt8888, true, &0x4433_2211u32.to_ne_bytes()),
        [0x11, 0x22, 0x33, 0x44]
    );
}

/// Plain types into unorm8 (Mesa `util/format/format_utils.h`): unsigned
/// narrowing rounds, (x · 255 + half) / max; signed values below 0 are 0 and
/// others use their 7, 15 or 31 value bits widened by replication or
/// narrowed by rounding; floats clamp and round to nearest even.
#[test]
fn plain_types_convert_like_mesa() {
    use PixelFormat::Rgba;
    use PixelType as T;
    let bytes =
        |v: &[i64], size: usize| -> Vec<u8> { v.iter().flat_map(|&x| x.to_ne_bytes()[..size].to_vec()).collect() };
    // BYTE: 127 → 2·127 + 127>>6 = 255; 64 → 129; −5 → 0; 1 → 2.
    assert_eq!(
        one_texel(Rgba, T::Byte, false, &bytes(&[127, 64, -5, 1], 1)),
        [255, 129, 0, 2]
    );
    // UNSIGNED_SHORT: 0x8080 → 128; 0xFFFF → 255; 0x0080 → 0; 0x0081 → 1.
    assert_eq!(
        one_texel(Rgba, T::UnsignedShort, false, &bytes(&[0x8080, 0xFFFF, 0x80, 0x81], 2)),
        [128, 255, 0, 1]
    );
    // SHORT: 16384 → 128; 32767 → 255; −1 → 0; 64 → 0 ((64·255 + 16383) / 32767).
    assert_eq!(
        one_texel(Rgba, T::Short, false, &bytes(&[16384, 32767, -1, 64], 2)),
        [128, 255, 0, 0]
    );
    // UNSIGNED_INT and INT: the top bits.
    assert_eq!(
        one_texel(
            Rgba,
            T::UnsignedInt,
            false,
            &bytes(&[0x8000_0000, 0xFFFF_FFFF, 0, 0x0100_0000], 4)
        ),
        [128, 255, 0, 1]
    );
    assert_eq!(
        one_texel(Rgba, T::Int, false, &bytes(&[1 << 30, i32::MAX as i64, -7, 1 << 23], 4)),
        [128, 255, 0, 1]
    );
    // FLOAT: 0.5 · 255 = 127.5 → 128 (even); 0.25 → 63.75 → 64; −1 → 0; 2 → 255.
    let f: Vec<u8> = [0.5f32, 0.25, -1.0, 2.0].iter().flat_map(|v| v.to_ne_bytes()).collect();
    assert_eq!(one_texel(Rgba, T::Float, false, &f), [128, 64, 0, 255]);
    let f: Vec<u8> = [1.5f32 / 255.0, 2.5 / 255.0, f32::NAN, 1.0]
        .iter()
        .flat_map(|v| v.to_ne_bytes())
        .collect();
    assert_eq!(one_texel(Rgba, T::Float, false, &f), [2, 2, 0, 255]);
}

/// Every type with padding: 3×2 pixels of 3 components, 8-byte alignment,
/// row length 5, one skipped row and pixel. Each row starts at a multiple of
/// the aligned stride; the texels must be the picked values, whatever the type.
#[test]
fn every_plain_type_honours_alignment_row_length_and_skips() {
    use PixelType as T;
    for ty in [
        T::UnsignedByte,
        T::Byte,
        T::UnsignedShort,
        T::Short,
        T::UnsignedInt,
        T::Int,
        T::Float,
    ] {
        let size: usize = match ty {
            T::UnsignedByte | T::Byte => 1,
            T::UnsignedShort | T::Short => 2,
            _ => 4,
        };
        let store = PixelStore {
            row_length: 5,
            skip_rows: 1,
            skip_pixels: 1,
            alignment: 8,
            ..PixelStore::default()
        };
        // 5 pixels × 3 components × size, padded to a multiple of 8.
        let stride = (15 * size).next_multiple_of(8);
        let mut bytes = vec![0xA5u8; stride * 3];
        // The value of component c of pixel (x, y): (1 + x + 3y + c) / 16 of full scale.
        let full = |v: u8| -> Vec<u8> {
            match ty {
                T::UnsignedByte => vec![v * 16],
                T::Byte => vec![v * 8],
                T::UnsignedShort => (u16::from(v) * 4096).to_ne_bytes().to_vec(),
                T::Short => (i16::from(v) * 2048).to_ne_bytes().to_vec(),
                T::UnsignedInt => (u32::from(v) << 28).to_ne_bytes().to_vec(),
                T::Int => (i32::from(v) << 27).to_ne_bytes().to_vec(),
                _ => (f32::from(v) / 16.0).to_ne_bytes().to_vec(),
            }
        };
        for y in 0..2usize {
            for x in 0..3usize {
                for c in 0..3usize {
                    let at = (y + 1) * stride + ((x + 1) * 3 + c) * size;
                    bytes[at..at + size].copy_from_slice(&full((1 + x + 3 * y + c) as u8));
                }
            }
        }
        let mut gl = context();
        let px = data(PixelFormat::Rgb, ty, store, &bytes);
        gl.tex_image(TexImageTarget::D2, 0, InternalFormat::Rgb8, [3, 2, 1], 0, Some(px))
            .unwrap();
        let got: Vec<u8> = texels(&gl, 0).chunks(4).flat_map(|t| t[..3].to_vec()).collect();
        // v/16 of full scale in 8 bits, as each type's conversion rounds it.
        let want: Vec<u8> = (0..2)
            .flat_map(|y| (0..3).flat_map(move |x| (0..3).map(move |c| (1 + x + 3 * y + c) as u32)))
            .map(|v| match ty {
                T::UnsignedByte => v * 16,
                // 7 value bits widened: 2x + x>>6 (x = 8v).
                T::Byte => 16 * v + ((8 * v) >> 6),
                T::UnsignedShort => (v * 4096 * 255 + 32767) / 65535,
                T::Short => (v * 2048 * 255 + 16383) / 32767,
                T::UnsignedInt => ((u64::from(v) << 28) * 255 + 0x7FFF_FFFF).div_euclid(0xFFFF_FFFF) as u32,
                T::Int => ((u64::from(v) << 27) * 255 + 0x3FFF_FFFF).div_euclid(0x7FFF_FFFF) as u32,
                _ => (v as f32 / 16.0 * 255.0).round_ties_even() as u32,
            } as u8)
            .collect();
        assert_eq!(got, want, "{ty:?}");
    }
}

/// What each internal format keeps of an 8-bit value, read back as
/// UNSIGNED_SHORT: the values Mesa 22.3.6 llvmpipe returns (probe `fmts.c`,
/// §18): 4-bit channels keep (v·15 + 127)/255, 5-bit (v·31 + 127)/255, …
#[test]
fn internal_formats_quantize_like_llvmpipe() {
    // (format, channel read, [(8-bit value, 16-bit readback)]).
    type Case = (InternalFormat, usize, &'static [(u8, u16)]);
    let cases: [Case; 10] = [
        (
            InternalFormat::Rgba4,
            0,
            &[(8, 0), (9, 4369), (127, 30583), (128, 34952), (254, 65535)],
        ),
        (InternalFormat::Rgba2, 0, &[(8, 0), (9, 4369), (200, 52428)]),
        (
            InternalFormat::Rgb5,
            0,
            &[(1, 0), (8, 2114), (127, 31710), (128, 33825), (200, 50737)],
        ),
        (
            InternalFormat::R3G3B2,
            0,
            &[(17, 0), (127, 28086), (128, 37449), (200, 46811)],
        ),
        (InternalFormat::R3G3B2, 2, &[(127, 21845), (128, 43690)]),
        (
            InternalFormat::Rgb10,
            0,
            &[(1, 256), (8, 2050), (128, 32928), (200, 51441), (254, 65279)],
        ),
        (InternalFormat::Rgb10A2, 3, &[(127, 21845), (128, 43690), (254, 65535)]),
        (InternalFormat::Rgb5A1, 3, &[(127, 0), (128, 65535)]),
        (InternalFormat::Luminance4Alpha4, 0, &[(8, 0), (9, 4369), (200, 52428)]),
        (InternalFormat::Rgba16, 1, &[(1, 257), (200, 51400)]),
    ];
    for (internal, c, values) in cases {
        for &(v, want) in values {
            let mut gl = context();
            let bytes = [v; 4];
            let px = data(PixelFormat::Rgba, PixelType::UnsignedByte, packed(1), &bytes);
            gl.tex_image(TexImageTarget::D2, 0, internal, [1, 1, 1], 0, Some(px))
                .unwrap();
            let mut out = [0u8; 8];
            gl.get_tex_image(
                TexImageTarget::D2,
                0,
                PixelFormat::Rgba,
                PixelType::UnsignedShort,
                &packed(1),
                &mut out,
            )
            .unwrap();
            let got = u16::from_ne_bytes([out[2 * c], out[2 * c + 1]]);
            assert_eq!(got, want, "{internal:?} channel {c} of {v}");
        }
    }
    // The sizes GL_TEXTURE_*_SIZE reports (Mesa's choice on llvmpipe).
    let sizes = [
        (InternalFormat::Alpha4, TexLevelParamName::AlphaSize, 8),
        (InternalFormat::Alpha12, TexLevelParamName::AlphaSize, 16),
        (InternalFormat::Luminance6Alpha2, TexLevelParamName::LuminanceSize, 8),
        (InternalFormat::Luminance4Alpha4, TexLevelParamName::LuminanceSize, 4),
        (InternalFormat::Intensity12, TexLevelParamName::IntensitySize, 16),
        (InternalFormat::Rgba2, TexLevelParamName::RedSize, 4),
        (InternalFormat::R3G3B2, TexLevelParamName::BlueSize, 2),
        (InternalFormat::Rgb12, TexLevelParamName::GreenSize, 16),
        (InternalFormat::Srgb8Alpha8, TexLevelParamName::AlphaSize, 8),
        (InternalFormat::One, TexLevelParamName::LuminanceSize, 8),
        (InternalFormat::Three, TexLevelParamName::RedSize, 8),
        (InternalFormat::Three, TexLevelParamName::AlphaSize, 0),
    ];
    for (internal, name, want) in sizes {
        let mut gl = context();
        let px = data(PixelFormat::Rgba, PixelType::UnsignedByte, packed(1), &[0; 4]);
        gl.tex_image(TexImageTarget::D2, 0, internal, [1, 1, 1], 0, Some(px))
            .unwrap();
        assert_eq!(
            gl.get_tex_level_parameter(TexImageTarget::D2, 0, name),
            Ok(want),
            "{internal:?} {name:?}"
        );
    }
}

/// Depth textures from floats i/255, read back as UNSIGNED_INT (Mesa's values, probe `fmts.c`).
#[test]
fn depth_textures_quantize_like_llvmpipe() {
    let cases = [
        (
            InternalFormat::DepthComponent,
            [0u32, 16843009, 2139062143, 2155905279, 4294967295],
        ),
        (
            InternalFormat::DepthComponent24,
            [0, 16843009, 2139062143, 2155905279, 4294967295],
        ),
        (
            InternalFormat::DepthComponent16,
            [0, 16843007, 2139062143, 2155905023, 4294967295],
        ),
    ];
    let depths: Vec<u8> = [0.0f32, 1.0 / 255.0, 127.0 / 255.0, 128.0 / 255.0, 1.0]
        .iter()
        .flat_map(|v| v.to_ne_bytes())
        .collect();
    for (internal, want) in cases {
        let mut gl = context();
        let px = data(PixelFormat::DepthComponent, PixelType::Float, packed(4), &depths);
        gl.tex_image(TexImageTarget::D2, 0, internal, [5, 1, 1], 0, Some(px))
            .unwrap();
        let mut out = [0u8; 20];
        let r = gl.get_tex_image(
            TexImageTarget::D2,
            0,
            PixelFormat::DepthComponent,
            PixelType::UnsignedInt,
            &packed(4),
            &mut out,
        );
        r.unwrap();
        let got: Vec<u32> = out
            .chunks(4)
            .map(|c| u32::from_ne_bytes([c[0], c[1], c[2], c[3]]))
            .collect();
        assert_eq!(got, want, "{internal:?}");
        let s = gl.textures().sampling(0, TextureTarget::D2);
        assert!(s.is_none(), "mipmap filter without levels: incomplete");
    }
}

/// glGetTexImage: luminance reads back as (L, 0, 0, 1) in RGBA, and an RGBA
/// texture packed as LUMINANCE gives its red (Mesa's `texgetimage.c`).
#[test]
fn readback_rebases_luminance_and_packs_red_as_luminance() {
    let mut gl = context();
    let px = data(PixelFormat::Rgba, PixelType::UnsignedByte, packed(1), &[10, 20, 30, 40]);
    gl.tex_image(
        TexImageTarget::D2,
        0,
        InternalFormat::LuminanceAlpha,
        [1, 1, 1],
        0,
        Some(px),
    )
    .unwrap();
    let mut out = [0u8; 4];
    gl.get_tex_image(
        TexImageTarget::D2,
        0,
        PixelFormat::Rgba,
        PixelType::UnsignedByte,
        &packed(1),
        &mut out,
    )
    .unwrap();
    assert_eq!(out, [10, 0, 0, 40]);
    gl.tex_image(TexImageTarget::D2, 0, InternalFormat::Rgba8, [1, 1, 1], 0, Some(px))
        .unwrap();
    let mut out = [0u8; 2];
    gl.get_tex_image(
        TexImageTarget::D2,
        0,
        PixelFormat::LuminanceAlpha,
        PixelType::UnsignedByte,
        &packed(1),
        &mut out,
    )
    .unwrap();
    assert_eq!(out, [10, 40]);
    // BGR with a pack row length of 2 and alignment 4: the second pixel lands at byte 3.
    let px = data(
        PixelFormat::Rgba,
        PixelType::UnsignedByte,
        packed(1),
        &[1, 2, 3, 4, 5, 6, 7, 8],
    );
    gl.tex_image(TexImageTarget::D2, 0, InternalFormat::Rgb8, [1, 2, 1], 0, Some(px))
        .unwrap();
    let pack = PixelStore {
        row_length: 2,
        alignment: 4,
        ..PixelStore::default()
    };
    let mut out = [0xEEu8; 11];
    gl.get_tex_image(
        TexImageTarget::D2,
        0,
        PixelFormat::Bgr,
        PixelType::UnsignedByte,
        &pack,
        &mut out,
    )
    .unwrap();
    // Rows 6 bytes → 8 with alignment 4.
    assert_eq!(out, [3, 2, 1, 0xEE, 0xEE, 0xEE, 0xEE, 0xEE, 7, 6, 5]);
}

/// GL errors in Mesa 22.3.6's order and kind (each case checked against Mesa
/// with the probe `err.c`); an erroneous call changes nothing.
#[test]
fn errors_are_mesas() {
    use GlError::{InvalidEnum as Enum, InvalidOperation as Op, InvalidValue as Value};
    let mut gl = context();
    let px = [0u8; 4096];
    let rgba = |bytes: &[u8]| {
        data(
            PixelFormat::Rgba,
            PixelType::UnsignedByte,
            packed(1),
            &px[..bytes.len()],
        )
    };
    let img = |gl: &mut Context, t, level, internal, size: [i32; 3], border, p: Option<PixelData<'_>>| {
        gl.tex_image(t, level, internal, size, border, p)
    };
    let d2 = TexImageTarget::D2;
    assert_eq!(
        img(&mut gl, d2, -1, InternalFormat::Rgba, [1, 1, 1], 0, Some(rgba(&px))),
        Err(Value)
    );
    assert_eq!(
        img(&mut gl, d2, 13, InternalFormat::Rgba, [1, 1, 1], 0, Some(rgba(&px))),
        Err(Value)
    );
    assert_eq!(
        img(&mut gl, d2, 0, InternalFormat::Rgba, [1, 1, 1], 2, Some(rgba(&px))),
        Err(Value)
    );
    assert_eq!(
        img(&mut gl, d2, 0, InternalFormat::Rgba, [-1, 1, 1], 0, Some(rgba(&px))),
        Err(Value)
    );
    // Border 1 needs at least 2 texels a side.
    assert_eq!(
        img(&mut gl, d2, 0, InternalFormat::Rgba, [1, 3, 1], 1, Some(rgba(&px))),
        Err(Value)
    );
    let depth = data(PixelFormat::DepthComponent, PixelType::Float, packed(1), &px);
    assert_eq!(
        img(
            &mut gl,
            d2,
            0,
            InternalFormat::DepthComponent,
            [1, 1, 1],
            0,
            Some(rgba(&px))
        ),
        Err(Op)
    );
    assert_eq!(
        img(&mut gl, d2, 0, InternalFormat::Rgba, [1, 1, 1], 0, Some(depth)),
        Err(Op)
    );
    let p565 = data(PixelFormat::Rgba, PixelType::UnsignedShort565, packed(1), &px);
    assert_eq!(
        img(&mut gl, d2, 0, InternalFormat::Rgba, [1, 1, 1], 0, Some(p565)),
        Err(Op)
    );
    // The level is checked first.
    assert_eq!(
        img(&mut gl, d2, -1, InternalFormat::Rgba, [1, 1, 1], 0, Some(p565)),
        Err(Value)
    );
    let d3 = TexImageTarget::D3;
    assert_eq!(
        img(
            &mut gl,
            d3,
            0,
            InternalFormat::DepthComponent,
            [1, 1, 1],
            0,
            Some(depth)
        ),
        Err(Op)
    );
    assert_eq!(
        img(&mut gl, d3, 0, InternalFormat::Rgba, [257, 1, 1], 0, None),
        Err(Value),
        "softgl's 3D limit is 256"
    );
    assert_eq!(
        img(&mut gl, d2, 0, InternalFormat::Rgba, [4097, 1, 1], 0, None),
        Err(Value),
        "softgl's limit is 4096"
    );
    let face = TexImageTarget::CubeFace(0);
    assert_eq!(
        img(&mut gl, face, 0, InternalFormat::Rgba, [2, 1, 1], 0, None),
        Err(Value)
    );
    assert_eq!(
        img(
            &mut gl,
            face,
            0,
            InternalFormat::DepthComponent,
            [2, 2, 1],
            0,
            Some(depth)
        ),
        Ok(())
    );
    assert_eq!(gl.get_error(), Some(Value), "the first error is kept");
    assert_eq!(gl.get_error(), None);
    // Borders are stripped: a 5×5 image with border 1 is a 3×3 image with border 0.
    img(&mut gl, d2, 0, InternalFormat::Rgba, [5, 5, 1], 1, Some(rgba(&px))).unwrap();
    assert_eq!(gl.get_tex_level_parameter(d2, 0, TexLevelParamName::Width), Ok(3));
    assert_eq!(gl.get_tex_level_parameter(d2, 0, TexLevelParamName::Border), Ok(0));
    img(&mut gl, d2, 0, InternalFormat::Rgba, [2, 2, 1], 1, Some(rgba(&px))).unwrap();
    assert_eq!(gl.get_tex_level_parameter(d2, 0, TexLevelParamName::Width), Ok(0));

    // Proxies: bad sizes clear the proxy image without an error; other errors are errors.
    let proxy = TexImageTarget::Proxy(TextureTarget::D2);
    assert_eq!(
        img(&mut gl, proxy, -1, InternalFormat::Rgba, [1, 1, 1], 0, None),
        Err(Value)
    );
    assert_eq!(
        img(&mut gl, proxy, 0, InternalFormat::Rgba, [100000, 1, 1], 0, None),
        Ok(())
    );
    assert_eq!(gl.get_tex_level_parameter(proxy, 0, TexLevelParamName::Width), Ok(0));
    assert_eq!(
        gl.get_tex_level_parameter(proxy, 0, TexLevelParamName::InternalFormat),
        Ok(0x1908)
    );
    img(&mut gl, proxy, 0, InternalFormat::Rgba4, [64, 32, 1], 0, None).unwrap();
    assert_eq!(gl.get_tex_level_parameter(proxy, 0, TexLevelParamName::Width), Ok(64));
    assert_eq!(gl.get_tex_level_parameter(proxy, 0, TexLevelParamName::RedSize), Ok(4));
    assert_eq!(
        gl.get_tex_level_parameter(proxy, 0, TexLevelParamName::InternalFormat),
        Ok(0x8056)
    );
    img(&mut gl, proxy, 0, InternalFormat::Rgba, [6, 6, 1], 1, None).unwrap();
    assert_eq!(gl.get_tex_level_parameter(proxy, 0, TexLevelParamName::Width), Ok(6));
    assert_eq!(gl.get_tex_level_parameter(proxy, 0, TexLevelParamName::Border), Ok(1));
    assert_eq!(
        img(
            &mut gl,
            proxy,
            0,
            InternalFormat::DepthComponent,
            [1, 1, 1],
            0,
            Some(rgba(&px))
        ),
        Err(Op)
    );
    let pcube = TexImageTarget::Proxy(TextureTarget::Cube);
    assert_eq!(img(&mut gl, pcube, 0, InternalFormat::Rgba, [2, 1, 1], 0, None), Ok(()));
    assert_eq!(gl.get_tex_level_parameter(pcube, 0, TexLevelParamName::Width), Ok(0));

    // Sub-images.
    gl.bind_texture(TextureTarget::D2, 1).unwrap();
    let sub = |gl: &mut Context, level, off: [i32; 3], size: [i32; 3], p| gl.tex_sub_image(d2, level, off, size, p);
    assert_eq!(sub(&mut gl, 0, [0; 3], [1, 1, 1], rgba(&px)), Err(Op), "no image");
    assert_eq!(sub(&mut gl, -1, [0; 3], [1, 1, 1], rgba(&px)), Err(Value));
    img(&mut gl, d2, 0, InternalFormat::Rgba, [4, 4, 1], 0, Some(rgba(&px))).unwrap();
    assert_eq!(sub(&mut gl, 0, [3, 0, 0], [2, 1, 1], rgba(&px)), Err(Value));
    assert_eq!(sub(&mut gl, 0, [-1, 0, 0], [1, 1, 1], rgba(&px)), Err(Value));
    assert_eq!(sub(&mut gl, 0, [0, 0, 0], [-1, 1, 1], rgba(&px)), Err(Value));
    assert_eq!(sub(&mut gl, 0, [0, 0, 0], [1, 1, 1], depth), Err(Op));
    assert_eq!(sub(&mut gl, 0, [4, 4, 0], [0, 0, 1], rgba(&px)), Ok(()));
    // The format check comes before the region check.
    assert_eq!(sub(&mut gl, 0, [9, 0, 0], [1, 1, 1], p565), Err(Op));
    assert_eq!(gl.tex_sub_image(proxy, 0, [0; 3], [1, 1, 1], rgba(&px)), Err(Enum));

    // Copies.
    let copy = |gl: &mut Context, t, level, internal, size: [i32; 2], border| {
        gl.copy_tex_image(t, level, internal, [0, 0], size, border)
    };
    assert_eq!(copy(&mut gl, d2, 0, InternalFormat::Three, [2, 2], 0), Err(Enum));
    assert_eq!(copy(&mut gl, d2, -1, InternalFormat::Three, [2, 2], 0), Err(Value));
    assert_eq!(copy(&mut gl, d2, 0, InternalFormat::Rgba, [2, 2], 2), Err(Value));
    assert_eq!(copy(&mut gl, d2, 0, InternalFormat::Rgba, [-1, 2], 0), Err(Value));
    assert_eq!(copy(&mut gl, face, 0, InternalFormat::Rgba, [2, 1], 0), Err(Value));
    assert_eq!(copy(&mut gl, d3, 0, InternalFormat::Rgba, [2, 1], 0), Err(Enum));
    assert_eq!(copy(&mut gl, d2, 0, InternalFormat::DepthComponent, [2, 2], 0), Ok(()));
    gl.bind_texture(TextureTarget::D2, 2).unwrap();
    let csub = |gl: &mut Context, off: [i32; 3], size: [i32; 2]| gl.copy_tex_sub_image(d2, 0, off, [0, 0], size);
    assert_eq!(csub(&mut gl, [0; 3], [1, 1]), Err(Op), "no image");
    img(&mut gl, d2, 0, InternalFormat::Rgba, [4, 4, 1], 0, None).unwrap();
    assert_eq!(csub(&mut gl, [3, 3, 0], [2, 2]), Err(Value));
    assert_eq!(csub(&mut gl, [0, 0, 0], [-1, 1]), Err(Value));

    // Readback.
    let mut out = [0u8; 256];
    let get = |gl: &mut Context, t, level, f, ty, out: &mut [u8]| gl.get_tex_image(t, level, f, ty, &packed(4), out);
    assert_eq!(
        get(&mut gl, d2, -1, PixelFormat::Rgba, PixelType::UnsignedByte, &mut out),
        Err(Value)
    );
    assert_eq!(
        get(&mut gl, d2, 0, PixelFormat::DepthComponent, PixelType::Float, &mut out),
        Err(Op)
    );
    assert_eq!(
        get(&mut gl, d2, 3, PixelFormat::Rgba, PixelType::UnsignedByte, &mut out),
        Ok(()),
        "no image: nothing"
    );
    assert_eq!(
        get(&mut gl, proxy, 0, PixelFormat::Rgba, PixelType::UnsignedByte, &mut out),
        Err(Enum)
    );
    assert_eq!(
        get(&mut gl, d2, 0, PixelFormat::Rgba, PixelType::UnsignedShort565, &mut out),
        Err(Op)
    );
    assert_eq!(
        get(
            &mut gl,
            d2,
            0,
            PixelFormat::Rgba,
            PixelType::UnsignedByte,
            &mut out[..63]
        ),
        Err(Op),
        "too small"
    );

    // Levels, mipmaps, residency.
    assert_eq!(gl.get_tex_level_parameter(d2, -1, TexLevelParamName::Width), Err(Value));
    gl.bind_texture(TextureTarget::Cube, 3).unwrap();
    img(&mut gl, face, 0, InternalFormat::Rgba, [4, 4, 1], 0, None).unwrap();
    assert_eq!(gl.generate_mipmap(TextureTarget::Cube), Err(Op), "five faces missing");
    gl.bind_texture(TextureTarget::D1, 5).unwrap();
    assert_eq!(gl.generate_mipmap(TextureTarget::D1), Err(Op), "no base image");
    gl.tex_parameter(TextureTarget::D1, TexParam::MaxLevel(0)).unwrap();
    assert_eq!(
        gl.generate_mipmap(TextureTarget::D1),
        Ok(()),
        "BASE_LEVEL >= MAX_LEVEL: nothing to do"
    );
    assert_eq!(gl.are_textures_resident(&[1, 0]), Err(Value));
    gl.tex_parameter(TextureTarget::D2, TexParam::BorderColor([2.0, -1.0, 0.5, 3.0]))
        .unwrap();
    assert_eq!(
        gl.get_tex_parameter(TextureTarget::D2, TexParamName::BorderColor),
        Ok(TexParam::BorderColor([1.0, 0.0, 0.5, 1.0]))
    );
    gl.tex_parameter(TextureTarget::D2, TexParam::LodBias(100.3)).unwrap();
    assert_eq!(
        gl.get_tex_parameter(TextureTarget::D2, TexParamName::LodBias),
        Ok(TexParam::LodBias(100.3))
    );
    gl.tex_parameter(TextureTarget::D2, TexParam::Priority(-2.0)).unwrap();
    assert_eq!(
        gl.get_tex_parameter(TextureTarget::D2, TexParamName::Priority),
        Ok(TexParam::Priority(0.0))
    );

    // Between begin and end every texture call is InvalidOperation.
    gl.begin(softgl::PrimitiveMode::Triangles).unwrap();
    assert_eq!(gl.bind_texture(TextureTarget::D2, 1), Err(Op));
    assert_eq!(img(&mut gl, d2, 0, InternalFormat::Rgba, [1, 1, 1], 0, None), Err(Op));
    gl.end().unwrap();
}

/// glCopyTexImage reads the colour buffer as stored (unorm8: 0.2 → 51, …);
/// luminance takes red; pixels outside the framebuffer leave texels 0;
/// glCopyTexSubImage writes a region; depth formats read the depth buffer.
#[test]
fn copies_read_the_framebuffer() {
    let mut gl = context();
    gl.clear_color(0.2, 0.4, 0.6, 0.8).unwrap();
    gl.clear_depth(0.5).unwrap();
    gl.clear(softgl::ClearMask::COLOR | softgl::ClearMask::DEPTH).unwrap();
    let d2 = TexImageTarget::D2;
    gl.copy_tex_image(d2, 0, InternalFormat::Rgba8, [6, 6], [3, 2], 0)
        .unwrap();
    // Columns 6 and 7 are inside the 8×8 framebuffer, column 8 is not.
    #[rustfmt::skip]
    assert_eq!(texels(&gl, 0), [
        51, 102, 153, 204, 51, 102, 153, 204, 0, 0, 0, 0,
        51, 102, 153, 204, 51, 102, 153, 204, 0, 0, 0, 0,
    ]);
    gl.copy_tex_image(d2, 0, InternalFormat::Luminance8, [0, 0], [2, 1], 0)
        .unwrap();
    assert_eq!(texels(&gl, 0), [51, 51, 51, 255, 51, 51, 51, 255]);
    gl.clear_color(1.0, 0.0, 0.0, 1.0).unwrap();
    gl.clear(softgl::ClearMask::COLOR).unwrap();
    gl.copy_tex_sub_image(d2, 0, [1, 0, 0], [4, 4], [1, 1]).unwrap();
    assert_eq!(texels(&gl, 0), [51, 51, 51, 255, 255, 255, 255, 255]);
    // A 1D copy reads one row.
    gl.copy_tex_image(TexImageTarget::D1, 0, InternalFormat::Rgb8, [0, 0], [2, 1], 0)
        .unwrap();
    let t = &gl.textures().bound(0, TextureTarget::D1).image(0, 0).unwrap().texels;
    assert_eq!(t.as_slice(), &[255, 0, 0, 255, 255, 0, 0, 255]);
    // Depth: the stored 24-bit value of 0.5, as a float.
    gl.copy_tex_image(d2, 0, InternalFormat::DepthComponent24, [0, 0], [1, 1], 0)
        .unwrap();
    let z = gl.framebuffer().depth_at(0, 0).unwrap();
    let want = (f64::from(z) / 16777215.0) as f32;
    assert_eq!(texels(&gl, 0), want.to_ne_bytes());
}

/// What the draw gets: the object's LOD bias quantized to 1/256 plus the
/// unit's, MIN_LOD no lower than 0, the border colour as the base format
/// sees it (luminance: (L, L, L, 1)), wraps the target lacks as REPEAT,
/// compare only for depth formats.
#[test]
fn the_sampling_view_is_gallium_s_sampler_state() {
    let mut gl = context();
    let t = TextureTarget::D1;
    let px = data(PixelFormat::Luminance, PixelType::UnsignedByte, packed(1), &[7, 9]);
    gl.tex_image(
        TexImageTarget::D1,
        0,
        InternalFormat::Luminance8,
        [2, 1, 1],
        0,
        Some(px),
    )
    .unwrap();
    for p in [
        TexParam::MinFilter(Filter::Linear, MipFilter::None),
        TexParam::WrapS(Wrap::ClampToBorder),
        TexParam::WrapT(Wrap::Clamp),
        TexParam::LodBias(0.3),
        TexParam::MinLod(-5.0),
        TexParam::MaxLod(3.5),
        TexParam::BorderColor([0.2, 0.4, 0.6, 0.8]),
        TexParam::CompareMode(true),
    ] {
        gl.tex_parameter(t, p).unwrap();
    }
    let s = gl.textures().sampling(0, t).unwrap();
    assert_eq!(s.key.wrap, [Wrap::ClampToBorder, Wrap::Repeat, Wrap::Repeat]);
    assert_eq!(s.key.compare, None, "not a depth texture");
    assert_eq!(s.base, BaseFormat::Luminance);
    let view = s.texture_ref(0.5);
    // 0.3 · 256 = 76.8 → 77.
    assert_eq!(view.lod_bias, 77.0 / 256.0 + 0.5);
    assert_eq!((view.min_lod, view.max_lod), (0.0, 3.5));
    assert_eq!(view.border, [0.2, 0.2, 0.2, 1.0]);
    assert_eq!(view.images[0].texels, [7, 7, 7, 255, 9, 9, 9, 255]);
    // A depth texture compares.
    let d = 0.25f32.to_ne_bytes();
    let px = data(PixelFormat::DepthComponent, PixelType::Float, packed(1), &d);
    gl.tex_image(
        TexImageTarget::D1,
        0,
        InternalFormat::DepthComponent16,
        [1, 1, 1],
        0,
        Some(px),
    )
    .unwrap();
    let s = gl.textures().sampling(0, t).unwrap();
    assert_eq!(s.key.compare, Some(softgl::CompareFunc::Lequal));
    // 0.25 · 65535 = 16383.75 → 16383 (truncated), read as 16383 · f32(1/65535).
    let z = 16383.0f32 * (1.0 / 65535.0f64) as f32;
    assert_eq!(s.images[0].texels, z.to_ne_bytes());
}

/// 3D uploads: IMAGE_HEIGHT sets the rows between images and SKIP_IMAGES
/// skips whole images (GL 1.5 §3.8.1); a sub-image writes a box; a copy
/// writes one slice.
#[test]
fn volumes_honour_image_height_and_skip_images() {
    let mut gl = context();
    // Alpha bytes, rows of 2, images of 3 rows (one unused), one image skipped.
    let store = PixelStore {
        image_height: 3,
        skip_images: 1,
        alignment: 1,
        ..PixelStore::default()
    };
    let bytes: Vec<u8> = (0..18).collect();
    let px = data(PixelFormat::Alpha, PixelType::UnsignedByte, store, &bytes);
    gl.tex_image(TexImageTarget::D3, 0, InternalFormat::Alpha8, [2, 2, 2], 0, Some(px))
        .unwrap();
    let a = |gl: &mut Context| -> Vec<u8> {
        let img = gl.textures().bound(0, TextureTarget::D3).image(0, 0).unwrap();
        img.texels.chunks(4).map(|t| t[3]).collect()
    };
    // Image 1 starts at byte 6, image 2 at byte 12.
    assert_eq!(a(&mut gl), [6, 7, 8, 9, 12, 13, 14, 15]);
    // One byte short of the last texel.
    let px = data(PixelFormat::Alpha, PixelType::UnsignedByte, store, &bytes[..15]);
    assert_eq!(
        gl.tex_image(TexImageTarget::D3, 0, InternalFormat::Alpha8, [2, 2, 2], 0, Some(px)),
        Err(GlError::InvalidOperation)
    );
    // A 1×2×2 box at x = 1.
    let px = data(
        PixelFormat::Alpha,
        PixelType::UnsignedByte,
        packed(1),
        &[100, 101, 102, 103],
    );
    gl.tex_sub_image(TexImageTarget::D3, 0, [1, 0, 0], [1, 2, 2], px)
        .unwrap();
    assert_eq!(a(&mut gl), [6, 100, 8, 101, 12, 102, 14, 103]);
    // Slice 1, texel (0, 1) from the framebuffer's alpha (cleared to 0.8 → 204).
    gl.clear_color(0.2, 0.4, 0.6, 0.8).unwrap();
    gl.clear(softgl::ClearMask::COLOR).unwrap();
    gl.copy_tex_sub_image(TexImageTarget::D3, 0, [0, 1, 1], [0, 0], [1, 1])
        .unwrap();
    assert_eq!(a(&mut gl), [6, 100, 8, 101, 12, 102, 204, 103]);
}

/// A cube map is complete when its six faces have base images of one size
/// and format (and, mipmapped, every level of every face).
#[test]
fn cube_maps_need_six_matching_faces() {
    let mut gl = context();
    gl.tex_parameter(
        TextureTarget::Cube,
        TexParam::MinFilter(Filter::Linear, MipFilter::None),
    )
    .unwrap();
    for f in 0..6 {
        assert!(gl.textures().sampling(0, TextureTarget::Cube).is_none());
        let bytes = [f * 10; 16];
        let px = data(PixelFormat::Rgba, PixelType::UnsignedByte, packed(1), &bytes);
        let internal = if f == 5 {
            InternalFormat::Rgb8
        } else {
            InternalFormat::Rgba8
        };
        gl.tex_image(TexImageTarget::CubeFace(f), 0, internal, [2, 2, 1], 0, Some(px))
            .unwrap();
    }
    assert!(
        gl.textures().sampling(0, TextureTarget::Cube).is_none(),
        "face 5 differs in format"
    );
    let px = data(PixelFormat::Rgba, PixelType::UnsignedByte, packed(1), &[50; 16]);
    gl.tex_image(
        TexImageTarget::CubeFace(5),
        0,
        InternalFormat::Rgba8,
        [2, 2, 1],
        0,
        Some(px),
    )
    .unwrap();
    let s = gl.textures().sampling(0, TextureTarget::Cube).expect("complete");
    assert_eq!(s.images.len(), 6);
    assert_eq!(s.images[3].texels, [30; 16], "face −Y");
    // Mipmapped: generate_mipmap fills level 1 of every face.
    gl.tex_parameter(
        TextureTarget::Cube,
        TexParam::MinFilter(Filter::Linear, MipFilter::Linear),
    )
    .unwrap();
    assert!(gl.textures().sampling(0, TextureTarget::Cube).is_none());
    gl.generate_mipmap(TextureTarget::Cube).unwrap();
    let s = gl.textures().sampling(0, TextureTarget::Cube).expect("complete");
    assert_eq!(s.images.len(), 12);
    assert_eq!(
        s.images[6 + 2].texels,
        [20; 4],
        "level 1, face +Y: the average of equal texels"
    );
}
