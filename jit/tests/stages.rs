//! Per-stage tests of the reference interpreter.
//!
//! Every expected value is computed here from the GL 1.5 specification's formulas
//! (§4.1 per-fragment operations, §2.14.9 unorm conversions) with `f64` arithmetic
//! and this file's own memory-layout rules, never with the crate's pixel helpers,
//! so a test and the interpreter agree only if both follow the specification.
//! Each case runs through [`softgl_jit::interp::run`] on a tiny target, and
//! through the key's compiled specialist on a copy of it: the two must leave
//! the buffers identical, so every case here also pins the JIT.

use softgl_jit::interp::{run, run_with_planes};
use softgl_jit::key::Stages;
use softgl_jit::pixel::{self, BAYER4};
use softgl_jit::shade::slot;
use softgl_jit::{
    BlendEquation, BlendFactor, BlendKey, ColorFormat, ColorMask, CompareFunc, DepthFormat, DepthKey, DepthTarget,
    FragmentError, FragmentKey, FragmentSpan, FragmentUniforms, KeyError, LogicOp, Specialist, Stage, StencilKey,
    StencilOp, Target, SPAN_MAX,
};
use softgl_jit::{FogMode, FogUniforms, Planes, ShadeKey, TextureSet};

// ---------------------------------------------------------------------------
// Fixtures: owned buffers, spans, and the memory layout as the docs state it.
// ---------------------------------------------------------------------------

/// An owned depth buffer of one of the three formats.
#[derive(Clone, Debug, PartialEq)]
enum DepthBuf {
    D16(Vec<u16>),
    D24(Vec<u32>),
    D32(Vec<u32>),
    D32F(Vec<u32>),
}

impl DepthBuf {
    fn new(format: DepthFormat, len: usize, clear: u32) -> DepthBuf {
        match format {
            DepthFormat::D16 => DepthBuf::D16(vec![clear as u16; len]),
            DepthFormat::D24 => DepthBuf::D24(vec![clear; len]),
            DepthFormat::D32 => DepthBuf::D32(vec![clear; len]),
            DepthFormat::D32F => DepthBuf::D32F(vec![clear; len]),
        }
    }

    fn format(&self) -> DepthFormat {
        match self {
            DepthBuf::D16(_) => DepthFormat::D16,
            DepthBuf::D24(_) => DepthFormat::D24,
            DepthBuf::D32(_) => DepthFormat::D32,
            DepthBuf::D32F(_) => DepthFormat::D32F,
        }
    }

    fn get(&self, i: usize) -> u32 {
        match self {
            DepthBuf::D16(d) => u32::from(d[i]),
            DepthBuf::D24(d) | DepthBuf::D32(d) | DepthBuf::D32F(d) => d[i],
        }
    }

    fn set(&mut self, i: usize, v: u32) {
        match self {
            DepthBuf::D16(d) => d[i] = u16::try_from(v).expect("D16 value fits 16 bits"),
            DepthBuf::D24(d) | DepthBuf::D32(d) | DepthBuf::D32F(d) => d[i] = v,
        }
    }

    fn view(&mut self) -> DepthTarget<'_> {
        match self {
            DepthBuf::D16(d) => DepthTarget::D16(d),
            DepthBuf::D24(d) => DepthTarget::D24(d),
            DepthBuf::D32(d) => DepthTarget::D32(d),
            DepthBuf::D32F(d) => DepthTarget::D32F(d),
        }
    }
}

/// A framebuffer owning its buffers, tightly packed (stride = one row).
#[derive(Clone, Debug, PartialEq)]
struct Fb {
    width: u32,
    height: u32,
    format: ColorFormat,
    color: Vec<u8>,
    depth: Option<DepthBuf>,
    stencil: Option<Vec<u8>>,
    top_down: bool,
}

/// Bytes per pixel of each format, as the format docs state them.
fn bpp(format: ColorFormat) -> usize {
    match format {
        ColorFormat::Rgba8 | ColorFormat::Bgra8 => 4,
        ColorFormat::Rgb8 => 3,
        ColorFormat::Rgb565 => 2,
        ColorFormat::Rgba16 | ColorFormat::Rgbx16 => 8,
        ColorFormat::Rgba32F | ColorFormat::Rgbx32F | ColorFormat::Rgba16F | ColorFormat::Rgbx16F => 16,
    }
}

impl Fb {
    fn new(width: u32, height: u32, format: ColorFormat) -> Fb {
        Fb {
            width,
            height,
            format,
            color: vec![0; (width * height) as usize * bpp(format)],
            depth: None,
            stencil: None,
            top_down: false,
        }
    }

    fn with_depth(mut self, format: DepthFormat, clear: u32) -> Fb {
        self.depth = Some(DepthBuf::new(format, (self.width * self.height) as usize, clear));
        self
    }

    fn with_stencil(mut self, clear: u8) -> Fb {
        self.stencil = Some(vec![clear; (self.width * self.height) as usize]);
        self
    }

    fn top_down(mut self) -> Fb {
        self.top_down = true;
        self
    }

    /// The key with every stage off that names exactly this framebuffer's buffers.
    fn key(&self) -> FragmentKey {
        FragmentKey::new(
            self.format,
            self.depth.as_ref().map(DepthBuf::format),
            self.stencil.is_some(),
        )
    }

    /// Runs the interpreter on this framebuffer and the specialist on a copy,
    /// and checks that both leave the same buffers.
    fn run(&mut self, key: &FragmentKey, u: &FragmentUniforms, spans: &[FragmentSpan]) -> Result<(), FragmentError> {
        let mut jit = self.clone();
        let compiled = Specialist::compile(key);
        let r = self.run_with(|t| run(key, u, spans, t));
        if key.validate().is_ok() {
            let specialist = compiled.expect("a valid key compiles");
            let rj = jit.run_with(|t| specialist.run(u, spans, t));
            assert_eq!(rj, r, "JIT and interpreter disagree on the result for {key:?}");
            assert!(jit == *self, "JIT and interpreter buffers differ for {key:?}");
        }
        r
    }

    /// [`Fb::run`] for keys with a shading stage, spans naming `planes`.
    fn run_planes(&mut self, key: &FragmentKey, u: &FragmentUniforms, spans: &[FragmentSpan], planes: &[Planes]) {
        let mut jit = self.clone();
        let specialist = Specialist::compile(key).expect("a valid key compiles");
        self.run_with(|t| run_with_planes(key, u, &TextureSet::default(), spans, planes, t))
            .expect("the key names the buffers");
        jit.run_with(|t| specialist.run_with_planes(u, &TextureSet::default(), spans, planes, t))
            .expect("the key names the buffers");
        assert!(jit == *self, "JIT and interpreter buffers differ for {key:?}");
    }

