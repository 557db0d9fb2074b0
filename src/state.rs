//! GL state that shapes rasterization and the fragment stages, and how it
//! becomes a [`FragmentKey`] and [`FragmentUniforms`] at draw time.

use crate::fog::FogState;
use crate::framebuffer::{float_to_unorm, Framebuffer};
use crate::geometry::varying::VaryingLayout;
use crate::texture::unit::TexCoordName;
use softgl_jit::texture::TexTarget as TextureTarget;
use softgl_jit::{
    BlendFactor, BlendKey, ColorMask, CompareFunc, DepthKey, FragmentKey, FragmentUniforms, LogicOp, StencilKey,
    StencilOp,
};

/// Capabilities for `enable`/`disable`/`is_enabled`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Capability {
    AlphaTest,
    Blend,
    ColorLogicOp,
    CullFace,
    DepthTest,
    Dither,
    PolygonOffsetFill,
    PolygonOffsetLine,
    PolygonOffsetPoint,
    ScissorTest,
    StencilTest,
    /// `GL_FOG`.
    Fog,
    /// `GL_COLOR_SUM`: add the secondary colour to the primary one.
    ColorSum,
    Lighting,
    /// `GL_LINE_STIPPLE`.
    LineStipple,
    /// `GL_POLYGON_STIPPLE`.
    PolygonStipple,
    /// `GL_LIGHTi`, `i < 8`.
    Light(u8),
    ColorMaterial,
    Normalize,
    RescaleNormal,
    /// `GL_CLIP_PLANEi`, `i < 6`.
    ClipPlane(u8),
    /// `GL_TEXTURE_1D`, `2D`, `3D`, `CUBE_MAP` of the active texture unit.
    Texture(TextureTarget),
    /// `GL_TEXTURE_GEN_S` … `Q` of the active texture unit.
    TexGen(TexCoordName),
    /// `GL_MULTISAMPLE` (on by default): per-sample coverage and depth in
    /// a multisampled framebuffer (`multisample.rs`).
    Multisample,
    /// `GL_SAMPLE_COVERAGE`: `glSampleCoverage`'s mask.
    SampleCoverage,
    /// `GL_SAMPLE_ALPHA_TO_COVERAGE` (state only: not applied yet).
    SampleAlphaToCoverage,
    /// `GL_SAMPLE_ALPHA_TO_ONE` (state only: not applied yet).
    SampleAlphaToOne,
}

impl Capability {
    /// Whether the capability names something that exists (a light below
    /// 8, a clip plane below 6).
    pub fn valid(self) -> bool {
        match self {
            Capability::Light(i) => usize::from(i) < crate::lighting::MAX_LIGHTS,
            Capability::ClipPlane(i) => usize::from(i) < crate::lighting::MAX_CLIP_PLANES,
            _ => true,
        }
    }
}

/// The ten GL 1.x primitive modes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PrimitiveMode {
    Points,
    Lines,
    LineStrip,
    LineLoop,
    Triangles,
    TriangleStrip,
    TriangleFan,
    Quads,
    QuadStrip,
    Polygon,
}

impl PrimitiveMode {
    pub const ALL: [PrimitiveMode; 10] = [
        PrimitiveMode::Points,
        PrimitiveMode::Lines,
        PrimitiveMode::LineStrip,
        PrimitiveMode::LineLoop,
        PrimitiveMode::Triangles,
        PrimitiveMode::TriangleStrip,
        PrimitiveMode::TriangleFan,
        PrimitiveMode::Quads,
        PrimitiveMode::QuadStrip,
        PrimitiveMode::Polygon,
    ];
}

/// Polygon faces, for culling and polygon mode.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Face {
    Front,
    Back,
    FrontAndBack,
}

/// Which winding is front-facing (`glFrontFace`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum FrontFace {
    Ccw,
    Cw,
}

/// How polygons are rasterized (`glPolygonMode`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PolygonMode {
    Point,
    Line,
    Fill,
}

/// `glShadeModel`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ShadeModel {
    Flat,
    Smooth,
}

/// Which buffers `clear` clears.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub struct ClearMask {
    pub color: bool,
    pub depth: bool,
    pub stencil: bool,
    /// The accumulation buffer (not in [`ClearMask::ALL`], which is colour, depth and stencil).
    pub accum: bool,
}

