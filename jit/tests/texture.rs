//! The reference sampler and texture environment against llvmpipe's pixels.
//!
//! Each line of [`CASES`] is a 16x16 scene: one texture (LCG texels), a
//! full-viewport quad whose texture coordinates are affine in the window
//! position with power-of-two steps (so both sides know them exactly), and
//! an environment. `tests/llvmpipe/probe.c` rendered them with Mesa 22.3.6
//! llvmpipe (OSMesa) into `tests/llvmpipe/probe.txt`; here softgl's
//! reference computes every pixel from the same description and must match
//! byte for byte. `regenerate` (ignored) re-runs the probe.

use softgl_jit::key::CompareFunc;
use softgl_jit::shade::unorm8;
use softgl_jit::texture::{
    effective_combine, environment, sample_quad, BaseFormat, CombineFn, CombineKey, CombineSrc, DepthMode, EnvMode,
    Filter, Image, MipFilter, Operand, SamplerKey, TexTarget, TexUnitKey, TexelFormat, TextureRef, Wrap, MAX_UNITS,
};
use std::collections::HashMap;

/// Scene side in pixels (the probe's `N`).
const N: usize = 16;

/// The scenes: a name, then `key=value` words (defaults in `probe.c`).
const CASES: &[&str] = &[
    // Magnified 8x8 RGBA8, 0.375 texels a pixel: the AoS path, 8.8 weights.
    "mag_linear_repeat format=rgba8 s0=-0.375 sx=0.046875 t0=0.125 ty=0.0390625",
    "mag_nearest_repeat min=nearest mag=nearest s0=-0.375 sx=0.046875 t0=0.125 ty=0.0390625",
    "mag_linear_edge wrap_s=clamp_to_edge wrap_t=clamp_to_edge s0=-0.25 sx=0.09375 t0=-0.5 ty=0.125",
    "mag_nearest_edge min=nearest mag=nearest wrap_s=clamp_to_edge wrap_t=clamp_to_edge s0=-0.25 sx=0.09375 t0=-0.5 ty=0.125",
    // SoA wraps with a border colour.
    "mag_linear_clamp wrap_s=clamp wrap_t=clamp br=0.25 bg=0.5 bb=1 ba=0.75 s0=-0.25 sx=0.09375 t0=-0.5 ty=0.125",
    "mag_linear_border wrap_s=clamp_to_border wrap_t=clamp_to_border br=0.25 bg=2 bb=-1 ba=0.75 s0=-0.25 sx=0.09375 t0=-0.5 ty=0.125",
    "mag_nearest_border min=nearest mag=nearest wrap_s=clamp_to_border wrap_t=repeat br=0.25 bg=0.5 bb=1 ba=0.75 s0=-0.25 sx=0.09375 t0=-0.5 ty=0.125",
    "mag_nearest_clamp min=nearest mag=nearest wrap_s=clamp wrap_t=clamp br=0.25 s0=-0.25 sx=0.09375 t0=-0.5 ty=0.125",
    "mag_linear_mirror wrap_s=mirrored_repeat wrap_t=mirrored_repeat s0=-1.5 sx=0.1875 t0=-0.75 ty=0.125",
    "mag_nearest_mirror min=nearest mag=nearest wrap_s=mirrored_repeat wrap_t=mirrored_repeat s0=-1.5 sx=0.1875 t0=-0.75 ty=0.125",
    // Non-power-of-two REPEAT (its own arithmetic on both paths).
    "npot_linear_repeat w=5 h=3 s0=-0.625 sx=0.0625 t0=-0.25 ty=0.09375",
    "npot_nearest_repeat w=5 h=3 min=nearest mag=nearest s0=-0.625 sx=0.0625 t0=-0.25 ty=0.09375",
    "npot_linear_mirror w=5 h=3 wrap_s=mirrored_repeat wrap_t=clamp s0=-0.625 sx=0.0625 t0=-0.25 ty=0.09375",
    // Minification of a mipmapped 64x64: lambda from the quad.
    "min_trilinear w=64 h=64 levels=7 min=linear_mipmap_linear s0=0.0078125 sx=0.046875 t0=0.25 ty=0.015625",
    "min_trilinear_aniso w=64 h=64 levels=7 min=linear_mipmap_linear s0=0.0078125 sx=0.09375 tx=0.03125 t0=0.25 ty=0.015625",
    "min_nearest_nearest w=64 h=64 levels=7 min=nearest_mipmap_nearest s0=0.0078125 sx=0.1484375 t0=0.25 ty=0.015625",
    "min_linear_nearest w=64 h=64 levels=7 min=linear_mipmap_nearest s0=0.0078125 sx=0.1484375 t0=0.25 ty=0.015625",
    "min_nearest_linear w=64 h=64 levels=7 min=nearest_mipmap_linear s0=0.0078125 sx=0.1171875 t0=0.25 ty=0.015625",
    "min_linear_only w=64 h=64 levels=7 min=linear s0=0.0078125 sx=0.1171875 t0=0.25 ty=0.015625",
    "min_nearest_mag_linear w=64 h=64 levels=7 min=nearest mag=linear s0=0.0078125 sx=0.046875 t0=0.25 ty=0.015625",
    "min_switch_over w=64 h=64 levels=7 min=nearest_mipmap_nearest mag=linear s0=0.0078125 sx=0.015625 sy=0.0078125 t0=0.25 ty=0.015625",
    "min_bias w=64 h=64 levels=7 min=linear_mipmap_linear bias=1.25 s0=0.0078125 sx=0.046875 t0=0.25 ty=0.015625",
    "min_lod_clamps w=64 h=64 levels=7 min=linear_mipmap_linear min_lod=2.5 max_lod=3.25 s0=0.0078125 sx=0.1875 t0=0.25 ty=0.015625",
    "min_base_level w=64 h=64 levels=7 min=linear_mipmap_linear base=2 max_level=4 s0=0.0078125 sx=0.09375 t0=0.25 ty=0.015625",
    "min_lod_equal w=64 h=64 levels=7 min=linear_mipmap_linear min_lod=1.5 max_lod=1.5 s0=0.0078125 sx=0.046875 t0=0.25 ty=0.015625",
    "min_projected w=64 h=64 levels=7 min=linear_mipmap_linear q0=2 s0=0.015625 sx=0.09375 t0=0.5 ty=0.03125",
    // Base formats on the AoS path, 16-bit and sRGB on the SoA path.
    "fmt_l8 format=l8 s0=-0.375 sx=0.046875 t0=0.125 ty=0.0390625",
    "fmt_a8 format=a8 env=modulate cr=0.5 cg=0.25 cb=1 ca=0.75 s0=-0.375 sx=0.046875 t0=0.125 ty=0.0390625",
    "fmt_i8 format=i8 s0=-0.375 sx=0.046875 t0=0.125 ty=0.0390625",
    "fmt_la8 format=la8 s0=-0.375 sx=0.046875 t0=0.125 ty=0.0390625",
    "fmt_rgb8 format=rgb8 s0=-0.375 sx=0.046875 t0=0.125 ty=0.0390625",
    "fmt_rgba16 format=rgba16 s0=-0.375 sx=0.046875 t0=0.125 ty=0.0390625",
    "fmt_srgba8 format=srgba8 s0=-0.375 sx=0.046875 t0=0.125 ty=0.0390625",
    "fmt_srgba8_mip format=srgba8 w=64 h=64 levels=7 min=linear_mipmap_linear s0=0.0078125 sx=0.046875 t0=0.25 ty=0.015625",
    // 1D, 3D and cube maps.
    "tgt_1d target=1d w=16 h=1 levels=5 min=linear_mipmap_linear s0=-0.1875 sx=0.09375 sy=0.03125",
    "tgt_3d target=3d w=8 h=8 d=8 s0=-0.375 sx=0.046875 t0=0.125 ty=0.0390625 r0=0.25 rx=0.0078125 ry=0.015625",
    "tgt_3d_mip target=3d w=16 h=16 d=16 levels=5 min=linear_mipmap_linear s0=0.0078125 sx=0.09375 t0=0.25 ty=0.0390625 r0=0.25 rx=0.03125 ry=0.015625",
    "tgt_cube target=cube w=8 h=8 s0=-1 sx=0.125 t0=-0.75 ty=0.0625 r0=0.5 rx=0.03125",
    "tgt_cube_nearest target=cube w=8 h=8 min=nearest mag=nearest s0=-1 sx=0.125 t0=-0.75 ty=0.0625 r0=-0.5 ry=0.0625",
    "tgt_cube_mip target=cube w=16 h=16 levels=5 min=linear_mipmap_linear s0=-1 sx=0.125 t0=-0.75 ty=0.0625 r0=0.5 rx=0.03125",
    // Depth textures: compare and DEPTH_TEXTURE_MODE.
    "depth_compare format=depth compare=lequal r0=0.25 rx=0.03125 s0=-0.375 sx=0.046875 t0=0.125 ty=0.0390625",
    "depth_compare_nearest format=depth compare=greater min=nearest mag=nearest depth_mode=alpha env=modulate cr=0.5 cg=0.5 cb=0.5 ca=1 r0=0.25 rx=0.03125 s0=-0.375 sx=0.046875 t0=0.125 ty=0.0390625",
    "depth_plain format=depth depth_mode=intensity s0=-0.375 sx=0.046875 t0=0.125 ty=0.0390625",
    // Legacy environments.
    "env_modulate env=modulate cr=0.5 cg=0.25 cb=1 ca=0.75 s0=-0.375 sx=0.046875 t0=0.125 ty=0.0390625",
    "env_decal env=decal cr=0.5 cg=0.25 cb=1 ca=0.75 s0=-0.375 sx=0.046875 t0=0.125 ty=0.0390625",
    "env_blend env=blend cr=0.5 cg=0.25 cb=1 ca=0.75 er=0.125 eg=0.875 eb=0.5 ea=0.25 s0=-0.375 sx=0.046875 t0=0.125 ty=0.0390625",
    "env_blend_i8 format=i8 env=blend cr=0.5 cg=0.25 cb=1 ca=0.75 er=0.125 eg=0.875 eb=0.5 ea=0.25 s0=-0.375 sx=0.046875 t0=0.125 ty=0.0390625",
    "env_add env=add cr=0.5 cg=0.25 cb=1 ca=0.75 s0=-0.375 sx=0.046875 t0=0.125 ty=0.0390625",
    "env_add_i8 format=i8 env=add cr=0.5 cg=0.25 cb=1 ca=0.75 s0=-0.375 sx=0.046875 t0=0.125 ty=0.0390625",
    "env_decal_rgb8 format=rgb8 env=decal cr=0.5 cg=0.25 cb=1 ca=0.75 s0=-0.375 sx=0.046875 t0=0.125 ty=0.0390625",
    "env_replace_la8 format=la8 env=replace cr=0.5 cg=0.25 cb=1 ca=0.75 s0=-0.375 sx=0.046875 t0=0.125 ty=0.0390625",
    // Combine functions, operands and scales.
    "cmb_add_signed env=combine crgb=add_signed calpha=add_signed scrgb=2 cr=0.5 cg=0.25 cb=1 ca=0.75 s0=-0.375 sx=0.046875 t0=0.125 ty=0.0390625",
    "cmb_interpolate env=combine crgb=interpolate calpha=interpolate srgb2=primary_color orgb2=one_minus_src_color sa2=constant ea=0.375 cr=0.5 cg=0.25 cb=1 ca=0.75 s0=-0.375 sx=0.046875 t0=0.125 ty=0.0390625",
    "cmb_subtract env=combine crgb=subtract calpha=subtract sca=4 orgb1=one_minus_src_alpha cr=0.5 cg=0.25 cb=1 ca=0.75 s0=-0.375 sx=0.046875 t0=0.125 ty=0.0390625",
    "cmb_dot3_rgb env=combine crgb=dot3_rgb calpha=replace scrgb=4 sca=2 srgb1=constant er=0.75 eg=0.25 eb=0.625 ea=0.3 s0=-0.375 sx=0.046875 t0=0.125 ty=0.0390625",
    "cmb_dot3_rgba env=combine crgb=dot3_rgba srgb1=primary_color cr=0.5 cg=0.875 cb=0.125 ca=0.75 scrgb=2 s0=-0.375 sx=0.046875 t0=0.125 ty=0.0390625",
    "cmb_replace_ops env=combine crgb=replace calpha=replace orgb0=one_minus_src_alpha oa0=one_minus_src_alpha s0=-0.375 sx=0.046875 t0=0.125 ty=0.0390625",
    "cmb_modulate_scale env=combine crgb=modulate calpha=add scrgb=4 sca=2 srgb1=constant er=0.75 eg=0.25 eb=0.625 ea=0.3 s0=-0.375 sx=0.046875 t0=0.125 ty=0.0390625",
];

