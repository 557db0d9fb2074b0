//! Display lists compile `glBegin` … `glEnd` runs of vertex attribute calls
//! into arrays replayed as one draw (`gl::lists`): every test here draws the
//! same calls made at once and through a list (compiled with `GL_COMPILE`
//! and called, and with `GL_COMPILE_AND_EXECUTE`), and wants the same bytes
//! in the colour buffer, the same current attributes afterwards and the same
//! errors. (Smooth `GL_QUADS` are the exception: a list splits them v1-v3,
//! as llvmpipe's indexed replay does, `docs/llvmpipe-facts.md` §37.)

mod current;

use current::{GL_INVALID_ENUM, GL_INVALID_OPERATION};
use OSMesa::consts::*;
use OSMesa::*;

const GL_POINTS: u32 = 0;
const GL_TRIANGLES: u32 = 4;
const GL_TRIANGLE_STRIP: u32 = 5;
const GL_QUADS: u32 = 7;
const GL_QUAD_STRIP: u32 = 8;
const GL_POLYGON: u32 = 9;
const GL_COMPILE: u32 = 0x1300;
const GL_COMPILE_AND_EXECUTE: u32 = 0x1301;
const GL_LIGHTING: u32 = 0x0B50;
const GL_LIGHT0: u32 = 0x4000;
const GL_POSITION: u32 = 0x1203;
const GL_AMBIENT_AND_DIFFUSE: u32 = 0x1602;
const GL_COLOR_MATERIAL: u32 = 0x0B57;
const GL_DEPTH_TEST: u32 = 0x0B71;
const GL_SMOOTH: u32 = 0x1D01;
const GL_CURRENT_COLOR: u32 = 0x0B00;
const GL_CURRENT_NORMAL: u32 = 0x0B02;
const GL_TEXTURE_MIN_FILTER: u32 = 0x2801;
const GL_TEXTURE_MAG_FILTER: u32 = 0x2800;
const GL_NEAREST: i32 = 0x2600;
const W: i32 = 24;

/// What a drawing leaves: the colour buffer, the current colour, normal and
/// texture coordinates, and the pending error.
#[derive(Debug, PartialEq)]
struct Outcome {
    pixels: Vec<u8>,
    current: [[f32; 4]; 3],
    error: u32,
}

fn get4(pname: u32) -> [f32; 4] {
    let mut v = [0.0f32; 4];
    // SAFETY: room for the 4 floats (3 for the normal) these names return.
    unsafe { glGetFloatv(pname, v.as_mut_ptr()) };
    v
}

/// Runs `setup` then `draw` on a fresh `W`² context: the drawing's outcome.
fn outcome(setup: fn(), draw: &dyn Fn()) -> Outcome {
    let mut buf = vec![0u8; (W * W * 4) as usize];
    let ctx = current::current_in_pixels(&mut buf, W, W);
    glClearColor(0.1, 0.2, 0.3, 1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    setup();
    draw();
    glFinish();
    let o = Outcome {
        pixels: Vec::new(),
        current: [
            get4(GL_CURRENT_COLOR),
            get4(GL_CURRENT_NORMAL),
            get4(GL_CURRENT_TEXTURE_COORDS),
        ],
        error: glGetError(),
    };
    OSMesaDestroyContext(ctx);
    Outcome { pixels: buf, ..o }
}

/// `a` and `b` equal (the differing pixels counted rather than printed).
fn check(a: &Outcome, b: &Outcome, what: &str) {
    let differ = a
        .pixels
        .chunks(4)
        .zip(b.pixels.chunks(4))
        .filter(|(p, q)| p != q)
        .count();
    assert_eq!(differ, 0, "{what}: pixels differ");
    assert_eq!((a.current, a.error), (b.current, b.error), "{what}");
}

/// `body` made at once where `outer` says, through list 1 compiled with
/// `GL_COMPILE` beforehand, and (when `execute`) compiled with
/// `GL_COMPILE_AND_EXECUTE` there: all three outcomes equal. Returns it.
fn same_as_calls(setup: fn(), body: fn(), outer: fn(&dyn Fn()), execute: bool) -> Outcome {
    let direct = outcome(setup, &|| outer(&body));
    let listed = outcome(setup, &|| {
        glNewList(1, GL_COMPILE);
        body();
        glEndList();
        assert_eq!(glGetError(), GL_NO_ERROR, "compiling records, never fails");
        outer(&|| glCallList(1));
    });
    check(&direct, &listed, "GL_COMPILE then glCallList");
    if execute {
        let both = outcome(setup, &|| {
            outer(&|| {
                glNewList(1, GL_COMPILE_AND_EXECUTE);
                body();
                glEndList();
            })
        });
        check(&direct, &both, "GL_COMPILE_AND_EXECUTE");
    }
    direct
}

fn nothing() {}

fn lit() {
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    let p = [1.0f32, 1.0, 2.0, 0.0];
    let red = [0.8f32, 0.2, 0.2, 1.0];
    // SAFETY: 4 floats each.
    unsafe {
        glLightfv(GL_LIGHT0, GL_POSITION, p.as_ptr());
        glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, red.as_ptr());
    }
}

