//! Tiered specialists dropped right after their quick compile, before the
//! background thread upgrades them, leave no module behind: the thread skips
//! the upgrade or frees the code it made. Alone in its test binary so that
//! [`live_modules`] counts only this test's modules.

#[path = "support/mod.rs"]
#[allow(dead_code, reason = "only its keys are used here")]
mod support;

use softgl_jit::specialist::live_modules;
use softgl_jit::texture::{EnvMode, Filter, MipFilter, Wrap};
use softgl_jit::{Specialist, Tier};

#[test]
fn two_hundred_tiered_specialists_dropped_at_once_free_every_module() {
    let keys = [
        support::one_unit_key(
            Filter::Linear,
            MipFilter::Linear,
            Filter::Linear,
            Wrap::Repeat,
            EnvMode::Modulate,
        ),
        support::one_unit_key(
            Filter::Nearest,
            MipFilter::None,
            Filter::Nearest,
            Wrap::ClampToEdge,
            EnvMode::Replace,
        ),
        support::one_unit_key(
            Filter::Linear,
            MipFilter::None,
            Filter::Linear,
            Wrap::ClampToBorder,
            EnvMode::Add,
        ),
    ];
    assert_eq!(live_modules(), 0);
    for i in 0..200 {
        let s = Specialist::compile_tier(&keys[i % keys.len()], Tier::Tiered).expect("compiles");
        // Some are dropped while their upgrade compiles, some before it starts.
        if i % 50 == 0 {
            std::thread::yield_now();
        }
        drop(s);
    }
    // The background thread runs its queue in order: once this upgrade is
    // installed, every job queued before it is over.
    let last = Specialist::compile_tier(&keys[0], Tier::Tiered).expect("compiles");
    last.wait_optimized();
    assert!(last.is_upgraded());
    assert_eq!(live_modules(), 2, "the last specialist's quick and optimized code only");
    drop(last);
    assert_eq!(live_modules(), 0);
}
