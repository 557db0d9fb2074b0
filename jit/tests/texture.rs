//! The reference sampler and texture environment against llvmpipe's pixels.
//!
//! Each line of `tests/llvmpipe/cases.txt` is a 16x16 scene: one texture (LCG texels), a
//! full-viewport quad whose texture coordinates are affine in the window
//! position with power-of-two steps (so both sides know them exactly), and
//! an environment. `tests/llvmpipe/probe.c` rendered them with Mesa 22.3.6
//! llvmpipe (OSMesa) into `tests/llvmpipe/probe.txt`; here softgl's
//! reference computes every pixel from the same description and must match
//! byte for byte. `regenerate` (ignored) re-runs the probe.

#[path = "llvmpipe/cases.rs"]
mod cases;

use cases::{cases, compare, difference, filter, probe_line, recorded, texels, wrap, Case};
use softgl_jit::shade::unorm8;
use softgl_jit::texture::{
    effective_combine, environment, sample_quad, BaseFormat, CombineFn, CombineKey, CombineSrc, DepthMode, EnvMode,
    Filter, Image, MipFilter, Operand, SamplerKey, SamplerStatics, TexTarget, TexUnitKey, TexelFormat, TextureRef,
    Wrap, MAX_UNITS,
};

/// Scene side in pixels (the probe's `N`).
const N: usize = 16;

/// Everything softgl needs to compute a case: key, images, levels.
struct Scene {
    /// The enabled units: the same texture and coordinates, each its environment.
    units: [Option<TexUnitKey>; MAX_UNITS],
    images: Vec<(Vec<u8>, [u32; 3])>,
    base: u32,
    max_level: u32,
}

impl Scene {
    /// The scene's images as the sampler reads them.
    fn images(&self) -> Vec<Image<'_>> {
        self.images
            .iter()
            .map(|(t, [w, h, d])| Image {
                texels: t,
                units: None,
                width: *w,
                height: *h,
                depth: *d,
            })
            .collect()
    }
}

fn scene(c: &Case, seed: u32) -> Scene {
    let target = cases::target(c);
    let fmt = c.s("format", "rgba8");
    let (w, h, d) = (c.i("w", 8) as u32, c.i("h", 8) as u32, c.i("d", 1) as u32);
    let levels = c.i("levels", 1) as u32;
    let mut images = Vec::new();
    for l in 0..levels {
        let lw = (w >> l).max(1);
        let lh = if target == TexTarget::D1 { 1 } else { (h >> l).max(1) };
        let ld = if target == TexTarget::D3 { (d >> l).max(1) } else { 1 };
        let faces = if target == TexTarget::Cube { 6 } else { 1 };
        for face in 0..faces {
            let data = texels(&fmt, seed * 1000 + l * 10 + face, (lw * lh * ld) as usize);
            images.push((data, [lw, lh, ld]));
        }
    }
    let (min, mip) = filter(&c.s("min", "linear"));
    let (mag, _) = filter(&c.s("mag", "linear"));
    let format = match fmt.as_str() {
        "srgba8" => TexelFormat::Srgba8,
        "rgba16" => TexelFormat::Rgba16,
        "depth" => TexelFormat::Depth32F,
        _ => TexelFormat::Rgba8,
    };
    let base = match fmt.as_str() {
        "rgb8" => BaseFormat::Rgb,
        "l8" => BaseFormat::Luminance,
        "a8" => BaseFormat::Alpha,
        "i8" => BaseFormat::Intensity,
        "la8" => BaseFormat::LuminanceAlpha,
        "depth" => BaseFormat::Depth,
        _ => BaseFormat::Rgba,
    };
    let depth_mode = cases::depth_mode(c);
    let dims = match target {
        TexTarget::D1 => 1,
        TexTarget::D2 | TexTarget::Cube | TexTarget::Rect => 2,
        TexTarget::D3 => 3,
    };
    let wraps = [
        wrap(&c.s("wrap_s", "repeat")),
        wrap(&c.s("wrap_t", "repeat")),
        wrap(&c.s("wrap_r", "repeat")),
    ];
    let sampler = SamplerKey {
        target,
        format,
        min,
        mip,
        mag,
        wrap: std::array::from_fn(|a| if a < dims { wraps[a] } else { Wrap::Repeat }),
        compare: c.kv.get("compare").map(|f| compare(f)),
        depth_mode,
        statics: SamplerStatics::default(),
    };
    let env_base = if base == BaseFormat::Depth {
        depth_mode.base()
    } else {
        base
    };
    let mut units = [None; MAX_UNITS];
    for u in cases::units(c) {
        let env = effective_combine(cases::env_mode(c, u), env_base, cases::combine(c, u));
        units[u] = Some(TexUnitKey { sampler, base, env });
    }
    let last = levels.saturating_sub(1);
    Scene {
        units,
        images,
        base: c.i("base", 0) as u32,
        max_level: (c.i("max_level", 1000) as u32).min(last),
    }
}

