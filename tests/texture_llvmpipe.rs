//! Texturing end to end against llvmpipe: every scene of
//! `jit/tests/llvmpipe/cases.txt` drawn through softgl's `Context` (upload,
//! parameters, environment, the quad or the receding floor) on both back
//! ends, compared with the image Mesa 22.3.6 llvmpipe made of the same calls
//! (`jit/tests/llvmpipe/probe.c` → `probe.txt`).

#[path = "../jit/tests/llvmpipe/cases.rs"]
mod cases;

use cases::{cases, compare, difference, filter, raw_texels, recorded, wrap, Case};
use softgl::{
    Backend, Capability, ClearMask, Context, EnvMode, FramebufferDesc, InternalFormat, MatrixMode, PixelData,
    PixelFormat, PixelStore, PixelType, PrimitiveMode, ReadFormat, TexEnvParam, TexImageTarget, TexParam,
    TextureTarget,
};

/// Uploads, configures and draws case `c` (texels seeded by `seed`) as probe.c does.
fn draw(gl: &mut Context, c: &Case, seed: u32, n: i32) {
    let target = cases::target(c);
    let fmt = c.s("format", "rgba8");
    let (internal, format, ty) = match fmt.as_str() {
        "rgba8" => (InternalFormat::Rgba8, PixelFormat::Rgba, PixelType::UnsignedByte),
        "rgb8" => (InternalFormat::Rgb8, PixelFormat::Rgb, PixelType::UnsignedByte),
        "l8" => (
            InternalFormat::Luminance8,
            PixelFormat::Luminance,
            PixelType::UnsignedByte,
        ),
        "a8" => (InternalFormat::Alpha8, PixelFormat::Alpha, PixelType::UnsignedByte),
        "i8" => (
            InternalFormat::Intensity8,
            PixelFormat::Luminance,
            PixelType::UnsignedByte,
        ),
        "la8" => (
            InternalFormat::Luminance8Alpha8,
            PixelFormat::LuminanceAlpha,
            PixelType::UnsignedByte,
        ),
        "rgba16" => (InternalFormat::Rgba16, PixelFormat::Rgba, PixelType::UnsignedShort),
        "srgba8" => (InternalFormat::Srgb8Alpha8, PixelFormat::Rgba, PixelType::UnsignedByte),
        "depth" => (
            InternalFormat::DepthComponent24,
            PixelFormat::DepthComponent,
            PixelType::Float,
        ),
        _ => panic!("format {fmt}"),
    };
    let name = gl.gen_textures(1).unwrap()[0];
    gl.bind_texture(target, name).unwrap();
    let (w, h, d) = (c.i("w", 8), c.i("h", 8), c.i("d", 1));
    let store = PixelStore {
        alignment: 1,
        ..PixelStore::DEFAULT
    };
    for l in 0..c.i("levels", 1) {
        let lw = (w >> l).max(1);
        let lh = if target == TextureTarget::D1 {
            1
        } else {
            (h >> l).max(1)
        };
        let ld = if target == TextureTarget::D3 {
            (d >> l).max(1)
        } else {
            1
        };
        let faces: Vec<TexImageTarget> = match target {
            TextureTarget::D1 => vec![TexImageTarget::D1],
            TextureTarget::D3 => vec![TexImageTarget::D3],
            TextureTarget::Cube => (0..6).map(TexImageTarget::CubeFace).collect(),
            _ => vec![TexImageTarget::D2],
        };
        for (face, t) in faces.into_iter().enumerate() {
            let seed = seed * 1000 + l as u32 * 10 + face as u32;
            let bytes = raw_texels(&fmt, seed, (lw * lh * ld) as usize);
            let pixels = PixelData {
                format,
                ty,
                store,
                bytes: &bytes,
            };
            gl.tex_image(t, l, internal, [lw, lh, ld], 0, Some(pixels)).unwrap();
        }
    }
    let (min, mip) = filter(&c.s("min", "linear"));
    let params = [
        TexParam::MinFilter(min, mip),
        TexParam::MagFilter(filter(&c.s("mag", "linear")).0),
        TexParam::WrapS(wrap(&c.s("wrap_s", "repeat"))),
        TexParam::WrapT(wrap(&c.s("wrap_t", "repeat"))),
        TexParam::WrapR(wrap(&c.s("wrap_r", "repeat"))),
        TexParam::BorderColor([c.f("br", 0.0), c.f("bg", 0.0), c.f("bb", 0.0), c.f("ba", 0.0)]),
        TexParam::LodBias(c.f("bias", 0.0)),
        TexParam::MinLod(c.f("min_lod", -1000.0)),
        TexParam::MaxLod(c.f("max_lod", 1000.0)),
        TexParam::BaseLevel(c.i("base", 0)),
        TexParam::MaxLevel(c.i("max_level", 1000)),
        TexParam::DepthMode(cases::depth_mode(c)),
    ];
    for p in params {
        gl.tex_parameter(target, p).unwrap();
    }
    if let Some(f) = c.kv.get("compare") {
        gl.tex_parameter(target, TexParam::CompareMode(true)).unwrap();
        gl.tex_parameter(target, TexParam::CompareFunc(compare(f))).unwrap();
    }
    // The same texture on every unit of the case, each with its environment
    // (combine state from cases::combine: GL's defaults where the case names none).
    let n_units = c.i("units", 1) as u32;
    for u in 0..n_units as usize {
        gl.active_texture(u as u32).unwrap();
        gl.bind_texture(target, name).unwrap();
        if cases::units(c).any(|e| e == u) {
            gl.enable(Capability::Texture(target)).unwrap();
        }
        let mode = cases::env_mode(c, u);
        gl.tex_env(TexEnvParam::Mode(mode)).unwrap();
        gl.tex_env(TexEnvParam::Color(cases::env_color(c, u))).unwrap();
        if mode == EnvMode::Combine {
            let k = cases::combine(c, u);
            gl.tex_env(TexEnvParam::CombineRgb(k.rgb)).unwrap();
            gl.tex_env(TexEnvParam::CombineAlpha(k.alpha)).unwrap();
            for i in 0..3u8 {
                let j = usize::from(i);
                gl.tex_env(TexEnvParam::SrcRgb(i, k.src_rgb[j])).unwrap();
                gl.tex_env(TexEnvParam::OperandRgb(i, k.op_rgb[j])).unwrap();
                gl.tex_env(TexEnvParam::SrcAlpha(i, k.src_alpha[j])).unwrap();
                gl.tex_env(TexEnvParam::OperandAlpha(i, k.op_alpha[j])).unwrap();
            }
            gl.tex_env(TexEnvParam::RgbScale(f32::from(k.scale_rgb))).unwrap();
            gl.tex_env(TexEnvParam::AlphaScale(f32::from(k.scale_alpha))).unwrap();
        }
    }
    gl.active_texture(0).unwrap();
    gl.clear_color(0.0, 0.0, 0.0, 0.0).unwrap();
    gl.clear(ClearMask::COLOR).unwrap();
    for m in [MatrixMode::Projection, MatrixMode::Modelview] {
        gl.matrix_mode(m).unwrap();
        gl.load_identity().unwrap();
    }
    gl.color4(c.f("cr", 1.0), c.f("cg", 1.0), c.f("cb", 1.0), c.f("ca", 1.0));
    if c.s("geom", "flat") == "persp" {
        gl.matrix_mode(MatrixMode::Projection).unwrap();
        gl.frustum(-0.5, 0.5, -0.5, 0.5, 1.0, 30.0).unwrap();
        gl.matrix_mode(MatrixMode::Modelview).unwrap();
        let (ps, pt, y) = (c.f("ps", 8.0), c.f("pt", 16.0), c.f("py", -1.0));
        let floor = [
            [-4.0, -1.5, 0.0, 0.0],
            [4.0, -1.5, 1.0, 0.0],
            [4.0, -30.0, 1.0, 1.0],
            [-4.0, -30.0, 0.0, 1.0],
        ];
        gl.begin(PrimitiveMode::Quads).unwrap();
        for v in floor {
            if c.i("cvary", 0) == 1 {
                gl.color4(c.f("cr", 1.0), c.f("cg", 1.0), c.f("cb", 1.0), c.f("ca", 1.0));
            }
            gl.tex_coord2(v[2] * ps, v[3] * pt);
            gl.vertex3(v[0], y, v[1]);
        }
    } else {
        let corner = [[0.0, 0.0], [n as f32, 0.0], [n as f32, n as f32], [0.0, n as f32]];
        let comps = [
            ("s0", "sx", "sy"),
            ("t0", "tx", "ty"),
            ("r0", "rx", "ry"),
            ("q0", "qx", "qy"),
        ];
        gl.begin(PrimitiveMode::Quads).unwrap();
        for [x, y] in corner {
            let tc = comps
                .map(|(a, dx, dy)| c.f(a, if a == "q0" { 1.0 } else { 0.0 }) + x * c.f(dx, 0.0) + y * c.f(dy, 0.0));
            for u in 0..n_units {
                gl.multi_tex_coord(u, tc).unwrap();
            }
            gl.vertex2(x * 2.0 / n as f32 - 1.0, y * 2.0 / n as f32 - 1.0);
        }
    }
    gl.end().unwrap();
}

