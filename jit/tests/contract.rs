//! The contract between the back ends: for random valid keys, uniforms, spans
//! and framebuffer contents, in every format, the buffers after a specialist
//! runs are bit-identical to the buffers after the interpreter runs.
//!
//! Keys and uniforms come from proptest strategies (so failures shrink to a
//! small key); the framebuffer and the spans come from a seeded generator whose
//! values are drawn from small pools half the time, so that equal depths, equal
//! stencil values, references and wrap-around edges actually occur.

#[allow(dead_code, reason = "the texel bench's texture sets are not used here")]
mod support;

use proptest::prelude::*;
use proptest::sample::select;
use softgl_jit::compile::SplatUniforms;
use softgl_jit::interp;
use softgl_jit::texture::{
    effective_combine, BaseFormat, CombineFn, CombineKey, CombineSrc, DepthMode, EnvMode, Filter, Image, MipFilter,
    Operand, SamplerKey, SamplerStatics, TexTarget, TexUnitKey, TexelFormat, TextureRef, Wrap, MAX_UNITS,
};
use softgl_jit::{
    BlendEquation, BlendFactor, BlendKey, ColorFormat, ColorMask, CompareFunc, DepthFormat, DepthKey, DepthTarget,
    DrawTextures, FragmentKey, FragmentSpan, FragmentUniforms, LogicOp, Specialist, StencilKey, StencilOp, Target,
    Tier, SPAN_MAX,
};
use softgl_jit::{DeepUniforms, FogMode, FogUniforms, Planes, ShadeKey, TextureSet};

/// Every colour format, the deep ones too (whose specialists run
/// `compile/deep.rs`).
const COLOR_FORMATS: [ColorFormat; 10] = [
    ColorFormat::Rgba8,
    ColorFormat::Bgra8,
    ColorFormat::Rgb8,
    ColorFormat::Rgb565,
    ColorFormat::Rgba16,
    ColorFormat::Rgba32F,
    ColorFormat::Rgbx16,
    ColorFormat::Rgba16F,
    ColorFormat::Rgbx16F,
    ColorFormat::Rgbx32F,
];

/// The deep formats.
const DEEP_FORMATS: [ColorFormat; 6] = [
    ColorFormat::Rgba16,
    ColorFormat::Rgba32F,
    ColorFormat::Rgbx16,
    ColorFormat::Rgba16F,
    ColorFormat::Rgbx16F,
    ColorFormat::Rgbx32F,
];

fn compare() -> impl Strategy<Value = CompareFunc> {
    select(&CompareFunc::ALL[..])
}

fn stencil_op() -> impl Strategy<Value = StencilOp> {
    select(&StencilOp::ALL[..])
}

fn blend_key() -> impl Strategy<Value = BlendKey> {
    let f = || select(&BlendFactor::ALL[..]);
    let e = || select(&BlendEquation::ALL[..]);
    (f(), f(), f(), f(), e(), e()).prop_map(|(src_rgb, dst_rgb, src_alpha, dst_alpha, eq_rgb, eq_alpha)| BlendKey {
        src_rgb,
        dst_rgb,
        src_alpha,
        dst_alpha,
        eq_rgb,
        eq_alpha,
    })
}

/// Any key, normalized (so it is valid for the buffers it names).
fn key() -> impl Strategy<Value = FragmentKey> {
    let buffers = (
        select(&COLOR_FORMATS[..]),
        prop::option::of(select(
            &[DepthFormat::D16, DepthFormat::D24, DepthFormat::D32, DepthFormat::D32F][..],
        )),
        any::<bool>(),
    );
    let stencil = prop::option::of((compare(), stencil_op(), stencil_op(), stencil_op()));
    let depth = prop::option::of((compare(), any::<bool>()));
    let color = (
        prop::option::of(blend_key()),
        prop::option::of(select(&LogicOp::ALL[..])),
        any::<bool>(),
        any::<[bool; 4]>(),
    );
    (
        buffers,
        any::<bool>(),
        prop::option::of(compare()),
        stencil,
        depth,
        color,
        any::<bool>(),
    )
        .prop_map(
            |((format, depth_format, stencil_buffer), scissor, alpha, stencil, depth, color, count)| {
                let (blend, logic_op, dither, [r, g, b, a]) = color;
                FragmentKey {
                    scissor,
                    alpha_test: alpha,
                    stencil: stencil.map(|(func, fail, zfail, zpass)| StencilKey {
                        func,
                        fail,
                        zfail,
                        zpass,
                    }),
                    depth: depth.map(|(func, write)| DepthKey { func, write }),
                    // Half the keys blend, the other half use the logic op when both are drawn.
                    blend: if logic_op.is_some() && dither { None } else { blend },
                    logic_op: if blend.is_some() && !dither { None } else { logic_op },
                    dither,
                    color_mask: ColorMask { r, g, b, a },
                    count,
                    ..FragmentKey::new(format, depth_format, stencil_buffer)
                }
                .normalized()
            },
        )
}

/// Floats where the deep formats' stages have edges: 0 and 1, the span's
/// byte values over 255, values past [0, 1] and infinities.
const DEEP_FLOATS: [f32; 17] = [
    0.0,
    -0.0,
    1.0,
    0.5,
    128.0 / 255.0,
    1.0 / 255.0,
    254.0 / 255.0,
    1.5,
    -0.25,
    1e30,
    f32::INFINITY,
    f32::NEG_INFINITY,
    // Half floats' edges: the largest, past it, a denormal, below the least.
    65504.0,
    -65535.0,
    3.0e-6,
    -1.0e-5,
    2.0e-8,
];

/// The deep formats' uniforms: alpha reference and constant colour from
/// [`DEEP_FLOATS`] or any in [-0.5, 1.5], clamping on or off.
fn deep_uniforms() -> impl Strategy<Value = DeepUniforms> {
    let float = || prop_oneof![select(&DEEP_FLOATS[..]), -0.5f32..1.5];
    (float(), [float(), float(), float(), float()], any::<bool>()).prop_map(|(alpha_ref, k, clamp)| DeepUniforms {
        alpha_ref: alpha_ref.to_bits(),
        blend_color: k.map(f32::to_bits),
        clamp: u32::from(clamp),
    })
}

fn uniforms() -> impl Strategy<Value = FragmentUniforms> {
    (
        (-4i32..40, -4i32..8, -4i32..90, -4i32..8),
        any::<[u8; 4]>(),
        select(&[0u8, 1, 127, 128, 254, 255][..]),
        select(&[0u8, 1, 2, 127, 254, 255][..]),
        select(&[0xffu8, 0x0f, 0xf0, 0x01, 0x00, 0xa5][..]),
        select(&[0xffu8, 0x0f, 0xf0, 0x01, 0x00, 0x5a][..]),
        deep_uniforms(),
    )
        .prop_map(
            |((x0, y0, x1, y1), blend_color, alpha_ref, stencil_ref, vm, wm, deep)| FragmentUniforms {
                scissor: [x0, y0, x1, y1],
                blend_color,
                alpha_ref,
                stencil_ref,
                stencil_value_mask: vm,
                stencil_write_mask: wm,
                fog: FogUniforms::default(),
                deep,
            },
        )
}

/// softgl's deterministic generator, with the bulk data drawn from it.
struct Rng(softgl_jit::rng::Rng);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0.next_u64()
    }

    fn below(&mut self, n: u64) -> u64 {
        self.0.below(n)
    }

    /// A byte: half the time from the values where the stages have edges.
    fn byte(&mut self) -> u8 {
        const POOL: [u8; 8] = [0, 1, 2, 127, 128, 254, 255, 0x5a];
        if self.next() & 1 == 0 {
            POOL[self.below(8) as usize]
        } else {
            self.next() as u8
        }
    }

    /// A stored float channel: from [`DEEP_FLOATS`] (or x86's default NaN)
    /// half the time, else in [-0.5, 1.5].
    fn deep_float(&mut self) -> f32 {
        match self.below(4) {
            0 | 1 => self.below(3001) as f32 / 2000.0 - 0.5,
            2 if self.below(8) == 0 => f32::from_bits(0xffc0_0000),
            _ => DEEP_FLOATS[self.below(DEEP_FLOATS.len() as u64) as usize],
        }
    }

    /// A depth value for `max`: half the time from a pool that collides with the buffer's.
    fn depth(&mut self, max: u32) -> u32 {
        let pool = [0, 1, max / 2, max - 1, max, 0x1234, u32::MAX];
        if self.next() & 1 == 0 {
            pool[self.below(pool.len() as u64) as usize]
        } else {
            self.next() as u32
        }
    }
}

/// Owned buffers for one target.
#[derive(Clone, Debug, PartialEq)]
struct Buffers {
    width: u32,
    height: u32,
    stride: usize,
    top_down: bool,
    format: ColorFormat,
    color: Vec<u8>,
    depth16: Option<Vec<u16>>,
    depth32: Option<(DepthFormat, Vec<u32>)>,
    stencil: Option<Vec<u8>>,
    /// The fragments counted by keys that count (`FragmentKey::count`).
    passed: u64,
}