/// Texture coordinate `c` (s, t, r, q) at window position (x, y): exact by construction.
fn coord(c: &Case, x: f64, y: f64) -> [f32; 4] {
    let names = [
        ("s0", "sx", "sy"),
        ("t0", "tx", "ty"),
        ("r0", "rx", "ry"),
        ("q0", "qx", "qy"),
    ];
    names.map(|(a, dx, dy)| {
        let a0 = f64::from(c.f(a, if a == "q0" { 1.0 } else { 0.0 }));
        let v = a0 + x * f64::from(c.f(dx, 0.0)) + y * f64::from(c.f(dy, 0.0));
        assert_eq!(f64::from(v as f32), v, "{}: coordinates must be exact", c.name);
        v as f32
    })
}

/// softgl's 16x16 image of a case (RGBA bytes, bottom row first).
fn render(c: &Case, seed: u32) -> Vec<u8> {
    let sc = scene(c, seed);
    let images = sc.images();
    let tex = TextureRef {
        images: &images,
        base_level: sc.base,
        max_level: sc.max_level,
        min_lod: c.f("min_lod", -1000.0),
        max_lod: c.f("max_lod", 1000.0),
        lod_bias: softgl_jit::texture::quantized_lod_bias(c.f("bias", 0.0)),
        border: [c.f("br", 0.0), c.f("bg", 0.0), c.f("bb", 0.0), c.f("ba", 0.0)],
        float_depth: false,
    };
    let primary = [c.f("cr", 1.0), c.f("cg", 1.0), c.f("cb", 1.0), c.f("ca", 1.0)];
    let env_color: [[f32; 4]; MAX_UNITS] = std::array::from_fn(|u| cases::env_color(c, u));
    let mut out = vec![0u8; N * N * 4];
    for y in 0..N {
        // llvmpipe's quads pair rows of the top-down frame: row = N−1−y.
        let row = N - 1 - y;
        let qrow = row & !1;
        for x in 0..N {
            let qx = x & !1;
            let at = |px: usize, r: usize| coord(c, px as f64 + 0.5, (N - 1 - r) as f64 + 0.5);
            let quad = [at(qx, qrow), at(qx + 1, qrow), at(qx, qrow + 1), at(qx + 1, qrow + 1)];
            let lane = (x - qx) + 2 * (row - qrow);
            let mut samples = [[0.0; 4]; MAX_UNITS];
            for (u, unit) in sc.units.iter().enumerate() {
                if let Some(unit) = unit {
                    samples[u] = sample_quad(unit, &tex, &quad, lane);
                }
            }
            let colour = environment(&sc.units, &samples, primary, &env_color);
            out[(y * N + x) * 4..][..4].copy_from_slice(&colour.map(unorm8));
        }
    }
    out
}

#[test]
fn every_case_matches_llvmpipe_byte_for_byte() {
    let llvmpipe = recorded();
    let mut failures = Vec::new();
    let mut count = 0;
    for (i, line) in cases() {
        let c = Case::parse(line);
        if c.kv.get("geom").is_some_and(|g| g == "persp") {
            continue;
        }
        count += 1;
        let want = llvmpipe
            .get(&c.name)
            .unwrap_or_else(|| panic!("{} not recorded", c.name));
        let got = render(&c, i as u32);
        if let Some(r) = difference(&c.name, &got, want, N).report {
            failures.push(r);
        }
    }
    assert!(
        failures.is_empty(),
        "{} of {count} cases differ:\n{}",
        failures.len(),
        failures.join("\n")
    );
    assert!(count >= 80, "{count} cases");
}

