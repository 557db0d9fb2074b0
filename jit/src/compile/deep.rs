//! The deep colour formats (`ColorFormat::Rgba16`, `ColorFormat::Rgba32F`)
//! in generated code, the same operations as the interpreter's
//! `crate::deep::run_span`: the group's colour stays `f32x4` a channel from
//! the planes (or the span's bytes over 255) on; RGBA16 clamps it, converts
//! it with llvmpipe's magic-number rounding and blends in 16-bit unorm in
//! `i32x4` lanes; RGBA32F clamps only when the uniforms say so and blends
//! in f32. The tests, depth and stencil are the 8-bit code's stages.
//!
//! A group's four pixels are 32 (RGBA16) or 64 (RGBA32F) bytes: loaded
//! whole and taken apart into one vector a channel (two byte shuffles and
//! four widenings, or a 4×4 transpose of eight shuffles), put together the
//! same way for the store, the channels the colour mask keeps and the lanes
//! that live selected from the new values, the others stored as they were.

use super::{mem, uniform_offset, Gen, Group, SpanValues, Uniforms, I32X4};
use crate::key::{BlendEquation, BlendFactor, BlendKey, CompareFunc, Stage};
use crate::uniforms::{DeepUniforms, FragmentUniforms};
use cranelift_codegen::ir::condcodes::{FloatCC, IntCC};
use cranelift_codegen::ir::{types, Block, InstBuilder, MemFlagsData, Value};
use std::mem::offset_of;

const F32X4: types::Type = types::F32X4;

/// A group's colour channels as the deep stages carry them.
#[derive(Default)]
struct DeepGroup {
    /// The fragment colour, `f32x4` a channel, once shaded (clamped as the format says).
    rgba: Option<[Value; 4]>,
    /// The values to store (`u16` in `i32` lanes, or f32 bits), once packed or blended.
    out: Option<[Value; 4]>,
    /// The stored channels (as `out`), once loaded.
    dst: Option<[Value; 4]>,
}

