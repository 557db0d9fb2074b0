//! Texturing through the C ABI: texture objects, uploads sized from the
//! unpack state and read back, parameters, the environment, coordinate
//! generation, multitexture coordinates and arrays, errors, display lists,
//! the attribute stacks, and textured pixels.

mod current;

use current::{GL_INVALID_ENUM, GL_INVALID_OPERATION, GL_INVALID_VALUE};
use std::ffi::c_void;
use std::ptr::null;
use std::sync::atomic::{AtomicUsize, Ordering};
use OSMesa::consts::*;
use OSMesa::*;

/// A context current on this thread, 8 x 8 pixels as units.
fn current(buf: &mut [u8]) -> OSMesaContext {
    current::current_in_pixels(buf, 8, 8)
}

const GL_QUADS: u32 = 7;
const GL_COMPILE: u32 = 0x1300;
const GL_TEXTURE_MAG_FILTER: u32 = 0x2800;
const GL_TEXTURE_MIN_FILTER: u32 = 0x2801;
const GL_TEXTURE_WRAP_S: u32 = 0x2802;
const GL_TEXTURE_WRAP_T: u32 = 0x2803;
const GL_TEXTURE_BORDER_COLOR: u32 = 0x1004;
const GL_TEXTURE_PRIORITY: u32 = 0x8066;
const GL_TEXTURE_MAX_LEVEL: u32 = 0x813D;
const GL_TEXTURE_MIN_LOD: u32 = 0x813A;
const GL_TEXTURE_WIDTH: u32 = 0x1000;
const GL_TEXTURE_HEIGHT: u32 = 0x1001;
const GL_TEXTURE_INTERNAL_FORMAT: u32 = 0x1003;
const GL_NEAREST: u32 = 0x2600;
const GL_LINEAR: u32 = 0x2601;
const GL_LINEAR_MIPMAP_LINEAR: u32 = 0x2703;
const GL_REPEAT: u32 = 0x2901;
const GL_CLAMP_TO_EDGE: u32 = 0x812F;
const GL_TEXTURE_ENV_MODE: u32 = 0x2200;
const GL_TEXTURE_ENV_COLOR: u32 = 0x2201;
const GL_MODULATE: u32 = 0x2100;
const GL_REPLACE: u32 = 0x1E01;
const GL_DECAL: u32 = 0x2101;
const GL_COMBINE: u32 = 0x8570;
const GL_COMBINE_RGB: u32 = 0x8571;
const GL_DOT3_RGB: u32 = 0x86AE;
const GL_SOURCE1_RGB: u32 = 0x8581;
const GL_OPERAND2_ALPHA: u32 = 0x859A;
const GL_SRC_COLOR: u32 = 0x0300;
const GL_ONE_MINUS_SRC_ALPHA: u32 = 0x0303;
const GL_RGB_SCALE: u32 = 0x8573;
const GL_TEXTURE_GEN_MODE: u32 = 0x2500;
const GL_OBJECT_PLANE: u32 = 0x2501;
const GL_EYE_PLANE: u32 = 0x2502;
const GL_OBJECT_LINEAR: u32 = 0x2401;
const GL_SPHERE_MAP: u32 = 0x2402;
const GL_T: u32 = 0x2001;
const GL_R: u32 = 0x2002;
const GL_TEXTURE_GEN_T: u32 = 0x0C61;
const GL_TEXTURE_MATRIX: u32 = 0x0BA8;
const GL_TEXTURE: u32 = 0x1702;
const GL_MODELVIEW: u32 = 0x1700;
const GL_TEXTURE_BIT: u32 = 0x40000;
const GL_TRANSFORM_BIT: u32 = 0x1000;
const GL_TEXTURE_STACK_DEPTH: u32 = 0x0BA5;
const GL_MATRIX_MODE: u32 = 0x0BA0;
const GL_ENABLE_BIT: u32 = 0x2000;
const GL_CLIENT_VERTEX_ARRAY_BIT: u32 = 0x2;
const GL_RGBA8: i32 = 0x8058;
const GL_LUMINANCE8: i32 = 0x8040;

fn int(pname: u32) -> i32 {
    let mut v = [-7i32; 16];
    // SAFETY: room for 16 values, the most any pname here has.
    unsafe { glGetIntegerv(pname, v.as_mut_ptr()) };
    v[0]
}

fn floats4(pname: u32) -> [f32; 4] {
    let mut v = [f32::NAN; 16];
    // SAFETY: room for 16 values.
    unsafe { glGetFloatv(pname, v.as_mut_ptr()) };
    [v[0], v[1], v[2], v[3]]
}

fn tex_int(pname: u32) -> i32 {
    let mut v = [-7i32; 4];
    // SAFETY: room for the 4 values of any parameter.
    unsafe { glGetTexParameteriv(GL_TEXTURE_2D, pname, v.as_mut_ptr()) };
    v[0]
}

fn level_int(target: u32, level: i32, pname: u32) -> i32 {
    let mut v = -7;
    // SAFETY: one writable value.
    unsafe { glGetTexLevelParameteriv(target, level, pname, &mut v) };
    v
}

fn env_int(pname: u32) -> i32 {
    let mut v = [-7i32; 4];
    // SAFETY: room for 4 values.
    unsafe { glGetTexEnviv(GL_TEXTURE_ENV, pname, v.as_mut_ptr()) };
    v[0]
}

fn gen_texture() -> u32 {
    let mut t = 0;
    // SAFETY: room for one name.
    unsafe { glGenTextures(1, &mut t) };
    t
}

/// Uploads `w` x `h` tightly packed RGBA bytes to level 0 of the bound 2D texture.
fn upload_rgba(w: i32, h: i32, texels: &[u8]) {
    assert_eq!(texels.len(), (w * h * 4) as usize);
    // SAFETY: `texels` holds the image (alignment 4 adds no padding to RGBA rows).
    unsafe {
        glTexImage2D(
            GL_TEXTURE_2D,
            0,
            GL_RGBA8,
            w,
            h,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            texels.as_ptr().cast(),
        )
    };
}

