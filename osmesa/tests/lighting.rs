//! The lighting and clip plane entry points through the C ABI: state,
//! queries, GL errors, the attribute stack and display lists.

use OSMesa::consts::*;
use OSMesa::*;

mod current;
use current::{current, GL_INVALID_ENUM, GL_INVALID_OPERATION, GL_INVALID_VALUE};

const GL_LIGHTING: u32 = 0x0B50;
const GL_LIGHT0: u32 = 0x4000;
const GL_NORMALIZE: u32 = 0x0BA1;
const GL_RESCALE_NORMAL: u32 = 0x803A;
const GL_COLOR_MATERIAL: u32 = 0x0B57;
const GL_CLIP_PLANE0: u32 = 0x3000;
const GL_AMBIENT: u32 = 0x1200;
const GL_DIFFUSE: u32 = 0x1201;
const GL_POSITION: u32 = 0x1203;
const GL_SPOT_DIRECTION: u32 = 0x1204;
const GL_SPOT_EXPONENT: u32 = 0x1205;
const GL_SPOT_CUTOFF: u32 = 0x1206;
const GL_LINEAR_ATTENUATION: u32 = 0x1208;
const GL_EMISSION: u32 = 0x1600;
const GL_SHININESS: u32 = 0x1601;
const GL_AMBIENT_AND_DIFFUSE: u32 = 0x1602;
const GL_LIGHT_MODEL_TWO_SIDE: u32 = 0x0B52;
const GL_LIGHT_MODEL_AMBIENT: u32 = 0x0B53;
const GL_LIGHT_MODEL_COLOR_CONTROL: u32 = 0x81F8;
const GL_SEPARATE_SPECULAR_COLOR: u32 = 0x81FA;
const GL_COLOR_MATERIAL_PARAMETER: u32 = 0x0B56;
const GL_CURRENT_NORMAL: u32 = 0x0B02;
const GL_MAX_LIGHTS: u32 = 0x0D31;
const GL_LIGHTING_BIT: u32 = 0x40;
const GL_TRANSFORM_BIT: u32 = 0x1000;
const GL_ENABLE_BIT: u32 = 0x2000;
const GL_COMPILE: u32 = 0x1300;
const GL_TRIANGLES: u32 = 4;

fn get_light(light: u32, pname: u32) -> [f32; 4] {
    let mut v = [-9.0f32; 4];
    // SAFETY: room for 4 floats.
    unsafe { glGetLightfv(light, pname, v.as_mut_ptr()) };
    v
}

fn get_material(face: u32, pname: u32) -> [f32; 4] {
    let mut v = [-9.0f32; 4];
    // SAFETY: room for 4 floats.
    unsafe { glGetMaterialfv(face, pname, v.as_mut_ptr()) };
    v
}

