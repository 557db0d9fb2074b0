//! Per-vertex lighting (GL 1.5 §2.14), in f32 as llvmpipe runs Mesa's
//! fixed-function vertex program (`main/ffvertex_prog.c` through
//! `prog_to_nir` and gallivm): the same space (object space when Mesa's
//! `_NeedEyeCoords` is false), the same operation order (a `DP3` is
//! `(z·z' + y·y') + x·x'` once NIR scalarizes it, a `MAD` is an unfused
//! multiply then add), the same derived constants computed on the CPU, and
//! gallivm's `pow` as `exp2(log2(x)·y)` with its polynomial approximations.
//! `docs/llvmpipe-facts.md` §§ "Vertex lighting" records each fact and its file.
//!
//! [`LightSetup`] holds what one draw needs, derived once from the state;
//! [`LightSetup::light`] lights one vertex (the general path) and
//! [`LightSetup::light_batch`] a batch, through a fast path when every enabled
//! light is infinite, without spot, and the viewer is not local (the common
//! case), whose output equals the general path's bit for bit (tested).
//!
//! [`LightSetup::light_many`] is that fast path for [`CHUNK`] vertices at
//! once (without `GL_COLOR_MATERIAL`), the vertex loop innermost and the
//! values in arrays, one per component, so that the compiler vectorizes it
//! across vertices; each vertex still sees the same f32 operations in the
//! same order, so the bits are the per-vertex path's (tested, NaN and
//! infinite normals included). Measured on the lit16 frame (callgrind, one
//! infinite light): 31 instructions a vertex, where the per-vertex call
//! (`transform_slots`, lighting then fog, texture and position) took 234.
//! The specular power keeps gallivm's `exp2(log2(x)·y)` polynomials at every
//! shininess: a shortcut for common exponents would have to give the
//! polynomials' bits, not the exact power. (The benchmark frames have
//! shininess 0, which takes Mesa's shortcut and computes no power.) Its
//! `fmuladd` steps use the inline [`super::fma`], not an `fmaf` call.
//!
//! The general path (positional or spot lights, local viewer: MuJoCo's
//! state) costs about 1,800 instructions a vertex with three lights, four
//! `pow`s among them. Its callers light less rather than faster
//! ([`super::batch`]): a vertex is lit only when a primitive that is drawn
//! needs it (not for a triangle trivially rejected), and once a draw for
//! each distinct input (`LitCache`). On MuJoCo's floor plane
//! (`osmesa/bench/mujoco_passes.c`, 160,000 vertices, callgrind) the draw
//! went from 2,640 instructions a vertex to 192; the colours are this
//! path's, bit for bit.

use super::fma::fma;
use crate::lighting::{ColorControl, ColorMaterialMode, LightingState, Material, MAX_LIGHTS};
use crate::state::Face;
use glam::{Mat4, Vec3, Vec4};

/// What lighting reads of one vertex: object position, normal, and the
/// colour (the material values `glColorMaterial` names, when on).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightInput {
    pub pos: Vec4,
    pub normal: Vec3,
    pub color: Vec4,
}

/// Lit colours of one vertex, clamped to `[0, 1]`: front and back (the back
/// ones only with two-sided lighting), primary and secondary (the secondary
/// ones only with `GL_SEPARATE_SPECULAR_COLOR`, else zero).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LitColors {
    pub front: [f32; 4],
    pub front_secondary: [f32; 4],
    pub back: [f32; 4],
    pub back_secondary: [f32; 4],
}

pub type V3 = [f32; 3];

/// Vertices [`LightSetup::light_many`] lights at once.
pub const CHUNK: usize = 64;

/// The clamped colours of [`CHUNK`] vertices lit by
/// [`LightSetup::light_many`], one array per side (front, back), colour
/// (primary, secondary), channel (r, g, b).
pub struct ManyLit {
    acc: [[[[f32; CHUNK]; 3]; 2]; 2],
}

impl Default for ManyLit {
    fn default() -> Self {
        ManyLit {
            acc: [[[[0.0; CHUNK]; 3]; 2]; 2],
        }
    }
}

/// NIR's scalarized `fdot3`: `(a.z·b.z + a.y·b.y) + a.x·b.x`.
#[inline(always)]
pub fn dp3(a: V3, b: V3) -> f32 {
    a[2] * b[2] + a[1] * b[1] + a[0] * b[0]
}

/// Mesa's C `DOT3`: `(a.x·b.x + a.y·b.y) + a.z·b.z`.
fn dot3_c(a: V3, b: V3) -> f32 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// Mesa's `NORMALIZE_3FV` (on the CPU): unchanged when the length is 0.
fn normalize_c(v: V3) -> V3 {
    let len = dot3_c(v, v);
    if len == 0.0 {
        return v;
    }
    let s = 1.0 / len.sqrt();
    v.map(|c| c * s)
}

/// gallivm's `lp_build_rsqrt`: `1 / sqrt(|x|)`, both IEEE (the fast
/// `rsqrtps` path is compiled out); `prog_to_nir` adds the `fabs`.
#[inline(always)]
pub fn rsq(x: f32) -> f32 {
    1.0 / x.abs().sqrt()
}

/// The program's `emit_normalize_vec3`: `DP3`, `RSQ`, `MUL`.
#[inline(always)]
pub fn normalize_vp(v: V3) -> V3 {
    normalize_len(v).0
}

/// `v·v` at or above this (2^-100) took no denormal step: its terms are not
/// negative, so a denormal product (< 2^-126) was below half an ulp of the
/// sum, and flushing it changes nothing.
const FTZ_SAFE: f32 = 7.888_609e-31;

/// `DP3(v, v)`, `RSQ` and `MUL` as llvmpipe's vertex stage runs them, with
/// the x86 flush-to-zero and denormals-are-zero modes that `draw_vbo` sets
/// (`util_fpstate_set_denorms_to_zero`, `draw_pt.c`; docs/llvmpipe-facts.md
/// "Denormals in the vertex stage"): the normalized vector, `v·v` and its
/// `rsq`. Only a vector shorter than 2^-50 can see a denormal, so the
/// flushing arithmetic runs only for those ([`normalize_flushed`]).
#[inline(always)]
fn normalize_len(v: V3) -> (V3, f32, f32) {
    let d2 = dp3(v, v);
    if d2 < FTZ_SAFE {
        return normalize_flushed(v);
    }
    let s = rsq(d2);
    (v.map(|c| c * s), d2, s)
}

/// A denormal as the FTZ and DAZ modes see it: zero of its sign.
fn flush(x: f32) -> f32 {
    if x.is_subnormal() {
        0.0f32.copysign(x)
    } else {
        x
    }
}

/// [`normalize_len`] with every operand and result flushed: a normal of
/// length 1e-20 has `v·v` = 1e-40, a denormal, hence 0 and an infinite
/// `rsq`, so the normalized vector is infinite (NaN where a component is 0).
#[cold]
fn normalize_flushed(v: V3) -> (V3, f32, f32) {
    let v = v.map(flush);
    let sq = |k: usize| flush(v[k] * v[k]);
    let d2 = flush(flush(sq(2) + sq(1)) + sq(0));
    let s = rsq(d2);
    (v.map(|c| flush(c * s)), d2, s)
}

fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// gallivm's `lp_build_polynomial`: even and odd terms in `x²`, each step a
/// `fmuladd`, which LLVM fuses on a CPU with FMA (`lp_bld_arit.c`). `N`
/// coefficients (at least 2), rounded to f32 as `lp_build_const_vec` does.
#[inline(always)]
fn polynomial<const N: usize>(x: f32, coeffs: &[f64; N]) -> f32 {
    let x2 = x * x;
    let c = |i: usize| coeffs[i] as f32;
    // The highest even and odd coefficients start their chains.
    let (top_even, top_odd) = if N % 2 == 1 { (N - 1, N - 2) } else { (N - 2, N - 1) };
    let mut even = c(top_even);
    let mut i = top_even;
    while i >= 2 {
        i -= 2;
        even = fma(x2, even, c(i));
    }
    let mut odd = c(top_odd);
    let mut i = top_odd;
    while i >= 3 {
        i -= 2;
        odd = fma(x2, odd, c(i));
    }
    fma(odd, x, even)
}

