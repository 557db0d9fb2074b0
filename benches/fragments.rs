//! Fragment throughput of the per-fragment back ends, in fragments per second.
//!
//! Every back end runs the same work: each [`Scene`] is a key over a 256x256
//! RGBA8 target covered by 64-wide spans, starting from the same buffers each
//! iteration, with two kinds of data: *coherent* (full spans, smooth color
//! gradients, depth increasing with x + y) and *random* (seeded random colors,
//! depths and coverage masks). Groups are `<scene>/<data>` with one entry per
//! back end, so the interpreter and the JIT sit side by side.

use std::hint::black_box;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, BatchSize, Criterion, Throughput};
use softgl_jit::shade::slot;
use softgl_jit::TextureSet;
use softgl_jit::{
    BlendKey, ColorFormat, CompareFunc, DepthFormat, DepthKey, DepthTarget, FogMode, FogUniforms, FragmentKey,
    FragmentSpan, FragmentUniforms, LogicOp, Planes, ShadeKey, Specialist, StencilKey, StencilOp, Target, SPAN_MAX,
};

mod common;

/// Width and height of the target.
const SIZE: u32 = 256;

/// A way to run a key's stages over spans into a target.
trait Backend {
    /// Its name in the report.
    const NAME: &'static str;
    /// What the back end makes of a key before running it (a compiled
    /// specialist); made once per scene, outside the measurement.
    type Prepared;

    fn prepare(&self, key: &FragmentKey) -> Self::Prepared;

    fn run(
        &self,
        prepared: &Self::Prepared,
        u: &FragmentUniforms,
        work: (&[FragmentSpan], &[Planes]),
        target: &mut Target<'_>,
    );
}

/// The reference interpreter.
struct Interpreter;

impl Backend for Interpreter {
    const NAME: &'static str = "interpreter";
    type Prepared = FragmentKey;

    fn prepare(&self, key: &FragmentKey) -> FragmentKey {
        *key
    }

    fn run(
        &self,
        key: &FragmentKey,
        u: &FragmentUniforms,
        (spans, planes): (&[FragmentSpan], &[Planes]),
        target: &mut Target<'_>,
    ) {
        softgl_jit::interp::run_with_planes(key, u, &TextureSet::default(), spans, planes, target)
            .expect("scene keys match their buffers");
    }
}

/// Cranelift specialists, compiled once per scene outside the measurement.
struct Jit;

impl Backend for Jit {
    const NAME: &'static str = "jit";
    type Prepared = Specialist;

    fn prepare(&self, key: &FragmentKey) -> Specialist {
        Specialist::compile(key).expect("bench keys compile")
    }

    fn run(
        &self,
        s: &Specialist,
        u: &FragmentUniforms,
        (spans, planes): (&[FragmentSpan], &[Planes]),
        target: &mut Target<'_>,
    ) {
        s.run_with_planes(u, &TextureSet::default(), spans, planes, target)
            .expect("scene keys match their buffers");
    }
}

/// The buffers a scene draws into, restored before every iteration.
#[derive(Clone)]
struct Buffers {
    color: Vec<u8>,
    depth: Option<Vec<u32>>,
    stencil: Option<Vec<u8>>,
}

impl Buffers {
    fn target(&mut self) -> Target<'_> {
        Target::new(
            SIZE,
            SIZE,
            ColorFormat::Rgba8,
            &mut self.color,
            SIZE as usize * 4,
            self.depth.as_deref_mut().map(DepthTarget::D24),
            self.stencil.as_deref_mut(),
        )
        .expect("buffers sized for the target")
    }
}

/// One benchmark input: a key, its uniforms, and the starting buffers.
struct Scene {
    name: &'static str,
    key: FragmentKey,
    uniforms: FragmentUniforms,
    buffers: Buffers,
    /// The planes of the spans' primitive, for keys with a shading stage.
    planes: Vec<Planes>,
}

