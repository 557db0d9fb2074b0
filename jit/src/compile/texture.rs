//! Texturing in generated code: each enabled unit's coordinates at the
//! group's lanes and at their 2×2 quads' pixels, from the planes exactly as
//! `crate::shade::tex_coords` computes them (llvmpipe's frame: quads start
//! at even `px` and even `row`); the samples from the reference sampler
//! through the callout (`crate::callout::texture_group`); then the texture
//! environment of every unit in `f32x4`, the same operations as
//! `crate::texture::environment` in the same order, so the bits equal the
//! interpreter's.

use super::sample::{native_unit, Projected};
use super::{mem, Gen, Group, SpanCall, SpanValues};
use crate::callout::{texture_group, TexCall, TexView};
use crate::key::ShadeKey;
use crate::shade::slot;
use crate::texture::lod::needs_lod;
use crate::texture::{CombineFn, CombineKey, CombineSrc, Operand, TexUnitKey, TexelFormat, MAX_UNITS};
use cranelift_codegen::ir::{types, AbiParam, InstBuilder, Signature, StackSlot, StackSlotData, StackSlotKind, Value};
use std::mem::{offset_of, size_of};

const F32X4: cranelift_codegen::ir::Type = types::F32X4;

/// Four channels of four lanes.
type Rgba = [Value; 4];