impl Buffers {
    /// Runs `f` on the buffers' target, adding what it counts to `passed`.
    fn counted(&mut self, f: impl FnOnce(&mut Target<'_>)) {
        let mut t = self.target();
        f(&mut t);
        let n = t.samples_passed();
        self.passed += n;
    }

    fn random(key: &FragmentKey, rng: &mut Rng) -> Buffers {
        let width = 1 + rng.below(90) as u32;
        let height = 1 + rng.below(5) as u32;
        let bpp = key.color_format.bytes_per_pixel();
        // Rows of floats start at a float (a row's padding is whole floats).
        let pad = match key.color_format.is_float() {
            true => 4 * rng.below(2) as usize,
            false => rng.below(8) as usize,
        };
        let stride = width as usize * bpp + pad;
        let n = (width * height) as usize;
        let color_len = stride * (height as usize - 1) + width as usize * bpp;
        let color = match key.color_format.is_float() {
            // Floats (half formats' too: any f32 in store is read as it is).
            true => (0..color_len / 4)
                .flat_map(|_| rng.deep_float().to_ne_bytes())
                .chain((0..color_len % 4).map(|_| 0))
                .collect(),
            false => (0..color_len).map(|_| rng.byte()).collect(),
        };
        let (mut depth16, mut depth32) = (None, None);
        match key.depth_format {
            Some(DepthFormat::D16) => depth16 = Some((0..n).map(|_| rng.depth(0xffff) as u16).collect()),
            // Float depth: any bits up to 1.0's are a float in [0, 1].
            Some(f @ DepthFormat::D32F) => {
                depth32 = Some((
                    f,
                    (0..n).map(|_| rng.depth(f.max_value()) % (f.max_value() + 1)).collect(),
                ))
            }
            Some(f) => depth32 = Some((f, (0..n).map(|_| rng.depth(f.max_value()) & f.max_value()).collect())),
            None => {}
        }
        let stencil = key.stencil_buffer.then(|| (0..n).map(|_| rng.byte()).collect());
        Buffers {
            width,
            height,
            stride,
            top_down: rng.next() & 1 == 0,
            format: key.color_format,
            color,
            depth16,
            depth32,
            stencil,
            passed: 0,
        }
    }

    fn target(&mut self) -> Target<'_> {
        let depth = match (&mut self.depth16, &mut self.depth32) {
            (Some(d), _) => Some(DepthTarget::D16(d)),
            (None, Some((DepthFormat::D24, d))) => Some(DepthTarget::D24(d)),
            (None, Some((DepthFormat::D32F, d))) => Some(DepthTarget::D32F(d)),
            (None, Some((_, d))) => Some(DepthTarget::D32(d)),
            (None, None) => None,
        };
        Target::new(
            self.width,
            self.height,
            self.format,
            &mut self.color,
            self.stride,
            depth,
            self.stencil.as_deref_mut(),
        )
        .expect("buffers sized for the target")
        .with_top_down(self.top_down)
    }
}

/// Spans over (and a little beyond) the target, with random coverage.
fn spans(b: &Buffers, key: &FragmentKey, rng: &mut Rng) -> Vec<FragmentSpan> {
    let max = key.depth_format.map_or(u32::MAX, DepthFormat::max_value);
    (0..1 + rng.below(6))
        .map(|_| {
            let mut s = FragmentSpan::new(
                rng.below(u64::from(b.width) + 6) as u32,
                rng.below(u64::from(b.height) + 1) as u32,
            );
            s.len = rng.below(SPAN_MAX as u64 + 1) as u32;
            s.mask = match rng.below(3) {
                0 => u64::MAX,
                _ => rng.next(),
            };
            for i in 0..SPAN_MAX {
                (s.r[i], s.g[i], s.b[i], s.a[i]) = (rng.byte(), rng.byte(), rng.byte(), rng.byte());
                s.z[i] = rng.depth(max);
            }
            s
        })
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 600, ..ProptestConfig::default() })]

    #[test]
    fn jit_equals_interpreter(key in key(), u in uniforms(), seed in any::<u64>()) {
        let mut rng = Rng(softgl_jit::rng::Rng::new((seed ^ (seed >> 32)) as u32));
        let mut interp_buf = Buffers::random(&key, &mut rng);
        let spans = spans(&interp_buf, &key, &mut rng);
        let mut jit_buf = interp_buf.clone();
        let specialist = Specialist::compile(&key).expect("a valid key compiles");
        interp_buf.counted(|t| interp::run(&key, &u, &spans, t).expect("the key names the buffers"));
        jit_buf.counted(|t| specialist.run(&u, &spans, t).expect("the key names the buffers"));
        prop_assert_eq!(jit_buf.passed, interp_buf.passed, "counts differ");
        prop_assert!(key.count || interp_buf.passed == 0, "only counting keys count");
        prop_assert_eq!(&jit_buf.color, &interp_buf.color, "color differs");
        prop_assert_eq!(&jit_buf.depth16, &interp_buf.depth16, "depth differs");
        prop_assert_eq!(&jit_buf.depth32, &interp_buf.depth32, "depth differs");
        prop_assert_eq!(&jit_buf.stencil, &interp_buf.stencil, "stencil differs");
    }
}

/// Shading stages: any combination, flat or not, with or without
/// multisampling's alpha stages (alpha to coverage at any sample's
/// threshold, alpha to one).
fn shade_key() -> impl Strategy<Value = ShadeKey> {
    let fog = prop::option::of(select(&[FogMode::Linear, FogMode::Exp, FogMode::Exp2][..]));
    let coverage = (prop::option::of(0u8..4), any::<bool>())
        .prop_map(|(quarters, to_one)| softgl_jit::AlphaCoverage { quarters, to_one });
    (any::<[bool; 4]>(), fog, coverage).prop_map(|([color, flat, color_sum, depth], fog, coverage)| ShadeKey {
        color,
        flat,
        color_sum,
        fog,
        depth,
        tex: Default::default(),
        coverage,
    })
}

/// A float for a plane or a fog parameter: from a pool of edge values (zeros,
/// ties, huge, infinite, NaN) a quarter of the time, else of any magnitude
/// between 1e-3 and 1e3 with either sign.
fn float(rng: &mut Rng) -> f32 {
    const POOL: [f32; 10] = [0.0, -0.0, 0.5, 1.0, -1.0, 1e30, -1e30, f32::INFINITY, f32::NAN, 2.5e-3];
    if rng.below(4) == 0 {
        return POOL[rng.below(POOL.len() as u64) as usize];
    }
    let mag = 10f32.powf(rng.below(6001) as f32 / 1000.0 - 3.0);
    if rng.next() & 1 == 0 {
        mag
    } else {
        -mag
    }
}

/// Random planes, with colours and depth mostly in range so that most fragments do not saturate.
fn planes(rng: &mut Rng) -> Planes {
    let mut p = Planes::default();
    for k in 0..softgl_jit::shade::PLANES {
        let scale = if rng.below(3) == 0 { 1.0 } else { 1e-3 };
        let a0 = if rng.below(2) == 0 {
            rng.below(1000) as f32 / 999.0
        } else {
            float(rng)
        };
        p.set(k, a0, float(rng) * scale, float(rng) * scale);
    }
    // 1/w exactly 1 (every glOrtho draw: the specialists skip the division),
    // with slopes of either sign of zero, or 1 at the lanes' first pixel only.
    let inv_w = softgl_jit::shade::slot::INV_W;
    match rng.below(6) {
        0 => p.set(inv_w, 1.0, 0.0, 0.0),
        1 => p.set(inv_w, 1.0, -0.0, -0.0),
        2 => p.set(inv_w, 1.0, 0.0, f32::MIN_POSITIVE),
        _ => {}
    }
    p
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, ..ProptestConfig::default() })]

    /// Keys with a shading stage: random planes per span, random fog values.
    #[test]
    fn shaded_jit_equals_interpreter(
        key in key(),
        shade in shade_key(),
        u in uniforms(),
        fog in (any::<[bool; 2]>(), 0u32..1000, 0u32..1000, 0u32..1000, any::<[u8; 3]>()),
        seed in any::<u64>(),
    ) {
        let key = FragmentKey { shade: Some(shade), ..key };
        let mut rng = Rng(softgl_jit::rng::Rng::new((seed ^ (seed >> 32)) as u32));
        let (same, negative, start, end, density, color) = (fog.0[0], fog.0[1], fog.1, fog.2, fog.3, fog.4);
        let (start, end) = (start as f32 / 100.0, if same { start as f32 / 100.0 } else { end as f32 / 50.0 });
        let density = if negative { float(&mut rng).abs() } else { density as f32 / 200.0 };
        let u = FragmentUniforms {
            fog: FogUniforms::new(start, end, density, color.map(|c| f32::from(c) / 255.0)),
            ..u
        };
        let (jit_buf, interp_buf) = run_both(&key, Tier::Optimized, &u, &TextureSet::default(), &mut rng, planes);
        prop_assert_eq!(&jit_buf, &interp_buf, "buffers differ");
    }
}

