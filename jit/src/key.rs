//! `FragmentKey`: everything about per-fragment state that changes the *code* of a
//! specialist. Plain `Copy + Eq + Hash` data; values that change often live in
//! [`FragmentUniforms`](crate::FragmentUniforms) instead.

/// Layout of the color buffer, as stored in memory.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ColorFormat {
    /// Bytes R, G, B, A.
    Rgba8,
    /// Bytes B, G, R, A.
    Bgra8,
    /// Bytes R, G, B (no alpha: destination alpha reads as 1).
    Rgb8,
    /// One little-endian `u16`: R in bits 11..16, G in 5..11, B in 0..5 (no alpha).
    Rgb565,
    /// R, G, B, A as native-endian `u16` unorm (OSMesa's `GL_UNSIGNED_SHORT`,
    /// `GL_RGBA16`): a deep format ([`ColorFormat::is_deep`]).
    Rgba16,
    /// R, G, B, A as native-endian `f32` (OSMesa's `GL_FLOAT`, `GL_RGBA32F`):
    /// a deep format.
    Rgba32F,
    /// `GL_RGB16` (and `GL_RGB12`, `GL_RGB10`): laid out as
    /// [`ColorFormat::Rgba16`], alpha not stored (llvmpipe's
    /// `R16G16B16X16_UNORM`): the fourth channel holds 65535, which no
    /// fragment writes (the colour mask drops alpha), so alpha reads 1.
    Rgbx16,
    /// `GL_RGBA16F`: laid out as [`ColorFormat::Rgba32F`], every stored
    /// value a half float (`crate::deep::half_bits`, llvmpipe's conversion:
    /// round toward zero), so every value read is the half's.
    Rgba16F,
    /// `GL_RGB16F`: [`ColorFormat::Rgba16F`] with alpha 1 (as `Rgbx16`).
    Rgbx16F,
    /// `GL_RGB32F`: [`ColorFormat::Rgba32F`] with alpha 1 (as `Rgbx16`).
    Rgbx32F,
}

impl ColorFormat {
    /// Bytes one pixel takes.
    pub const fn bytes_per_pixel(self) -> usize {
        match self {
            ColorFormat::Rgba8 | ColorFormat::Bgra8 => 4,
            ColorFormat::Rgb8 => 3,
            ColorFormat::Rgb565 => 2,
            ColorFormat::Rgba16 | ColorFormat::Rgbx16 => 8,
            ColorFormat::Rgba32F | ColorFormat::Rgbx32F | ColorFormat::Rgba16F | ColorFormat::Rgbx16F => 16,
        }
    }

    /// Whether channels are wider than a byte: no packed 32-bit pixel
    /// (`pixel`), the interpreter's deep path (`deep`) and no specialist.
    pub const fn is_deep(self) -> bool {
        match self {
            ColorFormat::Rgba8 | ColorFormat::Bgra8 | ColorFormat::Rgb8 | ColorFormat::Rgb565 => false,
            ColorFormat::Rgba16
            | ColorFormat::Rgbx16
            | ColorFormat::Rgba16F
            | ColorFormat::Rgbx16F
            | ColorFormat::Rgba32F
            | ColorFormat::Rgbx32F => true,
        }
    }

    /// Whether a deep format stores floats (GL's `GL_FLOAT` component
    /// type: unclamped under `GL_FIXED_ONLY`, blended in f32).
    pub const fn is_float(self) -> bool {
        match self {
            ColorFormat::Rgba16F | ColorFormat::Rgbx16F | ColorFormat::Rgba32F | ColorFormat::Rgbx32F => true,
            ColorFormat::Rgba8
            | ColorFormat::Bgra8
            | ColorFormat::Rgb8
            | ColorFormat::Rgb565
            | ColorFormat::Rgba16
            | ColorFormat::Rgbx16 => false,
        }
    }

    /// Whether a float format's values are half floats (stored as f32).
    pub const fn is_half(self) -> bool {
        matches!(self, ColorFormat::Rgba16F | ColorFormat::Rgbx16F)
    }

