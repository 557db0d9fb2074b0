//! Texture units: what `glEnable(GL_TEXTURE_2D)`, `glTexEnv`, `glTexGen`,
//! the texture matrix stacks and `glMultiTexCoord` set per unit, and how a
//! draw turns them into the fragment key's [`TexUnitKey`]s and the
//! [`TextureSet`] the fragment stage samples.
//!
//! A unit takes part in a draw only when one of its targets is enabled and
//! the texture bound there is complete (Mesa's `update_ff_texture_state`,
//! `main/texstate.c`: the enabled targets are tried cube map, 3D, rectangle, 2D, 1D,
//! and the first complete one is used). Any other unit adds nothing: no key
//! entry, no varyings, no vertex work.

use crate::context::Context;
use crate::error::{GlError, GlResult};
use crate::matrix::{MatrixStack, MAX_TEXTURE_DEPTH};
use crate::state::Capability;
use crate::texture::store::SharedSampling;
use crate::texture::{Sampling, TextureStore};
use glam::Mat4;
use softgl_jit::texture::{
    effective_combine, quantized_lod_bias, BaseFormat, CombineFn, CombineKey, CombineSrc, EnvMode, Operand,
    TexTarget as TextureTarget, TexUnitKey, TextureSet, MAX_UNITS,
};

/// A texture coordinate (`GL_S`, `GL_T`, `GL_R`, `GL_Q`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TexCoordName {
    S,
    T,
    R,
    Q,
}

impl TexCoordName {
    pub const ALL: [TexCoordName; 4] = [TexCoordName::S, TexCoordName::T, TexCoordName::R, TexCoordName::Q];

    /// 0 for `S` … 3 for `Q`.
    pub fn index(self) -> usize {
        self as usize
    }
}

/// `GL_TEXTURE_GEN_MODE`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TexGenMode {
    ObjectLinear,
    EyeLinear,
    SphereMap,
    NormalMap,
    ReflectionMap,
}

impl TexGenMode {
    /// Whether the mode needs eye coordinates (Mesa's `TEXGEN_NEED_EYE_COORD`,
    /// which also puts lighting in eye space).
    pub fn needs_eye_coords(self) -> bool {
        self != TexGenMode::ObjectLinear
    }
}

/// One `glTexGen` parameter.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TexGenParam {
    Mode(TexGenMode),
    /// In object coordinates.
    ObjectPlane([f32; 4]),
    /// Given in object coordinates, kept (and returned) in eye coordinates.
    EyePlane([f32; 4]),
}

/// What `glGetTexGen` asks for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TexGenParamName {
    Mode,
    ObjectPlane,
    EyePlane,
}

/// One `glTexEnv` parameter (`GL_TEXTURE_ENV`, or `GL_TEXTURE_FILTER_CONTROL`
/// for [`TexEnvParam::LodBias`]). Source and operand indices are 0, 1, 2.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TexEnvParam {
    Mode(EnvMode),
    Color([f32; 4]),
    CombineRgb(CombineFn),
    CombineAlpha(CombineFn),
    SrcRgb(u8, CombineSrc),
    SrcAlpha(u8, CombineSrc),
    OperandRgb(u8, Operand),
    OperandAlpha(u8, Operand),
    /// 1, 2 or 4.
    RgbScale(f32),
    /// 1, 2 or 4.
    AlphaScale(f32),
    /// `GL_TEXTURE_LOD_BIAS` of `GL_TEXTURE_FILTER_CONTROL`: the unit's bias,
    /// added to the texture object's.
    LodBias(f32),
}

/// What `glGetTexEnv` asks for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TexEnvParamName {
    Mode,
    Color,
    CombineRgb,
    CombineAlpha,
    SrcRgb(u8),
    SrcAlpha(u8),
    OperandRgb(u8),
    OperandAlpha(u8),
    RgbScale,
    AlphaScale,
    LodBias,
}

