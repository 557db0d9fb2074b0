//! The shading stage in generated code: attribute planes evaluated for four
//! fragments at once in `f32x4`, then the colour sum, fog and the conversion
//! to unorm8, each step the same f32 operation as `crate::shade` (fused
//! multiply-adds exactly where it has them), so the bits equal the
//! interpreter's.

use super::{le, mem, Gen, Group, SpanPlanes, SpanValues, SplatUniforms, I32X4};
use crate::key::{ColorFormat, DepthFormat, FragmentKey, ShadeKey};
use crate::shade::{exp2_coeffs, slot, FogMode, Planes};
use cranelift_codegen::ir::condcodes::{FloatCC, IntCC};
use cranelift_codegen::ir::{types, BlockArg, InstBuilder, MemFlagsData, Value};
use std::mem::offset_of;

const F32X4: cranelift_codegen::ir::Type = types::F32X4;

impl Gen<'_> {
    /// The span's planes pointer (from its [`SpanPlanes`] `entry`), its
    /// row in llvmpipe's top-down frame (`interp::row_of(y, height)`)
    /// splatted, and the x of its first four pixels as f32, made once a span.
    pub(super) fn planes_and_row(
        &mut self,
        entry: Value,
        (x0, y, height): (Value, Value, Value),
    ) -> (Value, Value, Value) {
        let planes = self
            .b
            .ins()
            .load(self.ptr, mem(), entry, offset_of!(SpanPlanes, planes) as i32);
        // `height.saturating_sub(y + 1)`.
        let below = self.b.ins().isub(height, y);
        let below = self.b.ins().iadd_imm_u(below, -1);
        let above = self.b.ins().icmp(IntCC::UnsignedGreaterThan, height, y);
        let zero = self.b.ins().iconst(types::I32, 0);
        let row = self.b.ins().select(above, below, zero);
        let row = self.b.ins().fcvt_from_uint(types::F32, row);
        let row = self.b.ins().splat(F32X4, row);
        let x = self.b.ins().splat(I32X4, x0);
        let idx = self.vconst([0, 1, 2, 3]);
        let x = self.b.ins().iadd(x, idx);
        (planes, row, self.b.ins().fcvt_from_sint(F32X4, x))
    }

    /// Sets the group's depth from its primitive's planes (keys whose shading
    /// stage computes depth).
    pub(super) fn shade_depth(&mut self, g: &mut Group, sv: &SpanValues, key: &ShadeKey) {
        if !key.depth {
            return;
        }
        let (planes, row, _) = sv.planes.expect("loaded for keys with a shading stage");
        let px = g.px.expect("carried by the loop for keys with a shading stage");
        let at = |s: &mut Self, k: usize| s.plane(planes, k, px, row);
        if key.depth {
            if let Some(format) = self.key.depth_format {
                let z = at(self, slot::Z);
                g.z = Some(match format {
                    DepthFormat::D32 => self.unorm_lanes(z, format.max_value()),
                    DepthFormat::D32F => self.float_depth_lanes(z),
                    DepthFormat::D16 | DepthFormat::D24 => {
                        let floor = !self.depth_write_max_only();
                        self.unorm_lanes_small(z, format.max_value(), floor)
                    }
                });
            }
        }
    }

    /// Planes `ks` at the lanes, each divided by the 1/w plane (times
    /// `w = 1 / (1/w)`, made once a group and kept in `g.w`), as
    /// `crate::shade::fragment`. When the span's 1/w plane is exactly 1
    /// (bit 0 of `SpanPlanes::ones`, [`crate::Planes::is_one`]: then `1 / 1` is 1
    /// and `v · 1` is `v`) the planes' values are taken as they are: the
    /// same bits without the division and the multiplies (the `fill`
    /// frame's groups: 11 instructions fewer of 66).
    /// With `keep_w`, the merged w is kept in `g.w` for later stages.
    fn perspective(&mut self, g: &mut Group, sv: &SpanValues, ks: &[usize], keep_w: bool) -> Vec<Value> {
        let (planes, row, _) = sv.planes.expect("loaded for keys with a shading stage");
        let px = g.px.expect("carried by the loop for keys with a shading stage");
        let divided = |s: &mut Self, w: Value| -> Vec<Value> {
            ks.iter()
                .map(|&k| {
                    let v = s.plane(planes, k, px, row);
                    s.b.ins().fmul(v, w)
                })
                .collect()
        };
        if sv.w_is_one {
            if keep_w && g.w.is_none() {
                g.w = Some(self.fconst(1.0));
            }
            return ks.iter().map(|&k| self.plane(planes, k, px, row)).collect();
        }
        let Some(w_one) = sv.w_one else {
            let w = self.w(g, planes, px, row);
            g.w = Some(w);
            return divided(self, w);
        };
        let need_w = keep_w && g.w.is_none();
        let g_w = g.w;
        let params = self.diamond(
            w_one,
            |s| {
                let mut v: Vec<Value> = ks.iter().map(|&k| s.plane(planes, k, px, row)).collect();
                if need_w {
                    v.push(s.fconst(1.0));
                }
                v
            },
            |s| {
                let w = match g_w {
                    Some(w) => w,
                    None => s.inverse_w(planes, px, row),
                };
                let mut v = divided(s, w);
                if need_w {
                    v.push(w);
                }
                v
            },
        );
        if need_w {
            g.w = params.last().copied();
        }
        params[..ks.len()].to_vec()
    }

    /// `fast`'s values where `flag` is set, else `slow`'s (as many, each
    /// `f32x4`): a branch and a merge. Constants either arm makes are
    /// forgotten after it (they dominate neither the other arm nor the merge).
    pub(super) fn diamond(
        &mut self,
        flag: Value,
        fast: impl FnOnce(&mut Self) -> Vec<Value>,
        slow: impl FnOnce(&mut Self) -> Vec<Value>,
    ) -> Vec<Value> {
        let (fast_b, slow_b, merge) = (self.b.create_block(), self.b.create_block(), self.b.create_block());
        self.b.ins().brif(flag, fast_b, &[], slow_b, &[]);
        let (consts, fconsts) = (self.consts.len(), self.fconsts.len());
        let arm = |s: &mut Self, block, f: &mut dyn FnMut(&mut Self) -> Vec<Value>| {
            s.b.switch_to_block(block);
            let v = f(s);
            if s.b.block_params(merge).is_empty() {
                for _ in 0..v.len() {
                    s.b.append_block_param(merge, F32X4);
                }
            }
            let args: Vec<BlockArg> = v.into_iter().map(Into::into).collect();
            s.b.ins().jump(merge, &args);
            s.consts.truncate(consts);
            s.fconsts.truncate(fconsts);
        };
        let mut fast = Some(fast);
        let mut slow = Some(slow);
        arm(self, fast_b, &mut |s| (fast.take().expect("called once"))(s));
        arm(self, slow_b, &mut |s| (slow.take().expect("called once"))(s));
        self.b.switch_to_block(merge);
        self.b.block_params(merge).to_vec()
    }

    /// `1 / (1/w)` at `(px, row)`.
    pub(super) fn inverse_w(&mut self, planes: Value, px: Value, row: Value) -> Value {
        let iw = self.plane(planes, slot::INV_W, px, row);
        let one = self.fconst(1.0);
        self.b.ins().fdiv(one, iw)
    }

    /// `g.w`, or `1 / (1/w)` at the lanes (not kept: the caller keeps it
    /// where it dominates).
    fn w(&mut self, g: &Group, planes: Value, px: Value, row: Value) -> Value {
        match g.w {
            Some(w) => w,
            None => self.inverse_w(planes, px, row),
        }
    }

    /// The colour planes `ks` at the lanes as the key takes them: flat
    /// values as they are, else divided by the 1/w plane. The fog
    /// coordinate's plane is always divided. Keeps w in `g.w` when made.
    fn colour_planes(
        &mut self,
        g: &mut Group,
        sv: &SpanValues,
        key: &ShadeKey,
        (ks, keep_w): (&[usize], bool),
    ) -> Vec<Value> {
        if !key.flat {
            return self.perspective(g, sv, ks, keep_w);
        }
        let (planes, row, _) = sv.planes.expect("loaded for keys with a shading stage");
        let px = g.px.expect("carried by the loop for keys with a shading stage");
        if key.fog.is_some() && g.w.is_none() {
            g.w = Some(self.w(g, planes, px, row));
        }
        ks.iter()
            .map(|&k| {
                let v = self.plane(planes, k, px, row);
                match (k, g.w) {
                    (slot::FOG, Some(w)) => self.b.ins().fmul(v, w),
                    _ => v,
                }
            })
            .collect()
    }

    /// Shades only the alpha channel, for the alpha test of an untextured
    /// key ([`Self::shade_color`] makes the others later).
    pub(super) fn shade_alpha(&mut self, g: &mut Group, sv: &SpanValues, key: &ShadeKey) {
        if g.alpha_shaded {
            return;
        }
        // The other channels, shaded later, read w.
        let a = self.colour_planes(g, sv, key, (&[slot::COLOR + 3], true))[0];
        if key.coverage.quarters.is_some() {
            g.alpha_f = Some(a);
        }
        g.rgba[3] = self.unorm_lanes_small(a, 255, true);
        g.alpha_shaded = true;
    }

    /// Sets the group's colour (as bytes, or packed when no later stage
    /// reads the channels) from its primitive's planes.
    pub(super) fn shade_color(&mut self, g: &mut Group, sv: &SpanValues, key: &ShadeKey) {
        let alpha_shaded = g.alpha_shaded;
        let c = self.shaded_f32(g, sv, key);
        if !alpha_shaded && key.coverage.quarters.is_some() {
            g.alpha_f = Some(c[3]);
        }
        if self.packs_from_shade() {
            // Straight to the packed pixels: no later stage reads the channels.
            g.packed = Some(self.unorm8_packed(c, sv.colour_bounded));
        } else if alpha_shaded {
            for (k, ck) in c.iter().take(3).enumerate() {
                g.rgba[k] = self.unorm_lanes_small(*ck, 255, true);
            }
        } else {
            g.rgba = c.map(|v| self.unorm_lanes_small(v, 255, true));
        }
    }

    /// The group's colour from its primitive's planes, in f32 (as
    /// `crate::shade::fragment_f32`): the primary colour, texturing,
    /// colour sum and fog. With alpha already shaded (`g.alpha_shaded`)
    /// the fourth value is not alpha.
    pub(super) fn shaded_f32(&mut self, g: &mut Group, sv: &SpanValues, key: &ShadeKey) -> [Value; 4] {
        let alpha_shaded = g.alpha_shaded;
        // The primary colour (without an alpha already shaded), the
        // secondary colour and the fog coordinate, in that order.
        let mut ks: Vec<usize> = (0..4)
            .filter(|&c| c < 3 || !alpha_shaded)
            .map(|c| slot::COLOR + c)
            .collect();
        let primary = ks.len();
        if key.color_sum {
            ks.extend((0..3).map(|c| slot::SECONDARY + c));
        }
        if key.fog.is_some() {
            ks.push(slot::FOG);
        }
        // Texturing reads w after.
        let v = self.colour_planes(g, sv, key, (&ks, key.textured()));
        // With alpha already shaded, `c[3]` is not read: `rgba[3]` stays.
        let c3 = if alpha_shaded { v[0] } else { v[3] };
        let mut c = [v[0], v[1], v[2], c3];
        if key.textured() {
            c = self.texture(g, sv, key, c);
        }
        if key.color_sum {
            for (k, ck) in c.iter_mut().take(3).enumerate() {
                *ck = self.b.ins().fadd(*ck, v[primary + k]);
            }
        }
        if let (Some(mode), Some(&coord)) = (key.fog, v.last().filter(|_| key.fog.is_some())) {
            let f = self.fog_factor(mode, coord, sv.u);
            let one = self.fconst(1.0);
            let inv = self.b.ins().fsub(one, f);
            for (k, ck) in c.iter_mut().take(3).enumerate() {
                let off = offset_of!(SplatUniforms, fog_color) + 16 * k;
                let fog = self.b.ins().load(F32X4, mem().with_aligned(), sv.u, off as i32);
                let a = self.b.ins().fmul(fog, inv);
                let b = self.b.ins().fmul(*ck, f);
                *ck = self.b.ins().fadd(a, b);
            }
        }
        c
    }

    /// Whether the shading stage may hand over the packed colour instead of
    /// the four channels: no later stage reads them (no alpha test, no
    /// blend) and the format holds one byte a channel.
    pub(super) fn packs_from_shade(&self) -> bool {
        Self::packs_from_shade_of(&self.key)
    }

    /// [`Self::packs_from_shade`] of `k`.
    pub(super) fn packs_from_shade_of(k: &FragmentKey) -> bool {
        k.alpha_test.is_none()
            && !k.shade.is_some_and(|s| s.coverage.is_on())
            && (k.blend.is_none() || k.logic_op.is_some())
            && matches!(
                k.color_format,
                ColorFormat::Rgba8 | ColorFormat::Bgra8 | ColorFormat::Rgb8
            )
    }

    /// The four channels as unorm8 bytes packed in the format's order (as
    /// [`Self::unorm_lanes_small`] then `Gen::pack`): `v · 255`, lanes above 255
    /// (and +∞) set to it, rounded half to even, converted; the saturating
    /// narrowings then make negatives and NaN (converted to `i32::MIN`) 0, and
    /// one byte shuffle interleaves the channels. 16 instructions a group of
    /// four where the channel by channel path takes 30.
    ///
    /// With `bounded` (the channels are below 2^22 in magnitude,
    /// `Planes::colour_bounded`) without the clamp to 255: `v · 255` is then
    /// below 2^31, converts without overflow, and the narrowings make lanes
    /// above 255 255 (as the clamp does) and NaN 0 (as it does). 12 + 4
    /// instructions where the clamp makes it 16 + 4; and the plane value
    /// is then used once, so Cranelift folds each plane's `a0` load into
    /// its multiply-add (a value used twice, as `min_const` uses it, makes
    /// every value it is made from count as used twice).
    fn unorm8_packed(&mut self, c: [Value; 4], bounded: bool) -> Value {
        let [r, g, b, a] = c.map(|v| {
            let m = self.fconst(255.0);
            let t = self.b.ins().fmul(v, m);
            let t = if bounded { t } else { self.min_const(m, t) };
            let t = self.b.ins().nearest(t);
            self.int_lanes(t)
        });
        let rg = self.b.ins().snarrow(r, g);
        let ba = self.b.ins().snarrow(b, a);
        // Bytes r0..r3 g0..g3 b0..b3 a0..a3.
        let planar = self.b.ins().unarrow(rg, ba);
        self.interleave(planar)
    }

    /// The byte indices of [`Self::interleave`]'s shuffle: 16 for a zero byte.
    fn interleave_mask(&self) -> [u8; 16] {
        let (c0, c2) = if self.key.color_format == ColorFormat::Bgra8 {
            (8, 0)
        } else {
            (0, 8)
        };
        // Index 16 takes a byte of the zero vector (RGB8 stores no alpha).
        let has_alpha = self.key.color_format.has_alpha();
        let mut mask = [0u8; 16];
        for i in 0..4u8 {
            let alpha = if has_alpha { 12 + i } else { 16 };
            mask[4 * i as usize..4 * i as usize + 4].copy_from_slice(&[c0 + i, 4 + i, c2 + i, alpha]);
        }
        mask
    }

    /// On x86-64, [`Self::interleave`]'s shuffle as the mask of one
    /// `pshufb` (an index with its top bit set makes a zero byte), made
    /// where it is kept in a register for a loop ([`Gen::pshufb_mask`]).
    pub(super) fn make_pshufb_mask(&mut self) -> Option<Value> {
        let m = self.interleave_mask().map(|i| if i == 16 { 0x80 } else { i });
        self.x86.then(|| self.vconst_bytes(m))
    }

    /// Bytes `r0..r3 g0..g3 b0..b3 a0..a3` as four pixels of the format
    /// (one with a byte a channel): one byte shuffle.
    pub(super) fn interleave(&mut self, planar: Value) -> Value {
        let mask = self.interleave_mask();
        let has_alpha = self.key.color_format.has_alpha();
        if let Some(m) = self.pshufb_mask {
            // `pshufb` itself, its mask kept in a register for the loop
            // ([`Gen::pshufb_mask`]): `shuffle` reads `planar` twice, and
            // Cranelift then folds no load of the values it is made from
            // (every plane's `a0`: 4 instructions a group).
            let bytes = self.b.ins().x86_pshufb(planar, m);
            return self.b.ins().bitcast(I32X4, le(), bytes);
        }
        let m = self.b.func.dfg.immediates.push(mask.to_vec().into());
        let other = if has_alpha { planar } else { self.vconst_bytes([0; 16]) };
        let bytes = self.b.ins().shuffle(planar, other, m);
        self.b.ins().bitcast(I32X4, le(), bytes)
    }

    /// `min(m, t)` with NaN kept (`m < t ? m : t`), one `minps` on x86-64.
    pub(super) fn min_const(&mut self, m: Value, t: Value) -> Value {
        let over = self.b.ins().fcmp(FloatCC::LessThan, m, t);
        let over = self.b.ins().bitcast(F32X4, MemFlagsData::new(), over);
        self.b.ins().bitselect(over, m, t)
    }

    /// Rounded f32 lanes to i32 (`i32::MIN` for NaN and out of range on x86-64).
    pub(super) fn int_lanes(&mut self, r: Value) -> Value {
        if self.x86 {
            self.b.ins().x86_cvtt2dq(I32X4, r)
        } else {
            self.b.ins().fcvt_to_sint_sat(I32X4, r)
        }
    }

    /// Plane `k` at the lanes' pixels: `fma(dady, row, fma(dadx, px, a0))`,
    /// each coefficient one aligned vector load (`Planes` stores them splatted).
    pub(super) fn plane(&mut self, planes: Value, k: usize, px: Value, row: Value) -> Value {
        if let Some((_, [a0, dadx, dady])) = self.plane_cache.filter(|(c, _)| *c == k) {
            let inner = self.b.ins().fma(dadx, px, a0);
            return self.b.ins().fma(dady, row, inner);
        }
        // In this order Cranelift folds `a0`, the load just before its
        // fused multiply-add, into it and needs no copy of `px` or `row`
        // (`vfmadd213ps`): 4 instructions a plane where the other orders
        // take 5.
        let dadx = self.plane_coeff(planes, k, 1);
        let dady = self.plane_coeff(planes, k, 2);
        let a0 = self.plane_coeff(planes, k, 0);
        let inner = self.b.ins().fma(dadx, px, a0);
        self.b.ins().fma(dady, row, inner)
    }

    /// Coefficient `c` (`a0`, `dadx`, `dady`) of plane `k`: one aligned
    /// vector load (`Planes` stores them splatted).
    pub(super) fn plane_coeff(&mut self, planes: Value, k: usize, c: usize) -> Value {
        let off = offset_of!(Planes, coeffs) + (3 * k + c) * 16;
        self.b.ins().load(F32X4, mem().with_aligned(), planes, off as i32)
    }

    pub(super) fn fconst(&mut self, v: f32) -> Value {
        if let Some(&(_, c)) = self.fconsts.iter().find(|(k, _)| *k == v.to_bits()) {
            return c;
        }
        let c = self.b.ins().f32const(v);
        let c = self.b.ins().splat(F32X4, c);
        self.fconsts.push((v.to_bits(), c));
        c
    }

    /// `clamp(v, 0, 1)`, NaN as 0 (`crate::shade::saturate`).
    pub(super) fn saturate(&mut self, v: Value) -> Value {
        let ordered = self.b.ins().fcmp(FloatCC::Ordered, v, v);
        let zero = self.fconst(0.0);
        let one = self.fconst(1.0);
        let lo = self.b.ins().fmax(v, zero);
        let c = self.b.ins().fmin(lo, one);
        let bits = self.b.ins().bitcast(I32X4, MemFlagsData::new(), c);
        let bits = self.b.ins().band(bits, ordered);
        self.b.ins().bitcast(F32X4, MemFlagsData::new(), bits)
    }

    /// `round_half_even(saturate(v) · max)` as integer lanes (`unorm8`, `unorm_depth`).
    fn unorm_lanes(&mut self, v: Value, max: u32) -> Value {
        let v = self.saturate(v);
        let m = self.fconst(max as f32);
        let v = self.b.ins().fmul(v, m);
        let v = self.b.ins().nearest(v);
        self.b.ins().fcvt_to_uint_sat(I32X4, v)
    }

    /// The bits of `min(max(v, 0), 1)` with SSE's operand order, NaN and -0
    /// as +0 (`DepthFormat::from_window` for `D32F`).
    fn float_depth_lanes(&mut self, v: Value) -> Value {
        let zero = self.fconst(0.0);
        let one = self.fconst(1.0);
        let positive = self.b.ins().fcmp(FloatCC::GreaterThan, v, zero);
        let bits = self.b.ins().bitcast(I32X4, MemFlagsData::new(), v);
        let bits = self.b.ins().band(bits, positive);
        let lo = self.b.ins().bitcast(F32X4, MemFlagsData::new(), bits);
        let below = self.b.ins().fcmp(FloatCC::LessThan, lo, one);
        let one_bits = self.splat(i64::from(1.0f32.to_bits()));
        self.b.ins().bitselect(below, bits, one_bits)
    }

    /// [`Self::unorm_lanes`] for `max < 2^24` in fewer instructions (the
    /// same values: rounding is monotonic, 0 and `max` are exact): `v · max`,
    /// lanes above `max` set to it (one `minps`, NaN kept), rounded
    /// half to even, converted (x86's conversion gives `i32::MIN` for NaN
    /// and negative overflow), negatives to 0.
    /// Without `floor` the negatives are left (for a key whose depth
    /// goes only into `max(z, stored)`, [`Self::depth_write_max_only`]).
    fn unorm_lanes_small(&mut self, v: Value, max: u32, floor: bool) -> Value {
        let m = self.fconst(max as f32);
        let t = self.b.ins().fmul(v, m);
        let t = self.min_const(m, t);
        let r = self.b.ins().nearest(t);
        let i = self.int_lanes(r);
        if !floor {
            return i;
        }
        let zero = self.splat(0);
        self.b.ins().smax(i, zero)
    }

    /// Whether the shaded depth is read only by a `GREATER`/`GEQUAL`
    /// test that writes and is the key's last stage (no stencil ops, no
    /// colour, no count): the test then stores `max(z, stored)` and reads
    /// nothing else ([`Gen::depth_test`]), and as every stored value is at
    /// least 0 a negative `z` (or `i32::MIN` for NaN) leaves `stored` as
    /// 0 would: the conversion's floor at 0 can go (one instruction a
    /// group of the shadow maps' depth-only pass).
    fn depth_write_max_only(&self) -> bool {
        let k = &self.key;
        let stages = k.stages();
        let last_is_depth = matches!(stages.as_slice().last(), Some(crate::key::Stage::DepthTest { .. }));
        last_is_depth
            && !(k.stencil.is_some() && k.stencil_buffer)
            && matches!(k.depth_format, Some(DepthFormat::D16 | DepthFormat::D24))
            && k.depth.is_some_and(|d| {
                d.write
                    && matches!(
                        d.func,
                        crate::key::CompareFunc::Greater | crate::key::CompareFunc::Gequal
                    )
            })
    }

    /// The fog factor of `coord` (`crate::shade::fog_factor`).
    fn fog_factor(&mut self, mode: FogMode, coord: Value, u: Value) -> Value {
        // `SplatUniforms::fog_params` `k`: one vector load.
        let p = |s: &mut Self, k: usize| {
            let off = offset_of!(SplatUniforms, fog_params) + 16 * k;
            s.b.ins().load(F32X4, mem().with_aligned(), u, off as i32)
        };
        let f = match mode {
            FogMode::Linear => {
                let (p0, p1) = (p(self, 0), p(self, 1));
                let t = self.b.ins().fmul(coord, p0);
                self.b.ins().fadd(t, p1)
            }
            FogMode::Exp => {
                // `-(c·p2)` as `c·(-p2)`: the same bits.
                let minus_p2 = p(self, 4);
                let x = self.b.ins().fmul(coord, minus_p2);
                self.exp2(x)
            }
            FogMode::Exp2 => {
                // `-(t·t)` as `t·(c·(-p3))`: the same bits.
                let (p3, minus_p3) = (p(self, 3), p(self, 5));
                let t = self.b.ins().fmul(coord, p3);
                let minus_t = self.b.ins().fmul(coord, minus_p3);
                let x = self.b.ins().fmul(t, minus_t);
                self.exp2(x)
            }
        };
        self.saturate_factor(f)
    }

    /// `clamp(f, 0, 1)` with NaN as 0 by two compares, for the fog factor:
    /// it differs from [`Self::saturate`] only in making −0 +0, which no
    /// colour byte can see (`fog·(1 − f) + c·f` is then ±0 either way, and
    /// both convert to 0).
    fn saturate_factor(&mut self, f: Value) -> Value {
        let one = self.fconst(1.0);
        let zero = self.fconst(0.0);
        let f = self.select_if(FloatCC::GreaterThanOrEqual, f, one);
        let positive = self.b.ins().fcmp(FloatCC::GreaterThan, f, zero);
        let bits = self.b.ins().bitcast(I32X4, MemFlagsData::new(), f);
        let bits = self.b.ins().band(bits, positive);
        self.b.ins().bitcast(F32X4, MemFlagsData::new(), bits)
    }

    /// `bound` in the lanes where `v <cc> bound` (false for NaN), else `v`.
    pub(super) fn select_if(&mut self, cc: FloatCC, v: Value, bound: Value) -> Value {
        let m = self.b.ins().fcmp(cc, v, bound);
        let m = self.b.ins().bitcast(F32X4, MemFlagsData::new(), m);
        self.b.ins().bitselect(m, bound, v)
    }

    /// llvmpipe's `exp2` (`crate::shade::exp2`).
    fn exp2(&mut self, x: Value) -> Value {
        let hi = self.fconst(128.0);
        let lo = self.fconst(-126.99999);
        // The clamp by compares keeps NaN, as the reference does.
        let x = self.select_if(FloatCC::GreaterThan, x, hi);
        let x = self.select_if(FloatCC::LessThan, x, lo);
        let ipart = self.b.ins().floor(x);
        let fpart = self.b.ins().fsub(x, ipart);
        // `ipart` is an integer in `-127..=128` or NaN, and a NaN lane's
        // result is NaN whatever `i` is (its polynomial is): x86's plain
        // conversion (one instruction, `i32::MIN` for NaN) where the
        // saturating one takes seven.
        let i = self.int_lanes(ipart);
        let bias = self.splat(127);
        let i = self.b.ins().iadd(i, bias);
        let i = self.b.ins().ishl_imm_u(i, 23);
        let expipart = self.b.ins().bitcast(F32X4, MemFlagsData::new(), i);
        let c = exp2_coeffs().map(|v| self.fconst(v));
        let x2 = self.b.ins().fmul(fpart, fpart);
        let odd = self.b.ins().fma(x2, c[5], c[3]);
        let odd = self.b.ins().fma(x2, odd, c[1]);
        let even = self.b.ins().fma(x2, c[4], c[2]);
        let even = self.b.ins().fma(x2, even, c[0]);
        let poly = self.b.ins().fma(odd, fpart, even);
        self.b.ins().fmul(expipart, poly)
    }
}