impl ClearMask {
    pub const COLOR: ClearMask = ClearMask {
        color: true,
        depth: false,
        stencil: false,
        accum: false,
    };
    pub const DEPTH: ClearMask = ClearMask {
        color: false,
        depth: true,
        stencil: false,
        accum: false,
    };
    pub const STENCIL: ClearMask = ClearMask {
        color: false,
        depth: false,
        stencil: true,
        accum: false,
    };
    pub const ACCUM: ClearMask = ClearMask {
        color: false,
        depth: false,
        stencil: false,
        accum: true,
    };
    pub const ALL: ClearMask = ClearMask {
        color: true,
        depth: true,
        stencil: true,
        accum: false,
    };
}

impl std::ops::BitOr for ClearMask {
    type Output = ClearMask;
    fn bitor(self, o: ClearMask) -> ClearMask {
        ClearMask {
            color: self.color || o.color,
            depth: self.depth || o.depth,
            stencil: self.stencil || o.stencil,
            accum: self.accum || o.accum,
        }
    }
}

/// A window rectangle `x, y, width, height` (viewport, scissor box).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct WindowRect {
    pub x: i32,
    pub y: i32,
    pub width: i32,
    pub height: i32,
}

/// GL's multisample state (GL 1.3 §3.2.1, §4.1.3).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MultisampleState {
    /// `GL_MULTISAMPLE`.
    pub enabled: bool,
    /// `GL_SAMPLE_COVERAGE`, and `glSampleCoverage`'s value (clamped to
    /// `[0, 1]`) and invert flag.
    pub coverage: bool,
    pub coverage_value: f32,
    pub coverage_invert: bool,
    pub alpha_to_coverage: bool,
    pub alpha_to_one: bool,
}

impl Default for MultisampleState {
    /// GL's initial state: multisampling on, coverage 1 not inverted.
    fn default() -> MultisampleState {
        MultisampleState {
            enabled: true,
            coverage: false,
            coverage_value: 1.0,
            coverage_invert: false,
            alpha_to_coverage: false,
            alpha_to_one: false,
        }
    }
}

/// Every piece of state the fragment stages and the rasterizer read.
#[derive(Clone, Debug, PartialEq)]
pub struct RasterState {
    pub alpha_test: bool,
    pub blend: bool,
    pub color_logic_op: bool,
    pub cull: bool,
    pub depth_test: bool,
    pub dither: bool,
    pub offset_fill: bool,
    pub offset_line: bool,
    pub offset_point: bool,
    pub scissor_test: bool,
    pub stencil_test: bool,

    pub alpha_func: CompareFunc,
    pub alpha_ref: f32,
    pub stencil_func: CompareFunc,
    pub stencil_ref: i32,
    pub stencil_value_mask: u32,
    pub stencil_write_mask: u32,
    pub stencil_fail: StencilOp,
    pub stencil_zfail: StencilOp,
    pub stencil_zpass: StencilOp,
    pub depth_func: CompareFunc,
    pub depth_write: bool,
    pub blend_func: BlendKey,
    pub blend_color: [f32; 4],
    pub logic_op: LogicOp,
    pub color_mask: ColorMask,

    pub scissor: WindowRect,
    pub viewport: WindowRect,
    pub depth_range: (f64, f64),
    /// `glClipControl` (`crate::clip_control`).
    pub clip_control: crate::clip_control::ClipControl,
    pub cull_face: Face,
    pub front_face: FrontFace,
    pub polygon_mode_front: PolygonMode,
    pub polygon_mode_back: PolygonMode,
    pub offset_factor: f32,
    pub offset_units: f32,
    pub shade_model: ShadeModel,
    pub point_size: f32,
    /// GL 1.4's `glPointParameter` state.
    pub point_params: PointParams,
    pub line_width: f32,
    /// `GL_LINE_STIPPLE` and `glLineStipple`'s factor (1 to 256) and pattern.
    pub line_stipple: bool,
    pub line_stipple_factor: i32,
    pub line_stipple_pattern: u16,
    /// `GL_POLYGON_STIPPLE` and `glPolygonStipple`'s pattern: row `y mod 32`
    /// of window y (up), its bit 31 column `x mod 32 = 0` (Mesa's `ctx->PolygonStipple`).
    pub polygon_stipple: bool,
    pub polygon_stipple_pattern: [u32; 32],