/// One coordinate's generation state.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TexGen {
    /// `GL_TEXTURE_GEN_S` … `Q`.
    pub enabled: bool,
    pub mode: TexGenMode,
    pub object_plane: [f32; 4],
    /// In eye coordinates (the plane given times the inverse modelview then in force).
    pub eye_plane: [f32; 4],
}

/// The state of one texture unit but its matrix stack (what `GL_TEXTURE_BIT`
/// and `GL_ENABLE_BIT` save).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TexUnit {
    /// Enabled targets, indexed by [`target_index`].
    pub enabled: [bool; 5],
    pub env_mode: EnvMode,
    /// `GL_TEXTURE_ENV_COLOR`, clamped to `[0, 1]` as Mesa keeps it for
    /// fixed-point colour buffers.
    pub env_color: [f32; 4],
    pub combine: CombineKey,
    /// `GL_TEXTURE_FILTER_CONTROL`'s `GL_TEXTURE_LOD_BIAS`, as given.
    pub lod_bias: f32,
    /// S, T, R, Q.
    pub gen: [TexGen; 4],
}

impl Default for TexUnit {
    fn default() -> TexUnit {
        let gen = |plane: [f32; 4]| TexGen {
            enabled: false,
            mode: TexGenMode::EyeLinear,
            object_plane: plane,
            eye_plane: plane,
        };
        TexUnit {
            enabled: [false; 5],
            env_mode: EnvMode::Modulate,
            env_color: [0.0; 4],
            combine: CombineKey::DEFAULT,
            lod_bias: 0.0,
            gen: [
                gen([1.0, 0.0, 0.0, 0.0]),
                gen([0.0, 1.0, 0.0, 0.0]),
                gen([0.0; 4]),
                gen([0.0; 4]),
            ],
        }
    }
}

/// Where a target's enable sits in [`TexUnit::enabled`].
pub fn target_index(target: TextureTarget) -> usize {
    match target {
        TextureTarget::D1 => 0,
        TextureTarget::D2 => 1,
        TextureTarget::D3 => 2,
        TextureTarget::Cube => 3,
        TextureTarget::Rect => 4,
    }
}

/// The order enabled targets are tried in (GL 4.4 compatibility §16.2, Mesa's
/// `TEXTURE_x_INDEX`; ARB_texture_rectangle issue 10: rectangle above 2D, below 3D).
const PRIORITY: [TextureTarget; 5] = [
    TextureTarget::Cube,
    TextureTarget::D3,
    TextureTarget::Rect,
    TextureTarget::D2,
    TextureTarget::D1,
];

/// Every texture unit's state, the texture matrix stacks and the client
/// active unit (`glClientActiveTexture`).
#[derive(Clone, Debug)]
pub struct TextureUnits {
    pub units: [TexUnit; MAX_UNITS],
    matrices: [MatrixStack; MAX_UNITS],
    client_active: usize,
}

impl Default for TextureUnits {
    fn default() -> TextureUnits {
        TextureUnits {
            units: [TexUnit::default(); MAX_UNITS],
            matrices: std::array::from_fn(|_| MatrixStack::new(MAX_TEXTURE_DEPTH)),
            client_active: 0,
        }
    }
}

/// The texturing of one draw: each sampling unit's key, its texture and
/// environment colour, and which units sample (bit `u`).
#[derive(Clone, Debug)]
pub struct TexturePlan<'a> {
    pub keys: [Option<TexUnitKey>; MAX_UNITS],
    pub mask: u8,
    samplings: [Option<Sampling<'a>>; MAX_UNITS],
    /// Each unit's quantized `GL_TEXTURE_FILTER_CONTROL` bias.
    lod_bias: [f32; MAX_UNITS],
    env_color: [[f32; 4]; MAX_UNITS],
}

impl Default for TexturePlan<'_> {
    fn default() -> Self {
        TexturePlan {
            keys: [None; MAX_UNITS],
            mask: 0,
            samplings: std::array::from_fn(|_| None),
            lod_bias: [0.0; MAX_UNITS],
            env_color: [[0.0; 4]; MAX_UNITS],
        }
    }
}

