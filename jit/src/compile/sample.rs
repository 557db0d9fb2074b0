//! Native sampling of the paths real programs spend their time in: 2D
//! `Rgba8` textures (every unorm8 base format is stored expanded to RGBA)
//! with every minification filter (NEAREST, LINEAR and the four mipmap
//! filters) and magnification filter, REPEAT or CLAMP_TO_EDGE. These take llvmpipe's 8-bit
//! AoS path; each step is the reference's (`crate::texture::sample_quad`,
//! `lod`, `filter::aos`) operation on four lanes, with x86's conversions
//! (`crate::texture::arith`), so the bits equal the interpreter's.
//!
//! Sizes, texel addresses and λ's values come from the unit's
//! [`UnitView`](crate::callout::UnitView) at run time, never from the key;
//! per lane, since the lanes of a group can lie in quads of different levels.

use super::{le, mem, Gen, I32X4};
use crate::callout::{LevelView, TexView, UnitView};
use crate::texture::{Filter, MipFilter, SamplerKey, TexTarget, TexUnitKey, TexelFormat, Wrap, MAX_LEVELS};
use cranelift_codegen::ir::condcodes::{FloatCC, IntCC};
use cranelift_codegen::ir::{types, InstBuilder, MemFlagsData, StackSlotData, StackSlotKind, Value};
use std::mem::{offset_of, size_of};

const F32X4: cranelift_codegen::ir::Type = types::F32X4;

/// The lane scratch of the texel gathers: byte offsets of its arrays (four
/// lanes each).
mod lanes {
    /// Each lane's level (`i32`).
    pub const LEVEL: i32 = 0;
    /// Each lane's level's texels (pointers).
    pub const PTR: i32 = 16;
    pub const WIDTH: i32 = 48;
    pub const HEIGHT: i32 = 64;
    /// Up to four texel byte offsets per lane, one array each (`u32`).
    pub const INDEX: i32 = 80;
    /// The texels fetched there.
    pub const TEXEL: i32 = 144;
    pub const SIZE: u32 = 208;
}