/// A deep format's lane arithmetic for [`Gen::factor_lanes`]: its 0 and
/// 1, subtraction and the lesser of two.
#[derive(Clone, Copy)]
struct FactorOps {
    zero: fn(&mut Gen<'_>) -> Value,
    one: fn(&mut Gen<'_>) -> Value,
    sub: fn(&mut Gen<'_>, Value, Value) -> Value,
    min: fn(&mut Gen<'_>, Value, Value) -> Value,
}

/// The offset of a [`DeepUniforms`] field from a specialist's second argument.
const fn deep_offset(field: usize) -> usize {
    uniform_offset(offset_of!(FragmentUniforms, deep) + field)
}

impl Gen<'_> {
    /// The stages of a deep-format key for group `g` (`Gen::stages` hands
    /// these keys here), ending at `next`.
    pub(super) fn deep_stages(&mut self, mut g: Group, sv: &SpanValues, u: &Uniforms, next: Block) {
        let format = self.key.color_format;
        let stages = self.key.stages();
        if let Some(shade) = self.key.shade {
            self.shade_depth(&mut g, sv, &shade);
        }
        let mut d = DeepGroup::default();
        for stage in stages.as_slice() {
            match *stage {
                // The colour is shaded where first read; the scissor is tested once a span (`emit`).
                Stage::Shade(_) | Stage::Scissor => {}
                Stage::AlphaTest(func) => {
                    let c = self.deep_colour(&mut g, sv, &mut d);
                    let r = self.b.ins().load(
                        types::F32,
                        mem(),
                        sv.u,
                        deep_offset(offset_of!(DeepUniforms, alpha_ref)) as i32,
                    );
                    let r = self.b.ins().splat(F32X4, r);
                    let pass = self.fcompare(func, c[3], r);
                    let live = self.live(&mut g);
                    g.live = Some(self.b.ins().band(live, pass));
                    self.skip_if_dead(&g, next);
                }
                Stage::AlphaCoverage(cov) => {
                    let mut c = self.deep_colour(&mut g, sv, &mut d);
                    if let Some(q) = cov.quarters {
                        // Ordered: NaN fails, as `AlphaCoverage::keeps`.
                        let t = self.fconst(crate::key::AlphaCoverage::threshold(q));
                        let pass = self.b.ins().fcmp(FloatCC::GreaterThan, c[3], t);
                        let live = self.live(&mut g);
                        g.live = Some(self.b.ins().band(live, pass));
                        self.skip_if_dead(&g, next);
                    }
                    if cov.to_one {
                        c[3] = self.fconst(1.0);
                        d.rgba = Some(c);
                    }
                }
                Stage::StencilTest { stencil, depth_on } => self.stencil_test(&mut g, (stencil, depth_on), u, next),
                Stage::DepthTest { depth, stencil } => self.depth_test(&mut g, sv, (depth, stencil), u, next),
                Stage::Count => self.count(&mut g, sv),
                Stage::Blend(blend) => {
                    let c = self.deep_colour(&mut g, sv, &mut d);
                    let dst = self.deep_dst(&g, &mut d);
                    let k = self.deep_blend_color(sv, &blend);
                    d.out = Some(if format.is_float() {
                        let dst = dst.map(|v| self.b.ins().bitcast(F32X4, MemFlagsData::new(), v));
                        let out = self.blend_f32_lanes(&blend, c, dst, k);
                        out.map(|v| self.store_value(v))
                    } else {
                        let src = c.map(|v| self.unorm16_lanes(v, true));
                        let k = k.map(|k| k.map(|v| self.unorm16_lanes(v, false)));
                        self.blend16_lanes(&blend, src, dst, k)
                    });
                }
                Stage::Pack { .. } => {
                    if d.out.is_none() {
                        let c = self.deep_colour(&mut g, sv, &mut d);
                        d.out = Some(if format.is_float() {
                            c.map(|v| self.store_value(v))
                        } else {
                            c.map(|v| self.unorm16_lanes(v, true))
                        });
                    }
                }
                Stage::LogicOp(op) => {
                    // On RGBA16's 16-bit channels; GL applies none to floats.
                    if !format.is_float() {
                        let dst = self.deep_dst(&g, &mut d);
                        let s = d.out.expect("Pack precedes LogicOp in every stage list");
                        let low = self.splat(0xffff);
                        d.out = Some(std::array::from_fn(|c| {
                            let v = self.logic_op(op, s[c], dst[c]);
                            self.b.ins().band(v, low)
                        }));
                    }
                }
                Stage::ColorWrite(mask) => {
                    let s = d.out.expect("Pack precedes ColorWrite in every stage list");
                    let keep = [mask.r, mask.g, mask.b, mask.a];
                    if keep == [true; 4] && g.live.is_none() {
                        // No test ran: a group whose four lanes are live
                        // stores its pixels without reading them.
                        let full = self.b.ins().icmp_imm_u(IntCC::Equal, g.bits, 15);
                        let whole = self.b.create_block();
                        let part = self.b.create_block();
                        self.b.ins().brif(full, whole, &[], part, &[]);
                        self.b.switch_to_block(whole);
                        let (consts, fconsts) = (self.consts.len(), self.fconsts.len());
                        self.deep_store(g.color_p, s);
                        self.consts.truncate(consts);
                        self.fconsts.truncate(fconsts);
                        self.b.ins().jump(next, &[]);
                        self.b.switch_to_block(part);
                    }
                    let live = self.live(&mut g);
                    let dst = self.deep_dst(&g, &mut d);
                    let out: [Value; 4] = std::array::from_fn(|c| {
                        if keep[c] {
                            self.select(live, s[c], dst[c])
                        } else {
                            dst[c]
                        }
                    });
                    self.deep_store(g.color_p, out);
                }
            }
        }
        self.b.ins().jump(next, &[]);
    }

    /// The group's fragment colour in f32, made the first time a stage
    /// reads it: from the planes (a key with a shaded colour) or the span's
    /// bytes times `1/255`, clamped as `crate::deep::run_span` clamps it
    /// (RGBA16's is then always in [0, 1]).
    fn deep_colour(&mut self, g: &mut Group, sv: &SpanValues, d: &mut DeepGroup) -> [Value; 4] {
        if let Some(c) = d.rgba {
            return c;
        }
        let mut c = match self.key.shade.filter(|s| s.color) {
            Some(shade) => self.shaded_f32(g, sv, &shade),
            None => {
                let scale = self.fconst(1.0 / 255.0);
                std::array::from_fn(|k| {
                    let v = self.span_channel(sv, g.lane0, k);
                    let v = self.b.ins().fcvt_from_sint(F32X4, v);
                    self.b.ins().fmul(v, scale)
                })
            }
        };
        // The interpreter clamps in its shading stage: keys without one
        // take the span's bytes, already in [0, 1].
        if self.key.shade.is_some() {
            if !self.key.color_format.is_float() {
                c = c.map(|v| self.clamp_colour(v));
            } else {
                // `DeepUniforms::clamp`, as a lane mask.
                let on = self.b.ins().load(
                    types::I32,
                    mem(),
                    sv.u,
                    deep_offset(offset_of!(DeepUniforms, clamp)) as i32,
                );
                let on = self.b.ins().splat(I32X4, on);
                let zero = self.splat(0);
                let on = self.b.ins().icmp(IntCC::NotEqual, on, zero);
                c = c.map(|v| {
                    let clamped = self.clamp_colour(v);
                    self.fselect(on, clamped, v)
                });
            }
        }
        d.rgba = Some(c);
        c
    }

    /// `crate::deep::clamp_colour`: `max(v, 0)` then `min(v, 1)` as x86's
    /// `maxps`/`minps` (NaN and -0 to +0).
    fn clamp_colour(&mut self, v: Value) -> Value {
        let zero = self.fconst(0.0);
        let one = self.fconst(1.0);
        let above = self.b.ins().fcmp(FloatCC::GreaterThan, v, zero);
        let v = self.fselect(above, v, zero);
        let below = self.b.ins().fcmp(FloatCC::LessThan, v, one);
        self.fselect(below, v, one)
    }

    /// `crate::deep::float_bits` on `f32x4` lanes: the bits as `i32x4`, a
    /// NaN lane `CANONICAL_NAN` (two instructions a channel: `cmpunordps`,
    /// `blendvps`; 2.3 instructions a fragment of `FILL_TYPE=float` `fill`,
    /// 936.9 → 1012.6 M for two frames under callgrind; the 8-bit formats
    /// do not run it).
    fn float_bits(&mut self, v: Value) -> Value {
        let nan = self.b.ins().fcmp(FloatCC::Unordered, v, v);
        let bits = self.b.ins().bitcast(I32X4, MemFlagsData::new(), v);
        let canonical = self.splat(i64::from(crate::deep::CANONICAL_NAN));
        self.select(nan, canonical, bits)
    }

    /// `crate::deep::store_value` of a float format on `f32x4` lanes: the
    /// bits to store as `i32x4` ([`Self::float_bits`], or a half's).
    fn store_value(&mut self, v: Value) -> Value {
        if self.key.color_format.is_half() {
            self.half_bits(v)
        } else {
            self.float_bits(v)
        }
    }

    /// `crate::deep::half_bits` on `f32x4` lanes: the mantissa masked to 10
    /// bits, below 2^-14 `trunc(v · 2^24) · 2^-24`, finite magnitudes past
    /// 65504 made ±65504, NaN canonical.
    fn half_bits(&mut self, v: Value) -> Value {
        let flags = MemFlagsData::new();
        let bits = self.float_bits(v);
        let abs_mask = self.splat(0x7fff_ffff);
        let abs = self.b.ins().band(bits, abs_mask);
        let mantissa = self.splat(0xffff_e000u32 as i32 as i64);
        let normal = self.b.ins().band(bits, mantissa);
        let up = self.fconst(16_777_216.0);
        let down = self.fconst(1.0 / 16_777_216.0);
        let scaled = self.b.ins().fmul(v, up);
        let cut = self.b.ins().trunc(scaled);
        let small = self.b.ins().fmul(cut, down);
        let small = self.b.ins().bitcast(I32X4, flags, small);
        let min_normal = self.splat(0x3880_0000);
        let is_small = self.b.ins().icmp(IntCC::SignedLessThan, abs, min_normal);
        let r = self.select(is_small, small, normal);
        let max_half = self.splat(0x477f_e000);
        let inf = self.splat(0x7f80_0000);
        let above = self.b.ins().icmp(IntCC::SignedGreaterThan, abs, max_half);
        let finite = self.b.ins().icmp(IntCC::SignedLessThan, abs, inf);
        let big = self.b.ins().band(above, finite);
        let sign_mask = self.splat(0x8000_0000u32 as i32 as i64);
        let sign = self.b.ins().band(bits, sign_mask);
        let clamped = self.b.ins().bor(sign, max_half);
        self.select(big, clamped, r)
    }

    /// `t` in the lanes of lane mask `mask`, else `f`, of `f32x4` values.
    fn fselect(&mut self, mask: Value, t: Value, f: Value) -> Value {
        let flags = MemFlagsData::new();
        let (ti, fi) = (
            self.b.ins().bitcast(I32X4, flags, t),
            self.b.ins().bitcast(I32X4, flags, f),
        );
        let v = self.select(mask, ti, fi);
        self.b.ins().bitcast(F32X4, flags, v)
    }

    /// Lanes where `incoming <func> reference` holds, on f32 (ordered but
    /// for NOTEQUAL, as `CompareFunc::test`).
    fn fcompare(&mut self, func: CompareFunc, incoming: Value, reference: Value) -> Value {
        let cc = match func {
            CompareFunc::Never => return self.splat(0),
            CompareFunc::Always => return self.splat(-1),
            CompareFunc::Less => FloatCC::LessThan,
            CompareFunc::Equal => FloatCC::Equal,
            CompareFunc::Lequal => FloatCC::LessThanOrEqual,
            CompareFunc::Greater => FloatCC::GreaterThan,
            CompareFunc::Notequal => FloatCC::NotEqual,
            CompareFunc::Gequal => FloatCC::GreaterThanOrEqual,
        };
        self.b.ins().fcmp(cc, incoming, reference)
    }

    /// `crate::deep::unorm16` on f32 lanes: `saturate(c) · (65535/65536) + 128`,
    /// whose low 16 bits are the value. `clamped`: `v` is already
    /// in [0, 1] (no NaN), and `saturate` the identity on it (its `fmax` and
    /// `fmin` are about 20 instructions a channel on x86-64: the `fill`
    /// frame into RGBA16 took twice the time of RGBA32F's with them).
    fn unorm16_lanes(&mut self, v: Value, clamped: bool) -> Value {
        let v = if clamped { v } else { self.saturate(v) };
        let scale = self.fconst((65535.0f64 / 65536.0) as f32);
        let v = self.b.ins().fmul(v, scale);
        let bias = self.fconst(128.0);
        let v = self.b.ins().fadd(v, bias);
        let bits = self.b.ins().bitcast(I32X4, MemFlagsData::new(), v);
        let low = self.splat(0xffff);
        self.b.ins().band(bits, low)
    }

    /// The constant colour as f32 lanes, for blends that read it.
    fn deep_blend_color(&mut self, sv: &SpanValues, blend: &BlendKey) -> Option<[Value; 4]> {
        let reads = [blend.src_rgb, blend.dst_rgb, blend.src_alpha, blend.dst_alpha]
            .into_iter()
            .any(|f| {
                matches!(
                    f,
                    BlendFactor::ConstantColor
                        | BlendFactor::OneMinusConstantColor
                        | BlendFactor::ConstantAlpha
                        | BlendFactor::OneMinusConstantAlpha
                )
            });
        reads.then(|| {
            std::array::from_fn(|c| {
                let off = deep_offset(offset_of!(DeepUniforms, blend_color) + 4 * c);
                let v = self.b.ins().load(types::F32, mem(), sv.u, off as i32);
                self.b.ins().splat(F32X4, v)
            })
        })
    }

    /// `crate::deep::blend16` on `i32` lanes holding 16-bit values.
    fn blend16_lanes(&mut self, key: &BlendKey, src: [Value; 4], dst: [Value; 4], k: Option<[Value; 4]>) -> [Value; 4] {
        let k = k.unwrap_or(src);
        std::array::from_fn(|c| {
            let (sf, df, eq) = crate::deep::channel_blend(key, c);
            let term = |g: &mut Self, x: Value, f: BlendFactor| match f {
                BlendFactor::Zero => g.splat(0),
                // `mul_unorm16(x, 65535) == x` for every 16-bit x.
                BlendFactor::One => x,
                _ => {
                    let f = g.factor16(f, c, (src, dst, k));
                    g.mul_unorm16(x, f)
                }
            };
            match eq {
                BlendEquation::Min => self.b.ins().umin(src[c], dst[c]),
                BlendEquation::Max => self.b.ins().umax(src[c], dst[c]),
                BlendEquation::Add => {
                    let (s, d) = (term(self, src[c], sf), term(self, dst[c], df));
                    let sum = self.b.ins().iadd(s, d);
                    let max = self.splat(0xffff);
                    self.b.ins().umin(sum, max)
                }
                BlendEquation::Subtract | BlendEquation::ReverseSubtract => {
                    let (s, d) = (term(self, src[c], sf), term(self, dst[c], df));
                    let (a, b) = if eq == BlendEquation::Subtract { (s, d) } else { (d, s) };
                    let diff = self.b.ins().isub(a, b);
                    let zero = self.splat(0);
                    self.b.ins().smax(diff, zero)
                }
            }
        })
    }

    /// `interp::factor` in 16-bit unorm, on `i32` lanes.
    fn factor16(&mut self, f: BlendFactor, c: usize, sdk: ([Value; 4], [Value; 4], [Value; 4])) -> Value {
        let ops = FactorOps {
            zero: |g| g.splat(0),
            one: |g| g.splat(0xffff),
            sub: |g, a, b| g.b.ins().isub(a, b),
            min: |g, a, b| g.b.ins().umin(a, b),
        };
        self.factor_lanes(f, c, sdk, ops)
    }

    /// `interp::factor` on lanes of any deep format, with its arithmetic.
    fn factor_lanes(
        &mut self,
        f: BlendFactor,
        c: usize,
        (s, d, k): ([Value; 4], [Value; 4], [Value; 4]),
        ops: FactorOps,
    ) -> Value {
        let inv = |g: &mut Self, v: Value| {
            let one = (ops.one)(g);
            (ops.sub)(g, one, v)
        };
        match f {
            BlendFactor::Zero => (ops.zero)(self),
            BlendFactor::One => (ops.one)(self),
            BlendFactor::SrcColor => s[c],
            BlendFactor::OneMinusSrcColor => inv(self, s[c]),
            BlendFactor::DstColor => d[c],
            BlendFactor::OneMinusDstColor => inv(self, d[c]),
            BlendFactor::SrcAlpha => s[3],
            BlendFactor::OneMinusSrcAlpha => inv(self, s[3]),
            BlendFactor::DstAlpha => d[3],
            BlendFactor::OneMinusDstAlpha => inv(self, d[3]),
            BlendFactor::ConstantColor => k[c],
            BlendFactor::OneMinusConstantColor => inv(self, k[c]),
            BlendFactor::ConstantAlpha => k[3],
            BlendFactor::OneMinusConstantAlpha => inv(self, k[3]),
            BlendFactor::SrcAlphaSaturate => {
                if c == 3 {
                    (ops.one)(self)
                } else {
                    let a = inv(self, d[3]);
                    (ops.min)(self, s[3], a)
                }
            }
        }
    }

    /// `crate::deep::mul_unorm16` on `i32` lanes: `t = a · b` fits in 32
    /// bits, and so does `t + (t >> 16) + 0x8000`.
    fn mul_unorm16(&mut self, a: Value, b: Value) -> Value {
        let t = self.b.ins().imul(a, b);
        let hi = self.b.ins().ushr_imm_u(t, 16);
        let t = self.b.ins().iadd(t, hi);
        let half = self.splat(0x8000);
        let t = self.b.ins().iadd(t, half);
        self.b.ins().ushr_imm_u(t, 16)
    }

    /// `crate::deep::blend_f32` on `f32x4` lanes.
    fn blend_f32_lanes(
        &mut self,
        key: &BlendKey,
        src: [Value; 4],
        dst: [Value; 4],
        k: Option<[Value; 4]>,
    ) -> [Value; 4] {
        let k = k.unwrap_or(src);
        std::array::from_fn(|c| {
            let (sf, df, eq) = crate::deep::channel_blend(key, c);
            let term = |g: &mut Self, x: Value, f: BlendFactor| match f {
                BlendFactor::One => x,
                _ => {
                    let f = g.factor_f32(f, c, (src, dst, k));
                    g.b.ins().fmul(x, f)
                }
            };
            match eq {
                BlendEquation::Min | BlendEquation::Max => {
                    let cc = if eq == BlendEquation::Min {
                        FloatCC::LessThan
                    } else {
                        FloatCC::GreaterThan
                    };
                    let pick = self.b.ins().fcmp(cc, src[c], dst[c]);
                    self.fselect(pick, src[c], dst[c])
                }
                BlendEquation::Add => {
                    let (s, d) = (term(self, src[c], sf), term(self, dst[c], df));
                    self.b.ins().fadd(s, d)
                }
                BlendEquation::Subtract => {
                    let (s, d) = (term(self, src[c], sf), term(self, dst[c], df));
                    self.b.ins().fsub(s, d)
                }
                BlendEquation::ReverseSubtract => {
                    let (s, d) = (term(self, src[c], sf), term(self, dst[c], df));
                    self.b.ins().fsub(d, s)
                }
            }
        })
    }

    /// `interp::factor` in f32 lanes (the saturate's min as `minps`).
    fn factor_f32(&mut self, f: BlendFactor, c: usize, sdk: ([Value; 4], [Value; 4], [Value; 4])) -> Value {
        let ops = FactorOps {
            zero: |g| g.fconst(0.0),
            one: |g| g.fconst(1.0),
            sub: |g, a, b| g.b.ins().fsub(a, b),
            min: |g, a, b| {
                let lt = g.b.ins().fcmp(FloatCC::LessThan, a, b);
                g.fselect(lt, a, b)
            },
        };
        self.factor_lanes(f, c, sdk, ops)
    }

    /// The group's stored channels, loaded and taken apart once.
    fn deep_dst(&mut self, g: &Group, d: &mut DeepGroup) -> [Value; 4] {
        if let Some(v) = d.dst {
            return v;
        }
        let p = g.color_p;
        let v = match self.key.color_format.is_float() {
            false => {
                let v0 = self.b.ins().load(types::I8X16, mem(), p, 0);
                let v1 = self.b.ins().load(types::I8X16, mem(), p, 16);
                let rg = self.shuffle16(v0, v1, RG_OR_PIXELS_01);
                let ba = self.shuffle16(v0, v1, BA_OR_PIXELS_23);
                let rg = self.b.ins().bitcast(types::I16X8, super::le(), rg);
                let ba = self.b.ins().bitcast(types::I16X8, super::le(), ba);
                [
                    self.b.ins().uwiden_low(rg),
                    self.b.ins().uwiden_high(rg),
                    self.b.ins().uwiden_low(ba),
                    self.b.ins().uwiden_high(ba),
                ]
            }
            true => {
                let px: [Value; 4] = std::array::from_fn(|i| self.b.ins().load(I32X4, mem(), p, 16 * i as i32));
                self.transpose(px)
            }
        };
        d.dst = Some(v);
        v
    }

    /// Stores channels `v` (as [`Self::deep_dst`] gives them) as the group's four pixels.
    fn deep_store(&mut self, p: Value, v: [Value; 4]) {
        match self.key.color_format.is_float() {
            false => {
                // The values are 16-bit: the saturating narrowing is exact.
                let rg = self.b.ins().unarrow(v[0], v[1]);
                let ba = self.b.ins().unarrow(v[2], v[3]);
                let rg = self.b.ins().bitcast(types::I8X16, super::le(), rg);
                let ba = self.b.ins().bitcast(types::I8X16, super::le(), ba);
                let p01 = self.shuffle16(rg, ba, RG_OR_PIXELS_01);
                let p23 = self.shuffle16(rg, ba, BA_OR_PIXELS_23);
                self.b.ins().store(mem(), p01, p, 0);
                self.b.ins().store(mem(), p23, p, 16);
            }
            true => {
                let px = self.transpose(v);
                for (i, v) in px.into_iter().enumerate() {
                    self.b.ins().store(mem(), v, p, 16 * i as i32);
                }
            }
        }
    }

    /// The `u16` elements `idx` of `a` then `b` (indices 0–15), as bytes.
    fn shuffle16(&mut self, a: Value, b: Value, idx: [u8; 8]) -> Value {
        let mut mask = [0u8; 16];
        for (i, e) in idx.iter().enumerate() {
            mask[2 * i] = 2 * e;
            mask[2 * i + 1] = 2 * e + 1;
        }
        let m = self.b.func.dfg.immediates.push(mask.to_vec().into());
        self.b.ins().shuffle(a, b, m)
    }

    /// The `u32` lanes `idx` of `a` then `b` (indices 0–7).
    fn shuffle32(&mut self, a: Value, b: Value, idx: [u8; 4]) -> Value {
        let mut mask = [0u8; 16];
        for (i, e) in idx.iter().enumerate() {
            for j in 0..4 {
                mask[4 * i + j] = 4 * e + j as u8;
            }
        }
        let m = self.b.func.dfg.immediates.push(mask.to_vec().into());
        let a = self.b.ins().bitcast(types::I8X16, super::le(), a);
        let b = self.b.ins().bitcast(types::I8X16, super::le(), b);
        let v = self.b.ins().shuffle(a, b, m);
        self.b.ins().bitcast(I32X4, super::le(), v)
    }

    /// The 4×4 transpose of `i32x4` rows: pixels to channels and back.
    fn transpose(&mut self, [p0, p1, p2, p3]: [Value; 4]) -> [Value; 4] {
        let t0 = self.shuffle32(p0, p1, [0, 4, 1, 5]);
        let t1 = self.shuffle32(p2, p3, [0, 4, 1, 5]);
        let t2 = self.shuffle32(p0, p1, [2, 6, 3, 7]);
        let t3 = self.shuffle32(p2, p3, [2, 6, 3, 7]);
        [
            self.shuffle32(t0, t1, [0, 1, 4, 5]),
            self.shuffle32(t0, t1, [2, 3, 6, 7]),
            self.shuffle32(t2, t3, [0, 1, 4, 5]),
            self.shuffle32(t2, t3, [2, 3, 6, 7]),
        ]
    }
}

/// The `u16` elements of two RGBA16 vectors that make the red and green
/// channels of four pixels (`r0..r3 g0..g3`) from the pixels, and pixels 0
/// and 1 from the `rg` and `ba` channel vectors (the shuffle is its own
/// inverse on this layout).
const RG_OR_PIXELS_01: [u8; 8] = [0, 4, 8, 12, 1, 5, 9, 13];
/// Blue and alpha from the pixels, or pixels 2 and 3 from the channels.
const BA_OR_PIXELS_23: [u8; 8] = [2, 6, 10, 14, 3, 7, 11, 15];