/// A [`TexturePlan`] holding its textures' texels: what a deferred draw keeps.
#[derive(Clone, Debug, Default)]
pub struct SharedPlan {
    keys: [Option<TexUnitKey>; MAX_UNITS],
    mask: u8,
    samplings: [Option<SharedSampling>; MAX_UNITS],
    lod_bias: [f32; MAX_UNITS],
    env_color: [[f32; 4]; MAX_UNITS],
}

impl SharedPlan {
    /// Whether no unit samples.
    pub fn is_empty(&self) -> bool {
        self.mask == 0
    }

    /// The texels the plan holds, unit by unit (a texture on two units twice).
    pub fn texels(&self) -> impl Iterator<Item = &crate::texture::store::SharedTexels> {
        self.samplings.iter().flatten().flat_map(SharedSampling::texels)
    }

    /// The plan again, viewing the texels held.
    pub fn plan(&self) -> TexturePlan<'_> {
        TexturePlan {
            keys: self.keys,
            mask: self.mask,
            samplings: std::array::from_fn(|u| self.samplings[u].as_ref().map(SharedSampling::sampling)),
            lod_bias: self.lod_bias,
            env_color: self.env_color,
        }
    }
}

impl TexturePlan<'_> {
    /// The plan with its texels held, for a draw that runs later.
    pub fn share(&self) -> SharedPlan {
        // Most draws sample nothing: 0.6 k instructions a draw went to
        // walking eight empty units (callgrind, osmesa/bench/quads.c).
        if self.mask == 0 {
            return SharedPlan::default();
        }
        SharedPlan {
            keys: self.keys,
            mask: self.mask,
            samplings: std::array::from_fn(|u| self.samplings[u].as_ref().map(Sampling::share)),
            lod_bias: self.lod_bias,
            env_color: self.env_color,
        }
    }

    /// What the fragment stage samples: each unit's texture (its object's
    /// LOD bias plus the unit's) and environment colour.
    pub fn set(&self) -> TextureSet<'_> {
        let mut set = TextureSet {
            env_color: self.env_color,
            ..TextureSet::default()
        };
        for (u, s) in self.samplings.iter().enumerate() {
            set.units[u] = s.as_ref().map(|s| s.texture_ref(self.lod_bias[u]));
        }
        set
    }
}

impl TextureUnits {
    /// Unit `unit`'s texture matrix stack.
    pub fn matrix_stack(&self, unit: usize) -> &MatrixStack {
        &self.matrices[unit]
    }

    pub fn matrix_stack_mut(&mut self, unit: usize) -> &mut MatrixStack {
        &mut self.matrices[unit]
    }

    /// The top of unit `unit`'s texture matrix stack.
    pub fn matrix(&self, unit: usize) -> &Mat4 {
        self.matrices[unit].top()
    }

    /// The client active unit (`GL_CLIENT_ACTIVE_TEXTURE`).
    pub fn client_active(&self) -> usize {
        self.client_active
    }