/// Re-renders every case with llvmpipe: needs gcc and Mesa's libOSMesa.
#[test]
#[ignore]
fn regenerate() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/llvmpipe");
    let exe = std::env::temp_dir().join("softgl-texture-probe");
    let status = std::process::Command::new("gcc")
        .args(["-O1", "-o"])
        .arg(&exe)
        .arg(dir.join("probe.c"))
        .arg("-lOSMesa")
        .status()
        .expect("gcc runs");
    assert!(status.success());
    let input: String = cases().map(|(i, l)| probe_line(i, l) + "\n").collect();
    let mut child = std::process::Command::new(&exe)
        .env("LP_NUM_THREADS", "1")
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .spawn()
        .expect("the probe runs");
    use std::io::Write;
    child
        .stdin
        .take()
        .expect("stdin")
        .write_all(input.as_bytes())
        .expect("write");
    let out = child.wait_with_output().expect("the probe finishes");
    assert!(out.status.success());
    std::fs::write(dir.join("probe.txt"), out.stdout).expect("write probe.txt");
}

// ------------------------------------------------------------------------
// Values computed by hand (or in f64), not by the code under test.

/// A 1D RGBA8 texture whose texels are `values` (all four channels).
fn gray_1d(values: &[u8]) -> Vec<u8> {
    values.iter().flat_map(|&v| [v; 4]).collect()
}

fn unit_1d(min: Filter, mag: Filter, wrap: Wrap, format: TexelFormat) -> TexUnitKey {
    TexUnitKey {
        sampler: SamplerKey {
            target: TexTarget::D1,
            format,
            min,
            mip: MipFilter::None,
            mag,
            wrap: [wrap, Wrap::Repeat, Wrap::Repeat],
            compare: None,
            depth_mode: DepthMode::Luminance,
            statics: SamplerStatics::default(),
        },
        base: BaseFormat::Rgba,
        env: CombineKey::DEFAULT,
    }
}

/// The red channel sampled at `s` (constant over the quad: magnified).
fn red_at(unit: &TexUnitKey, texels: &[u8], width: u32, s: f32, border: [f32; 4]) -> f32 {
    let images = [Image {
        texels,
        units: None,
        width,
        height: 1,
        depth: 1,
    }];
    let tex = TextureRef {
        images: &images,
        base_level: 0,
        max_level: 0,
        min_lod: -1000.0,
        max_lod: 1000.0,
        lod_bias: 0.0,
        border,
        float_depth: false,
    };
    let c = [s, 0.0, 0.0, 1.0];
    sample_quad(unit, &tex, &[c; 4], 0)[0]
}

const C255: f32 = (1.0f64 / 255.0) as f32;

#[test]
fn aos_linear_weight_is_the_8_bit_fraction_and_rounds_half_up() {
    // s = 0.3 on 8 texels: 0.3·2048 = 614.4 → 614 − 128 = 486 = 1·256 + 230: texels 1 and 2,
    // weight 230/256 (the exact 0.9 would be 230.4). Texel 1 = 0, texel 2 = 255:
    // (230·255 + 128) >> 8 = 58778 >> 8 = 229.
    let texels = gray_1d(&[7, 0, 255, 9, 9, 9, 9, 9]);
    let u = unit_1d(Filter::Linear, Filter::Linear, Wrap::Repeat, TexelFormat::Rgba8);
    assert_eq!(red_at(&u, &texels, 8, 0.3, [0.0; 4]), 229.0 * C255);
    // The SoA path (16-bit texels) keeps the exact fraction 0.9 (in f32 from 0.3·8 − 0.5).
    let t16: Vec<u8> = [7u16, 0, 65535, 9, 9, 9, 9, 9]
        .iter()
        .flat_map(|v| [v.to_ne_bytes(); 4].concat())
        .collect();
    let u16 = unit_1d(Filter::Linear, Filter::Linear, Wrap::Repeat, TexelFormat::Rgba16);
    let w = 0.3f32 * 8.0 - 0.5 - 1.0;
    assert_eq!(red_at(&u16, &t16, 8, 0.3, [0.0; 4]), w.mul_add(1.0, 0.0));
}