#[test]
fn every_scene_matches_llvmpipe_on_both_back_ends() {
    let llvmpipe = recorded();
    let mut report = Vec::new();
    let mut count = 0;
    for backend in [Backend::Interpreter, Backend::Jit] {
        for (i, line) in cases() {
            let c = Case::parse(line);
            let n = c.i("size", 16);
            let want = llvmpipe
                .get(&c.name)
                .unwrap_or_else(|| panic!("{} not recorded", c.name));
            let mut gl = Context::new(FramebufferDesc::rgba8_d24s8(n as u32, n as u32)).unwrap();
            gl.set_backend(backend);
            // The natively sampled code (a tiered key runs the reference
            // sampler through the callout until its upgrade is in).
            gl.set_jit_tier(Some(softgl_jit::Tier::Optimized));
            gl.viewport(0, 0, n, n).unwrap();
            draw(&mut gl, &c, i as u32, n);
            let got = gl.read_pixels(0, 0, n, n, ReadFormat::Rgba8).unwrap();
            if backend == Backend::Jit {
                // The scene ran on a compiled specialist, not on the interpreter fallback.
                let stats = gl.specialist_stats();
                assert!(stats.misses >= 1 && stats.failures == 0, "{}: {stats:?}", c.name);
            }
            let d = difference(&format!("{backend:?} {}", c.name), &got, want, n as usize);
            count += 1;
            // Every scene identical, the current colour under perspective too
            // (a uniform in llvmpipe, constant planes in softgl: llvmpipe facts §20).
            if d.pixels > 0 {
                report.extend(d.report);
            }
        }
    }
    assert!(
        report.is_empty(),
        "{} of {count} renders differ:\n{}",
        report.len(),
        report.join("\n")
    );
}