    /// Bits a channel stores (`GL_RED_BITS`; alpha is 0 where none is stored).
    pub const fn channel_bits(self, channel: usize) -> u32 {
        match (self, channel) {
            (ColorFormat::Rgb565, 1) => 6,
            (
                ColorFormat::Rgb565
                | ColorFormat::Rgb8
                | ColorFormat::Rgbx16
                | ColorFormat::Rgbx16F
                | ColorFormat::Rgbx32F,
                3,
            ) => 0,
            (ColorFormat::Rgb565, _) => 5,
            (ColorFormat::Rgba8 | ColorFormat::Bgra8 | ColorFormat::Rgb8, _) => 8,
            (ColorFormat::Rgba16 | ColorFormat::Rgbx16 | ColorFormat::Rgba16F | ColorFormat::Rgbx16F, _) => 16,
            (ColorFormat::Rgba32F | ColorFormat::Rgbx32F, _) => 32,
        }
    }

    /// Whether the buffer stores alpha.
    pub const fn has_alpha(self) -> bool {
        match self {
            ColorFormat::Rgba8
            | ColorFormat::Bgra8
            | ColorFormat::Rgba16
            | ColorFormat::Rgba16F
            | ColorFormat::Rgba32F => true,
            ColorFormat::Rgb8
            | ColorFormat::Rgb565
            | ColorFormat::Rgbx16
            | ColorFormat::Rgbx16F
            | ColorFormat::Rgbx32F => false,
        }
    }

    /// Whether converting 8-bit color to this format loses bits (so dithering matters).
    pub const fn is_reduced(self) -> bool {
        match self {
            ColorFormat::Rgba8
            | ColorFormat::Bgra8
            | ColorFormat::Rgb8
            | ColorFormat::Rgba16
            | ColorFormat::Rgbx16
            | ColorFormat::Rgba16F
            | ColorFormat::Rgbx16F
            | ColorFormat::Rgba32F
            | ColorFormat::Rgbx32F => false,
            ColorFormat::Rgb565 => true,
        }
    }
}

/// Layout of the depth buffer: one value per pixel, unsigned normalized.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum DepthFormat {
    /// `u16` per pixel.
    D16,
    /// `u32` per pixel holding a 24-bit value (bits 24..32 are zero).
    D24,
    /// `u32` per pixel, all 32 bits.
    D32,
    /// `u32` per pixel holding the bits of an `f32` in `[0, 1]`
    /// (`GL_DEPTH_COMPONENT32F`), never -0 or NaN: there the unsigned order of
    /// the bits is the order of the floats, so the depth test compares bits.
    D32F,
}

impl DepthFormat {
    /// Number of depth bits.
    pub const fn bits(self) -> u32 {
        match self {
            DepthFormat::D16 => 16,
            DepthFormat::D24 => 24,
            DepthFormat::D32 | DepthFormat::D32F => 32,
        }
    }

    /// Largest storable value: window depth 1.0.
    pub const fn max_value(self) -> u32 {
        match self {
            DepthFormat::D16 => 0xffff,
            DepthFormat::D24 => 0x00ff_ffff,
            DepthFormat::D32 => 0xffff_ffff,
            DepthFormat::D32F => 0x3f80_0000,
        }
    }

    /// Window depth `z` in buffer units: the f32 clamped to `[0, 1]` the
    /// float format stores (llvmpipe's `lp_build_clamp`, `max(z, 0)` then
    /// `min(.., 1)` as SSE's `maxps`/`minps`: NaN and -0 become +0), or the
    /// unorm value rounded to nearest even (`lp_build_clamped_float_to_unsigned_norm`).
    #[inline]
    pub fn from_window(self, z: f32) -> u32 {
        match self {
            DepthFormat::D32F => clamp_float_depth(z).to_bits(),
            f => (crate::shade::saturate(z) * f.max_value() as f32).round_ties_even() as u32,
        }
    }

    /// Whether the format stores floats.
    pub const fn is_float(self) -> bool {
        matches!(self, DepthFormat::D32F)
    }
}

/// `min(max(z, 0), 1)` with SSE's operand order: `max(z, 0)` is `z > 0 ? z : 0`
/// (NaN and -0 give +0), `min(v, 1)` is `v < 1 ? v : 1`.
#[inline]
pub fn clamp_float_depth(z: f32) -> f32 {
    let v = if z > 0.0 { z } else { 0.0 };
    if v < 1.0 {
        v
    } else {
        1.0
    }
}