    pub clear_color: [f32; 4],
    pub clear_depth: f64,
    pub clear_stencil: i32,
    /// `GL_CLAMP_FRAGMENT_COLOR` `GL_TRUE` (`OSMesaColorClamp(GL_TRUE)`): float
    /// colour buffers get clamped colours too; false is GL's `GL_FIXED_ONLY`.
    pub clamp_fragment_color: bool,
    /// `glClearAccum`'s colour, each channel in `[-1, 1]`.
    pub clear_accum: [f32; 4],
    /// `glFog` state with `GL_FOG`.
    pub fog: FogState,
    /// `GL_COLOR_SUM`.
    pub color_sum: bool,
    /// Multisampling: `GL_MULTISAMPLE`, `GL_SAMPLE_*` and `glSampleCoverage`.
    pub multisample: MultisampleState,

    /// Lighting, materials, normals and user clip planes.
    pub lighting: crate::lighting::LightingState,
}

impl RasterState {
    /// GL's initial state for a window of `width` × `height`.
    pub fn new(width: u32, height: u32) -> RasterState {
        let full = WindowRect {
            x: 0,
            y: 0,
            width: width as i32,
            height: height as i32,
        };
        RasterState {
            alpha_test: false,
            blend: false,
            color_logic_op: false,
            cull: false,
            depth_test: false,
            dither: true,
            offset_fill: false,
            offset_line: false,
            offset_point: false,
            scissor_test: false,
            stencil_test: false,
            alpha_func: CompareFunc::Always,
            alpha_ref: 0.0,
            stencil_func: CompareFunc::Always,
            stencil_ref: 0,
            stencil_value_mask: !0,
            stencil_write_mask: !0,
            stencil_fail: StencilOp::Keep,
            stencil_zfail: StencilOp::Keep,
            stencil_zpass: StencilOp::Keep,
            depth_func: CompareFunc::Less,
            depth_write: true,
            blend_func: BlendKey::DEFAULT,
            blend_color: [0.0; 4],
            logic_op: LogicOp::Copy,
            color_mask: ColorMask::ALL,
            scissor: full,
            viewport: full,
            depth_range: (0.0, 1.0),
            clip_control: crate::clip_control::ClipControl::default(),
            cull_face: Face::Back,
            front_face: FrontFace::Ccw,
            polygon_mode_front: PolygonMode::Fill,
            polygon_mode_back: PolygonMode::Fill,
            offset_factor: 0.0,
            offset_units: 0.0,
            shade_model: ShadeModel::Smooth,
            point_size: 1.0,
            point_params: PointParams::DEFAULT,
            line_width: 1.0,
            line_stipple: false,
            line_stipple_factor: 1,
            line_stipple_pattern: 0xFFFF,
            polygon_stipple: false,
            polygon_stipple_pattern: [!0; 32],
            clear_color: [0.0; 4],
            clear_depth: 1.0,
            clear_stencil: 0,
            clear_accum: [0.0; 4],
            clamp_fragment_color: false,
            fog: FogState::default(),
            color_sum: false,
            multisample: MultisampleState::default(),
            lighting: crate::lighting::LightingState::default(),
        }
    }

    /// The enable flag behind `cap` (which must be [`Capability::valid`]);
    /// `None` for the texture capabilities, which are per texture unit
    /// (`crate::texture::unit`).
    pub fn flag_mut(&mut self, cap: Capability) -> Option<&mut bool> {
        Some(match cap {
            Capability::AlphaTest => &mut self.alpha_test,
            Capability::Blend => &mut self.blend,
            Capability::ColorLogicOp => &mut self.color_logic_op,
            Capability::CullFace => &mut self.cull,
            Capability::DepthTest => &mut self.depth_test,
            Capability::Dither => &mut self.dither,
            Capability::PolygonOffsetFill => &mut self.offset_fill,
            Capability::PolygonOffsetLine => &mut self.offset_line,
            Capability::PolygonOffsetPoint => &mut self.offset_point,
            Capability::ScissorTest => &mut self.scissor_test,
            Capability::StencilTest => &mut self.stencil_test,
            Capability::Fog => &mut self.fog.enabled,
            Capability::ColorSum => &mut self.color_sum,
            Capability::Lighting => &mut self.lighting.enabled,
            Capability::LineStipple => &mut self.line_stipple,
            Capability::PolygonStipple => &mut self.polygon_stipple,
            Capability::Light(i) => &mut self.lighting.lights[usize::from(i)].enabled,
            Capability::ColorMaterial => &mut self.lighting.color_material,
            Capability::Normalize => &mut self.lighting.normalize,
            Capability::RescaleNormal => &mut self.lighting.rescale_normal,
            Capability::ClipPlane(i) => &mut self.lighting.clip_enabled[usize::from(i)],
            Capability::Multisample => &mut self.multisample.enabled,
            Capability::SampleCoverage => &mut self.multisample.coverage,
            Capability::SampleAlphaToCoverage => &mut self.multisample.alpha_to_coverage,
            Capability::SampleAlphaToOne => &mut self.multisample.alpha_to_one,
            Capability::Texture(_) | Capability::TexGen(_) => return None,
        })
    }

