//! The multisample state through the C ABI (GL 1.3 §3.2.1, §4.1.3):
//! `GL_MULTISAMPLE` and the `GL_SAMPLE_*` enables, `glSampleCoverage` (also in
//! display lists and the attribute stack), and the counts MuJoCo reads
//! (`GL_SAMPLES`, `GL_SAMPLE_BUFFERS`, `GL_MAX_SAMPLES`) with llvmpipe's
//! answers for an OSMesa buffer (docs/llvmpipe-facts.md §29).

mod current;

use OSMesa::consts::*;
use OSMesa::*;

const GL_MULTISAMPLE: u32 = 0x809D;
const GL_SAMPLE_ALPHA_TO_COVERAGE: u32 = 0x809E;
const GL_SAMPLE_ALPHA_TO_ONE: u32 = 0x809F;
const GL_SAMPLE_COVERAGE: u32 = 0x80A0;
const GL_SAMPLE_BUFFERS: u32 = 0x80A8;
const GL_SAMPLES: u32 = 0x80A9;
const GL_SAMPLE_COVERAGE_VALUE: u32 = 0x80AA;
const GL_SAMPLE_COVERAGE_INVERT: u32 = 0x80AB;
const GL_MAX_SAMPLES: u32 = 0x8D57;
const GL_MULTISAMPLE_BIT: u32 = 0x2000_0000;
const GL_ENABLE_BIT: u32 = 0x2000;
const GL_COMPILE: u32 = 0x1300;

fn int(pname: u32) -> i32 {
    let mut v = -1;
    // SAFETY: room for one value.
    unsafe { glGetIntegerv(pname, &mut v) };
    v
}

fn float(pname: u32) -> f32 {
    let mut v = -1.0;
    // SAFETY: room for one value.
    unsafe { glGetFloatv(pname, &mut v) };
    v
}

fn coverage() -> (f32, bool) {
    (float(GL_SAMPLE_COVERAGE_VALUE), int(GL_SAMPLE_COVERAGE_INVERT) != 0)
}

#[test]
fn the_multisample_state_has_gls_defaults_and_mesas_counts() {
    let mut buf = vec![0u8; 8 * 8 * 4];
    let ctx = current::current(&mut buf, 8, 8);
    // An OSMesa buffer has one sample (Mesa: GL_SAMPLES 0, GL_SAMPLE_BUFFERS 0).
    assert_eq!(
        (int(GL_SAMPLES), int(GL_SAMPLE_BUFFERS), int(GL_MAX_SAMPLES)),
        (0, 0, 4)
    );
    assert_eq!(glIsEnabled(GL_MULTISAMPLE), GL_TRUE);
    for cap in [GL_SAMPLE_COVERAGE, GL_SAMPLE_ALPHA_TO_COVERAGE, GL_SAMPLE_ALPHA_TO_ONE] {
        assert_eq!(glIsEnabled(cap), GL_FALSE, "{cap:#x}");
    }
    assert_eq!(coverage(), (1.0, false));
    glSampleCoverage(2.0, GL_TRUE);
    assert_eq!(coverage(), (1.0, true), "clamped to [0, 1]");
    glSampleCoverageARB(0.25, GL_FALSE);
    assert_eq!(coverage(), (0.25, false));
    for cap in [
        GL_MULTISAMPLE,
        GL_SAMPLE_COVERAGE,
        GL_SAMPLE_ALPHA_TO_COVERAGE,
        GL_SAMPLE_ALPHA_TO_ONE,
    ] {
        glDisable(cap);
        glEnable(cap);
        assert_eq!(glIsEnabled(cap), GL_TRUE, "{cap:#x}");
    }
    assert_eq!(glGetError(), GL_NO_ERROR);
    OSMesaDestroyContext(ctx);
}

#[test]
fn sample_coverage_is_compiled_and_pushed() {
    let mut buf = vec![0u8; 8 * 8 * 4];
    let ctx = current::current(&mut buf, 8, 8);
    glNewList(1, GL_COMPILE);
    glSampleCoverage(0.5, GL_TRUE);
    glEndList();
    assert_eq!(coverage(), (1.0, false), "compiled, not executed");
    glCallList(1);
    assert_eq!(coverage(), (0.5, true));
    glPushAttrib(GL_MULTISAMPLE_BIT);
    glSampleCoverage(0.75, GL_FALSE);
    glDisable(GL_MULTISAMPLE);
    glEnable(GL_SAMPLE_COVERAGE);
    glPopAttrib();
    assert_eq!(coverage(), (0.5, true));
    assert_eq!(
        (glIsEnabled(GL_MULTISAMPLE), glIsEnabled(GL_SAMPLE_COVERAGE)),
        (GL_TRUE, GL_FALSE)
    );
    // GL_ENABLE_BIT holds the enables, not the value.
    glPushAttrib(GL_ENABLE_BIT);
    glDisable(GL_MULTISAMPLE);
    glSampleCoverage(0.125, GL_FALSE);
    glPopAttrib();
    assert_eq!(glIsEnabled(GL_MULTISAMPLE), GL_TRUE);
    assert_eq!(coverage(), (0.125, false));
    assert_eq!(glGetError(), GL_NO_ERROR);
    OSMesaDestroyContext(ctx);
}