#[test]
fn repeat_wraps_the_first_and_last_texel_together() {
    // s = 0 with LINEAR REPEAT: halfway between texel 3 and texel 0 (weight 128):
    // 40 + ((128·(10 − 40) + 128) >> 8) = 40 + (−3712 >> 8) = 40 − 15 = 25.
    let texels = gray_1d(&[10, 20, 30, 40]);
    let u = unit_1d(Filter::Linear, Filter::Linear, Wrap::Repeat, TexelFormat::Rgba8);
    assert_eq!(red_at(&u, &texels, 4, 0.0, [0.0; 4]), 25.0 * C255);
    let e = unit_1d(Filter::Linear, Filter::Linear, Wrap::ClampToEdge, TexelFormat::Rgba8);
    assert_eq!(red_at(&e, &texels, 4, 0.0, [0.0; 4]), 10.0 * C255);
    assert_eq!(red_at(&e, &texels, 4, 1.0, [0.0; 4]), 40.0 * C255);
    assert_eq!(red_at(&e, &texels, 4, -5.0, [0.0; 4]), 10.0 * C255);
}

#[test]
fn nearest_wraps_at_and_beyond_the_edges() {
    let texels = gray_1d(&[10, 20, 30, 40]);
    let border = [0.5, 0.5, 0.5, 0.5];
    // (wrap, s, texel value or None for the border): indices worked out from s·4.
    let cases: [(Wrap, f32, Option<u8>); 16] = [
        (Wrap::Repeat, -0.1, Some(40)),  // floor(−0.4) = −1 → 3
        (Wrap::Repeat, 1.1, Some(10)),   // floor(4.4) = 4 → 0
        (Wrap::Repeat, 0.999, Some(40)), // 3.996 → 3
        (Wrap::Repeat, 1.0, Some(10)),   // 4 → 0
        (Wrap::ClampToEdge, -0.1, Some(10)),
        (Wrap::ClampToEdge, 1.0, Some(40)),
        (Wrap::ClampToEdge, 1e6, Some(40)),
        (Wrap::Clamp, -7.0, Some(10)),
        (Wrap::Clamp, 1.5, Some(40)),
        (Wrap::ClampToBorder, -0.1, None), // −1 is outside
        (Wrap::ClampToBorder, 1.0, None),  // 4 is outside
        (Wrap::ClampToBorder, 0.999, Some(40)),
        (Wrap::MirroredRepeat, -0.1, Some(10)), // mirrors to 0.1 → 0.4 → 0
        (Wrap::MirroredRepeat, 1.1, Some(40)),  // 0.9 → 3.6 → 3
        (Wrap::MirroredRepeat, 1.3, Some(30)),  // 0.7 → 2.8 → 2
        (Wrap::MirroredRepeat, -1.3, Some(30)), // 0.7
    ];
    for (wrap, s, want) in cases {
        let u = unit_1d(Filter::Nearest, Filter::Nearest, wrap, TexelFormat::Rgba8);
        let want = want.map_or(0.5, |v| f32::from(v) * C255);
        assert_eq!(red_at(&u, &texels, 4, s, border), want, "{wrap:?} at {s}");
    }
}

#[test]
fn linear_clamp_blends_the_border_in() {
    // GL_CLAMP, s = 0: s·4 clamped to [0, 4] minus 0.5 = −0.5: texels −1 (border) and 0, weight 0.5.
    let texels = gray_1d(&[10, 20, 30, 40]);
    let u = unit_1d(Filter::Linear, Filter::Linear, Wrap::Clamp, TexelFormat::Rgba8);
    let t0 = 10.0 * C255;
    assert_eq!(red_at(&u, &texels, 4, 0.0, [1.0; 4]), 0.5f32.mul_add(t0 - 1.0, 1.0));
    // Far outside the coordinate clamps to the edge: texels 3 and 4 (border), weight 0.5.
    let t3 = 40.0 * C255;
    assert_eq!(red_at(&u, &texels, 4, 9.0, [1.0; 4]), 0.5f32.mul_add(1.0 - t3, t3));
    // The border colour is clamped to [0, 1].
    let b = unit_1d(
        Filter::Nearest,
        Filter::Nearest,
        Wrap::ClampToBorder,
        TexelFormat::Rgba8,
    );
    assert_eq!(red_at(&b, &texels, 4, -1.0, [7.0; 4]), 1.0);
    assert_eq!(red_at(&b, &texels, 4, -1.0, [-7.0; 4]), 0.0);
}