/// Planes for the loop over a span's full groups: 1/w mostly exactly 1,
/// colours mostly in range, else up to and across the bound under which
/// that loop converts them without the clamp to 255
/// (`Planes::colour_bounded`: `|a0| + (|dadx| + |dady|) · extent <= 2^22`).
fn loop_planes(rng: &mut Rng) -> Planes {
    let mut p = planes(rng);
    if rng.below(8) != 0 {
        p.constant(softgl_jit::shade::slot::INV_W, 1.0);
    }
    // `n / div` of either sign, `n` below `below`.
    let signed = |rng: &mut Rng, below: u64, div: f32| {
        let v = rng.below(below) as f32 / div;
        if rng.next() & 1 == 0 {
            v
        } else {
            -v
        }
    };
    for c in 0..4 {
        let k = softgl_jit::shade::slot::COLOR + c;
        let (a0, dx, dy) = match rng.below(6) {
            // In range, across the pixels of a span or two.
            0..=2 => (
                rng.below(1000) as f32 / 999.0,
                signed(rng, 100, 4000.0),
                signed(rng, 100, 400.0),
            ),
            // Near the bound: 2^22 with the extent's slopes, either side.
            3 => {
                let a0 = 4_194_304.0 - rng.below(20_000) as f32;
                let a0 = if rng.next() & 1 == 0 { a0 } else { -a0 };
                (a0, signed(rng, 40, 1.0), signed(rng, 40, 1.0))
            }
            // Past 2^31 / 255 (the conversion's overflow) at some pixels.
            4 => (signed(rng, 2, 1.0) * 8.5e6, signed(rng, 2, 1.0) * 1e5, 0.0),
            _ => (float(rng), float(rng), float(rng)),
        };
        p.set(k, a0, dx, dy);
    }
    p
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    /// Keys that test no lane (whose spans' leading full groups run in a
    /// loop of their own) with a smooth colour or none, spans mostly whole
    /// or whole to some lane: the loop, its bounded conversion and the
    /// general loop after it equal the interpreter.
    #[test]
    fn full_group_loop_equals_interpreter(
        key in key(),
        shade in shade_key(),
        shaded in 0u32..4,
        seed in any::<u64>(),
    ) {
        let shade = ShadeKey { color: shaded != 0, flat: shade.flat && shaded == 1, ..shade };
        let key = FragmentKey {
            alpha_test: None,
            stencil: None,
            depth: None,
            shade: (shaded != 3 || shade.fog.is_some()).then_some(shade),
            ..key
        }
        .normalized();
        let mut rng = Rng(softgl_jit::rng::Rng::new((seed ^ (seed >> 32)) as u32));
        let mut interp_buf = Buffers::random(&key, &mut rng);
        let mut spans = spans(&interp_buf, &key, &mut rng);
        for s in &mut spans {
            let n = rng.below(65);
            s.mask = match rng.below(4) {
                0 | 1 => u64::MAX,
                2 => u64::MAX.checked_shr(64 - n as u32).unwrap_or(0),
                _ => u64::MAX.checked_shr(64 - n as u32).unwrap_or(0) | (rng.next() << n.min(63)),
            };
        }
        let planes: Vec<Planes> = (0..1 + rng.below(3)).map(|_| loop_planes(&mut rng)).collect();
        for s in &mut spans {
            s.planes = rng.below(planes.len() as u64) as u32;
        }
        let u = FragmentUniforms::default();
        let mut jit_buf = interp_buf.clone();
        let specialist = Specialist::compile_tier(&key, Tier::Optimized).expect("a valid key compiles");
        interp_buf.counted(|t| {
            interp::run_with_planes(&key, &u, &TextureSet::default(), &spans, &planes, t)
                .expect("the key names the buffers")
        });
        jit_buf.counted(|t| {
            specialist
                .run_with_planes(&u, &TextureSet::default(), &spans, &planes, t)
                .expect("the key names the buffers")
        });
        prop_assert_eq!(jit_buf.passed, interp_buf.passed, "counts differ");
        prop_assert_eq!(&jit_buf.color, &interp_buf.color, "color differs");
    }
}

#[test]
fn a_span_without_its_planes_is_an_error() {
    let key = FragmentKey {
        shade: Some(ShadeKey {
            color: true,
            ..ShadeKey::default()
        }),
        ..FragmentKey::new(ColorFormat::Rgba8, None, false)
    };
    let mut color = vec![0u8; 16];
    let mut target = Target::new(4, 1, ColorFormat::Rgba8, &mut color, 16, None, None).unwrap();
    let mut span = FragmentSpan::new(0, 0);
    span.set(0, [1, 2, 3, 4], 0);
    span.planes = 1;
    let planes = [Planes::default()];
    assert_eq!(
        interp::run_with_planes(
            &key,
            &FragmentUniforms::default(),
            &TextureSet::default(),
            std::slice::from_ref(&span),
            &planes,
            &mut target
        ),
        Err(interp::FragmentError::MissingPlanes)
    );
    let s = Specialist::compile(&key).unwrap();
    assert_eq!(
        s.run_with_planes(
            &FragmentUniforms::default(),
            &TextureSet::default(),
            std::slice::from_ref(&span),
            &planes,
            &mut target
        ),
        Err(interp::FragmentError::MissingPlanes)
    );
    assert_eq!(color, vec![0u8; 16]);
}

/// The 565 ordered dither in compiled code divides by 255 as `(n + 1 + (n >> 8)) >> 8`;
/// that identity must hold over every value the packing can form (`c * 63 + 247`).
#[test]
fn division_by_255_identity_holds_over_the_packing_range() {
    for n in 0u32..=255 * 63 + 247 {
        assert_eq!((n + 1 + (n >> 8)) >> 8, n / 255, "n = {n}");
    }
}

/// One fogged fragment by hand: constant planes (1/w = 1), EXP fog of density
/// ln 2 at coordinate 1 halves the colour towards the fog colour.
#[test]
fn a_fogged_fragment_by_hand() {
    let key = FragmentKey {
        shade: Some(ShadeKey {
            color: true,
            fog: Some(FogMode::Exp),
            ..ShadeKey::default()
        }),
        ..FragmentKey::new(ColorFormat::Rgba8, None, false)
    };
    let mut p = Planes::default();
    for (k, v) in [(0, 1.0), (1, 1.0), (2, 0.0), (3, 0.2), (4, 0.6), (8, 1.0)] {
        p.constant(k, v);
    }
    let u = FragmentUniforms {
        fog: FogUniforms::new(0.0, 1.0, std::f32::consts::LN_2, [0.0, 1.0, 0.2]),
        ..FragmentUniforms::default()
    };
    let mut span = FragmentSpan::new(0, 0);
    for i in 0..4 {
        span.set(i, [9, 9, 9, 9], 0);
    }
    let run = |jit: bool| {
        let mut color = vec![0u8; 16];
        let mut target = Target::new(4, 1, ColorFormat::Rgba8, &mut color, 16, None, None).unwrap();
        let spans = std::slice::from_ref(&span);
        if jit {
            let s = Specialist::compile(&key).unwrap();
            s.run_with_planes(&u, &TextureSet::default(), spans, &[p], &mut target)
                .unwrap();
        } else {
            interp::run_with_planes(&key, &u, &TextureSet::default(), spans, &[p], &mut target).unwrap();
        }
        color
    };
    // f = 2^-(ln2 · log2 e) ≈ 0.5: r = 0.5 → 127.5 → 128 (or 127), g 0.5, b 0.2, alpha 0.6.
    let interp = run(false);
    assert_eq!(&interp[..4], &[128, 128, 51, 153]);
    assert_eq!(run(true), interp);
}

/// Texture targets, half the time 2D (the target compiled natively).
fn tex_target() -> impl Strategy<Value = TexTarget> {
    select(
        &[
            TexTarget::D2,
            TexTarget::D2,
            TexTarget::D2,
            TexTarget::D1,
            TexTarget::D3,
            TexTarget::Cube,
            TexTarget::Rect,
        ][..],
    )
}

/// Texel formats, half the time RGBA8 (the format compiled natively).
fn texel_format() -> impl Strategy<Value = TexelFormat> {
    select(
        &[
            TexelFormat::Rgba8,
            TexelFormat::Rgba8,
            TexelFormat::Rgba8,
            TexelFormat::Srgba8,
            TexelFormat::Rgba16,
            TexelFormat::Depth32F,
        ][..],
    )
}

/// Wrap modes, mostly REPEAT and CLAMP_TO_EDGE (the modes compiled natively).
fn wrap() -> impl Strategy<Value = Wrap> {
    select(
        &[
            Wrap::Repeat,
            Wrap::Repeat,
            Wrap::ClampToEdge,
            Wrap::ClampToEdge,
            Wrap::Clamp,
            Wrap::ClampToBorder,
            Wrap::MirroredRepeat,
        ][..],
    )
}

fn sampler_key() -> impl Strategy<Value = SamplerKey> {
    let filter = || select(&[Filter::Nearest, Filter::Linear][..]);
    (
        tex_target(),
        texel_format(),
        (
            filter(),
            select(&[MipFilter::None, MipFilter::Nearest, MipFilter::Linear][..]),
            filter(),
        ),
        [wrap(), wrap(), wrap()],
        prop::option::of(compare()),
        select(&[DepthMode::Luminance, DepthMode::Intensity, DepthMode::Alpha][..]),
    )
        .prop_map(|(target, format, (min, mip, mag), mut wrap, compare, depth_mode)| {
            let dims = match target {
                TexTarget::D1 => 1,
                TexTarget::D2 | TexTarget::Cube | TexTarget::Rect => 2,
                TexTarget::D3 => 3,
            };
            for w in wrap.iter_mut().skip(dims) {
                *w = Wrap::Repeat;
            }
            // Rectangle textures: no mipmap filter, no REPEAT or MIRRORED_REPEAT (GL refuses them).
            let mip = if target == TexTarget::Rect {
                MipFilter::None
            } else {
                mip
            };
            if target == TexTarget::Rect {
                for w in wrap.iter_mut().take(2) {
                    if matches!(w, Wrap::Repeat | Wrap::MirroredRepeat) {
                        *w = Wrap::ClampToEdge;
                    }
                }
            }
            SamplerKey {
                target,
                format,
                min,
                mip,
                mag,
                wrap,
                compare: compare.filter(|_| format == TexelFormat::Depth32F),
                depth_mode,
                statics: SamplerStatics::default(),
            }
        })
}