/// A quad strip across the window, a normal per vertex (lit16's shape).
fn strip() {
    glBegin(GL_QUAD_STRIP);
    for i in 0..=6 {
        let x = i as f32 * 4.0;
        let a = i as f32 * 0.4;
        glNormal3f(a.sin(), 0.3, a.cos());
        glVertex3f(x, 2.0, 0.5);
        glNormal3f(a.sin(), -0.3, a.cos());
        glVertex3f(x, 20.0, -0.5);
    }
    glEnd();
}

#[test]
fn a_lit_strip_draws_the_same_from_a_list() {
    let o = same_as_calls(lit, strip, |list| list(), true);
    assert_ne!(
        o.pixels[..4],
        o.pixels[(W * 10 * 4 + 40) as usize..][..4],
        "something drawn"
    );
    // Called twice with another current normal between: same again.
    same_as_calls(
        lit,
        strip,
        |list| {
            list();
            glNormal3f(0.0, 0.0, 1.0);
            glTranslatef(1.0, 1.0, 0.0);
            list();
        },
        false,
    );
}

/// Colours given after some vertices: those before take the current colour
/// when the list runs (not when it was compiled), and the colour varies per
/// vertex from then on; a colour after the last vertex is current after.
fn late_colors() {
    glBegin(GL_TRIANGLES);
    glVertex2f(1.0, 1.0);
    glVertex2f(20.0, 2.0);
    glColor3f(0.0, 1.0, 0.0);
    glVertex2f(10.0, 22.0);
    glVertex2f(2.0, 12.0);
    glColor4ub(10, 20, 250, 128);
    glVertex2f(23.0, 12.0);
    glTexCoord2f(0.5, 0.25);
    glVertex2f(12.0, 1.0);
    glColor3f(0.25, 0.5, 0.75);
    glEnd();
}

#[test]
fn attributes_not_set_yet_are_the_current_ones_when_the_list_runs() {
    glColor3f(1.0, 0.0, 0.0); // no context yet: ignored
    same_as_calls(
        nothing,
        late_colors,
        |list| {
            glColor3f(1.0, 0.0, 1.0);
            glTexCoord4f(1.0, 2.0, 3.0, 4.0);
            list();
            // The vertex format the list left (its colour varies), then a
            // triangle of the current colour.
            glBegin(GL_TRIANGLES);
            glVertex2f(0.0, 20.0);
            glVertex2f(8.0, 24.0);
            glVertex2f(0.0, 24.0);
            glEnd();
            glColor3f(0.5, 0.5, 0.0);
            list();
        },
        true,
    );
}

/// A colour before `glBegin` in the list, vertices only inside: Mesa's
/// vertex format makes that colour constant, then varying at the second
/// primitive (`src/immediate.rs`).
fn color_then_quads() {
    glColor3f(0.9, 0.1, 0.1);
    glBegin(GL_QUADS);
    for (x, y) in [(1.0, 1.0), (11.0, 1.0), (11.0, 11.0), (1.0, 11.0)] {
        glVertex2f(x, y);
    }
    glEnd();
    glColor3f(0.1, 0.9, 0.1);
    glBegin(GL_TRIANGLE_STRIP);
    for (x, y) in [(12.0, 12.0), (23.0, 12.0), (12.0, 23.0), (23.0, 23.0)] {
        glVertex2f(x, y);
    }
    glEnd();
}

#[test]
fn colours_around_runs_keep_the_vertex_format() {
    same_as_calls(nothing, color_then_quads, |list| list(), true);
    same_as_calls(
        nothing,
        color_then_quads,
        |list| {
            glShadeModel(GL_SMOOTH);
            list();
            list();
        },
        false,
    );
}

fn color_material() {
    lit();
    glEnable(GL_COLOR_MATERIAL);
}

fn colored_lit_triangles() {
    glBegin(GL_TRIANGLES);
    glNormal3f(0.0, 0.0, 1.0);
    glColor3f(0.2, 0.9, 0.3);
    glVertex2f(1.0, 1.0);
    glVertex2f(22.0, 3.0);
    glColor3f(0.9, 0.9, 0.1);
    glNormal3f(0.6, 0.0, 0.8);
    glVertex2f(10.0, 22.0);
    glEnd();
}

#[test]
fn colour_material_follows_the_colours_of_a_run() {
    same_as_calls(color_material, colored_lit_triangles, |list| list(), true);
}

fn textured() {
    let texels: [u8; 16] = [255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 0, 255];
    // SAFETY: 2x2 RGBA texels.
    unsafe {
        glTexImage2D(
            GL_TEXTURE_2D,
            0,
            GL_RGBA as i32,
            2,
            2,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            texels.as_ptr().cast(),
        )
    };
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_2D);
}