#[test]
fn lambda_for_known_derivatives() {
    use softgl_jit::texture::lod::{self, fast_log2, LodState};
    // 64×64 base, ds/dx = 1/16, dt/dy = 1/32: ρ² = max((64/16)², (64/32)²) = 16.
    let (rho, sq) = lod::rho_quad(2, [64.0; 3], [0.0; 3], [1.0 / 16.0, 0.0, 0.0], [0.0, 1.0 / 32.0, 0.0]);
    assert_eq!((rho, sq), (16.0, true));
    // Diagonal derivatives add their squares: (64·1/16)² + (64·1/16)² = 32.
    let (rho, _) = lod::rho_quad(2, [64.0; 3], [0.0; 3], [1.0 / 16.0, 1.0 / 16.0, 0.0], [0.0; 3]);
    assert_eq!(rho, 32.0);
    // 1D: max(|ds/dx|, |ds/dy|)·width, not squared.
    assert_eq!(
        lod::rho_quad(1, [64.0; 3], [0.0; 3], [-0.25, 0.0, 0.0], [0.125, 0.0, 0.0]),
        (16.0, false)
    );
    // fast_log2 is exact at powers of two and linear between: 9 = 2³·1.125 → 3.125.
    assert_eq!(fast_log2(16.0), 4.0);
    assert_eq!(fast_log2(9.0), 3.125);
    assert_eq!(fast_log2(0.75), -0.5); // 2⁻¹·1.5 → −1 + 0.5
    let plain = LodState {
        min_lod: 0.0,
        max_lod: 1000.0,
        bias: 0.0,
        min_max_equal: false,
        apply_min: false,
        apply_max: false,
    };
    // LINEAR mipmaps: λ = 3.125/2 = 1.5625 → levels 1 and 2, weight 0.5625.
    let l = lod::levels(
        MipFilter::Linear,
        lod::select(MipFilter::Linear, &plain, 9.0, true),
        0,
        6,
    );
    assert_eq!((l.minified, l.level0, l.level1, l.weight), (true, 1, 2, 0.5625));
    // NEAREST: level from the exponent: (exponent(9) + 1) >> 1 = (3 + 1) >> 1 = 2.
    let l = lod::levels(
        MipFilter::Nearest,
        lod::select(MipFilter::Nearest, &plain, 9.0, true),
        0,
        6,
    );
    assert_eq!((l.minified, l.level0), (true, 2));
    // ρ² = 2: λ = fast_log2(2)/2 = 0.5; with a bias NEAREST rounds λ half to even.
    let biased = LodState { bias: 1.0, ..plain };
    assert_eq!(lod::select(MipFilter::Nearest, &biased, 2.0, true), (true, 2, 0.0)); // 1.5 → 2
    assert_eq!(
        lod::select(MipFilter::Nearest, &LodState { bias: 2.0, ..plain }, 2.0, true),
        (true, 2, 0.0)
    ); // 2.5 → 2
       // Magnified (ρ ≤ 1) stays at the base level; past the last level the weight is 0.
    let l = lod::levels(
        MipFilter::Linear,
        lod::select(MipFilter::Linear, &plain, 0.25, true),
        2,
        6,
    );
    assert_eq!((l.minified, l.level0, l.level1, l.weight), (false, 2, 2, 0.0));
    let l = lod::levels(
        MipFilter::Linear,
        lod::select(MipFilter::Linear, &plain, 1e30, true),
        0,
        6,
    );
    assert_eq!((l.level0, l.level1, l.weight), (6, 6, 0.0));
    // MIN_LOD 2.5 lifts λ = 1.5625; MAX_LOD 1 caps it.
    let clamped = LodState {
        min_lod: 2.5,
        apply_min: true,
        ..plain
    };
    assert_eq!(lod::select(MipFilter::Linear, &clamped, 9.0, true), (true, 2, 0.5));
    let capped = LodState {
        max_lod: 1.0,
        apply_max: true,
        ..plain
    };
    assert_eq!(lod::select(MipFilter::Linear, &capped, 9.0, true), (true, 1, 0.0));
}

