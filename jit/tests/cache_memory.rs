//! Evicting a specialist frees its code: 10,000 distinct keys compiled through
//! a cache of 64 grow resident memory by less than 8 MiB. (A `JITModule`
//! dropped without `free_memory` keeps its pages: at least two per module, so
//! leaking would grow it by more than 80 MiB.) Alone in its test binary so that
//! no other test allocates while it measures.

use softgl_jit::{
    BlendFactor, BlendKey, ColorFormat, ColorMask, CompareFunc, DepthFormat, DepthKey, FragmentKey, LogicOp,
    SpecialistCache, StencilKey, StencilOp,
};
use std::collections::HashSet;

/// Resident memory in bytes, from `/proc/self/statm`.
fn resident() -> u64 {
    let statm = std::fs::read_to_string("/proc/self/statm").expect("Linux /proc");
    let pages: u64 = statm
        .split_whitespace()
        .nth(1)
        .and_then(|v| v.parse().ok())
        .expect("statm");
    pages * 4096
}

/// Distinct key `i`, by mixed radix over depth, stencil and alpha functions,
/// logic op or blend, and color mask.
fn key(i: usize) -> FragmentKey {
    let f = |n: usize| CompareFunc::ALL[n % 8];
    let color = i / 512;
    FragmentKey {
        depth: Some(DepthKey {
            func: f(i),
            write: true,
        }),
        stencil: Some(StencilKey {
            func: f(i / 8),
            fail: StencilOp::Keep,
            zfail: StencilOp::Keep,
            zpass: StencilOp::Incr,
        }),
        alpha_test: Some(f(i / 64)),
        logic_op: (color < 16).then(|| LogicOp::ALL[color]),
        blend: (color >= 16).then(|| BlendKey {
            src_rgb: BlendFactor::ALL[color - 16],
            ..BlendKey::DEFAULT
        }),
        color_mask: ColorMask {
            a: false,
            ..ColorMask::ALL
        },
        ..FragmentKey::new(ColorFormat::Rgba8, Some(DepthFormat::D24), true)
    }
    .normalized()
}

#[test]
fn ten_thousand_keys_through_a_cache_of_64_stay_within_8_mib() {
    let keys: Vec<FragmentKey> = (0..10_200).map(key).collect();
    assert_eq!(
        keys.iter().collect::<HashSet<_>>().len(),
        keys.len(),
        "keys are distinct"
    );
    let mut cache = SpecialistCache::new(64);
    // Warm up the allocator and fill the cache before measuring.
    for k in &keys[..200] {
        assert!(cache.get(k).is_some());
    }
    let before = resident();
    for k in &keys[200..] {
        assert!(cache.get(k).is_some());
    }
    let grown = resident().saturating_sub(before);
    let s = cache.stats();
    assert_eq!((s.misses, s.evictions, s.failures, s.resident), (10_200, 10_136, 0, 64));
    eprintln!("resident memory grew by {} KiB over 10,000 compiles", grown / 1024);
    assert!(grown < 8 << 20, "resident memory grew by {grown} bytes");
}
