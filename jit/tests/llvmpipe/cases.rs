//! The texture scenes shared by `jit/tests/texture.rs` (softgl's reference
//! sampler) and `tests/texture_llvmpipe.rs` (softgl end to end): their
//! descriptions (`cases.txt`), texels (the probe's LCG) and llvmpipe's images
//! (`probe.txt`, written by `probe.c`).
#![allow(dead_code)]

use softgl_jit::key::CompareFunc;
use softgl_jit::texture::{CombineFn, CombineSrc, Filter, MipFilter, Operand, Wrap};
use std::collections::HashMap;

/// The scenes, one a line: a name, then `key=value` words (defaults in `probe.c`).
pub const CASES: &str = include_str!("cases.txt");

/// The cases softgl's reference computes here (not the perspective ones).
pub fn cases() -> impl Iterator<Item = (usize, &'static str)> {
    CASES
        .lines()
        .filter(|l| !l.trim().is_empty() && !l.starts_with('#'))
        .enumerate()
}

/// One scene's description: its name and `key=value` words.
pub struct Case {
    pub name: String,
    pub kv: HashMap<String, String>,
}

impl Case {
    pub fn parse(line: &str) -> Case {
        let mut words = line.split_whitespace();
        let name = words.next().expect("a case has a name").to_string();
        let kv = words
            .map(|w| {
                let (k, v) = w.split_once('=').expect("key=value");
                (k.to_string(), v.to_string())
            })
            .collect();
        Case { name, kv }
    }

    pub fn s(&self, k: &str, default: &str) -> String {
        self.kv.get(k).cloned().unwrap_or_else(|| default.to_string())
    }

    pub fn f(&self, k: &str, default: f32) -> f32 {
        self.kv.get(k).map_or(default, |v| v.parse().expect("a number"))
    }

    pub fn i(&self, k: &str, default: i32) -> i32 {
        self.kv.get(k).map_or(default, |v| v.parse().expect("an integer"))
    }
}

pub fn filter(s: &str) -> (Filter, MipFilter) {
    match s {
        "nearest" => (Filter::Nearest, MipFilter::None),
        "linear" => (Filter::Linear, MipFilter::None),
        "nearest_mipmap_nearest" => (Filter::Nearest, MipFilter::Nearest),
        "linear_mipmap_nearest" => (Filter::Linear, MipFilter::Nearest),
        "nearest_mipmap_linear" => (Filter::Nearest, MipFilter::Linear),
        "linear_mipmap_linear" => (Filter::Linear, MipFilter::Linear),
        _ => panic!("filter {s}"),
    }
}

pub fn wrap(s: &str) -> Wrap {
    match s {
        "repeat" => Wrap::Repeat,
        "clamp" => Wrap::Clamp,
        "clamp_to_edge" => Wrap::ClampToEdge,
        "clamp_to_border" => Wrap::ClampToBorder,
        "mirrored_repeat" => Wrap::MirroredRepeat,
        _ => panic!("wrap {s}"),
    }
}

pub fn combine_fn(s: &str) -> CombineFn {
    match s {
        "replace" => CombineFn::Replace,
        "modulate" => CombineFn::Modulate,
        "add" => CombineFn::Add,
        "add_signed" => CombineFn::AddSigned,
        "interpolate" => CombineFn::Interpolate,
        "subtract" => CombineFn::Subtract,
        "dot3_rgb" => CombineFn::Dot3Rgb,
        "dot3_rgba" => CombineFn::Dot3Rgba,
        _ => panic!("combine {s}"),
    }
}

pub fn source(s: &str) -> CombineSrc {
    match s {
        "texture" => CombineSrc::Texture,
        "constant" => CombineSrc::Constant,
        "primary_color" => CombineSrc::PrimaryColor,
        "previous" => CombineSrc::Previous,
        _ => match s.strip_prefix("texture").and_then(|n| n.parse().ok()) {
            Some(n) => CombineSrc::TextureUnit(n),
            None => panic!("source {s}"),
        },
    }
}

