//! Texturing through the C ABI: texture objects, uploads sized from the
//! unpack state and read back, errors, display lists.

mod current;

use current::{GL_INVALID_ENUM, GL_INVALID_OPERATION, GL_INVALID_VALUE};
use std::ffi::c_void;
use std::ptr::null;
use OSMesa::consts::*;
use OSMesa::*;

/// A context current on this thread, 8 x 8 pixels as units.
fn current(buf: &mut [u8]) -> OSMesaContext {
    current::current_in_pixels(buf, 8, 8)
}

const GL_QUADS: u32 = 7;
const GL_COMPILE: u32 = 0x1300;
const GL_TEXTURE_MAG_FILTER: u32 = 0x2800;
const GL_TEXTURE_PRIORITY: u32 = 0x8066;
const GL_TEXTURE_WIDTH: u32 = 0x1000;
const GL_TEXTURE_HEIGHT: u32 = 0x1001;
const GL_TEXTURE_INTERNAL_FORMAT: u32 = 0x1003;
const GL_NEAREST: u32 = 0x2600;
const GL_RGBA8: i32 = 0x8058;
const GL_LUMINANCE8: i32 = 0x8040;

fn int(pname: u32) -> i32 {
    let mut v = [-7i32; 16];
    // SAFETY: room for 16 values, the most any pname here has.
    unsafe { glGetIntegerv(pname, v.as_mut_ptr()) };
    v[0]
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