/// Level `level` of the bound 2D texture as tight RGBA bytes.
fn read_rgba(level: i32) -> Vec<u8> {
    let (w, h) = (
        level_int(GL_TEXTURE_2D, level, GL_TEXTURE_WIDTH),
        level_int(GL_TEXTURE_2D, level, GL_TEXTURE_HEIGHT),
    );
    let mut out = vec![0xEEu8; (w * h * 4) as usize];
    // SAFETY: room for the image with the default pack state (RGBA rows need no padding).
    unsafe { glGetTexImage(GL_TEXTURE_2D, level, GL_RGBA, GL_UNSIGNED_BYTE, out.as_mut_ptr().cast()) };
    out
}

fn px(buf: &[u8], x: usize, y: usize) -> [u8; 4] {
    let o = (y * 8 + x) * 4;
    buf[o..o + 4].try_into().unwrap()
}

fn quad() {
    glBegin(GL_QUADS);
    glTexCoord2f(0.0, 0.0);
    glVertex2f(0.0, 0.0);
    glTexCoord2f(1.0, 0.0);
    glVertex2f(8.0, 0.0);
    glTexCoord2f(1.0, 1.0);
    glVertex2f(8.0, 8.0);
    glTexCoord2f(0.0, 1.0);
    glVertex2f(0.0, 8.0);
    glEnd();
}

/// A 2 x 2 RGBA texture: red, green (bottom row), blue, white (top row).
const QUADRANTS: [u8; 16] = [255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255];

#[test]
fn objects_are_named_bound_and_deleted() {
    let mut buf = vec![0u8; 8 * 8 * 4];
    let ctx = current(&mut buf);
    let mut names = [0u32; 3];
    // SAFETY: room for 3 names.
    unsafe { glGenTextures(3, names.as_mut_ptr()) };
    assert!(names.iter().all(|&n| n != 0));
    assert!(names[0] != names[1] && names[1] != names[2] && names[0] != names[2]);
    // A name is a texture once bound (Mesa's glIsTexture too).
    assert_eq!(glIsTexture(names[0]), GL_FALSE);
    glBindTexture(GL_TEXTURE_2D, names[0]);
    assert_eq!(glIsTexture(names[0]), GL_TRUE);
    assert_eq!(int(GL_TEXTURE_BINDING_2D), names[0] as i32);
    assert_eq!(int(GL_TEXTURE_BINDING_1D), 0);
    // Bound to another target: GL_INVALID_OPERATION.
    glBindTexture(GL_TEXTURE_1D, names[0]);
    assert_eq!(glGetError(), GL_INVALID_OPERATION);
    // Deleting the bound texture binds 0 again.
    // SAFETY: one name.
    unsafe { glDeleteTextures(1, &names[0]) };
    assert_eq!((int(GL_TEXTURE_BINDING_2D), glIsTexture(names[0])), (0, GL_FALSE));
    // Resident: all (GL_TRUE, the array untouched); a name never made is GL_INVALID_VALUE.
    glBindTexture(GL_TEXTURE_2D, names[1]);
    let mut res = [7u8; 1];
    // SAFETY: one name, one result.
    assert_eq!(
        unsafe { glAreTexturesResident(1, &names[1], res.as_mut_ptr()) },
        GL_TRUE
    );
    assert_eq!((res, glGetError()), ([7], GL_NO_ERROR));
    // SAFETY: one name, one result.
    assert_eq!(unsafe { glAreTexturesResident(1, &9999, res.as_mut_ptr()) }, GL_FALSE);
    assert_eq!(glGetError(), GL_INVALID_VALUE);
    // SAFETY: negative counts are refused before any read.
    unsafe {
        glGenTextures(-1, names.as_mut_ptr());
        assert_eq!(glGetError(), GL_INVALID_VALUE);
        glDeleteTextures(-1, names.as_ptr());
        assert_eq!(glGetError(), GL_INVALID_VALUE);
        glPrioritizeTextures(1, &names[1], &0.25f32);
    }
    assert_eq!(tex_int(GL_TEXTURE_PRIORITY), (0.25 * 2147483647.0) as i32);
    // EXT names are the same functions.
    glBindTextureEXT(GL_TEXTURE_2D, 0);
    assert_eq!(int(GL_TEXTURE_BINDING_2D), 0);
    assert_eq!(glGetError(), GL_NO_ERROR);
    OSMesaDestroyContext(ctx);
}