#[test]
fn lod_bias_is_quantized_as_mesa_does() {
    use softgl_jit::texture::quantized_lod_bias;
    assert_eq!(quantized_lod_bias(100.0), 16.0);
    assert_eq!(quantized_lod_bias(-100.0), -16.0);
    assert_eq!(quantized_lod_bias(0.3), 77.0 / 256.0); // 76.8 → 77
    assert_eq!(quantized_lod_bias(-1.0 / 512.0), -1.0 / 256.0); // −0.5 rounds away from zero
}

/// The environment of one unit over `primary` with texture colour `t`.
fn env1(k: CombineKey, t: [f32; 4], primary: [f32; 4], constant: [f32; 4]) -> [f32; 4] {
    let mut units = [None; MAX_UNITS];
    units[0] = Some(TexUnitKey {
        env: k,
        ..unit_1d(Filter::Nearest, Filter::Nearest, Wrap::Repeat, TexelFormat::Rgba8)
    });
    let mut samples = [[0.0; 4]; MAX_UNITS];
    samples[0] = t;
    environment(&units, &samples, primary, &[constant; MAX_UNITS])
}

#[test]
fn combine_functions_by_hand() {
    let t = [0.5, 0.5, 0.25, 1.0];
    let p = [0.5, 0.25, 1.0, 0.75];
    let k = [0.25, 0.75, 0.5, 0.125];
    let with = |rgb: CombineFn, alpha: CombineFn| CombineKey {
        rgb,
        alpha,
        src_rgb: [CombineSrc::Texture, CombineSrc::Previous, CombineSrc::Constant],
        ..CombineKey::DEFAULT
    };
    use CombineFn as F;
    assert_eq!(env1(with(F::Replace, F::Replace), t, p, k), t);
    assert_eq!(env1(with(F::Modulate, F::Modulate), t, p, k), [0.25, 0.125, 0.25, 0.75]);
    assert_eq!(env1(with(F::Add, F::Add), t, p, k), [1.0, 0.75, 1.0, 1.0]); // 1.25, 1.75 saturate
    assert_eq!(env1(with(F::AddSigned, F::AddSigned), t, p, k), [0.5, 0.25, 0.75, 1.0]);
    assert_eq!(env1(with(F::Subtract, F::Subtract), t, p, k), [0.0, 0.25, 0.0, 0.25]);
    // INTERPOLATE t·c + p·(1 − c), c = the constant's colour (source 2, operand SrcColor).
    let interp = CombineKey {
        op_rgb: [Operand::SrcColor; 3],
        op_alpha: [Operand::SrcAlpha; 3],
        ..with(F::Interpolate, F::Interpolate)
    };
    assert_eq!(
        env1(interp, t, p, k),
        [
            0.5 * 0.25 + 0.5 * 0.75,
            0.5 * 0.75 + 0.25 * 0.25,
            0.25 * 0.5 + 1.0 * 0.5,
            1.0 * 0.125 + 0.75 * 0.875
        ]
    );
    // DOT3: (2t − 1)·(2p − 1) = 0·0 + 0·(−0.5) + (−0.5)·1 = −0.5 → 0; with p' it is positive.
    let p2 = [1.0, 0.75, 0.0, 0.5];
    // 0·1 + 0·0.5 + (−0.5)·(−1) = 0.5 in every RGB channel; alpha MODULATE 1·0.5.
    assert_eq!(env1(with(F::Dot3Rgb, F::Modulate), t, p2, k), [0.5, 0.5, 0.5, 0.5]);
    assert_eq!(env1(with(F::Dot3Rgba, F::Modulate), t, p2, k), [0.5; 4]);
    assert_eq!(env1(with(F::Dot3Rgb, F::Modulate), t, p, k), [0.0, 0.0, 0.0, 0.75]);
    // Scales multiply then saturate all channels; DOT3 takes them too.
    let scaled = CombineKey {
        scale_rgb: 2,
        scale_alpha: 4,
        ..with(F::Modulate, F::Modulate)
    };
    assert_eq!(env1(scaled, t, p, k), [0.5, 0.25, 0.5, 1.0]);
    let dot_scaled = CombineKey {
        scale_rgb: 4,
        ..with(F::Dot3Rgb, F::Modulate)
    };
    assert_eq!(
        env1(dot_scaled, [0.75, 0.5, 0.5, 1.0], [0.75, 0.5, 0.5, 1.0], k),
        [1.0, 1.0, 1.0, 1.0]
    ); // 0.25·4
       // Operands: 1 − colour, alpha, 1 − alpha.
    let ops = CombineKey {
        op_rgb: [Operand::OneMinusSrcColor, Operand::SrcAlpha, Operand::SrcAlpha],
        op_alpha: [Operand::OneMinusSrcAlpha, Operand::SrcAlpha, Operand::SrcAlpha],
        ..with(F::Modulate, F::Modulate)
    };
    assert_eq!(env1(ops, t, p, k), [0.5 * 0.75, 0.5 * 0.75, 0.75 * 0.75, 0.0]);
}