/// One scene's description: its name and `key=value` words.
struct Case {
    name: String,
    kv: HashMap<String, String>,
}

impl Case {
    fn parse(line: &str) -> Case {
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

    fn s(&self, k: &str, default: &str) -> String {
        self.kv.get(k).cloned().unwrap_or_else(|| default.to_string())
    }

    fn f(&self, k: &str, default: f32) -> f32 {
        self.kv.get(k).map_or(default, |v| v.parse().expect("a number"))
    }

    fn i(&self, k: &str, default: i32) -> i32 {
        self.kv.get(k).map_or(default, |v| v.parse().expect("an integer"))
    }
}

fn filter(s: &str) -> (Filter, MipFilter) {
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

fn wrap(s: &str) -> Wrap {
    match s {
        "repeat" => Wrap::Repeat,
        "clamp" => Wrap::Clamp,
        "clamp_to_edge" => Wrap::ClampToEdge,
        "clamp_to_border" => Wrap::ClampToBorder,
        "mirrored_repeat" => Wrap::MirroredRepeat,
        _ => panic!("wrap {s}"),
    }
}

fn combine_fn(s: &str) -> CombineFn {
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

fn source(s: &str) -> CombineSrc {
    match s {
        "texture" => CombineSrc::Texture,
        "constant" => CombineSrc::Constant,
        "primary_color" => CombineSrc::PrimaryColor,
        "previous" => CombineSrc::Previous,
        _ => panic!("source {s}"),
    }
}

fn operand(s: &str) -> Operand {
    match s {
        "src_color" => Operand::SrcColor,
        "one_minus_src_color" => Operand::OneMinusSrcColor,
        "src_alpha" => Operand::SrcAlpha,
        "one_minus_src_alpha" => Operand::OneMinusSrcAlpha,
        _ => panic!("operand {s}"),
    }
}

fn compare(s: &str) -> CompareFunc {
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
struct Lcg(u32);

impl Lcg {
    fn byte(&mut self) -> u8 {
        self.0 = self.0.wrapping_mul(1_103_515_245).wrapping_add(12345);
        (self.0 >> 16) as u8
    }
}

/// One image's texels in softgl's storage, as the probe uploads them.
fn texels(format: &str, seed: u32, n: usize) -> Vec<u8> {
    let mut g = Lcg(seed);
    let bytes = match format {
        "rgba8" | "srgba8" | "depth" => 4,
        "rgb8" => 3,
        "la8" => 2,
        "l8" | "a8" | "i8" => 1,
        "rgba16" => 8,
        _ => panic!("format {format}"),
    };
    let raw: Vec<u8> = (0..n * bytes).map(|_| g.byte()).collect();
    let mut out = Vec::with_capacity(n * 8);
    for t in raw.chunks(bytes) {
        let px: Vec<u8> = match format {
            "rgba8" | "srgba8" | "rgba16" => t.to_vec(),
            "rgb8" => vec![t[0], t[1], t[2], 255],
            "l8" => vec![t[0], t[0], t[0], 255],
            "a8" => vec![0, 0, 0, t[0]],
            "i8" => vec![t[0]; 4],
            "la8" => vec![t[0], t[0], t[0], t[1]],
            "depth" => (if t[0] & 1 == 1 { 1.0f32 } else { 0.0 }).to_ne_bytes().to_vec(),
            _ => unreachable!(),
        };
        out.extend(px);
    }
    out
}

/// Everything softgl needs to compute a case: key, images, levels.
struct Scene {
    unit: TexUnitKey,
    images: Vec<(Vec<u8>, [u32; 3])>,
    base: u32,
    max_level: u32,
}

fn scene(c: &Case, seed: u32) -> Scene {
    let target = match c.s("target", "2d").as_str() {
        "1d" => TexTarget::D1,
        "3d" => TexTarget::D3,
        "cube" => TexTarget::Cube,
        _ => TexTarget::D2,
    };
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
    let depth_mode = match c.s("depth_mode", "luminance").as_str() {
        "intensity" => DepthMode::Intensity,
        "alpha" => DepthMode::Alpha,
        _ => DepthMode::Luminance,
    };
    let dims = match target {
        TexTarget::D1 => 1,
        TexTarget::D2 | TexTarget::Cube => 2,
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
    };
    let mode = match c.s("env", "replace").as_str() {
        "modulate" => EnvMode::Modulate,
        "decal" => EnvMode::Decal,
        "blend" => EnvMode::Blend,
        "add" => EnvMode::Add,
        "combine" => EnvMode::Combine,
        _ => EnvMode::Replace,
    };
    let d = CombineKey::DEFAULT;
    let names = ["0", "1", "2"];
    let combine = CombineKey {
        rgb: combine_fn(&c.s("crgb", "modulate")),
        alpha: combine_fn(&c.s("calpha", "modulate")),
        src_rgb: std::array::from_fn(|i| {
            c.kv.get(&format!("srgb{}", names[i]))
                .map_or(d.src_rgb[i], |s| source(s))
        }),
        op_rgb: std::array::from_fn(|i| {
            c.kv.get(&format!("orgb{}", names[i]))
                .map_or(d.op_rgb[i], |s| operand(s))
        }),
        src_alpha: std::array::from_fn(|i| {
            c.kv.get(&format!("sa{}", names[i]))
                .map_or(d.src_alpha[i], |s| source(s))
        }),
        op_alpha: std::array::from_fn(|i| {
            c.kv.get(&format!("oa{}", names[i]))
                .map_or(d.op_alpha[i], |s| operand(s))
        }),
        scale_rgb: c.f("scrgb", 1.0) as u8,
        scale_alpha: c.f("sca", 1.0) as u8,
    };
    let env_base = if base == BaseFormat::Depth {
        depth_mode.base()
    } else {
        base
    };
    let last = levels.saturating_sub(1);
    Scene {
        unit: TexUnitKey {
            sampler,
            base,
            env: effective_combine(mode, env_base, combine),
        },
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
    let images: Vec<Image<'_>> = sc
        .images
        .iter()
        .map(|(t, [w, h, d])| Image {
            texels: t,
            width: *w,
            height: *h,
            depth: *d,
        })
        .collect();
    let tex = TextureRef {
        images: &images,
        base_level: sc.base,
        max_level: sc.max_level,
        min_lod: c.f("min_lod", -1000.0),
        max_lod: c.f("max_lod", 1000.0),
        lod_bias: softgl_jit::texture::quantized_lod_bias(c.f("bias", 0.0)),
        border: [c.f("br", 0.0), c.f("bg", 0.0), c.f("bb", 0.0), c.f("ba", 0.0)],
    };
    let primary = [c.f("cr", 1.0), c.f("cg", 1.0), c.f("cb", 1.0), c.f("ca", 1.0)];
    let env_color = [[c.f("er", 0.0), c.f("eg", 0.0), c.f("eb", 0.0), c.f("ea", 0.0)]; MAX_UNITS];
    let mut units = [None; MAX_UNITS];
    units[0] = Some(sc.unit);
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
            samples[0] = sample_quad(&sc.unit, &tex, &quad, lane);
            let colour = environment(&units, &samples, primary, &env_color);
            out[(y * N + x) * 4..][..4].copy_from_slice(&colour.map(unorm8));
        }
    }
    out
}

fn recorded() -> HashMap<String, Vec<u8>> {
    let text = include_str!("llvmpipe/probe.txt");
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
fn probe_line(i: usize, line: &str) -> String {
    format!("{line} seed={i}")
}

#[test]
fn every_case_matches_llvmpipe_byte_for_byte() {
    let llvmpipe = recorded();
    let mut failures = Vec::new();
    for (i, line) in CASES.iter().enumerate() {
        let c = Case::parse(line);
        let want = llvmpipe
            .get(&c.name)
            .unwrap_or_else(|| panic!("{} not recorded", c.name));
        let got = render(&c, i as u32);
        let diff: Vec<usize> = (0..N * N)
            .filter(|&p| got[4 * p..4 * p + 4] != want[4 * p..4 * p + 4])
            .collect();
        if let Some(&p) = diff.first() {
            failures.push(format!(
                "{}: {} pixels differ, first at ({}, {}): softgl {:?} llvmpipe {:?}",
                c.name,
                diff.len(),
                p % N,
                p / N,
                &got[4 * p..4 * p + 4],
                &want[4 * p..4 * p + 4]
            ));
        }
    }
    assert!(
        failures.is_empty(),
        "{} of {} cases differ:\n{}",
        failures.len(),
        CASES.len(),
        failures.join("\n")
    );
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
    let input: String = CASES.iter().enumerate().map(|(i, l)| probe_line(i, l) + "\n").collect();
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