    fn run_with(&mut self, f: impl FnOnce(&mut Target<'_>) -> Result<(), FragmentError>) -> Result<(), FragmentError> {
        let stride = self.width as usize * bpp(self.format);
        let mut target = Target::new(
            self.width,
            self.height,
            self.format,
            &mut self.color,
            stride,
            self.depth.as_mut().map(DepthBuf::view),
            self.stencil.as_deref_mut(),
        )
        .expect("buffers sized for the target")
        .with_top_down(self.top_down);
        f(&mut target)
    }

    /// Byte offset of window pixel `(x, y)`: row 0 is the bottom row in memory
    /// unless the target is top-down.
    fn offset(&self, x: u32, y: u32) -> usize {
        let row = if self.top_down { self.height - 1 - y } else { y };
        (row * self.width + x) as usize * bpp(self.format)
    }

    fn pixel(&self, x: u32, y: u32) -> &[u8] {
        let off = self.offset(x, y);
        &self.color[off..off + bpp(self.format)]
    }

    fn set_pixel(&mut self, x: u32, y: u32, bytes: &[u8]) {
        let off = self.offset(x, y);
        let n = bpp(self.format);
        self.color[off..off + n].copy_from_slice(&bytes[..n]);
    }

    /// Depth and stencil rows are always bottom-up.
    fn index(&self, x: u32, y: u32) -> usize {
        (y * self.width + x) as usize
    }

    fn depth(&self, x: u32, y: u32) -> u32 {
        self.depth.as_ref().expect("has depth").get(self.index(x, y))
    }

    fn set_depth(&mut self, x: u32, y: u32, v: u32) {
        let i = self.index(x, y);
        self.depth.as_mut().expect("has depth").set(i, v);
    }

    fn stencil(&self, x: u32, y: u32) -> u8 {
        self.stencil.as_ref().expect("has stencil")[self.index(x, y)]
    }

    fn set_stencil(&mut self, x: u32, y: u32, v: u8) {
        let i = self.index(x, y);
        self.stencil.as_mut().expect("has stencil")[i] = v;
    }
}

/// A span at `(x, y)` with one covered fragment per entry.
fn span(x: u32, y: u32, frags: &[([u8; 4], u32)]) -> FragmentSpan {
    let mut s = FragmentSpan::new(x, y);
    for (i, &(rgba, z)) in frags.iter().enumerate() {
        s.set(i, rgba, z);
    }
    s
}

/// A span at `(x, y)` of fragments with one color and depth 0.
fn span_rgba(x: u32, y: u32, frags: &[[u8; 4]]) -> FragmentSpan {
    let f: Vec<_> = frags.iter().map(|&c| (c, 0)).collect();
    span(x, y, &f)
}

/// Fragments laid out row-major over rows of `width`, each row cut into spans of
/// at most [`SPAN_MAX`]. Fragment `i` lands at `(i % width, i / width)`.
fn grid_spans(width: u32, frags: &[([u8; 4], u32)]) -> Vec<FragmentSpan> {
    let mut spans = Vec::new();
    for (row, chunk) in frags.chunks(width as usize).enumerate() {
        for (j, part) in chunk.chunks(SPAN_MAX).enumerate() {
            spans.push(span((j * SPAN_MAX) as u32, row as u32, part));
        }
    }
    spans
}

fn grid_pos(width: u32, i: usize) -> (u32, u32) {
    (i as u32 % width, i as u32 / width)
}

/// The `2^bits - 1` of a channel.
fn channel_max(bits: u32) -> f64 {
    f64::from((1u32 << bits) - 1)
}

/// llvmpipe's conversion of a unorm byte to a `bits`-bit channel: its high
/// `bits` bits (`scale_bits` in `lp_state_fs.c`; docs/llvmpipe-facts.md §13).
fn spec_reduce(c: u8, bits: u32) -> u32 {
    u32::from(c) >> (8 - bits)
}

/// GL's conversion of a `bits`-bit channel to the nearest unorm byte: `round(v * 255 / max)`.
fn spec_expand(v: u32, bits: u32) -> u8 {
    (f64::from(v) * 255.0 / channel_max(bits)).round() as u8
}

/// The 16-bit RGB565 value of unorm bytes, as llvmpipe stores them.
fn spec_565([r, g, b, _]: [u8; 4]) -> u16 {
    ((spec_reduce(r, 5) << 11) | (spec_reduce(g, 6) << 5) | spec_reduce(b, 5)) as u16
}

/// The bytes a pixel of color `c` occupies in memory, and how many there are.
fn encode(format: ColorFormat, [r, g, b, a]: [u8; 4]) -> ([u8; 4], usize) {
    match format {
        ColorFormat::Rgba8 => ([r, g, b, a], 4),
        ColorFormat::Bgra8 => ([b, g, r, a], 4),
        ColorFormat::Rgb8 => ([r, g, b, 0], 3),
        ColorFormat::Rgb565 => {
            let [lo, hi] = spec_565([r, g, b, a]).to_le_bytes();
            ([lo, hi, 0, 0], 2)
        }
        ColorFormat::Rgba16
        | ColorFormat::Rgbx16
        | ColorFormat::Rgba16F
        | ColorFormat::Rgbx16F
        | ColorFormat::Rgba32F
        | ColorFormat::Rgbx32F => {
            unreachable!("the byte formats only: the deep ones are tests/contract.rs's")
        }
    }
}

fn encoded(format: ColorFormat, c: [u8; 4]) -> Vec<u8> {
    let (bytes, n) = encode(format, c);
    bytes[..n].to_vec()
}

/// `incoming <func> stored`, GL 1.5 §4.1.4 (alpha), §4.1.5 (stencil), §4.1.6 (depth).
fn spec_compare(func: CompareFunc, incoming: u32, stored: u32) -> bool {
    match func {
        CompareFunc::Never => false,
        CompareFunc::Always => true,
        CompareFunc::Less => incoming < stored,
        CompareFunc::Lequal => incoming <= stored,
        CompareFunc::Equal => incoming == stored,
        CompareFunc::Gequal => incoming >= stored,
        CompareFunc::Greater => incoming > stored,
        CompareFunc::Notequal => incoming != stored,
    }
}

const FUNCS: [CompareFunc; 8] = CompareFunc::ALL;

fn uniforms() -> FragmentUniforms {
    FragmentUniforms::default()
}

const RED: [u8; 4] = [255, 0, 0, 255];
const BLUE: [u8; 4] = [0, 0, 255, 255];

// ---------------------------------------------------------------------------
// Blend (GL 1.5 §4.1.7, with GL_ARB_imaging's constant color and separate
// RGB/alpha state of GL 2.0): C = clamp(Cs * S + Cd * D), each term rounded
// to the nearest unorm byte.
// ---------------------------------------------------------------------------

/// Factor `f` for channel `c` (3 is alpha), in unorm units `0..=255`.
fn spec_factor(f: BlendFactor, c: usize, s: [u8; 4], d: [u8; 4], k: [u8; 4]) -> f64 {
    let (s, d, k) = (s.map(f64::from), d.map(f64::from), k.map(f64::from));
    match f {
        BlendFactor::Zero => 0.0,
        BlendFactor::One => 255.0,
        BlendFactor::SrcColor => s[c],
        BlendFactor::OneMinusSrcColor => 255.0 - s[c],
        BlendFactor::DstColor => d[c],
        BlendFactor::OneMinusDstColor => 255.0 - d[c],
        BlendFactor::SrcAlpha => s[3],
        BlendFactor::OneMinusSrcAlpha => 255.0 - s[3],
        BlendFactor::DstAlpha => d[3],
        BlendFactor::OneMinusDstAlpha => 255.0 - d[3],
        BlendFactor::ConstantColor => k[c],
        BlendFactor::OneMinusConstantColor => 255.0 - k[c],
        BlendFactor::ConstantAlpha => k[3],
        BlendFactor::OneMinusConstantAlpha => 255.0 - k[3],
        // (f, f, f, 1) with f = min(As, 1 - Ad).
        BlendFactor::SrcAlphaSaturate => {
            if c == 3 {
                255.0
            } else {
                s[3].min(255.0 - d[3])
            }
        }
    }
}

/// The product of a unorm value and a unorm factor: `round(a * b / 255)` as
/// llvmpipe computes it, `(t + (t >> 8) + 128) >> 8` with `t = a * b` (measured
/// on all 393,216 blends tried, docs/llvmpipe-facts.md §8). It differs from
/// exact rounding on 24 pairs only; `unorm_multiply_is_llvmpipes_rounding`
/// pins those.
fn spec_term(a: u8, b: f64) -> f64 {
    let t = u32::from(a) * b as u32;
    f64::from((t + (t >> 8) + 128) >> 8)
}

#[test]
fn unorm_multiply_is_llvmpipes_rounding() {
    // Measured on llvmpipe: SRC_ALPHA, ONE_MINUS_SRC_ALPHA blends.
    let over = |s: u8, a: u8, d: u8| pixel::mul_unorm8(s, a) + pixel::mul_unorm8(d, 255 - a);
    assert_eq!(over(200, 100, 50), 108);
    assert_eq!(over(255, 128, 0), 128);
    assert_eq!(over(1, 1, 254), 253);
    assert_eq!(over(10, 250, 240), 15);
    assert_eq!(over(0, 128, 255), 127);
    assert_eq!(over(77, 33, 190), 175);
    // Against exact rounding: exactly 24 pairs differ, each one lower, each at n + 0.50196.
    let mut differ = 0;
    for a in 0..=255u8 {
        for b in 0..=255u8 {
            let exact = (f64::from(a) * f64::from(b) / 255.0).round() as u8;
            let got = pixel::mul_unorm8(a, b);
            if got != exact {
                differ += 1;
                assert_eq!(got + 1, exact, "{a} * {b}");
                assert_eq!(f64::from(a) * f64::from(b) % 255.0, 128.0, "{a} * {b}");
            }
        }
    }
    assert_eq!(differ, 24);
}

fn spec_blend(key: &BlendKey, s: [u8; 4], d: [u8; 4], k: [u8; 4]) -> [u8; 4] {
    std::array::from_fn(|c| {
        let (sf, df, eq) = if c < 3 {
            (key.src_rgb, key.dst_rgb, key.eq_rgb)
        } else {
            (key.src_alpha, key.dst_alpha, key.eq_alpha)
        };
        let ts = spec_term(s[c], spec_factor(sf, c, s, d, k));
        let td = spec_term(d[c], spec_factor(df, c, s, d, k));
        let v = match eq {
            BlendEquation::Add => ts + td,
            BlendEquation::Subtract => ts - td,
            BlendEquation::ReverseSubtract => td - ts,
            BlendEquation::Min => f64::from(s[c].min(d[c])),
            BlendEquation::Max => f64::from(s[c].max(d[c])),
        };
        v.clamp(0.0, 255.0) as u8
    })
}

const GRID: [u8; 6] = [0, 1, 127, 128, 254, 255];

/// Source/destination pairs over [`GRID`]: every color value against every alpha,
/// with G and B permuted so color factors differ per channel.
fn blend_cases(format: ColorFormat) -> Vec<([u8; 4], [u8; 4])> {
    let n = GRID.len();
    let pick = |i: usize, a: u8| [GRID[i], GRID[n - 1 - i], GRID[(i + 2) % n], a];
    let mut cases = Vec::new();
    for sc in 0..n {
        for &sa in &GRID {
            for dc in 0..n {
                match format {
                    ColorFormat::Rgba8 | ColorFormat::Bgra8 => {
                        for &da in &GRID {
                            cases.push((pick(sc, sa), pick(dc, da)));
                        }
                    }
                    // No stored alpha: the destination reads alpha 1.
                    ColorFormat::Rgb8 => cases.push((pick(sc, sa), pick(dc, 255))),
                    ColorFormat::Rgba16
                    | ColorFormat::Rgbx16
                    | ColorFormat::Rgba16F
                    | ColorFormat::Rgbx16F
                    | ColorFormat::Rgba32F
                    | ColorFormat::Rgbx32F => {
                        unreachable!("the byte formats only: the deep ones are tests/contract.rs's")
                    }
                    ColorFormat::Rgb565 => {
                        // Stored 5/6-bit values, read as the nearest byte.
                        const R5: [u32; 6] = [0, 1, 15, 16, 30, 31];
                        const G6: [u32; 6] = [0, 1, 31, 32, 62, 63];
                        let d = [
                            spec_expand(R5[dc], 5),
                            spec_expand(G6[n - 1 - dc], 6),
                            spec_expand(R5[(dc + 2) % n], 5),
                            255,
                        ];
                        cases.push((pick(sc, sa), d));
                    }
                }
            }
        }
    }
    cases
}

/// Runs every key in `keys` over [`blend_cases`] and checks every stored byte.
fn check_blend(format: ColorFormat, keys: &[BlendKey], k: [u8; 4]) {
    let cases = blend_cases(format);
    let width = 64;
    let height = cases.len().div_ceil(width as usize) as u32;
    let mut fb = Fb::new(width, height, format);
    for (i, &(_, d)) in cases.iter().enumerate() {
        let (x, y) = grid_pos(width, i);
        fb.set_pixel(x, y, &encode(format, d).0);
    }
    let initial = fb.color.clone();
    let frags: Vec<_> = cases.iter().map(|&(s, _)| (s, 0)).collect();
    let spans = grid_spans(width, &frags);
    let u = FragmentUniforms {
        blend_color: k,
        ..uniforms()
    };
    for bk in keys {
        fb.color.copy_from_slice(&initial);
        let key = FragmentKey {
            blend: Some(*bk),
            ..fb.key()
        };
        fb.run(&key, &u, &spans).expect("valid key");
        for (i, &(s, d)) in cases.iter().enumerate() {
            let (x, y) = grid_pos(width, i);
            let want = spec_blend(bk, s, d, k);
            let (bytes, n) = encode(format, want);
            assert_eq!(
                fb.pixel(x, y),
                &bytes[..n],
                "{format:?} {bk:?} k={k:?}: src {s:?} over dst {d:?} should give {want:?}"
            );
        }
    }
}

/// Every pair of factors, the alpha factors being the RGB pair swapped so the
/// alpha channel also sees all 225 pairs, with equations `(eq_rgb, eq_alpha)`.
fn keys_for(eq_rgb: BlendEquation, eq_alpha: BlendEquation) -> Vec<BlendKey> {
    let mut keys = Vec::new();
    for &a in &BlendFactor::ALL {
        for &b in &BlendFactor::ALL {
            keys.push(BlendKey {
                src_rgb: a,
                dst_rgb: b,
                src_alpha: b,
                dst_alpha: a,
                eq_rgb,
                eq_alpha,
            });
        }
    }
    keys
}

#[test]
fn blend_worked_examples() {
    let mut fb = Fb::new(2, 1, ColorFormat::Rgba8);
    fb.set_pixel(0, 0, &[100, 200, 250, 64]);
    fb.set_pixel(1, 0, &[10, 20, 30, 100]);
    // Classic "over": RGB SRC_ALPHA, ONE_MINUS_SRC_ALPHA; alpha ONE, ONE_MINUS_SRC_ALPHA.
    // r = round(200*128/255) + round(100*127/255) = 100 + 50, and so on.
    let over = BlendKey {
        src_rgb: BlendFactor::SrcAlpha,
        dst_rgb: BlendFactor::OneMinusSrcAlpha,
        src_alpha: BlendFactor::One,
        dst_alpha: BlendFactor::OneMinusSrcAlpha,
        ..BlendKey::DEFAULT
    };
    let key = FragmentKey {
        blend: Some(over),
        ..fb.key()
    };
    fb.run(&key, &uniforms(), &[span_rgba(0, 0, &[[200, 100, 50, 128]])])
        .unwrap();
    assert_eq!(fb.pixel(0, 0), &[150, 150, 150, 160]);
    // SRC_ALPHA_SATURATE, ONE: f = min(200, 255 - 100) = 155 for RGB, 1 for alpha.
    let saturate = BlendKey {
        src_rgb: BlendFactor::SrcAlphaSaturate,
        dst_rgb: BlendFactor::One,
        src_alpha: BlendFactor::SrcAlphaSaturate,
        dst_alpha: BlendFactor::Zero,
        ..BlendKey::DEFAULT
    };
    let key = FragmentKey {
        blend: Some(saturate),
        ..fb.key()
    };
    fb.run(&key, &uniforms(), &[span_rgba(1, 0, &[[255, 255, 255, 200]])])
        .unwrap();
    assert_eq!(fb.pixel(1, 0), &[165, 175, 185, 200]);
    // Untouched neighbour.
    assert_eq!(fb.pixel(0, 0), &[150, 150, 150, 160]);
}

#[test]
fn blend_every_factor_pair_and_equation_pair_rgba8() {
    for &eq_rgb in &BlendEquation::ALL {
        for &eq_alpha in &BlendEquation::ALL {
            check_blend(ColorFormat::Rgba8, &keys_for(eq_rgb, eq_alpha), [1, 128, 254, 127]);
        }
    }
}

#[test]
fn blend_every_factor_pair_bgra8() {
    for (e, &eq_rgb) in BlendEquation::ALL.iter().enumerate() {
        let eq_alpha = BlendEquation::ALL[(e + 1) % 5];
        check_blend(ColorFormat::Bgra8, &keys_for(eq_rgb, eq_alpha), [254, 0, 128, 1]);
    }
}

#[test]
fn blend_without_stored_alpha_reads_destination_alpha_one() {
    for format in [ColorFormat::Rgb8, ColorFormat::Rgb565] {
        for (e, &eq_rgb) in BlendEquation::ALL.iter().enumerate() {
            let eq_alpha = BlendEquation::ALL[(e + 3) % 5];
            check_blend(format, &keys_for(eq_rgb, eq_alpha), [127, 255, 1, 128]);
        }
    }
    // Spelled out: DST_ALPHA gives 1 and ONE_MINUS_DST_ALPHA gives 0, so
    // SRC_ALPHA_SATURATE is min(As, 0) = 0.
    for format in [ColorFormat::Rgb8, ColorFormat::Rgb565] {
        let mut fb = Fb::new(3, 1, format);
        let dst = encoded(format, [0, 255, 0, 0]);
        for x in 0..3 {
            fb.set_pixel(x, 0, &dst);
        }
        let cases = [
            (BlendFactor::Zero, BlendFactor::DstAlpha, [0, 255, 0, 255]),
            (BlendFactor::One, BlendFactor::OneMinusDstAlpha, [255, 0, 255, 255]),
            (BlendFactor::SrcAlphaSaturate, BlendFactor::One, [0, 255, 0, 255]),
        ];
        for (x, (src, dstf, want)) in cases.into_iter().enumerate() {
            let key = FragmentKey {
                blend: Some(BlendKey {
                    src_rgb: src,
                    dst_rgb: dstf,
                    ..BlendKey::DEFAULT
                }),
                ..fb.key()
            };
            fb.run(&key, &uniforms(), &[span_rgba(x as u32, 0, &[[255, 0, 255, 255]])])
                .unwrap();
            assert_eq!(
                fb.pixel(x as u32, 0),
                encoded(format, want),
                "{format:?} {src:?} {dstf:?}"
            );
        }
    }
}

#[test]
fn blend_constant_factors_over_a_grid_of_constants() {
    use BlendFactor::*;
    let constant = [
        ConstantColor,
        OneMinusConstantColor,
        ConstantAlpha,
        OneMinusConstantAlpha,
    ];
    let mut keys = Vec::new();
    for &a in &constant {
        for &b in constant.iter().chain(&[Zero, One]) {
            for eq in [
                BlendEquation::Add,
                BlendEquation::Subtract,
                BlendEquation::ReverseSubtract,
            ] {
                keys.push(BlendKey {
                    src_rgb: a,
                    dst_rgb: b,
                    src_alpha: b,
                    dst_alpha: a,
                    eq_rgb: eq,
                    eq_alpha: eq,
                });
            }
        }
    }
    let n = GRID.len();
    for kc in 0..n {
        for &ka in &GRID {
            let k = [GRID[kc], GRID[n - 1 - kc], GRID[(kc + 3) % n], ka];
            check_blend(ColorFormat::Rgba8, &keys, k);
        }
    }
}

#[test]
fn blend_rgb565_keeps_every_stored_value_under_zero_one() {
    // Reading a 5/6-bit value as a byte and storing it back is exact for every
    // value: ZERO, ONE leaves all 65536 patterns unchanged.
    let mut fb = Fb::new(256, 256, ColorFormat::Rgb565);
    for v in 0..=u16::MAX {
        fb.set_pixel(u32::from(v) % 256, u32::from(v) / 256, &v.to_le_bytes());
    }
    let initial = fb.color.clone();
    let key = FragmentKey {
        blend: Some(BlendKey {
            src_rgb: BlendFactor::Zero,
            dst_rgb: BlendFactor::One,
            ..BlendKey::DEFAULT
        }),
        ..fb.key()
    };
    let frags = vec![([77, 77, 77, 77], 0); 65536];
    fb.run(&key, &uniforms(), &grid_spans(256, &frags)).unwrap();
    assert!(fb.color == initial, "some RGB565 value changed under ZERO, ONE");
}

// ---------------------------------------------------------------------------
// Stencil (GL 1.5 §4.1.5).
// ---------------------------------------------------------------------------

/// The stencil value after `op` (before the write mask), 8-bit stencil.
fn spec_stencil_op(op: StencilOp, s: u8, r: u8) -> u8 {
    let s = u32::from(s);
    let v = match op {
        StencilOp::Keep => s,
        StencilOp::Zero => 0,
        StencilOp::Replace => u32::from(r),
        StencilOp::Incr => (s + 1).min(255),
        StencilOp::Decr => s.saturating_sub(1),
        StencilOp::Invert => 255 - s,
        StencilOp::IncrWrap => (s + 1) % 256,
        StencilOp::DecrWrap => (s + 255) % 256,
    };
    v as u8
}

/// Only the bits set in the write mask change.
fn spec_stencil_write(new: u8, old: u8, write_mask: u8) -> u8 {
    (new & write_mask) | (old & !write_mask)
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Outcome {
    StencilFail,
    DepthFail,
    DepthPass,
}

#[test]
fn stencil_every_op_for_every_outcome_with_write_masks() {
    let stored_values = [0u8, 1, 128, 254, 255];
    let write_masks = [0xffu8, 0x00, 0x0f, 0xf0, 0xa5];
    for &op in &StencilOp::ALL {
        for outcome in [Outcome::StencilFail, Outcome::DepthFail, Outcome::DepthPass] {
            for &stored in &stored_values {
                for &wm in &write_masks {
                    for reference in [0x5a, 0xff] {
                        // The other two outcomes get ops that would show if applied.
                        let (fail, zfail, zpass) = match outcome {
                            Outcome::StencilFail => (op, StencilOp::Invert, StencilOp::Replace),
                            Outcome::DepthFail => (StencilOp::Replace, op, StencilOp::Invert),
                            Outcome::DepthPass => (StencilOp::Invert, StencilOp::Zero, op),
                        };
                        let func = match outcome {
                            Outcome::StencilFail => CompareFunc::Never,
                            _ => CompareFunc::Always,
                        };
                        let mut fb = Fb::new(4, 1, ColorFormat::Rgba8)
                            .with_depth(DepthFormat::D24, 0x80_0000)
                            .with_stencil(0x33);
                        fb.set_stencil(1, 0, stored);
                        let key = FragmentKey {
                            stencil: Some(StencilKey {
                                func,
                                fail,
                                zfail,
                                zpass,
                            }),
                            depth: Some(DepthKey {
                                func: CompareFunc::Less,
                                write: true,
                            }),
                            ..fb.key()
                        };
                        let u = FragmentUniforms {
                            stencil_ref: reference,
                            stencil_value_mask: 0x0f,
                            stencil_write_mask: wm,
                            ..uniforms()
                        };
                        let z = if outcome == Outcome::DepthFail { 0x80_0000 } else { 0x10 };
                        fb.run(&key, &u, &[span(1, 0, &[(RED, z)])]).unwrap();
                        let want = spec_stencil_write(spec_stencil_op(op, stored, reference), stored, wm);
                        let ctx = format!("{op:?} on {outcome:?}, stored {stored}, ref {reference}, wmask {wm:#x}");
                        assert_eq!(fb.stencil(1, 0), want, "{ctx}");
                        for x in [0, 2, 3] {
                            assert_eq!(fb.stencil(x, 0), 0x33, "{ctx}: neighbour {x}");
                        }
                        let passed = outcome == Outcome::DepthPass;
                        let color: &[u8] = if passed { &RED } else { &[0; 4] };
                        assert_eq!(fb.pixel(1, 0), color, "{ctx}");
                        assert_eq!(fb.depth(1, 0), if passed { 0x10 } else { 0x80_0000 }, "{ctx}");
                    }
                }
            }
        }
    }
}

#[test]
fn stencil_without_depth_test_applies_zpass() {
    // With the depth test off (buffer present or not), a passing fragment takes zpass.
    for with_depth in [false, true] {
        for &op in &StencilOp::ALL {
            for stored in [0u8, 128, 255] {
                let mut fb = Fb::new(2, 1, ColorFormat::Rgb8).with_stencil(stored);
                if with_depth {
                    fb = fb.with_depth(DepthFormat::D16, 0);
                }
                let key = FragmentKey {
                    stencil: Some(StencilKey {
                        func: CompareFunc::Equal,
                        fail: StencilOp::Zero,
                        zfail: StencilOp::Zero,
                        zpass: op,
                    }),
                    ..fb.key()
                };
                let u = FragmentUniforms {
                    stencil_ref: stored,
                    stencil_write_mask: 0xff,
                    ..uniforms()
                };
                fb.run(&key, &u, &[span(0, 0, &[(RED, 0xffff)])]).unwrap();
                assert_eq!(
                    fb.stencil(0, 0),
                    spec_stencil_op(op, stored, stored),
                    "{op:?} at {stored}"
                );
                assert_eq!(fb.stencil(1, 0), stored);
                assert_eq!(fb.pixel(0, 0), &RED[..3]);
                if with_depth {
                    assert_eq!(fb.depth(0, 0), 0, "depth test off never writes depth");
                }
            }
        }
    }
}

#[test]
fn stencil_every_function_with_value_masks() {
    // GL compares (ref & mask) <func> (stored & mask).
    let value_masks = [0xffu8, 0x0f, 0xf0, 0x00];
    for &func in &FUNCS {
        for stored in [0u8, 0x23, 0x80, 0xff] {
            let refs = [stored.wrapping_sub(1), stored, stored.wrapping_add(1), 0x13, 0x00, 0xff];
            for &vm in &value_masks {
                let mut fb = Fb::new(refs.len() as u32, 1, ColorFormat::Rgba8).with_stencil(stored);
                for (x, &r) in refs.iter().enumerate() {
                    // One run per reference: it is a uniform.
                    let key = FragmentKey {
                        stencil: Some(StencilKey {
                            func,
                            fail: StencilOp::Invert,
                            zfail: StencilOp::Keep,
                            zpass: StencilOp::Replace,
                        }),
                        ..fb.key()
                    };
                    let u = FragmentUniforms {
                        stencil_ref: r,
                        stencil_value_mask: vm,
                        ..uniforms()
                    };
                    fb.run(&key, &u, &[span_rgba(x as u32, 0, &[RED])]).unwrap();
                    let pass = spec_compare(func, u32::from(r & vm), u32::from(stored & vm));
                    let ctx = format!("{func:?} ref {r:#x} stored {stored:#x} mask {vm:#x}");
                    // The value mask never limits what is written: REPLACE writes all of ref.
                    let want = if pass { r } else { !stored };
                    assert_eq!(fb.stencil(x as u32, 0), want, "{ctx}");
                    assert_eq!(fb.pixel(x as u32, 0), if pass { RED } else { [0; 4] }, "{ctx}");
                }
            }
        }
    }
    // Spelled out: 0x13 and 0x23 are equal under mask 0x0f and differ under 0xf0.
    let mut fb = Fb::new(2, 1, ColorFormat::Rgba8).with_stencil(0x23);
    let key = FragmentKey {
        stencil: Some(StencilKey {
            func: CompareFunc::Equal,
            fail: StencilOp::Keep,
            zfail: StencilOp::Keep,
            zpass: StencilOp::Keep,
        }),
        ..fb.key()
    };
    for (x, vm, written) in [(0u32, 0x0fu8, true), (1, 0xf0, false)] {
        let u = FragmentUniforms {
            stencil_ref: 0x13,
            stencil_value_mask: vm,
            ..uniforms()
        };
        fb.run(&key, &u, &[span_rgba(x, 0, &[RED])]).unwrap();
        assert_eq!(fb.pixel(x, 0) == RED, written, "mask {vm:#x}");
    }
}

// ---------------------------------------------------------------------------
// Depth (GL 1.5 §4.1.6): incoming z is clamped to the buffer's range.
// ---------------------------------------------------------------------------

fn depth_max(format: DepthFormat) -> u32 {
    match format {
        DepthFormat::D16 => (1 << 16) - 1,
        DepthFormat::D24 => (1 << 24) - 1,
        DepthFormat::D32 => u32::MAX,
        DepthFormat::D32F => 1.0f32.to_bits(),
    }
}

#[test]
fn depth_every_function_format_and_write_mask() {
    // (Float depth: values up to 1.0's bits are floats in [0, 1], ordered as their bits.)
    for format in [DepthFormat::D16, DepthFormat::D24, DepthFormat::D32, DepthFormat::D32F] {
        let max = depth_max(format);
        // (stored, incoming) pairs: equal, one below, one above, at and beyond max.
        let mut cases = Vec::new();
        for stored in [0, 1, max / 2, max - 1, max] {
            for incoming in [stored.wrapping_sub(1), stored, stored.wrapping_add(1), 0, max] {
                cases.push((stored, incoming));
            }
            for beyond in [max.saturating_add(1), max.saturating_add(12345), u32::MAX] {
                cases.push((stored, beyond));
            }
        }
        assert!(cases.len() <= SPAN_MAX);
        for &func in &FUNCS {
            for write in [false, true] {
                let mut fb = Fb::new(cases.len() as u32, 1, ColorFormat::Rgba8).with_depth(format, 0);
                for (x, &(stored, _)) in cases.iter().enumerate() {
                    fb.set_depth(x as u32, 0, stored);
                }
                let key = FragmentKey {
                    depth: Some(DepthKey { func, write }),
                    ..fb.key()
                };
                let frags: Vec<_> = cases.iter().map(|&(_, z)| (RED, z)).collect();
                fb.run(&key, &uniforms(), &[span(0, 0, &frags)]).unwrap();
                for (x, &(stored, incoming)) in cases.iter().enumerate() {
                    let z = incoming.min(max);
                    let pass = spec_compare(func, z, stored);
                    let ctx = format!("{format:?} {func:?} write {write}: incoming {incoming:#x} stored {stored:#x}");
                    let want = if pass && write { z } else { stored };
                    assert_eq!(fb.depth(x as u32, 0), want, "{ctx}");
                    assert!(fb.depth(x as u32, 0) <= max, "{ctx}");
                    assert_eq!(fb.pixel(x as u32, 0), if pass { RED } else { [0; 4] }, "{ctx}");
                }
            }
        }
    }
}

#[test]
fn depth_clamps_incoming_above_the_format_max() {
    // A D24 buffer keeps bits 24..32 zero; z beyond max compares and stores as max.
    let mut fb = Fb::new(3, 1, ColorFormat::Rgba8).with_depth(DepthFormat::D24, 0x00ff_ffff);
    let key = FragmentKey {
        depth: Some(DepthKey {
            func: CompareFunc::Lequal,
            write: true,
        }),
        ..fb.key()
    };
    let frags = [(RED, 0x0100_0000), (RED, u32::MAX), (RED, 0x00ff_ffff)];
    fb.run(&key, &uniforms(), &[span(0, 0, &frags)]).unwrap();
    for x in 0..3 {
        assert_eq!(fb.depth(x, 0), 0x00ff_ffff);
        assert_eq!(fb.pixel(x, 0), RED);
    }
    // LESS against max: a clamped z equals max, so it fails.
    let mut fb = Fb::new(1, 1, ColorFormat::Rgba8).with_depth(DepthFormat::D16, 0xffff);
    let key = FragmentKey {
        depth: Some(DepthKey {
            func: CompareFunc::Less,
            write: true,
        }),
        ..fb.key()
    };
    fb.run(&key, &uniforms(), &[span(0, 0, &[(RED, 0x1_0000)])]).unwrap();
    assert_eq!(fb.pixel(0, 0), [0; 4]);
    assert_eq!(fb.depth(0, 0), 0xffff);
}

// ---------------------------------------------------------------------------
// Alpha test (GL 1.5 §4.1.4): alpha <func> ref.
// ---------------------------------------------------------------------------

#[test]
fn alpha_test_every_function_around_the_reference() {
    for reference in [0u8, 1, 127, 128, 254, 255] {
        let mut alphas: Vec<u8> = vec![0, 255, reference];
        alphas.extend(reference.checked_sub(1));
        alphas.extend(reference.checked_add(1));
        for &func in &FUNCS {
            let mut fb = Fb::new(alphas.len() as u32, 1, ColorFormat::Rgba8);
            let key = FragmentKey {
                alpha_test: Some(func),
                ..fb.key()
            };
            let u = FragmentUniforms {
                alpha_ref: reference,
                ..uniforms()
            };
            let frags: Vec<_> = alphas.iter().map(|&a| [10, 20, 30, a]).collect();
            fb.run(&key, &u, &[span_rgba(0, 0, &frags)]).unwrap();
            for (x, &a) in alphas.iter().enumerate() {
                let pass = spec_compare(func, u32::from(a), u32::from(reference));
                let want = if pass { [10, 20, 30, a] } else { [0; 4] };
                assert_eq!(fb.pixel(x as u32, 0), want, "{func:?} alpha {a} ref {reference}");
            }
        }
    }
}

// ---------------------------------------------------------------------------
// Scissor (GL 1.5 §4.1.2): x0 <= x < x1, y0 <= y < y1, in window coordinates.
// ---------------------------------------------------------------------------

fn check_scissor(box_: [i32; 4], top_down: bool) {
    let (w, h) = (8u32, 8u32);
    let mut fb = Fb::new(w, h, ColorFormat::Rgba8);
    if top_down {
        fb = fb.top_down();
    }
    let key = FragmentKey {
        scissor: true,
        ..fb.key()
    };
    let u = FragmentUniforms {
        scissor: box_,
        ..uniforms()
    };
    // Rows as one span each, plus spans that start mid-row across the edges.
    let spans: Vec<_> = (0..h).map(|y| span_rgba(0, y, &[RED; 8])).collect();
    fb.run(&key, &u, &spans).unwrap();
    let [x0, y0, x1, y1] = box_;
    for y in 0..h {
        for x in 0..w {
            let (xi, yi) = (x as i32, y as i32);
            let inside = xi >= x0 && xi < x1 && yi >= y0 && yi < y1;
            assert_eq!(
                fb.pixel(x, y) == RED,
                inside,
                "box {box_:?} top_down {top_down}: ({x}, {y})"
            );
        }
    }
    // Spans of 5 starting mid-row, at x = 1, 2 or 3.
    let start = |y: u32| y % 3 + 1;
    let mut fb2 = Fb::new(w, h, ColorFormat::Rgba8);
    let spans: Vec<_> = (0..h).map(|y| span_rgba(start(y), y, &[BLUE; 5])).collect();
    fb2.run(&key, &u, &spans).unwrap();
    for y in 0..h {
        for x in 0..w {
            let (xi, yi) = (x as i32, y as i32);
            let covered = (start(y)..start(y) + 5).contains(&x);
            let inside = xi >= x0 && xi < x1 && yi >= y0 && yi < y1;
            assert_eq!(fb2.pixel(x, y) == BLUE, covered && inside, "box {box_:?}: ({x}, {y})");
        }
    }
}

#[test]
fn scissor_edges() {
    // Inside/outside each edge: columns 1|2 and 5|6, rows 2|3 and 6|7.
    check_scissor([2, 3, 6, 7], false);
    check_scissor([2, 3, 6, 7], true);
    check_scissor([0, 0, 8, 8], false);
    check_scissor([-5, -5, 100, 100], false);
    check_scissor([7, 7, 8, 8], false);
    // Empty boxes.
    check_scissor([3, 3, 3, 3], false);
    check_scissor([5, 0, 2, 8], false);
    check_scissor([0, 0, 0, 0], false);
}

// ---------------------------------------------------------------------------
// Logic op (GL 1.5 §4.1.10): bitwise on the stored representation.
// ---------------------------------------------------------------------------

/// The operation as the spec's table writes it.
fn spec_logic(op: LogicOp, s: u32, d: u32) -> u32 {
    match op {
        LogicOp::Clear => 0,
        LogicOp::And => s & d,
        LogicOp::AndReverse => s & !d,
        LogicOp::Copy => s,
        LogicOp::AndInverted => !s & d,
        LogicOp::Noop => d,
        LogicOp::Xor => s ^ d,
        LogicOp::Or => s | d,
        LogicOp::Nor => !(s | d),
        LogicOp::Equiv => !(s ^ d),
        LogicOp::Invert => !d,
        LogicOp::OrReverse => s | !d,
        LogicOp::CopyInverted => !s,
        LogicOp::OrInverted => !s | d,
        LogicOp::Nand => !(s & d),
        LogicOp::Set => !0,
    }
}

#[test]
fn logic_op_table_matches_gl_enum_truth_tables() {
    // The low four bits of GL_CLEAR..GL_SET (0x1500..0x150F) are each op's truth
    // table: bit (1 - s) * 2 + (1 - d) is the result for source bit s, dest bit d.
    for (code, &op) in LogicOp::ALL.iter().enumerate() {
        for s in 0..2u32 {
            for d in 0..2u32 {
                let bit = (code >> ((1 - s) * 2 + (1 - d))) & 1;
                assert_eq!(spec_logic(op, s, d) & 1, bit as u32, "{op:?} s={s} d={d}");
            }
        }
    }
}

const LS: u8 = 0b1100_1010;
const LD: u8 = 0b1010_0110;

#[test]
fn logic_op_all_sixteen_rgba8() {
    let src = [LS, !LS, LS.rotate_left(1), LS];
    let dst = [LD, LD, !LD, LD.rotate_left(3)];
    for &op in &LogicOp::ALL {
        let mut fb = Fb::new(4, 1, ColorFormat::Rgba8);
        fb.set_pixel(1, 0, &dst);
        fb.set_pixel(2, 0, &dst);
        let key = FragmentKey {
            logic_op: Some(op),
            ..fb.key()
        };
        fb.run(&key, &uniforms(), &[span_rgba(1, 0, &[src])]).unwrap();
        let want: [u8; 4] = std::array::from_fn(|c| spec_logic(op, u32::from(src[c]), u32::from(dst[c])) as u8);
        assert_eq!(fb.pixel(1, 0), want, "{op:?}");
        assert_eq!(fb.pixel(2, 0), dst, "{op:?} neighbour");
        assert_eq!(fb.pixel(0, 0), [0; 4], "{op:?} neighbour");
    }
}

#[test]
fn logic_op_all_sixteen_rgb565() {
    // s = 0xCACA is R 25, G 22, B 10; send the bytes nearest those levels.
    let s: u32 = 0xCACA;
    let d: u16 = 0xA6A6;
    let src = [
        spec_expand(s >> 11, 5),
        spec_expand((s >> 5) & 63, 6),
        spec_expand(s & 31, 5),
        255,
    ];
    assert_eq!(u32::from(spec_565(src)), s);
    // Dithering comes before the logic op; 0 and 255 are exact levels it cannot move.
    let (src_exact, s_exact) = ([255, 0, 255, 255], 0xF81F);
    let cases = [(src, s, false), (src_exact, s_exact, false), (src_exact, s_exact, true)];
    for &op in &LogicOp::ALL {
        for (src, s, dither) in cases {
            let mut fb = Fb::new(2, 1, ColorFormat::Rgb565);
            fb.set_pixel(0, 0, &d.to_le_bytes());
            fb.set_pixel(1, 0, &d.to_le_bytes());
            let key = FragmentKey {
                logic_op: Some(op),
                dither,
                ..fb.key()
            };
            fb.run(&key, &uniforms(), &[span_rgba(0, 0, &[src])]).unwrap();
            let want = (spec_logic(op, s, u32::from(d)) & 0xffff) as u16;
            assert_eq!(fb.pixel(0, 0), want.to_le_bytes(), "{op:?} s {s:#x} dither {dither}");
            assert_eq!(fb.pixel(1, 0), d.to_le_bytes());
        }
    }
    // Through a color mask: only green's bits take the result.
    let mut fb = Fb::new(1, 1, ColorFormat::Rgb565);
    fb.set_pixel(0, 0, &d.to_le_bytes());
    let key = FragmentKey {
        logic_op: Some(LogicOp::Xor),
        color_mask: ColorMask {
            r: false,
            g: true,
            b: false,
            a: true,
        },
        ..fb.key()
    };
    fb.run(&key, &uniforms(), &[span_rgba(0, 0, &[src])]).unwrap();
    let want = ((s as u16 ^ d) & 0x07e0) | (d & !0x07e0);
    assert_eq!(fb.pixel(0, 0), want.to_le_bytes());
}

// ---------------------------------------------------------------------------
// Color mask (GL 1.5 §4.2.2): bytes in memory order.
// ---------------------------------------------------------------------------

#[test]
fn color_mask_each_channel_each_format() {
    let src = [0x11, 0x82, 0xf3, 0x44];
    let dst_rgba = [0xe0, 0x1d, 0x5c, 0xbb];
    for format in [
        ColorFormat::Rgba8,
        ColorFormat::Bgra8,
        ColorFormat::Rgb8,
        ColorFormat::Rgb565,
    ] {
        for bits in 0..16u32 {
            let mask = ColorMask::from_bits(bits);
            let mut fb = Fb::new(2, 1, format);
            let dst = encoded(format, dst_rgba);
            fb.set_pixel(0, 0, &dst);
            fb.set_pixel(1, 0, &dst);
            let key = FragmentKey {
                color_mask: mask,
                ..fb.key()
            };
            fb.run(&key, &uniforms(), &[span_rgba(0, 0, &[src])]).unwrap();
            let want = match format {
                ColorFormat::Rgb565 => {
                    let (s, d) = (spec_565(src), spec_565(dst_rgba));
                    let m = |on: bool, bits: u16| if on { bits } else { 0 };
                    let bits = m(mask.r, 0xf800) | m(mask.g, 0x07e0) | m(mask.b, 0x001f);
                    ((s & bits) | (d & !bits)).to_le_bytes().to_vec()
                }
                _ => {
                    let pick = |on: bool, c: usize| if on { src[c] } else { dst_rgba[c] };
                    let chosen = [pick(mask.r, 0), pick(mask.g, 1), pick(mask.b, 2), pick(mask.a, 3)];
                    encoded(format, chosen)
                }
            };
            assert_eq!(fb.pixel(0, 0), want, "{format:?} {mask:?}");
            assert_eq!(fb.pixel(1, 0), dst, "{format:?} {mask:?} neighbour");
        }
    }
    // Spelled out for BGRA8 with only red on: memory byte 2 changes.
    let mut fb = Fb::new(1, 1, ColorFormat::Bgra8);
    fb.set_pixel(0, 0, &[1, 2, 3, 4]);
    let key = FragmentKey {
        color_mask: ColorMask {
            r: true,
            g: false,
            b: false,
            a: false,
        },
        ..fb.key()
    };
    fb.run(&key, &uniforms(), &[span_rgba(0, 0, &[[0xaa, 0xbb, 0xcc, 0xdd]])])
        .unwrap();
    assert_eq!(fb.pixel(0, 0), [1, 2, 0xaa, 4]);
}

// ---------------------------------------------------------------------------
// RGB565 conversion and dithering (GL 1.5 §2.14.9, §4.1.9).
// ---------------------------------------------------------------------------

#[test]
fn rgb565_keeps_the_high_bits_without_dither() {
    let mut fb = Fb::new(64, 4, ColorFormat::Rgb565);
    let frags: Vec<_> = (0..=255u8).map(|c| ([c, c, c, 255], 0)).collect();
    fb.run(&fb.key(), &uniforms(), &grid_spans(64, &frags)).unwrap();
    for c in 0..=255u8 {
        let (x, y) = grid_pos(64, usize::from(c));
        let v = u16::from_le_bytes([fb.pixel(x, y)[0], fb.pixel(x, y)[1]]);
        let (r, g, b) = (u32::from(v >> 11), u32::from((v >> 5) & 63), u32::from(v & 31));
        assert_eq!(
            (r, g, b),
            (spec_reduce(c, 5), spec_reduce(c, 6), spec_reduce(c, 5)),
            "byte {c}"
        );
    }
    // Spelled out: 7 (0.85 of a 5-bit step) stores 0, 8 stores 1.
    let stored = |c: u8| {
        let (x, y) = grid_pos(64, usize::from(c));
        u16::from_le_bytes([fb.pixel(x, y)[0], fb.pixel(x, y)[1]]) >> 11
    };
    assert_eq!(
        (stored(7), stored(8), stored(127), stored(128), stored(255)),
        (0, 1, 15, 16, 31)
    );
}

#[test]
fn rgb565_dither_picks_floor_or_ceil_with_the_bayer_counts() {
    // Byte c fills a 4x4 block at block (c % 16, c / 16) of a 64x64 target. On the
    // exact value c * max / 255 every dithered level is its floor or floor + 1;
    // the bias at matrix entry b is (16 b + 7) / 255 of a level, so the block has
    // floor + 1 exactly where frac * 255 + 16 b + 7 >= 255, and its mean is within
    // 1/32 of a level of the exact value.
    let mut entries: Vec<u32> = BAYER4.iter().flatten().map(|&b| u32::from(b)).collect();
    entries.sort_unstable();
    assert_eq!(entries, (0..16).collect::<Vec<_>>(), "BAYER4 is a permutation of 0..16");

    let mut fb = Fb::new(64, 64, ColorFormat::Rgb565);
    let frags: Vec<_> = (0..64 * 64)
        .map(|i| {
            let (x, y) = (i % 64, i / 64);
            let c = (y / 4 * 16 + x / 4) as u8;
            ([c, c, c, 255], 0)
        })
        .collect();
    let key = FragmentKey {
        dither: true,
        ..fb.key()
    };
    fb.run(&key, &uniforms(), &grid_spans(64, &frags)).unwrap();
    for c in 0..=255u8 {
        let (bx, by) = (u32::from(c) % 16 * 4, u32::from(c) / 16 * 4);
        for (bits, shift) in [(5u32, 11u32), (6, 5), (5, 0)] {
            let max = (1u32 << bits) - 1;
            let exact = f64::from(c) * f64::from(max) / 255.0;
            let floor = exact.floor() as u32;
            let residue = u32::from(c) * max % 255;
            let mut ceil_count = 0;
            let mut sum = 0;
            for y in by..by + 4 {
                for x in bx..bx + 4 {
                    let p = fb.pixel(x, y);
                    let v = (u32::from(u16::from_le_bytes([p[0], p[1]])) >> shift) & max;
                    assert!(v == floor || v == floor + 1, "byte {c} {bits}-bit at ({x}, {y}): {v}");
                    let b = u32::from(BAYER4[(y & 3) as usize][(x & 3) as usize]);
                    let want_ceil = residue + 16 * b + 7 >= 255;
                    assert_eq!(
                        v == floor + 1,
                        want_ceil,
                        "byte {c} {bits}-bit at ({x}, {y}), entry {b}"
                    );
                    ceil_count += u32::from(v == floor + 1);
                    sum += v;
                }
            }
            let from_matrix = BAYER4
                .iter()
                .flatten()
                .filter(|&&b| residue + 16 * u32::from(b) + 7 >= 255)
                .count();
            assert_eq!(ceil_count as usize, from_matrix, "byte {c} {bits}-bit");
            let mean = f64::from(sum) / 16.0;
            assert!(
                (mean - exact).abs() <= 1.0 / 32.0,
                "byte {c} {bits}-bit: mean {mean} vs {exact}"
            );
            if c == 0 || c == 255 {
                assert_eq!(ceil_count, 0, "exact levels never dither");
            }
        }
    }
}

#[test]
fn dither_is_the_identity_on_8_bit_formats() {
    for format in [ColorFormat::Rgba8, ColorFormat::Bgra8, ColorFormat::Rgb8] {
        let mut fb = Fb::new(8, 4, format);
        let key = FragmentKey {
            dither: true,
            ..fb.key()
        };
        let frags: Vec<_> = (0..32u8).map(|i| ([i * 7 + 3, 255 - i, i * 5, i], 0)).collect();
        fb.run(&key, &uniforms(), &grid_spans(8, &frags)).unwrap();
        for (i, &(c, _)) in frags.iter().enumerate() {
            let (x, y) = grid_pos(8, i);
            assert_eq!(fb.pixel(x, y), encoded(format, c), "{format:?}");
        }
    }
}

// ---------------------------------------------------------------------------
// Stage lists, normalization and validation.
// ---------------------------------------------------------------------------

fn stage_list(key: &FragmentKey) -> Vec<Stage> {
    let stages: Stages = key.stages();
    stages.as_slice().to_vec()
}

const OVER: BlendKey = BlendKey {
    src_rgb: BlendFactor::SrcAlpha,
    dst_rgb: BlendFactor::OneMinusSrcAlpha,
    src_alpha: BlendFactor::One,
    dst_alpha: BlendFactor::Zero,
    eq_rgb: BlendEquation::Add,
    eq_alpha: BlendEquation::Add,
};

const STENCIL: StencilKey = StencilKey {
    func: CompareFunc::Equal,
    fail: StencilOp::Keep,
    zfail: StencilOp::Incr,
    zpass: StencilOp::Replace,
};

const DEPTH: DepthKey = DepthKey {
    func: CompareFunc::Less,
    write: true,
};

fn all_on(format: ColorFormat) -> FragmentKey {
    FragmentKey {
        scissor: true,
        alpha_test: Some(CompareFunc::Greater),
        stencil: Some(STENCIL),
        depth: Some(DEPTH),
        blend: Some(OVER),
        dither: true,
        ..FragmentKey::new(format, Some(DepthFormat::D24), true)
    }
}

#[test]
fn stages_all_off_is_pack_and_write() {
    let key = FragmentKey::new(ColorFormat::Rgba8, None, false);
    assert_eq!(
        stage_list(&key),
        [Stage::Pack { dither: false }, Stage::ColorWrite(ColorMask::ALL)]
    );
    // Buffers alone add no stage.
    let key = FragmentKey::new(ColorFormat::Rgb565, Some(DepthFormat::D16), true);
    assert_eq!(
        stage_list(&key),
        [
            Stage::Pack { dither: false },
            Stage::ColorWrite(ColorMask {
                a: false,
                ..ColorMask::ALL
            })
        ]
    );
}

#[test]
fn stages_all_on_in_gl_order() {
    let key = all_on(ColorFormat::Rgb565);
    assert_eq!(
        stage_list(&key),
        [
            Stage::Scissor,
            Stage::AlphaTest(CompareFunc::Greater),
            Stage::StencilTest {
                stencil: STENCIL,
                depth_on: true
            },
            Stage::DepthTest {
                depth: DEPTH,
                stencil: Some(STENCIL)
            },
            Stage::Blend(OVER),
            Stage::Pack { dither: true },
            Stage::ColorWrite(ColorMask {
                a: false,
                ..ColorMask::ALL
            }),
        ]
    );
    // On an 8-bit format dithering does nothing, so Pack does not dither.
    let key = all_on(ColorFormat::Rgba8);
    assert!(stage_list(&key).contains(&Stage::Pack { dither: false }));
    assert!(stage_list(&key).contains(&Stage::ColorWrite(ColorMask::ALL)));
}

#[test]
fn stages_stencil_and_depth_alone() {
    let base = FragmentKey::new(ColorFormat::Rgba8, Some(DepthFormat::D32), true);
    let stencil_only = FragmentKey {
        stencil: Some(STENCIL),
        ..base
    };
    assert_eq!(
        stage_list(&stencil_only)[0],
        Stage::StencilTest {
            stencil: STENCIL,
            depth_on: false
        }
    );
    let depth_only = FragmentKey {
        depth: Some(DEPTH),
        ..base
    };
    assert_eq!(
        stage_list(&depth_only)[0],
        Stage::DepthTest {
            depth: DEPTH,
            stencil: None
        }
    );
    assert_eq!(stage_list(&depth_only).len(), 3);
}

#[test]
fn stages_logic_op_drops_blend() {
    let key = FragmentKey {
        logic_op: Some(LogicOp::Xor),
        ..all_on(ColorFormat::Rgba8)
    };
    let stages = stage_list(&key);
    assert!(!stages.iter().any(|s| matches!(s, Stage::Blend(_))));
    assert_eq!(
        stages[stages.len() - 3..],
        [
            Stage::Pack { dither: false },
            Stage::LogicOp(LogicOp::Xor),
            Stage::ColorWrite(ColorMask::ALL)
        ]
    );
}

#[test]
fn stages_color_mask_none_drops_color_stages() {
    let drop_color = |key: FragmentKey| {
        let stages = stage_list(&key);
        assert!(
            !stages.iter().any(|s| matches!(
                s,
                Stage::Blend(_) | Stage::Pack { .. } | Stage::LogicOp(_) | Stage::ColorWrite(_)
            )),
            "{stages:?}"
        );
        stages
    };
    let none = FragmentKey {
        color_mask: ColorMask::NONE,
        ..all_on(ColorFormat::Rgba8)
    };
    assert_eq!(drop_color(none).len(), 4, "scissor, alpha, stencil and depth stay");
    drop_color(FragmentKey {
        logic_op: Some(LogicOp::Set),
        blend: None,
        ..none
    });
    // Only alpha on a format without alpha writes nothing either.
    for format in [ColorFormat::Rgb8, ColorFormat::Rgb565] {
        let alpha_only = FragmentKey {
            color_mask: ColorMask {
                a: true,
                ..ColorMask::NONE
            },
            ..all_on(format)
        };
        drop_color(alpha_only);
    }
    // And it really writes nothing, while depth and stencil still update.
    let mut fb = Fb::new(2, 1, ColorFormat::Rgb8)
        .with_depth(DepthFormat::D24, 100)
        .with_stencil(7);
    let key = FragmentKey {
        stencil: Some(STENCIL),
        depth: Some(DEPTH),
        blend: Some(OVER),
        color_mask: ColorMask {
            a: true,
            ..ColorMask::NONE
        },
        ..fb.key()
    };
    let u = FragmentUniforms {
        stencil_ref: 7,
        ..uniforms()
    };
    fb.run(&key, &u, &[span(0, 0, &[(RED, 50)])]).unwrap();
    assert_eq!(fb.pixel(0, 0), [0, 0, 0]);
    assert_eq!(fb.depth(0, 0), 50);
    assert_eq!(fb.stencil(0, 0), 7, "zpass REPLACE with ref 7");
}

#[test]
fn normalized_drops_what_cannot_have_an_effect() {
    // No buffers: the tests go.
    let key = FragmentKey {
        stencil: Some(STENCIL),
        depth: Some(DEPTH),
        ..FragmentKey::new(ColorFormat::Rgba8, None, false)
    };
    assert_eq!(key.validate(), Err(KeyError::StencilWithoutBuffer));
    assert_eq!(key.normalized(), FragmentKey::new(ColorFormat::Rgba8, None, false));
    let key = FragmentKey {
        depth: Some(DEPTH),
        ..FragmentKey::new(ColorFormat::Rgba8, None, true)
    };
    assert_eq!(key.validate(), Err(KeyError::DepthWithoutBuffer));
    // Logic op wins over blend.
    let key = FragmentKey {
        logic_op: Some(LogicOp::Or),
        ..all_on(ColorFormat::Rgba8)
    };
    assert_eq!(key.validate(), Err(KeyError::BlendWithLogicOp));
    assert_eq!(key.normalized().blend, None);
    assert_eq!(key.normalized().logic_op, Some(LogicOp::Or));
    // Dither only on reduced formats.
    assert!(!all_on(ColorFormat::Rgba8).normalized().dither);
    assert!(all_on(ColorFormat::Rgb565).normalized().dither);
    // Alpha mask bit only where alpha is stored.
    assert!(!all_on(ColorFormat::Rgb8).normalized().color_mask.a);
    assert!(all_on(ColorFormat::Bgra8).normalized().color_mask.a);
    // Writing nothing drops blend, logic op and dither; tests stay.
    let n = FragmentKey {
        color_mask: ColorMask {
            a: true,
            ..ColorMask::NONE
        },
        ..all_on(ColorFormat::Rgb565)
    }
    .normalized();
    assert_eq!((n.blend, n.logic_op, n.dither), (None, None, false));
    assert_eq!(
        (n.scissor, n.alpha_test, n.stencil, n.depth),
        (true, Some(CompareFunc::Greater), Some(STENCIL), Some(DEPTH))
    );
    // Keys that behave the same normalize equal.
    let a = FragmentKey {
        dither: true,
        ..FragmentKey::new(ColorFormat::Rgb8, None, false)
    };
    assert_ne!(a, FragmentKey::new(ColorFormat::Rgb8, None, false));
    assert_eq!(
        a.normalized(),
        FragmentKey::new(ColorFormat::Rgb8, None, false).normalized()
    );
}

#[test]
fn normalized_is_valid_idempotent_and_keeps_the_stage_list() {
    let mut keys = Vec::new();
    for format in [
        ColorFormat::Rgba8,
        ColorFormat::Bgra8,
        ColorFormat::Rgb8,
        ColorFormat::Rgb565,
    ] {
        for depth_format in [None, Some(DepthFormat::D16), Some(DepthFormat::D24)] {
            for stencil_buffer in [false, true] {
                for bits in 0..64u32 {
                    keys.push(FragmentKey {
                        scissor: bits & 1 != 0,
                        stencil: (bits & 2 != 0).then_some(STENCIL),
                        depth: (bits & 4 != 0).then_some(DEPTH),
                        blend: (bits & 8 != 0).then_some(OVER),
                        logic_op: (bits & 16 != 0).then_some(LogicOp::Nand),
                        dither: true,
                        color_mask: if bits & 32 != 0 {
                            ColorMask::NONE
                        } else {
                            ColorMask::ALL
                        },
                        ..FragmentKey::new(format, depth_format, stencil_buffer)
                    });
                }
            }
        }
    }
    for key in keys {
        let n = key.normalized();
        assert_eq!(n.validate(), Ok(()), "{key:?}");
        assert_eq!(n.normalized(), n, "{key:?}");
        // Normalizing a valid key never changes what it runs.
        if key.validate().is_ok() {
            assert_eq!(stage_list(&n), stage_list(&key), "{key:?}");
        }
    }
}

// ---------------------------------------------------------------------------
// Pixel ownership (GL 1.5 §4.1.1): fragments outside the target are dropped.
// ---------------------------------------------------------------------------

/// Runs `spans` on a 4x2 RGBA8 + D24 + S8 target whose buffers have one extra
/// guard row each, and returns which target pixels were written. Panics if a
/// guard byte changed.
const NOTHING: [(u32, u32); 0] = [];

fn written_pixels(spans: &[FragmentSpan]) -> Vec<(u32, u32)> {
    let (w, h) = (4u32, 2u32);
    let mut color = vec![0xaau8; (w * (h + 1) * 4) as usize];
    let mut depth = vec![0x00ff_ffffu32; (w * (h + 1)) as usize];
    let mut stencil = vec![0x77u8; (w * (h + 1)) as usize];
    let key = FragmentKey {
        stencil: Some(StencilKey {
            func: CompareFunc::Always,
            fail: StencilOp::Keep,
            zfail: StencilOp::Keep,
            zpass: StencilOp::Replace,
        }),
        depth: Some(DepthKey {
            func: CompareFunc::Always,
            write: true,
        }),
        ..FragmentKey::new(ColorFormat::Rgba8, Some(DepthFormat::D24), true)
    };
    let u = FragmentUniforms {
        stencil_ref: 0x11,
        ..uniforms()
    };
    let mut t = Target::new(
        w,
        h,
        ColorFormat::Rgba8,
        &mut color,
        (w * 4) as usize,
        Some(DepthTarget::D24(&mut depth)),
        Some(&mut stencil),
    )
    .unwrap();
    run(&key, &u, spans, &mut t).unwrap();
    let mut written = Vec::new();
    for i in 0..(w * (h + 1)) as usize {
        let px = &color[i * 4..i * 4 + 4];
        let hit = px == RED;
        assert_eq!(depth[i] == 5, hit, "pixel {i}: depth and color disagree");
        assert_eq!(stencil[i] == 0x11, hit, "pixel {i}: stencil and color disagree");
        if !hit {
            assert_eq!(px, [0xaa; 4], "pixel {i} partly written");
            assert_eq!((depth[i], stencil[i]), (0x00ff_ffff, 0x77), "pixel {i}");
        }
        if hit {
            let (x, y) = (i as u32 % w, i as u32 / w);
            assert!(y < h, "guard row written at x {x}");
            written.push((x, y));
        }
    }
    written
}

fn full_span(x: u32, y: u32, len: u32, mask: u64) -> FragmentSpan {
    let mut s = FragmentSpan::new(x, y);
    for i in 0..SPAN_MAX {
        s.set(i, RED, 5);
    }
    s.len = len;
    s.mask = mask;
    s
}

#[test]
fn ownership_drops_fragments_outside_the_target() {
    // Past the right edge: row 0 would spill into row 1, row 1 into the guard.
    assert_eq!(written_pixels(&[full_span(2, 0, 4, 0xf)]), [(2, 0), (3, 0)]);
    assert_eq!(written_pixels(&[full_span(2, 1, 64, !0)]), [(2, 1), (3, 1)]);
    assert_eq!(written_pixels(&[full_span(3, 1, 2, 0b11)]), [(3, 1)]);
    // Rows and columns outside.
    assert_eq!(written_pixels(&[full_span(0, 2, 4, 0xf)]), NOTHING);
    assert_eq!(written_pixels(&[full_span(4, 0, 4, 0xf)]), NOTHING);
    assert_eq!(written_pixels(&[full_span(0, u32::MAX, 64, !0)]), NOTHING);
    assert_eq!(written_pixels(&[full_span(u32::MAX, 0, 64, !0)]), NOTHING);
    assert_eq!(written_pixels(&[full_span(u32::MAX - 1, u32::MAX, 64, !0)]), NOTHING);
    // Whole row.
    assert_eq!(
        written_pixels(&[full_span(0, 1, 4, 0xf)]),
        [(0, 1), (1, 1), (2, 1), (3, 1)]
    );
}

#[test]
fn ownership_respects_len_and_mask() {
    // len 0 writes nothing, whatever the mask says.
    assert_eq!(written_pixels(&[full_span(0, 0, 0, !0)]), NOTHING);
    // Uncovered bits write nothing.
    assert_eq!(written_pixels(&[full_span(0, 0, 4, 0b0101)]), [(0, 0), (2, 0)]);
    assert_eq!(written_pixels(&[full_span(0, 1, 4, 0)]), NOTHING);
    // Mask bits beyond len are ignored.
    assert_eq!(written_pixels(&[full_span(0, 0, 2, !0)]), [(0, 0), (1, 0)]);
    // A len beyond SPAN_MAX is capped, not trusted.
    assert_eq!(written_pixels(&[full_span(0, 0, 1000, 0b1001)]), [(0, 0), (3, 0)]);
    // Several spans.
    let spans = [full_span(1, 0, 1, 1), full_span(3, 1, 1, 1), full_span(9, 9, 1, 1)];
    assert_eq!(written_pixels(&spans), [(1, 0), (3, 1)]);
    // On a target as wide as a span: len 63 drops slot 63, len 64 keeps it.
    for len in [63u32, 64] {
        let mut fb = Fb::new(64, 1, ColorFormat::Rgba8);
        fb.run(&fb.key(), &uniforms(), &[full_span(0, 0, len, !0)]).unwrap();
        let written: Vec<u32> = (0..64).filter(|&x| fb.pixel(x, 0) == RED).collect();
        assert_eq!(written, (0..len).collect::<Vec<_>>(), "len {len}");
    }
}

// ---------------------------------------------------------------------------
// Top-down targets.
// ---------------------------------------------------------------------------

#[test]
fn top_down_writes_row_y_at_memory_row_height_minus_1_minus_y() {
    let (w, h) = (4u32, 3u32);
    let mut color = vec![0u8; (w * h * 4) as usize];
    let mut depth = vec![0xffffu16; (w * h) as usize];
    let mut stencil = vec![0u8; (w * h) as usize];
    let key = FragmentKey {
        stencil: Some(StencilKey {
            func: CompareFunc::Always,
            fail: StencilOp::Keep,
            zfail: StencilOp::Keep,
            zpass: StencilOp::Incr,
        }),
        depth: Some(DEPTH),
        ..FragmentKey::new(ColorFormat::Rgba8, Some(DepthFormat::D16), true)
    };
    let mut t = Target::new(
        w,
        h,
        ColorFormat::Rgba8,
        &mut color,
        (w * 4) as usize,
        Some(DepthTarget::D16(&mut depth)),
        Some(&mut stencil),
    )
    .unwrap()
    .with_top_down(true);
    let spans = [span(1, 0, &[([1, 2, 3, 4], 10)]), span(2, 2, &[([5, 6, 7, 8], 20)])];
    run(&key, &uniforms(), &spans, &mut t).unwrap();
    let px = |x: u32, row: u32| {
        let off = ((row * w + x) * 4) as usize;
        &color[off..off + 4]
    };
    assert_eq!(px(1, 2), [1, 2, 3, 4], "window row 0 is memory row 2");
    assert_eq!(px(2, 0), [5, 6, 7, 8], "window row 2 is memory row 0");
    let written = color.chunks(4).filter(|p| p != &[0; 4]).count();
    assert_eq!(written, 2);
    // Depth and stencil rows stay bottom-up.
    assert_eq!((depth[1], depth[2 * 4 + 2]), (10, 20));
    assert_eq!((stencil[1], stencil[2 * 4 + 2]), (1, 1));
    assert_eq!(depth.iter().filter(|&&d| d != 0xffff).count(), 2);
    // Scissor stays in window coordinates: box row 0 only.
    let mut fb = Fb::new(2, 2, ColorFormat::Rgb8).top_down();
    let key = FragmentKey {
        scissor: true,
        ..fb.key()
    };
    let u = FragmentUniforms {
        scissor: [0, 0, 2, 1],
        ..uniforms()
    };
    fb.run(&key, &u, &[span_rgba(0, 0, &[RED; 2]), span_rgba(0, 1, &[RED; 2])])
        .unwrap();
    assert_eq!(fb.color, [0, 0, 0, 0, 0, 0, 255, 0, 0, 255, 0, 0]);
}

// ---------------------------------------------------------------------------
// Errors.
// ---------------------------------------------------------------------------

#[test]
fn mismatched_key_and_target_is_an_error_and_writes_nothing() {
    let mut fb = Fb::new(2, 1, ColorFormat::Rgba8)
        .with_depth(DepthFormat::D24, 7)
        .with_stencil(3);
    let good = fb.key();
    let spans = [span(0, 0, &[(RED, 1)])];
    let wrong = [
        FragmentKey {
            color_format: ColorFormat::Bgra8,
            ..good
        },
        FragmentKey {
            depth_format: Some(DepthFormat::D16),
            ..good
        },
        FragmentKey {
            depth_format: Some(DepthFormat::D32),
            ..good
        },
        FragmentKey {
            depth_format: None,
            ..good
        },
        FragmentKey {
            stencil_buffer: false,
            ..good
        },
    ];
    for key in wrong {
        assert_eq!(
            fb.run(&key, &uniforms(), &spans),
            Err(FragmentError::TargetMismatch),
            "{key:?}"
        );
    }
    let mut bare = Fb::new(2, 1, ColorFormat::Rgba8);
    assert_eq!(bare.run(&good, &uniforms(), &spans), Err(FragmentError::TargetMismatch));
    assert_eq!(fb.color, [0; 8]);
    assert_eq!(bare.color, [0; 8]);
    assert_eq!((fb.depth(0, 0), fb.stencil(0, 0)), (7, 3));
    fb.run(&good, &uniforms(), &spans).unwrap();
    assert_eq!(fb.pixel(0, 0), RED);
}

#[test]
fn invalid_key_is_an_error_and_writes_nothing() {
    let spans = [span_rgba(0, 0, &[RED])];
    let mut fb = Fb::new(1, 1, ColorFormat::Rgba8);
    let key = FragmentKey {
        stencil: Some(STENCIL),
        ..fb.key()
    };
    assert_eq!(
        fb.run(&key, &uniforms(), &spans),
        Err(FragmentError::Key(KeyError::StencilWithoutBuffer))
    );
    let key = FragmentKey {
        depth: Some(DEPTH),
        ..fb.key()
    };
    assert_eq!(
        fb.run(&key, &uniforms(), &spans),
        Err(FragmentError::Key(KeyError::DepthWithoutBuffer))
    );
    let key = FragmentKey {
        blend: Some(OVER),
        logic_op: Some(LogicOp::Copy),
        ..fb.key()
    };
    assert_eq!(
        fb.run(&key, &uniforms(), &spans),
        Err(FragmentError::Key(KeyError::BlendWithLogicOp))
    );
    assert_eq!(fb.color, [0; 4]);
    // The normalized key runs.
    fb.run(&key.normalized(), &uniforms(), &spans).unwrap();
    assert_eq!(fb.pixel(0, 0), RED);
}

// ---------------------------------------------------------------------------
// The shading stage: planes to colour and depth.
// ---------------------------------------------------------------------------

/// `round(c · 255)` of a colour clamped to [0, 1] (§2.14.9).
fn spec_unorm8(c: f64) -> u8 {
    (c.clamp(0.0, 1.0) * 255.0).round() as u8
}

/// A 4x1 RGBA8 + D24 framebuffer, the depth test ALWAYS writing, and one
/// full span over it naming planes 0.
fn shaded(shade: ShadeKey) -> (Fb, FragmentKey, Vec<FragmentSpan>) {
    let fb = Fb::new(4, 1, ColorFormat::Rgba8).with_depth(DepthFormat::D24, 0);
    let key = FragmentKey {
        depth: Some(DepthKey {
            func: CompareFunc::Always,
            write: true,
        }),
        shade: Some(shade),
        ..fb.key()
    };
    let s = span(0, 0, &[([0; 4], 0); 4]);
    (fb, key, vec![s])
}

#[test]
fn shading_interpolates_over_w_divides_and_takes_depth_from_its_plane() {
    let (mut fb, key, spans) = shaded(ShadeKey {
        color: true,
        depth: true,
        ..ShadeKey::default()
    });
    // 1/w = 2 everywhere; red over w from 0.4 rising 0.125 a pixel (red 0.2 +
    // 0.0625 x); green over w 1.2 (0.6); blue 0; alpha over w 2 (1.0). Depth
    // 0.25 + 0.125 x. Row 0 of a 1-high target is llvmpipe's row 0, so dy is unused.
    let mut p = Planes::default();
    p.set(slot::INV_W, 2.0, 0.0, 7.0);
    p.set(slot::COLOR, 0.4, 0.125, 3.0);
    p.constant(slot::COLOR + 1, 1.2);
    p.constant(slot::COLOR + 3, 2.0);
    p.set(slot::Z, 0.25, 0.125, 5.0);
    fb.run_planes(&key, &uniforms(), &spans, &[p]);
    for x in 0..4u32 {
        let r = (0.4 + 0.125 * f64::from(x)) / 2.0;
        assert_eq!(fb.pixel(x, 0), &[spec_unorm8(r), spec_unorm8(0.6), 0, 255], "x = {x}");
        let z = 0.25 + 0.125 * f64::from(x);
        assert_eq!(fb.depth(x, 0), (z * f64::from(0xff_ffffu32)).round() as u32);
    }
}

#[test]
fn flat_colours_are_their_planes_values_and_the_sum_saturates() {
    let (mut fb, key, spans) = shaded(ShadeKey {
        color: true,
        flat: true,
        color_sum: true,
        ..ShadeKey::default()
    });
    let mut p = Planes::default();
    p.constant(slot::INV_W, 4.0); // not divided by: flat
    for (k, v) in [(0, 0.8), (1, 0.1), (2, 0.35), (3, 0.4)] {
        p.constant(slot::COLOR + k, v);
    }
    for (k, v) in [(0, 0.5), (1, 0.25), (2, 0.0)] {
        p.constant(slot::SECONDARY + k, v);
    }
    fb.run_planes(&key, &uniforms(), &spans, &[p]);
    // RGB sums (0.8 + 0.5 saturates), alpha the primary's.
    assert_eq!(
        fb.pixel(2, 0),
        &[255, spec_unorm8(0.35), spec_unorm8(0.35), spec_unorm8(0.4)]
    );
}

#[test]
fn linear_fog_blends_towards_the_fog_colour() {
    let (mut fb, key, spans) = shaded(ShadeKey {
        color: true,
        fog: Some(FogMode::Linear),
        ..ShadeKey::default()
    });
    // Fog coordinate x (over w, w = 1), start 0, end 4: f = (4 − x) / 4.
    let mut p = Planes::default();
    p.constant(slot::INV_W, 1.0);
    p.constant(slot::COLOR, 1.0);
    p.constant(slot::COLOR + 3, 0.6);
    p.set(slot::FOG, 0.0, 1.0, 0.0);
    let u = FragmentUniforms {
        fog: FogUniforms::new(0.0, 4.0, 1.0, [0.0, 0.7, 1.0]),
        ..uniforms()
    };
    fb.run_planes(&key, &u, &spans, &[p]);
    for x in 0..4u32 {
        let f = (4.0 - f64::from(x)) / 4.0;
        let want = [spec_unorm8(f), spec_unorm8((1.0 - f) * 0.7), spec_unorm8(1.0 - f), 153];
        assert_eq!(fb.pixel(x, 0), &want, "x = {x}");
    }
}

/// Float depth (`GL_DEPTH_COMPONENT32F`) from the shading stage: the plane's
/// f32 clamped to `[0, 1]` as llvmpipe's `lp_build_clamp` (SSE `maxps(z, 0)`
/// then `minps(.., 1)`): negative, -0 and NaN store +0, above 1 stores 1.0,
/// everything else (a denormal too) its own bits.
#[test]
fn float_depth_from_the_planes_is_the_clamped_f32() {
    let zs = [0.3f32, -0.0, f32::NAN, 1.5, -2.0, 1e-40, 1.0, 0.999_999_94];
    let mut fb = Fb::new(zs.len() as u32, 1, ColorFormat::Rgba8).with_depth(DepthFormat::D32F, 0x3f80_0000);
    let key = FragmentKey {
        depth: Some(DepthKey {
            func: CompareFunc::Always,
            write: true,
        }),
        shade: Some(ShadeKey {
            depth: true,
            ..ShadeKey::default()
        }),
        ..fb.key()
    };
    let mut planes = Vec::new();
    let mut spans = Vec::new();
    for (i, &z) in zs.iter().enumerate() {
        let mut p = Planes::default();
        p.constant(slot::INV_W, 1.0);
        p.constant(slot::Z, z);
        planes.push(p);
        let mut s = span(i as u32, 0, &[([0; 4], 0)]);
        s.planes = i as u32;
        spans.push(s);
    }
    fb.run_planes(&key, &uniforms(), &spans, &planes);
    let want = [0.3f32, 0.0, 0.0, 1.0, 0.0, 1e-40, 1.0, 0.999_999_94];
    for (x, w) in want.iter().enumerate() {
        assert_eq!(fb.depth(x as u32, 0), w.to_bits(), "z = {}", zs[x]);
    }
}

/// Float depth compares as floats: LESS keeps the nearer of 0.25 and 0.5
/// either way round, EQUAL passes only the same float.
#[test]
fn float_depth_test_orders_as_floats() {
    let (q, h) = (0.25f32.to_bits(), 0.5f32.to_bits());
    for (func, stored, incoming, pass) in [
        (CompareFunc::Less, h, q, true),
        (CompareFunc::Less, q, h, false),
        (CompareFunc::Gequal, q, h, true),
        (CompareFunc::Equal, q, q, true),
        (CompareFunc::Equal, q, q + 1, false),
    ] {
        let mut fb = Fb::new(1, 1, ColorFormat::Rgba8).with_depth(DepthFormat::D32F, stored);
        let key = FragmentKey {
            depth: Some(DepthKey { func, write: true }),
            ..fb.key()
        };
        fb.run(&key, &uniforms(), &[span(0, 0, &[(RED, incoming)])]).unwrap();
        assert_eq!(fb.depth(0, 0), if pass { incoming } else { stored }, "{func:?}");
    }
}
