//! Thousands of GL calls with random enumerants, sizes and floats (NaN,
//! infinities, ±1e38, negative sizes) through the C ABI: no panic happens
//! (not even one the export's guard would catch), every `glGetError` code is
//! a GL error, and nothing is written outside the caller's buffer.

mod current;

use std::ptr::null_mut;
use std::sync::atomic::{AtomicUsize, Ordering};
use OSMesa::consts::*;
use OSMesa::*;

static PANICS: AtomicUsize = AtomicUsize::new(0);

/// softgl's deterministic generator, so a failure replays.
struct Rng(softgl::rng::Rng);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0.next_u64()
    }

    fn pick<T: Copy>(&mut self, v: &[T]) -> T {
        self.0.pick(v)
    }

    fn f(&mut self) -> f32 {
        let special = [
            f32::NAN,
            f32::INFINITY,
            -f32::INFINITY,
            0.0,
            1.0,
            -1.0,
            1e38,
            -1e38,
            0.5,
            1e-7,
        ];
        if self.next().is_multiple_of(3) {
            self.pick(&special)
        } else {
            (self.next() % 2001) as f32 / 1000.0 - 1.0
        }
    }

    fn i(&mut self) -> i32 {
        self.pick(&[-1, 0, 1, 2, 3, 7, 8, 255, 1000, 16384, 16385, i32::MAX, i32::MIN])
    }

    /// A valid enumerant of some GL 1.x call, or a bad one.
    fn e(&mut self) -> u32 {
        self.pick(&[
            0,
            1,
            2,
            3,
            4,
            5,
            6,
            7,
            8,
            9,
            10,
            0x200,
            0x201,
            0x203,
            0x207,
            0x300,
            0x302,
            0x303,
            0x308,
            0x404,
            0x405,
            0x408,
            0x900,
            0x901,
            0x0B44,
            0x0B71,
            0x0B90,
            0x0BC0,
            0x0BE2,
            0x0BF2,
            0x0BD0,
            0x0C11,
            0x8037,
            0x2A01,
            0x2A02,
            0x0B50,
            0x0DE1,
            0x0BA1,
            0x1500,
            0x1506,
            0x150F,
            0x1700,
            0x1701,
            0x1702,
            0x1B00,
            0x1B01,
            0x1B02,
            0x1D00,
            0x1D01,
            0x1E00,
            0x1E01,
            0x1E02,
            0x150A,
            0x8006,
            0x8007,
            0x800B,
            0x8001,
            0x8074,
            0x8076,
            0x1401,
            0x1406,
            0x1908,
            0x1907,
            0x1902,
            0x1901,
            0x0BA2,
            0x0BA6,
            0x0C23,
            0x0D33,
            0x0CF5,
            0x0D05,
            0x0C50,
            0x1102,
            0x2A23,
            0xFFFF_FFFF,
            0x1234,
        ])
    }
}

const W: i32 = 9;
const H: i32 = 7;
const ROW: i32 = W + 3; // largest OSMESA_ROW_LENGTH tried
const TAIL: usize = 64;