/// `lp_build_exp2_polynomial` (degree 5), Mesa's literals as written.
#[allow(clippy::excessive_precision)]
const EXP2_POLY: [f64; 6] = [
    1.000000000000000000000,
    0.693153073200168932794,
    0.240153617044375388211,
    0.0558263180532956664775,
    0.00898934009049466391101,
    0.00187757667519147912699,
];

/// `lp_build_log2_polynomial` (degree 4), Mesa's literals as written.
#[allow(clippy::excessive_precision)]
const LOG2_POLY: [f64; 5] = [
    2.88539009343309178325,
    0.961791550404184197881,
    0.577440339438736392009,
    0.403343858251329912514,
    0.406718052498846252698,
];

/// gallivm's `lp_build_exp2`: `x` clamped to `[-126.99999, 128]` (NaN
/// kept), `2^floor(x)` built in the exponent bits times a polynomial of the
/// fraction.
pub fn lp_exp2(x: f32) -> f32 {
    let x = if x.is_nan() { x } else { x.clamp(-126.99999, 128.0) };
    let ipart = x.floor();
    let fpart = x - ipart;
    // fptosi of NaN is 0x80000000 on x86 (cvttps2dq).
    let i = if ipart.is_nan() { i32::MIN } else { ipart as i32 };
    let expipart = f32::from_bits((i.wrapping_add(127) as u32) << 23);
    expipart * polynomial(fpart, &EXP2_POLY)
}

/// gallivm's `lp_build_log2_safe`: exponent plus `y·P(y²)`,
/// `y = (m − 1)/(m + 1)`; `+inf` for `+inf`, `-inf` for 0, NaN below 0.
pub fn lp_log2_safe(x: f32) -> f32 {
    let i = x.to_bits();
    let logexp = (((i & 0x7f80_0000) >> 23) as i32 - 127) as f32;
    let mant = f32::from_bits((i & 0x007f_ffff) | 1.0f32.to_bits());
    let y = (mant - 1.0) / (mant + 1.0);
    let p = polynomial(y * y, &LOG2_POLY);
    let mut res = fma(y, p, logexp);
    if x >= f32::INFINITY {
        res = f32::INFINITY;
    }
    if x == 0.0 {
        res = f32::NEG_INFINITY;
    }
    if x < 0.0 {
        res = f32::NAN;
    }
    res
}

/// gallivm's `lp_build_pow`: `exp2(log2(x)·y)`, and 0 when `x == 0`
/// (so `0^0` is 0 there, not GL's 1).
pub fn lp_pow(x: f32, y: f32) -> f32 {
    if x == 0.0 {
        0.0
    } else {
        lp_exp2(lp_log2_safe(x) * y)
    }
}

/// `prog_to_nir`'s `LIT`: `(1, max(x, 0), x <= 0 ? 0 : pow(max(y, 0), clamp(w, ±128)), 1)`.
#[inline(always)]
fn lit(x: f32, y: f32, w: f32) -> [f32; 3] {
    let z = if 0.0 >= x {
        0.0
    } else {
        lp_pow(y.max(0.0), w.clamp(-128.0, 128.0))
    };
    [1.0, x.max(0.0), z]
}

/// Which material values of a side come from the vertex colour.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct FromColor {
    emission: bool,
    ambient: bool,
    diffuse: bool,
    specular: bool,
}

/// One side's material as the program sees it.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Side {
    emission: [f32; 4],
    ambient: [f32; 4],
    diffuse: [f32; 4],
    specular: [f32; 4],
    shininess: f32,
    from_color: FromColor,
}

impl Side {
    fn from_material(m: &Material, from_color: FromColor) -> Side {
        Side {
            emission: m.emission,
            ambient: m.ambient,
            diffuse: m.diffuse,
            specular: m.specular,
            shininess: m.shininess,
            from_color,
        }
    }

    /// The material values for a vertex of colour `c`.
    #[inline(always)]
    fn values(&self, c: [f32; 4]) -> [[f32; 4]; 4] {
        let f = self.from_color;
        let pick = |from: bool, v: [f32; 4]| if from { c } else { v };
        [
            pick(f.emission, self.emission),
            pick(f.ambient, self.ambient),
            pick(f.diffuse, self.diffuse),
            pick(f.specular, self.specular),
        ]
    }
}

/// The derived constants of one enabled light (`gl_light._Position`, …).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct LightConst {
    /// Position (divided by w when positional), eye or object space.
    position: V3,
    positional: bool,
    /// `STATE_LIGHT_POSITION_NORMALIZED` (infinite lights).
    vp_inf: V3,
    /// `STATE_LIGHT_HALF_VECTOR` (infinite lights, non-local viewer).
    half_inf: V3,
    /// Normalized spot direction, cosine of the cutoff, exponent.
    spot: Option<(V3, f32, f32)>,
    /// Constant, linear, quadratic: only for a positional light whose
    /// attenuation is not (1, 0, 0).
    attenuation: Option<V3>,
    /// Light colours: ambient, diffuse, specular.
    colors: [[f32; 4]; 3],
}

/// How normals are brought into the lighting space.
#[derive(Clone, Copy, Debug, PartialEq)]
enum NormalFix {
    None,
    Normalize,
    Rescale(f32),
}

/// The program's `get_transformed_normal` (`main/ffvertex_prog.c`): in eye
/// space the rows of the inverse transpose of the modelview, then
/// `GL_NORMALIZE` or `GL_RESCALE_NORMAL` as the state says. Lighting and
/// texture coordinate generation share it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NormalTransform {
    eye_space: bool,
    /// Rows of the inverse transpose of the modelview's upper 3x3.
    rows: [V3; 3],
    fix: NormalFix,
}

impl NormalTransform {
    /// Normals for `state` under the modelview `mv`, brought to eye space
    /// when `eye_space` (Mesa's `_NeedEyeCoords`), else left in object space.
    pub fn new(state: &LightingState, mv: &Mat4, eye_space: bool) -> NormalTransform {
        let inv = crate::inverse::inverse(mv).to_cols_array();
        // Row r of the inverse transpose is column r of the inverse.
        let rows = [0, 1, 2].map(|r| [inv[4 * r], inv[4 * r + 1], inv[4 * r + 2]]);
        let fix = if state.normalize {
            NormalFix::Normalize
        } else if eye_space && state.rescale_normal {
            // update_modelview_scale: 1/sqrt of the inverse's third row.
            let scale = if length_preserving(mv) {
                1.0
            } else {
                let mut f = inv[2] * inv[2] + inv[6] * inv[6] + inv[10] * inv[10];
                if f < 1e-12 {
                    f = 1.0;
                }
                1.0 / f.sqrt()
            };
            NormalFix::Rescale(scale)
        } else {
            NormalFix::None
        };
        NormalTransform { eye_space, rows, fix }
    }

    /// The normal `n` in the space chosen, fixed up as the state says.
    #[inline(always)]
    pub fn apply(&self, n: Vec3) -> V3 {
        let n = n.to_array();
        let n = if self.eye_space {
            self.rows.map(|row| dp3(n, row))
        } else {
            n
        };
        match self.fix {
            NormalFix::None => n,
            NormalFix::Normalize => normalize_vp(n),
            NormalFix::Rescale(s) => n.map(|c| c * s),
        }
    }
}