fn combine_src() -> impl Strategy<Value = CombineSrc> {
    prop_oneof![
        Just(CombineSrc::Texture),
        (0u8..MAX_UNITS as u8).prop_map(CombineSrc::TextureUnit),
        Just(CombineSrc::Constant),
        Just(CombineSrc::PrimaryColor),
        Just(CombineSrc::Previous),
    ]
}

fn combine_key() -> impl Strategy<Value = CombineKey> {
    let func = || {
        select(
            &[
                CombineFn::Replace,
                CombineFn::Modulate,
                CombineFn::Add,
                CombineFn::AddSigned,
                CombineFn::Interpolate,
                CombineFn::Subtract,
                CombineFn::Dot3Rgb,
                CombineFn::Dot3Rgba,
            ][..],
        )
    };
    let op = || {
        select(
            &[
                Operand::SrcColor,
                Operand::OneMinusSrcColor,
                Operand::SrcAlpha,
                Operand::OneMinusSrcAlpha,
            ][..],
        )
    };
    let alpha_op = || select(&[Operand::SrcAlpha, Operand::OneMinusSrcAlpha][..]);
    let scale = || select(&[1u8, 2, 4][..]);
    (
        func(),
        func().prop_filter("DOT3 is an RGB function", |f| {
            !matches!(f, CombineFn::Dot3Rgb | CombineFn::Dot3Rgba)
        }),
        [combine_src(), combine_src(), combine_src()],
        [op(), op(), op()],
        [combine_src(), combine_src(), combine_src()],
        [alpha_op(), alpha_op(), alpha_op()],
        scale(),
        scale(),
    )
        .prop_map(
            |(rgb, alpha, src_rgb, op_rgb, src_alpha, op_alpha, scale_rgb, scale_alpha)| CombineKey {
                rgb,
                alpha,
                src_rgb,
                op_rgb,
                src_alpha,
                op_alpha,
                scale_rgb,
                scale_alpha,
            },
        )
}

fn tex_unit_key() -> impl Strategy<Value = TexUnitKey> {
    let base = select(
        &[
            BaseFormat::Alpha,
            BaseFormat::Luminance,
            BaseFormat::LuminanceAlpha,
            BaseFormat::Intensity,
            BaseFormat::Rgb,
            BaseFormat::Rgba,
        ][..],
    );
    let mode = select(
        &[
            EnvMode::Modulate,
            EnvMode::Replace,
            EnvMode::Decal,
            EnvMode::Blend,
            EnvMode::Add,
            EnvMode::Combine,
        ][..],
    );
    (sampler_key(), base, mode, combine_key()).prop_map(|(sampler, base, mode, combine)| {
        let base = if sampler.format == TexelFormat::Depth32F {
            BaseFormat::Depth
        } else {
            base
        };
        let env_base = if base == BaseFormat::Depth {
            sampler.depth_mode.base()
        } else {
            base
        };
        TexUnitKey {
            sampler,
            base,
            env: effective_combine(mode, env_base, combine),
        }
    })
}

/// Texture units: unit 0 nearly always, unit 1 half the time, the others rarely.
fn tex_units() -> impl Strategy<Value = [Option<TexUnitKey>; MAX_UNITS]> {
    let unit = |p: f64| prop::option::weighted(p, tex_unit_key());
    (
        unit(0.9),
        unit(0.5),
        unit(0.1),
        unit(0.1),
        unit(0.05),
        unit(0.05),
        unit(0.05),
        unit(0.1),
    )
        .prop_map(|(a, b, c, d, e, f, g, h)| [a, b, c, d, e, f, g, h])
}

/// One unit's texture, owned: every level of its chain (some outside the
/// sampled range left empty) and its sampling values.
struct OwnedTexture {
    levels: Vec<(Vec<u8>, [u32; 3])>,
    base_level: u32,
    max_level: u32,
    lods: [f32; 3],
    border: [f32; 4],
    /// A float depth texture (`TextureRef::float_depth`): texels beyond
    /// [0, 1] too, the compare's reference unclamped.
    float_depth: bool,
}

impl OwnedTexture {
    /// A random texture for `key`: sizes 1..=64 (3D 1..=8, cube faces square).
    fn random(key: &SamplerKey, rng: &mut Rng) -> OwnedTexture {
        let mut size = |max: u64| 1 + rng.below(max) as u32;
        let dims = match key.target {
            TexTarget::D1 => [size(64), 1, 1],
            TexTarget::D2 => [size(64), size(64), 1],
            // One level; its coordinates are unnormalized, so the random
            // ones (around [-2, 2]) reach the first texels and the clamps.
            TexTarget::Rect => [size(5), size(5), 1],
            TexTarget::D3 => [size(8), size(8), size(8)],
            TexTarget::Cube => {
                let s = size(32);
                [s, s, 1]
            }
        };
        let count = match key.target {
            TexTarget::Rect => 1,
            _ => 32 - dims.iter().max().expect("three sizes").leading_zeros(),
        };
        let base_level = rng.below(u64::from(count)) as u32;
        let max_level = base_level + rng.below(u64::from(count - base_level)) as u32;
        let faces = if key.target == TexTarget::Cube { 6 } else { 1 };
        let bpp = key.format.bytes_per_texel();
        let float_depth = key.format == TexelFormat::Depth32F && rng.below(2) == 0;
        let mut levels = Vec::new();
        for l in 0..count {
            let d = dims.map(|s| (s >> l).max(1));
            for _ in 0..faces {
                let sampled = (base_level..=max_level).contains(&l);
                if !sampled && rng.below(2) == 0 {
                    levels.push((Vec::new(), [0; 3]));
                    continue;
                }
                let n = (d[0] * d[1] * d[2]) as usize;
                let texels = match key.format {
                    TexelFormat::Depth32F => (0..n)
                        .flat_map(|_| {
                            const POOL: [f32; 4] = [0.0, 0.25, 0.5, 1.0];
                            const FLOAT_POOL: [f32; 4] = [-0.5, 1.5, 1e30, f32::NAN];
                            let v = if float_depth && rng.below(8) == 0 {
                                FLOAT_POOL[rng.below(4) as usize]
                            } else if rng.below(2) == 0 {
                                POOL[rng.below(4) as usize]
                            } else {
                                rng.below(1 << 24) as f32 / (1 << 24) as f32
                            };
                            v.to_ne_bytes()
                        })
                        .collect(),
                    _ => (0..n * bpp).map(|_| rng.byte()).collect(),
                };
                levels.push((texels, d));
            }
        }
        const LODS: [f32; 9] = [-1000.0, -100.0, -1.0, 0.0, 0.5, 1.0, 2.5, 100.0, 1000.0];
        let lod = |rng: &mut Rng| LODS[rng.below(LODS.len() as u64) as usize];
        let (a, b) = (lod(rng), lod(rng));
        let bias = if rng.below(2) == 0 { 0.0 } else { lod(rng) / 4.0 };
        OwnedTexture {
            levels,
            base_level,
            max_level,
            lods: [a.min(b), a.max(b), bias],
            border: [0, 1, 2, 3].map(|_| f32::from(rng.byte()) / 255.0),
            float_depth,
        }
    }

    fn images(&self) -> Vec<Image<'_>> {
        self.levels
            .iter()
            .map(|(texels, [width, height, depth])| Image {
                texels,
                units: None,
                width: *width,
                height: *height,
                depth: *depth,
            })
            .collect()
    }

    fn texture_ref<'a>(&self, images: &'a [Image<'a>]) -> TextureRef<'a> {
        TextureRef {
            images,
            base_level: self.base_level,
            max_level: self.max_level,
            min_lod: self.lods[0],
            max_lod: self.lods[1],
            lod_bias: self.lods[2],
            border: self.border,
            float_depth: self.float_depth,
        }
    }
}

/// A texture coordinate plane value: a quarter of the time from a pool of
/// stiff values (NaN, ±1e6, ±∞, zero, edges), else within a few repeats.
fn tex_float(rng: &mut Rng, scale: f32) -> f32 {
    const POOL: [f32; 10] = [
        f32::NAN,
        1e6,
        -1e6,
        f32::INFINITY,
        f32::NEG_INFINITY,
        0.0,
        0.5,
        1.0,
        -1.0,
        1e30,
    ];
    if rng.below(4) == 0 {
        return POOL[rng.below(POOL.len() as u64) as usize];
    }
    (rng.below(20001) as f32 / 5000.0 - 2.0) * scale
}