#[test]
fn random_calls_neither_panic_nor_write_outside_the_buffer() {
    std::panic::set_hook(Box::new(|_| {
        PANICS.fetch_add(1, Ordering::SeqCst);
    }));
    let image = (ROW * H * 4) as usize;
    let mut buf = vec![0u8; image + TAIL];
    buf[image..].fill(0x5C);
    let ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 8, null_mut());
    // SAFETY: `buf` holds ROW x H RGBA pixels, more than any layout tried needs.
    assert_eq!(
        unsafe { OSMesaMakeCurrent(ctx, buf.as_mut_ptr().cast(), GL_UNSIGNED_BYTE, W, H) },
        GL_TRUE
    );
    let mut r = Rng(softgl::rng::Rng::new(0x9E37_79B9));
    let mut read = vec![0u8; (W * H * 4) as usize + TAIL];
    let mut ints = [0i32; 16];
    let mut floats = [0f32; 16];
    let mut seen = [0usize; 2]; // glGetError: no error, an error
    for step in 0..20_000 {
        match r.next() % 40 {
            0 => glEnable(r.e()),
            1 => glDisable(r.e()),
            2 => glClear(r.pick(&[
                GL_COLOR_BUFFER_BIT,
                GL_DEPTH_BUFFER_BIT,
                GL_STENCIL_BUFFER_BIT,
                0x4700,
                1,
            ])),
            3 => glClearColor(r.f(), r.f(), r.f(), r.f()),
            4 => glViewport(r.i(), r.i(), r.i(), r.i()),
            5 => glScissor(r.i(), r.i(), r.i(), r.i()),
            6 => glDepthRange(f64::from(r.f()), f64::from(r.f())),
            7 => glMatrixMode(r.e()),
            8 => glLoadIdentity(),
            9 => glRotatef(r.f() * 360.0, r.f(), r.f(), r.f()),
            10 => glOrtho(
                f64::from(r.f()),
                f64::from(r.f()),
                f64::from(r.f()),
                1.0,
                -1.0,
                f64::from(r.f()),
            ),
            11 => glFrustum(-1.0, 1.0, -1.0, 1.0, f64::from(r.f()), f64::from(r.f()) * 10.0),
            12 => glPushMatrix(),
            13 => glPopMatrix(),
            14 => glBegin(r.e()),
            15..=17 => glVertex3f(r.f(), r.f(), r.f()),
            18 => glColor4f(r.f(), r.f(), r.f(), r.f()),
            19 => glEnd(),
            20 => glBlendFunc(r.e(), r.e()),
            21 => glBlendEquation(r.e()),
            22 => glDepthFunc(r.e()),
            23 => glStencilFunc(r.e(), r.i(), r.next() as u32),
            24 => glStencilOp(r.e(), r.e(), r.e()),
            25 => glAlphaFunc(r.e(), r.f()),
            26 => glLogicOp(r.e()),
            27 => glPolygonMode(r.e(), r.e()),
            28 => glPolygonOffset(r.f() * 100.0, r.f() * 100.0),
            29 => glPointSize(r.f() * 20.0),
            30 => glLineWidth(r.f() * 20.0),
            31 => glCullFace(r.e()),
            32 => glShadeModel(r.e()),
            33 => {
                // SAFETY: 16 ints hold every value glGetIntegerv returns.
                unsafe { glGetIntegerv(r.e(), ints.as_mut_ptr()) }
            }
            34 => {
                // SAFETY: 16 floats hold every value glGetFloatv returns.
                unsafe { glGetFloatv(r.e(), floats.as_mut_ptr()) }
            }
            35 => {
                // Within the framebuffer's size, default pack state: fits `read`.
                let (x, y) = (r.i().clamp(-3, W), r.i().clamp(-3, H));
                let (w, h) = ((r.next() % (W as u64 + 1)) as i32, (r.next() % (H as u64 + 1)) as i32);
                let format = r.pick(&[GL_RGBA, GL_DEPTH_COMPONENT, GL_STENCIL_INDEX, 0x1234]);
                let ty = if format == GL_RGBA { GL_UNSIGNED_BYTE } else { GL_FLOAT };
                let ty = if format == GL_STENCIL_INDEX {
                    GL_UNSIGNED_BYTE
                } else {
                    ty
                };
                // SAFETY: w * h * 4 bytes at most, with 4-byte row alignment; `read` is larger.
                unsafe { glReadPixels(x, y, w, h, format, ty, read.as_mut_ptr().cast()) }
            }
            36 => OSMesaPixelStore(OSMESA_Y_UP, (r.next() % 2) as i32),
            37 => OSMesaPixelStore(OSMESA_ROW_LENGTH, r.pick(&[-1, 0, 2, W, W + 1, ROW])),
            38 => glRectf(r.f() * 10.0, r.f() * 10.0, r.f() * 10.0, r.f() * 10.0),
            _ => current::finish_and_count_error(step, &mut seen),
        }
        assert_eq!(PANICS.load(Ordering::SeqCst), 0, "a panic at step {step}");
    }
    glEnd();
    glFinish();
    assert!(
        buf[image..].iter().all(|&b| b == 0x5C),
        "written past the caller's buffer"
    );
    // The run exercised both sides: calls that failed and calls that drew.
    assert!(seen[0] > 20 && seen[1] > 20, "glGetError outcomes {seen:?}");
    assert!(
        buf[..image].iter().any(|&b| b != 0),
        "nothing was ever drawn or cleared"
    );
    OSMesaDestroyContext(ctx);
    let _ = std::panic::take_hook();
}