/// The eight GL comparison functions (alpha, stencil and depth tests).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CompareFunc {
    Never,
    Less,
    Equal,
    Lequal,
    Greater,
    Notequal,
    Gequal,
    Always,
}

impl CompareFunc {
    /// All eight functions, in GL enum order.
    pub const ALL: [CompareFunc; 8] = [
        CompareFunc::Never,
        CompareFunc::Less,
        CompareFunc::Equal,
        CompareFunc::Lequal,
        CompareFunc::Greater,
        CompareFunc::Notequal,
        CompareFunc::Gequal,
        CompareFunc::Always,
    ];

    /// `incoming <func> stored`, the way every GL test reads. On floats the
    /// comparisons are ordered except NOTEQUAL (NaN passes only NOTEQUAL), as
    /// llvmpipe's depth-texture compare (`lp_build_sample_comparefunc`).
    pub fn test<T: PartialOrd>(self, incoming: T, stored: T) -> bool {
        match self {
            CompareFunc::Never => false,
            CompareFunc::Less => incoming < stored,
            CompareFunc::Equal => incoming == stored,
            CompareFunc::Lequal => incoming <= stored,
            CompareFunc::Greater => incoming > stored,
            CompareFunc::Notequal => incoming != stored,
            CompareFunc::Gequal => incoming >= stored,
            CompareFunc::Always => true,
        }
    }
}

/// What a stencil test outcome does to the stored stencil value.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum StencilOp {
    Keep,
    Zero,
    Replace,
    /// Increment, clamped to 255.
    Incr,
    /// Decrement, clamped to 0.
    Decr,
    Invert,
    /// Increment, 255 wraps to 0.
    IncrWrap,
    /// Decrement, 0 wraps to 255.
    DecrWrap,
}

impl StencilOp {
    /// All eight operations.
    pub const ALL: [StencilOp; 8] = [
        StencilOp::Keep,
        StencilOp::Zero,
        StencilOp::Replace,
        StencilOp::Incr,
        StencilOp::Decr,
        StencilOp::Invert,
        StencilOp::IncrWrap,
        StencilOp::DecrWrap,
    ];

    /// The new stencil value before the write mask is applied.
    pub fn apply(self, stored: u8, reference: u8) -> u8 {
        match self {
            StencilOp::Keep => stored,
            StencilOp::Zero => 0,
            StencilOp::Replace => reference,
            StencilOp::Incr => stored.saturating_add(1),
            StencilOp::Decr => stored.saturating_sub(1),
            StencilOp::Invert => !stored,
            StencilOp::IncrWrap => stored.wrapping_add(1),
            StencilOp::DecrWrap => stored.wrapping_sub(1),
        }
    }
}

/// Blend factors of GL 1.4 (with `GL_ARB_imaging`'s constant color).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BlendFactor {
    Zero,
    One,
    SrcColor,
    OneMinusSrcColor,
    DstColor,
    OneMinusDstColor,
    SrcAlpha,
    OneMinusSrcAlpha,
    DstAlpha,
    OneMinusDstAlpha,
    ConstantColor,
    OneMinusConstantColor,
    ConstantAlpha,
    OneMinusConstantAlpha,
    SrcAlphaSaturate,
}

impl BlendFactor {
    /// All fifteen factors.
    pub const ALL: [BlendFactor; 15] = [
        BlendFactor::Zero,
        BlendFactor::One,
        BlendFactor::SrcColor,
        BlendFactor::OneMinusSrcColor,
        BlendFactor::DstColor,
        BlendFactor::OneMinusDstColor,
        BlendFactor::SrcAlpha,
        BlendFactor::OneMinusSrcAlpha,
        BlendFactor::DstAlpha,
        BlendFactor::OneMinusDstAlpha,
        BlendFactor::ConstantColor,
        BlendFactor::OneMinusConstantColor,
        BlendFactor::ConstantAlpha,
        BlendFactor::OneMinusConstantAlpha,
        BlendFactor::SrcAlphaSaturate,
    ];
}