    /// The texturing a draw does now: per unit with an enabled target whose
    /// texture is complete, its key (the environment translated for the
    /// texture's base format), its texture with the unit's LOD bias added,
    /// and its environment colour.
    pub fn plan<'a>(&self, store: &'a TextureStore) -> TexturePlan<'a> {
        let mut plan = TexturePlan::default();
        if self.units.iter().all(|u| !u.enabled.iter().any(|&e| e)) {
            return plan;
        }
        for (u, unit) in self.units.iter().enumerate() {
            let found = PRIORITY
                .iter()
                .filter(|&&t| unit.enabled[target_index(t)])
                .find_map(|&t| store.sampling(u, t));
            let Some(sampling) = found else {
                continue;
            };
            let (sampler, base) = (sampling.key, sampling.base);
            // A depth texture's environment treats it as GL_DEPTH_TEXTURE_MODE says.
            let env_base = match base {
                BaseFormat::Depth => sampler.depth_mode.base(),
                _ => base,
            };
            let lod_bias = quantized_lod_bias(unit.lod_bias);
            plan.keys[u] = Some(TexUnitKey {
                sampler: sampler.with_statics(&sampling.texture_ref(lod_bias)),
                base,
                env: effective_combine(unit.env_mode, env_base, unit.combine),
            });
            plan.samplings[u] = Some(sampling);
            plan.lod_bias[u] = lod_bias;
            plan.env_color[u] = unit.env_color;
            plan.mask |= 1 << u;
        }
        plan
    }

    /// Bit `u` set when unit `u` has a target enabled (the units a draw may
    /// sample, before their textures are checked).
    pub fn enabled_mask(&self) -> u8 {
        let mut mask = 0;
        for (u, unit) in self.units.iter().enumerate() {
            if unit.enabled.iter().any(|&e| e) {
                mask |= 1 << u;
            }
        }
        mask
    }

    /// Whether a unit of `mask` generates a coordinate from eye coordinates
    /// (Mesa's `_GenFlags & TEXGEN_NEED_EYE_COORD`, which puts lighting in eye space).
    pub fn need_eye_coords(&self, mask: u8) -> bool {
        (0..MAX_UNITS)
            .filter(|&u| mask & (1 << u) != 0)
            .flat_map(|u| self.units[u].gen.iter())
            .any(|g| g.enabled && g.mode.needs_eye_coords())
    }
}

/// Mesa's `_mesa_transform_vector`: the row vector `v` times `m`, each sum
/// in order, in f32 (how an eye plane is kept, `main/texgen.c`).
fn times(v: [f32; 4], m: &Mat4) -> [f32; 4] {
    let m = m.to_cols_array();
    [0, 1, 2, 3].map(|j| v[0] * m[4 * j] + v[1] * m[4 * j + 1] + v[2] * m[4 * j + 2] + v[3] * m[4 * j + 3])
}

fn check_index(i: u8) -> GlResult {
    if i < 3 {
        Ok(())
    } else {
        Err(GlError::InvalidEnum)
    }
}

fn check_source(s: CombineSrc) -> GlResult {
    match s {
        CombineSrc::TextureUnit(u) if usize::from(u) >= MAX_UNITS => Err(GlError::InvalidEnum),
        _ => Ok(()),
    }
}

fn scale_of(s: f32) -> GlResult<u8> {
    match s {
        1.0 => Ok(1),
        2.0 => Ok(2),
        4.0 => Ok(4),
        _ => Err(GlError::InvalidValue),
    }
}

impl TexUnit {
    /// Applies `p` (`glTexEnv`), or says why GL rejects it.
    fn set_env(&mut self, p: TexEnvParam) -> GlResult {
        let c = &mut self.combine;
        match p {
            TexEnvParam::Mode(m) => self.env_mode = m,
            TexEnvParam::Color(rgba) => self.env_color = rgba.map(|v| if v.is_nan() { 0.0 } else { v.clamp(0.0, 1.0) }),
            TexEnvParam::CombineRgb(f) => c.rgb = f,
            TexEnvParam::CombineAlpha(f) => {
                if matches!(f, CombineFn::Dot3Rgb | CombineFn::Dot3Rgba) {
                    return Err(GlError::InvalidEnum);
                }
                c.alpha = f
            }
            TexEnvParam::SrcRgb(i, s) => {
                check_index(i)?;
                check_source(s)?;
                c.src_rgb[usize::from(i)] = s
            }
            TexEnvParam::SrcAlpha(i, s) => {
                check_index(i)?;
                check_source(s)?;
                c.src_alpha[usize::from(i)] = s
            }
            TexEnvParam::OperandRgb(i, o) => {
                check_index(i)?;
                c.op_rgb[usize::from(i)] = o
            }
            TexEnvParam::OperandAlpha(i, o) => {
                check_index(i)?;
                if matches!(o, Operand::SrcColor | Operand::OneMinusSrcColor) {
                    return Err(GlError::InvalidEnum);
                }
                c.op_alpha[usize::from(i)] = o
            }
            TexEnvParam::RgbScale(s) => c.scale_rgb = scale_of(s)?,
            TexEnvParam::AlphaScale(s) => c.scale_alpha = scale_of(s)?,
            TexEnvParam::LodBias(b) => self.lod_bias = b,
        }
        Ok(())
    }