/// Full 64-wide spans covering the target: red follows x, green y, blue and
/// alpha the diagonal, z = (x + y) * 0x7fff grows to just under the D24 max.
fn coherent_spans() -> Vec<FragmentSpan> {
    let mut spans = Vec::new();
    for y in 0..SIZE {
        for x0 in (0..SIZE).step_by(SPAN_MAX) {
            let mut s = FragmentSpan::new(x0, y);
            for i in 0..SPAN_MAX {
                let x = x0 + i as u32;
                let diag = ((x + y) / 2) as u8;
                s.set(i, [x as u8, y as u8, diag, 255 - diag], (x + y) * 0x7fff);
            }
            spans.push(s);
        }
    }
    spans
}

/// Spans over the same pixels with seeded random colors, depths (D24 range)
/// and coverage (each fragment covered with probability 3/4).
fn random_spans() -> Vec<FragmentSpan> {
    let mut rng = softgl_jit::rng::Rng::new(0x2545_f491);
    let mut next = move || rng.next_u64();
    let mut spans = coherent_spans();
    for s in &mut spans {
        for i in 0..SPAN_MAX {
            let [r, g, b, a, ..] = next().to_le_bytes();
            (s.r[i], s.g[i], s.b[i], s.a[i]) = (r, g, b, a);
            s.z[i] = next() as u32 & 0x00ff_ffff;
        }
        s.mask = next() | next();
    }
    spans
}

