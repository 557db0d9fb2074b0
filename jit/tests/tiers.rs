//! Tiered compilation: the quick code (single-pass register allocation) and
//! the optimized code (backtracking) of textured keys both equal the
//! interpreter bit for bit, and a tiered specialist switches to its optimized
//! code without changing what it draws.

#[path = "support/mod.rs"]
mod support;

use softgl_jit::compile::native_unit;
use softgl_jit::shade::slot;
use softgl_jit::texture::{EnvMode, Filter, MipFilter, TextureSet, Wrap};
use softgl_jit::{
    interp, ColorFormat, FragmentKey, FragmentSpan, FragmentUniforms, Planes, Specialist, Target, Tier, SPAN_MAX,
};
use std::collections::HashSet;

/// Target size: a full span and one whose last group crosses the right edge per row.
const W: u32 = SPAN_MAX as u32 + 6;
const H: u32 = 6;

/// The keys: NEAREST and trilinear on one unit (sampled natively), a
/// trilinear and a bilinear CLAMP_TO_EDGE unit, and a CLAMP_TO_BORDER unit
/// (sampled through the callout).
fn keys() -> [(&'static str, FragmentKey); 4] {
    let one = |min, mip, wrap| support::one_unit_key(min, mip, min, wrap, EnvMode::Modulate);
    let trilinear = one(Filter::Linear, MipFilter::Linear, Wrap::Repeat);
    let two = support::with_bilinear_second_unit(trilinear);
    // With the statics of the texture they draw with (else a natively
    // sampled unit would leave the draw to the interpreter).
    let levels = levels();
    let images = support::images(&levels);
    let set = texture_set(&images);
    [
        ("nearest", one(Filter::Nearest, MipFilter::None, Wrap::Repeat)),
        ("trilinear", trilinear),
        ("two_units", two),
        ("border", one(Filter::Linear, MipFilter::Nearest, Wrap::ClampToBorder)),
    ]
    .map(|(name, key)| (name, support::bind(&key, &set)))
}

/// The texture of [`levels`] with a grey-blue border on units 0 and 1.
fn texture_set<'a>(images: &'a [softgl_jit::texture::Image<'a>]) -> TextureSet<'a> {
    let mut set = support::two_units(images);
    for tex in set.units.iter_mut().flatten() {
        tex.border = [0.2, 0.4, 0.6, 0.8];
    }
    set
}

/// A 32² RGBA8 texture's chain down to 1², seeded texels.
fn levels() -> Vec<(u32, u32, Vec<u8>)> {
    let mut rng = softgl_jit::rng::Rng::new(0x7133);
    (0..=5)
        .map(|l| {
            let s = 32 >> l;
            (s, s, (0..s * s * 4).map(|_| rng.next_u64() as u8).collect())
        })
        .collect()
}

/// Two primitives: colour gradients under unit 0 minified about 1.7× (so
/// trilinear blends two levels) and unit 1 magnified; then the coordinates
/// far from the origin and beyond the edges (the border's texels).
fn planes() -> [Planes; 2] {
    let mut near = Planes::default();
    near.constant(slot::INV_W, 1.0);
    for c in 0..4 {
        near.set(slot::COLOR + c, 0.3 + 0.1 * c as f32, 0.01, -0.02);
    }
    let d = 1.7 / 32.0;
    near.set(slot::tex(0), 0.1, d, 0.3 * d);
    near.set(slot::tex(0) + 1, -0.2, 0.2 * d, 1.9 * d);
    near.constant(slot::tex(0) + 3, 1.0);
    near.set(slot::tex(1), 0.3, 0.011, 0.002);
    near.set(slot::tex(1) + 1, 0.6, -0.003, 0.013);
    near.constant(slot::tex(1) + 3, 1.0);
    let mut far = near;
    far.set(slot::tex(0), 100.3, 0.37, 0.01);
    far.set(slot::tex(0) + 1, -7.1, 0.013, 0.29);
    far.set(slot::tex(1), -1.5, 0.05, 0.0);
    [near, far]
}

/// Two spans a row, seeded coverage, alternating primitives.
fn spans() -> Vec<FragmentSpan> {
    let mut rng = softgl_jit::rng::Rng::new(0x5a5a);
    let mut spans = Vec::new();
    for y in 0..H {
        for x in (0..W).step_by(SPAN_MAX) {
            let mut s = FragmentSpan::new(x, y);
            for i in 0..(W - x).min(SPAN_MAX as u32) as usize {
                if !rng.next_u64().is_multiple_of(8) {
                    s.set(i, [200, 150, 100, 255], 0);
                }
            }
            s.planes = (x / SPAN_MAX as u32 + y) % 2;
            spans.push(s);
        }
    }
    spans
}

/// The colour buffer after `key`'s stages ran over [`spans`] with the
/// texture on every unit the key has, on `specialist` or (`None`) the interpreter.
fn render(key: &FragmentKey, specialist: Option<&Specialist>) -> Vec<u8> {
    let levels = levels();
    let images = support::images(&levels);
    let set = texture_set(&images);
    let planes = planes();
    let spans = spans();
    let u = FragmentUniforms::default();
    let mut color: Vec<u8> = (0..W * H * 4).map(|i| (i * 7) as u8).collect();
    let mut t = Target::new(W, H, ColorFormat::Rgba8, &mut color, W as usize * 4, None, None)
        .expect("buffer sized for the target");
    match specialist {
        Some(s) => s.run_with_planes(&u, &set, &spans, &planes, &mut t),
        None => interp::run_with_planes(key, &u, &set, &spans, &planes, &mut t),
    }
    .expect("the key names the buffer");
    color
}

#[test]
fn the_keys_sample_natively_except_the_border_unit() {
    let native: Vec<bool> = keys()
        .iter()
        .map(|(_, k)| k.shade.expect("shaded").tex.iter().flatten().all(native_unit))
        .collect();
    assert_eq!(native, [true, true, true, false]);
}

#[test]
fn quick_and_optimized_code_equal_the_interpreter() {
    for (name, key) in keys() {
        let reference = render(&key, None);
        // Texels, not one colour: 100 of the 420 pixels at least (the border
        // key's far primitive reads mostly its border colour).
        let colours: HashSet<&[u8]> = reference.chunks(4).collect();
        assert!(colours.len() > 100, "{name}: only {} colours", colours.len());
        let quick = Specialist::compile_tier(&key, Tier::Quick).expect("compiles");
        let optimized = Specialist::compile_tier(&key, Tier::Optimized).expect("compiles");
        assert!(!quick.is_optimized(), "{name}");
        assert!(optimized.is_optimized(), "{name}");
        assert!(render(&key, Some(&quick)) == reference, "{name}: quick code differs");
        assert!(
            render(&key, Some(&optimized)) == reference,
            "{name}: optimized code differs"
        );
    }
}

#[test]
fn a_tiered_specialist_switches_to_optimized_code_with_the_same_output() {
    for (name, key) in keys() {
        let reference = render(&key, None);
        let tiered = Specialist::compile_tier(&key, Tier::Tiered).expect("compiles");
        // Usually still the quick code: the optimized compile takes longer than this draw.
        let before = render(&key, Some(&tiered));
        tiered.wait_optimized();
        assert!(tiered.is_optimized() && tiered.is_upgraded(), "{name}");
        assert!(before == reference, "{name}: output before the upgrade differs");
        assert!(
            render(&key, Some(&tiered)) == reference,
            "{name}: output after the upgrade differs"
        );
    }
}

#[test]
fn the_default_policy_tiers_textured_keys_only() {
    let textured = keys()[1].1;
    let plain = FragmentKey::new(ColorFormat::Rgba8, None, false);
    assert_eq!(Tier::for_key(&textured), Tier::Tiered);
    assert_eq!(Tier::for_key(&plain), Tier::Optimized);
    let s = Specialist::compile(&plain).expect("compiles");
    assert!(s.is_optimized() && !s.is_upgraded());
    // Nothing to wait for: returns at once.
    s.wait_optimized();
    let t = Specialist::compile(&textured).expect("compiles");
    t.wait_optimized();
    assert!(t.is_optimized() && t.is_upgraded());
}

#[test]
fn tier_names_parse() {
    assert_eq!(Tier::parse(Some("quick")), Some(Tier::Quick));
    assert_eq!(Tier::parse(Some(" Optimized ")), Some(Tier::Optimized));
    assert_eq!(Tier::parse(Some("tiered")), Some(Tier::Tiered));
    assert_eq!(Tier::parse(Some("fast")), None);
    assert_eq!(Tier::parse(None), None);
}

fn tiered(key: &FragmentKey) -> Result<Specialist, softgl_jit::SpecialistError> {
    Specialist::compile_tier(key, Tier::Tiered)
}

#[test]
fn the_cache_counts_upgrades_resident_and_evicted() {
    let mut cache = softgl_jit::SpecialistCache::with_compiler(2, tiered);
    for (name, key) in keys() {
        cache.get(&key).expect("compiles").wait_optimized();
        assert!(cache.get(&key).is_some_and(|s| s.is_upgraded()), "{name}");
    }
    let s = cache.stats();
    assert_eq!((s.misses, s.hits, s.evictions, s.resident, s.upgrades), (4, 4, 2, 2, 4));
    cache.set_capacity(1);
    let s = cache.stats();
    assert_eq!((s.evictions, s.resident, s.upgrades), (3, 1, 4));
}
