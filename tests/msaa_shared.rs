//! A 4× multisampled draw shades each pixel once and hands the colour to
//! every sample's tests and writes (`multisample::shared_halves`,
//! `raster::scene`'s groups): the same bytes as each sample shading on its
//! own (`Context::set_msaa_shared_shading(false)`). Random scenes, each
//! drawn both ways on both back ends, every sample's colour, depth and
//! stencil compared: textured (linear filtering, modulate), smooth and flat
//! colours, blending, alpha test, alpha to one and to coverage, fog,
//! stencil, depth test of every depth format, scissor, sample coverage,
//! `GL_MULTISAMPLE` switched off and on, polygon stipple, lines, points,
//! colour formats of 4, 3 and 2 bytes, draws that flush mid-draw, an
//! occlusion query's count.

use softgl::texture::{
    EnvMode, Filter, InternalFormat, MipFilter, PixelData, PixelFormat, PixelStore, PixelType, TexImageTarget,
    TexParam, TextureTarget, Wrap,
};
use softgl::{
    Backend, BlendFactor, Capability, ClearMask, ColorFormat, CompareFunc, Context, FogMode, FogParam, Framebuffer,
    FramebufferDesc, MatrixMode, PrimitiveMode, QueryTarget, ShadeModel, StencilOp, TexEnvParam,
};

const W: u32 = 150;
const H: u32 = 90;

/// xorshift32: the scenes' numbers.
struct Rng(u32);

impl Rng {
    fn next(&mut self) -> u32 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 17;
        self.0 ^= self.0 << 5;
        self.0
    }

    fn below(&mut self, n: u32) -> u32 {
        self.next() % n
    }

    fn unit(&mut self) -> f32 {
        (self.next() >> 8) as f32 / (1 << 24) as f32
    }

    fn chance(&mut self, percent: u32) -> bool {
        self.below(100) < percent
    }
}

fn desc(rng: &mut Rng) -> FramebufferDesc {
    let color = [
        ColorFormat::Rgba8,
        ColorFormat::Bgra8,
        ColorFormat::Rgb8,
        ColorFormat::Rgb565,
    ][rng.below(4) as usize];
    let depth_bits = [16, 24, 32, FramebufferDesc::FLOAT_DEPTH, 0][rng.below(5) as usize];
    FramebufferDesc {
        width: W,
        height: H,
        color,
        depth_bits,
        stencil_bits: if rng.chance(70) { 8 } else { 0 },
    }
}

fn texture(gl: &mut Context, rng: &mut Rng) {
    let t = gl.gen_textures(1).unwrap()[0];
    gl.bind_texture(TextureTarget::D2, t).unwrap();
    let bytes: Vec<u8> = (0..8 * 8 * 4).map(|_| rng.next() as u8).collect();
    let pixels = PixelData {
        format: PixelFormat::Rgba,
        ty: PixelType::UnsignedByte,
        store: PixelStore::DEFAULT,
        bytes: &bytes,
    };
    gl.tex_image(TexImageTarget::D2, 0, InternalFormat::Rgba8, [8, 8, 1], 0, Some(pixels))
        .unwrap();
    let d2 = TextureTarget::D2;
    gl.tex_parameter(d2, TexParam::MinFilter(Filter::Linear, MipFilter::None))
        .unwrap();
    gl.tex_parameter(d2, TexParam::MagFilter(Filter::Linear)).unwrap();
    gl.tex_parameter(d2, TexParam::WrapS(Wrap::Repeat)).unwrap();
    gl.tex_parameter(d2, TexParam::WrapT(Wrap::Repeat)).unwrap();
    gl.tex_env(TexEnvParam::Mode(EnvMode::Modulate)).unwrap();
}

fn toggle(gl: &mut Context, rng: &mut Rng, cap: Capability, percent: u32) {
    if rng.chance(percent) {
        gl.enable(cap).unwrap();
    } else {
        gl.disable(cap).unwrap();
    }
}