impl Gen<'_> {
    /// The colour after the texture environment of `key`'s units over
    /// `primary` (`crate::shade::texture`).
    pub(super) fn texture(&mut self, g: &Group, sv: &SpanValues, key: &ShadeKey, primary: Rgba) -> Rgba {
        let mask = |f: &dyn Fn(&TexUnitKey) -> bool| -> u32 {
            (0..MAX_UNITS)
                .filter(|&u| key.tex[u].as_ref().is_some_and(f))
                .map(|u| 1 << u)
                .sum()
        };
        let native = if self.native_sampling { mask(&native_unit) } else { 0 };
        let called = mask(&|_| true) & !native;
        let view = self
            .b
            .ins()
            .load(self.ptr, mem(), sv.call, offset_of!(SpanCall, tex) as i32);
        let mut samples = [None; MAX_UNITS];
        if called != 0 {
            let slot = self.tex_slot();
            let args = self.b.ins().stack_addr(self.ptr, slot, 0);
            samples = self.call_sampler(g, sv, (args, called), view);
        }
        if native != 0 {
            let lod = key
                .tex
                .iter()
                .flatten()
                .any(|t| native_unit(t) && needs_lod(&t.sampler));
            let mut shared = None;
            for (u, unit) in key.tex.iter().enumerate() {
                if let Some(unit) = unit.as_ref().filter(|t| native_unit(t)) {
                    if unit.sampler.format == TexelFormat::Depth32F {
                        // No λ: the lanes' own s, t and r.
                        let c = match sv.tex_one[u] {
                            Some(flag) => self.diamond(
                                flag,
                                |s| s.plain_depth_coords(g, sv, u),
                                |s| {
                                    let points = s.native_points(g, sv, false);
                                    s.project_depth(sv, u, points[0]).to_vec()
                                },
                            ),
                            None => {
                                let points = match &shared {
                                    Some(p) => p,
                                    None => shared.insert(self.native_points(g, sv, lod)),
                                };
                                let lane = points[0];
                                self.project_depth(sv, u, lane).to_vec()
                            }
                        };
                        samples[u] = Some(self.sample_depth(u, &unit.sampler, view, [c[0], c[1], c[2]]));
                        continue;
                    }
                    let quad = needs_lod(&unit.sampler);
                    let c = match sv.tex_one[u] {
                        // w and q/w exactly 1 over the span: s and t are the
                        // planes' values, without the divisions by 1/w at
                        // the lanes and their quads and by q (the `tex`
                        // frame's trilinear unit: 7 divisions and 24
                        // instructions fewer a group).
                        Some(flag) => {
                            let v = self.diamond(
                                flag,
                                |s| s.plain_coords(g, sv, u, quad),
                                |s| {
                                    let points = s.native_points(g, sv, lod);
                                    s.project(sv, u, &points, quad).flat()
                                },
                            );
                            Projected::from_flat(&v)
                        }
                        None => {
                            let points = match &shared {
                                Some(p) => p,
                                None => shared.insert(self.native_points(g, sv, lod)),
                            };
                            let points = points.clone();
                            self.project(sv, u, &points, quad)
                        }
                    };
                    samples[u] = Some(self.sample_native((g, sv), (u, &unit.sampler), view, &c));
                }
            }
        }
        self.environment(key, view, &samples, primary)
    }

    /// The span's planes, and the lanes' pixels (x, y) followed, with
    /// `quad`, by the top-left, top-right and bottom-left pixels of their quads.
    fn lane_points(&mut self, g: &Group, sv: &SpanValues, quad: bool) -> (Value, Vec<(Value, Value)>) {
        let (planes, row, _) = sv.planes.expect("loaded for keys with a shading stage");
        let px = g.px.expect("carried by the loop for keys with a shading stage");
        let mut pts = vec![(px, row)];
        if quad {
            let one = self.fconst(1.0);
            let (qx, _) = self.even(px);
            let (qy, _) = self.even(row);
            let qx1 = self.b.ins().fadd(qx, one);
            let qy1 = self.b.ins().fadd(qy, one);
            pts.extend([(qx, qy), (qx1, qy), (qx, qy1)]);
        }
        (planes, pts)
    }

    /// The lanes' pixels and, with `quad`, the top-left, top-right and
    /// bottom-left pixels of their quads, each with its w.
    fn native_points(&mut self, g: &Group, sv: &SpanValues, quad: bool) -> Vec<(Value, Value, Value)> {
        let (planes, pts) = self.lane_points(g, sv, quad);
        pts.into_iter()
            .enumerate()
            .map(|(p, (x, y))| match g.w.filter(|_| p == 0) {
                // The lanes' own w, as the shading stage made it.
                Some(w) => (x, y, w),
                None => {
                    let one = self.fconst(1.0);
                    let iw = self.plane(planes, slot::INV_W, x, y);
                    (x, y, self.b.ins().fdiv(one, iw))
                }
            })
            .collect()
    }

    /// Unit `u`'s s and t planes at the lanes and, with `quad`, at their
    /// quads' top-left, top-right and bottom-left pixels (the points of
    /// [`Self::native_points`]), as [`Projected::flat`] lists them: what
    /// [`Self::project`] makes when w and q/w are exactly 1.
    fn plain_coords(&mut self, g: &Group, sv: &SpanValues, u: usize, quad: bool) -> Vec<Value> {
        let (planes, pts) = self.lane_points(g, sv, quad);
        pts.into_iter()
            .flat_map(|(x, y)| [0, 1].map(|k| self.plane(planes, slot::tex(u) + k, x, y)))
            .collect()
    }

    /// Unit `u`'s s, t and r planes at the lanes: what
    /// [`Self::project_depth`] makes when w and q/w are exactly 1.
    fn plain_depth_coords(&mut self, g: &Group, sv: &SpanValues, u: usize) -> Vec<Value> {
        let (planes, pts) = self.lane_points(g, sv, false);
        let (x, y) = pts[0];
        (0..3).map(|k| self.plane(planes, slot::tex(u) + k, x, y)).collect()
    }

    /// Unit `u`'s s, t and r at the lanes' `point`, projected (`c·(1/q)`,
    /// each `c` its plane's value times w: `crate::texture::QuadSample::new`).
    fn project_depth(&mut self, sv: &SpanValues, u: usize, (x, y, w): (Value, Value, Value)) -> [Value; 3] {
        let (planes, _, _) = sv.planes.expect("loaded for keys with a shading stage");
        let c = [0, 1, 2, 3].map(|k| {
            let v = self.plane(planes, slot::tex(u) + k, x, y);
            self.b.ins().fmul(v, w)
        });
        let one = self.fconst(1.0);
        let inv = self.b.ins().fdiv(one, c[3]);
        [0, 1, 2].map(|k| self.b.ins().fmul(c[k], inv))
    }

    /// Unit `u`'s s and t at `points`, projected (`s·(1/q)`, Mesa's TXP).
    fn project(&mut self, sv: &SpanValues, u: usize, points: &[(Value, Value, Value)], quad: bool) -> Projected {
        let (planes, _, _) = sv.planes.expect("loaded for keys with a shading stage");
        let at = |s: &mut Self, (x, y, w): (Value, Value, Value)| {
            let mut c = [0, 1, 3].map(|k| {
                let v = s.plane(planes, slot::tex(u) + k, x, y);
                s.b.ins().fmul(v, w)
            });
            let one = s.fconst(1.0);
            let inv = s.b.ins().fdiv(one, c[2]);
            for v in &mut c[..2] {
                *v = s.b.ins().fmul(*v, inv);
            }
            [c[0], c[1]]
        };
        Projected {
            at: at(self, points[0]),
            quad: (quad && points.len() == 4).then(|| [1, 2, 3].map(|p| at(self, points[p]))),
        }
    }

    /// Natively sampled unit `u` through the reference sampler (a group
    /// whose lanes λ puts on different levels).
    pub(super) fn sample_called(&mut self, g: &Group, sv: &SpanValues, u: usize, view: Value) -> Rgba {
        let slot = self.tex_slot();
        let args = self.b.ins().stack_addr(self.ptr, slot, 0);
        self.call_sampler(g, sv, (args, 1 << u), view)[u].expect("unit u was sampled")
    }

    /// Calls the reference sampler for the units of `units` at the group's
    /// lanes, with their coordinates at the lanes' quads evaluated here as
    /// the interpreter does (`crate::shade::quad_coords`); their samples.
    fn call_sampler(
        &mut self,
        g: &Group,
        sv: &SpanValues,
        (args, units): (Value, u32),
        view: Value,
    ) -> [Option<Rgba>; MAX_UNITS] {
        let (planes, row, _) = sv.planes.expect("loaded for keys with a shading stage");
        let px = g.px.expect("carried by the loop for keys with a shading stage");
        let store = |s: &mut Self, v: Value, off: usize| s.b.ins().store(mem(), v, args, off as i32);
        store(self, px, offset_of!(TexCall, px));
        store(self, row, offset_of!(TexCall, row));
        store(self, view, offset_of!(TexCall, view));
        let live = match g.live {
            Some(live) => self.b.ins().vhigh_bits(types::I32, live),
            None => g.bits,
        };
        store(self, live, offset_of!(TexCall, live));
        let mask = self.b.ins().iconst(types::I32, i64::from(units));
        store(self, mask, offset_of!(TexCall, units));
        // Each unit's coordinates at the pixels of each lane's quad
        // (`TexCall::coords`), `crate::shade::tex_coords` with the
        // instruction: the callout's own took libm `fmaf` calls.
        let one = self.fconst(1.0);
        let (qx, _) = self.even(px);
        let (qy, _) = self.even(row);
        let qx1 = self.b.ins().fadd(qx, one);
        let qy1 = self.b.ins().fadd(qy, one);
        for (k, (x, y)) in [(qx, qy), (qx1, qy), (qx, qy1), (qx1, qy1)].into_iter().enumerate() {
            let iw = self.plane(planes, slot::INV_W, x, y);
            let one = self.fconst(1.0);
            let w = self.b.ins().fdiv(one, iw);
            for u in (0..MAX_UNITS).filter(|u| units & (1 << u) != 0) {
                for c in 0..4 {
                    let v = self.plane(planes, slot::tex(u) + c, x, y);
                    let v = self.b.ins().fmul(v, w);
                    let off = offset_of!(TexCall, coords) + ((u * 4 + k) * 4 + c) * 16;
                    store(self, v, off);
                }
            }
        }
        let mut sig = Signature::new(self.b.func.signature.call_conv);
        sig.params.push(AbiParam::new(self.ptr));
        let sig = self.b.import_signature(sig);
        let callee = texture_group as unsafe extern "C" fn(*mut TexCall) as usize as i64;
        let callee = self.b.ins().iconst(self.ptr, callee);
        self.b.ins().call_indirect(sig, callee, &[args]);
        // Values made before the call would live across it (spilled): make
        // the constants again.
        self.consts.clear();
        self.fconsts.clear();
        std::array::from_fn(|u| {
            (units & (1 << u) != 0).then(|| {
                std::array::from_fn(|c| {
                    let off = offset_of!(TexCall, samples) + (u * 4 + c) * 16;
                    self.b.ins().load(F32X4, mem(), args, off as i32)
                })
            })
        })
    }

    /// The environment of every enabled unit, in order
    /// (`crate::texture::environment`).
    fn environment(&mut self, key: &ShadeKey, view: Value, samples: &[Option<Rgba>; MAX_UNITS], primary: Rgba) -> Rgba {
        let mut previous = primary;
        for (u, unit) in key.tex.iter().enumerate() {
            let Some(unit) = unit else { continue };
            let mut env_color = None;
            let mut source = |s: &mut Self, src: CombineSrc| -> Rgba {
                match src {
                    CombineSrc::Texture => samples[u].expect("every enabled unit is sampled"),
                    CombineSrc::TextureUnit(n) => match samples.get(n as usize) {
                        Some(Some(t)) => *t,
                        _ => [s.fconst(0.0); 4],
                    },
                    CombineSrc::Constant => *env_color.get_or_insert_with(|| {
                        std::array::from_fn(|c| {
                            let off = offset_of!(TexView<'static>, env_color) + (u * 4 + c) * 16;
                            s.b.ins().load(F32X4, mem(), view, off as i32)
                        })
                    }),
                    CombineSrc::PrimaryColor => primary,
                    CombineSrc::Previous => previous,
                }
            };
            previous = self.combine(&unit.env, &mut source);
        }
        previous
    }

    /// One unit's combine (`crate::texture::env::combine`).
    fn combine(&mut self, k: &CombineKey, source: &mut impl FnMut(&mut Self, CombineSrc) -> Rgba) -> Rgba {
        // Both scales apply to every function, DOT3 included.
        let (rgb_shift, alpha_shift) = (k.scale_rgb, k.scale_alpha);
        // The operands a function reads, in the channels it reads.
        let mut args = |s: &mut Self, f: CombineFn, srcs: [CombineSrc; 3], ops: [Operand; 3], channels: &[usize]| {
            let mut a = [[None; 4]; 3];
            for i in 0..arity(f) {
                let c = source(s, srcs[i]);
                for &ch in channels {
                    a[i][ch] = Some(s.operand(ops[i], c, ch));
                }
            }
            a
        };
        let a = args(self, k.rgb, k.src_rgb, k.op_rgb, &[0, 1, 2]);
        let rgb = self.function(k.rgb, &a, &[0, 1, 2]);
        let alpha = if k.rgb == CombineFn::Dot3Rgba {
            rgb[3]
        } else {
            let a = args(self, k.alpha, k.src_alpha, k.op_alpha, &[3]);
            self.function(k.alpha, &a, &[3])[3]
        };
        let mut out = [rgb[0], rgb[1], rgb[2], alpha];
        let alpha_fn = if k.rgb == CombineFn::Dot3Rgba { k.rgb } else { k.alpha };
        for (c, v) in out.iter_mut().enumerate() {
            let (shift, f) = if c < 3 {
                (rgb_shift, k.rgb)
            } else {
                (alpha_shift, alpha_fn)
            };
            if rgb_shift != 1 || alpha_shift != 1 {
                // A scale saturates all four channels after the multiply (by
                // 1 the identity, which saturation does not see).
                if shift != 1 {
                    let s = self.fconst(f32::from(shift));
                    *v = self.b.ins().fmul(*v, s);
                }
                *v = self.saturate(*v);
            } else if needs_saturate(f) {
                *v = self.saturate(*v);
            }
        }
        out
    }

    /// Channel `ch` of operand `op` of colour `c`.
    fn operand(&mut self, op: Operand, c: Rgba, ch: usize) -> Value {
        let one = self.fconst(1.0);
        match op {
            Operand::SrcColor => c[ch],
            Operand::OneMinusSrcColor => self.b.ins().fsub(one, c[ch]),
            Operand::SrcAlpha => c[3],
            Operand::OneMinusSrcAlpha => self.b.ins().fsub(one, c[3]),
        }
    }

    /// Function `f` of three operands in `channels` (`crate::texture::env`'s
    /// `function`); DOT3 puts its scalar in every channel.
    fn function(&mut self, f: CombineFn, a: &[[Option<Value>; 4]; 3], channels: &[usize]) -> Rgba {
        let zero = self.fconst(0.0);
        let mut out = [zero; 4];
        let arg = |i: usize, ch: usize| a[i][ch].expect("operands made for the function's channels");
        if let CombineFn::Dot3Rgb | CombineFn::Dot3Rgba = f {
            let two = self.fconst(2.0);
            let minus_one = self.fconst(-1.0);
            let signed = |s: &mut Self, i: usize, ch: usize| {
                let v = s.b.ins().fmul(arg(i, ch), two);
                s.b.ins().fadd(v, minus_one)
            };
            let (s0, s1, s2) = (signed(self, 0, 0), signed(self, 0, 1), signed(self, 0, 2));
            let (t0, t1, t2) = (signed(self, 1, 0), signed(self, 1, 1), signed(self, 1, 2));
            let p2 = self.b.ins().fmul(s2, t2);
            let p1 = self.b.ins().fmul(s1, t1);
            let sum = self.b.ins().fadd(p2, p1);
            let p0 = self.b.ins().fmul(s0, t0);
            let dot = self.b.ins().fadd(sum, p0);
            return [dot; 4];
        }
        for &ch in channels {
            let x = arg(0, ch);
            if f == CombineFn::Replace {
                out[ch] = x;
                continue;
            }
            let y = arg(1, ch);
            out[ch] = match f {
                CombineFn::Replace => x,
                CombineFn::Modulate => self.b.ins().fmul(x, y),
                CombineFn::Add => self.b.ins().fadd(x, y),
                CombineFn::AddSigned => {
                    // `(x + -0.5) + y`, the order NIR's algebraic pass leaves.
                    let h = self.fconst(-0.5);
                    let v = self.b.ins().fadd(x, h);
                    self.b.ins().fadd(v, y)
                }
                CombineFn::Interpolate => {
                    let z = arg(2, ch);
                    let one = self.fconst(1.0);
                    let xz = self.b.ins().fmul(x, z);
                    let iz = self.b.ins().fsub(one, z);
                    let yz = self.b.ins().fmul(y, iz);
                    self.b.ins().fadd(xz, yz)
                }
                CombineFn::Subtract => self.b.ins().fsub(x, y),
                CombineFn::Dot3Rgb | CombineFn::Dot3Rgba => unreachable!("handled above"),
            };
        }
        out
    }

    /// The function's [`TexCall`] stack slot, made on first use.
    fn tex_slot(&mut self) -> StackSlot {
        if let Some(s) = self.tex_slot {
            return s;
        }
        let data = StackSlotData::new(StackSlotKind::ExplicitSlot, size_of::<TexCall>() as u32, 4);
        let s = self.b.create_sized_stack_slot(data);
        self.tex_slot = Some(s);
        s
    }

    /// `v - (v & 1)` of lanes holding non-negative integers
    /// (`crate::shade::quad_origin`), and `v & 1` as integer lanes.
    fn even(&mut self, v: Value) -> (Value, Value) {
        let i = self.int_lanes(v);
        let one = self.splat(1);
        let odd = self.b.ins().band(i, one);
        let oddf = self.b.ins().fcvt_from_sint(F32X4, odd);
        (self.b.ins().fsub(v, oddf), odd)
    }
}

/// How many operands function `f` reads.
fn arity(f: CombineFn) -> usize {
    match f {
        CombineFn::Replace => 1,
        CombineFn::Modulate
        | CombineFn::Add
        | CombineFn::AddSigned
        | CombineFn::Subtract
        | CombineFn::Dot3Rgb
        | CombineFn::Dot3Rgba => 2,
        CombineFn::Interpolate => 3,
    }
}

/// Whether a function's result is clamped (`crate::texture::env`'s `needs_saturate`).
fn needs_saturate(f: CombineFn) -> bool {
    match f {
        CombineFn::Replace | CombineFn::Modulate | CombineFn::Interpolate => false,
        CombineFn::Add | CombineFn::AddSigned | CombineFn::Subtract | CombineFn::Dot3Rgb | CombineFn::Dot3Rgba => true,
    }
}