/// Planes with texture coordinates: 1/w mostly 1, constant or gently sloped,
/// coordinates from [`tex_float`] with slopes from magnification to strong
/// minification, q/w mostly 1/w or 1.
fn textured_planes(rng: &mut Rng) -> Planes {
    let mut p = planes(rng);
    match rng.below(8) {
        // w exactly 1 (glOrtho): the specialists' short path when q/w is 1 too.
        0..=1 => p.constant(softgl_jit::shade::slot::INV_W, 1.0),
        2..=6 => p.set(
            softgl_jit::shade::slot::INV_W,
            1.0,
            tex_float(rng, 1e-3),
            tex_float(rng, 1e-3),
        ),
        _ => {}
    }
    for u in 0..MAX_UNITS {
        for c in 0..4 {
            let k = softgl_jit::shade::slot::tex(u) + c;
            if c == 3 && rng.below(4) != 0 {
                // q = 1 at the vertices: q/w is 1/w (perspective), or 1 where w is.
                if rng.below(2) == 0 {
                    let (a0, dx, dy) = p.get(softgl_jit::shade::slot::INV_W);
                    p.set(k, a0, dx, dy);
                } else {
                    p.constant(k, 1.0);
                }
                continue;
            }
            let slope = [1e-3, 1e-2, 0.1, 1.0][rng.below(4) as usize];
            // Far from the origin now and then (REPEAT of a non-power-of-two
            // size wraps from the fraction there), and exact power-of-two
            // slopes (ρ² on the ties of λ's rounding).
            let a0 = match rng.below(8) {
                0 => tex_float(rng, 1.0) + [1e3, -3e4, 1e5][rng.below(3) as usize],
                _ => tex_float(rng, 1.0),
            };
            let mut d = || match rng.below(4) {
                0 => [1.0, 0.5, 0.25, 1.0 / 16.0, 1.0 / 32.0, 1.0 / 64.0, 3.0 / 64.0][rng.below(7) as usize],
                _ => tex_float(rng, slope),
            };
            let (dx, dy) = (d(), d());
            p.set(k, a0, dx, dy);
        }
    }
    p
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    /// Textured keys: random units (targets, formats, filters, wraps,
    /// environments), random textures and texture coordinates.
    #[test]
    fn textured_jit_equals_interpreter(
        key in key(),
        shade in shade_key(),
        tex in tex_units(),
        u in uniforms(),
        seed in any::<u64>(),
    ) {
        // Both tiers' code: a draw runs the quick code (single-pass, every
        // unit through the callout) until the optimized code is installed.
        let tier = if seed & 1 == 0 { Tier::Quick } else { Tier::Optimized };
        textured_case(key, shade, tex, u, (seed, tier))?;
    }

    /// Units the specialist samples natively (2D RGBA8 or sRGB, REPEAT or
    /// CLAMP_TO_EDGE, any filters; rectangles, CLAMP_TO_EDGE), one or two.
    #[test]
    fn natively_sampled_jit_equals_interpreter(
        key in key(),
        shade in shade_key(),
        units in (native_unit_key(), prop::option::of(native_unit_key())),
        u in uniforms(),
        seed in any::<u64>(),
    ) {
        let mut tex = [None; MAX_UNITS];
        (tex[0], tex[1]) = (Some(units.0), units.1);
        prop_assert!(tex.iter().flatten().all(softgl_jit::compile::native_unit));
        textured_case(key, shade, tex, u, (seed, Tier::Optimized))?;
    }

    /// Depth textures the specialist samples natively (2D, NEAREST, REPEAT,
    /// CLAMP_TO_EDGE or CLAMP, every compare function or none, every depth
    /// mode, unorm and float depth), alone or after a natively sampled RGBA8
    /// unit (MuJoCo's light passes: the floor's texture, then the shadow map).
    #[test]
    fn natively_sampled_depth_jit_equals_interpreter(
        key in key(),
        shade in shade_key(),
        units in (prop::option::of(native_unit_key()), native_depth_unit_key()),
        u in uniforms(),
        seed in any::<u64>(),
    ) {
        let mut tex = [None; MAX_UNITS];
        (tex[0], tex[1]) = (units.0, Some(units.1));
        prop_assert!(tex.iter().flatten().all(softgl_jit::compile::native_unit));
        textured_case(key, shade, tex, u, (seed, Tier::Optimized))?;
    }
}

/// A depth unit the specialist samples natively.
fn native_depth_unit_key() -> impl Strategy<Value = TexUnitKey> {
    let wrap = || select(&[Wrap::Repeat, Wrap::ClampToEdge, Wrap::Clamp][..]);
    (tex_unit_key(), [wrap(), wrap()], prop::option::of(compare())).prop_map(|(mut unit, [s, t], compare)| {
        let k = &mut unit.sampler;
        (k.target, k.format, k.compare) = (TexTarget::D2, TexelFormat::Depth32F, compare);
        (k.min, k.mip, k.mag) = (Filter::Nearest, MipFilter::None, Filter::Nearest);
        k.wrap = [s, t, Wrap::Repeat];
        unit.base = BaseFormat::Depth;
        unit
    })
}

/// Random buffers, spans over them and planes from `make_planes` (one to
/// three primitives), run through the specialist of `key` compiled in `tier`
/// and through the interpreter: the buffers after each, JIT first.
fn run_both(
    key: &FragmentKey,
    tier: Tier,
    u: &FragmentUniforms,
    textures: &TextureSet<'_>,
    rng: &mut Rng,
    make_planes: fn(&mut Rng) -> Planes,
) -> (Buffers, Buffers) {
    let mut interp_buf = Buffers::random(key, rng);
    let mut spans = spans(&interp_buf, key, rng);
    let planes: Vec<Planes> = (0..1 + rng.below(3)).map(|_| make_planes(rng)).collect();
    for s in &mut spans {
        s.planes = rng.below(planes.len() as u64) as u32;
    }
    let mut jit_buf = interp_buf.clone();
    let specialist = Specialist::compile_tier(key, tier).expect("a valid key compiles");
    interp_buf
        .counted(|t| interp::run_with_planes(key, u, textures, &spans, &planes, t).expect("the key names the buffers"));
    jit_buf.counted(|t| {
        specialist
            .run_with_planes(u, textures, &spans, &planes, t)
            .expect("the key names the buffers")
    });
    (jit_buf, interp_buf)
}

/// A unit the specialist samples natively: a third of them rectangles
/// (CLAMP_TO_EDGE, no mipmap filter, as GL allows them), a third of the
/// others sRGB (llvmpipe's SoA path, 2D only).
fn native_unit_key() -> impl Strategy<Value = TexUnitKey> {
    let wrap = || select(&[Wrap::Repeat, Wrap::ClampToEdge][..]);
    let target = select(&[TexTarget::D2, TexTarget::D2, TexTarget::Rect][..]);
    let format = select(&[TexelFormat::Rgba8, TexelFormat::Rgba8, TexelFormat::Srgba8][..]);
    (tex_unit_key(), [wrap(), wrap()], target, format).prop_map(|(mut unit, [s, t], target, format)| {
        let k = &mut unit.sampler;
        let format = if target == TexTarget::Rect {
            TexelFormat::Rgba8
        } else {
            format
        };
        (k.target, k.format, k.compare) = (target, format, None);
        k.wrap = [s, t, Wrap::Repeat];
        if target == TexTarget::Rect {
            k.wrap = [Wrap::ClampToEdge, Wrap::ClampToEdge, Wrap::Repeat];
            k.mip = MipFilter::None;
        }
        if unit.base == BaseFormat::Depth {
            unit.base = BaseFormat::Rgba;
        }
        unit
    })
}

/// One textured case: `tex` on `shade` on `key`, textures, spans and planes from `seed`.
fn textured_case(
    key: FragmentKey,
    shade: ShadeKey,
    tex: [Option<TexUnitKey>; MAX_UNITS],
    u: FragmentUniforms,
    (seed, tier): (u64, Tier),
) -> Result<(), TestCaseError> {
    let key = FragmentKey {
        shade: Some(ShadeKey {
            color: true,
            tex,
            ..shade
        }),
        ..key
    };
    let mut rng = Rng(softgl_jit::rng::Rng::new((seed ^ (seed >> 32)) as u32));
    // A unit of the key without a texture in the set now and then.
    let owned: Vec<Option<OwnedTexture>> = tex
        .iter()
        .map(|t| {
            t.as_ref()
                .filter(|_| rng.below(20) != 0)
                .map(|t| OwnedTexture::random(&t.sampler, &mut rng))
        })
        .collect();
    let images: Vec<Vec<Image<'_>>> = owned
        .iter()
        .map(|o| o.as_ref().map_or_else(Vec::new, OwnedTexture::images))
        .collect();
    let mut textures = TextureSet::default();
    for (unit, o) in owned.iter().enumerate() {
        textures.units[unit] = o.as_ref().map(|o| o.texture_ref(&images[unit]));
        textures.env_color[unit] = [0, 1, 2, 3].map(|_| f32::from(rng.byte()) / 255.0);
    }
    // The key made for these textures, but now and then one whose statics
    // disagree with them (the specialist then runs on the interpreter).
    let key = if rng.below(10) != 0 {
        support::bind(&key, &textures)
    } else {
        key
    };
    let (jit_buf, interp_buf) = run_both(&key, tier, &u, &textures, &mut rng, textured_planes);
    prop_assert_eq!(&jit_buf, &interp_buf, "buffers differ");
    Ok(())
}