#[test]
fn light_state_round_trips_and_positions_are_in_eye_space() {
    let mut buf = vec![0u8; 4 * 4 * 4];
    let ctx = current(&mut buf, 4, 4);
    assert_eq!(get_light(GL_LIGHT0, GL_DIFFUSE), [1.0, 1.0, 1.0, 1.0]);
    assert_eq!(get_light(GL_LIGHT0 + 1, GL_DIFFUSE), [0.0, 0.0, 0.0, 1.0]);
    assert_eq!(get_light(GL_LIGHT0, GL_POSITION), [0.0, 0.0, 1.0, 0.0]);
    glTranslatef(1.0, 2.0, 3.0);
    let pos = [1.0f32, 1.0, 1.0, 1.0];
    let dir = [0.0f32, 0.0, -1.0];
    // SAFETY: 4 and 3 readable floats.
    unsafe {
        glLightfv(GL_LIGHT0 + 2, GL_POSITION, pos.as_ptr());
        glLightfv(GL_LIGHT0 + 2, GL_SPOT_DIRECTION, dir.as_ptr());
    }
    assert_eq!(get_light(GL_LIGHT0 + 2, GL_POSITION), [2.0, 3.0, 4.0, 1.0]);
    assert_eq!(get_light(GL_LIGHT0 + 2, GL_SPOT_DIRECTION)[..3], [0.0, 0.0, -1.0]);
    glLightf(GL_LIGHT0 + 2, GL_SPOT_CUTOFF, 45.0);
    glLighti(GL_LIGHT0 + 2, GL_SPOT_EXPONENT, 7);
    assert_eq!(get_light(GL_LIGHT0 + 2, GL_SPOT_CUTOFF)[0], 45.0);
    assert_eq!(get_light(GL_LIGHT0 + 2, GL_SPOT_EXPONENT)[0], 7.0);
    assert_eq!(glGetError(), GL_NO_ERROR);
    // Integer colours: the largest integer is 1.0.
    let white = [i32::MAX; 4];
    // SAFETY: 4 readable ints.
    unsafe { glLightiv(GL_LIGHT0 + 3, GL_AMBIENT, white.as_ptr()) };
    assert_eq!(get_light(GL_LIGHT0 + 3, GL_AMBIENT), [1.0; 4]);
    let mut iv = [0i32; 4];
    // SAFETY: room for 4 ints.
    unsafe { glGetLightiv(GL_LIGHT0 + 3, GL_AMBIENT, iv.as_mut_ptr()) };
    assert_eq!(iv, [i32::MAX; 4]);
    let mut max = 0;
    // SAFETY: room for one int.
    unsafe { glGetIntegerv(GL_MAX_LIGHTS, &mut max) };
    assert_eq!(max, 8);
    OSMesaDestroyContext(ctx);
}

#[test]
fn bad_light_and_material_values_are_gl_errors() {
    let mut buf = vec![0u8; 4 * 4 * 4];
    let ctx = current(&mut buf, 4, 4);
    glLightf(GL_LIGHT0 + 8, GL_SPOT_CUTOFF, 10.0);
    assert_eq!(glGetError(), GL_INVALID_ENUM);
    glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 91.0);
    assert_eq!(glGetError(), GL_INVALID_VALUE);
    glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 180.0);
    assert_eq!(glGetError(), GL_NO_ERROR);
    glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 129.0);
    assert_eq!(glGetError(), GL_INVALID_VALUE);
    glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, -1.0);
    assert_eq!(glGetError(), GL_INVALID_VALUE);
    // A vector parameter through the scalar call: the value and three zeros
    // (Mesa's `_mesa_Lightf`), no error.
    glLightf(GL_LIGHT0 + 3, GL_POSITION, 1.0);
    assert_eq!(glGetError(), GL_NO_ERROR);
    assert_eq!(get_light(GL_LIGHT0 + 3, GL_POSITION), [1.0, 0.0, 0.0, 0.0]);
    glMaterialf(GL_FRONT, GL_SHININESS, 128.5);
    assert_eq!(glGetError(), GL_INVALID_VALUE);
    glMaterialf(GL_FRONT, GL_SHININESS, -0.5);
    assert_eq!(glGetError(), GL_INVALID_VALUE);
    glMaterialf(0x1234, GL_SHININESS, 1.0);
    assert_eq!(glGetError(), GL_INVALID_ENUM);
    glEnable(GL_LIGHT0 + 8);
    assert_eq!(glGetError(), GL_INVALID_ENUM);
    glEnable(GL_CLIP_PLANE0 + 6);
    assert_eq!(glGetError(), GL_INVALID_ENUM);
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, 0x1234);
    assert_eq!(glGetError(), GL_INVALID_ENUM);
    glMaterialf(GL_FRONT, GL_EMISSION, 0.5); // as Mesa's TAG(Materialf): no error
    assert_eq!(glGetError(), GL_NO_ERROR);
    assert_eq!(get_material(GL_FRONT, GL_EMISSION)[0], 0.5);
    glMaterialf(GL_FRONT, GL_EMISSION, 0.0);
    glLightModelf(GL_LIGHT_MODEL_AMBIENT, 0.25); // (0.25, 0, 0, 0), as `_mesa_LightModelf`
    assert_eq!(glGetError(), GL_NO_ERROR);
    let mut ambient = [-1.0f32; 4];
    // SAFETY: room for 4 floats.
    unsafe { glGetFloatv(GL_LIGHT_MODEL_AMBIENT, ambient.as_mut_ptr()) };
    assert_eq!(ambient, [0.25, 0.0, 0.0, 0.0]);
    glColorMaterial(GL_FRONT, 0x1234);
    assert_eq!(glGetError(), GL_INVALID_ENUM);
    let eq = [1.0f64, 0.0, 0.0, 0.0];
    // SAFETY: 4 readable doubles.
    unsafe { glClipPlane(GL_CLIP_PLANE0 + 6, eq.as_ptr()) };
    assert_eq!(glGetError(), GL_INVALID_ENUM);
    // glMaterial is allowed between glBegin and glEnd, glLight is not.
    glBegin(GL_TRIANGLES);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 3.0);
    glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 1.0);
    glEnd();
    assert_eq!(glGetError(), GL_INVALID_OPERATION);
    assert_eq!(get_material(GL_BACK, GL_SHININESS)[0], 3.0);
    // There, GL_INVALID_OPERATION comes before any argument check.
    let mut plane = [0.0f64; 4];
    glBegin(GL_TRIANGLES);
    glLightModelf(0x1234, 1.0);
    glEnd();
    assert_eq!(glGetError(), GL_INVALID_OPERATION);
    glBegin(GL_TRIANGLES);
    // SAFETY: room for 4 doubles.
    unsafe { glGetClipPlane(0, plane.as_mut_ptr()) };
    glEnd();
    assert_eq!(glGetError(), GL_INVALID_OPERATION);
    OSMesaDestroyContext(ctx);
}