    /// Whether `cap` is enabled.
    pub fn flag(&self, cap: Capability) -> bool {
        match cap {
            Capability::AlphaTest => self.alpha_test,
            Capability::Blend => self.blend,
            Capability::ColorLogicOp => self.color_logic_op,
            Capability::CullFace => self.cull,
            Capability::DepthTest => self.depth_test,
            Capability::Dither => self.dither,
            Capability::PolygonOffsetFill => self.offset_fill,
            Capability::PolygonOffsetLine => self.offset_line,
            Capability::PolygonOffsetPoint => self.offset_point,
            Capability::ScissorTest => self.scissor_test,
            Capability::StencilTest => self.stencil_test,
            Capability::Fog => self.fog.enabled,
            Capability::ColorSum => self.color_sum,
            Capability::Lighting => self.lighting.enabled,
            Capability::LineStipple => self.line_stipple,
            Capability::PolygonStipple => self.polygon_stipple,
            Capability::Light(i) => self.lighting.lights.get(usize::from(i)).is_some_and(|l| l.enabled),
            Capability::ColorMaterial => self.lighting.color_material,
            Capability::Normalize => self.lighting.normalize,
            Capability::RescaleNormal => self.lighting.rescale_normal,
            Capability::ClipPlane(i) => self.lighting.clip_enabled.get(usize::from(i)) == Some(&true),
            Capability::Multisample => self.multisample.enabled,
            Capability::SampleCoverage => self.multisample.coverage,
            Capability::SampleAlphaToCoverage => self.multisample.alpha_to_coverage,
            Capability::SampleAlphaToOne => self.multisample.alpha_to_one,
            // Per texture unit: the context answers for the active one.
            Capability::Texture(_) | Capability::TexGen(_) => false,
        }
    }

    /// The scissor box clipped against nothing, as `[x0, y0, x1, y1]`.
    fn scissor_box(&self) -> [i32; 4] {
        let s = self.scissor;
        [s.x, s.y, s.x.saturating_add(s.width), s.y.saturating_add(s.height)]
    }

    /// The fragment key for drawing into `fb`: normalized, so stages that cannot
    /// change a pixel (a scissor box covering the framebuffer, tests without
    /// their buffer) are left out. `GL_DITHER` dithers only with `ordered_dither`
    /// (the context's opt-in knob): llvmpipe ignores it and truncates.
    pub fn fragment_key(&self, fb: &Framebuffer, ordered_dither: bool) -> FragmentKey {
        let [x0, y0, x1, y1] = self.scissor_box();
        let scissor_covers = x0 <= 0 && y0 <= 0 && x1 >= fb.width() as i32 && y1 >= fb.height() as i32;
        let key = FragmentKey {
            color_format: fb.color_format(),
            depth_format: fb.depth_format(),
            stencil_buffer: fb.has_stencil(),
            scissor: self.scissor_test && !scissor_covers,
            alpha_test: (self.alpha_test && self.alpha_func != CompareFunc::Always).then_some(self.alpha_func),
            stencil: self.stencil_test.then_some(StencilKey {
                func: self.stencil_func,
                fail: self.stencil_fail,
                zfail: self.stencil_zfail,
                zpass: self.stencil_zpass,
            }),
            depth: self.depth_test.then_some(DepthKey {
                func: self.depth_func,
                write: self.depth_write,
            }),
            blend: (self.blend && self.blend_func != BlendKey::DEFAULT).then_some(self.blend_func),
            dither: self.dither && ordered_dither,
            logic_op: (self.color_logic_op && self.logic_op != LogicOp::Copy).then_some(self.logic_op),
            color_mask: if fb.color_enabled() {
                self.color_mask
            } else {
                ColorMask::NONE
            },
            shade: None,
            count: false,
        };
        key.normalized()
    }