    fn env(&self, name: TexEnvParamName) -> GlResult<TexEnvParam> {
        let c = &self.combine;
        let i = |i: u8| check_index(i).map(|_| usize::from(i));
        Ok(match name {
            TexEnvParamName::Mode => TexEnvParam::Mode(self.env_mode),
            TexEnvParamName::Color => TexEnvParam::Color(self.env_color),
            TexEnvParamName::CombineRgb => TexEnvParam::CombineRgb(c.rgb),
            TexEnvParamName::CombineAlpha => TexEnvParam::CombineAlpha(c.alpha),
            TexEnvParamName::SrcRgb(k) => TexEnvParam::SrcRgb(k, c.src_rgb[i(k)?]),
            TexEnvParamName::SrcAlpha(k) => TexEnvParam::SrcAlpha(k, c.src_alpha[i(k)?]),
            TexEnvParamName::OperandRgb(k) => TexEnvParam::OperandRgb(k, c.op_rgb[i(k)?]),
            TexEnvParamName::OperandAlpha(k) => TexEnvParam::OperandAlpha(k, c.op_alpha[i(k)?]),
            TexEnvParamName::RgbScale => TexEnvParam::RgbScale(f32::from(c.scale_rgb)),
            TexEnvParamName::AlphaScale => TexEnvParam::AlphaScale(f32::from(c.scale_alpha)),
            TexEnvParamName::LodBias => TexEnvParam::LodBias(self.lod_bias),
        })
    }
}

impl Context {
    /// The enable flag of a texture capability on the active unit; `None`
    /// for every other capability.
    pub(crate) fn texture_flag_mut(&mut self, cap: Capability) -> Option<&mut bool> {
        let unit = self.active_texture_unit();
        let u = &mut self.tex_units.get_mut().units[unit];
        match cap {
            Capability::Texture(t) => Some(&mut u.enabled[target_index(t)]),
            Capability::TexGen(c) => Some(&mut u.gen[c.index()].enabled),
            _ => None,
        }
    }

    /// Whether a texture capability is enabled on the active unit; `None` for
    /// every other capability.
    pub(crate) fn texture_flag(&self, cap: Capability) -> Option<bool> {
        let u = &self.tex_units.units[self.active_texture_unit()];
        match cap {
            Capability::Texture(t) => Some(u.enabled[target_index(t)]),
            Capability::TexGen(c) => Some(u.gen[c.index()].enabled),
            _ => None,
        }
    }

    /// Every unit's texture state (enables, environment, generation, matrices).
    pub fn tex_units(&self) -> &TextureUnits {
        &self.tex_units
    }

    /// Replaces unit `unit`'s state but its matrix stack: how `glPopAttrib`
    /// restores `GL_TEXTURE_BIT` and `GL_ENABLE_BIT`.
    pub fn restore_tex_unit(&mut self, unit: usize, state: TexUnit) -> GlResult {
        self.outside()?;
        let ok = unit < MAX_UNITS;
        self.record(if ok { Ok(()) } else { Err(GlError::InvalidEnum) })?;
        self.tex_units.get_mut().units[unit] = state;
        Ok(())
    }

    /// `glTexEnv` on the active unit.
    pub fn tex_env(&mut self, p: TexEnvParam) -> GlResult {
        self.outside()?;
        let unit = self.active_texture_unit();
        let mut u = self.tex_units.units[unit];
        self.record(u.set_env(p))?;
        self.tex_units.get_mut().units[unit] = u;
        Ok(())
    }