#[test]
fn materials_colour_material_and_the_model() {
    let mut buf = vec![0u8; 4 * 4 * 4];
    let ctx = current(&mut buf, 4, 4);
    assert_eq!(get_material(GL_FRONT, GL_AMBIENT), [0.2, 0.2, 0.2, 1.0]);
    assert_eq!(get_material(GL_BACK, GL_DIFFUSE), [0.8, 0.8, 0.8, 1.0]);
    let red = [1.0f32, 0.0, 0.0, 0.5];
    // SAFETY: 4 readable floats.
    unsafe { glMaterialfv(GL_BACK, GL_AMBIENT_AND_DIFFUSE, red.as_ptr()) };
    assert_eq!(get_material(GL_BACK, GL_AMBIENT), red);
    assert_eq!(get_material(GL_BACK, GL_DIFFUSE), red);
    assert_eq!(get_material(GL_FRONT, GL_DIFFUSE), [0.8, 0.8, 0.8, 1.0]);
    // GL_FRONT_AND_BACK is not a face to query.
    get_material(GL_FRONT_AND_BACK, GL_DIFFUSE);
    assert_eq!(glGetError(), GL_INVALID_ENUM);
    // Colour material: the material follows the current colour.
    glColorMaterial(GL_FRONT, GL_EMISSION);
    glEnable(GL_COLOR_MATERIAL);
    glColor4f(0.25, 0.5, 0.75, 1.0);
    assert_eq!(get_material(GL_FRONT, GL_EMISSION), [0.25, 0.5, 0.75, 1.0]);
    assert_eq!(get_material(GL_BACK, GL_EMISSION), [0.0, 0.0, 0.0, 1.0]);
    let mut mode = 0;
    // SAFETY: room for one int each.
    unsafe {
        glGetIntegerv(GL_COLOR_MATERIAL_PARAMETER, &mut mode);
    }
    assert_eq!(mode as u32, GL_EMISSION);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR as i32);
    let mut v = [0i32; 2];
    // SAFETY: room for one int each.
    unsafe {
        glGetIntegerv(GL_LIGHT_MODEL_TWO_SIDE, &mut v[0]);
        glGetIntegerv(GL_LIGHT_MODEL_COLOR_CONTROL, &mut v[1]);
    }
    assert_eq!(v, [1, GL_SEPARATE_SPECULAR_COLOR as i32]);
    glNormal3b(0, 127, 0);
    let mut n = [0f32; 3];
    // SAFETY: room for 3 floats.
    unsafe { glGetFloatv(GL_CURRENT_NORMAL, n.as_mut_ptr()) };
    assert_eq!(n, [1.0 / 255.0, 1.0, 1.0 / 255.0]);
    assert_eq!(glGetError(), GL_NO_ERROR);
    OSMesaDestroyContext(ctx);
}

