//! The scenes: deterministic functions over [`Rec`], each with the tolerance
//! softgl must meet against its reference and the reason for it. The
//! reference is llvmpipe, except for scenes with an exact [`Scene::oracle`]
//! (geometry where Mesa's f32 clippers are known to be wrong).

mod combos;
mod fog;
mod framebuffers;
pub mod glu;
mod lighting;
pub mod oracle;
mod pixels;
mod primitives;
mod stages;
mod stiff;
mod texture;
mod timing;

use crate::call::Rec;
use softgl::{ClearMask, ColorFormat, MatrixMode};

/// How far softgl may land from its reference on a scene.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tolerance {
    /// A pixel is "over" when one of its channels differs by more than this.
    pub channel: u8,
    /// Pixels that may differ by 1..=`channel` (a ceiling measured at the
    /// commit that set it; 0 when `channel` is 0).
    pub near: Near,
    /// Pixels over `channel` allowed, as a share of all pixels.
    pub share_over: f64,
    /// Pixels drawn by one renderer and not the other that are allowed.
    pub coverage: usize,
    /// Why the tolerance is what it is.
    pub reason: &'static str,
}

impl Tolerance {
    /// Bit-exact: softgl follows llvmpipe's rules for everything in the scene.
    pub const EXACT: Tolerance = Tolerance {
        channel: 0,
        near: Near::NONE,
        share_over: 0.0,
        coverage: 0,
        reason: "softgl reproduces llvmpipe's rasterization, setup and arithmetic for this scene bit for bit",
    };

    /// Colours 1 LSB off llvmpipe's on at most `test` pixels at the tests'
    /// size and `report` at the report's (measured), none further.
    pub const fn one_lsb(test: usize, report: usize) -> Tolerance {
        Tolerance::lsb(
            test,
            report,
            "Colours may differ by 1 LSB on the pixels counted: softgl's f32 attribute setup does not repeat \
             llvmpipe's step for step (docs/llvmpipe-facts.md 11).",
        )
    }

    /// 1 LSB off on at most `test` pixels at the tests' size and `report`
    /// at the report's (measured), none further, for `reason`.
    pub const fn lsb(test: usize, report: usize, reason: &'static str) -> Tolerance {
        Tolerance {
            channel: 1,
            near: Near { test, report },
            share_over: 0.0,
            coverage: 0,
            reason,
        }
    }

    /// The budget of pixels within `channel` but not equal, at a size.
    pub fn near(&self, full: bool) -> usize {
        if full {
            self.near.report
        } else {
            self.near.test
        }
    }
}

/// A count of pixels at the tests' size and at the report's.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Near {
    pub test: usize,
    pub report: usize,
}

impl Near {
    pub const NONE: Near = Near { test: 0, report: 0 };
}

/// Which part of the pipeline a scene exercises.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Group {
    /// One per-fragment stage alone.
    Stage,
    /// Realistic combinations of stages.
    Combination,
    /// Primitive modes, shading, culling, offset.
    Primitive,
    /// DESIGN.md's stiff and extreme input.
    Stiff,
    /// Large random scenes, for timing.
    Timing,
    /// Fog and the colour sum (issue 11).
    Fog,
    /// Lighting, materials and user clip planes (issue 11).
    Lighting,
    /// Texturing (issue 12).
    Texture,
    /// Framebuffer objects, blits, multisample resolve, occlusion queries (issue 14).
    Framebuffer,
    /// Raster position, bitmaps, pixel rectangles, the accumulation buffer (issue 14).
    Pixels,
}

impl Group {
    /// Every group, in the report's order.
    pub const ALL: [Group; 10] = [
        Group::Stage,
        Group::Combination,
        Group::Primitive,
        Group::Stiff,
        Group::Timing,
        Group::Fog,
        Group::Lighting,
        Group::Texture,
        Group::Framebuffer,
        Group::Pixels,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Group::Stage => "stages alone",
            Group::Combination => "combinations",
            Group::Primitive => "primitives",
            Group::Stiff => "stiff and extreme",
            Group::Timing => "timing",
            Group::Fog => "fog and colour sum",
            Group::Lighting => "lighting and clip planes",
            Group::Texture => "texturing",
            Group::Framebuffer => "framebuffer objects and queries",
            Group::Pixels => "bitmaps and pixel paths",
        }
    }
}

/// The size a scene is rendered at and the work it does.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Size {
    pub w: u32,
    pub h: u32,
    /// The report's size (true) or the tests' small one.
    pub full: bool,
}

