//! Native sampling of the paths real programs spend their time in: 2D
//! `Rgba8` textures (every unorm8 base format is stored expanded to RGBA)
//! with equal minification and magnification filters, NEAREST or LINEAR,
//! any mipmap filter, REPEAT or CLAMP_TO_EDGE. These take llvmpipe's 8-bit
//! AoS path; each step is the reference's (`crate::texture::sample_quad`,
//! `lod`, `filter::aos`) operation on four lanes, with x86's conversions
//! (`crate::texture::arith`), so the bits equal the interpreter's.
//!
//! Sizes, texel addresses and λ's values come from the unit's
//! [`UnitView`](crate::callout::UnitView) at run time, never from the key;
//! per lane, since the lanes of a group can lie in quads of different levels.

use super::{mem, Gen, I32X4};
use crate::callout::{LevelView, TexView, UnitView};
use crate::texture::{Filter, MipFilter, SamplerKey, TexTarget, TexUnitKey, TexelFormat, Wrap, MAX_LEVELS};
use cranelift_codegen::ir::condcodes::{FloatCC, IntCC};
use cranelift_codegen::ir::{types, InstBuilder, MemFlagsData, Value};
use std::mem::{offset_of, size_of};

const F32X4: cranelift_codegen::ir::Type = types::F32X4;

/// Whether generated code samples `unit` itself (else it calls the reference).
pub fn native_unit(unit: &TexUnitKey) -> bool {
    let s: &SamplerKey = &unit.sampler;
    s.target == TexTarget::D2
        && s.format == TexelFormat::Rgba8
        && s.compare.is_none()
        && s.min == s.mag
        && s.wrap[..2]
            .iter()
            .all(|w| matches!(w, Wrap::Repeat | Wrap::ClampToEdge))
}

/// A unit's projected coordinates (s, t) at a group's lanes and, when λ is
/// needed, at the top-left, top-right and bottom-left pixels of their quads.
pub(super) struct Projected {
    pub at: [Value; 2],
    pub quad: Option<[[Value; 2]; 3]>,
}