fn scenes() -> Vec<Scene> {
    let background: Vec<u8> = (0..SIZE * SIZE)
        .flat_map(|i| [(i / SIZE) as u8, 64, (i % SIZE) as u8, 255])
        .collect();
    let color_only = Buffers {
        color: background.clone(),
        depth: None,
        stencil: None,
    };
    let cleared_depth = vec![0x00ff_ffff; (SIZE * SIZE) as usize];
    let less = DepthKey {
        func: CompareFunc::Less,
        write: true,
    };
    let over = BlendKey::OVER;
    let rgba8 = FragmentKey::new(ColorFormat::Rgba8, None, false);
    // One perspective triangle's planes over the target: colours and the fog
    // coordinate over w, 1/w from 1 to 0.5 across, depth across the D24 range.
    let mut planes = Planes::default();
    planes.set(slot::INV_W, 1.0, -0.5 / SIZE as f32, 0.0);
    for (k, (a0, dx, dy)) in [(1.0, -1.0, 0.5), (0.2, 1.5, 0.0), (0.5, 0.0, 1.0), (1.0, -0.2, -0.2)]
        .into_iter()
        .enumerate()
    {
        planes.set(slot::COLOR + k, a0, dx / SIZE as f32, dy / SIZE as f32);
    }
    for k in 0..3 {
        planes.set(slot::SECONDARY + k, 0.1, 0.1 / SIZE as f32, 0.0);
    }
    planes.set(slot::FOG, 0.5, 4.0 / SIZE as f32, 2.0 / SIZE as f32);
    planes.set(slot::Z, 0.1, 0.4 / SIZE as f32, 0.4 / SIZE as f32);
    let depth_key = FragmentKey {
        depth: Some(less),
        ..FragmentKey::new(ColorFormat::Rgba8, Some(DepthFormat::D24), false)
    };
    let shaded = ShadeKey {
        color: true,
        depth: true,
        ..ShadeKey::default()
    };
    let stencil_buffers = Buffers {
        stencil: Some((0..SIZE * SIZE).map(|i| (i % 3) as u8).collect()),
        ..color_only.clone()
    };
    vec![
        Scene {
            name: "minimal",
            key: rgba8,
            uniforms: FragmentUniforms::default(),
            buffers: color_only.clone(),
            planes: Vec::new(),
        },
        Scene {
            name: "shaded",
            key: FragmentKey {
                shade: Some(shaded),
                ..depth_key
            },
            uniforms: FragmentUniforms::default(),
            buffers: Buffers {
                depth: Some(cleared_depth.clone()),
                ..color_only.clone()
            },
            planes: vec![planes],
        },
        Scene {
            name: "shaded_fog",
            key: FragmentKey {
                shade: Some(ShadeKey {
                    color_sum: true,
                    fog: Some(FogMode::Exp),
                    ..shaded
                }),
                ..depth_key
            },
            uniforms: FragmentUniforms {
                fog: FogUniforms::new(0.0, 1.0, 0.5, [0.5, 0.6, 0.7]),
                ..FragmentUniforms::default()
            },
            buffers: Buffers {
                depth: Some(cleared_depth.clone()),
                ..color_only.clone()
            },
            planes: vec![planes],
        },
        Scene {
            name: "depth_only",
            key: FragmentKey {
                depth: Some(less),
                ..FragmentKey::new(ColorFormat::Rgba8, Some(DepthFormat::D24), false)
            },
            uniforms: FragmentUniforms::default(),
            buffers: Buffers {
                depth: Some(cleared_depth.clone()),
                ..color_only.clone()
            },
            planes: Vec::new(),
        },
        Scene {
            name: "blend_only",
            key: FragmentKey {
                blend: Some(over),
                ..rgba8
            },
            uniforms: FragmentUniforms::default(),
            buffers: color_only.clone(),
            planes: Vec::new(),
        },
        Scene {
            name: "logic_op",
            key: FragmentKey {
                logic_op: Some(LogicOp::Xor),
                ..rgba8
            },
            uniforms: FragmentUniforms::default(),
            buffers: color_only.clone(),
            planes: Vec::new(),
        },
        Scene {
            name: "stencil_only",
            key: FragmentKey {
                stencil: Some(StencilKey {
                    func: CompareFunc::Notequal,
                    fail: StencilOp::Keep,
                    zfail: StencilOp::Keep,
                    zpass: StencilOp::Incr,
                }),
                ..FragmentKey::new(ColorFormat::Rgba8, None, true)
            },
            uniforms: FragmentUniforms {
                stencil_ref: 1,
                ..FragmentUniforms::default()
            },
            buffers: stencil_buffers,
            planes: Vec::new(),
        },
        Scene {
            name: "all_ops",
            key: common::all_ops_key(),
            uniforms: FragmentUniforms {
                scissor: [8, 8, SIZE as i32 - 8, SIZE as i32 - 8],
                alpha_ref: 8,
                ..FragmentUniforms::default()
            },
            buffers: Buffers {
                color: background,
                depth: Some(cleared_depth),
                stencil: Some(vec![0; (SIZE * SIZE) as usize]),
            },
            planes: Vec::new(),
        },
    ]
}

/// Measures `backend` on every scene, one criterion group per scene so back
/// ends sit side by side.
fn bench_backend<B: Backend>(c: &mut Criterion, backend: &B) {
    for (data, spans) in [("coherent", coherent_spans()), ("random", random_spans())] {
        let fragments: u64 = spans.iter().map(|s| u64::from(s.live_mask().count_ones())).sum();
        for scene in scenes() {
            let prepared = backend.prepare(&scene.key);
            let mut group = c.benchmark_group(format!("{}/{data}", scene.name));
            group.throughput(Throughput::Elements(fragments));
            group.bench_function(B::NAME, |b| {
                b.iter_batched_ref(
                    || scene.buffers.clone(),
                    |buffers| {
                        let mut target = buffers.target();
                        backend.run(&prepared, &scene.uniforms, (&spans, &scene.planes), &mut target);
                        black_box(target.color());
                    },
                    BatchSize::LargeInput,
                );
            });
            group.finish();
        }
    }
}

fn interpreter(c: &mut Criterion) {
    bench_backend(c, &Interpreter);
}

fn jit(c: &mut Criterion) {
    bench_backend(c, &Jit);
}

criterion_group! {
    name = benches;
    config = Criterion::default()
        .sample_size(20)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2));
    targets = interpreter, jit
}
criterion_main!(benches);