#[test]
fn uploads_honour_the_unpack_state_and_read_back() {
    let mut buf = vec![0u8; 8 * 8 * 4];
    let ctx = current(&mut buf);
    glBindTexture(GL_TEXTURE_2D, gen_texture());
    // 3 x 2 RGB bytes, alignment 4: rows of 9 bytes padded to 12.
    let mut rgb = [0u8; 12 + 9];
    for (k, v) in rgb.iter_mut().enumerate() {
        *v = k as u8 * 10;
    }
    // SAFETY: 21 bytes: one padded row, then the last row without padding.
    unsafe {
        glTexImage2D(
            GL_TEXTURE_2D,
            0,
            GL_RGB as i32,
            3,
            2,
            0,
            GL_RGB,
            GL_UNSIGNED_BYTE,
            rgb.as_ptr().cast(),
        )
    };
    assert_eq!(glGetError(), GL_NO_ERROR);
    let rgba = |r: &[u8]| [r[0], r[1], r[2], 255];
    let expect: Vec<u8> = [0, 3, 6, 12, 15, 18].iter().flat_map(|&o| rgba(&rgb[o..])).collect();
    assert_eq!(read_rgba(0), expect);
    assert_eq!(level_int(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT), GL_RGB as i32);
    assert_eq!((level_int(GL_TEXTURE_2D, 0, 0x88F1), glGetError()), (0, GL_NO_ERROR)); // STENCIL_SIZE

    // A 2 x 2 sub-image read from a 5-pixel-wide buffer, 1 pixel in and 1 row
    // up, luminance bytes at alignment 1; the buffer ends at its last pixel.
    let lum = [0u8, 0, 0, 0, 0, 0, 100, 101, 0, 0, 0, 110, 111];
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 5);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 1);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
    // SAFETY: the layout ends at byte 1 + 5 + 5 + 2 = 13 = lum.len().
    unsafe {
        glTexSubImage2D(
            GL_TEXTURE_2D,
            0,
            1,
            0,
            2,
            2,
            GL_LUMINANCE,
            GL_UNSIGNED_BYTE,
            lum.as_ptr().cast(),
        )
    };
    assert_eq!(glGetError(), GL_NO_ERROR);
    let img = read_rgba(0);
    assert_eq!(&img[4..12], &[100, 100, 100, 255, 101, 101, 101, 255]);
    assert_eq!(&img[16..24], &[110, 110, 110, 255, 111, 111, 111, 255]);
    assert_eq!(&img[..4], &expect[..4], "texel (0, 0) untouched");
    for p in [GL_UNPACK_ROW_LENGTH, GL_UNPACK_SKIP_PIXELS, GL_UNPACK_SKIP_ROWS] {
        glPixelStorei(p, 0);
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);

    // Packed 5-6-5 into a luminance texture: L is R (GL 1.5 §3.8.1); read
    // back as RGBA, L lands in R alone (GL 1.5 §6.1.4, Mesa's rebase).
    let texel: u16 = 0xF800; // red: R 31, G 0, B 0
                             // SAFETY: one 2-byte texel.
    unsafe {
        glTexImage2D(
            GL_TEXTURE_2D,
            0,
            GL_LUMINANCE8,
            1,
            1,
            0,
            GL_RGB,
            GL_UNSIGNED_SHORT_5_6_5,
            (&texel as *const u16).cast(),
        )
    };
    assert_eq!((glGetError(), read_rgba(0)), (GL_NO_ERROR, vec![255, 0, 0, 255]));

    // Colour indices pass GL's default pixel maps (one entry, 0): all zero,
    // as in Mesa; stencil indices are no texture's.
    let idx = [3u8, 200, 0, 0, 7, 9, 0, 0];
    // SAFETY: 2 x 2 index bytes, rows padded to 4 bytes (alignment 4).
    unsafe {
        glTexImage2D(
            GL_TEXTURE_2D,
            0,
            GL_RGBA8,
            2,
            2,
            0,
            GL_COLOR_INDEX,
            GL_UNSIGNED_BYTE,
            idx.as_ptr().cast(),
        )
    };
    assert_eq!((glGetError(), read_rgba(0)), (GL_NO_ERROR, vec![0; 16]));
    // SAFETY: as above.
    unsafe {
        glTexImage2D(
            GL_TEXTURE_2D,
            0,
            GL_RGBA8,
            2,
            2,
            0,
            GL_STENCIL_INDEX,
            GL_UNSIGNED_BYTE,
            idx.as_ptr().cast(),
        )
    };
    assert_eq!(glGetError(), GL_INVALID_OPERATION);

    // glGetTexImage with the pack state: BGRA floats, 2 pixels in of a 3-pixel row.
    upload_rgba(2, 2, &QUADRANTS);
    glPixelStorei(GL_PACK_ROW_LENGTH, 3);
    glPixelStorei(GL_PACK_SKIP_PIXELS, 1);
    let mut f = [-1.0f32; 3 * 4 * 2];
    // SAFETY: 2 rows of 3 BGRA float pixels.
    unsafe { glGetTexImage(GL_TEXTURE_2D, 0, GL_BGRA, GL_FLOAT, f.as_mut_ptr().cast()) };
    assert_eq!(glGetError(), GL_NO_ERROR);
    assert_eq!(&f[..4], &[-1.0; 4], "the skipped pixel is untouched");
    assert_eq!(&f[4..12], &[0.0, 0.0, 1.0, 1.0, 0.0, 1.0, 0.0, 1.0]);
    assert_eq!(&f[16..24], &[1.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0, 1.0]);
    OSMesaDestroyContext(ctx);
}

#[test]
fn bad_uploads_are_refused_in_mesas_order() {
    let mut buf = vec![0u8; 8 * 8 * 4];
    let ctx = current(&mut buf);
    glBindTexture(GL_TEXTURE_2D, gen_texture());
    let px = [0u8; 64];
    let p = px.as_ptr().cast::<c_void>();
    type Call = (u32, i32, i32, i32, i32, u32, u32);
    // (target, level, internal format, width, border, format, type) → error, measured on Mesa (tests/c/textured.c).
    let cases: [(Call, u32); 11] = [
        (
            (GL_TEXTURE_1D, 0, GL_RGBA as i32, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE),
            GL_INVALID_ENUM,
        ),
        (
            (0x1234, 0, GL_RGBA as i32, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE),
            GL_INVALID_ENUM,
        ),
        (
            (GL_TEXTURE_2D, -1, GL_RGBA as i32, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE),
            GL_INVALID_VALUE,
        ),
        (
            (GL_TEXTURE_2D, 0, GL_RGBA as i32, 1, 2, GL_RGBA, GL_UNSIGNED_BYTE),
            GL_INVALID_VALUE,
        ),
        (
            (GL_TEXTURE_2D, 0, GL_RGBA as i32, -1, 0, GL_RGBA, GL_UNSIGNED_BYTE),
            GL_INVALID_VALUE,
        ),
        (
            (GL_TEXTURE_2D, 0, GL_RGBA as i32, 1, 0, 0x1234, GL_UNSIGNED_BYTE),
            GL_INVALID_ENUM,
        ),
        (
            (GL_TEXTURE_2D, 0, GL_RGBA as i32, 1, 0, GL_RGBA, 0x1234),
            GL_INVALID_ENUM,
        ),
        (
            (GL_TEXTURE_2D, 0, GL_RGBA as i32, 1, 0, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5),
            GL_INVALID_OPERATION,
        ),
        // A bad type and a bad internal format: the type first.
        ((GL_TEXTURE_2D, 0, 0x1234, 1, 0, GL_RGBA, 0x1234), GL_INVALID_ENUM),
        ((GL_TEXTURE_2D, 0, 5, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE), GL_INVALID_VALUE),
        (
            (GL_TEXTURE_2D, 0, GL_RGBA as i32, 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT),
            GL_INVALID_OPERATION,
        ),
    ];
    for ((target, level, internal, w, border, format, ty), err) in cases {
        // SAFETY: 64 bytes hold any 1 x 1 image here.
        unsafe { glTexImage2D(target, level, internal, w, 1, border, format, ty, p) };
        assert_eq!(
            glGetError(),
            err,
            "{target:#x} {level} {internal:#x} {w} {border} {format:#x} {ty:#x}"
        );
    }
    // Nothing was stored by the failed calls.
    assert_eq!(level_int(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH), 0);
    // Proxies: a size that does not fit clears the proxy, without an error.
    // SAFETY: proxies read no pixels.
    unsafe {
        glTexImage2D(
            GL_PROXY_TEXTURE_2D,
            0,
            GL_RGBA as i32,
            1 << 20,
            4,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            null(),
        )
    };
    assert_eq!(
        (level_int(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH), glGetError()),
        (0, GL_NO_ERROR)
    );
    // SAFETY: as above.
    unsafe {
        glTexImage2D(
            GL_PROXY_TEXTURE_2D,
            0,
            GL_RGBA as i32,
            64,
            32,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            null(),
        )
    };
    assert_eq!(level_int(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT), 32);
    // Sub-images must lie inside the level; copies have no proxy target.
    upload_rgba(2, 2, &QUADRANTS);
    // SAFETY: 64 bytes hold the 3 x 1 image.
    unsafe { glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 0, 3, 1, GL_RGBA, GL_UNSIGNED_BYTE, p) };
    assert_eq!(glGetError(), GL_INVALID_VALUE);
    glCopyTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 0, 0, 2, 2, 0);
    assert_eq!(glGetError(), GL_INVALID_ENUM);
    // Level queries: a bad name, a target without images, a negative level.
    let mut v = 0;
    // SAFETY: one writable value each.
    unsafe {
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, 0x1234, &mut v);
        assert_eq!(glGetError(), GL_INVALID_ENUM);
        glGetTexLevelParameteriv(GL_TEXTURE_CUBE_MAP, 0, GL_TEXTURE_WIDTH, &mut v);
        assert_eq!(glGetError(), GL_INVALID_ENUM);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, -1, GL_TEXTURE_WIDTH, &mut v);
        assert_eq!(glGetError(), GL_INVALID_VALUE);
    }
    // Between glBegin and glEnd.
    glBegin(GL_QUADS);
    glBindTexture(GL_TEXTURE_2D, 0);
    glEnd();
    assert_eq!(glGetError(), GL_INVALID_OPERATION);
    OSMesaDestroyContext(ctx);
}