#[test]
fn clip_planes_are_kept_in_eye_space() {
    let mut buf = vec![0u8; 4 * 4 * 4];
    let ctx = current(&mut buf, 4, 4);
    glTranslatef(0.0, 0.0, -5.0);
    let eq = [0.0f64, 0.0, 1.0, 1.0];
    let mut got = [9.0f64; 4];
    // SAFETY: 4 readable doubles, room for 4.
    unsafe {
        glClipPlane(GL_CLIP_PLANE0 + 5, eq.as_ptr());
        glGetClipPlane(GL_CLIP_PLANE0 + 5, got.as_mut_ptr());
    }
    // z_obj + 1 >= 0 with z_obj = z_eye + 5: z_eye + 6 >= 0.
    assert_eq!(got, [0.0, 0.0, 1.0, 6.0]);
    glEnable(GL_CLIP_PLANE0 + 5);
    assert_eq!(glIsEnabled(GL_CLIP_PLANE0 + 5), GL_TRUE);
    assert_eq!(glGetError(), GL_NO_ERROR);
    OSMesaDestroyContext(ctx);
}

#[test]
fn the_attribute_stack_and_display_lists_hold_lighting() {
    let mut buf = vec![0u8; 4 * 4 * 4];
    let ctx = current(&mut buf, 4, 4);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0 + 1);
    glPushAttrib(GL_LIGHTING_BIT | GL_TRANSFORM_BIT);
    glDisable(GL_LIGHTING);
    glDisable(GL_LIGHT0 + 1);
    glEnable(GL_NORMALIZE);
    glEnable(GL_CLIP_PLANE0);
    glMaterialf(GL_FRONT, GL_SHININESS, 50.0);
    glPopAttrib();
    assert_eq!(glIsEnabled(GL_LIGHTING), GL_TRUE);
    assert_eq!(glIsEnabled(GL_LIGHT0 + 1), GL_TRUE);
    assert_eq!(glIsEnabled(GL_NORMALIZE), GL_FALSE);
    assert_eq!(glIsEnabled(GL_CLIP_PLANE0), GL_FALSE);
    assert_eq!(get_material(GL_FRONT, GL_SHININESS)[0], 0.0);
    // GL_ENABLE_BIT restores the enables only.
    glPushAttrib(GL_ENABLE_BIT);
    glEnable(GL_RESCALE_NORMAL);
    glMaterialf(GL_FRONT, GL_SHININESS, 9.0);
    glPopAttrib();
    assert_eq!(glIsEnabled(GL_RESCALE_NORMAL), GL_FALSE);
    assert_eq!(get_material(GL_FRONT, GL_SHININESS)[0], 9.0);
    // A display list compiles lighting calls and runs them later.
    let list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glLightf(GL_LIGHT0 + 4, GL_SPOT_CUTOFF, 20.0);
    glMaterialf(GL_FRONT, GL_SHININESS, 12.0);
    glEnable(GL_COLOR_MATERIAL);
    glEndList();
    assert_eq!(get_light(GL_LIGHT0 + 4, GL_SPOT_CUTOFF)[0], 180.0);
    assert_eq!(glIsEnabled(GL_COLOR_MATERIAL), GL_FALSE);
    glCallList(list);
    assert_eq!(get_light(GL_LIGHT0 + 4, GL_SPOT_CUTOFF)[0], 20.0);
    assert_eq!(get_material(GL_FRONT, GL_SHININESS)[0], 12.0);
    assert_eq!(glIsEnabled(GL_COLOR_MATERIAL), GL_TRUE);
    assert_eq!(glGetError(), GL_NO_ERROR);
    OSMesaDestroyContext(ctx);
}
