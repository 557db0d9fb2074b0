//! What GL allows between `glBegin` and `glEnd` (piglit's
//! `gl-1.0-beginend-coverage`), through the C ABI: the colour index and edge
//! flag as current state, edge flags drawn by polygon mode `GL_LINE` (from
//! `glEdgeFlag` and from `glEdgeFlagPointer`), evaluator calls that generate
//! nothing without a map, the calls that are errors there, and unimplemented
//! commands compiled into display lists; and `glEnable` of a client array,
//! which Mesa accepts (piglit's line-flat-clip-color relies on it).

mod current;

use current::{GL_INVALID_ENUM, GL_INVALID_OPERATION};
use OSMesa::consts::*;
use OSMesa::*;

const GL_POLYGON: u32 = 9;
const GL_TRIANGLES: u32 = 4;
const GL_FRONT_AND_BACK: u32 = 0x0408;
const GL_LINE: u32 = 0x1B01;
const GL_CURRENT_INDEX: u32 = 0x0B01;
const GL_EDGE_FLAG: u32 = 0x0B43;
const GL_CURRENT_BIT: u32 = 0x1;
const GL_COMPILE: u32 = 0x1300;
const W: usize = 8;

/// A context current on this thread drawing into `buf` (W x W RGBA bytes),
/// pixels as units.
fn current(buf: &mut [u8]) -> OSMesaContext {
    current::current_in_pixels(buf, W as i32, W as i32)
}

fn green_at(buf: &[u8], x: usize, y: usize) -> bool {
    let o = (y * W + x) * 4;
    buf[o..o + 4] == [0, 255, 0, 255]
}

fn get_float(pname: u32) -> f32 {
    let mut v = -1.0f32;
    // SAFETY: one writable float for these single-valued names.
    unsafe { glGetFloatv(pname, &mut v) };
    v
}

fn get_bool(pname: u32) -> u8 {
    let mut v = 7u8;
    // SAFETY: one writable boolean.
    unsafe { glGetBooleanv(pname, &mut v) };
    v
}

/// The square piglit's gl-1.0-edgeflag draws: bottom and top edges flagged,
/// the sides not. Returns which of bottom, top, left, right are green.
fn square_edges(buf: &[u8]) -> [bool; 4] {
    [
        green_at(buf, 3, 1),
        green_at(buf, 3, 5),
        green_at(buf, 1, 3),
        green_at(buf, 5, 3),
    ]
}

const SQUARE: [[f32; 2]; 4] = [[1.5, 1.5], [5.5, 1.5], [5.5, 5.5], [1.5, 5.5]];

#[test]
fn index_and_edge_flag_are_current_state_allowed_between_begin_and_end() {
    let mut buf = vec![0u8; W * W * 4];
    let ctx = current(&mut buf);
    glBegin(GL_TRIANGLES);
    glIndexf(3.5);
    glEdgeFlag(GL_FALSE);
    glEvalCoord1f(0.5);
    glEvalCoord2d(0.5, 0.25);
    glEvalPoint1(2);
    glEvalPoint2(1, 2);
    glEnd();
    assert_eq!(glGetError(), GL_NO_ERROR);
    assert_eq!((get_float(GL_CURRENT_INDEX), get_bool(GL_EDGE_FLAG)), (3.5, GL_FALSE));
    glPushAttrib(GL_CURRENT_BIT);
    glIndexub(200);
    glEdgeFlag(GL_TRUE);
    assert_eq!((get_float(GL_CURRENT_INDEX), get_bool(GL_EDGE_FLAG)), (200.0, GL_TRUE));
    glPopAttrib();
    assert_eq!((get_float(GL_CURRENT_INDEX), get_bool(GL_EDGE_FLAG)), (3.5, GL_FALSE));
    // No map is enabled: the evaluator calls made no vertex, so this is one
    // triangle covering the lower-left half, not a shifted one.
    glColor3f(0.0, 1.0, 0.0);
    glBegin(GL_TRIANGLES);
    glVertex2f(0.0, 0.0);
    glEvalCoord1f(0.5);
    glVertex2f(8.0, 0.0);
    glVertex2f(0.0, 8.0);
    glEnd();
    glFinish();
    assert!(green_at(&buf, 1, 1) && !green_at(&buf, 6, 6));
    OSMesaDestroyContext(ctx);
}