#[test]
fn parameters_environment_and_generation_are_set_and_queried() {
    let mut buf = vec![0u8; 8 * 8 * 4];
    let ctx = current(&mut buf);
    glBindTexture(GL_TEXTURE_2D, gen_texture());
    // GL's initial values.
    assert_eq!(tex_int(GL_TEXTURE_MIN_FILTER) as u32, 0x2702); // NEAREST_MIPMAP_LINEAR
    assert_eq!(tex_int(GL_TEXTURE_WRAP_S) as u32, GL_REPEAT);
    assert_eq!(tex_int(GL_TEXTURE_MAX_LEVEL), 1000);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR as i32);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE as f32);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, -2.5);
    let border = [0.25f32, 0.5, 0.75, 1.0];
    // SAFETY: 4 values.
    unsafe { glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border.as_ptr()) };
    assert_eq!(glGetError(), GL_NO_ERROR);
    assert_eq!(tex_int(GL_TEXTURE_MIN_FILTER) as u32, GL_LINEAR_MIPMAP_LINEAR);
    assert_eq!(tex_int(GL_TEXTURE_WRAP_T) as u32, GL_CLAMP_TO_EDGE);
    // Integer queries of a LOD round half away from zero (Mesa's `lroundf`);
    // colours map onto the integer range (`FLOAT_TO_INT`).
    assert_eq!(tex_int(GL_TEXTURE_MIN_LOD), -3);
    let mut c = [0i32; 4];
    let mut f = [0f32; 4];
    // SAFETY: room for 4 values each.
    unsafe {
        glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, c.as_mut_ptr());
        glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, f.as_mut_ptr());
    }
    assert_eq!(c, [536870911, 1073741823, 1610612735, 2147483647]);
    assert_eq!(f, border);
    // Bad values and names.
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR_MIPMAP_LINEAR as i32);
    assert_eq!(glGetError(), GL_INVALID_ENUM);
    glTexParameteri(GL_TEXTURE_2D, 0x1234, 0);
    assert_eq!(glGetError(), GL_INVALID_ENUM);
    glTexParameteri(0x1234, GL_TEXTURE_MAG_FILTER, GL_LINEAR as i32);
    assert_eq!(glGetError(), GL_INVALID_ENUM);

    // The environment of the active unit.
    assert_eq!(env_int(GL_TEXTURE_ENV_MODE) as u32, GL_MODULATE);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE as i32);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_DOT3_RGB as i32);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, 0x84C3); // GL_TEXTURE3: the crossbar
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND2_ALPHA, GL_ONE_MINUS_SRC_ALPHA as i32);
    glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 2.0);
    let ec = [0.1f32, 0.2, 0.3, 0.4];
    // SAFETY: 4 values.
    unsafe { glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, ec.as_ptr()) };
    assert_eq!(glGetError(), GL_NO_ERROR);
    assert_eq!(env_int(GL_TEXTURE_ENV_MODE) as u32, GL_COMBINE);
    assert_eq!(env_int(GL_COMBINE_RGB) as u32, GL_DOT3_RGB);
    assert_eq!(env_int(GL_SOURCE1_RGB), 0x84C3);
    assert_eq!(env_int(GL_OPERAND2_ALPHA) as u32, GL_ONE_MINUS_SRC_ALPHA);
    assert_eq!(env_int(GL_RGB_SCALE), 2);
    let mut got = [0f32; 4];
    // SAFETY: room for 4 values.
    unsafe { glGetTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, got.as_mut_ptr()) };
    assert_eq!(got, ec);
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND2_ALPHA, GL_SRC_COLOR as i32);
    assert_eq!(glGetError(), GL_INVALID_ENUM, "alpha operands take alpha only");
    glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 3.0);
    assert_eq!(glGetError(), GL_INVALID_VALUE);
    // Unit 1 has its own environment.
    glActiveTexture(GL_TEXTURE0 + 1);
    assert_eq!(env_int(GL_TEXTURE_ENV_MODE) as u32, GL_MODULATE);
    assert_eq!(int(GL_ACTIVE_TEXTURE) as u32, GL_TEXTURE0 + 1);
    glActiveTexture(GL_TEXTURE0);

    // Coordinate generation: the eye plane is kept in eye coordinates.
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR as i32);
    let plane = [1.0f64, 2.0, 3.0, 4.0];
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(0.0, 0.0, 2.0);
    // SAFETY: 4 values.
    unsafe {
        glTexGendv(GL_T, GL_OBJECT_PLANE, plane.as_ptr());
        glTexGendv(GL_T, GL_EYE_PLANE, plane.as_ptr());
    }
    glLoadIdentity();
    let (mut obj, mut eye, mut mode) = ([0f64; 4], [0f32; 4], 0i32);
    // SAFETY: room for 4 values each.
    unsafe {
        glGetTexGendv(GL_T, GL_OBJECT_PLANE, obj.as_mut_ptr());
        glGetTexGenfv(GL_T, GL_EYE_PLANE, eye.as_mut_ptr());
        glGetTexGeniv(GL_T, GL_TEXTURE_GEN_MODE, &mut mode);
    }
    assert_eq!((obj, mode as u32), (plane, GL_OBJECT_LINEAR));
    // p · M⁻¹ with M a translation by z = 2: w' = w − 2z = 4 − 6.
    assert_eq!(eye, [1.0, 2.0, 3.0, -2.0]);
    glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP as i32);
    assert_eq!(glGetError(), GL_INVALID_ENUM);
    // A scalar form sets a plane to (param, 0, 0, 0), as Mesa's do.
    glTexGenf(GL_T, GL_EYE_PLANE, 1.0);
    assert_eq!(glGetError(), GL_NO_ERROR);
    // SAFETY: room for 4 values.
    unsafe { glGetTexGenfv(GL_T, GL_EYE_PLANE, eye.as_mut_ptr()) };
    assert_eq!(eye, [1.0, 0.0, 0.0, 0.0]);
    glEnable(GL_TEXTURE_GEN_T);
    assert_eq!(glIsEnabled(GL_TEXTURE_GEN_T), GL_TRUE);
    glActiveTexture(GL_TEXTURE0 + 2);
    assert_eq!(glIsEnabled(GL_TEXTURE_GEN_T), GL_FALSE, "per unit");
    glActiveTexture(GL_TEXTURE0);
    assert_eq!(glGetError(), GL_NO_ERROR);
    OSMesaDestroyContext(ctx);
}