impl Size {
    pub fn wf(self) -> f32 {
        self.w as f32
    }
    pub fn hf(self) -> f32 {
        self.h as f32
    }
    /// `n` in the report, `n / 8` (at least 1) in the tests.
    pub fn count(self, n: usize) -> usize {
        if self.full {
            n
        } else {
            (n / 8).max(1)
        }
    }
}

/// A scene: a name, a tolerance, and the calls it makes.
pub struct Scene {
    pub name: &'static str,
    pub group: Group,
    pub tolerance: Tolerance,
    /// The exact image, when the scene has one: then every back end,
    /// llvmpipe too, is compared with it instead of with llvmpipe.
    pub oracle: Option<fn(Size) -> image::RgbaImage>,
    /// Size in the report; the tests use `test_size`.
    pub full_size: (u32, u32),
    pub test_size: (u32, u32),
    /// The colour buffer's format (RGBA8 unless the scene says otherwise).
    pub color: ColorFormat,
    /// Whether the window has an accumulation buffer (OSMesa's 16 bits a channel).
    pub accum: bool,
    build: fn(&mut Rec, Size),
}

/// A scene recorded at one size.
#[derive(Clone, Debug)]
pub struct Recording {
    pub width: u32,
    pub height: u32,
    pub color: ColorFormat,
    /// An accumulation buffer with the window.
    pub accum: bool,
    pub calls: Vec<crate::call::Call>,
}

impl Scene {
    const fn new(name: &'static str, group: Group, tolerance: Tolerance, build: fn(&mut Rec, Size)) -> Scene {
        Scene {
            name,
            group,
            tolerance,
            oracle: None,
            full_size: (256, 256),
            test_size: (96, 96),
            color: ColorFormat::Rgba8,
            accum: false,
            build,
        }
    }

    /// The same scene with an accumulation buffer.
    const fn with_accum(mut self) -> Scene {
        self.accum = true;
        self
    }

    /// The same scene rendered into a `color` buffer.
    const fn in_format(mut self, color: ColorFormat) -> Scene {
        self.color = color;
        self
    }

    const fn with_oracle(mut self, oracle: fn(Size) -> image::RgbaImage) -> Scene {
        self.oracle = Some(oracle);
        self
    }

    /// The size the scene is recorded at.
    pub fn size(&self, full: bool) -> Size {
        let (w, h) = if full { self.full_size } else { self.test_size };
        Size { w, h, full }
    }

    const fn sized(mut self, full: (u32, u32), test: (u32, u32)) -> Scene {
        self.full_size = full;
        self.test_size = test;
        self
    }

    /// The calls of the scene: the common prologue (viewport, a pixel-unit
    /// orthographic projection, clear to transparent black), then the scene.
    pub fn record(&self, full: bool) -> Recording {
        let size = self.size(full);
        let (w, h) = (size.w, size.h);
        let mut r = Rec::default();
        reset_state(&mut r, w, h);
        r.viewport(0, 0, w as i32, h as i32)
            .matrix_mode(MatrixMode::Projection)
            .load_identity()
            .ortho(0.0, w as f64, 0.0, h as f64, -1.0, 1.0)
            .matrix_mode(MatrixMode::Modelview)
            .load_identity()
            .clear_color(0.0, 0.0, 0.0, 0.0)
            .clear(ClearMask::ALL);
        (self.build)(&mut r, size);
        Recording {
            width: w,
            height: h,
            color: self.color,
            accum: self.accum,
            calls: r.calls,
        }
    }
}