/// Everything one draw's lighting needs, derived once from the state.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightSetup {
    /// Mesa's `_NeedEyeCoords`: light in eye space; else in object space.
    eye_space: bool,
    modelview: Mat4,
    normal: NormalTransform,
    /// The enabled lights, in index order: the first `count`.
    lights: [LightConst; MAX_LIGHTS],
    count: usize,
    sides: [Side; 2],
    model_ambient: [f32; 4],
    two_side: bool,
    separate: bool,
    local_viewer: bool,
    /// Mesa's `material_shininess_is_zero` (decided from the state).
    shininess_zero: bool,
    /// Light products `light · material` per light, side and term
    /// (ambient, diffuse, specular), alpha the material's.
    products: [[[[f32; 4]; 3]; 2]; MAX_LIGHTS],
    fast: bool,
    /// Whether a side takes a material value from the vertex colour
    /// (`GL_COLOR_MATERIAL`); when not, `mats` and `scene` are the same at
    /// every vertex and the fast path reads them from here.
    color_material: bool,
    /// Each side's material values ([`Side::values`]) when no colour is read.
    mats: [[[f32; 4]; 4]; 2],
    /// Each side's scene colour ([`LightSetup::scene`]) when no colour is read.
    scene: [[f32; 4]; 2],
}

pub use crate::inverse::length_preserving;

impl LightSetup {
    /// The constants for drawing with `state` under the modelview `mv`.
    pub fn new(state: &LightingState, mv: &Mat4) -> LightSetup {
        LightSetup::with_eye_coords(state, mv, false)
    }

    /// [`LightSetup::new`] in eye space when `force_eye`: Mesa lights in eye
    /// space whenever `_NeedEyeCoords` is set, which texture coordinate
    /// generation needing eye coordinates also sets (`_mesa_update_tnl_spaces`).
    pub fn with_eye_coords(state: &LightingState, mv: &Mat4, force_eye: bool) -> LightSetup {
        let enabled: Vec<(usize, &crate::lighting::Light)> =
            state.lights.iter().enumerate().filter(|(_, l)| l.enabled).collect();
        let positional = enabled.iter().any(|(_, l)| l.position[3] != 0.0);
        let spot = enabled.iter().any(|(_, l)| l.spot_cutoff != 180.0);
        let separate = state.color_control == ColorControl::SeparateSpecular;
        // main/light.c: _mesa_update_lighting and _mesa_update_tnl_spaces.
        let need_vertices = positional || spot || separate || state.local_viewer;
        let eye_space = force_eye || need_vertices || !length_preserving(mv);
        let inv = crate::inverse::inverse(mv).to_cols_array();
        let mvc = mv.to_cols_array();
        // compute_light_positions: _EyeZDir is (0, 0, 1) in eye space, the
        // modelview's third row (TRANSFORM_NORMAL of (0, 0, 1)) in object space.
        let eye_z = if eye_space {
            [0.0, 0.0, 1.0]
        } else {
            [0, 4, 8].map(|k| 0.0 * mvc[k] + 0.0 * mvc[k + 1] + 1.0 * mvc[k + 2])
        };
        let list: Vec<LightConst> = enabled
            .iter()
            .map(|(_, l)| {
                let mut p = if eye_space {
                    l.position
                } else {
                    crate::lighting::transform_point(&Mat4::from_cols_array(&inv), l.position)
                };
                let is_positional = l.position[3] != 0.0;
                if is_positional {
                    let w_inv = 1.0 / p[3];
                    p = [p[0] * w_inv, p[1] * w_inv, p[2] * w_inv, p[3]];
                }
                let pos = [p[0], p[1], p[2]];
                let vp_inf = normalize_c(pos);
                let half_inf = {
                    let h = [vp_inf[0] + eye_z[0], vp_inf[1] + eye_z[1], vp_inf[2] + eye_z[2]];
                    normalize_c(h)
                };
                let spot = (l.spot_cutoff != 180.0).then(|| {
                    let d = normalize_c(normalize_c(l.spot_direction));
                    (d, l.cos_cutoff(), l.spot_exponent)
                });
                let attenuated = l.attenuation != [1.0, 0.0, 0.0];
                LightConst {
                    position: pos,
                    positional: is_positional,
                    vp_inf,
                    half_inf,
                    spot,
                    attenuation: (attenuated && is_positional).then_some(l.attenuation),
                    colors: [l.ambient, l.diffuse, l.specular],
                }
            })
            .collect();
        let mut setup = LightSetup {
            eye_space,
            modelview: *mv,
            normal: NormalTransform::new(state, mv, eye_space),
            lights: [LightConst::default(); MAX_LIGHTS],
            count: list.len(),
            sides: [Side::from_material(&state.materials[0], FromColor::default()); 2],
            model_ambient: state.model_ambient,
            two_side: state.two_side,
            separate,
            local_viewer: state.local_viewer,
            shininess_zero: false,
            products: [[[[0.0; 4]; 3]; 2]; MAX_LIGHTS],
            fast: !state.local_viewer && list.iter().all(|l| !l.positional && l.spot.is_none()),
            color_material: false,
            mats: [[[0.0; 4]; 4]; 2],
            scene: [[0.0; 4]; 2],
        };
        setup.lights[..list.len()].copy_from_slice(&list);
        setup.set_materials(state, &state.materials, false);
        setup
    }

    /// The same draw with the materials `materials` (front, back): how a
    /// vertex whose `glMaterial` came between `glBegin` and `glEnd` is lit.
    /// `varying_shininess` says the shininess was one of them: Mesa's program
    /// then reads it per vertex and never takes its shininess-0 shortcut
    /// (`check_active_shininess`, `main/ffvertex_prog.c`).
    pub fn with_materials(
        &self,
        state: &LightingState,
        materials: &[Material; 2],
        varying_shininess: bool,
    ) -> LightSetup {
        let mut setup = *self;
        setup.set_materials(state, materials, varying_shininess);
        setup
    }

    /// The material-dependent part: sides, light products, the shininess-0 shortcut.
    fn set_materials(&mut self, state: &LightingState, materials: &[Material; 2], varying_shininess: bool) {
        let sides = [0, 1].map(|s| {
            let applies = state.color_material
                && match state.color_material_face {
                    Face::Front => s == 0,
                    Face::Back => s == 1,
                    Face::FrontAndBack => true,
                };
            let mode = state.color_material_mode;
            let from_color = if applies {
                FromColor {
                    emission: mode == ColorMaterialMode::Emission,
                    ambient: matches!(mode, ColorMaterialMode::Ambient | ColorMaterialMode::AmbientAndDiffuse),
                    diffuse: matches!(mode, ColorMaterialMode::Diffuse | ColorMaterialMode::AmbientAndDiffuse),
                    specular: mode == ColorMaterialMode::Specular,
                }
            } else {
                FromColor::default()
            };
            Side::from_material(&materials[s], from_color)
        });
        // check_active_shininess: the front's, else (two-sided) the back's.
        self.shininess_zero =
            !varying_shininess && sides[0].shininess == 0.0 && !(state.two_side && sides[1].shininess != 0.0);
        for (p, l) in self.products.iter_mut().zip(&self.lights[..self.count]) {
            *p = [0, 1].map(|s| {
                let mat = sides[s].values([0.0; 4]);
                [0, 1, 2].map(|k| {
                    let (lc, mc) = (l.colors[k], mat[k + 1]);
                    [lc[0] * mc[0], lc[1] * mc[1], lc[2] * mc[2], mc[3]]
                })
            });
        }
        self.sides = sides;
        self.color_material = self.reads_color();
        self.mats = [0, 1].map(|s| sides[s].values([0.0; 4]));
        self.scene = [0, 1].map(|s| self.scene(&self.mats[s]));
    }