#[test]
fn units_matrices_and_current_coordinates() {
    let mut buf = vec![0u8; 8 * 8 * 4];
    let ctx = current(&mut buf);
    assert_eq!(int(GL_MAX_TEXTURE_UNITS), 8);
    assert_eq!(int(GL_MAX_TEXTURE_SIZE), 4096);
    assert_eq!(int(GL_MAX_3D_TEXTURE_SIZE), 256);
    glMultiTexCoord2f(GL_TEXTURE0 + 1, 0.5, 0.25);
    glMultiTexCoord3sARB(GL_TEXTURE0 + 7, 1, 2, 3);
    glTexCoord1f(9.0);
    assert_eq!(floats4(GL_CURRENT_TEXTURE_COORDS), [9.0, 0.0, 0.0, 1.0]);
    glActiveTexture(GL_TEXTURE0 + 1);
    assert_eq!(floats4(GL_CURRENT_TEXTURE_COORDS), [0.5, 0.25, 0.0, 1.0]);
    glActiveTextureARB(GL_TEXTURE0 + 7);
    assert_eq!(floats4(GL_CURRENT_TEXTURE_COORDS), [1.0, 2.0, 3.0, 1.0]);
    // Each unit has its texture matrix stack.
    glMatrixMode(GL_TEXTURE);
    glScalef(2.0, 3.0, 4.0);
    assert_eq!(floats4(GL_TEXTURE_MATRIX), [2.0, 0.0, 0.0, 0.0]);
    glActiveTexture(GL_TEXTURE0);
    assert_eq!(floats4(GL_TEXTURE_MATRIX), [1.0, 0.0, 0.0, 0.0]);
    glPushMatrix();
    assert_eq!(int(GL_TEXTURE_STACK_DEPTH), 2);
    glActiveTexture(GL_TEXTURE0 + 7);
    assert_eq!(int(GL_TEXTURE_STACK_DEPTH), 1, "a stack per unit");
    glActiveTexture(GL_TEXTURE0);
    glPopMatrix();
    // GL_TRANSFORM_BIT keeps the matrix mode (not the matrices).
    glPushAttrib(GL_TRANSFORM_BIT);
    glMatrixMode(GL_MODELVIEW);
    glPopAttrib();
    assert_eq!(int(GL_MATRIX_MODE) as u32, GL_TEXTURE);
    glMultiTexCoord4d(GL_TEXTURE0 + 8, 1.0, 1.0, 1.0, 1.0);
    assert_eq!(glGetError(), GL_INVALID_ENUM);
    glActiveTexture(GL_TEXTURE0 + 8);
    assert_eq!(glGetError(), GL_INVALID_ENUM);
    glClientActiveTexture(GL_TEXTURE0 + 8);
    assert_eq!(glGetError(), GL_INVALID_ENUM);
    // The client active unit picks the coordinate array the calls name.
    let coords = [0.5f32; 8];
    glClientActiveTexture(GL_TEXTURE0 + 3);
    // SAFETY: `coords` outlives every draw of this test (none reads it).
    unsafe { glTexCoordPointer(2, GL_FLOAT, 0, coords.as_ptr().cast()) };
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    assert_eq!((int(GL_TEXTURE_COORD_ARRAY_SIZE), int(GL_TEXTURE_COORD_ARRAY)), (2, 1));
    assert_eq!(int(GL_CLIENT_ACTIVE_TEXTURE) as u32, GL_TEXTURE0 + 3);
    glClientActiveTexture(GL_TEXTURE0);
    assert_eq!((int(GL_TEXTURE_COORD_ARRAY_SIZE), int(GL_TEXTURE_COORD_ARRAY)), (4, 0));
    assert_eq!(glGetError(), GL_NO_ERROR);
    OSMesaDestroyContext(ctx);
}