/// Blend equations (GL 1.4 / `GL_EXT_blend_minmax`, `GL_EXT_blend_subtract`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BlendEquation {
    Add,
    Subtract,
    ReverseSubtract,
    Min,
    Max,
}

impl BlendEquation {
    /// All five equations.
    pub const ALL: [BlendEquation; 5] = [
        BlendEquation::Add,
        BlendEquation::Subtract,
        BlendEquation::ReverseSubtract,
        BlendEquation::Min,
        BlendEquation::Max,
    ];
}

/// The sixteen logic operations, `s` the incoming and `d` the stored value.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum LogicOp {
    Clear,
    And,
    AndReverse,
    Copy,
    AndInverted,
    Noop,
    Xor,
    Or,
    Nor,
    Equiv,
    Invert,
    OrReverse,
    CopyInverted,
    OrInverted,
    Nand,
    Set,
}

impl LogicOp {
    /// All sixteen operations, in GL enum order.
    pub const ALL: [LogicOp; 16] = [
        LogicOp::Clear,
        LogicOp::And,
        LogicOp::AndReverse,
        LogicOp::Copy,
        LogicOp::AndInverted,
        LogicOp::Noop,
        LogicOp::Xor,
        LogicOp::Or,
        LogicOp::Nor,
        LogicOp::Equiv,
        LogicOp::Invert,
        LogicOp::OrReverse,
        LogicOp::CopyInverted,
        LogicOp::OrInverted,
        LogicOp::Nand,
        LogicOp::Set,
    ];

    /// The operation on bit patterns.
    pub fn apply(self, s: u32, d: u32) -> u32 {
        match self {
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
}

/// Which color channels are written (`glColorMask`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct ColorMask {
    pub r: bool,
    pub g: bool,
    pub b: bool,
    pub a: bool,
}

impl ColorMask {
    /// Every channel written: GL's default.
    pub const ALL: ColorMask = ColorMask {
        r: true,
        g: true,
        b: true,
        a: true,
    };
    /// No channel written.
    pub const NONE: ColorMask = ColorMask {
        r: false,
        g: false,
        b: false,
        a: false,
    };

    /// The mask whose bits 0–3 say r, g, b, a (tests walk all 16 masks).
    pub fn from_bits(bits: u32) -> ColorMask {
        ColorMask {
            r: bits & 1 != 0,
            g: bits & 2 != 0,
            b: bits & 4 != 0,
            a: bits & 8 != 0,
        }
    }

    /// The mask restricted to the channels `format` stores.
    pub fn for_format(self, format: ColorFormat) -> ColorMask {
        ColorMask {
            a: self.a && format.has_alpha(),
            ..self
        }
    }

    /// Whether no stored channel is written.
    pub fn writes_nothing(self, format: ColorFormat) -> bool {
        let m = self.for_format(format);
        !(m.r || m.g || m.b || m.a)
    }
}

/// The stencil test and its three operations.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct StencilKey {
    pub func: CompareFunc,
    /// Applied when the stencil test fails.
    pub fail: StencilOp,
    /// Applied when the stencil test passes and the depth test fails.
    pub zfail: StencilOp,
    /// Applied when both pass (or the depth test is off).
    pub zpass: StencilOp,
}

/// The depth test and whether it writes (`glDepthMask`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct DepthKey {
    pub func: CompareFunc,
    pub write: bool,
}

/// Separate RGB and alpha blend factors and equations.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct BlendKey {
    pub src_rgb: BlendFactor,
    pub dst_rgb: BlendFactor,
    pub src_alpha: BlendFactor,
    pub dst_alpha: BlendFactor,
    pub eq_rgb: BlendEquation,
    pub eq_alpha: BlendEquation,
}

impl BlendKey {
    /// GL's default state: `ONE, ZERO, FUNC_ADD` for both.
    pub const DEFAULT: BlendKey = BlendKey {
        src_rgb: BlendFactor::One,
        dst_rgb: BlendFactor::Zero,
        src_alpha: BlendFactor::One,
        dst_alpha: BlendFactor::Zero,
        eq_rgb: BlendEquation::Add,
        eq_alpha: BlendEquation::Add,
    };