/// Draws seed `seed`'s scene into `fb` on `backend`, sharing the shading
/// or not; with the samples an occlusion query counted.
fn draw(seed: u32, backend: Backend, share: bool) -> (Context, u64) {
    let mut rng = Rng(seed.wrapping_mul(0x9e37_79b9) | 1);
    let fb = Framebuffer::new_multisample(desc(&mut rng), 4).unwrap();
    let mut gl = Context::with_framebuffer(fb);
    gl.set_backend(backend);
    gl.set_msaa_shared_shading(share);
    if rng.chance(30) {
        // Scenes past their bound mid-draw (flushed in the background).
        gl.set_threads(2);
        gl.set_scene_bound(4096);
    }
    gl.viewport(0, 0, W as i32, H as i32).unwrap();
    gl.matrix_mode(MatrixMode::Projection).unwrap();
    gl.ortho(0.0, f64::from(W), 0.0, f64::from(H), -1.0, 1.0).unwrap();
    gl.matrix_mode(MatrixMode::Modelview).unwrap();
    gl.clear_color(0.1, 0.2, 0.3, 0.4).unwrap();
    gl.clear_stencil(0).unwrap();
    gl.clear(ClearMask::ALL).unwrap();
    texture(&mut gl, &mut rng);
    let q = gl.queries_mut().gen(1).unwrap()[0];
    gl.queries_mut().begin(QueryTarget::SamplesPassed, q).unwrap();
    for _draw in 0..8 {
        toggle(&mut gl, &mut rng, Capability::Texture(TextureTarget::D2), 60);
        toggle(&mut gl, &mut rng, Capability::DepthTest, 60);
        toggle(&mut gl, &mut rng, Capability::Blend, 50);
        toggle(&mut gl, &mut rng, Capability::AlphaTest, 40);
        toggle(&mut gl, &mut rng, Capability::StencilTest, 40);
        toggle(&mut gl, &mut rng, Capability::ScissorTest, 20);
        toggle(&mut gl, &mut rng, Capability::Fog, 20);
        toggle(&mut gl, &mut rng, Capability::SampleCoverage, 15);
        toggle(&mut gl, &mut rng, Capability::SampleAlphaToCoverage, 10);
        toggle(&mut gl, &mut rng, Capability::SampleAlphaToOne, 10);
        toggle(&mut gl, &mut rng, Capability::Multisample, 85);
        toggle(&mut gl, &mut rng, Capability::PolygonStipple, 5);
        gl.shade_model(if rng.chance(20) {
            ShadeModel::Flat
        } else {
            ShadeModel::Smooth
        })
        .unwrap();
        let depth = [
            CompareFunc::Less,
            CompareFunc::Lequal,
            CompareFunc::Greater,
            CompareFunc::Gequal,
            CompareFunc::Equal,
            CompareFunc::Notequal,
        ];
        gl.depth_func(depth[rng.below(6) as usize]).unwrap();
        let blend = [
            (BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha),
            (BlendFactor::One, BlendFactor::One),
            (BlendFactor::DstColor, BlendFactor::Zero),
        ][rng.below(3) as usize];
        gl.blend_func(blend.0, blend.1).unwrap();
        gl.alpha_func(CompareFunc::Gequal, [0.5, 0.99, 0.2][rng.below(3) as usize])
            .unwrap();
        gl.stencil_func(
            [CompareFunc::Always, CompareFunc::Equal, CompareFunc::Notequal][rng.below(3) as usize],
            rng.below(3) as i32,
            0xff,
        )
        .unwrap();
        // Ops that keep where the tests fail let the shading test early.
        let ops = [
            (StencilOp::Keep, StencilOp::Incr, StencilOp::Replace),
            (StencilOp::Keep, StencilOp::Keep, StencilOp::Replace),
            (StencilOp::Keep, StencilOp::Keep, StencilOp::Incr),
        ][rng.below(3) as usize];
        gl.stencil_op(ops.0, ops.1, ops.2).unwrap();
        gl.scissor(
            rng.below(40) as i32,
            rng.below(30) as i32,
            60 + rng.below(90) as i32,
            40 + rng.below(50) as i32,
        )
        .unwrap();
        gl.sample_coverage(rng.unit(), rng.chance(50)).unwrap();
        gl.fog(FogParam::Mode(FogMode::Linear)).unwrap();
        gl.fog(FogParam::Start(-1.0)).unwrap();
        gl.fog(FogParam::End(1.0)).unwrap();
        gl.fog(FogParam::Color([0.7, 0.1, 0.4, 0.5])).unwrap();
        gl.polygon_stipple(std::array::from_fn(|_| rng.next())).unwrap();
        let mode = [
            PrimitiveMode::Triangles,
            PrimitiveMode::Triangles,
            PrimitiveMode::TriangleStrip,
            PrimitiveMode::Lines,
            PrimitiveMode::Points,
        ][rng.below(5) as usize];
        gl.line_width([1.0, 2.5, 5.0][rng.below(3) as usize]).unwrap();
        gl.point_size([1.0, 3.0, 6.5][rng.below(3) as usize]).unwrap();
        gl.begin(mode).unwrap();
        for _ in 0..3 * (1 + rng.below(12)) {
            gl.color4(rng.unit(), rng.unit(), rng.unit(), rng.unit());
            gl.tex_coord2(rng.unit() * 3.0 - 1.0, rng.unit() * 3.0 - 1.0);
            let (x, y) = (
                rng.unit() * (W as f32 + 20.0) - 10.0,
                rng.unit() * (H as f32 + 20.0) - 10.0,
            );
            gl.vertex3(x, y, rng.unit() * 1.8 - 0.9);
        }
        gl.end().unwrap();
        if rng.chance(15) {
            // A clear between draws (scissored when the test is on).
            gl.clear(ClearMask {
                color: rng.chance(50),
                depth: rng.chance(50),
                stencil: rng.chance(50),
                accum: false,
            })
            .unwrap();
        }
    }
    gl.queries_mut().end(QueryTarget::SamplesPassed).unwrap();
    gl.flush().unwrap();
    let passed = gl.query_result(q).unwrap();
    (gl, passed)
}

