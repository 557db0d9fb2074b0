//! The specialist cache: LRU order, counters, capacity, and failed compiles.

use softgl_jit::cache::{capacity_from, DEFAULT_CAPACITY};
use softgl_jit::{
    ColorFormat, CompareFunc, DepthFormat, DepthKey, FragmentKey, LogicOp, Specialist, SpecialistCache, SpecialistError,
};

/// Key `i` of 16 distinct keys: a logic op each.
fn key(i: usize) -> FragmentKey {
    FragmentKey {
        logic_op: Some(LogicOp::ALL[i]),
        ..FragmentKey::new(ColorFormat::Rgba8, None, false)
    }
}

#[test]
fn counts_hits_misses_and_evictions_in_lru_order() {
    let mut cache = SpecialistCache::new(4);
    for i in 0..4 {
        assert!(cache.get(&key(i)).is_some());
    }
    // Touch key 0 so key 1 is the least recently used.
    assert_eq!(cache.get(&key(0)).map(|s| *s.key()), Some(key(0)));
    assert!(cache.get(&key(4)).is_some());
    let s = cache.stats();
    assert_eq!((s.hits, s.misses, s.evictions, s.failures, s.resident), (1, 5, 1, 0, 4));
    // Key 0 survived, key 1 was evicted and compiles again.
    cache.get(&key(0));
    cache.get(&key(1));
    let s = cache.stats();
    assert_eq!((s.hits, s.misses, s.evictions), (2, 6, 2));
    assert!(s.median_compile.is_some() && s.total_compile >= s.median_compile.unwrap());
}

#[test]
fn shrinking_the_capacity_evicts() {
    let mut cache = SpecialistCache::new(8);
    for i in 0..8 {
        cache.get(&key(i));
    }
    cache.set_capacity(3);
    let s = cache.stats();
    assert_eq!((s.capacity, s.resident, s.evictions), (3, 3, 5));
    // The three most recent stayed.
    for i in 5..8 {
        cache.get(&key(i));
    }
    assert_eq!(cache.stats().hits, 3);
    cache.set_capacity(0);
    assert_eq!(cache.stats().capacity, 1, "a capacity of 0 keeps one");
}

fn failing(_: &FragmentKey) -> Result<Specialist, SpecialistError> {
    Err(SpecialistError::Panic("refused by the test".into()))
}

#[test]
fn a_failed_compile_is_counted_and_remembered() {
    let mut cache = SpecialistCache::with_compiler(4, failing);
    assert!(cache.get(&key(0)).is_none());
    assert!(cache.get(&key(0)).is_none());
    let s = cache.stats();
    assert_eq!(
        (s.misses, s.hits, s.failures),
        (1, 1, 1),
        "compiled once, then remembered"
    );
}

#[test]
fn an_invalid_key_is_a_typed_error() {
    let key = FragmentKey {
        depth: Some(DepthKey {
            func: CompareFunc::Less,
            write: true,
        }),
        ..FragmentKey::new(ColorFormat::Rgba8, None, false)
    };
    assert!(matches!(Specialist::compile(&key), Err(SpecialistError::Key(_))));
    let ok = FragmentKey {
        depth: key.depth,
        ..FragmentKey::new(ColorFormat::Rgba8, Some(DepthFormat::D16), false)
    };
    assert!(Specialist::compile(&ok).is_ok());
}

#[test]
fn softgl_specialists_sets_the_capacity() {
    assert_eq!(capacity_from(Some("12")), 12);
    assert_eq!(capacity_from(Some(" 300 ")), 300);
    assert_eq!(capacity_from(Some("0")), DEFAULT_CAPACITY);
    assert_eq!(capacity_from(Some("many")), DEFAULT_CAPACITY);
    assert_eq!(capacity_from(None), DEFAULT_CAPACITY);
}