    /// Transparency: `SRC_ALPHA, ONE_MINUS_SRC_ALPHA, FUNC_ADD` for both.
    pub const OVER: BlendKey = BlendKey {
        src_rgb: BlendFactor::SrcAlpha,
        dst_rgb: BlendFactor::OneMinusSrcAlpha,
        src_alpha: BlendFactor::SrcAlpha,
        dst_alpha: BlendFactor::OneMinusSrcAlpha,
        ..BlendKey::DEFAULT
    };
}

/// The code-shaping part of per-fragment state. Build it with
/// [`FragmentKey::new`] and the `with_*` methods; [`FragmentKey::validate`] says
/// whether a hand-built key is consistent with its buffers.
///
/// Texturing, colour sum and fog are part of the shading stage ([`ShadeKey`]),
/// the first of [`FragmentKey::stages`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct FragmentKey {
    pub color_format: ColorFormat,
    pub depth_format: Option<DepthFormat>,
    pub stencil_buffer: bool,
    pub scissor: bool,
    pub alpha_test: Option<CompareFunc>,
    pub stencil: Option<StencilKey>,
    pub depth: Option<DepthKey>,
    /// Ignored (and dropped by [`FragmentKey::normalized`]) while `logic_op` is on.
    pub blend: Option<BlendKey>,
    /// The ordered (Bayer) dither; off, colour is truncated to the channel's
    /// high bits as llvmpipe does. Only meaningful for formats with fewer than
    /// 8 bits a channel.
    pub dither: bool,
    pub logic_op: Option<LogicOp>,
    pub color_mask: ColorMask,
    /// Colour and depth computed from the primitive's planes; `None`: taken
    /// from the span (`FragmentSpan::r` … `z`).
    pub shade: Option<ShadeKey>,
    /// Count the fragments that pass every test (scissor, alpha, stencil,
    /// depth: GL 1.5 §4.1.7) into the target (`Target::samples_passed`),
    /// for an active occlusion query; off, the stage emits no code.
    pub count: bool,
}

/// The shading stage: which attributes a fragment interpolates from its
/// primitive's [`Planes`](crate::shade::Planes) and what it makes of them
/// (`crate::shade::fragment` is its reference).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct ShadeKey {
    /// The primary colour (perspective-correct unless `flat`); else the
    /// colour is the span's.
    pub color: bool,
    /// The colour planes hold constant values, not values over w.
    pub flat: bool,
    /// Add the secondary colour (`GL_COLOR_SUM`, separate specular).
    pub color_sum: bool,
    /// Fog the colour.
    pub fog: Option<crate::shade::FogMode>,
    /// Depth from the Z plane (16- and 24-bit buffers); else from the span.
    pub depth: bool,
    /// The enabled, complete texture units (all `None`: untextured). Their
    /// environment runs on the primary colour before the colour sum and fog,
    /// so texturing needs `color`.
    pub tex: [Option<crate::texture::TexUnitKey>; crate::texture::MAX_UNITS],
    /// Multisampling's alpha stages for the sample this draw writes.
    pub coverage: AlphaCoverage,
}

/// `GL_SAMPLE_ALPHA_TO_COVERAGE` and `GL_SAMPLE_ALPHA_TO_ONE` (GL 1.5
/// §4.1.3) as llvmpipe runs them (`lp_state_fs.c`, after the alpha test):
/// sample `s` of 4 is kept when the shaded alpha (f32) is above `s/4`
/// (`lp_build_sample_alpha_to_coverage`); a draw with multisampling off in
/// its rasterizer state (bitmaps) keeps the fragment when alpha is above
/// 0.5 (`lp_build_alpha_to_coverage`); then alpha becomes 1. The samples
/// being drawn one scene each, a key holds the one sample's threshold.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct AlphaCoverage {
    /// Kill the fragment unless alpha > `quarters / 4` (`None`: off).
    pub quarters: Option<u8>,
    /// Alpha becomes 1 after the coverage test.
    pub to_one: bool,
}

impl AlphaCoverage {
    /// Whether either stage is on.
    pub fn is_on(&self) -> bool {
        self.quarters.is_some() || self.to_one
    }

