//! Native sampling of the paths real programs spend their time in: 2D
//! and rectangle `Rgba8` textures (every unorm8 base format is stored expanded to RGBA)
//! with every minification filter (NEAREST, LINEAR and the four mipmap
//! filters) and magnification filter, REPEAT or CLAMP_TO_EDGE. These take llvmpipe's 8-bit
//! AoS path; each step is the reference's (`crate::texture::sample_quad`,
//! `lod`, `filter::aos`) operation on four lanes, with x86's conversions
//! (`crate::texture::arith`), so the bits equal the interpreter's.
//!
//! 2D depth textures with NEAREST and no mipmaps (MuJoCo's shadow maps:
//! `GL_COMPARE_R_TO_TEXTURE`, CLAMP_TO_EDGE, projective texgen) take
//! llvmpipe's SoA path here too ([`Gen::sample_depth`]): the nearest texel of
//! the base level, the compare, the depth mode. Through the callout
//! (`crate::callout::texture_group`: coordinates of both quads of a group
//! with libm `fmaf` calls, `QuadSample`, `filter::soa`) a shadowed light pass
//! of `osmesa/bench/shadow_lookup.c` (320×240, 4×) ran 1232 instructions a
//! sample more than the same pass untextured; natively 26 (callgrind).
//!
//! 2D sRGB textures (`Srgba8`: MuJoCo's PNG textures, trilinear REPEAT)
//! take the SoA path natively with every filter, REPEAT or CLAMP_TO_EDGE
//! ([`Gen::soa_levels`]): the λ and levels of the AoS path, each texel's
//! channels decoded to linear f32 (`arith::srgb8_to_linear`'s cubic in
//! fused multiply-adds, vectorized per channel), the f32 weights and lerps
//! of `filter::soa_at`, and the f32 weight between two levels. The same
//! light pass with its checker as `GL_SRGB8` (`shadow_lookup.c srgb`): 1149
//! → 216 instructions a sample, and MuJoCo's `noshadow` frame at 640×480
//! lost its 145 M instructions of callout (three renders; 1.172 G → 1.040 G
//! without the compiles, callgrind).
//!
//! Sizes, texel addresses and λ's values come from the unit's
//! [`UnitView`](crate::callout::UnitView) at run time, never from the key;
//! per lane, since the lanes of a group can lie in quads of different levels.

use super::{le, mem, Gen, Group, SpanValues, I32X4};
use crate::callout::{LevelView, TexView, UnitView};
use crate::key::CompareFunc;
use crate::texture::{DepthMode, Filter, MipFilter, SamplerKey, TexTarget, TexUnitKey, TexelFormat, Wrap, MAX_LEVELS};
use cranelift_codegen::ir::condcodes::{FloatCC, IntCC};
use cranelift_codegen::ir::{types, InstBuilder, MemFlagsData, StackSlot, StackSlotData, StackSlotKind, Type, Value};
use std::mem::{offset_of, size_of};

const F32X4: Type = types::F32X4;

/// Whether generated code samples `unit` itself (else it calls the reference).
pub fn native_unit(unit: &TexUnitKey) -> bool {
    native_sampler(&unit.sampler)
}

/// [`native_unit`] of a unit with sampler `s`.
pub fn native_sampler(s: &SamplerKey) -> bool {
    match s.format {
        TexelFormat::Rgba8 => {
            matches!(s.target, TexTarget::D2 | TexTarget::Rect)
                && s.compare.is_none()
                && s.wrap[..2]
                    .iter()
                    .all(|w| matches!(w, Wrap::Repeat | Wrap::ClampToEdge))
        }
        TexelFormat::Srgba8 => {
            s.target == TexTarget::D2
                && s.compare.is_none()
                && s.wrap[..2]
                    .iter()
                    .all(|w| matches!(w, Wrap::Repeat | Wrap::ClampToEdge))
        }
        TexelFormat::Depth32F => s.target == TexTarget::D2 && native_depth(s),
        TexelFormat::Rgba16 => false,
    }
}

/// The depth textures sampled natively ([`Gen::sample_depth`]): NEAREST
/// without mipmaps (no λ), REPEAT, CLAMP_TO_EDGE or CLAMP (which reads no
/// border with NEAREST), with or without a compare.
fn native_depth(s: &SamplerKey) -> bool {
    s.min == Filter::Nearest
        && s.mag == Filter::Nearest
        && s.mip == MipFilter::None
        && s.wrap[..2]
            .iter()
            .all(|w| matches!(w, Wrap::Repeat | Wrap::ClampToEdge | Wrap::Clamp))
}

/// A unit's projected coordinates (s, t) at a group's lanes and, when λ is
/// needed, at the top-left, top-right and bottom-left pixels of their quads.
pub(super) struct Projected {
    pub at: [Value; 2],
    pub quad: Option<[[Value; 2]; 3]>,
}

impl Projected {
    /// `at`, then the quad's points if any, as one list (2 or 8 values).
    pub fn flat(&self) -> Vec<Value> {
        let mut v = self.at.to_vec();
        for p in self.quad.iter().flatten() {
            v.extend(p);
        }
        v
    }

    /// The inverse of [`Self::flat`].
    pub fn from_flat(v: &[Value]) -> Projected {
        Projected {
            at: [v[0], v[1]],
            quad: (v.len() == 8).then(|| [[v[2], v[3]], [v[4], v[5]], [v[6], v[7]]]),
        }
    }
}

