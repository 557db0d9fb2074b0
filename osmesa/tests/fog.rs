//! Fog, secondary colour and fog coordinates through the C ABI: state,
//! queries, errors, the attribute stack, display lists, arrays and pixels.

mod current;

use current::{GL_INVALID_ENUM, GL_INVALID_VALUE};
use OSMesa::consts::*;
use OSMesa::*;

/// A context current on this thread, 8 x 8 pixels as units.
fn current(buf: &mut [u8]) -> OSMesaContext {
    current::current_in_pixels(buf, 8, 8)
}

const GL_QUADS: u32 = 7;
const GL_FOG: u32 = 0x0B60;
const GL_FOG_DENSITY: u32 = 0x0B62;
const GL_FOG_START: u32 = 0x0B63;
const GL_FOG_END: u32 = 0x0B64;
const GL_FOG_MODE: u32 = 0x0B65;
const GL_FOG_COLOR: u32 = 0x0B66;
const GL_FOG_INDEX: u32 = 0x0B61;
const GL_FOG_COORD_SRC: u32 = 0x8450;
const GL_FOG_COORD: u32 = 0x8451;
const GL_FRAGMENT_DEPTH: u32 = 0x8452;
const GL_CURRENT_FOG_COORD: u32 = 0x8453;
const GL_FOG_COORD_ARRAY: u32 = 0x8457;
const GL_COLOR_SUM: u32 = 0x8458;
const GL_CURRENT_SECONDARY_COLOR: u32 = 0x8459;
const GL_SECONDARY_COLOR_ARRAY: u32 = 0x845E;
const GL_LINEAR: u32 = 0x2601;
const GL_EXP: u32 = 0x0800;
const GL_EXP2: u32 = 0x0801;
const GL_FOG_BIT: u32 = 0x80;
const GL_ENABLE_BIT: u32 = 0x2000;
const GL_COMPILE: u32 = 0x1300;

fn float(pname: u32) -> f32 {
    let mut v = [f32::NAN; 4];
    // SAFETY: room for 4 values, the most any pname here has.
    unsafe { glGetFloatv(pname, v.as_mut_ptr()) };
    v[0]
}

fn floats4(pname: u32) -> [f32; 4] {
    let mut v = [f32::NAN; 4];
    // SAFETY: room for the 4 values.
    unsafe { glGetFloatv(pname, v.as_mut_ptr()) };
    v
}

fn int(pname: u32) -> i32 {
    let mut v = [-7i32; 4];
    // SAFETY: room for 4 values.
    unsafe { glGetIntegerv(pname, v.as_mut_ptr()) };
    v[0]
}

fn quad(z: f32) {
    glBegin(GL_QUADS);
    glVertex3f(0.0, 0.0, z);
    glVertex3f(8.0, 0.0, z);
    glVertex3f(8.0, 8.0, z);
    glVertex3f(0.0, 8.0, z);
    glEnd();
}

fn px(buf: &[u8], x: usize, y: usize) -> [u8; 4] {
    let o = (y * 8 + x) * 4;
    buf[o..o + 4].try_into().unwrap()
}

#[test]
fn fog_state_is_set_queried_and_checked() {
    let mut buf = vec![0u8; 8 * 8 * 4];
    let ctx = current(&mut buf);
    // GL's initial values.
    assert_eq!(
        (
            int(GL_FOG_MODE) as u32,
            float(GL_FOG_DENSITY),
            float(GL_FOG_START),
            float(GL_FOG_END)
        ),
        (GL_EXP, 1.0, 0.0, 1.0)
    );
    assert_eq!(int(GL_FOG_COORD_SRC) as u32, GL_FRAGMENT_DEPTH);
    assert_eq!(glIsEnabled(GL_FOG), GL_FALSE);
    glFogi(GL_FOG_MODE, GL_EXP2 as i32);
    glFogf(GL_FOG_DENSITY, 0.75);
    glFogi(GL_FOG_START, 3);
    let end = [9.5f32];
    // SAFETY: one readable value.
    unsafe { glFogfv(GL_FOG_END, end.as_ptr()) };
    let color = [0.25f32, 1.5, -1.0, 0.5];
    // SAFETY: four readable values.
    unsafe { glFogfv(GL_FOG_COLOR, color.as_ptr()) };
    glFogf(GL_FOG_INDEX, 4.0);
    glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD as i32);
    glEnable(GL_FOG);
    assert_eq!(glGetError(), GL_NO_ERROR);
    assert_eq!(
        (
            int(GL_FOG_MODE) as u32,
            float(GL_FOG_DENSITY),
            float(GL_FOG_START),
            float(GL_FOG_END)
        ),
        (GL_EXP2, 0.75, 3.0, 9.5)
    );
    assert_eq!(
        (float(GL_FOG_INDEX), int(GL_FOG_COORD_SRC) as u32, glIsEnabled(GL_FOG)),
        (4.0, GL_FOG_COORD, GL_TRUE)
    );
    assert_eq!(floats4(GL_FOG_COLOR), color);
    // glFogiv's colour maps integers onto [-1, 1].
    let icolor = [i32::MAX, 0, i32::MIN, i32::MAX];
    // SAFETY: four readable values.
    unsafe { glFogiv(GL_FOG_COLOR, icolor.as_ptr()) };
    assert_eq!(floats4(GL_FOG_COLOR), [1.0, 1.0 / 4294967295.0, -1.0, 1.0]);
    // Errors change nothing.
    glFogf(GL_FOG_DENSITY, -0.5);
    assert_eq!((glGetError(), float(GL_FOG_DENSITY)), (GL_INVALID_VALUE, 0.75));
    glFogi(GL_FOG_MODE, 0x1234);
    assert_eq!((glGetError(), int(GL_FOG_MODE) as u32), (GL_INVALID_ENUM, GL_EXP2));
    glFogi(GL_FOG_COORD_SRC, GL_LINEAR as i32);
    assert_eq!(glGetError(), GL_INVALID_ENUM);
    glFogf(0x0B67, 1.0);
    assert_eq!(glGetError(), GL_INVALID_ENUM);
    OSMesaDestroyContext(ctx);
}