#[test]
fn polygon_mode_line_draws_only_flagged_edges() {
    let mut buf = vec![0u8; W * W * 4];
    let ctx = current(&mut buf);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glColor3f(0.0, 1.0, 0.0);
    glBegin(GL_POLYGON);
    for (i, [x, y]) in SQUARE.into_iter().enumerate() {
        glEdgeFlag(u8::from(i % 2 == 0));
        glVertex2f(x, y);
    }
    glEnd();
    glFinish();
    assert_eq!(square_edges(&buf), [true, true, false, false]);

    // The same from arrays, and with every flag set all four edges.
    buf.fill(0);
    let flags = [GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE];
    // SAFETY: both arrays outlive the draws below.
    unsafe {
        glVertexPointer(2, GL_FLOAT, 0, SQUARE.as_ptr().cast());
        glEdgeFlagPointer(0, flags.as_ptr().cast());
    }
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_EDGE_FLAG_ARRAY);
    glDrawArrays(GL_POLYGON, 0, 4);
    glFinish();
    assert_eq!(square_edges(&buf), [true, true, false, false]);
    glDisableClientState(GL_EDGE_FLAG_ARRAY);
    glEdgeFlag(GL_TRUE);
    glDrawArrays(GL_POLYGON, 0, 4);
    glFinish();
    assert_eq!(square_edges(&buf), [true, true, true, true]);
    assert_eq!(glGetError(), GL_NO_ERROR);
    OSMesaDestroyContext(ctx);
}

#[test]
fn client_state_flush_and_buffers_are_errors_between_begin_and_end() {
    let mut buf = vec![0u8; W * W * 4];
    let ctx = current(&mut buf);
    let calls: [(&str, fn()); 7] = [
        ("glEnableClientState", || glEnableClientState(GL_VERTEX_ARRAY)),
        // SAFETY: a null pointer is never read.
        ("glVertexPointer", || unsafe {
            glVertexPointer(2, GL_FLOAT, 0, std::ptr::null())
        }),
        ("glFlush", || glFlush()),
        ("glFinish", || glFinish()),
        ("glDrawBuffer", || glDrawBuffer(0x0404)),
        ("glListBase", || glListBase(1)),
        ("glPushClientAttrib", || glPushClientAttrib(1)),
    ];
    for (name, call) in calls {
        glBegin(GL_TRIANGLES);
        call();
        glEnd();
        assert_eq!(glGetError(), GL_INVALID_OPERATION, "{name}");
    }
    OSMesaDestroyContext(ctx);
}

#[test]
fn compiled_commands_fail_when_the_list_runs_and_queries_at_once() {
    let mut buf = vec![0u8; W * W * 4];
    let ctx = current(&mut buf);
    let list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    // No accumulation buffer was asked for: GL_INVALID_OPERATION, but only
    // when the list runs (glAccum is compiled).
    glAccum(0x0100, 1.0); // GL_ACCUM
    glEndList();
    assert_eq!(glGetError(), GL_NO_ERROR);
    glCallList(list);
    assert_eq!(glGetError(), GL_INVALID_OPERATION);
    // A query is never compiled: its error comes at once.
    glNewList(list, GL_COMPILE);
    let mut map = [0.0f32; 1];
    // SAFETY: a bad query name writes nothing.
    unsafe { glGetMapfv(0x0D97, 0x0A03, map.as_mut_ptr()) }; // GL_MAP1_VERTEX_3, not a query name
    assert_eq!(glGetError(), GL_INVALID_ENUM);
    // Queries that succeed run at once too.
    map[0] = 7.0;
    // SAFETY: room for the map's one entry.
    unsafe { glGetPixelMapfv(0x0C70, map.as_mut_ptr()) }; // GL_PIXEL_MAP_I_TO_I
    assert_eq!((glGetError(), map[0]), (GL_NO_ERROR, 0.0));
    glEndList();
    glCallList(list);
    assert_eq!(glGetError(), GL_NO_ERROR);
    OSMesaDestroyContext(ctx);
}

#[test]
fn gl_enable_switches_client_arrays_as_mesa_does() {
    let mut buf = vec![0u8; W * W * 4];
    let ctx = current(&mut buf);
    let full = [[0.0f32, 0.0], [8.0, 0.0], [8.0, 8.0], [0.0, 8.0]];
    // SAFETY: the array outlives the draw.
    unsafe { glVertexPointer(2, GL_FLOAT, 0, full.as_ptr().cast()) };
    glEnable(GL_VERTEX_ARRAY);
    assert_eq!((glGetError(), glIsEnabled(GL_VERTEX_ARRAY)), (GL_NO_ERROR, GL_TRUE));
    glColor3f(0.0, 1.0, 0.0);
    glDrawArrays(GL_POLYGON, 0, 4);
    glFinish();
    assert!(green_at(&buf, 4, 4));
    glDisable(GL_VERTEX_ARRAY);
    assert_eq!(glIsEnabled(GL_VERTEX_ARRAY), GL_FALSE);
    OSMesaDestroyContext(ctx);
}