/// A one-unit 2D RGBA8 key with these filters and wrap, REPLACE.
fn one_unit_key(min: Filter, mip: MipFilter, mag: Filter, wrap: Wrap) -> FragmentKey {
    support::one_unit_key(min, mip, mag, wrap, EnvMode::Replace)
}

/// Runs `key` over one full 16×2 span pair with `planes` and texture `levels`
/// (square sides, RGBA8 bytes) on both back ends; the JIT's pixels, after
/// checking they equal the interpreter's.
fn run_one_unit(key: &FragmentKey, planes: Planes, levels: &[(u32, u32, Vec<u8>)]) -> Vec<u8> {
    run_one_unit_on(key, planes, levels, (16, 2))
}

/// [`run_one_unit`] on a `width`×`height` target (`width` ≤ 64).
fn run_one_unit_on(
    key: &FragmentKey,
    planes: Planes,
    levels: &[(u32, u32, Vec<u8>)],
    (width, height): (u32, u32),
) -> Vec<u8> {
    let images = support::images(levels);
    let mut set = TextureSet::default();
    set.units[0] = Some(support::whole_chain(&images));
    let key = &support::bind(key, &set);
    let spans: Vec<FragmentSpan> = (0..height)
        .map(|y| {
            let mut s = FragmentSpan::new(0, y);
            for i in 0..width as usize {
                s.set(i, [0; 4], 0);
            }
            s
        })
        .collect();
    let run = |jit: bool| {
        let mut color = vec![0u8; (width * height * 4) as usize];
        let stride = width as usize * 4;
        let mut target = Target::new(width, height, ColorFormat::Rgba8, &mut color, stride, None, None).unwrap();
        let u = FragmentUniforms::default();
        if jit {
            let s = Specialist::compile(key).unwrap();
            s.run_with_planes(&u, &set, &spans, &[planes], &mut target).unwrap();
        } else {
            interp::run_with_planes(key, &u, &set, &spans, &[planes], &mut target).unwrap();
        }
        color
    };
    let jit = run(true);
    assert_eq!(jit, run(false), "JIT and interpreter differ");
    jit
}

/// Planes with w = 1, white, and unit 0's s and t from `(a0, dadx, dady)`.
fn st_planes(s: (f32, f32, f32), t: (f32, f32, f32)) -> Planes {
    use softgl_jit::shade::slot;
    let mut p = Planes::default();
    p.constant(slot::INV_W, 1.0);
    for c in 0..4 {
        p.constant(slot::COLOR + c, 1.0);
    }
    p.set(slot::tex(0), s.0, s.1, s.2);
    p.set(slot::tex(0) + 1, t.0, t.1, t.2);
    p.constant(slot::tex(0) + 3, 1.0);
    p
}

/// λ on the tie of its rounding: ds/dx·32 = dt/dx·32 = 1 gives ρ² = 2; with
/// no bias and no LOD clamp llvmpipe takes λ's integer part from ρ²'s
/// exponent, `(128 − 126) >> 1 = 1`, where rounding `log2(2)/2 = 0.5` half to
/// even would give 0: every fragment reads level 1 (green).
#[test]
fn lod_on_the_rounding_tie_reads_level_1_on_both_back_ends() {
    let key = one_unit_key(Filter::Nearest, MipFilter::Nearest, Filter::Nearest, Wrap::Repeat);
    let fill = |side: u32, rgba: [u8; 4]| (side, side, rgba.repeat((side * side) as usize));
    let levels = [
        fill(32, [255, 0, 0, 255]),
        fill(16, [0, 255, 0, 255]),
        fill(8, [0, 0, 255, 255]),
        fill(4, [0, 0, 255, 255]),
        fill(2, [0, 0, 255, 255]),
        fill(1, [0, 0, 255, 255]),
    ];
    let d = 1.0 / 32.0;
    let color = run_one_unit(&key, st_planes((0.25, d, 0.0), (0.5, d, 0.0)), &levels);
    assert!(color.chunks(4).all(|p| p == [0, 255, 0, 255]), "{color:?}");
}

/// REPEAT of a non-power-of-two texture far from the origin: llvmpipe wraps
/// from the fraction of s (its weights keep their 8 bits there) where a
/// power-of-two texture would scale s first.
#[test]
fn npot_repeat_far_from_the_origin_matches() {
    let mut rng = softgl_jit::rng::Rng::new(77);
    let texels: Vec<u8> = (0..3 * 5 * 4).map(|_| rng.next_u64() as u8).collect();
    for filter in [Filter::Nearest, Filter::Linear] {
        let key = one_unit_key(filter, MipFilter::None, filter, Wrap::Repeat);
        let planes = st_planes((100_000.3, 0.37, 0.01), (-30_000.2, 0.013, 0.29));
        let color = run_one_unit(&key, planes, &[(3, 5, texels.clone())]);
        // Every fragment is one of the texels (NEAREST) or between them.
        assert!(color.chunks(4).any(|p| p != [0, 0, 0, 0]));
    }
}

/// λ from each lane's own quad: with 1/w sloped, ρ differs from quad to quad
/// and the level changes inside groups (so both the one-level path and the
/// callout run), on even and odd rows, with the x derivative dominating ρ in
/// one case and the y derivative in another.
#[test]
fn lambda_of_each_quad_matches() {
    use softgl_jit::shade::slot;
    let mut rng = softgl_jit::rng::Rng::new(91);
    let levels: Vec<(u32, u32, Vec<u8>)> = (0..=6)
        .map(|l| {
            let s = 64u32 >> l;
            (s, s, (0..s * s * 4).map(|_| rng.next_u64() as u8).collect())
        })
        .collect();
    let filters = [
        (Filter::Linear, MipFilter::Linear),
        (Filter::Nearest, MipFilter::Nearest),
        (Filter::Nearest, MipFilter::Linear),
    ];
    for (min, mip) in filters {
        let key = one_unit_key(min, mip, Filter::Linear, Wrap::Repeat);
        for (s, t, w) in [
            ((0.1, 0.21, 0.013), (0.2, 0.011, 0.02), (0.07, 0.03)),
            ((0.3, 0.012, 0.2), (0.1, 0.02, 0.31), (0.07, 0.03)),
            // λ growing to the right and crossing 0 (the lanes below it read
            // the first level twice, their right neighbours two levels) at a
            // different column on each row.
            ((0.1, 0.004, 0.001), (0.2, 0.0005, 0.004), (-0.012, -0.002)),
        ] {
            // 1/w and q/w (q = 1) sloped alike: s/q is perspective-correct.
            let mut planes = st_planes(s, t);
            for k in [slot::INV_W, slot::tex(0) + 3] {
                planes.set(k, 1.0, w.0, w.1);
            }
            let color = run_one_unit_on(&key, planes, &levels, (64, 16));
            // The pixels are texels of several levels, not one colour.
            assert!(color.chunks(4).any(|p| p != &color[..4]), "{min:?} {mip:?}");
        }
    }
}