/// Sets every piece of state a scene may touch back to GL's defaults, so a
/// frame replayed on the same context starts where the first one did.
fn reset_state(r: &mut Rec, w: u32, h: u32) {
    use crate::call::Call;
    use softgl::{
        BlendEquation, BlendFactor, Capability, CompareFunc, Face, FrontFace, LogicOp, PolygonMode, ShadeModel,
        StencilOp,
    };
    for cap in [
        Capability::AlphaTest,
        Capability::Blend,
        Capability::ColorLogicOp,
        Capability::CullFace,
        Capability::DepthTest,
        Capability::PolygonOffsetFill,
        Capability::PolygonOffsetLine,
        Capability::PolygonOffsetPoint,
        Capability::ScissorTest,
        Capability::StencilTest,
        Capability::Fog,
        Capability::ColorSum,
        Capability::Lighting,
        Capability::ColorMaterial,
        Capability::Normalize,
        Capability::RescaleNormal,
    ]
    .into_iter()
    .chain((0..6).map(Capability::ClipPlane))
    {
        r.disable(cap);
    }
    r.enable(Capability::Dither)
        .call(Call::DepthFunc(CompareFunc::Less))
        .call(Call::DepthMask(true))
        .call(Call::DepthRange(0.0, 1.0))
        .call(Call::ColorMask([true; 4]))
        .call(Call::BlendFunc(BlendFactor::One, BlendFactor::Zero))
        .call(Call::BlendEquation(BlendEquation::Add))
        .call(Call::BlendColor([0.0; 4]))
        .call(Call::LogicOp(LogicOp::Copy))
        .call(Call::StencilFunc(CompareFunc::Always, 0, 0xff))
        .call(Call::StencilOp(StencilOp::Keep, StencilOp::Keep, StencilOp::Keep))
        .call(Call::StencilMask(0xff))
        .call(Call::AlphaFunc(CompareFunc::Always, 0.0))
        .call(Call::ShadeModel(ShadeModel::Smooth))
        .call(Call::FrontFace(FrontFace::Ccw))
        .call(Call::CullFace(Face::Back))
        .call(Call::PolygonMode(Face::FrontAndBack, PolygonMode::Fill))
        .call(Call::PolygonOffset(0.0, 0.0))
        .call(Call::PointSize(1.0))
        .call(Call::LineWidth(1.0))
        .scissor(0, 0, w as i32, h as i32)
        .call(Call::ClearDepth(1.0))
        .call(Call::ClearStencil(0))
        .color(1.0, 1.0, 1.0, 1.0);
}

/// Every scene, in report order.
pub fn all() -> Vec<Scene> {
    let mut v = Vec::new();
    v.extend(stages::scenes());
    v.extend(combos::scenes());
    v.extend(primitives::scenes());
    v.extend(stiff::scenes());
    v.extend(framebuffers::stiff_scenes());
    v.extend(pixels::stiff_scenes());
    v.extend(fog::scenes());
    v.extend(lighting::scenes());
    v.extend(texture::scenes());
    v.extend(framebuffers::scenes());
    v.extend(pixels::scenes());
    v.extend(timing::scenes());
    v
}

/// The scene called `name`.
pub fn by_name(name: &str) -> Option<Scene> {
    all().into_iter().find(|s| s.name == name)
}

/// softgl's xorshift32: the same numbers on every back end and run.
pub use softgl::rng::Rng;

/// A `cols` x `rows` grid of panels over the window, each `[x0, y0, x1, y1]`.
pub fn panels(n: usize, s: Size) -> Vec<[f32; 4]> {
    let cols = (n as f32).sqrt().ceil() as usize;
    let rows = n.div_ceil(cols);
    let (pw, ph) = (s.wf() / cols as f32, s.hf() / rows as f32);
    (0..n)
        .map(|i| {
            let (c, r) = ((i % cols) as f32, (i / cols) as f32);
            [c * pw, r * ph, (c + 1.0) * pw, (r + 1.0) * ph]
        })
        .collect()
}

/// `n` random smooth triangles of about `extent` pixels, random colours,
/// z in `[-1, 1]`, alpha in `alpha`.
pub fn random_triangles(r: &mut Rec, rng: &mut Rng, n: usize, s: Size, extent: f32, alpha: (f32, f32)) {
    r.begin(softgl::PrimitiveMode::Triangles);
    for _ in 0..n {
        let (cx, cy) = (rng.range(-4.0, s.wf() + 4.0), rng.range(-4.0, s.hf() + 4.0));
        for _ in 0..3 {
            let a = rng.range(alpha.0, alpha.1);
            r.color(rng.unit(), rng.unit(), rng.unit(), a);
            r.vertex(
                cx + rng.range(-extent, extent),
                cy + rng.range(-extent, extent),
                rng.range(-1.0, 1.0),
            );
        }
    }
    r.end();
}

/// A smooth gradient background over the whole window (red across x, green up y).
pub fn gradient_background(r: &mut Rec, s: Size) {
    r.begin(softgl::PrimitiveMode::TriangleStrip)
        .color(0.0, 0.0, 0.8, 1.0)
        .vertex(0.0, 0.0, 0.0)
        .color(1.0, 0.0, 0.4, 0.5)
        .vertex(s.wf(), 0.0, 0.0)
        .color(0.0, 1.0, 0.6, 0.25)
        .vertex(0.0, s.hf(), 0.0)
        .color(1.0, 1.0, 0.0, 1.0)
        .vertex(s.wf(), s.hf(), 0.0)
        .end();
}