/// Whether generated code samples `unit` itself (else it calls the reference).
pub fn native_unit(unit: &TexUnitKey) -> bool {
    let s: &SamplerKey = &unit.sampler;
    s.target == TexTarget::D2
        && s.format == TexelFormat::Rgba8
        && s.compare.is_none()
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
        let Some(quad) = c.quad else {
            // No λ: one filter, level `first`.
            let texels = self.fetch_level(unit, key, (key.min, first), c.at);
            return self.texels_to_float(texels);
        };
        let (ipart, fpart, minified) = self.lambda(unit, key.mip, quad);
        let last = self.unit_i32(unit, offset_of!(UnitView, last));
        let l0 = self.b.ins().iadd(ipart, first);
        // The levels λ selects (`lod::levels`) and the minification filter there.
        let (level0, min) = match key.mip {
            MipFilter::None => (first, self.fetch_level(unit, key, (key.min, first), c.at)),
            MipFilter::Nearest => {
                let l = self.b.ins().smax(l0, first);
                let l = self.b.ins().smin(l, last);
                (l, self.fetch_level(unit, key, (key.min, l), c.at))
            }
            MipFilter::Linear => {
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
                let c0 = self.fetch_level(unit, key, (key.min, level0), c.at);
                let c1 = self.fetch_level(unit, key, (key.min, level1), c.at);
                (level0, self.lerp_texels(w, c0, c1))
            }
        };
        let texels = if key.min == key.mag {
            // Magnified lanes sample the same filter: the minified path with
            // its mipmap filter is theirs too (`lod::filter`).
            min
        } else {
            // Magnified lanes: the magnification filter at the first level λ
            // selects (the base level, except where ρ is NaN on the
            // exponent-only path: the last).
            let mag = self.fetch_level(unit, key, (key.mag, level0), c.at);
            self.b.ins().bitselect(minified, min, mag)
        };
        self.texels_to_float(texels)
    }

    /// Packed RGBA8 lanes to four float channels (`arith::unorm8_to_float`).
    fn texels_to_float(&mut self, texels: Value) -> [Value; 4] {
        let k = self.fconst((1.0f64 / 255.0) as f32);
        self.channels(texels).map(|v| {
            let f = self.b.ins().fcvt_from_sint(F32X4, v);
            self.b.ins().fmul(f, k)
        })
    }

    /// λ's integer part, (linear mipmap filter) fraction, and the lanes it
    /// minifies (`crate::texture::lod::{rho_quad, select}` for two dimensions).
    fn lambda(&mut self, unit: Value, mip: MipFilter, quad: [[Value; 2]; 3]) -> (Value, Option<Value>, Value) {
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
        let zero = self.fconst(0.0);
        let minified = self.b.ins().fcmp(FloatCC::GreaterThan, lod, zero);
        match mip {
            MipFilter::Linear => {
                let f = self.b.ins().floor(lod);
                let fpart = self.b.ins().fsub(lod, f);
                (self.int_lanes(f), Some(fpart), minified)
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
                let only = self.b.ins().band_not(only, equal);
                // There minified is ρ > 1.
                let one = self.fconst(1.0);
                let above = self.b.ins().fcmp(FloatCC::GreaterThan, rho, one);
                let minified = self.b.ins().bitselect(only, above, minified);
                (self.b.ins().bitselect(only, from_exp, ipart), None, minified)
            }
        }
    }

    /// The packed RGBA8 of each lane's level `level`, filtered with `filter`
    /// at `at` (`crate::texture::filter::aos`, two dimensions).
    fn fetch_level(
        &mut self,
        unit: Value,
        key: &SamplerKey,
        (filter, level): (Filter, Value),
        at: [Value; 2],
    ) -> Value {
        // Each lane's level: its texels and sizes, gathered by a loop over
        // the lanes (one copy of the code: compile time grows with its size).
        let scratch = self.lane_scratch();
        self.b.ins().store(mem(), level, scratch, lanes::LEVEL);
        self.lane_loop(|s, at4, at8| {
            let l = s.b.ins().uload32(mem(), at4, lanes::LEVEL);
            // Levels are within `first..=last` < MAX_LEVELS; the clamp keeps
            // the address inside the view whatever the lane holds.
            let last = s.b.ins().iconst(types::I32, (MAX_LEVELS - 1) as i64);
            let l = s.b.ins().ireduce(types::I32, l);
            let l = s.b.ins().umin(l, last);
            let l = s.b.ins().uextend(s.ptr, l);
            let off = s.b.ins().imul_imm_u(l, size_of::<LevelView>() as i64);
            let lv = s.b.ins().iadd(unit, off);
            let base = offset_of!(UnitView, levels) as i32;
            let p =
                s.b.ins()
                    .load(s.ptr, mem(), lv, base + offset_of!(LevelView, texels) as i32);
            s.b.ins().store(mem(), p, at8, lanes::PTR);
            let w =
                s.b.ins()
                    .load(types::I32, mem(), lv, base + offset_of!(LevelView, width) as i32);
            s.b.ins().store(mem(), w, at4, lanes::WIDTH);
            let h =
                s.b.ins()
                    .load(types::I32, mem(), lv, base + offset_of!(LevelView, height) as i32);
            s.b.ins().store(mem(), h, at4, lanes::HEIGHT);
        });
        let size = [lanes::WIDTH, lanes::HEIGHT].map(|off| self.b.ins().load(I32X4, mem(), scratch, off));
        let pot = [0, 1].map(|a| self.unit_i32(unit, offset_of!(UnitView, pot) + 16 * a));
        let one = self.splat(1);
        // Coordinates are clamped to the level (they already are: the clamp
        // only guarantees it), rows made once.
        let wm = self.b.ins().isub(size[0], one);
        let hm = self.b.ins().isub(size[1], one);
        let column = |s: &mut Self, x: Value| s.b.ins().umin(x, wm);
        let row = |s: &mut Self, y: Value| {
            let y = s.b.ins().umin(y, hm);
            s.b.ins().imul(y, size[0])
        };
        match filter {
            Filter::Nearest => {
                let x = self.nearest_axis(at[0], size[0], pot[0], key.wrap[0]);
                let y = self.nearest_axis(at[1], size[1], pot[1], key.wrap[1]);
                let x = column(self, x);
                let y = row(self, y);
                self.fetch(&[(x, y)])[0]
            }
            Filter::Linear => {
                let (x0, x1, wx) = self.linear_axis(at[0], size[0], pot[0], key.wrap[0]);
                let (y0, y1, wy) = self.linear_axis(at[1], size[1], pot[1], key.wrap[1]);
                let [x0, x1] = [x0, x1].map(|x| column(self, x));
                let [y0, y1] = [y0, y1].map(|y| row(self, y));
                let t = self.fetch(&[(x0, y0), (x1, y0), (x0, y1), (x1, y1)]);
                let r0 = self.lerp_texels(wx, t[0], t[1]);
                let r1 = self.lerp_texels(wx, t[2], t[3]);
                self.lerp_texels(wy, r0, r1)
            }
        }
    }

    /// The packed texels at each `(x, y)`, column and row offset
    /// (`row · width`), of each lane's level (gathered by [`Self::fetch_level`]
    /// into the lane scratch), by a loop over the lanes.
    fn fetch(&mut self, at: &[(Value, Value)]) -> Vec<Value> {
        let scratch = self.lane_scratch();
        for (k, &(x, y)) in at.iter().enumerate() {
            let index = self.b.ins().iadd(y, x);
            let index = self.b.ins().ishl_imm_u(index, 2);
            self.b.ins().store(mem(), index, scratch, lanes::INDEX + 16 * k as i32);
        }
        let n = at.len();
        self.lane_loop(|s, at4, at8| {
            let p = s.b.ins().load(s.ptr, mem(), at8, lanes::PTR);
            for k in 0..n {
                let off = s.b.ins().uload32(mem(), at4, lanes::INDEX + 16 * k as i32);
                let addr = s.b.ins().iadd(p, off);
                let t = s.b.ins().load(types::I32, mem(), addr, 0);
                s.b.ins().store(mem(), t, at4, lanes::TEXEL + 16 * k as i32);
            }
        });
        (0..n)
            .map(|k| self.b.ins().load(I32X4, mem(), scratch, lanes::TEXEL + 16 * k as i32))
            .collect()
    }

    /// Runs `body` once for each of the four lanes, with the addresses of
    /// the lane's 4-byte and 8-byte elements in the lane scratch. Values made
    /// in the body do not dominate what follows: the constant caches are
    /// restored.
    fn lane_loop(&mut self, body: impl FnOnce(&mut Self, Value, Value)) {
        let scratch = self.lane_scratch();
        let saved = (self.consts.clone(), self.fconsts.clone());
        let head = self.b.create_block();
        let lane = self.b.append_block_param(head, self.ptr);
        let work = self.b.create_block();
        let exit = self.b.create_block();
        let zero = self.b.ins().iconst(self.ptr, 0);
        self.b.ins().jump(head, &[zero.into()]);
        self.b.switch_to_block(head);
        let done = self.b.ins().icmp_imm_u(IntCC::UnsignedGreaterThanOrEqual, lane, 4);
        self.b.ins().brif(done, exit, &[], work, &[]);
        self.b.switch_to_block(work);
        let o4 = self.b.ins().ishl_imm_u(lane, 2);
        let at4 = self.b.ins().iadd(scratch, o4);
        let o8 = self.b.ins().ishl_imm_u(lane, 3);
        let at8 = self.b.ins().iadd(scratch, o8);
        body(self, at4, at8);
        let next = self.b.ins().iadd_imm_u(lane, 1);
        self.b.ins().jump(head, &[next.into()]);
        self.b.switch_to_block(exit);
        (self.consts, self.fconsts) = saved;
    }

    /// The address of the function's lane scratch (a stack slot made on first use).
    fn lane_scratch(&mut self) -> Value {
        let slot = match self.lane_slot {
            Some(s) => s,
            None => {
                let data = StackSlotData::new(StackSlotKind::ExplicitSlot, lanes::SIZE, 4);
                let s = self.b.create_sized_stack_slot(data);
                self.lane_slot = Some(s);
                s
            }
        };
        self.b.ins().stack_addr(self.ptr, slot, 0)
    }

    /// The 8-bit lerp of packed RGBA8 lanes `a` to `b` with each lane's
    /// weight `w` (0..=255) in every channel (`arith::lerp8`), as llvmpipe
    /// computes it: on 16-bit lanes, `pmulhrsw(w, (b − a) << 7)` is
    /// `(w·(b − a) + 128) >> 8`.
    fn lerp_texels(&mut self, w: Value, a: Value, b: Value) -> Value {
        let wb = self.b.ins().bitcast(types::I8X16, le(), w);
        let half = |s: &mut Self, v: Value, high: bool| {
            let bytes = s.b.ins().bitcast(types::I8X16, le(), v);
            if high {
                s.b.ins().uwiden_high(bytes)
            } else {
                s.b.ins().uwiden_low(bytes)
            }
        };
        let mut out = [w; 2];
        for (h, o) in out.iter_mut().enumerate() {
            // Lane 2h's weight in its four channels, then lane 2h + 1's (byte
            // 1 of each lane is zero: the weight is below 256).
            let (l0, l1) = (8 * h as u8, 8 * h as u8 + 4);
            let mask = [
                l0,
                l0 + 1,
                l0,
                l0 + 1,
                l0,
                l0 + 1,
                l0,
                l0 + 1,
                l1,
                l1 + 1,
                l1,
                l1 + 1,
                l1,
                l1 + 1,
                l1,
                l1 + 1,
            ];
            let m = self.b.func.dfg.immediates.push(mask.to_vec().into());
            let ws = self.b.ins().shuffle(wb, wb, m);
            let ws = self.b.ins().bitcast(types::I16X8, le(), ws);
            let a16 = half(self, a, h == 1);
            let b16 = half(self, b, h == 1);
            let d = self.b.ins().isub(b16, a16);
            let d = self.b.ins().ishl_imm_u(d, 7);
            let step = self.b.ins().sqmul_round_sat(ws, d);
            *o = self.b.ins().iadd(a16, step);
        }
        let bytes = self.b.ins().unarrow(out[0], out[1]);
        self.b.ins().bitcast(I32X4, le(), bytes)
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