#[test]
fn the_fog_bit_and_lists_save_and_replay_fog() {
    let mut buf = vec![0u8; 8 * 8 * 4];
    let ctx = current(&mut buf);
    glFogf(GL_FOG_START, 2.0);
    glPushAttrib(GL_FOG_BIT);
    glFogf(GL_FOG_START, 5.0);
    glFogi(GL_FOG_MODE, GL_LINEAR as i32);
    glEnable(GL_FOG);
    glEnable(GL_COLOR_SUM);
    glPopAttrib();
    assert_eq!((float(GL_FOG_START), int(GL_FOG_MODE) as u32), (2.0, GL_EXP));
    assert_eq!((glIsEnabled(GL_FOG), glIsEnabled(GL_COLOR_SUM)), (GL_FALSE, GL_FALSE));
    glEnable(GL_FOG);
    glPushAttrib(GL_ENABLE_BIT);
    glDisable(GL_FOG);
    glPopAttrib();
    assert_eq!(glIsEnabled(GL_FOG), GL_TRUE);
    // A list records glFog, glSecondaryColor and glFogCoord.
    glNewList(1, GL_COMPILE);
    glFogf(GL_FOG_END, 7.0);
    glSecondaryColor3ub(255, 0, 51);
    glFogCoordf(2.5);
    glEndList();
    assert_eq!((float(GL_FOG_END), float(GL_CURRENT_FOG_COORD)), (1.0, 0.0));
    glCallList(1);
    assert_eq!((float(GL_FOG_END), float(GL_CURRENT_FOG_COORD)), (7.0, 2.5));
    assert_eq!(floats4(GL_CURRENT_SECONDARY_COLOR), [1.0, 0.0, 0.2, 1.0]);
    assert_eq!(glGetError(), GL_NO_ERROR);
    OSMesaDestroyContext(ctx);
}

#[test]
fn fogged_and_summed_pixels() {
    let mut buf = vec![0u8; 8 * 8 * 4];
    let ctx = current(&mut buf);
    // Linear fog from 0 to 1 at eye depth 0.25: f = 0.75, red towards blue.
    glEnable(GL_FOG);
    glFogi(GL_FOG_MODE, GL_LINEAR as i32);
    glFogf(GL_FOG_END, 1.0);
    let blue = [0.0f32, 0.0, 1.0, 1.0];
    // SAFETY: four readable values.
    unsafe { glFogfv(GL_FOG_COLOR, blue.as_ptr()) };
    glColor4f(1.0, 0.0, 0.0, 0.6);
    quad(-0.25);
    glFinish();
    // 0.75 · 255 = 191.25, 0.25 · 255 = 63.75, alpha untouched.
    assert_eq!(px(&buf, 3, 3), [191, 0, 64, 153]);
    // Fog coordinates from an array: |−0.4| gives f = 0.6.
    glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD as i32);
    let pos = [0.0f32, 0.0, 8.0, 0.0, 8.0, 8.0, 0.0, 8.0];
    let fog = [-0.4f32; 4];
    let sec = [0u8, 64, 0, 0, 64, 0, 0, 64, 0, 0, 64, 0];
    // SAFETY: the arrays outlive the draw.
    unsafe {
        glVertexPointer(2, GL_FLOAT, 0, pos.as_ptr().cast());
        glFogCoordPointer(GL_FLOAT, 0, fog.as_ptr().cast());
        glSecondaryColorPointer(3, GL_UNSIGNED_BYTE, 0, sec.as_ptr().cast());
    }
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_FOG_COORD_ARRAY);
    glEnableClientState(GL_SECONDARY_COLOR_ARRAY);
    assert_eq!(
        (glIsEnabled(GL_FOG_COORD_ARRAY), glIsEnabled(GL_SECONDARY_COLOR_ARRAY)),
        (GL_TRUE, GL_TRUE)
    );
    glColor4f(1.0, 0.0, 0.0, 1.0);
    glDrawArrays(GL_QUADS, 0, 4);
    glFinish();
    // 0.6 · 255 = 153, 0.4 · 255 = 102 (no colour sum yet).
    assert_eq!(px(&buf, 5, 2), [153, 0, 102, 255]);
    // With the colour sum, green 64/255 is added before fog: 0.6 · 64 = 38.4.
    glEnable(GL_COLOR_SUM);
    glDrawArrays(GL_QUADS, 0, 4);
    glFinish();
    assert_eq!(px(&buf, 5, 2), [153, 38, 102, 255]);
    assert_eq!(glGetError(), GL_NO_ERROR);
    OSMesaDestroyContext(ctx);
}