impl Gen<'_> {
    /// Unit `u`'s filtered RGBA (`crate::texture::sample_quad`), `view` the
    /// call's [`TexView`].
    pub(super) fn sample_native(&mut self, u: usize, key: &SamplerKey, view: Value, c: &Projected) -> [Value; 4] {
        let unit = self.b.ins().iadd_imm_u(
            view,
            (offset_of!(TexView<'static>, units) + u * size_of::<UnitView>()) as i64,
        );
        let first = self.unit_i32(unit, offset_of!(UnitView, first));
        let texels = match (key.mip, c.quad) {
            (MipFilter::None, _) | (_, None) => self.fetch_level(unit, key, first, c.at),
            (mip, Some(quad)) => {
                let (ipart, fpart) = self.lambda(unit, mip, quad);
                let last = self.unit_i32(unit, offset_of!(UnitView, last));
                let l0 = self.b.ins().iadd(ipart, first);
                match mip {
                    MipFilter::Nearest => {
                        let l = self.b.ins().smax(l0, first);
                        let l = self.b.ins().smin(l, last);
                        self.fetch_level(unit, key, l, c.at)
                    }
                    _ => {
                        let fpart = fpart.expect("λ's fraction for a linear mipmap filter");
                        let below = self.b.ins().icmp(IntCC::SignedLessThan, l0, first);
                        let above = self.b.ins().icmp(IntCC::SignedGreaterThanOrEqual, l0, last);
                        let one = self.splat(1);
                        let l1 = self.b.ins().iadd(l0, one);
                        let level0 = self.b.ins().bitselect(above, last, l0);
                        let level0 = self.b.ins().bitselect(below, first, level0);
                        let level1 = self.b.ins().bitselect(above, last, l1);
                        let level1 = self.b.ins().bitselect(below, first, level1);
                        let ends = self.b.ins().bor(below, above);
                        // The 8-bit weight `trunc(fpart·256)`, 0 at the chain's ends and
                        // where it is not positive (NaN converts to i32::MIN); 256
                        // (fpart rounded to 1) is 0 as the reference's `as u8` makes it.
                        let k = self.fconst(256.0);
                        let w = self.b.ins().fmul(fpart, k);
                        let w = self.int_lanes(w);
                        let zero = self.splat(0);
                        let w = self.b.ins().smax(w, zero);
                        let ff = self.splat(255);
                        let w = self.b.ins().band(w, ff);
                        let w = self.b.ins().bitselect(ends, zero, w);
                        let c0 = self.fetch_level(unit, key, level0, c.at);
                        let c1 = self.fetch_level(unit, key, level1, c.at);
                        std::array::from_fn(|ch| self.lerp8(w, c0[ch], c1[ch]))
                    }
                }
            }
        };
        let k = self.fconst((1.0f64 / 255.0) as f32);
        texels.map(|v| {
            let f = self.b.ins().fcvt_from_sint(F32X4, v);
            self.b.ins().fmul(f, k)
        })
    }

    /// λ's integer part and (linear mipmap filter) fraction
    /// (`crate::texture::lod::{rho_quad, select}` for two dimensions).
    fn lambda(&mut self, unit: Value, mip: MipFilter, quad: [[Value; 2]; 3]) -> (Value, Option<Value>) {
        let [tl, tr, bl] = quad;
        let size = [0, 1].map(|a| self.unit_f32(unit, offset_of!(UnitView, base_size) + 16 * a));
        let sq = |s: &mut Self, d: Value, size: Value| {
            let v = s.b.ins().fmul(d, size);
            s.b.ins().fmul(v, v)
        };
        let rho = [tr, bl].map(|p| {
            let ds = self.b.ins().fsub(p[0], tl[0]);
            let dt = self.b.ins().fsub(p[1], tl[1]);
            let a = sq(self, ds, size[0]);
            let b = sq(self, dt, size[1]);
            self.b.ins().fadd(a, b)
        });
        let rho = self.maxps(rho[0], rho[1]);
        // fast_log2(ρ²)·0.5 + bias, clamped where the state says so.
        let bits = self.b.ins().bitcast(I32X4, MemFlagsData::new(), rho);
        let e = self.b.ins().ushr_imm_u(bits, 23);
        let ff = self.splat(255);
        let e = self.b.ins().band(e, ff);
        let m = self.splat(0x007f_ffff);
        let mant = self.b.ins().band(bits, m);
        let one_bits = self.splat(0x3f80_0000);
        let mant = self.b.ins().bor(mant, one_bits);
        let mant = self.b.ins().bitcast(F32X4, MemFlagsData::new(), mant);
        let bias128 = self.splat(128);
        let ef = self.b.ins().isub(e, bias128);
        let ef = self.b.ins().fcvt_from_sint(F32X4, ef);
        let log = self.b.ins().fadd(ef, mant);
        let half = self.fconst(0.5);
        let lod = self.b.ins().fmul(log, half);
        let bias = self.unit_f32(unit, offset_of!(UnitView, bias));
        let lod = self.b.ins().fadd(lod, bias);
        let max_lod = self.unit_f32(unit, offset_of!(UnitView, max_lod));
        let clamped = self.minps(lod, max_lod);
        let apply = self.unit_fmask(unit, offset_of!(UnitView, apply_max));
        let lod = self.b.ins().bitselect(apply, clamped, lod);
        let min_lod = self.unit_f32(unit, offset_of!(UnitView, min_lod));
        let clamped = self.maxps(lod, min_lod);
        let apply = self.unit_fmask(unit, offset_of!(UnitView, apply_min));
        let lod = self.b.ins().bitselect(apply, clamped, lod);
        let equal = self.unit_fmask(unit, offset_of!(UnitView, min_max_equal));
        let lod = self.b.ins().bitselect(equal, min_lod, lod);
        match mip {
            MipFilter::Linear => {
                let f = self.b.ins().floor(lod);
                let fpart = self.b.ins().fsub(lod, f);
                (self.int_lanes(f), Some(fpart))
            }
            _ => {
                let r = self.b.ins().nearest(lod);
                let ipart = self.int_lanes(r);
                // No adjustment after log2: `round(log2(√ρ²))` from the exponent
                // (`lod::ilog2_sqrt`: the field minus 126, halved).
                let bias126 = self.splat(126);
                let from_exp = self.b.ins().isub(e, bias126);
                let from_exp = self.b.ins().sshr_imm_u(from_exp, 1);
                let only = self.unit_i32(unit, offset_of!(UnitView, exponent_only));
                let equal = self.unit_i32(unit, offset_of!(UnitView, min_max_equal));
                let not_equal = self.b.ins().band_not(only, equal);
                (self.b.ins().bitselect(not_equal, from_exp, ipart), None)
            }
        }
    }

    /// The RGBA bytes (`i32x4` a channel) of each lane's level `level`,
    /// filtered at `at` (`crate::texture::filter::aos`, two dimensions).
    fn fetch_level(&mut self, unit: Value, key: &SamplerKey, level: Value, at: [Value; 2]) -> [Value; 4] {
        // Each lane's level: its texels and sizes.
        let mut ptrs = [level; 4];
        let mut size = [self.splat(0); 2];
        for (lane, p) in ptrs.iter_mut().enumerate() {
            let l = self.b.ins().extractlane(level, lane as u8);
            // Levels are within `first..=last` < MAX_LEVELS; the mask keeps
            // the address inside the view whatever the lane holds.
            let last = self.b.ins().iconst(types::I32, (MAX_LEVELS - 1) as i64);
            let l = self.b.ins().umin(l, last);
            let l = self.b.ins().uextend(self.ptr, l);
            let off = self.b.ins().imul_imm_u(l, size_of::<LevelView>() as i64);
            let lv = self.b.ins().iadd(unit, off);
            let base = offset_of!(UnitView, levels) as i32;
            *p = self
                .b
                .ins()
                .load(self.ptr, mem(), lv, base + offset_of!(LevelView, texels) as i32);
            for (a, field) in [offset_of!(LevelView, width), offset_of!(LevelView, height)]
                .into_iter()
                .enumerate()
            {
                let v = self.b.ins().load(types::I32, mem(), lv, base + field as i32);
                size[a] = self.b.ins().insertlane(size[a], v, lane as u8);
            }
        }
        let pot = [0, 1].map(|a| self.unit_i32(unit, offset_of!(UnitView, pot) + 16 * a));
        let fetch = |s: &mut Self, x: Value, y: Value| s.fetch(&ptrs, size, x, y);
        match key.min {
            Filter::Nearest => {
                let x = self.nearest_axis(at[0], size[0], pot[0], key.wrap[0]);
                let y = self.nearest_axis(at[1], size[1], pot[1], key.wrap[1]);
                let t = fetch(self, x, y);
                self.channels(t)
            }
            Filter::Linear => {
                let (x0, x1, wx) = self.linear_axis(at[0], size[0], pot[0], key.wrap[0]);
                let (y0, y1, wy) = self.linear_axis(at[1], size[1], pot[1], key.wrap[1]);
                let t = [(x0, y0), (x1, y0), (x0, y1), (x1, y1)].map(|(x, y)| {
                    let t = fetch(self, x, y);
                    self.channels(t)
                });
                std::array::from_fn(|ch| {
                    let row0 = self.lerp8(wx, t[0][ch], t[1][ch]);
                    let row1 = self.lerp8(wx, t[2][ch], t[3][ch]);
                    self.lerp8(wy, row0, row1)
                })
            }
        }
    }

    /// The packed texels at `(x, y)` of each lane's level; coordinates are
    /// clamped to the level (they already are: the clamp only guarantees it).
    fn fetch(&mut self, ptrs: &[Value; 4], size: [Value; 2], x: Value, y: Value) -> Value {
        let one = self.splat(1);
        let wm = self.b.ins().isub(size[0], one);
        let hm = self.b.ins().isub(size[1], one);
        let x = self.b.ins().umin(x, wm);
        let y = self.b.ins().umin(y, hm);
        let row = self.b.ins().imul(y, size[0]);
        let index = self.b.ins().iadd(row, x);
        let mut out = self.splat(0);
        for (lane, &p) in ptrs.iter().enumerate() {
            let i = self.b.ins().extractlane(index, lane as u8);
            let i = self.b.ins().uextend(self.ptr, i);
            let off = self.b.ins().ishl_imm_u(i, 2);
            let addr = self.b.ins().iadd(p, off);
            let t = self.b.ins().load(types::I32, mem(), addr, 0);
            out = self.b.ins().insertlane(out, t, lane as u8);
        }
        out
    }

    /// Packed RGBA8 lanes to four channel lanes.
    fn channels(&mut self, t: Value) -> [Value; 4] {
        let ff = self.splat(255);
        let mut ch = [t; 4];
        for (c, v) in ch.iter_mut().enumerate().take(3) {
            let s = if c == 0 {
                t
            } else {
                self.b.ins().ushr_imm_u(t, 8 * c as i64)
            };
            *v = self.b.ins().band(s, ff);
        }
        ch[3] = self.b.ins().ushr_imm_u(t, 24);
        ch
    }

    /// `a + ((w·(b − a) + 128) >> 8)` (`crate::texture::arith::lerp8`).
    fn lerp8(&mut self, w: Value, a: Value, b: Value) -> Value {
        let d = self.b.ins().isub(b, a);
        let p = self.b.ins().imul(w, d);
        let half = self.splat(128);
        let p = self.b.ins().iadd(p, half);
        let p = self.b.ins().sshr_imm_u(p, 8);
        self.b.ins().iadd(a, p)
    }

    /// The nearest texel along an axis (`filter::aos_nearest_axis`).
    fn nearest_axis(&mut self, s: Value, len: Value, pot: Value, wrap: Wrap) -> Value {
        let lf = self.b.ins().fcvt_from_sint(F32X4, len);
        let one = self.splat(1);
        let len1 = self.b.ins().isub(len, one);
        let v = self.b.ins().fmul(s, lf);
        let v = self.b.ins().floor(v);
        let i = self.int_lanes(v);
        match wrap {
            Wrap::Repeat => {
                let p = self.b.ins().band(i, len1);
                let f = self.b.ins().floor(s);
                let f = self.b.ins().fsub(s, f);
                let max = self.fconst(1.0 - 1.0 / (1u32 << 24) as f32);
                // fract_safe: below the bound, else (and NaN) the bound.
                let f = self.minps(f, max);
                let v = self.b.ins().fmul(f, lf);
                let n = self.int_lanes(v);
                self.b.ins().bitselect(pot, p, n)
            }
            _ => {
                let zero = self.splat(0);
                let i = self.b.ins().smax(i, zero);
                self.b.ins().smin(i, len1)
            }
        }
    }

    /// The two texels and the 8-bit weight of the second along an axis
    /// (`filter::aos_linear_axis`).
    fn linear_axis(&mut self, s: Value, len: Value, pot: Value, wrap: Wrap) -> (Value, Value, Value) {
        let one = self.splat(1);
        let len1 = self.b.ins().isub(len, one);
        let zero = self.splat(0);
        let ff = self.splat(255);
        let m128 = self.splat(-128);
        let scaled = self.b.ins().ishl_imm_u(len, 8);
        let scaled = self.b.ins().fcvt_from_sint(F32X4, scaled);
        let u = self.b.ins().fmul(s, scaled);
        let u = self.b.ins().nearest(u);
        let u = self.int_lanes(u);
        let u = self.b.ins().iadd(u, m128);
        let i = self.b.ins().sshr_imm_u(u, 8);
        let w = self.b.ins().band(u, ff);
        match wrap {
            Wrap::Repeat => {
                let x_pot = self.b.ins().band(i, len1);
                // Not a power of two: from the fraction of s.
                let lf = self.b.ins().fcvt_from_sint(F32X4, len);
                let f = self.b.ins().floor(s);
                let f = self.b.ins().fsub(s, f);
                let v = self.b.ins().fmul(f, lf);
                let k = self.fconst(256.0);
                let v = self.b.ins().fmul(v, k);
                let v = self.b.ins().nearest(v);
                let v = self.int_lanes(v);
                let v = self.b.ins().iadd(v, m128);
                let hi = self.b.ins().sshr_imm_u(v, 8);
                let negative = self.b.ins().icmp(IntCC::SignedLessThan, hi, zero);
                let x_npot = self.b.ins().bitselect(negative, len1, hi);
                let x_npot = self.b.ins().smin(x_npot, len1);
                let w_npot = self.b.ins().band(v, ff);
                let x0 = self.b.ins().bitselect(pot, x_pot, x_npot);
                let w = self.b.ins().bitselect(pot, w, w_npot);
                let last = self.b.ins().icmp(IntCC::Equal, x0, len1);
                let next = self.b.ins().iadd(x0, one);
                let x1 = self.b.ins().bitselect(last, zero, next);
                (x0, x1, w)
            }
            _ => {
                let ge0 = self.b.ins().icmp(IntCC::SignedGreaterThanOrEqual, i, zero);
                let lt = self.b.ins().icmp(IntCC::SignedLessThan, i, len1);
                let x0 = self.b.ins().bitselect(ge0, i, zero);
                let x0 = self.b.ins().bitselect(lt, x0, len1);
                let inside = self.b.ins().band(ge0, lt);
                // The mask is −1 where inside: x1 = x0 + 1 there.
                let x1 = self.b.ins().isub(x0, inside);
                (x0, x1, w)
            }
        }
    }

    /// `minps(a, b)`: `a < b ? a : b`.
    fn minps(&mut self, a: Value, b: Value) -> Value {
        let lt = self.b.ins().fcmp(FloatCC::LessThan, a, b);
        let lt = self.b.ins().bitcast(F32X4, MemFlagsData::new(), lt);
        self.b.ins().bitselect(lt, a, b)
    }

    /// `maxps(a, b)`: `a > b ? a : b`.
    fn maxps(&mut self, a: Value, b: Value) -> Value {
        let gt = self.b.ins().fcmp(FloatCC::GreaterThan, a, b);
        let gt = self.b.ins().bitcast(F32X4, MemFlagsData::new(), gt);
        self.b.ins().bitselect(gt, a, b)
    }

    fn unit_f32(&mut self, unit: Value, off: usize) -> Value {
        self.b.ins().load(F32X4, mem(), unit, off as i32)
    }

    fn unit_i32(&mut self, unit: Value, off: usize) -> Value {
        self.b.ins().load(I32X4, mem(), unit, off as i32)
    }

    /// A mask of the unit view, typed for selecting `f32x4` lanes.
    fn unit_fmask(&mut self, unit: Value, off: usize) -> Value {
        self.unit_f32(unit, off)
    }
}