    /// Whether Mesa lights this draw in eye space (else object space).
    pub fn eye_space(&self) -> bool {
        self.eye_space
    }

    /// Whether [`LightSetup::light_batch`] takes the fast path.
    pub fn is_fast(&self) -> bool {
        self.fast
    }

    /// Whether lighting reads the vertex colour (`GL_COLOR_MATERIAL`).
    pub fn reads_color(&self) -> bool {
        self.sides.iter().any(|s| s.from_color != FromColor::default())
    }

    /// The normal in the lighting space, fixed up as the state says.
    #[inline(always)]
    fn normal(&self, n: Vec3) -> V3 {
        self.normal.apply(n)
    }

    /// The eye position the program computes for lighting (positional
    /// lights, local viewer), which its fog coordinate then reuses
    /// (`get_eye_position_z`); `None` when lighting computes none.
    pub fn eye_position(&self, p: Vec4) -> Option<[f32; 3]> {
        let needs = self.local_viewer || self.lights[..self.count].iter().any(|l| l.positional);
        needs.then(|| self.position(p))
    }

    /// The eye (or object) position: `MUL`/`MAD` by the modelview's columns.
    #[inline(always)]
    fn position(&self, p: Vec4) -> V3 {
        if !self.eye_space {
            return [p.x, p.y, p.z];
        }
        let c = self.modelview.to_cols_array();
        [0, 1, 2].map(|r| ((p.x * c[r] + p.y * c[4 + r]) + p.z * c[8 + r]) + p.w * c[12 + r])
    }

    /// The scene colour of a side: `lm_ambient · ambient + emission`, alpha
    /// the diffuse alpha (`STATE_LIGHTMODEL_SCENECOLOR` or the program's `MAD`).
    #[inline(always)]
    fn scene(&self, mat: &[[f32; 4]; 4]) -> [f32; 4] {
        let (e, a, lm) = (mat[0], mat[1], self.model_ambient);
        [lm[0] * a[0] + e[0], lm[1] * a[1] + e[1], lm[2] * a[2] + e[2], mat[2][3]]
    }

    /// The light products of light `i` for side `s` and vertex colour `c`.
    #[inline(always)]
    fn products(&self, i: usize, s: usize, mat: &[[f32; 4]; 4]) -> [[f32; 4]; 3] {
        let f = self.sides[s].from_color;
        if f == FromColor::default() {
            return self.products[i][s];
        }
        let from = [f.ambient, f.diffuse, f.specular];
        let mut p = self.products[i][s];
        for k in 0..3 {
            if from[k] {
                let (l, m) = (self.lights[i].colors[k], mat[k + 1]);
                p[k] = [l[0] * m[0], l[1] * m[1], l[2] * m[2], l[3] * m[3]];
            }
        }
        p
    }

    /// Lights one vertex (the general path).
    pub fn light(&self, v: &LightInput) -> LitColors {
        let n = self.normal(v.normal);
        let needs_pos = self.local_viewer || self.lights[..self.count].iter().any(|l| l.positional);
        let eye = if needs_pos { self.position(v.pos) } else { [0.0; 3] };
        let eye_hat = if self.local_viewer { normalize_vp(eye) } else { [0.0; 3] };
        let c = v.color.to_array();
        let mats = [self.sides[0].values(c), self.sides[1].values(c)];
        let nsides = if self.two_side { 2 } else { 1 };
        let mut acc = [[[0.0f32; 3]; 2]; 2]; // [side][primary, secondary]
        for s in 0..nsides {
            let sc = self.scene(&mats[s]);
            acc[s][0] = [sc[0], sc[1], sc[2]];
        }
        for (i, l) in self.lights[..self.count].iter().enumerate() {
            let (vp, dist) = if l.positional {
                let (vp, d2, r) = normalize_len(sub(l.position, eye));
                (vp, Some((d2, r)))
            } else {
                (l.vp_inf, None)
            };
            let mut att = None;
            if let Some((dir, cos_cutoff, exponent)) = l.spot {
                let s = dp3(vp.map(|x| -x), dir);
                let slt = if cos_cutoff < s { 1.0 } else { 0.0 };
                att = Some(slt * lp_pow(s.abs(), exponent));
            }
            if let (Some(k), Some((d2, r))) = (l.attenuation, dist) {
                // RCP of RSQ is folded to SQRT, SQRT·SQRT to |d²| (NIR algebraic).
                let d = d2.abs().sqrt();
                let dv = [r * d, d, d2.abs()];
                let da = 1.0 / dp3(k, dv);
                att = Some(match att {
                    Some(spot) => da * spot,
                    None => da,
                });
            }
            let half = if self.shininess_zero {
                [0.0; 3]
            } else if self.local_viewer {
                normalize_vp(sub(vp, eye_hat))
            } else if !l.positional {
                l.half_inf
            } else {
                normalize_vp([vp[0], vp[1], vp[2] + 1.0])
            };
            let nl = dp3(n, vp);
            let nh = if self.shininess_zero { nl } else { dp3(n, half) };
            for s in 0..nsides {
                let sign = if s == 0 { 1.0 } else { -1.0 };
                let (x, y) = (sign * nl, sign * nh);
                let w = if self.shininess_zero {
                    x
                } else {
                    self.sides[s].shininess
                };
                let lt = match att {
                    Some(a) => {
                        let [l0, l1, l2] = lit(x, y, w);
                        [l0 * a, l1 * a, l2 * a]
                    }
                    None if !self.shininess_zero => lit(x, y, w),
                    None => [1.0, x.max(0.0), if 0.0 < x { 1.0 } else { 0.0 }],
                };
                let [amb, dif, spe] = self.products(i, s, &mats[s]);
                let a = &mut acc[s];
                for k in 0..3 {
                    a[0][k] = if att.is_some() {
                        lt[0] * amb[k] + a[0][k]
                    } else {
                        amb[k] + a[0][k]
                    };
                    a[0][k] += lt[1] * dif[k];
                    let j = usize::from(self.separate);
                    a[j][k] += lt[2] * spe[k];
                }
            }
        }
        self.finish(&acc, &mats)
    }

    /// Clamped output colours from the accumulators.
    #[inline(always)]
    fn finish(&self, acc: &[[[f32; 3]; 2]; 2], mats: &[[[f32; 4]; 4]; 2]) -> LitColors {
        let sat = |x: f32| if x.is_nan() { 0.0 } else { x.clamp(0.0, 1.0) };
        let rgba = |c: [f32; 3], a: f32| [sat(c[0]), sat(c[1]), sat(c[2]), sat(a)];
        let sec = |c: [f32; 3]| if self.separate { rgba(c, 1.0) } else { [0.0; 4] };
        let mut out = LitColors {
            front: rgba(acc[0][0], mats[0][2][3]),
            front_secondary: sec(acc[0][1]),
            ..LitColors::default()
        };
        if self.two_side {
            out.back = rgba(acc[1][0], mats[1][2][3]);
            out.back_secondary = sec(acc[1][1]);
        }
        out
    }

    /// Lights one vertex through the fast path when it applies.
    #[inline]
    pub fn light_vertex(&self, v: &LightInput) -> LitColors {
        if self.fast {
            self.light_fast(v)
        } else {
            self.light(v)
        }
    }

    /// Lights `inputs` into `out` (same length): the fast path when it
    /// applies, else the general one.
    pub fn light_batch(&self, inputs: &[LightInput], out: &mut [LitColors]) {
        if self.fast {
            for (v, o) in inputs.iter().zip(out.iter_mut()) {
                *o = self.light_fast(v);
            }
        } else {
            for (v, o) in inputs.iter().zip(out.iter_mut()) {
                *o = self.light(v);
            }
        }
    }