pub fn operand(s: &str) -> Operand {
    match s {
        "src_color" => Operand::SrcColor,
        "one_minus_src_color" => Operand::OneMinusSrcColor,
        "src_alpha" => Operand::SrcAlpha,
        "one_minus_src_alpha" => Operand::OneMinusSrcAlpha,
        _ => panic!("operand {s}"),
    }
}

pub fn compare(s: &str) -> CompareFunc {
    match s {
        "never" => CompareFunc::Never,
        "less" => CompareFunc::Less,
        "equal" => CompareFunc::Equal,
        "lequal" => CompareFunc::Lequal,
        "greater" => CompareFunc::Greater,
        "notequal" => CompareFunc::Notequal,
        "gequal" => CompareFunc::Gequal,
        "always" => CompareFunc::Always,
        _ => panic!("compare {s}"),
    }
}

/// The probe's texel generator (`rb` in probe.c).
pub struct Lcg(u32);

impl Lcg {
    pub fn byte(&mut self) -> u8 {
        self.0 = self.0.wrapping_mul(1_103_515_245).wrapping_add(12345);
        (self.0 >> 16) as u8
    }
}

/// Bytes a texel of `format` takes in the probe's upload.
pub fn client_bytes(format: &str) -> usize {
    match format {
        "rgba8" | "srgba8" | "depth" => 4,
        "rgb8" => 3,
        "la8" => 2,
        "l8" | "a8" | "i8" => 1,
        "rgba16" => 8,
        _ => panic!("format {format}"),
    }
}

/// One image's client data as the probe uploads it (depth: floats 0 or 1).
pub fn raw_texels(format: &str, seed: u32, n: usize) -> Vec<u8> {
    let mut g = Lcg(seed);
    let mut raw: Vec<u8> = (0..n * client_bytes(format)).map(|_| g.byte()).collect();
    if format == "depth" {
        for t in raw.chunks_mut(4) {
            let d = if t[0] & 1 == 1 { 1.0f32 } else { 0.0 };
            t.copy_from_slice(&d.to_ne_bytes());
        }
    }
    raw
}

/// One image's texels in softgl's storage, as the probe uploads them.
pub fn texels(format: &str, seed: u32, n: usize) -> Vec<u8> {
    let raw = raw_texels(format, seed, n);
    let mut out = Vec::with_capacity(n * 8);
    for t in raw.chunks(client_bytes(format)) {
        let px: Vec<u8> = match format {
            "rgba8" | "srgba8" | "rgba16" | "depth" => t.to_vec(),
            "rgb8" => vec![t[0], t[1], t[2], 255],
            "l8" => vec![t[0], t[0], t[0], 255],
            "a8" => vec![0, 0, 0, t[0]],
            "i8" => vec![t[0]; 4],
            "la8" => vec![t[0], t[0], t[0], t[1]],
            _ => unreachable!(),
        };
        out.extend(px);
    }
    out
}

pub fn recorded() -> HashMap<String, Vec<u8>> {
    let text = include_str!("probe.txt");
    text.lines()
        .filter_map(|l| l.split_once(' '))
        .map(|(name, hex)| {
            let bytes = (0..hex.len() / 2)
                .map(|i| u8::from_str_radix(&hex[2 * i..2 * i + 2], 16).expect("hex"))
                .collect();
            (name.to_string(), bytes)
        })
        .collect()
}

/// The line the probe reads for case `i`.
pub fn probe_line(i: usize, line: &str) -> String {
    format!("{line} seed={i}")
}

/// How softgl's image `got` of scene `name` (`size`² RGBA pixels) differs
/// from llvmpipe's `want`: the differing pixels, whether each is within 1
/// in every channel, and a line describing the first.
pub struct Difference {
    pub pixels: usize,
    pub within_one: bool,
    pub report: Option<String>,
}