/// A draw's texture view is made once for a specialist's key; one made for
/// another key (or none) is not read: the specialist makes its own, and the
/// pixels are the interpreter's.
#[test]
fn a_view_made_for_another_key_is_not_read() {
    use softgl_jit::shade::slot;
    let levels: Vec<(u32, u32, Vec<u8>)> = (0..=4)
        .map(|l| {
            let s = 16u32 >> l;
            (s, s, (0..s * s * 4).map(|i| (i * 37 + l) as u8).collect())
        })
        .collect();
    let images = support::images(&levels);
    let mut set = TextureSet::default();
    set.units[0] = Some(support::whole_chain(&images));
    let trilinear = support::bind(
        &one_unit_key(Filter::Linear, MipFilter::Linear, Filter::Linear, Wrap::Repeat),
        &set,
    );
    let nearest = support::bind(
        &one_unit_key(Filter::Nearest, MipFilter::None, Filter::Nearest, Wrap::ClampToEdge),
        &set,
    );
    let mut planes = st_planes((0.1, 0.07, 0.01), (0.3, 0.01, 0.09));
    planes.set(slot::INV_W, 1.0, 0.0, 0.0);
    let spans: Vec<FragmentSpan> = (0..4)
        .map(|y| {
            let mut s = FragmentSpan::new(0, y);
            for i in 0..32 {
                s.set(i, [0; 4], 0);
            }
            s
        })
        .collect();
    let render = |run: &dyn Fn(&mut Target<'_>)| {
        let mut color = vec![0u8; 32 * 4 * 4];
        let mut t = Target::new(32, 4, ColorFormat::Rgba8, &mut color, 128, None, None).unwrap();
        run(&mut t);
        color
    };
    let u = FragmentUniforms::default();
    let want = render(&|t| interp::run_with_planes(&trilinear, &u, &set, &spans, &[planes], t).unwrap());
    let specialist = Specialist::compile(&trilinear).unwrap();
    let other = Specialist::compile(&nearest).unwrap();
    for view in [
        other.texture_view(&set),
        DrawTextures::None,
        specialist.texture_view(&set),
    ] {
        let got = render(&|t| {
            specialist
                .run_splatted(&SplatUniforms::new(&u), (&set, &view), &spans, &[planes], t)
                .unwrap()
        });
        assert_eq!(got, want);
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, ..ProptestConfig::default() })]

    /// The deep formats alone (the other proptests draw them most of the
    /// time): any key in a deep format, shaded from random planes half
    /// the time, with random deep uniforms (clamping on and off).
    #[test]
    fn deep_jit_equals_interpreter(
        key in key(),
        format in select(&DEEP_FORMATS[..]),
        shade in prop::option::of(shade_key()),
        u in uniforms(),
        seed in any::<u64>(),
    ) {
        let key = FragmentKey { color_format: format, shade, ..key }.normalized();
        let mut rng = Rng(softgl_jit::rng::Rng::new((seed ^ (seed >> 32)) as u32));
        let (jit_buf, interp_buf) = run_both(&key, Tier::Optimized, &u, &TextureSet::default(), &mut rng, planes);
        prop_assert_eq!(&jit_buf, &interp_buf, "buffers differ");
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    /// The deep path's tests and their writes are the 8-bit path's: for a
    /// key without alpha test (whose reference differs in precision), the
    /// same spans leave depth and stencil identical in RGBA8 and in RGBA16
    /// and RGBA32F, and without blending or logic op each written RGBA16
    /// channel is the RGBA8 one widened (v * 257, the span's bytes being
    /// exact in both) and each RGBA32F channel the byte over 255.
    #[test]
    fn the_deep_path_tests_and_writes_as_the_8_bit_path(key in key(), u in uniforms(), seed in any::<u64>()) {
        let base = FragmentKey { alpha_test: None, color_format: ColorFormat::Rgba8, dither: false, ..key }.normalized();
        let mut rng = Rng(softgl_jit::rng::Rng::new((seed ^ (seed >> 32)) as u32));
        let mut b8 = Buffers::random(&base, &mut rng);
        let spans = spans(&b8, &base, &mut rng);
        let before = b8.clone();
        interp::run(&base, &u, &spans, &mut b8.target()).expect("the key names the buffers");
        for format in [ColorFormat::Rgba16, ColorFormat::Rgba32F] {
            let deep = FragmentKey { color_format: format, ..base }.normalized();
            let mut b = before.clone();
            b.format = format;
            let bpp = format.bytes_per_pixel();
            b.stride = b.width as usize * bpp;
            // The same colours, widened: v * 257, or v / 255 as f32.
            b.color = before.color_pixels().iter().flat_map(|p| widen(format, *p)).collect();
            b.color.resize(b.stride * b.height as usize, 0);
            interp::run(&deep, &u, &spans, &mut b.target()).expect("the key names the buffers");
            prop_assert_eq!(&b.depth16, &b8.depth16);
            prop_assert_eq!(&b.depth32, &b8.depth32);
            prop_assert_eq!(&b.stencil, &b8.stencil);
            if base.blend.is_none() && base.logic_op.is_none() {
                let want: Vec<u8> = b8.color_pixels().iter().flat_map(|p| widen(format, *p)).collect();
                prop_assert_eq!(&b.color[..want.len()], &want[..], "{:?} colours", format);
            }
        }
    }
}

/// RGBA bytes as a deep format stores them: `v * 257`, or `v / 255` in f32
/// (what a span's byte becomes in the deep path, and back exactly).
fn widen(format: ColorFormat, p: [u8; 4]) -> Vec<u8> {
    match format {
        ColorFormat::Rgba16 => p.iter().flat_map(|&v| (u16::from(v) * 257).to_ne_bytes()).collect(),
        _ => p
            .iter()
            .flat_map(|&v| (f32::from(v) * (1.0 / 255.0)).to_ne_bytes())
            .collect(),
    }
}

impl Buffers {
    /// The RGBA8 pixels, rows bottom-up as stored, without the row padding.
    fn color_pixels(&self) -> Vec<[u8; 4]> {
        assert_eq!(self.format, ColorFormat::Rgba8);
        (0..self.height as usize)
            .flat_map(|row| {
                let line = &self.color[row * self.stride..][..self.width as usize * 4];
                line.chunks_exact(4)
                    .map(|p| [p[0], p[1], p[2], p[3]])
                    .collect::<Vec<_>>()
            })
            .collect()
    }
}

/// One shaded fragment by hand in each deep format: RGBA16 clamps (1.5 to
/// 65535) and converts with llvmpipe's rounding, then blends `SRC_ALPHA,
/// ONE_MINUS_SRC_ALPHA` in 16-bit unorm; RGBA32F adds unclamped.
#[test]
fn deep_fragments_by_hand() {
    let shade = ShadeKey {
        color: true,
        ..ShadeKey::default()
    };
    let mut p = Planes::default();
    for (k, v) in [(0, 1.0), (1, 0.25), (2, 1.5), (3, 0.1), (4, 0.5)] {
        p.constant(k, v);
    }
    let mut span = FragmentSpan::new(0, 0);
    span.set(0, [9, 9, 9, 9], 0);
    let u = FragmentUniforms::default();
    let run = |format: ColorFormat, blend: BlendKey, dst: &[u8]| {
        let key = FragmentKey {
            shade: Some(shade),
            blend: Some(blend),
            ..FragmentKey::new(format, None, false)
        };
        let mut color = dst.to_vec();
        let bpp = format.bytes_per_pixel();
        let mut target = Target::new(1, 1, format, &mut color, bpp, None, None).unwrap();
        interp::run_with_planes(
            &key,
            &u,
            &TextureSet::default(),
            std::slice::from_ref(&span),
            &[p],
            &mut target,
        )
        .unwrap();
        color
    };
    let over = BlendKey {
        src_rgb: BlendFactor::SrcAlpha,
        dst_rgb: BlendFactor::OneMinusSrcAlpha,
        src_alpha: BlendFactor::SrcAlpha,
        dst_alpha: BlendFactor::OneMinusSrcAlpha,
        ..BlendKey::DEFAULT
    };
    let dst16: Vec<u8> = [0x1000u16, 0x8000, 0xffff, 0x4000]
        .iter()
        .flat_map(|v| v.to_ne_bytes())
        .collect();
    let out = run(ColorFormat::Rgba16, over, &dst16);
    let got: Vec<u16> = out.chunks_exact(2).map(|c| u16::from_ne_bytes([c[0], c[1]])).collect();
    // Source (0.25, 1.5→1, 0.1, 0.5): 16384, 65535, 6554, 32768; alpha 32768.
    let m = softgl_jit::deep::mul_unorm16;
    let want: Vec<u16> = [(16384u16, 0x1000u16), (65535, 0x8000), (6554, 0xffff), (32768, 0x4000)]
        .iter()
        .map(|&(s, d)| m(s, 32768).saturating_add(m(d, 65535 - 32768)))
        .collect();
    assert_eq!(got, want);
    assert_eq!(softgl_jit::deep::unorm16(0.1), 6554);
    let add = BlendKey {
        src_rgb: BlendFactor::One,
        dst_rgb: BlendFactor::One,
        src_alpha: BlendFactor::One,
        dst_alpha: BlendFactor::One,
        ..BlendKey::DEFAULT
    };
    let dst32: Vec<u8> = [0.75f32, -0.5, 2.0, 0.25]
        .iter()
        .flat_map(|v| v.to_ne_bytes())
        .collect();
    let out = run(ColorFormat::Rgba32F, add, &dst32);
    let got: Vec<f32> = out
        .chunks_exact(4)
        .map(|c| f32::from_ne_bytes([c[0], c[1], c[2], c[3]]))
        .collect();
    assert_eq!(got, vec![0.25 + 0.75, 1.5 - 0.5, 0.1 + 2.0, 0.5 + 0.25]);
}