    /// The threshold alpha must be above, as llvmpipe makes it
    /// (`step · s` with `step = 1.0 / 4`, exact).
    pub fn threshold(quarters: u8) -> f32 {
        0.25 * f32::from(quarters)
    }

    /// Whether a fragment of alpha `a` is kept at threshold `quarters`
    /// (`a > t`, ordered: NaN is not kept).
    pub fn keeps(a: f32, quarters: u8) -> bool {
        a > Self::threshold(quarters)
    }
}

impl ShadeKey {
    /// Whether any texture unit is on.
    pub fn textured(&self) -> bool {
        self.tex.iter().any(Option::is_some)
    }
}

/// A key that does not fit the buffers it names.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
pub enum KeyError {
    #[error("stencil test on but the key has no stencil buffer")]
    StencilWithoutBuffer,
    #[error("depth test on but the key has no depth buffer")]
    DepthWithoutBuffer,
    #[error("blending and logic op both on: GL skips blending while logic op is on")]
    BlendWithLogicOp,
}

impl FragmentKey {
    /// Every stage off, all channels written: plain color writes into `color_format`.
    pub const fn new(
        color_format: ColorFormat,
        depth_format: Option<DepthFormat>,
        stencil_buffer: bool,
    ) -> FragmentKey {
        FragmentKey {
            color_format,
            depth_format,
            stencil_buffer,
            scissor: false,
            alpha_test: None,
            stencil: None,
            depth: None,
            blend: None,
            dither: false,
            logic_op: None,
            color_mask: ColorMask::ALL,
            shade: None,
            count: false,
        }
    }

    /// The same key with what cannot have an effect dropped, so that keys which
    /// behave the same compare equal: tests without their buffer always pass
    /// (GL 1.5 §4.1.5, §4.1.6), blending is skipped under a logic op (§4.1.10),
    /// dithering 8-bit channels is the identity, and a color mask that writes
    /// nothing makes blend and logic op moot.
    pub fn normalized(mut self) -> FragmentKey {
        if !self.stencil_buffer {
            self.stencil = None;
        }
        if self.depth_format.is_none() {
            self.depth = None;
        }
        if self.logic_op.is_some() {
            self.blend = None;
        }
        if !self.color_format.is_reduced() {
            self.dither = false;
        }
        self.color_mask = self.color_mask.for_format(self.color_format);
        if self.color_mask.writes_nothing(self.color_format) {
            self.blend = None;
            self.logic_op = None;
            self.dither = false;
        }
        self
    }

    /// Whether the key is consistent with the buffers it names.
    pub fn validate(&self) -> Result<(), KeyError> {
        if self.stencil.is_some() && !self.stencil_buffer {
            return Err(KeyError::StencilWithoutBuffer);
        }
        if self.depth.is_some() && self.depth_format.is_none() {
            return Err(KeyError::DepthWithoutBuffer);
        }
        if self.blend.is_some() && self.logic_op.is_some() {
            return Err(KeyError::BlendWithLogicOp);
        }
        Ok(())
    }

    /// The key split in two for a multisampled draw whose samples share
    /// its shading, as llvmpipe runs the fragment shader once a pixel and
    /// the per-sample tests and writes after it: the *shading half*, the
    /// stages up to the alpha test and alpha to one, writing the unorm8
    /// colour into an RGBA8 target and marking the fragments that pass by
    /// writing the stencil reference, 1
    /// ([`FragmentUniforms::shading_half`](crate::FragmentUniforms::shading_half)),
    /// into its stencil (always passing, replacing), and the
    /// *per-sample half*, the stages after them, taking the colour from the
    /// span (and depth from the sample's Z plane when this key takes it
    /// from the planes). Running the first over a primitive's pixels, then
    /// the second over each sample's covered pixels among those marked,
    /// with the colours written, leaves each sample's buffers as this key
    /// leaves them (the contract test `split_keys_equal_the_whole`).
    /// `None` for keys that cannot be split so: no colour from the planes,
    /// a per-sample alpha-to-coverage threshold, a deep format.
    pub fn split_shading(&self) -> Option<(FragmentKey, FragmentKey)> {
        let shade = self.shade.filter(|s| s.color && s.coverage.quarters.is_none())?;
        if self.color_format.is_deep() {
            return None;
        }
        let shading = FragmentKey {
            scissor: self.scissor,
            alpha_test: self.alpha_test,
            stencil: Some(StencilKey {
                func: CompareFunc::Always,
                fail: StencilOp::Keep,
                zfail: StencilOp::Keep,
                zpass: StencilOp::Replace,
            }),
            shade: Some(ShadeKey { depth: false, ..shade }),
            ..FragmentKey::new(ColorFormat::Rgba8, None, true)
        };
        let per_sample = FragmentKey {
            scissor: false,
            alpha_test: None,
            shade: shade.depth.then(|| ShadeKey {
                depth: true,
                ..ShadeKey::default()
            }),
            ..*self
        };
        Some((shading, per_sample))
    }