pub fn difference(name: &str, got: &[u8], want: &[u8], size: usize) -> Difference {
    let diff: Vec<usize> = (0..size * size)
        .filter(|&p| got[4 * p..4 * p + 4] != want[4 * p..4 * p + 4])
        .collect();
    let within_one = diff
        .iter()
        .all(|&p| (0..4).all(|k| got[4 * p + k].abs_diff(want[4 * p + k]) <= 1));
    let report = diff.first().map(|&p| {
        format!(
            "{name}: {} of {} pixels differ, first at ({}, {}): softgl {:?} llvmpipe {:?}",
            diff.len(),
            size * size,
            p % size,
            p / size,
            &got[4 * p..4 * p + 4],
            &want[4 * p..4 * p + 4]
        )
    });
    Difference {
        pixels: diff.len(),
        within_one,
        report,
    }
}

/// The case's texture target.
pub fn target(c: &Case) -> softgl_jit::texture::TexTarget {
    use softgl_jit::texture::TexTarget;
    match c.s("target", "2d").as_str() {
        "1d" => TexTarget::D1,
        "3d" => TexTarget::D3,
        "cube" => TexTarget::Cube,
        _ => TexTarget::D2,
    }
}

/// The case's `GL_DEPTH_TEXTURE_MODE`.
pub fn depth_mode(c: &Case) -> softgl_jit::texture::DepthMode {
    use softgl_jit::texture::DepthMode;
    match c.s("depth_mode", "luminance").as_str() {
        "intensity" => DepthMode::Intensity,
        "alpha" => DepthMode::Alpha,
        _ => DepthMode::Luminance,
    }
}

/// Unit `u`'s key `name`: `name` for unit 0, `name@u` for the others (probe.c's `K`).
pub fn key(name: &str, u: usize) -> String {
    if u == 0 {
        name.to_string()
    } else {
        format!("{name}@{u}")
    }
}

/// Texture units the case enables (`units=`, less those `off@u=1`).
pub fn units(c: &Case) -> impl Iterator<Item = usize> + '_ {
    (0..c.i("units", 1) as usize).filter(move |&u| c.i(&key("off", u), 0) == 0)
}

/// Unit `u`'s `GL_TEXTURE_ENV_MODE`.
pub fn env_mode(c: &Case, u: usize) -> softgl_jit::texture::EnvMode {
    use softgl_jit::texture::EnvMode;
    match c.s(&key("env", u), "replace").as_str() {
        "modulate" => EnvMode::Modulate,
        "decal" => EnvMode::Decal,
        "blend" => EnvMode::Blend,
        "add" => EnvMode::Add,
        "combine" => EnvMode::Combine,
        _ => EnvMode::Replace,
    }
}

/// Unit `u`'s combine state (`GL_COMBINE_RGB` …; GL's initial values where the case names none).
pub fn combine(c: &Case, u: usize) -> softgl_jit::texture::CombineKey {
    let d = softgl_jit::texture::CombineKey::DEFAULT;
    let k = |name: &str| key(name, u);
    softgl_jit::texture::CombineKey {
        rgb: combine_fn(&c.s(&k("crgb"), "modulate")),
        alpha: combine_fn(&c.s(&k("calpha"), "modulate")),
        src_rgb: std::array::from_fn(|i| c.kv.get(&k(&format!("srgb{i}"))).map_or(d.src_rgb[i], |s| source(s))),
        op_rgb: std::array::from_fn(|i| c.kv.get(&k(&format!("orgb{i}"))).map_or(d.op_rgb[i], |s| operand(s))),
        src_alpha: std::array::from_fn(|i| c.kv.get(&k(&format!("sa{i}"))).map_or(d.src_alpha[i], |s| source(s))),
        op_alpha: std::array::from_fn(|i| c.kv.get(&k(&format!("oa{i}"))).map_or(d.op_alpha[i], |s| operand(s))),
        scale_rgb: c.f(&k("scrgb"), 1.0) as u8,
        scale_alpha: c.f(&k("sca"), 1.0) as u8,
    }
}

/// Unit `u`'s `GL_TEXTURE_ENV_COLOR`.
pub fn env_color(c: &Case, u: usize) -> [f32; 4] {
    ["er", "eg", "eb", "ea"].map(|n| c.f(&key(n, u), 0.0))
}