    /// The varyings a draw's vertices carry, from the same state as
    /// [`Self::fragment_key`]: the primary colour when a stage reads the
    /// fragment colour (`reads_color`), with the secondary colour when the
    /// colour sum is on and the fog coordinate when fog is.
    pub fn varying_layout(&self, reads_color: bool) -> VaryingLayout {
        // Lighting adds back colours when two-sided, and a secondary colour
        // (summed, as GL 1.4 §3.9 says) with GL_SEPARATE_SPECULAR_COLOR.
        let l = &self.lighting;
        let two_side = l.enabled && l.two_side;
        let separate = l.enabled && l.color_control == crate::lighting::ColorControl::SeparateSpecular;
        VaryingLayout {
            color: reads_color,
            back_color: reads_color && two_side,
            secondary: reads_color && (self.color_sum || separate),
            back_secondary: reads_color && two_side && separate,
            fog: reads_color && self.fog.enabled,
            // Decided with the textures (`crate::texture::unit`).
            tex: 0,
            // Decided with the draw's vertex inputs (`Context::draw_with`).
            uniform_colors: false,
        }
    }

    /// The values the fragment stages read, in the units they compare in.
    pub fn fragment_uniforms(&self) -> FragmentUniforms {
        FragmentUniforms {
            scissor: self.scissor_box(),
            blend_color: self.blend_color.map(|c| float_to_unorm(c, 255) as u8),
            alpha_ref: float_to_unorm(self.alpha_ref, 255) as u8,
            stencil_ref: self.stencil_ref.clamp(0, 255) as u8,
            stencil_value_mask: self.stencil_value_mask as u8,
            stencil_write_mask: self.stencil_write_mask as u8,
            fog: self.fog.uniforms(),
            deep: softgl_jit::DeepUniforms {
                alpha_ref: self.alpha_ref.to_bits(),
                blend_color: self.blend_color.map(f32::to_bits),
                clamp: u32::from(self.clamp_fragment_color),
            },
        }
    }

    /// The polygon mode for a face.
    pub fn polygon_mode(&self, front: bool) -> PolygonMode {
        if front {
            self.polygon_mode_front
        } else {
            self.polygon_mode_back
        }
    }

    /// Whether a polygon facing this way is culled.
    pub fn culls(&self, front: bool) -> bool {
        self.cull
            && match self.cull_face {
                Face::Front => front,
                Face::Back => !front,
                Face::FrontAndBack => true,
            }
    }
}

/// Blend factors are valid for both source and destination in GL 1.4, except
/// `SRC_ALPHA_SATURATE`, which is a source factor only.
pub fn valid_dst_factor(f: BlendFactor) -> bool {
    f != BlendFactor::SrcAlphaSaturate
}

/// GL 1.4's point parameters (`glPointParameter`): the size bounds, the
/// fade threshold (state only: it acts under multisampling, which Mesa's
/// fixed-function points ignore) and the distance attenuation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointParams {
    pub size_min: f32,
    pub size_max: f32,
    pub fade_threshold: f32,
    /// Constant, linear and quadratic coefficients.
    pub attenuation: [f32; 3],
}

impl PointParams {
    /// GL's initial values; the largest size is llvmpipe's (Mesa sets it to
    /// the larger of `MaxPointSize` and `MaxLineWidth`, `st_context.c`: 255).
    pub const DEFAULT: PointParams = PointParams {
        size_min: 0.0,
        size_max: 255.0,
        fade_threshold: 1.0,
        attenuation: [1.0, 0.0, 0.0],
    };

    /// Whether the size depends on the distance (coefficients other than 1, 0, 0).
    pub fn attenuated(&self) -> bool {
        self.attenuation != [1.0, 0.0, 0.0]
    }

    /// The size a point of `size` is drawn with at eye depth `z_eye`, as
    /// Mesa's fixed-function vertex program makes it
    /// (`ffvertex_prog.c` `build_atten_pointsize`, the bounds of
    /// `STATE_POINT_SIZE_CLAMPED` with llvmpipe's limits 1 and 255):
    /// `size / sqrt(a + b·|z| + c·z²)` within the bounds; without
    /// attenuation the size within the bounds (`st_atom_rasterizer.c`).
    pub fn size(&self, size: f32, z_eye: f32) -> f32 {
        if !self.attenuated() {
            return size.max(self.size_min).min(self.size_max);
        }
        let [a, b, c] = self.attenuation;
        let d = z_eye.abs();
        let f = d * (d * c + b) + a;
        let s = size * (1.0 / f.sqrt());
        s.max(self.size_min.max(1.0)).min(self.size_max.min(255.0))
    }
}