    /// The stages this key runs, in GL order (GL 1.5 §4.1). A stage that is off
    /// is not in the list.
    pub fn stages(&self) -> Stages {
        let mut s = Stages {
            list: [Stage::Scissor; MAX_STAGES],
            len: 0,
        };
        if let Some(shade) = self.shade {
            s.push(Stage::Shade(shade));
        }
        if self.scissor {
            s.push(Stage::Scissor);
        }
        if let Some(func) = self.alpha_test {
            s.push(Stage::AlphaTest(func));
        }
        if let Some(coverage) = self.shade.map(|s| s.coverage).filter(AlphaCoverage::is_on) {
            s.push(Stage::AlphaCoverage(coverage));
        }
        if let Some(stencil) = self.stencil {
            s.push(Stage::StencilTest {
                stencil,
                depth_on: self.depth.is_some(),
            });
        }
        if let Some(depth) = self.depth {
            s.push(Stage::DepthTest {
                depth,
                stencil: self.stencil,
            });
        }
        if self.count {
            s.push(Stage::Count);
        }
        let mask = self.color_mask.for_format(self.color_format);
        if !mask.writes_nothing(self.color_format) {
            if let (Some(blend), None) = (self.blend, self.logic_op) {
                s.push(Stage::Blend(blend));
            }
            s.push(Stage::Pack {
                dither: self.dither && self.color_format.is_reduced(),
            });
            if let Some(op) = self.logic_op {
                s.push(Stage::LogicOp(op));
            }
            s.push(Stage::ColorWrite(mask));
        }
        s
    }
}

/// Longest possible stage list.
pub const MAX_STAGES: usize = 11;

/// One per-fragment stage with the part of the key it needs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[allow(
    clippy::large_enum_variant,
    reason = "a stage list is built once per draw and read by value; boxing would cost Copy"
)]
pub enum Stage {
    /// Interpolate colour and depth from the planes, texture, colour sum, fog.
    Shade(ShadeKey),
    /// Kill fragments outside the scissor box.
    Scissor,
    /// Kill fragments whose alpha fails `alpha <func> ref`.
    AlphaTest(CompareFunc),
    /// Alpha to coverage (kill unless the f32 alpha is above the sample's
    /// threshold) and alpha to one.
    AlphaCoverage(AlphaCoverage),
    /// Test and apply the `fail` op; with the depth test off, also apply `zpass`.
    StencilTest { stencil: StencilKey, depth_on: bool },
    /// Test, write depth, and apply the stencil `zfail`/`zpass` ops when stencil is on.
    DepthTest {
        depth: DepthKey,
        stencil: Option<StencilKey>,
    },
    /// Count the live fragments (they passed every test) into the target.
    Count,
    /// Blend the fragment color with the stored color.
    Blend(BlendKey),
    /// Convert the 8-bit color to the buffer's format, dithering if asked.
    Pack { dither: bool },
    /// Combine the packed color with the stored one.
    LogicOp(LogicOp),
    /// Store the packed color through the color mask.
    ColorWrite(ColorMask),
}

/// A fixed-capacity list of stages, in order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Stages {
    list: [Stage; MAX_STAGES],
    len: usize,
}

impl Stages {
    fn push(&mut self, stage: Stage) {
        self.list[self.len] = stage;
        self.len += 1;
    }

    /// The stages as a slice.
    pub fn as_slice(&self) -> &[Stage] {
        &self.list[..self.len]
    }
}