    /// Whether [`LightSetup::light_many`] applies: the fast path's case
    /// (infinite lights, no spot, non-local viewer) without
    /// `GL_COLOR_MATERIAL`, so that a vertex's colours depend on its
    /// normal alone.
    pub fn lights_many(&self) -> bool {
        self.fast && !self.color_material
    }

    /// The normal of a vertex as lighting takes it ([`NormalTransform::apply`]):
    /// what [`LightSetup::light_many`] reads.
    #[inline(always)]
    pub fn lighting_normal(&self, n: Vec3) -> V3 {
        self.normal(n)
    }

    /// Lights the first `len` vertices of `n` (their normals from
    /// [`LightSetup::lighting_normal`], one array per component) into `out`,
    /// when [`LightSetup::lights_many`]: the colours
    /// [`LightSetup::light_vertex`] gives each, bit for bit, computed a
    /// light at a time over all the vertices so that the loops vectorize
    /// (each vertex's values see the same f32 operations in the same order).
    pub fn light_many(&self, n: &[[f32; CHUNK]; 3], len: usize, out: &mut ManyLit) {
        match (self.two_side, self.separate) {
            (false, false) => self.light_many_sides::<1, 0>(n, len, out),
            (false, true) => self.light_many_sides::<1, 1>(n, len, out),
            (true, false) => self.light_many_sides::<2, 0>(n, len, out),
            (true, true) => self.light_many_sides::<2, 1>(n, len, out),
        }
    }

    /// [`Self::light_many`] for `N` sides, the specular term summed into
    /// accumulator `J`: [`Self::light_fast_sides`] with the vertex loop
    /// innermost.
    #[inline(always)]
    fn light_many_sides<const N: usize, const J: usize>(&self, n: &[[f32; CHUNK]; 3], len: usize, out: &mut ManyLit) {
        let len = len.min(CHUNK);
        let (nx, ny, nz) = (&n[0][..len], &n[1][..len], &n[2][..len]);
        for s in 0..N {
            for k in 0..3 {
                out.acc[s][0][k][..len].fill(self.scene[s][k]);
                out.acc[s][1][k][..len].fill(0.0);
            }
        }
        let mut nl = [0.0f32; CHUNK];
        let mut nh = [0.0f32; CHUNK];
        let mut lt1 = [0.0f32; CHUNK];
        let mut lt2 = [0.0f32; CHUNK];
        for (i, l) in self.lights[..self.count].iter().enumerate() {
            let (vp, h) = (l.vp_inf, l.half_inf);
            for v in 0..len {
                nl[v] = dp3([nx[v], ny[v], nz[v]], vp);
            }
            if !self.shininess_zero {
                for v in 0..len {
                    nh[v] = dp3([nx[v], ny[v], nz[v]], h);
                }
            }
            for s in 0..N {
                let sign = if s == 0 { 1.0 } else { -1.0 };
                for v in 0..len {
                    let x = sign * nl[v];
                    lt1[v] = x.max(0.0);
                }
                if self.shininess_zero {
                    for v in 0..len {
                        let x = sign * nl[v];
                        lt2[v] = if 0.0 < x { 1.0 } else { 0.0 };
                    }
                } else {
                    let shininess = self.sides[s].shininess;
                    for v in 0..len {
                        lt2[v] = lit(sign * nl[v], sign * nh[v], shininess)[2];
                    }
                }
                let [amb, dif, spe] = self.products[i][s];
                let [a0, aj] = &mut out.acc[s];
                for k in 0..3 {
                    let (a0, (lt1, lt2)) = (&mut a0[k][..len], (&lt1[..len], &lt2[..len]));
                    if J == 0 {
                        for v in 0..len {
                            a0[v] += amb[k];
                            a0[v] += lt1[v] * dif[k];
                            a0[v] += lt2[v] * spe[k];
                        }
                    } else {
                        let aj = &mut aj[k][..len];
                        for v in 0..len {
                            a0[v] += amb[k];
                            a0[v] += lt1[v] * dif[k];
                            aj[v] += lt2[v] * spe[k];
                        }
                    }
                }
            }
        }
        let sat = |x: f32| if x.is_nan() { 0.0 } else { x.clamp(0.0, 1.0) };
        for s in 0..N {
            for j in 0..=J {
                for k in 0..3 {
                    for a in &mut out.acc[s][j][k][..len] {
                        *a = sat(*a);
                    }
                }
            }
        }
    }