/// GL 1.5 tables 3.22 and 3.23 in f64: the colour a legacy mode makes of
/// fragment colour `f`, texture `t` (in the base format's channels: L in
/// `t[0]`, I in `t[0]`) and constant `c`.
fn gl_table(mode: EnvMode, base: BaseFormat, f: [f64; 4], t: [f64; 4], c: [f64; 4]) -> [f64; 4] {
    use BaseFormat as B;
    let (rgb, a): (Option<[f64; 3]>, Option<f64>) = match base {
        B::Alpha => (None, Some(t[3])),
        B::Luminance => (Some([t[0]; 3]), None),
        B::LuminanceAlpha => (Some([t[0]; 3]), Some(t[3])),
        B::Intensity => (Some([t[0]; 3]), Some(t[0])),
        B::Rgb => (Some([t[0], t[1], t[2]]), None),
        B::Rgba | B::Depth => (Some([t[0], t[1], t[2]]), Some(t[3])),
    };
    let ff = [f[0], f[1], f[2]];
    let out_rgb = |g: &dyn Fn(usize, f64) -> f64| rgb.map_or(ff, |ct| std::array::from_fn(|i| g(i, ct[i])));
    let (crgb, ca) = match mode {
        EnvMode::Replace => (rgb.unwrap_or(ff), a.unwrap_or(f[3])),
        EnvMode::Modulate => (out_rgb(&|i, ct| f[i] * ct), a.map_or(f[3], |at| f[3] * at)),
        EnvMode::Decal => match base {
            B::Rgb => (rgb.unwrap_or(ff), f[3]),
            B::Rgba => (out_rgb(&|i, ct| f[i] * (1.0 - t[3]) + ct * t[3]), f[3]),
            _ => (ff, f[3]), // undefined in GL; Mesa passes the fragment through
        },
        EnvMode::Blend => (
            out_rgb(&|i, ct| f[i] * (1.0 - ct) + c[i] * ct),
            match base {
                B::Intensity => f[3] * (1.0 - t[0]) + c[3] * t[0],
                _ => a.map_or(f[3], |at| f[3] * at),
            },
        ),
        EnvMode::Add => (
            out_rgb(&|i, ct| (f[i] + ct).min(1.0)),
            match base {
                B::Intensity => (f[3] + t[0]).min(1.0),
                _ => a.map_or(f[3], |at| f[3] * at),
            },
        ),
        EnvMode::Combine => unreachable!(),
    };
    [crgb[0], crgb[1], crgb[2], ca]
}

#[test]
fn legacy_modes_follow_the_gl_tables() {
    let f = [0.5f32, 0.25, 1.0, 0.75];
    let c = [0.125f32, 0.875, 0.5, 0.25];
    // Texture colours as the RGBA expansion stores them, and their GL channels.
    let cases = [
        (BaseFormat::Rgba, [0.5f32, 0.75, 0.25, 0.375]),
        (BaseFormat::Rgb, [0.5, 0.75, 0.25, 1.0]),
        (BaseFormat::Luminance, [0.625, 0.625, 0.625, 1.0]),
        (BaseFormat::LuminanceAlpha, [0.625, 0.625, 0.625, 0.375]),
        (BaseFormat::Intensity, [0.625; 4]),
        (BaseFormat::Alpha, [0.0, 0.0, 0.0, 0.375]),
    ];
    let modes = [
        EnvMode::Replace,
        EnvMode::Modulate,
        EnvMode::Decal,
        EnvMode::Blend,
        EnvMode::Add,
    ];
    for (base, t) in cases {
        for mode in modes {
            let k = effective_combine(mode, base, CombineKey::DEFAULT);
            let got = env1(k, t, f, c);
            let want = gl_table(mode, base, f.map(f64::from), t.map(f64::from), c.map(f64::from));
            for ch in 0..4 {
                // f32 products and sums of dyadic values: within 1e-6 of the f64 formula.
                assert!(
                    (f64::from(got[ch]) - want[ch]).abs() < 1e-6,
                    "{mode:?} {base:?} channel {ch}: {got:?} vs {want:?}"
                );
            }
        }
    }
    // Combine returns the given combine unchanged.
    let mine = CombineKey {
        rgb: CombineFn::Dot3Rgba,
        ..CombineKey::DEFAULT
    };
    assert_eq!(effective_combine(EnvMode::Combine, BaseFormat::Alpha, mine), mine);
}