/// NaNs in a float buffer: NaN and infinite shaded colours (payloads of
/// both signs) over NaN, infinite and finite destinations, through every
/// blend equation and no blend. Both back ends store the same bits, and
/// every NaN they store is `deep::CANONICAL_NAN` (x86 propagates the first
/// NaN operand's bits, and the two back ends order some operands
/// differently: without it the JIT stored 0xFFC00000 where the interpreter
/// stored 0x7FC00000).
#[test]
fn float_nans_are_stored_canonical_by_both_back_ends() {
    use softgl_jit::deep::CANONICAL_NAN;
    let nan = |bits: u32| f32::from_bits(bits);
    let shade = ShadeKey {
        color: true,
        flat: true,
        ..ShadeKey::default()
    };
    let colours = [
        [nan(0x7fc0_0001), nan(0xffc0_0042), f32::INFINITY, 0.0],
        [1.0, f32::INFINITY, f32::NEG_INFINITY, nan(0x7fc0_0000)],
        [0.5, -0.25, 2.0, f32::INFINITY],
    ];
    let dst: Vec<f32> = [
        nan(0x7fc0_0000),
        nan(0xffc0_0000),
        nan(0x7fa0_0003),
        f32::INFINITY,
        f32::NEG_INFINITY,
        0.0,
        1.5,
        -2.0,
    ]
    .iter()
    .cycle()
    .take(8 * 4 + 3)
    .copied()
    .skip(3)
    .collect();
    let dst: Vec<u8> = dst.iter().flat_map(|v| v.to_ne_bytes()).collect();
    let blend = |src, dst, eq| BlendKey {
        src_rgb: src,
        dst_rgb: dst,
        src_alpha: src,
        dst_alpha: dst,
        eq_rgb: eq,
        eq_alpha: eq,
    };
    let blends = [
        None,
        Some(blend(BlendFactor::One, BlendFactor::One, BlendEquation::Add)),
        Some(blend(
            BlendFactor::SrcAlpha,
            BlendFactor::OneMinusSrcAlpha,
            BlendEquation::Add,
        )),
        Some(blend(BlendFactor::DstColor, BlendFactor::Zero, BlendEquation::Add)),
        Some(blend(
            BlendFactor::ConstantColor,
            BlendFactor::SrcColor,
            BlendEquation::Subtract,
        )),
        Some(blend(
            BlendFactor::SrcAlphaSaturate,
            BlendFactor::DstAlpha,
            BlendEquation::ReverseSubtract,
        )),
        Some(blend(BlendFactor::One, BlendFactor::One, BlendEquation::Min)),
        Some(blend(BlendFactor::One, BlendFactor::One, BlendEquation::Max)),
    ];
    let mut span = FragmentSpan::new(0, 0);
    for i in 0..8 {
        span.set(i, [9, 9, 9, 9], 0);
    }
    let mut u = FragmentUniforms::default();
    u.deep.blend_color = [f32::INFINITY, nan(0xffc0_0007), 0.0, 0.5].map(f32::to_bits);
    let set = TextureSet::default();
    let mut nans = 0;
    for b in blends {
        for c in colours {
            let key = FragmentKey {
                shade: Some(shade),
                blend: b,
                ..FragmentKey::new(ColorFormat::Rgba32F, None, false)
            }
            .normalized();
            let mut p = Planes::default();
            for (k, v) in c.iter().enumerate() {
                p.constant(k, *v);
            }
            let run = |jit: bool| {
                let mut color = dst.clone();
                let mut t = Target::new(8, 1, ColorFormat::Rgba32F, &mut color, 8 * 16, None, None).unwrap();
                let spans = std::slice::from_ref(&span);
                if jit {
                    let s = Specialist::compile(&key).unwrap();
                    let view = s.texture_view(&set);
                    s.run_splatted(&SplatUniforms::new(&u), (&set, &view), spans, &[p], &mut t)
                        .unwrap();
                } else {
                    interp::run_with_planes(&key, &u, &set, spans, &[p], &mut t).unwrap();
                }
                color
            };
            let (jit, interp) = (run(true), run(false));
            assert_eq!(jit, interp, "{b:?} {c:?}");
            for v in jit
                .chunks_exact(4)
                .map(|v| u32::from_ne_bytes([v[0], v[1], v[2], v[3]]))
            {
                if f32::from_bits(v).is_nan() {
                    assert_eq!(v, CANONICAL_NAN, "{b:?} {c:?}");
                    nans += 1;
                }
            }
        }
    }
    assert!(nans > 100, "{nans} NaNs stored");
}

/// A key's shading half run over a span into an RGBA8 and stencil target
/// (the stencil cleared first), and its per-sample half over the span's
/// fragments the first marked, with the colours it wrote
/// ([`FragmentKey::split_shading`]), on the interpreter (`jit: None`) or
/// the halves' specialists; span by span, as a multisampled draw runs a
/// primitive's pixels.
fn run_split(
    (shading, ops): (&FragmentKey, &FragmentKey),
    jit: Option<(&Specialist, &Specialist)>,
    u: &FragmentUniforms,
    (spans, planes): (&[FragmentSpan], &[Planes]),
    buf: &mut Buffers,
) {
    let (w, h) = (buf.width, buf.height);
    let mut shade = Buffers {
        width: w,
        height: h,
        stride: 4 * w as usize,
        top_down: false,
        format: ColorFormat::Rgba8,
        color: vec![0; 4 * (w * h) as usize],
        depth16: None,
        depth32: None,
        stencil: Some(vec![0; (w * h) as usize]),
        passed: 0,
    };
    let su = u.shading_half();
    for span in spans {
        if let Some(st) = shade.stencil.as_mut() {
            st.fill(0);
        }
        let one = std::slice::from_ref(span);
        shade.counted(|t| {
            match jit {
                Some((s, _)) => s.run_with_planes(&su, &TextureSet::default(), one, planes, t),
                None => interp::run_with_planes(shading, &su, &TextureSet::default(), one, planes, t),
            }
            .expect("the shading half names its target")
        });
        let mut o = span.clone();
        o.mask = 0;
        for i in 0..(span.len as usize).min(SPAN_MAX) {
            let (x, y) = (span.x as usize + i, span.y as usize);
            if span.mask >> i & 1 == 0 || x >= w as usize || y >= h as usize {
                continue;
            }
            if shade.stencil.as_ref().is_some_and(|st| st[y * w as usize + x] == 1) {
                o.mask |= 1 << i;
                let c = &shade.color[4 * (y * w as usize + x)..][..4];
                (o.r[i], o.g[i], o.b[i], o.a[i]) = (c[0], c[1], c[2], c[3]);
            }
        }
        let one = std::slice::from_ref(&o);
        buf.counted(|t| {
            match jit {
                Some((_, s)) => s.run_with_planes(u, &TextureSet::default(), one, planes, t),
                None => interp::run_with_planes(ops, u, &TextureSet::default(), one, planes, t),
            }
            .expect("the per-sample half names the buffers")
        });
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, ..ProptestConfig::default() })]

    /// A multisampled draw shading each pixel once (softgl's
    /// `multisample::shared_halves`): a key's two halves, run one after
    /// the other span by span, leave the buffers as the whole key does,
    /// on the interpreter and on the halves' specialists.
    #[test]
    fn split_keys_equal_the_whole(
        key in key(),
        shade in shade_key(),
        u in uniforms(),
        seed in any::<u64>(),
    ) {
        let shade = ShadeKey {
            color: true,
            coverage: softgl_jit::AlphaCoverage { quarters: None, ..shade.coverage },
            ..shade
        };
        let key = FragmentKey { shade: Some(shade), ..key };
        prop_assume!(!key.color_format.is_deep());
        let (shading, ops) = key.split_shading().expect("a shaded 8-bit key splits");
        let mut rng = Rng(softgl_jit::rng::Rng::new((seed ^ (seed >> 32)) as u32));
        let mut whole = Buffers::random(&key, &mut rng);
        let mut spans = spans(&whole, &key, &mut rng);
        let planes: Vec<Planes> = (0..1 + rng.below(3)).map(|_| planes(&mut rng)).collect();
        for s in &mut spans {
            s.planes = rng.below(planes.len() as u64) as u32;
        }
        let (mut split, mut split_jit) = (whole.clone(), whole.clone());
        let t = TextureSet::default();
        whole.counted(|b| interp::run_with_planes(&key, &u, &t, &spans, &planes, b).expect("the key names the buffers"));
        run_split((&shading, &ops), None, &u, (&spans, &planes), &mut split);
        let s = Specialist::compile(&shading).expect("the shading half compiles");
        let o = Specialist::compile(&ops).expect("the per-sample half compiles");
        run_split((&shading, &ops), Some((&s, &o)), &u, (&spans, &planes), &mut split_jit);
        prop_assert_eq!(&split, &whole, "the interpreter's halves differ from the whole");
        prop_assert_eq!(&split_jit, &whole, "the specialists' halves differ from the whole");
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, ..ProptestConfig::default() })]

    /// The MuJoCo passes' keys whose code is specialised: depth-only
    /// shading under any depth test (the last stage or not: the shadow
    /// maps' `max(z, stored)` write), the colour from the span packed or
    /// blended `ONE, ONE`, a stencil test that always passes (the loop over
    /// full groups), any byte or 16-bit format, a third of the spans full.
    #[test]
    fn depth_only_and_additive_keys_jit_equals_interpreter(
        base in key(),
        depth in (compare(), any::<bool>()),
        depth_format in select(&[DepthFormat::D16, DepthFormat::D24, DepthFormat::D32, DepthFormat::D32F][..]),
        (colour, ones, stencil, count) in (0u8..3, any::<bool>(), prop::option::of(stencil_op()), any::<bool>()),
        u in uniforms(),
        seed in any::<u64>(),
    ) {
        let one = BlendFactor::One;
        let format = if base.color_format.is_deep() { ColorFormat::Rgba8 } else { base.color_format };
        let key = FragmentKey {
            scissor: false,
            alpha_test: None,
            stencil: stencil.map(|op| StencilKey {
                func: CompareFunc::Always,
                fail: StencilOp::Keep,
                zfail: op,
                zpass: op,
            }),
            depth: Some(DepthKey { func: depth.0, write: depth.1 }),
            blend: ones.then_some(BlendKey {
                src_rgb: one,
                dst_rgb: one,
                src_alpha: one,
                dst_alpha: one,
                eq_rgb: BlendEquation::Add,
                eq_alpha: BlendEquation::Add,
            }),
            logic_op: None,
            dither: false,
            color_mask: match colour {
                0 => ColorMask { r: false, g: false, b: false, a: false },
                1 => ColorMask { r: true, g: true, b: true, a: true },
                _ => base.color_mask,
            },
            shade: Some(ShadeKey { depth: true, ..ShadeKey::default() }),
            count,
            ..FragmentKey::new(format, Some(depth_format), base.stencil_buffer)
        }
        .normalized();
        let mut rng = Rng(softgl_jit::rng::Rng::new((seed ^ (seed >> 32)) as u32));
        let (jit_buf, interp_buf) = run_both(&key, Tier::Optimized, &u, &TextureSet::default(), &mut rng, planes);
        prop_assert_eq!(&jit_buf, &interp_buf, "buffers differ");
    }
}