    /// The colours of a [`LightSetup::light_many`] result as columns, in
    /// the order of [`LitColors`]' fields (front, front secondary, back,
    /// back secondary): each the red, green and blue of every vertex, and
    /// the alpha they share. Vertex `v`'s colours are
    /// [`LightSetup::many_colors`]`(m, v)`, read without picking each one.
    pub fn many_columns<'m>(&self, m: &'m ManyLit) -> [([&'m [f32; CHUNK]; 3], f32); 4] {
        static ZERO: [f32; CHUNK] = [0.0; CHUNK];
        let sat = |x: f32| if x.is_nan() { 0.0 } else { x.clamp(0.0, 1.0) };
        let col = |c: &'m [[f32; CHUNK]; 3], a: f32| ([&c[0], &c[1], &c[2]], sat(a));
        let zero = ([&ZERO, &ZERO, &ZERO], 0.0);
        let back = self.two_side;
        [
            col(&m.acc[0][0], self.mats[0][2][3]),
            if self.separate { col(&m.acc[0][1], 1.0) } else { zero },
            if back {
                col(&m.acc[1][0], self.mats[1][2][3])
            } else {
                zero
            },
            if back && self.separate {
                col(&m.acc[1][1], 1.0)
            } else {
                zero
            },
        ]
    }

    /// The colours of vertex `v` of a [`LightSetup::light_many`] result:
    /// what [`LightSetup::light_vertex`] returns for it.
    #[inline(always)]
    pub fn many_colors(&self, m: &ManyLit, v: usize) -> LitColors {
        let sat = |x: f32| if x.is_nan() { 0.0 } else { x.clamp(0.0, 1.0) };
        let rgba = |c: &[[f32; CHUNK]; 3], a: f32| [c[0][v], c[1][v], c[2][v], sat(a)];
        let sec = |c: &[[f32; CHUNK]; 3]| if self.separate { rgba(c, 1.0) } else { [0.0; 4] };
        let mut out = LitColors {
            front: rgba(&m.acc[0][0], self.mats[0][2][3]),
            front_secondary: sec(&m.acc[0][1]),
            ..LitColors::default()
        };
        if self.two_side {
            out.back = rgba(&m.acc[1][0], self.mats[1][2][3]);
            out.back_secondary = sec(&m.acc[1][1]);
        }
        out
    }

    /// Infinite lights without spot, non-local viewer: no position, no
    /// attenuation, the light direction and half vector are constants.
    #[inline(always)]
    fn light_fast(&self, v: &LightInput) -> LitColors {
        match (self.two_side, self.separate) {
            (false, false) => self.light_fast_sides::<1, 0>(v),
            (false, true) => self.light_fast_sides::<1, 1>(v),
            (true, false) => self.light_fast_sides::<2, 0>(v),
            (true, true) => self.light_fast_sides::<2, 1>(v),
        }
    }

    /// [`Self::light_fast`] for `N` sides, the specular term summed into
    /// accumulator `J` (1: `GL_SEPARATE_SPECULAR_COLOR`), the loops unrolled
    /// and the accumulators in registers (a run-time `J` kept them in
    /// memory: 37 instructions a vertex on lit16); without
    /// `GL_COLOR_MATERIAL` the material values and the scene colour are the
    /// draw's constants, not picked and summed again at every vertex (the
    /// same values: the same operations, once). Lighting was 8% of the lit16
    /// frame.
    #[inline(always)]
    fn light_fast_sides<const N: usize, const J: usize>(&self, v: &LightInput) -> LitColors {
        let n = self.normal(v.normal);
        let c = v.color.to_array();
        let picked;
        let mats = if self.color_material {
            picked = [self.sides[0].values(c), self.sides[1].values(c)];
            &picked
        } else {
            &self.mats
        };
        let mut acc = [[[0.0f32; 3]; 2]; 2];
        for s in 0..N {
            let sc = if self.color_material {
                self.scene(&mats[s])
            } else {
                self.scene[s]
            };
            acc[s][0] = [sc[0], sc[1], sc[2]];
        }
        for (i, l) in self.lights[..self.count].iter().enumerate() {
            let nl = dp3(n, l.vp_inf);
            let nh = if self.shininess_zero { nl } else { dp3(n, l.half_inf) };
            for s in 0..N {
                let sign = if s == 0 { 1.0 } else { -1.0 };
                let x = sign * nl;
                let lt1 = x.max(0.0);
                let lt2 = if self.shininess_zero {
                    if 0.0 < x {
                        1.0
                    } else {
                        0.0
                    }
                } else {
                    lit(x, sign * nh, self.sides[s].shininess)[2]
                };
                let [amb, dif, spe] = self.products(i, s, &mats[s]);
                let a = &mut acc[s];
                for k in 0..3 {
                    a[0][k] += amb[k];
                    a[0][k] += lt1 * dif[k];
                    a[J][k] += lt2 * spe[k];
                }
            }
        }
        self.finish(&acc, mats)
    }
}

#[cfg(test)]
mod tests {
    //! Expected colours come from the GL 1.5 spec's formula (§2.14.1),
    //! evaluated in f64 by [`spec_color`], not from the code above.
    use super::*;
    use crate::lighting::{Light, LightingState, Material};

    /// Mesa's `pow` approximation and f32 arithmetic against the spec's
    /// exact formula in f64: `log2`'s polynomial is good to ~1e-7, times a
    /// shininess up to 128 in the exponent gives ~1e-5 relative on a
    /// specular term; 3e-5 stays far below an 8-bit step (1/255 ≈ 4e-3).
    const TOL: f64 = 3e-5;

    type D3 = [f64; 3];
    fn d3(v: [f32; 3]) -> D3 {
        v.map(f64::from)
    }
    fn dot(a: D3, b: D3) -> f64 {
        a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
    }
    fn norm(a: D3) -> D3 {
        let l = dot(a, a).sqrt();
        a.map(|c| c / l)
    }

    /// GL 1.5 §2.14.1 for the front (`back == false`) or back face: the
    /// primary colour (specular included unless `separate`) and the secondary.
    fn spec_color(st: &LightingState, mv: &Mat4, v: &LightInput, back: bool) -> ([f64; 4], [f64; 3]) {
        let m = mv.as_dmat4();
        let p = m * v.pos.as_dvec4();
        let eye = [p.x / p.w, p.y / p.w, p.z / p.w];
        let inv_t = m.inverse().transpose();
        let mut n = {
            let n = inv_t * glam::DVec4::new(v.normal.x.into(), v.normal.y.into(), v.normal.z.into(), 0.0);
            [n.x, n.y, n.z]
        };
        if st.normalize {
            n = norm(n);
        } else if st.rescale_normal {
            let inv = m.inverse();
            let f = 1.0 / (inv.x_axis.z.powi(2) + inv.y_axis.z.powi(2) + inv.z_axis.z.powi(2)).sqrt();
            n = n.map(|c| c * f);
        }
        if back {
            n = n.map(|c| -c);
        }
        let side = usize::from(back);
        let mut mat = st.materials[side];
        let c = v.color.to_array();
        if st.color_material && crate::lighting::sides(st.color_material_face).contains(&side) {
            match st.color_material_mode {
                ColorMaterialMode::Emission => mat.emission = c,
                ColorMaterialMode::Ambient => mat.ambient = c,
                ColorMaterialMode::Diffuse => mat.diffuse = c,
                ColorMaterialMode::Specular => mat.specular = c,
                ColorMaterialMode::AmbientAndDiffuse => (mat.ambient, mat.diffuse) = (c, c),
            }
        }
        let f = |a: [f32; 4]| a.map(f64::from);
        let (e, a, d, s) = (f(mat.emission), f(mat.ambient), f(mat.diffuse), f(mat.specular));
        let lm = f(st.model_ambient);
        let mut col = [0, 1, 2].map(|k| e[k] + a[k] * lm[k]);
        let mut sec = [0.0; 3];
        for l in st.lights.iter().filter(|l| l.enabled) {
            let lp = f(l.position);
            let (vp, att) = if lp[3] != 0.0 {
                let q = [lp[0] / lp[3] - eye[0], lp[1] / lp[3] - eye[1], lp[2] / lp[3] - eye[2]];
                let dist = dot(q, q).sqrt();
                let k = d3(l.attenuation);
                (norm(q), 1.0 / (k[0] + k[1] * dist + k[2] * dist * dist))
            } else {
                (norm([lp[0], lp[1], lp[2]]), 1.0)
            };
            let spot = if l.spot_cutoff == 180.0 {
                1.0
            } else {
                let sdv = -dot(vp, norm(d3(l.spot_direction)));
                if sdv >= f64::from(l.spot_cutoff).to_radians().cos() {
                    sdv.powf(l.spot_exponent.into())
                } else {
                    0.0
                }
            };
            let h = if st.local_viewer {
                let ve = norm(eye.map(|c| -c));
                norm([vp[0] + ve[0], vp[1] + ve[1], vp[2] + ve[2]])
            } else {
                norm([vp[0], vp[1], vp[2] + 1.0])
            };
            let nvp = dot(n, vp);
            let fi = if nvp > 0.0 { 1.0 } else { 0.0 };
            let spec_pow = fi * dot(n, h).max(0.0).powf(mat.shininess.into());
            let (la, ld, ls) = (f(l.ambient), f(l.diffuse), f(l.specular));
            for k in 0..3 {
                col[k] += att * spot * (a[k] * la[k] + nvp.max(0.0) * d[k] * ld[k]);
                let sp = att * spot * spec_pow * s[k] * ls[k];
                if st.color_control == ColorControl::SeparateSpecular {
                    sec[k] += sp;
                } else {
                    col[k] += sp;
                }
            }
        }
        let sat = |x: f64| x.clamp(0.0, 1.0);
        ([sat(col[0]), sat(col[1]), sat(col[2]), sat(d[3])], sec.map(sat))
    }

    fn check(st: &LightingState, mv: &Mat4, v: &LightInput) -> LitColors {
        let setup = LightSetup::new(st, mv);
        let got = setup.light(v);
        let sides = if st.two_side { 2 } else { 1 };
        for side in 0..sides {
            let (want, want_sec) = spec_color(st, mv, v, side == 1);
            let (c, sc) = if side == 0 {
                (got.front, got.front_secondary)
            } else {
                (got.back, got.back_secondary)
            };
            for k in 0..4 {
                assert!(
                    (f64::from(c[k]) - want[k]).abs() <= TOL,
                    "side {side} {k}: {c:?} vs {want:?}"
                );
            }
            if st.color_control == ColorControl::SeparateSpecular {
                for k in 0..3 {
                    assert!((f64::from(sc[k]) - want_sec[k]).abs() <= TOL, "{sc:?} vs {want_sec:?}");
                }
            }
        }
        got
    }

    fn lit_state() -> LightingState {
        let mut st = LightingState {
            enabled: true,
            ..LightingState::default()
        };
        st.materials = [Material {
            ambient: [0.2, 0.3, 0.1, 1.0],
            diffuse: [0.6, 0.5, 0.4, 0.75],
            specular: [0.5, 0.5, 0.5, 1.0],
            emission: [0.05, 0.0, 0.1, 1.0],
            shininess: 20.0,
        }; 2];
        st.lights[0] = Light {
            enabled: true,
            ambient: [0.1, 0.1, 0.1, 1.0],
            ..Light::new(0)
        };
        st
    }

    fn vertex(n: [f32; 3]) -> LightInput {
        LightInput {
            pos: Vec4::new(0.3, -0.2, -2.0, 1.0),
            normal: Vec3::from_array(n).normalize(),
            color: Vec4::new(0.9, 0.2, 0.4, 0.5),
        }
    }

    #[test]
    fn tiny_vectors_normalize_as_under_flush_to_zero() {
        // 1e-20 squared is 1e-40, a denormal: flushed to 0, rsq is +inf, the
        // vector infinite and 0·inf NaN (llvmpipe's FTZ/DAZ vertex stage).
        let (v, d2, s) = normalize_len([1e-20, 1e-20, 1e-20]);
        assert_eq!((d2, s), (0.0, f32::INFINITY));
        assert_eq!(v, [f32::INFINITY; 3]);
        let v = normalize_vp([0.0, -1e-20, 0.0]);
        assert!(v[0].is_nan() && v[2].is_nan() && v[1] == f32::NEG_INFINITY, "{v:?}");
        // A denormal component counts as 0 (DAZ).
        let v = normalize_vp([1e-40, 0.0, 0.0]);
        assert!(v.iter().all(|c| c.is_nan()), "{v:?}");
        // Short vectors whose squares stay normal (>= 2^-126) normalize as
        // IEEE does, on either side of the 2^-100 switch: 3-4-5 triangles.
        for scale in [1e-17f32, 1e-16, 1e-14] {
            let v = normalize_vp([3.0 * scale, 0.0, 4.0 * scale]);
            assert!(
                (v[0] - 0.6).abs() < 1e-6 && v[1] == 0.0 && (v[2] - 0.8).abs() < 1e-6,
                "{scale}: {v:?}"
            );
        }
        // Lengths of 1 and 1e20 take the plain path (1e40 overflows: rsq 0).
        assert_eq!(normalize_vp([0.0, 2.0, 0.0]), [0.0, 1.0, 0.0]);
        assert_eq!(normalize_vp([0.0, 1e20, 0.0]), [0.0, 0.0, 0.0]);
    }

    #[test]
    fn directional_light_matches_the_spec_formula() {
        let mut st = lit_state();
        st.lights[0].position = [1.0, 1.0, 2.0, 0.0];
        let got = check(&st, &Mat4::IDENTITY, &vertex([0.2, 0.3, 1.0]));
        // Material diffuse alpha (0.75) is the lit alpha.
        assert_eq!(got.front[3], 0.75);
        let mv = Mat4::from_rotation_y(0.4) * Mat4::from_translation(Vec3::new(0.0, 0.0, -1.0));
        check(&st, &mv, &vertex([0.2, 0.3, 1.0]));
    }

    #[test]
    fn positional_light_with_attenuation() {
        let mut st = lit_state();
        st.lights[0].position = [1.0, 2.0, 1.0, 1.0];
        st.lights[0].attenuation = [0.5, 0.2, 0.1];
        let v = vertex([0.0, 0.4, 1.0]);
        let got = check(&st, &Mat4::IDENTITY, &v);
        // The attenuation matters: the same light unattenuated is brighter.
        st.lights[0].attenuation = [1.0, 0.0, 0.0];
        let bright = check(&st, &Mat4::IDENTITY, &v);
        assert!(bright.front[0] > got.front[0] + 0.05);
        // Homogeneous position: (2, 4, 2, 2) is the same point.
        st.lights[0].position = [2.0, 4.0, 2.0, 2.0];
        check(&st, &Mat4::IDENTITY, &v);
    }

    #[test]
    fn spotlight_inside_and_outside_its_cone() {
        let mut st = lit_state();
        st.lights[0].position = [0.3, -0.2, 0.0, 1.0];
        st.lights[0].spot_direction = [0.0, 0.1, -1.0];
        st.lights[0].spot_cutoff = 30.0;
        st.lights[0].spot_exponent = 8.0;
        let inside = check(&st, &Mat4::IDENTITY, &vertex([0.0, 0.0, 1.0]));
        st.lights[0].spot_direction = [1.0, 0.0, -0.2];
        let outside = check(&st, &Mat4::IDENTITY, &vertex([0.0, 0.0, 1.0]));
        // Outside the cone the light adds nothing, not even its ambient:
        // emission + model ambient × material ambient.
        let want = [0.05 + 0.2 * 0.2, 0.2 * 0.3, 0.1 + 0.2 * 0.1];
        for (got, want) in outside.front.iter().zip(want) {
            assert!((f64::from(*got) - want).abs() < 1e-6);
        }
        assert!(inside.front[0] > outside.front[0] + 0.1);
        // Exponent 128, the largest.
        st.lights[0].spot_direction = [0.0, 0.05, -1.0];
        st.lights[0].spot_exponent = 128.0;
        check(&st, &Mat4::IDENTITY, &vertex([0.0, 0.0, 1.0]));
    }

    #[test]
    fn two_sided_lighting_uses_back_materials_and_the_reversed_normal() {
        let mut st = lit_state();
        st.two_side = true;
        st.lights[0].position = [0.0, 0.0, -1.0, 0.0];
        st.materials[1].diffuse = [0.1, 0.9, 0.2, 0.5];
        st.materials[1].shininess = 5.0;
        // The normal faces away from the light: the back face is lit.
        let got = check(&st, &Mat4::IDENTITY, &vertex([0.1, 0.2, 1.0]));
        assert!(got.back[1] > got.front[1] + 0.5);
        assert_eq!(got.back[3], 0.5);
    }

    #[test]
    fn color_material_in_every_mode() {
        for mode in [
            ColorMaterialMode::Emission,
            ColorMaterialMode::Ambient,
            ColorMaterialMode::Diffuse,
            ColorMaterialMode::Specular,
            ColorMaterialMode::AmbientAndDiffuse,
        ] {
            for face in [Face::Front, Face::Back, Face::FrontAndBack] {
                let mut st = lit_state();
                st.two_side = true;
                st.color_material = true;
                st.color_material_mode = mode;
                st.color_material_face = face;
                st.lights[0].position = [0.5, 0.5, 1.0, 0.0];
                check(&st, &Mat4::IDENTITY, &vertex([0.0, 0.3, 1.0]));
                check(&st, &Mat4::IDENTITY, &vertex([0.0, 0.3, -1.0]));
            }
        }
    }

    #[test]
    fn separate_specular_goes_to_the_secondary_colour() {
        let mut st = lit_state();
        st.color_control = ColorControl::SeparateSpecular;
        st.lights[0].position = [0.0, 0.3, 1.0, 0.0];
        let got = check(&st, &Mat4::IDENTITY, &vertex([0.0, 0.1, 1.0]));
        assert!(got.front_secondary[0] > 0.3);
    }

    #[test]
    fn local_viewer_and_eight_mixed_lights() {
        let mut st = lit_state();
        st.local_viewer = true;
        for i in 0..8 {
            let fi = i as f32;
            st.lights[i] = Light {
                enabled: true,
                ambient: [0.02 * fi, 0.01, 0.03, 1.0],
                diffuse: [0.1, 0.05 * fi, 0.1, 1.0],
                specular: [0.1, 0.1, 0.02 * fi, 1.0],
                position: if i % 2 == 0 {
                    [fi - 3.0, 1.0, 1.0, 1.0]
                } else {
                    [1.0, fi - 4.0, 2.0, 0.0]
                },
                spot_direction: [0.0, 0.0, -1.0],
                spot_exponent: fi,
                spot_cutoff: if i % 3 == 0 { 180.0 } else { 80.0 },
                attenuation: [1.0, 0.05 * fi, 0.01],
            };
        }
        let mv = Mat4::from_rotation_x(0.3) * Mat4::from_translation(Vec3::new(0.1, 0.0, -0.5));
        check(&st, &mv, &vertex([0.1, 0.2, 1.0]));
        st.local_viewer = false;
        check(&st, &mv, &vertex([0.3, -0.2, 1.0]));
    }

    #[test]
    fn normalize_and_rescale_normal() {
        let mut st = lit_state();
        st.lights[0].position = [0.2, 0.4, 1.0, 0.0];
        let mv = Mat4::from_scale(Vec3::splat(0.5));
        let v = vertex([0.3, 0.1, 1.0]);
        // Without either, the scaled modelview makes the normal twice as long.
        let long = check(&st, &mv, &v);
        st.rescale_normal = true;
        let rescaled = check(&st, &mv, &v);
        st.rescale_normal = false;
        st.normalize = true;
        let normalized = check(&st, &mv, &v);
        assert!(long.front[2] > rescaled.front[2] + 0.05, "{long:?} {rescaled:?}");
        for k in 0..4 {
            assert!((rescaled.front[k] - normalized.front[k]).abs() < 1e-6);
        }
        // A normal of length 1e-20, normalized.
        let tiny = LightInput {
            normal: v.normal * 1e-20,
            ..v
        };
        let got = LightSetup::new(&st, &mv).light(&tiny);
        assert_eq!(got, LightSetup::new(&st, &mv).light(&tiny));
        assert!(got.front.iter().all(|c| (0.0..=1.0).contains(c)));
    }

    #[test]
    fn shininess_zero_and_128() {
        let mut st = lit_state();
        st.lights[0].position = [0.3, 0.2, 1.0, 0.0];
        st.materials[0].shininess = 0.0;
        check(&st, &Mat4::IDENTITY, &vertex([0.0, 0.0, 1.0]));
        st.materials[0].shininess = 128.0;
        check(&st, &Mat4::IDENTITY, &vertex([0.1, 0.1, 1.0]));
    }

    #[test]
    fn lighting_without_lights_is_the_scene_colour() {
        let mut st = lit_state();
        st.lights[0].enabled = false;
        let got = LightSetup::new(&st, &Mat4::IDENTITY).light(&vertex([0.0, 0.0, 1.0]));
        assert_eq!(got.front, [0.05 + 0.2f32 * 0.2, 0.2f32 * 0.3, 0.2f32 * 0.1 + 0.1, 0.75]);
    }

    #[test]
    fn the_fast_path_equals_the_general_path_bit_for_bit() {
        let mut rng = crate::rng::Rng::new(11);
        let mut checked = 0;
        let mut many = 0;
        for round in 0..40 {
            let mut st = lit_state();
            st.two_side = round % 2 == 0;
            st.normalize = round % 3 == 0;
            st.color_material = round % 5 == 0;
            st.color_control = if round % 4 == 0 {
                ColorControl::SeparateSpecular
            } else {
                ColorControl::SingleColor
            };
            st.materials[0].shininess = [0.0, 1.0, 17.5, 128.0][round % 4];
            for i in 0..(1 + round % 8) {
                st.lights[i].enabled = true;
                st.lights[i].position = [rng.unit() - 0.5, rng.unit() - 0.5, rng.unit(), 0.0];
                st.lights[i].specular = [rng.unit(), rng.unit(), rng.unit(), 1.0];
            }
            let mv = if round % 2 == 0 {
                Mat4::IDENTITY
            } else {
                Mat4::from_scale(Vec3::new(1.0, 2.0, 0.5))
            };
            let setup = LightSetup::new(&st, &mv);
            assert!(setup.is_fast());
            let inputs: Vec<LightInput> = (0..64)
                .map(|_| LightInput {
                    pos: Vec4::new(rng.unit(), rng.unit(), rng.unit(), 1.0),
                    normal: Vec3::new(rng.unit() - 0.5, rng.unit() - 0.5, rng.unit() - 0.5),
                    color: Vec4::new(rng.unit(), rng.unit(), rng.unit(), rng.unit()),
                })
                .collect();
            let mut fast = vec![LitColors::default(); inputs.len()];
            setup.light_batch(&inputs, &mut fast);
            for (v, f) in inputs.iter().zip(&fast) {
                let g = setup.light(v);
                let bits =
                    |c: &LitColors| [c.front, c.front_secondary, c.back, c.back_secondary].map(|a| a.map(f32::to_bits));
                assert_eq!(bits(&g), bits(f));
                checked += 1;
            }
            // The vertex-innermost path, on the same normals and special ones
            // (zero, tiny, huge, infinite, NaN), in a partial chunk too.
            if setup.lights_many() {
                let specials = [0.0, -0.0, 1e-20, -1e-25, 3e38, f32::INFINITY, f32::NAN];
                let normals: Vec<Vec3> = inputs
                    .iter()
                    .map(|v| v.normal)
                    .chain((0..CHUNK).map(|k| {
                        let s = |j: usize| specials[(k * 7 + j * 3 + round) % specials.len()];
                        Vec3::new(s(0), s(1), rng.unit() - 0.5)
                    }))
                    .collect();
                for (c, chunk) in normals.chunks(CHUNK - 5).enumerate() {
                    let mut n = [[0.0; CHUNK]; 3];
                    for (k, v) in chunk.iter().enumerate() {
                        let t = setup.lighting_normal(*v);
                        (n[0][k], n[1][k], n[2][k]) = (t[0], t[1], t[2]);
                    }
                    let mut out = ManyLit::default();
                    setup.light_many(&n, chunk.len(), &mut out);
                    for (k, v) in chunk.iter().enumerate() {
                        let input = LightInput {
                            normal: *v,
                            ..inputs[(c + k) % inputs.len()]
                        };
                        let bits = |c: &LitColors| {
                            [c.front, c.front_secondary, c.back, c.back_secondary].map(|a| a.map(f32::to_bits))
                        };
                        assert_eq!(bits(&setup.light_vertex(&input)), bits(&setup.many_colors(&out, k)));
                        let cols = setup.many_columns(&out).map(|(c, a)| [c[0][k], c[1][k], c[2][k], a]);
                        let g = setup.many_colors(&out, k);
                        let want = [g.front, g.front_secondary, g.back, g.back_secondary];
                        assert_eq!(cols.map(|c| c.map(f32::to_bits)), want.map(|c| c.map(f32::to_bits)));
                        many += 1;
                    }
                }
            }
        }
        assert_eq!(checked, 40 * 64);
        assert!(many > 10 * 128, "{many}");
    }

    #[test]
    fn gallivm_pow_is_close_to_powf_and_zero_at_zero() {
        // Exact powers of two: the polynomial's constant term is 1.
        for e in -126..=127 {
            assert_eq!(lp_exp2(e as f32), 2f32.powi(e), "{e}");
        }
        assert_eq!(lp_pow(0.0, 0.0), 0.0, "gallivm's pow(0, y) is 0, also for y = 0");
        assert_eq!(lp_pow(0.5, 0.0), 1.0);
        assert_eq!(lp_log2_safe(0.0), f32::NEG_INFINITY);
        assert!(lp_log2_safe(-1.0).is_nan());
        let mut worst = 0.0f64;
        for i in 1..2000 {
            let x = i as f32 / 2000.0;
            for y in [1.0f32, 2.5, 10.0, 64.0, 128.0] {
                let want = f64::from(x).powf(y.into());
                let got = f64::from(lp_pow(x, y));
                if want > 1e-30 {
                    worst = worst.max((got - want).abs() / want);
                }
            }
        }
        // log2's polynomial error (~1e-7) times y = 128 in the exponent.
        assert!(worst < 2e-5, "worst relative error {worst}");
    }
}