#[test]
fn display_lists_copy_pixels_and_run_names_at_once() {
    let mut buf = vec![0u8; 8 * 8 * 4];
    let ctx = current(&mut buf);
    let mut texels = QUADRANTS;
    glNewList(1, GL_COMPILE);
    // Names are made at once, even while compiling.
    let t = gen_texture();
    assert!(t != 0);
    glBindTexture(GL_TEXTURE_2D, t);
    upload_rgba(2, 2, &texels);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
    // A proxy upload runs at once, never compiled.
    // SAFETY: proxies read no pixels.
    unsafe {
        glTexImage2D(
            GL_PROXY_TEXTURE_2D,
            0,
            GL_RGBA as i32,
            16,
            8,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            null(),
        )
    };
    glEndList();
    assert_eq!(level_int(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH), 16);
    // Compiled, not run: nothing bound yet.
    assert_eq!(int(GL_TEXTURE_BINDING_2D), 0);
    // The list keeps the pixels of compile time.
    texels.fill(0);
    glCallList(1);
    assert_eq!(glGetError(), GL_NO_ERROR);
    assert_eq!(int(GL_TEXTURE_BINDING_2D), t as i32);
    assert_eq!(read_rgba(0), QUADRANTS.to_vec());
    assert_eq!(tex_int(GL_TEXTURE_MAG_FILTER) as u32, GL_NEAREST);
    OSMesaDestroyContext(ctx);
}

#[test]
fn attribute_stacks_save_texture_state() {
    let mut buf = vec![0u8; 8 * 8 * 4];
    let ctx = current(&mut buf);
    let (a, b) = (gen_texture(), gen_texture());
    glBindTexture(GL_TEXTURE_2D, a);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE as i32);
    glEnable(GL_TEXTURE_2D);
    glActiveTexture(GL_TEXTURE0 + 1);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL as i32);

    glPushAttrib(GL_TEXTURE_BIT);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    glDisable(GL_TEXTURE_2D);
    glActiveTexture(GL_TEXTURE0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT as i32);
    glBindTexture(GL_TEXTURE_2D, b);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE as i32);
    glPopAttrib();
    assert_eq!(glGetError(), GL_NO_ERROR);
    // The active unit, its environment and enable, the binding and the
    // bound object's parameters come back; `b` was not bound: it keeps its change.
    assert_eq!(int(GL_ACTIVE_TEXTURE) as u32, GL_TEXTURE0 + 1);
    assert_eq!(env_int(GL_TEXTURE_ENV_MODE) as u32, GL_DECAL);
    assert_eq!(glIsEnabled(GL_TEXTURE_2D), GL_TRUE);
    glActiveTexture(GL_TEXTURE0);
    assert_eq!(int(GL_TEXTURE_BINDING_2D), a as i32);
    assert_eq!(tex_int(GL_TEXTURE_WRAP_S) as u32, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, b);
    assert_eq!(tex_int(GL_TEXTURE_WRAP_S) as u32, GL_CLAMP_TO_EDGE);

    // GL_ENABLE_BIT: the enables of every unit, not the environment.
    glPushAttrib(GL_ENABLE_BIT);
    glDisable(GL_TEXTURE_2D);
    glEnable(GL_TEXTURE_GEN_T);
    glActiveTexture(GL_TEXTURE0 + 1);
    glDisable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    glPopAttrib();
    assert_eq!(glIsEnabled(GL_TEXTURE_2D), GL_TRUE);
    assert_eq!(env_int(GL_TEXTURE_ENV_MODE) as u32, GL_MODULATE);
    glActiveTexture(GL_TEXTURE0);
    assert_eq!(
        (glIsEnabled(GL_TEXTURE_2D), glIsEnabled(GL_TEXTURE_GEN_T)),
        (GL_TRUE, GL_FALSE)
    );

    // The client stack: each unit's array and the client active unit.
    let coords = [0.0f32; 8];
    glClientActiveTexture(GL_TEXTURE0 + 2);
    glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
    // SAFETY: `coords` outlives the test; nothing draws from it.
    unsafe { glTexCoordPointer(3, GL_FLOAT, 0, coords.as_ptr().cast()) };
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glClientActiveTexture(GL_TEXTURE0);
    glPopClientAttrib();
    assert_eq!(int(GL_CLIENT_ACTIVE_TEXTURE) as u32, GL_TEXTURE0 + 2);
    assert_eq!((int(GL_TEXTURE_COORD_ARRAY), int(GL_TEXTURE_COORD_ARRAY_SIZE)), (0, 4));
    assert_eq!(glGetError(), GL_NO_ERROR);
    OSMesaDestroyContext(ctx);
}