#[test]
fn units_chain_through_previous_and_the_crossbar_reads_zero_for_a_disabled_unit() {
    let modulate = effective_combine(EnvMode::Modulate, BaseFormat::Rgba, CombineKey::DEFAULT);
    let unit = |env| TexUnitKey {
        env,
        ..unit_1d(Filter::Nearest, Filter::Nearest, Wrap::Repeat, TexelFormat::Rgba8)
    };
    let mut units = [None; MAX_UNITS];
    units[0] = Some(unit(modulate));
    units[2] = Some(unit(modulate));
    let mut samples = [[0.0; 4]; MAX_UNITS];
    samples[0] = [0.5; 4];
    samples[2] = [0.5, 0.25, 1.0, 1.0];
    let p = [1.0, 1.0, 0.5, 1.0];
    let env = [[0.0; 4]; MAX_UNITS];
    // Unit 1 is off: unit 2's previous is unit 0's result.
    assert_eq!(environment(&units, &samples, p, &env), [0.25, 0.125, 0.25, 0.5]);
    // GL_TEXTURE1 (disabled) as a source reads 0; GL_TEXTURE0 reads unit 0's sample.
    let crossbar = |n: u8| CombineKey {
        rgb: CombineFn::Add,
        alpha: CombineFn::Add,
        src_rgb: [
            CombineSrc::TextureUnit(n),
            CombineSrc::PrimaryColor,
            CombineSrc::Constant,
        ],
        src_alpha: [
            CombineSrc::TextureUnit(n),
            CombineSrc::PrimaryColor,
            CombineSrc::Constant,
        ],
        ..CombineKey::DEFAULT
    };
    units[2] = Some(unit(crossbar(1)));
    assert_eq!(environment(&units, &samples, [0.25; 4], &env), [0.25; 4]);
    units[2] = Some(unit(crossbar(0)));
    assert_eq!(environment(&units, &samples, [0.25; 4], &env), [0.75; 4]);
}

#[test]
fn sample_with_three_quad_pixels_equals_sample_quad_off_cube_maps() {
    use softgl_jit::texture::sample;
    // A minified 2D mipmapped texture: λ from the quad, so the quad matters.
    let c = Case::parse("q w=64 h=64 levels=7 min=linear_mipmap_linear");
    let sc = scene(&c, 3);
    let images = sc.images();
    let tex = TextureRef {
        images: &images,
        base_level: 0,
        max_level: sc.max_level,
        min_lod: -1000.0,
        max_lod: 1000.0,
        lod_bias: 0.0,
        border: [0.0; 4],
        float_depth: false,
    };
    let unit = sc.units[0].expect("unit 0 is on");
    let quad = [
        [0.1, 0.2, 0.0, 1.0],
        [0.17, 0.21, 0.0, 1.0],
        [0.12, 0.29, 0.0, 1.0],
        [0.19, 0.3, 0.0, 1.0],
    ];
    for lane in 0..4 {
        let three = sample(&unit, &tex, quad[lane], [quad[0], quad[1], quad[2]]);
        assert_eq!(three, sample_quad(&unit, &tex, &quad, lane), "lane {lane}");
    }
    // λ ≈ log2(0.09·64) ≈ 2.5: between levels 2 and 3, so a different quad changes the result.
    let other = [
        [0.1, 0.2, 0.0, 1.0],
        [0.4, 0.2, 0.0, 1.0],
        [0.1, 0.5, 0.0, 1.0],
        [0.4, 0.5, 0.0, 1.0],
    ];
    assert_ne!(sample_quad(&unit, &tex, &quad, 0), sample_quad(&unit, &tex, &other, 0));
}