    /// `glGetTexEnv` of the active unit; the colour as clamped.
    pub fn get_tex_env(&mut self, name: TexEnvParamName) -> GlResult<TexEnvParam> {
        self.outside()?;
        let r = self.tex_units.units[self.active_texture_unit()].env(name);
        self.record(r)
    }

    /// `glTexGen` on the active unit. `SphereMap` is for S and T only,
    /// `NormalMap` and `ReflectionMap` for S, T and R (else `InvalidEnum`);
    /// an eye plane is multiplied by the inverse of the modelview in force.
    pub fn tex_gen(&mut self, coord: TexCoordName, p: TexGenParam) -> GlResult {
        self.outside()?;
        let unit = self.active_texture_unit();
        let eye = match p {
            TexGenParam::EyePlane(plane) => {
                let inv = crate::inverse::inverse(&self.matrix(crate::matrix::MatrixMode::Modelview));
                times(plane, &inv)
            }
            _ => [0.0; 4],
        };
        let g = &mut self.tex_units.get_mut().units[unit].gen[coord.index()];
        match p {
            TexGenParam::Mode(m) => {
                let ok = match m {
                    TexGenMode::ObjectLinear | TexGenMode::EyeLinear => true,
                    TexGenMode::SphereMap => matches!(coord, TexCoordName::S | TexCoordName::T),
                    TexGenMode::NormalMap | TexGenMode::ReflectionMap => coord != TexCoordName::Q,
                };
                if !ok {
                    return self.record(Err(GlError::InvalidEnum));
                }
                g.mode = m;
            }
            TexGenParam::ObjectPlane(plane) => g.object_plane = plane,
            TexGenParam::EyePlane(_) => g.eye_plane = eye,
        }
        Ok(())
    }

    /// `glGetTexGen` of the active unit (the eye plane in eye coordinates).
    pub fn get_tex_gen(&mut self, coord: TexCoordName, name: TexGenParamName) -> GlResult<TexGenParam> {
        self.outside()?;
        let g = &self.tex_units.units[self.active_texture_unit()].gen[coord.index()];
        Ok(match name {
            TexGenParamName::Mode => TexGenParam::Mode(g.mode),
            TexGenParamName::ObjectPlane => TexGenParam::ObjectPlane(g.object_plane),
            TexGenParamName::EyePlane => TexGenParam::EyePlane(g.eye_plane),
        })
    }

    /// `glTexCoord4f`: unit 0's current texture coordinates.
    pub fn tex_coord(&mut self, c: [f32; 4]) {
        self.current.tex_coords[0] = glam::Vec4::from_array(c);
    }

    /// `glMultiTexCoord4f`: unit `unit`'s current texture coordinates
    /// (`InvalidEnum` from unit 8 on; allowed between `begin` and `end`).
    pub fn multi_tex_coord(&mut self, unit: u32, c: [f32; 4]) -> GlResult {
        let r = self
            .current
            .tex_coords
            .get_mut(unit as usize)
            .map(|t| *t = glam::Vec4::from_array(c))
            .ok_or(GlError::InvalidEnum);
        self.record(r)
    }

    /// `glClientActiveTexture`: the unit whose coordinate array
    /// `glTexCoordPointer` and `GL_TEXTURE_COORD_ARRAY` name (`InvalidEnum`
    /// from unit 8 on).
    pub fn client_active_texture(&mut self, unit: u32) -> GlResult {
        let r = if (unit as usize) < MAX_UNITS {
            self.tex_units.get_mut().client_active = unit as usize;
            Ok(())
        } else {
            Err(GlError::InvalidEnum)
        };
        self.record(r)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plane_times_matrix_sums_rows_of_columns() {
        let m = Mat4::from_cols_array(&[
            1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0, 10.0, 11.0, 12.0, 13.0, 14.0, 15.0, 16.0,
        ]);
        // u_j = v · column j.
        assert_eq!(times([1.0, 0.0, 0.0, 1.0], &m), [5.0, 13.0, 21.0, 29.0]);
    }
}