/// A sample's colour, depth and stencil.
type Sample = (Vec<u8>, Vec<u32>, Vec<u8>);

/// Every sample's colour, depth and stencil bytes, and the query's count.
fn samples((mut gl, passed): (Context, u64)) -> (Vec<Sample>, u64) {
    let fb = gl.framebuffer();
    let s: Vec<_> = (0..4)
        .map(|s| {
            let f = fb.sample(s).unwrap();
            let depth = (0..H)
                .flat_map(|y| (0..W).map(move |x| (x, y)))
                .map(|(x, y)| f.depth_at(x, y).unwrap_or(0))
                .collect();
            (
                f.color_bytes().to_vec(),
                depth,
                f.stencil_buffer().map(<[u8]>::to_vec).unwrap_or_default(),
            )
        })
        .collect();
    (s, passed)
}

#[test]
fn shared_shading_draws_each_samples_bytes() {
    for seed in 0..64 {
        for backend in [Backend::Jit, Backend::Interpreter] {
            let (want, want_passed) = samples(draw(seed, backend, false));
            let (got, passed) = samples(draw(seed, backend, true));
            assert_eq!(passed, want_passed, "seed {seed} {backend:?}: samples passed");
            for (s, (g, w)) in got.iter().zip(&want).enumerate() {
                assert!(g.0 == w.0, "seed {seed} {backend:?}: sample {s}'s colour");
                assert!(g.1 == w.1, "seed {seed} {backend:?}: sample {s}'s depth");
                assert!(g.2 == w.2, "seed {seed} {backend:?}: sample {s}'s stencil");
            }
        }
    }
}

/// The two back ends agree on the shared draws too (the shading half's
/// key and the per-sample half's are the JIT's as any other).
#[test]
fn shared_shading_is_the_same_on_both_back_ends() {
    for seed in 100..116 {
        let jit = samples(draw(seed, Backend::Jit, true));
        let interp = samples(draw(seed, Backend::Interpreter, true));
        assert!(jit == interp, "seed {seed}");
    }
}