/// Two polygons rather than `GL_QUADS`, whose split differs between a list and
/// the calls as it does on llvmpipe (`docs/llvmpipe-facts.md` §37).
fn textured_quads() {
    glBegin(GL_POLYGON);
    glVertex2f(1.0, 1.0); // the current coordinates
    glTexCoord2f(1.0, 0.0);
    glVertex2f(11.0, 1.0);
    glTexCoord2f(1.0, 1.0);
    glVertex2f(11.0, 11.0);
    glTexCoord2f(0.0, 1.0);
    glVertex2f(1.0, 11.0);
    glEnd();
    glBegin(GL_POLYGON);
    glTexCoord2f(0.25, 0.75);
    glVertex2f(13.0, 13.0);
    glVertex2f(23.0, 13.0);
    glColor3f(0.5, 1.0, 1.0);
    glVertex2f(23.0, 23.0);
    glTexCoord2f(0.75, 0.25);
    glVertex2f(13.0, 23.0);
    glEnd();
}

#[test]
fn texture_coordinates_of_a_run() {
    let o = same_as_calls(
        textured,
        textured_quads,
        |list| {
            glTexCoord2f(0.9, 0.1);
            list();
        },
        true,
    );
    let at = |x: i32, y: i32| o.pixels[((y * W + x) * 4) as usize..][..4].to_vec();
    assert_ne!(at(9, 3), at(3, 9), "the coordinates vary");
    // Without a texture enabled the coordinates are current state alone.
    same_as_calls(nothing, textured_quads, |list| list(), true);
}

/// A state call between vertices: the run so far and the rest are the calls.
fn material_inside() {
    glBegin(GL_TRIANGLES);
    glNormal3f(0.0, 0.0, 1.0);
    glVertex2f(1.0, 1.0);
    let green = [0.1f32, 0.8, 0.1, 1.0];
    // SAFETY: 4 floats.
    unsafe { glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, green.as_ptr()) };
    glVertex2f(22.0, 3.0);
    glNormal3f(0.6, 0.0, 0.8);
    glVertex2f(10.0, 22.0);
    glEnd();
    glBegin(GL_POINTS);
    glColor3f(1.0, 1.0, 1.0);
    glVertex2f(20.5, 20.5);
    glRectf(1.0, 20.0, 3.0, 22.0); // an error inside glBegin
    glVertex2f(21.5, 20.5);
    glEnd();
}

#[test]
fn other_calls_inside_a_run_keep_their_meaning() {
    let o = same_as_calls(lit, material_inside, |list| list(), true);
    assert_eq!(o.error, GL_INVALID_OPERATION);
}

fn begin_only() {
    glBegin(GL_TRIANGLES);
    glColor3f(0.0, 0.0, 1.0);
    glVertex2f(1.0, 1.0);
    glVertex2f(22.0, 3.0);
}

fn end_only() {
    glVertex2f(10.0, 22.0);
    glEnd();
}

#[test]
fn a_begin_in_a_list_and_its_end_outside() {
    same_as_calls(
        nothing,
        begin_only,
        |list| {
            list();
            glColor3f(1.0, 1.0, 0.0);
            glVertex2f(10.0, 22.0);
            glEnd();
        },
        false, // (glEndList between glBegin and glEnd would be an error)
    );
    same_as_calls(
        nothing,
        end_only,
        |list| {
            glBegin(GL_TRIANGLES);
            glVertex2f(1.0, 1.0);
            glVertex2f(22.0, 3.0);
            list();
        },
        false,
    );
}

#[test]
fn a_list_called_between_begin_and_end_adds_its_vertices() {
    let o = same_as_calls(
        nothing,
        strip,
        |list| {
            glBegin(GL_POLYGON);
            glVertex2f(0.0, 0.0);
            list(); // its glBegin is an error, its glEnd ends the polygon
            glVertex2f(1.0, 1.0);
        },
        false,
    );
    assert_eq!(o.error, GL_INVALID_OPERATION);
}

fn bad_begin() {
    glBegin(0x77);
    glColor3f(0.0, 1.0, 1.0);
    glVertex2f(1.0, 1.0);
    glEnd();
}

#[test]
fn errors_of_a_run_come_when_it_runs() {
    let o = same_as_calls(nothing, bad_begin, |list| list(), true);
    assert_eq!(o.error, GL_INVALID_ENUM);
    fn two_begins() {
        glBegin(GL_TRIANGLES);
        glVertex2f(1.0, 1.0);
        glBegin(GL_POINTS);
        glVertex2f(22.0, 3.0);
        glVertex2f(10.0, 22.0);
        glEnd();
        glEnd();
    }
    let o = same_as_calls(nothing, two_begins, |list| list(), true);
    assert_eq!(o.error, GL_INVALID_OPERATION);
}

#[test]
fn nested_lists_replay_their_runs() {
    let direct = outcome(lit, &|| {
        strip();
        late_colors();
    });
    let nested = outcome(lit, &|| {
        glNewList(2, GL_COMPILE);
        strip();
        glEndList();
        glNewList(3, GL_COMPILE);
        glCallList(2);
        late_colors();
        glEndList();
        glCallList(3);
    });
    check(&direct, &nested, "nested");
}