#[test]
fn a_nearest_texture_covers_its_quadrants() {
    let mut buf = vec![0u8; 8 * 8 * 4];
    let ctx = current(&mut buf);
    glBindTexture(GL_TEXTURE_2D, gen_texture());
    upload_rgba(2, 2, &QUADRANTS);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
    glEnable(GL_TEXTURE_2D);
    // MODULATE with white: the texels themselves.
    glColor3f(1.0, 1.0, 1.0);
    quad();
    glFinish();
    assert_eq!(glGetError(), GL_NO_ERROR);
    // Rows bottom-up: texel row 0 at the bottom of the quad.
    assert_eq!(px(&buf, 1, 1), [255, 0, 0, 255]);
    assert_eq!(px(&buf, 6, 1), [0, 255, 0, 255]);
    assert_eq!(px(&buf, 1, 6), [0, 0, 255, 255]);
    assert_eq!(px(&buf, 6, 6), [255, 255, 255, 255]);
    // The same through a texture coordinate array on unit 0 and a texture
    // matrix that mirrors s: the quadrants swap left for right.
    let pos = [0.0f32, 0.0, 8.0, 0.0, 8.0, 8.0, 0.0, 8.0];
    let tc = [0.0f32, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0, 1.0];
    glMatrixMode(GL_TEXTURE);
    glTranslatef(1.0, 0.0, 0.0);
    glScalef(-1.0, 1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    // SAFETY: both arrays hold the 4 vertices drawn and outlive the draw.
    unsafe {
        glVertexPointer(2, GL_FLOAT, 0, pos.as_ptr().cast());
        glTexCoordPointer(2, GL_FLOAT, 0, tc.as_ptr().cast());
    }
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glDrawArrays(GL_QUADS, 0, 4);
    glFinish();
    assert_eq!(glGetError(), GL_NO_ERROR);
    assert_eq!(px(&buf, 1, 1), [0, 255, 0, 255]);
    assert_eq!(px(&buf, 6, 6), [0, 0, 255, 255]);
    OSMesaDestroyContext(ctx);
}

/// softgl's deterministic generator, so a failure replays.
struct Rng(softgl::rng::Rng);

impl Rng {
    fn n(&mut self, k: u64) -> u64 {
        self.0.next_u64() % k
    }

    fn pick<T: Copy>(&mut self, v: &[T]) -> T {
        self.0.pick(v)
    }

    fn size(&mut self) -> i32 {
        self.pick(&[-1, 0, 1, 1, 2, 3, 4, 5, 8])
    }

    fn float(&mut self) -> f32 {
        self.pick(&[
            f32::NAN,
            f32::INFINITY,
            -1e38,
            -2.0,
            -0.5,
            0.0,
            0.25,
            0.5,
            1.0,
            3.7,
            1e6,
            1e38,
        ])
    }
}

#[test]
fn random_texture_calls_neither_panic_nor_write_outside_the_buffers() {
    // Panics on this test's thread (the exports' guards would hide them).
    static PANICS: AtomicUsize = AtomicUsize::new(0);
    let me = std::thread::current().name().map(str::to_owned);
    let previous = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        if std::thread::current().name().map(str::to_owned) == me {
            PANICS.fetch_add(1, Ordering::SeqCst);
        }
        previous(info);
    }));
    let mut buf = vec![0u8; 8 * 8 * 4];
    let ctx = current(&mut buf);
    let mut r = Rng(softgl::rng::Rng::new(0x7E47_0012));
    // Uploads read from `src`, which holds every layout the sizes and unpack
    // values below make (at most 11,200 bytes); glGetTexImage writes into
    // `dst`, whose tail must stay untouched.
    let src: Vec<u8> = (0..16384u32).map(|k| (k * 37 % 251) as u8).collect();
    const LEN: usize = 16384;
    let mut dst = vec![0x5Cu8; LEN + 64];
    let targets = [
        GL_TEXTURE_1D,
        GL_TEXTURE_2D,
        GL_TEXTURE_3D,
        GL_TEXTURE_CUBE_MAP,
        0x8515,
        0x851A,
        GL_PROXY_TEXTURE_2D,
        0x1234,
    ];
    let internals = [
        3,
        4,
        GL_RGBA8,
        GL_LUMINANCE8,
        0x8049,
        0x8C43,
        0x8C41,
        0x803C,
        1,
        0x81A6,
        0x1234,
        0,
    ];
    let pairs = [
        (GL_RGBA, GL_UNSIGNED_BYTE),
        (GL_RGB, GL_UNSIGNED_BYTE),
        (GL_BGRA, GL_UNSIGNED_BYTE),
        (GL_LUMINANCE, GL_FLOAT),
        (GL_LUMINANCE_ALPHA, GL_SHORT),
        (GL_RGB, GL_UNSIGNED_SHORT_5_6_5),
        (GL_RGBA, 0x8033),
        (GL_BGRA, 0x8367),
        (GL_RGBA, 0x8368),
        (GL_ALPHA, GL_BYTE),
        (GL_RED, GL_UNSIGNED_INT),
    ];
    let formats = [
        GL_RGBA,
        GL_RGB,
        GL_BGRA,
        GL_LUMINANCE,
        GL_LUMINANCE_ALPHA,
        GL_ALPHA,
        GL_RED,
        GL_DEPTH_COMPONENT,
        GL_COLOR_INDEX,
        0x1234,
    ];
    let types = [
        GL_UNSIGNED_BYTE,
        GL_BYTE,
        GL_SHORT,
        GL_UNSIGNED_INT,
        GL_FLOAT,
        GL_UNSIGNED_SHORT_5_6_5,
        0x8033,
        0x8367,
        0x8368,
        0x1234,
    ];
    let pnames = [
        GL_TEXTURE_MIN_FILTER,
        GL_TEXTURE_MAG_FILTER,
        GL_TEXTURE_WRAP_S,
        GL_TEXTURE_WRAP_T,
        0x8072,
        GL_TEXTURE_MIN_LOD,
        GL_TEXTURE_MAX_LEVEL,
        0x813C,
        0x8501,
        0x8191,
        0x884C,
        0x884B,
        0x1234,
    ];
    let values = [
        GL_NEAREST,
        GL_LINEAR,
        GL_LINEAR_MIPMAP_LINEAR,
        0x2700,
        GL_REPEAT,
        GL_CLAMP_TO_EDGE,
        0x812D,
        0x8370,
        0x2900,
        0x884E,
        0,
        1,
        7,
        1000,
        0x1234,
    ];
    let env = [
        (GL_TEXTURE_ENV_MODE, GL_MODULATE),
        (GL_TEXTURE_ENV_MODE, GL_DECAL),
        (GL_TEXTURE_ENV_MODE, 0x0BE2),
        (GL_TEXTURE_ENV_MODE, 0x0104),
        (GL_TEXTURE_ENV_MODE, GL_COMBINE),
        (GL_COMBINE_RGB, GL_DOT3_RGB),
        (GL_COMBINE_RGB, 0x8575),
        (GL_SOURCE1_RGB, 0x84C5),
        (GL_SOURCE1_RGB, 0x8576),
        (GL_OPERAND2_ALPHA, GL_ONE_MINUS_SRC_ALPHA),
        (GL_RGB_SCALE, 4),
        (0x1234, 0),
    ];
    let (mut seen, mut uploads) = ([0usize; 2], [0usize; 2]);
    for step in 0..6000 {
        let t = r.pick(&targets);
        match r.n(24) {
            0..=3 => {
                for p in [
                    GL_UNPACK_ROW_LENGTH,
                    GL_UNPACK_SKIP_ROWS,
                    GL_UNPACK_SKIP_PIXELS,
                    GL_UNPACK_IMAGE_HEIGHT,
                ] {
                    glPixelStorei(p, r.pick(&[0, 0, 1, 2, 10]));
                }
                glPixelStorei(GL_UNPACK_SKIP_IMAGES, r.pick(&[0, 1]));
                glPixelStorei(GL_UNPACK_ALIGNMENT, r.pick(&[1, 2, 4, 8]));
                // Mostly valid calls (each argument bad one time in 8), so that
                // uploads of every kind are made, not only refused.
                let dims = 1 + r.n(3);
                let good = [[GL_TEXTURE_1D; 2], [GL_TEXTURE_2D, 0x8517], [GL_TEXTURE_3D; 2]][dims as usize - 1];
                let t = if r.n(8) == 0 { t } else { r.pick(&good) };
                let (w, h, d) = (r.size(), r.size(), r.size().min(4));
                let (level, border) = (r.pick(&[0, 0, 0, 1, 2, -1]), r.pick(&[0, 0, 0, 0, 1, 2]));
                let i = if r.n(8) == 0 {
                    r.pick(&internals)
                } else {
                    r.pick(&internals[..6])
                };
                let (f, ty) = if r.n(8) == 0 {
                    (r.pick(&formats), r.pick(&types))
                } else {
                    r.pick(&pairs)
                };
                let p = if r.n(8) == 0 { null() } else { src.as_ptr().cast() };
                // SAFETY: `src` holds every layout these sizes and unpack values make.
                unsafe {
                    match (dims, r.n(3)) {
                        (1, _) => glTexImage1D(t, level, i, w, border, f, ty, p),
                        (3, _) => glTexImage3D(t, level, i, w, h, d, border, f, ty, p),
                        (_, 0) => glTexSubImage2D(t, level, r.size(), r.size(), w, h, f, ty, p),
                        _ => glTexImage2D(t, level, i, w, h, border, f, ty, p),
                    }
                }
                uploads[usize::from(glGetError() == GL_NO_ERROR)] += 1;
            }
            4 => {
                for p in [
                    GL_PACK_ROW_LENGTH,
                    GL_PACK_SKIP_ROWS,
                    GL_PACK_SKIP_PIXELS,
                    GL_PACK_IMAGE_HEIGHT,
                ] {
                    glPixelStorei(p, r.pick(&[0, 0, 1, 2, 10]));
                }
                glPixelStorei(GL_PACK_ALIGNMENT, r.pick(&[1, 2, 4, 8]));
                // SAFETY: the largest level here (10 x 10 x 6 with borders, 16
                // bytes a pixel, the pack values above) fits in LEN bytes.
                unsafe {
                    glGetTexImage(
                        t,
                        r.pick(&[-1, 0, 1]),
                        r.pick(&formats),
                        r.pick(&types),
                        dst.as_mut_ptr().cast(),
                    )
                };
            }
            5 => glTexParameteri(t, r.pick(&pnames), r.pick(&values) as i32),
            6 => glTexParameterf(t, r.pick(&pnames), r.float()),
            7 => {
                let (p, v) = r.pick(&env);
                glTexEnvi(r.pick(&[GL_TEXTURE_ENV, GL_TEXTURE_ENV, 0x8500]), p, v as i32);
            }
            8 => glTexGeni(
                r.pick(&[0x2000, GL_T, GL_R, 0x2003, 0x1234]),
                GL_TEXTURE_GEN_MODE,
                r.pick(&[0x2400, GL_OBJECT_LINEAR, GL_SPHERE_MAP, 0x8511, 0x8512, 0x1234]) as i32,
            ),
            9 => glEnable(r.pick(&[
                GL_TEXTURE_1D,
                GL_TEXTURE_2D,
                GL_TEXTURE_3D,
                GL_TEXTURE_CUBE_MAP,
                0x0C60,
                GL_TEXTURE_GEN_T,
                0x0C62,
                0x0C63,
            ])),
            10 => glDisable(r.pick(&[GL_TEXTURE_2D, GL_TEXTURE_GEN_T, GL_TEXTURE_CUBE_MAP])),
            11 => glActiveTexture(GL_TEXTURE0 + r.n(10) as u32),
            12 => glBindTexture(t, r.n(6) as u32),
            13 => {
                let names: Vec<u32> = (0..r.n(3)).map(|_| r.n(6) as u32).collect();
                // SAFETY: `names` holds the count given.
                unsafe { glDeleteTextures(names.len() as i32, names.as_ptr()) };
            }
            14 => {
                gen_texture();
            }
            15 => glGenerateMipmap(t),
            16 => glCopyTexImage2D(
                t,
                r.pick(&[0, 1, -1]),
                r.pick(&[GL_RGBA, GL_RGB, 0x1902, 0x1234]),
                r.size(),
                r.size(),
                r.size(),
                r.size(),
                r.pick(&[0, 1]),
            ),
            17 => glCopyTexSubImage2D(t, 0, r.size(), r.size(), r.size(), r.size(), r.size(), r.size()),
            18 => glMultiTexCoord4f(GL_TEXTURE0 + r.n(9) as u32, r.float(), r.float(), r.float(), r.float()),
            19 => glPushAttrib(r.pick(&[GL_TEXTURE_BIT, GL_ENABLE_BIT, GL_TEXTURE_BIT | GL_ENABLE_BIT])),
            20 => glPopAttrib(),
            21 => {
                glMatrixMode(GL_TEXTURE);
                glScalef(r.float(), r.float(), 1.0);
                glMatrixMode(GL_MODELVIEW);
            }
            22 => {
                glColor4f(r.float(), 0.5, 0.5, 1.0);
                quad();
            }
            _ => current::finish_and_count_error(step, &mut seen),
        }
        assert_eq!(PANICS.load(Ordering::SeqCst), 0, "a panic at step {step}");
    }
    glFinish();
    assert!(
        dst[LEN..].iter().all(|&b| b == 0x5C),
        "written past the caller's buffer"
    );
    println!("glGetError outcomes {seen:?}, uploads failed and made {uploads:?}");
    assert!(seen[0] > 10 && seen[1] > 10, "glGetError outcomes {seen:?}");
    assert!(uploads[1] > 50, "uploads failed and made {uploads:?}");
    OSMesaDestroyContext(ctx);
}