impl Gen<'_> {
    /// Unit `u`'s filtered RGBA (`crate::texture::sample_quad`), `view` the
    /// call's [`TexView`].
    ///
    /// The texels are fetched from one level per level of the filter, the
    /// same for the group's four lanes: one look-up of its address and size
    /// instead of four. A group whose lanes λ puts on different levels (a
    /// line across a primitive where ⌊λ⌋ changes) takes the reference
    /// sampler through the callout instead, on the same coordinates.
    pub(super) fn sample_native(
        &mut self,
        (g, sv): (&Group, &SpanValues),
        (u, key): (usize, &SamplerKey),
        view: Value,
        c: &Projected,
    ) -> [Value; 4] {
        let unit = self.b.ins().iadd_imm_u(
            view,
            (offset_of!(TexView<'static>, units) + u * size_of::<UnitView>()) as i64,
        );
        let first = self.unit_i32(unit, offset_of!(UnitView, first));
        let first_s = self.b.ins().extractlane(first, 0);
        let soa = key.format == TexelFormat::Srgba8;
        let Some(quad) = c.quad else {
            // No λ: one filter, level `first`.
            if soa {
                return self.soa_level(unit, key, (key.min, first_s), c.at);
            }
            let texels = self.fetch_level(unit, key, (key.min, first_s), c.at);
            return self.texels_to_float(texels);
        };
        let (ipart, fpart, minified) = self.lambda(unit, key, quad);
        let last = self.unit_i32(unit, offset_of!(UnitView, last));
        let l0 = self.b.ins().iadd(ipart, first);
        // The levels λ selects (`lod::levels`): each lane's first, and for a
        // linear mipmap filter its second and the 8-bit weight between them.
        let (level0, second) = match key.mip {
            MipFilter::None => (first, None),
            MipFilter::Nearest => {
                let l = self.b.ins().smax(l0, first);
                (self.b.ins().smin(l, last), None)
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
                if soa {
                    // The f32 weight, 0 at the chain's ends (`lod::levels`).
                    let ends = self.b.ins().bitcast(F32X4, MemFlagsData::new(), ends);
                    let zero = self.fconst(0.0);
                    let w = self.b.ins().bitselect(ends, zero, fpart);
                    (level0, Some((level1, w)))
                } else {
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
                    (level0, Some((level1, w)))
                }
            }
        };
        let level0_s = self.b.ins().extractlane(level0, 0);
        let fetch = |s: &mut Self| {
            if soa {
                return s.soa_levels(unit, key, (level0_s, second, minified), c.at);
            }
            let min = match second {
                None => s.fetch_level(unit, key, (key.min, level0_s), c.at),
                Some((level1, w)) => {
                    // Both levels' texels stay widened for the lerp between them.
                    let level1_s = s.b.ins().extractlane(level1, 0);
                    let c0 = s.fetch_level_wide(unit, key, (key.min, level0_s), c.at);
                    let c1 = s.fetch_level_wide(unit, key, (key.min, level1_s), c.at);
                    let w = s.wide_weight(w);
                    let r = s.lerp_wide(w, c0, c1);
                    s.narrow(r)
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
                let mag = s.fetch_level(unit, key, (key.mag, level0_s), c.at);
                s.b.ins().bitselect(minified, min, mag)
            };
            s.texels_to_float(texels)
        };
        if key.mip == MipFilter::None {
            // Every lane on level `first`.
            return fetch(self);
        }
        // One level (or pair of levels) for the group? (The second does not
        // follow from the first: a lane λ puts below the chain reads the
        // first level twice, its neighbour on the first level the first and
        // the second.)
        let same = self.b.ins().splat(I32X4, level0_s);
        let mut same = self.b.ins().icmp(IntCC::Equal, level0, same);
        if let Some((level1, _)) = second {
            let l1 = self.b.ins().extractlane(level1, 0);
            let l1 = self.b.ins().splat(I32X4, l1);
            let same1 = self.b.ins().icmp(IntCC::Equal, level1, l1);
            same = self.b.ins().band(same, same1);
        }
        let same = self.b.ins().vall_true(same);
        let (fast, slow, done) = (self.b.create_block(), self.b.create_block(), self.b.create_block());
        let out: [Value; 4] = std::array::from_fn(|_| self.b.append_block_param(done, F32X4));
        self.b.ins().brif(same, fast, &[], slow, &[]);
        // Constants made in one branch do not reach the other or the join.
        let consts = (self.consts.clone(), self.fconsts.clone());
        self.b.switch_to_block(fast);
        let rgba = fetch(self);
        self.b.ins().jump(done, &rgba.map(Into::into));
        (self.consts, self.fconsts) = consts.clone();
        self.b.switch_to_block(slow);
        let rgba = self.sample_called(g, sv, u, view);
        self.b.ins().jump(done, &rgba.map(Into::into));
        (self.consts, self.fconsts) = consts;
        self.b.switch_to_block(done);
        out
    }

    /// Depth unit `u`'s sample (`crate::texture::QuadSample::lane` on
    /// llvmpipe's SoA path for a [`native_depth`] sampler) at the lanes'
    /// projected `[s, t, r]`: the nearest texel of level `first` (no λ),
    /// compared with the reference r (clamped to [0, 1] unless the texture
    /// is float depth, the key's `statics.float_depth`) if the key compares,
    /// through `GL_DEPTH_TEXTURE_MODE`. A level of 24-bit depth-test units
    /// (`statics.depth_units`) converts each unit as the reference does.
    pub(super) fn sample_depth(
        &mut self,
        u: usize,
        key: &SamplerKey,
        view: Value,
        [s, t, r]: [Value; 3],
    ) -> [Value; 4] {
        let unit = self.b.ins().iadd_imm_u(
            view,
            (offset_of!(TexView<'static>, units) + u * size_of::<UnitView>()) as i64,
        );
        // Level `first`'s texels (`first` < MAX_LEVELS: the clamp only
        // guarantees it) and size, the base side.
        let first = self
            .b
            .ins()
            .load(types::I32, mem(), unit, offset_of!(UnitView, first) as i32);
        let top = self.b.ins().iconst(types::I32, (MAX_LEVELS - 1) as i64);
        let l = self.b.ins().umin(first, top);
        let l = self.b.ins().uextend(self.ptr, l);
        let off = self.b.ins().imul_imm_u(l, size_of::<LevelView>() as i64);
        let lv = self.b.ins().iadd(unit, off);
        let base = offset_of!(UnitView, levels) + offset_of!(LevelView, texels);
        let texels = self.b.ins().load(self.ptr, mem(), lv, base as i32);
        let size = [0, 1].map(|a| self.unit_i32(unit, offset_of!(UnitView, base_side) + 16 * a));
        let pot = key.statics.pot;
        let x = self.depth_axis(s, size[0], pot[0], key.wrap[0]);
        let y = self.depth_axis(t, size[1], pot[1], key.wrap[1]);
        let row = self.b.ins().imul(y, size[0]);
        let index = self.b.ins().iadd(row, x);
        let d = self.gather_f32(texels, index);
        // 24-bit depth-test units (`DepthUnits::texel`): `(z & 0x7fffffff)`
        // through i32 (`cvtdq2ps`), times `f32(1/(2^24 − 1))`.
        let d = if key.statics.depth_units {
            let z = self.b.ins().bitcast(types::I32X4, MemFlagsData::new(), d);
            let mask = self.splat(0x7fff_ffff);
            let z = self.b.ins().band(z, mask);
            let z = self.b.ins().fcvt_from_sint(F32X4, z);
            let scale = self.fconst(crate::texture::UNORM24_SCALE);
            self.b.ins().fmul(z, scale)
        } else {
            d
        };
        let x = match key.compare {
            None => d,
            Some(func) => {
                let reference = if key.statics.float_depth {
                    r
                } else {
                    let (zero, one) = (self.fconst(0.0), self.fconst(1.0));
                    let v = self.maxps(r, zero);
                    self.minps(v, one)
                };
                // `func.test(reference, texel)`: ordered comparisons except
                // NOTEQUAL (Cranelift's `ne` holds for unordered operands), 1.0
                // where it passes, else +0.0.
                let cc = match func {
                    CompareFunc::Never => None,
                    CompareFunc::Always => Some(None),
                    CompareFunc::Less => Some(Some(FloatCC::LessThan)),
                    CompareFunc::Lequal => Some(Some(FloatCC::LessThanOrEqual)),
                    CompareFunc::Greater => Some(Some(FloatCC::GreaterThan)),
                    CompareFunc::Gequal => Some(Some(FloatCC::GreaterThanOrEqual)),
                    CompareFunc::Equal => Some(Some(FloatCC::Equal)),
                    CompareFunc::Notequal => Some(Some(FloatCC::NotEqual)),
                };
                match cc {
                    None => self.fconst(0.0),
                    Some(None) => self.fconst(1.0),
                    Some(Some(cc)) => {
                        let pass = self.b.ins().fcmp(cc, reference, d);
                        let one = self.splat(1.0f32.to_bits() as i64);
                        let v = self.b.ins().band(pass, one);
                        self.b.ins().bitcast(F32X4, MemFlagsData::new(), v)
                    }
                }
            }
        };
        // `GL_DEPTH_TEXTURE_MODE` (`sample::depth_swizzle`).
        match key.depth_mode {
            DepthMode::Luminance => {
                let one = self.fconst(1.0);
                [x, x, x, one]
            }
            DepthMode::Intensity => [x; 4],
            DepthMode::Alpha => {
                let zero = self.fconst(0.0);
                [zero, zero, zero, x]
            }
        }
    }

    /// The nearest texel along an axis of length `len` on the SoA path
    /// (`filter::soa_nearest_axis` for REPEAT, CLAMP_TO_EDGE and CLAMP),
    /// within `0..len` whatever the lane held; `pot` as in [`Self::nearest_axis`].
    fn depth_axis(&mut self, s: Value, len: Value, pot: bool, wrap: Wrap) -> Value {
        let one = self.splat(1);
        let len1 = self.b.ins().isub(len, one);
        let lf = self.b.ins().fcvt_from_sint(F32X4, len);
        match wrap {
            Wrap::Repeat => {
                let i = self.repeat_index(s, lf, len1, pot);
                // Other sizes: already below `len` but for NaN (the clamp
                // keeps the address inside).
                if pot {
                    i
                } else {
                    self.b.ins().umin(i, len1)
                }
            }
            _ => {
                let v = self.b.ins().fmul(s, lf);
                let i = self.int_lanes(v);
                let zero = self.splat(0);
                let i = self.b.ins().smax(i, zero);
                self.b.ins().smin(i, len1)
            }
        }
    }

    /// The `f32` texels at `index` (per lane) of `texels`: four loads
    /// through the gather slot, as [`Self::fetch`] makes them.
    fn gather_f32(&mut self, texels: Value, index: Value) -> Value {
        let slot = self.gather_slot();
        let base = self.b.ins().stack_addr(self.ptr, slot, 0);
        self.b.ins().store(mem(), index, base, 0);
        self.load_lanes(texels, base, 0, F32X4)
    }

    /// The 4-byte texels of `texels` at the four offsets stored at
    /// `base + at` (in texels), one load each into a vector of type `ty`
    /// (see [`Self::gather`]).
    fn load_lanes(&mut self, texels: Value, base: Value, at: i32, ty: Type) -> Value {
        let mut v = None;
        for lane in 0..4u8 {
            let off = self.b.ins().uload32(mem(), base, at + 4 * i32::from(lane));
            let off = if self.ptr == types::I64 {
                off
            } else {
                self.b.ins().ireduce(self.ptr, off)
            };
            // The ×4 of the texel size goes into the address.
            let off = self.b.ins().ishl_imm_u(off, 2);
            let addr = self.b.ins().iadd(texels, off);
            let t = self.b.ins().load(ty.lane_type(), mem(), addr, 0);
            v = Some(match v {
                None => self.b.ins().scalar_to_vector(ty, t),
                Some(v) => self.b.ins().insertlane(v, t, lane),
            });
        }
        v.expect("four lanes")
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
    /// minifies (`crate::texture::lod::{rho_quad, select}` for two
    /// dimensions), with the adjustments the key's statics compile in.
    fn lambda(&mut self, unit: Value, key: &SamplerKey, quad: [[Value; 2]; 3]) -> (Value, Option<Value>, Value) {
        let st = key.statics;
        let lod = if st.min_max_equal {
            // λ is GL_TEXTURE_MIN_LOD: ρ is not needed.
            self.unit_f32(unit, offset_of!(UnitView, min_lod))
        } else {
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
            let bits = self.b.ins().bitcast(I32X4, MemFlagsData::new(), rho);
            let e = self.b.ins().ushr_imm_u(bits, 23);
            let ff = self.splat(255);
            let e = self.b.ins().band(e, ff);
            if st.exponent_only(key.mip) {
                // No adjustment after log2: `round(log2(√ρ²))` from the exponent
                // (`lod::ilog2_sqrt`: the field minus 126, halved), minified
                // where ρ > 1.
                let bias126 = self.splat(126);
                let from_exp = self.b.ins().isub(e, bias126);
                let ipart = self.b.ins().sshr_imm_u(from_exp, 1);
                let one = self.fconst(1.0);
                let minified = self.b.ins().fcmp(FloatCC::GreaterThan, rho, one);
                return (ipart, None, minified);
            }
            // fast_log2(ρ²)·0.5, plus the bias and clamps the statics say.
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
            let mut lod = self.b.ins().fmul(log, half);
            if st.bias_non_zero {
                let bias = self.unit_f32(unit, offset_of!(UnitView, bias));
                lod = self.b.ins().fadd(lod, bias);
            }
            if st.apply_max {
                let max_lod = self.unit_f32(unit, offset_of!(UnitView, max_lod));
                lod = self.minps(lod, max_lod);
            }
            if st.apply_min {
                let min_lod = self.unit_f32(unit, offset_of!(UnitView, min_lod));
                lod = self.maxps(lod, min_lod);
            }
            lod
        };
        let zero = self.fconst(0.0);
        let minified = self.b.ins().fcmp(FloatCC::GreaterThan, lod, zero);
        match key.mip {
            MipFilter::Linear => {
                let f = self.b.ins().floor(lod);
                let fpart = self.b.ins().fsub(lod, f);
                (self.int_lanes(f), Some(fpart), minified)
            }
            _ => {
                let r = self.b.ins().nearest(lod);
                (self.int_lanes(r), None, minified)
            }
        }
    }

    /// The packed RGBA8 of level `level` (a scalar: the group's lanes share
    /// it), filtered with `filter` at `at` (`crate::texture::filter::aos`,
    /// two dimensions).
    fn fetch_level(&mut self, unit: Value, key: &SamplerKey, filter: (Filter, Value), at: [Value; 2]) -> Value {
        let t = self.fetch_level_wide(unit, key, filter, at);
        self.narrow(t)
    }

    /// Level `level`'s texels (a scalar: the group's lanes share it) and
    /// its width and height per lane. Levels are within `first..=last` <
    /// MAX_LEVELS; the clamp keeps the address inside the view whatever the
    /// lane held.
    fn level_texels(&mut self, unit: Value, level: Value) -> (Value, [Value; 2]) {
        let base = offset_of!(UnitView, levels) as i32;
        let top = self.b.ins().iconst(types::I32, (MAX_LEVELS - 1) as i64);
        let l = self.b.ins().umin(level, top);
        let l = self.b.ins().uextend(self.ptr, l);
        let off = self.b.ins().imul_imm_u(l, size_of::<LevelView>() as i64);
        let lv = self.b.ins().iadd(unit, off);
        let texels = self
            .b
            .ins()
            .load(self.ptr, mem(), lv, base + offset_of!(LevelView, texels) as i32);
        // The size from the base level's, `max(1, side >> (level − first))`
        // (`UnitView::new` checked every level has it): shifts instead of a
        // chain of loads ahead of the coordinate arithmetic.
        let first = self
            .b
            .ins()
            .load(types::I32, mem(), unit, offset_of!(UnitView, first) as i32);
        let down = self.b.ins().isub(level, first);
        let one = self.splat(1);
        let size = [0, 1].map(|a| {
            let side = self.unit_i32(unit, offset_of!(UnitView, base_side) + 16 * a);
            let v = self.b.ins().ushr(side, down);
            self.b.ins().smax(v, one)
        });
        (texels, size)
    }

    /// `unit`'s `level` (texels and size) with what keeps a texel index in
    /// it. Coordinates are clamped to the level (they already are: the
    /// clamp only guarantees it), rows made once. An axis whose wrap ends in
    /// a mask with `len − 1` (REPEAT of a power of two) or a clamp to
    /// `0..=len − 1` (CLAMP_TO_EDGE) has its texels there whatever the lane
    /// held (NaN included): only REPEAT of other sizes (NaN through `fract`)
    /// keeps the clamp. 8 instructions a group on the tex frame.
    fn level_address(&mut self, unit: Value, key: &SamplerKey, level: Value) -> LevelAddress {
        let (texels, size) = self.level_texels(unit, level);
        let one = self.splat(1);
        let last = size.map(|len| self.b.ins().isub(len, one));
        let pot = key.statics.pot;
        let bounded = [0, 1].map(|a| key.wrap[a] == Wrap::ClampToEdge || (key.wrap[a] == Wrap::Repeat && pot[a]));
        LevelAddress {
            texels,
            size,
            last,
            bounded,
        }
    }

    /// Column `x` of level `l`, clamped where its wrap does not bound it.
    fn texel_column(&mut self, l: &LevelAddress, x: Value) -> Value {
        if l.bounded[0] {
            x
        } else {
            self.b.ins().umin(x, l.last[0])
        }
    }

    /// The offset of row `y` of level `l` (`y · width`), clamped where its
    /// wrap does not bound it.
    fn texel_row(&mut self, l: &LevelAddress, y: Value) -> Value {
        let y = if l.bounded[1] {
            y
        } else {
            self.b.ins().umin(y, l.last[1])
        };
        self.b.ins().imul(y, l.size[0])
    }

    /// [`Self::fetch_level`] as the two halves of the widened halves.
    fn fetch_level_wide(
        &mut self,
        unit: Value,
        key: &SamplerKey,
        (filter, level): (Filter, Value),
        at: [Value; 2],
    ) -> [Value; 2] {
        let l = self.level_address(unit, key, level);
        let LevelAddress { texels, size, last, .. } = l;
        let pot = key.statics.pot;
        let norm = key.target.normalized();
        match filter {
            Filter::Nearest => {
                let x = self.nearest_axis(at[0], (size[0], last[0]), (pot[0], norm), key.wrap[0]);
                let y = self.nearest_axis(at[1], (size[1], last[1]), (pot[1], norm), key.wrap[1]);
                let x = self.texel_column(&l, x);
                let y = self.texel_row(&l, y);
                self.fetch(texels, &[(x, y)])[0]
            }
            Filter::Linear => {
                let (x0, x1, wx) = self.linear_axis(at[0], (size[0], last[0]), (pot[0], norm), key.wrap[0]);
                let (y0, y1, wy) = self.linear_axis(at[1], (size[1], last[1]), (pot[1], norm), key.wrap[1]);
                let [x0, x1] = [x0, x1].map(|x| self.texel_column(&l, x));
                let [y0, y1] = [y0, y1].map(|y| self.texel_row(&l, y));
                // The three lerps on widened texels, narrowed once.
                let t = self.fetch(texels, &[(x0, y0), (x1, y0), (x0, y1), (x1, y1)]);
                let (wx, wy) = (self.wide_weight(wx), self.wide_weight(wy));
                let r0 = self.lerp_wide(wx, t[0], t[1]);
                let r1 = self.lerp_wide(wx, t[2], t[3]);
                self.lerp_wide(wy, r0, r1)
            }
        }
    }

    /// The texels at each `(x, y)`, column and row offset (`row · width`),
    /// of the level's `texels` (from [`Self::fetch_level`]), widened
    /// (lanes 0–1, lanes 2–3: see [`Self::narrow`]).
    ///
    /// x86 has no gather in 128-bit code Cranelift emits, so each lane is a
    /// load of its own, and the way they are made matters: the offsets go
    /// through a stack slot (a store and four `movl`, which zero-extend:
    /// `pextrd` needs a `movl` more for that, and the shuffle port was what a
    /// group waited on) rather than `pextrd`; each texel's load comes right
    /// before the `movd`/`pinsrd` that takes it, so that Cranelift folds it
    /// in. It folds a load only into a single use, counting every use of
    /// whatever is computed from it (and through block parameters), and the
    /// filters use each texel twice: so the vector goes back to the slot
    /// (over its own offsets) and is widened from there, two `pmovzxbw` from
    /// memory where widening a register took three instructions; the ×4 of
    /// the texel size is in the address. Per vector 13 instructions where
    /// the gather into registers and widening took 18: the tex frame of
    /// `osmesa/bench/fill.c` runs 5% fewer instructions of generated code
    /// (1,750 M to 1,665 M, callgrind, 2 frames).
    fn fetch(&mut self, texels: Value, at: &[(Value, Value)]) -> Vec<[Value; 2]> {
        let base = self.gather(texels, at, true).0;
        (0..at.len())
            .map(|k| [0, 8].map(|h| self.b.ins().uload8x8(le().with_notrap(), base, (16 * k + h) as i32)))
            .collect()
    }

    /// The packed texels at each `(x, y)` as [`Self::fetch`] gathers them
    /// (not widened: the SoA path converts each channel to float).
    fn fetch_packed(&mut self, texels: Value, at: &[(Value, Value)]) -> Vec<Value> {
        self.gather(texels, at, false).1
    }

    /// [`Self::fetch`]'s gather through the stack slot: its address and the
    /// vectors, each stored back over its offsets when `store`.
    fn gather(&mut self, texels: Value, at: &[(Value, Value)], store: bool) -> (Value, Vec<Value>) {
        let slot = self.gather_slot();
        let base = self.b.ins().stack_addr(self.ptr, slot, 0);
        for (k, &(x, y)) in at.iter().enumerate() {
            let index = self.b.ins().iadd(y, x);
            self.b.ins().store(mem(), index, base, 16 * k as i32);
        }
        let mut out = Vec::with_capacity(at.len());
        for k in 0..at.len() {
            let v = self.load_lanes(texels, base, 16 * k as i32, I32X4);
            if store {
                self.b.ins().store(le().with_notrap(), v, base, 16 * k as i32);
            }
            out.push(v);
        }
        (base, out)
    }

    /// The function's stack slot for gather offsets (four vectors), made on first use.
    fn gather_slot(&mut self) -> StackSlot {
        if let Some(s) = self.gather_slot {
            return s;
        }
        let data = StackSlotData::new(StackSlotKind::ExplicitSlot, 64, 4);
        let s = self.b.create_sized_stack_slot(data);
        self.gather_slot = Some(s);
        s
    }

    /// The halves of the widened halves packed again (every value is a byte).
    fn narrow(&mut self, h: [Value; 2]) -> Value {
        let bytes = self.b.ins().unarrow(h[0], h[1]);
        self.b.ins().bitcast(I32X4, le(), bytes)
    }

    /// Each lane's weight (0..=255) in its four channels, in the halves'
    /// layout: lane 2h's, then lane 2h + 1's (byte 1 of each `i32` lane is
    /// zero: the weight is below 256).
    fn wide_weight(&mut self, w: Value) -> [Value; 2] {
        let wb = self.b.ins().bitcast(types::I8X16, le(), w);
        [0u8, 1].map(|h| {
            let (l0, l1) = (8 * h, 8 * h + 4);
            let mut mask = [0u8; 16];
            for (i, m) in mask.iter_mut().enumerate() {
                let l = if i < 8 { l0 } else { l1 };
                *m = l + (i as u8 & 1);
            }
            let m = self.b.func.dfg.immediates.push(mask.to_vec().into());
            let ws = self.b.ins().shuffle(wb, wb, m);
            self.b.ins().bitcast(types::I16X8, le(), ws)
        })
    }

    /// The 8-bit lerp on widened texels (`arith::lerp8`), as llvmpipe
    /// computes it: on 16-bit lanes, `pmulhrsw(w, (b − a) << 7)` is
    /// `(w·(b − a) + 128) >> 8`. Neither factor is ever −32768 (w ≤ 255,
    /// |b − a| ≤ 255), where `pmulhrsw` and `sqmul_round_sat` differ, so
    /// x86-64 takes the bare instruction (`sqmul_round_sat` adds a fix-up
    /// for that case: two instructions per lerp).
    fn lerp_wide(&mut self, w: [Value; 2], a: [Value; 2], b: [Value; 2]) -> [Value; 2] {
        std::array::from_fn(|h| {
            let d = self.b.ins().isub(b[h], a[h]);
            let d = self.b.ins().ishl_imm_u(d, 7);
            let step = if self.x86 {
                self.b.ins().x86_pmulhrsw(w[h], d)
            } else {
                self.b.ins().sqmul_round_sat(w[h], d)
            };
            self.b.ins().iadd(a[h], step)
        })
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

    /// REPEAT's nearest texel along an axis of length `lf` (as f32) and
    /// `len1` (`len − 1`): for a power-of-two size (`pot`) `floor(s · len)`
    /// masked with `len − 1`, else `fract_safe(s) · len` truncated
    /// (`fract_safe`: below the bound, else, and NaN, the bound).
    fn repeat_index(&mut self, s: Value, lf: Value, len1: Value, pot: bool) -> Value {
        if pot {
            let v = self.b.ins().fmul(s, lf);
            let v = self.b.ins().floor(v);
            let i = self.int_lanes(v);
            self.b.ins().band(i, len1)
        } else {
            let f = self.b.ins().floor(s);
            let f = self.b.ins().fsub(s, f);
            let max = self.fconst(1.0 - 1.0 / (1u32 << 24) as f32);
            let f = self.minps(f, max);
            let v = self.b.ins().fmul(f, lf);
            self.int_lanes(v)
        }
    }

    /// The nearest texel along an axis (`filter::aos_nearest_axis`) of
    /// length `len` (and `len − 1`); `pot`: REPEAT of a power-of-two size
    /// (the key's statics); `norm`: normalized coordinates (false for a
    /// rectangle texture: the clamp's coordinate is not scaled).
    fn nearest_axis(&mut self, s: Value, (len, len1): (Value, Value), (pot, norm): (bool, bool), wrap: Wrap) -> Value {
        let lf = self.b.ins().fcvt_from_sint(F32X4, len);
        match wrap {
            Wrap::Repeat => self.repeat_index(s, lf, len1, pot),
            _ => {
                let v = if norm { self.b.ins().fmul(s, lf) } else { s };
                let v = self.b.ins().floor(v);
                let i = self.int_lanes(v);
                let zero = self.splat(0);
                let i = self.b.ins().smax(i, zero);
                self.b.ins().smin(i, len1)
            }
        }
    }

    /// The two texels and the 8-bit weight of the second along an axis
    /// (`filter::aos_linear_axis`); `pot` and `norm` as in [`Self::nearest_axis`].
    fn linear_axis(
        &mut self,
        s: Value,
        (len, len1): (Value, Value),
        (pot, norm): (bool, bool),
        wrap: Wrap,
    ) -> (Value, Value, Value) {
        let one = self.splat(1);
        let zero = self.splat(0);
        let ff = self.splat(255);
        let m128 = self.splat(-128);
        // `round(v · 256) − 128` split into its texel (>> 8) and weight (& 255).
        let split = |g: &mut Self, v: Value| {
            let u = g.b.ins().nearest(v);
            let u = g.int_lanes(u);
            let u = g.b.ins().iadd(u, m128);
            (g.b.ins().sshr_imm_u(u, 8), g.b.ins().band(u, ff))
        };
        match wrap {
            Wrap::Repeat if pot => {
                let scaled = self.b.ins().ishl_imm_u(len, 8);
                let scaled = self.b.ins().fcvt_from_sint(F32X4, scaled);
                let u = self.b.ins().fmul(s, scaled);
                let (i, w) = split(self, u);
                let x0 = self.b.ins().band(i, len1);
                let next = self.b.ins().iadd(x0, one);
                (x0, self.b.ins().band(next, len1), w)
            }
            Wrap::Repeat => {
                // Not a power of two: from the fraction of s.
                let lf = self.b.ins().fcvt_from_sint(F32X4, len);
                let f = self.b.ins().floor(s);
                let f = self.b.ins().fsub(s, f);
                let v = self.b.ins().fmul(f, lf);
                let k = self.fconst(256.0);
                let v = self.b.ins().fmul(v, k);
                let (hi, w) = split(self, v);
                let negative = self.b.ins().icmp(IntCC::SignedLessThan, hi, zero);
                let x0 = self.b.ins().bitselect(negative, len1, hi);
                let x0 = self.b.ins().smin(x0, len1);
                let last = self.b.ins().icmp(IntCC::Equal, x0, len1);
                let next = self.b.ins().iadd(x0, one);
                (x0, self.b.ins().bitselect(last, zero, next), w)
            }
            _ => {
                // `s · len·256`, or `s · 256` for unnormalized coordinates.
                let scaled = if norm {
                    let scaled = self.b.ins().ishl_imm_u(len, 8);
                    self.b.ins().fcvt_from_sint(F32X4, scaled)
                } else {
                    self.fconst(256.0)
                };
                let u = self.b.ins().fmul(s, scaled);
                let (i, w) = split(self, u);
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

    /// The sRGB unit's filtered RGBA on llvmpipe's SoA path
    /// (`crate::texture::sample`'s `filter_levels` with `filter::soa_at`):
    /// level `level0` (a scalar: the group's lanes share it) with the
    /// minification filter, for a linear mipmap filter lerped with the next
    /// level by the f32 weight where it is positive (`filter::soa_mip`),
    /// and where min and mag differ the magnified lanes from level `level0`
    /// with the magnification filter.
    fn soa_levels(
        &mut self,
        unit: Value,
        key: &SamplerKey,
        (level0, second, minified): (Value, Option<(Value, Value)>, Value),
        at: [Value; 2],
    ) -> [Value; 4] {
        let mut min = self.soa_level(unit, key, (key.min, level0), at);
        if let Some((level1, w)) = second {
            let level1 = self.b.ins().extractlane(level1, 0);
            let c1 = self.soa_level(unit, key, (key.min, level1), at);
            let zero = self.fconst(0.0);
            let positive = self.b.ins().fcmp(FloatCC::GreaterThan, w, zero);
            let positive = self.b.ins().bitcast(F32X4, MemFlagsData::new(), positive);
            for (c, c1) in min.iter_mut().zip(c1) {
                let l = self.lerp_f(w, *c, c1);
                *c = self.b.ins().bitselect(positive, l, *c);
            }
        }
        if key.min == key.mag {
            return min;
        }
        let mag = self.soa_level(unit, key, (key.mag, level0), at);
        let minified = self.b.ins().bitcast(F32X4, MemFlagsData::new(), minified);
        std::array::from_fn(|c| self.b.ins().bitselect(minified, min[c], mag[c]))
    }

    /// One level of an sRGB unit filtered on the SoA path
    /// (`filter::soa_at`, two dimensions, REPEAT or CLAMP_TO_EDGE: no
    /// border): texels decoded to linear f32 each, then f32 lerps as fused
    /// multiply-adds, along s within each row, then along t.
    fn soa_level(
        &mut self,
        unit: Value,
        key: &SamplerKey,
        (filter, level): (Filter, Value),
        at: [Value; 2],
    ) -> [Value; 4] {
        // The bounds as in `fetch_level_wide` (a NaN coordinate on REPEAT of
        // other sizes than powers of two gives i32::MIN, which the reference
        // reads as a zero texel; every lerp with its NaN weight is NaN either
        // way, and NEAREST keeps the fraction below 1).
        let l = self.level_address(unit, key, level);
        let LevelAddress { texels, size, last, .. } = l;
        let pot = key.statics.pot;
        match filter {
            Filter::Nearest => {
                let x = self.depth_axis(at[0], size[0], pot[0], key.wrap[0]);
                let y = self.depth_axis(at[1], size[1], pot[1], key.wrap[1]);
                let x = self.texel_column(&l, x);
                let y = self.texel_row(&l, y);
                let t = self.fetch_packed(texels, &[(x, y)])[0];
                self.srgb_texel(t)
            }
            Filter::Linear => {
                let (x0, x1, wx) = self.soa_linear_axis(at[0], (size[0], last[0]), pot[0], key.wrap[0]);
                let (y0, y1, wy) = self.soa_linear_axis(at[1], (size[1], last[1]), pot[1], key.wrap[1]);
                let [x0, x1] = [x0, x1].map(|x| self.texel_column(&l, x));
                let [y0, y1] = [y0, y1].map(|y| self.texel_row(&l, y));
                let t = self.fetch_packed(texels, &[(x0, y0), (x1, y0), (x0, y1), (x1, y1)]);
                // A channel at a time: its four texels decoded and lerped
                // before the next channel's (decoding the four texels whole
                // first kept sixteen vectors live: a trilinear key compiled
                // in 6.2 ms against the RGBA8 one's 1.5).
                std::array::from_fn(|c| {
                    let v: Vec<Value> = t.iter().map(|&t| self.srgb_channel(t, c)).collect();
                    let r0 = self.lerp_f(wx, v[0], v[1]);
                    let r1 = self.lerp_f(wx, v[2], v[3]);
                    self.lerp_f(wy, r0, r1)
                })
            }
        }
    }

    /// The two texels and the f32 weight of the second along an axis of
    /// length `len` (and `len − 1`) on the SoA path
    /// (`filter::soa_linear_axis_at` for REPEAT and CLAMP_TO_EDGE of
    /// normalized coordinates); `pot` as in [`Self::nearest_axis`].
    fn soa_linear_axis(
        &mut self,
        s: Value,
        (len, len1): (Value, Value),
        pot: bool,
        wrap: Wrap,
    ) -> (Value, Value, Value) {
        let one = self.splat(1);
        let half = self.fconst(0.5);
        let lf = self.b.ins().fcvt_from_sint(F32X4, len);
        // `ifloor_fract`: floor as an integer and the fraction.
        let floor_fract = |g: &mut Self, v: Value| {
            let f = g.b.ins().floor(v);
            let w = g.b.ins().fsub(v, f);
            (g.int_lanes(f), w)
        };
        match wrap {
            Wrap::Repeat if pot => {
                let v = self.b.ins().fmul(s, lf);
                let v = self.b.ins().fsub(v, half);
                let (i, w) = floor_fract(self, v);
                let x0 = self.b.ins().band(i, len1);
                let next = self.b.ins().iadd(i, one);
                (x0, self.b.ins().band(next, len1), w)
            }
            Wrap::Repeat => {
                let f = self.b.ins().floor(s);
                let f = self.b.ins().fsub(s, f);
                let u = self.b.ins().fmul(f, lf);
                let u = self.b.ins().fsub(u, half);
                let (i, w) = floor_fract(self, u);
                let zero = self.fconst(0.0);
                let negative = self.b.ins().fcmp(FloatCC::LessThan, u, zero);
                let x0 = self.b.ins().bitselect(negative, len1, i);
                let last = self.b.ins().icmp(IntCC::Equal, x0, len1);
                let next = self.b.ins().iadd(x0, one);
                let zero = self.splat(0);
                (x0, self.b.ins().bitselect(last, zero, next), w)
            }
            _ => {
                // CLAMP_TO_EDGE: `max(min(s·len, len) − 0.5, 0)`.
                let v = self.b.ins().fmul(s, lf);
                let v = self.minps(v, lf);
                let v = self.b.ins().fsub(v, half);
                let zero = self.fconst(0.0);
                let v = self.maxps(v, zero);
                let (x0, w) = floor_fract(self, v);
                let next = self.b.ins().iadd(x0, one);
                (x0, self.b.ins().smin(next, len1), w)
            }
        }
    }

    /// Packed sRGB8 RGBA lanes to four f32 channels as llvmpipe's SoA fetch
    /// converts them ([`Self::srgb_channel`]).
    fn srgb_texel(&mut self, t: Value) -> [Value; 4] {
        std::array::from_fn(|c| self.srgb_channel(t, c))
    }

    /// Channel `c` of packed sRGB8 RGBA lanes as f32 (`arith::srgb8_to_linear`
    /// for r, g, b: `v/(12.6·255)` up to 15, else the cubic in fused
    /// multiply-adds; `unorm8_to_float` for alpha).
    fn srgb_channel(&mut self, t: Value, c: usize) -> Value {
        let v = if c == 3 {
            self.b.ins().ushr_imm_u(t, 24)
        } else {
            let ff = self.splat(255);
            let s = if c == 0 {
                t
            } else {
                self.b.ins().ushr_imm_u(t, 8 * c as i64)
            };
            self.b.ins().band(s, ff)
        };
        let x = self.b.ins().fcvt_from_sint(F32X4, v);
        if c == 3 {
            let k = self.fconst((1.0f64 / 255.0) as f32);
            return self.b.ins().fmul(x, k);
        }
        let k = self.fconst(1.0f32 / (12.6f32 * 255.0f32));
        let p = [
            0.0023f32,
            0.0030f32 / 255.0f32,
            0.6935f32 / (255.0f32 * 255.0f32),
            0.3012f32 / (255.0f32 * 255.0f32 * 255.0f32),
        ]
        .map(|v| self.fconst(v));
        let small_max = self.splat(15);
        let small = self.b.ins().icmp(IntCC::SignedLessThanOrEqual, v, small_max);
        let small = self.b.ins().bitcast(F32X4, MemFlagsData::new(), small);
        let linear = self.b.ins().fmul(x, k);
        let x2 = self.b.ins().fmul(x, x);
        let odd = self.b.ins().fma(x2, p[3], p[1]);
        let even = self.b.ins().fma(x2, p[2], p[0]);
        let poly = self.b.ins().fma(odd, x, even);
        self.b.ins().bitselect(small, linear, poly)
    }

    /// The f32 lerp `fma(w, b − a, a)` (`arith::lerp`).
    fn lerp_f(&mut self, w: Value, a: Value, b: Value) -> Value {
        let d = self.b.ins().fsub(b, a);
        self.b.ins().fma(w, d, a)
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
}

/// A level's texels and size as [`Gen::level_address`] makes
/// them: `last` is `size − 1`; `bounded` says per axis whether the wrap
/// already keeps an index in the level.
#[derive(Clone, Copy)]
struct LevelAddress {
    texels: Value,
    size: [Value; 2],
    last: [Value; 2],
    bounded: [bool; 2],
}
