//! Lighting, material and user clip plane state (GL 1.5 §2.11, §2.14): the
//! values `glLight`, `glLightModel`, `glMaterial`, `glColorMaterial` and
//! `glClipPlane` set, checked the GL way. The per-vertex arithmetic that
//! reads them is [`crate::geometry::lighting`].

use crate::state::Face;
use glam::{Mat4, Vec4};

/// `GL_MAX_LIGHTS`.
pub const MAX_LIGHTS: usize = 8;
/// `GL_MAX_CLIP_PLANES`.
pub const MAX_CLIP_PLANES: usize = 6;
/// `GL_MAX_SPOT_EXPONENT` and the largest shininess (Mesa's 128).
pub const MAX_EXPONENT: f32 = 128.0;

/// A `glLight` parameter with its value. `Position` is in object
/// coordinates (transformed by the modelview at the call); `SpotDirection`
/// likewise (by its upper 3x3).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LightParam {
    Ambient([f32; 4]),
    Diffuse([f32; 4]),
    Specular([f32; 4]),
    Position([f32; 4]),
    SpotDirection([f32; 3]),
    SpotExponent(f32),
    SpotCutoff(f32),
    ConstantAttenuation(f32),
    LinearAttenuation(f32),
    QuadraticAttenuation(f32),
}

/// Which `glGetLight` value to read.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum LightParamName {
    Ambient,
    Diffuse,
    Specular,
    Position,
    SpotDirection,
    SpotExponent,
    SpotCutoff,
    ConstantAttenuation,
    LinearAttenuation,
    QuadraticAttenuation,
}

/// `glLightModel` parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LightModelParam {
    Ambient([f32; 4]),
    LocalViewer(bool),
    TwoSide(bool),
    ColorControl(ColorControl),
}

/// `GL_LIGHT_MODEL_COLOR_CONTROL`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ColorControl {
    SingleColor,
    SeparateSpecular,
}

/// A `glMaterial` parameter with its value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum MaterialParam {
    Ambient([f32; 4]),
    Diffuse([f32; 4]),
    AmbientAndDiffuse([f32; 4]),
    Specular([f32; 4]),
    Emission([f32; 4]),
    Shininess(f32),
}

/// Which `glGetMaterial` value to read.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum MaterialParamName {
    Ambient,
    Diffuse,
    Specular,
    Emission,
    Shininess,
}

/// `glColorMaterial` modes: which material values follow the current colour.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ColorMaterialMode {
    Emission,
    Ambient,
    Diffuse,
    Specular,
    AmbientAndDiffuse,
}

/// One light source, positions and directions in eye coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Light {
    pub enabled: bool,
    pub ambient: [f32; 4],
    pub diffuse: [f32; 4],
    pub specular: [f32; 4],
    pub position: [f32; 4],
    pub spot_direction: [f32; 3],
    pub spot_exponent: f32,
    pub spot_cutoff: f32,
    /// Constant, linear, quadratic.
    pub attenuation: [f32; 3],
}

impl Light {
    /// GL's initial light `index` (light 0 is white, the others black).
    pub fn new(index: usize) -> Light {
        let on = if index == 0 { 1.0 } else { 0.0 };
        Light {
            enabled: false,
            ambient: [0.0, 0.0, 0.0, 1.0],
            diffuse: [on, on, on, 1.0],
            specular: [on, on, on, 1.0],
            position: [0.0, 0.0, 1.0, 0.0],
            spot_direction: [0.0, 0.0, -1.0],
            spot_exponent: 0.0,
            spot_cutoff: 180.0,
            attenuation: [1.0, 0.0, 0.0],
        }
    }

    /// Mesa's `_CosCutoff`: `cosf` of the cutoff converted to radians in
    /// double, never below 0 (`main/light.c`).
    pub fn cos_cutoff(&self) -> f32 {
        let c = ((f64::from(self.spot_cutoff) * std::f64::consts::PI / 180.0) as f32).cos();
        c.max(0.0)
    }
}

/// The material of one face.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    pub ambient: [f32; 4],
    pub diffuse: [f32; 4],
    pub specular: [f32; 4],
    pub emission: [f32; 4],
    pub shininess: f32,
}

impl Material {
    pub const DEFAULT: Material = Material {
        ambient: [0.2, 0.2, 0.2, 1.0],
        diffuse: [0.8, 0.8, 0.8, 1.0],
        specular: [0.0, 0.0, 0.0, 1.0],
        emission: [0.0, 0.0, 0.0, 1.0],
        shininess: 0.0,
    };
}

/// Lighting, normal and user clip plane state (`GL_LIGHTING_BIT` and the
/// transform part of `GL_TRANSFORM_BIT`).
#[derive(Clone, Debug, PartialEq)]
pub struct LightingState {
    pub enabled: bool,
    pub lights: [Light; MAX_LIGHTS],
    pub model_ambient: [f32; 4],
    pub local_viewer: bool,
    pub two_side: bool,
    pub color_control: ColorControl,
    /// Front and back.
    pub materials: [Material; 2],
    pub color_material: bool,
    pub color_material_face: Face,
    pub color_material_mode: ColorMaterialMode,
    pub normalize: bool,
    pub rescale_normal: bool,
    /// Plane equations in eye coordinates.
    pub clip_planes: [[f64; 4]; MAX_CLIP_PLANES],
    pub clip_enabled: [bool; MAX_CLIP_PLANES],
}

impl Default for LightingState {
    fn default() -> LightingState {
        LightingState {
            enabled: false,
            lights: std::array::from_fn(Light::new),
            model_ambient: [0.2, 0.2, 0.2, 1.0],
            local_viewer: false,
            two_side: false,
            color_control: ColorControl::SingleColor,
            materials: [Material::DEFAULT; 2],
            color_material: false,
            color_material_face: Face::FrontAndBack,
            color_material_mode: ColorMaterialMode::AmbientAndDiffuse,
            normalize: false,
            rescale_normal: false,
            clip_planes: [[0.0; 4]; MAX_CLIP_PLANES],
            clip_enabled: [false; MAX_CLIP_PLANES],
        }
    }
}

/// `Err(InvalidValue)` unless `ok`.
fn value(ok: bool) -> Result<(), crate::GlError> {
    if ok {
        Ok(())
    } else {
        Err(crate::GlError::InvalidValue)
    }
}

/// The faces (0 front, 1 back) a `Face` names.
pub fn sides(face: Face) -> &'static [usize] {
    match face {
        Face::Front => &[0],
        Face::Back => &[1],
        Face::FrontAndBack => &[0, 1],
    }
}

impl LightingState {
    /// `glLight` on light `index` with the modelview `mv` in force.
    pub fn set_light(&mut self, index: u32, param: LightParam, mv: &Mat4) -> crate::GlResult {
        let l = self.lights.get_mut(index as usize).ok_or(crate::GlError::InvalidEnum)?;
        match param {
            LightParam::Ambient(c) => l.ambient = c,
            LightParam::Diffuse(c) => l.diffuse = c,
            LightParam::Specular(c) => l.specular = c,
            LightParam::Position(p) => l.position = transform_point(mv, p),
            LightParam::SpotDirection(d) => l.spot_direction = transform_direction(mv, d),
            LightParam::SpotExponent(e) => {
                value((0.0..=MAX_EXPONENT).contains(&e))?;
                l.spot_exponent = e;
            }
            LightParam::SpotCutoff(c) => {
                value((0.0..=90.0).contains(&c) || c == 180.0)?;
                l.spot_cutoff = c;
            }
            LightParam::ConstantAttenuation(a) => {
                value(a >= 0.0)?;
                l.attenuation[0] = a;
            }
            LightParam::LinearAttenuation(a) => {
                value(a >= 0.0)?;
                l.attenuation[1] = a;
            }
            LightParam::QuadraticAttenuation(a) => {
                value(a >= 0.0)?;
                l.attenuation[2] = a;
            }
        }
        Ok(())
    }

    /// `glGetLight`: the value stored (positions and directions in eye coordinates).
    pub fn light(&self, index: u32, name: LightParamName) -> crate::GlResult<LightParam> {
        let l = self.lights.get(index as usize).ok_or(crate::GlError::InvalidEnum)?;
        Ok(match name {
            LightParamName::Ambient => LightParam::Ambient(l.ambient),
            LightParamName::Diffuse => LightParam::Diffuse(l.diffuse),
            LightParamName::Specular => LightParam::Specular(l.specular),
            LightParamName::Position => LightParam::Position(l.position),
            LightParamName::SpotDirection => LightParam::SpotDirection(l.spot_direction),
            LightParamName::SpotExponent => LightParam::SpotExponent(l.spot_exponent),
            LightParamName::SpotCutoff => LightParam::SpotCutoff(l.spot_cutoff),
            LightParamName::ConstantAttenuation => LightParam::ConstantAttenuation(l.attenuation[0]),
            LightParamName::LinearAttenuation => LightParam::LinearAttenuation(l.attenuation[1]),
            LightParamName::QuadraticAttenuation => LightParam::QuadraticAttenuation(l.attenuation[2]),
        })
    }

    /// `glLightModel`.
    pub fn set_model(&mut self, param: LightModelParam) {
        match param {
            LightModelParam::Ambient(c) => self.model_ambient = c,
            LightModelParam::LocalViewer(on) => self.local_viewer = on,
            LightModelParam::TwoSide(on) => self.two_side = on,
            LightModelParam::ColorControl(c) => self.color_control = c,
        }
    }

    /// `glMaterial` on `face`; shininess outside `[0, 128]` is `InvalidValue`.
    /// With `GL_COLOR_MATERIAL` on, the values it tracks keep following the
    /// colour: a `glMaterial` of them is ignored (Mesa's `_mesa_Materialfv`,
    /// `vbo/vbo_exec_api.c`, masks out `_ColorMaterialBitmask`).
    pub fn set_material(&mut self, face: Face, param: MaterialParam) -> crate::GlResult {
        if let MaterialParam::Shininess(s) = param {
            value((0.0..=MAX_EXPONENT).contains(&s))?;
        }
        let tracked = |side: usize, which: ColorMaterialMode| {
            self.color_material
                && sides(self.color_material_face).contains(&side)
                && (self.color_material_mode == which
                    || (self.color_material_mode == ColorMaterialMode::AmbientAndDiffuse
                        && matches!(which, ColorMaterialMode::Ambient | ColorMaterialMode::Diffuse)))
        };
        let mut keep = [[false; 4]; 2]; // [side][emission, ambient, diffuse, specular]
        for (side, k) in keep.iter_mut().enumerate() {
            *k = [
                ColorMaterialMode::Emission,
                ColorMaterialMode::Ambient,
                ColorMaterialMode::Diffuse,
                ColorMaterialMode::Specular,
            ]
            .map(|which| tracked(side, which));
        }
        for &side in sides(face) {
            let m = &mut self.materials[side];
            let [emission, ambient, diffuse, specular] = keep[side];
            let set = |dst: &mut [f32; 4], c: [f32; 4], kept: bool| {
                if !kept {
                    *dst = c;
                }
            };
            match param {
                MaterialParam::Ambient(c) => set(&mut m.ambient, c, ambient),
                MaterialParam::Diffuse(c) => set(&mut m.diffuse, c, diffuse),
                MaterialParam::AmbientAndDiffuse(c) => {
                    set(&mut m.ambient, c, ambient);
                    set(&mut m.diffuse, c, diffuse);
                }
                MaterialParam::Specular(c) => set(&mut m.specular, c, specular),
                MaterialParam::Emission(c) => set(&mut m.emission, c, emission),
                MaterialParam::Shininess(s) => m.shininess = s,
            }
        }
        Ok(())
    }

    /// `glGetMaterial` of one face (`FrontAndBack` is `InvalidEnum`).
    pub fn material(&self, face: Face, name: MaterialParamName) -> crate::GlResult<MaterialParam> {
        let m = match face {
            Face::Front => &self.materials[0],
            Face::Back => &self.materials[1],
            Face::FrontAndBack => return Err(crate::GlError::InvalidEnum),
        };
        Ok(match name {
            MaterialParamName::Ambient => MaterialParam::Ambient(m.ambient),
            MaterialParamName::Diffuse => MaterialParam::Diffuse(m.diffuse),
            MaterialParamName::Specular => MaterialParam::Specular(m.specular),
            MaterialParamName::Emission => MaterialParam::Emission(m.emission),
            MaterialParamName::Shininess => MaterialParam::Shininess(m.shininess),
        })
    }

    /// With `GL_COLOR_MATERIAL` on, the material values it names follow `color`.
    pub fn track_color(&mut self, color: Vec4) {
        if !self.color_material {
            return;
        }
        let c = color.to_array();
        let mode = self.color_material_mode;
        for &side in sides(self.color_material_face) {
            let m = &mut self.materials[side];
            match mode {
                ColorMaterialMode::Emission => m.emission = c,
                ColorMaterialMode::Ambient => m.ambient = c,
                ColorMaterialMode::Diffuse => m.diffuse = c,
                ColorMaterialMode::Specular => m.specular = c,
                ColorMaterialMode::AmbientAndDiffuse => (m.ambient, m.diffuse) = (c, c),
            }
        }
    }

    /// `glClipPlane`: `plane` in object coordinates, stored in eye
    /// coordinates (times the inverse modelview, as Mesa's `main/clip.c`).
    pub fn set_clip_plane(&mut self, index: u32, plane: [f64; 4], mv: &Mat4) -> crate::GlResult {
        let slot = self
            .clip_planes
            .get_mut(index as usize)
            .ok_or(crate::GlError::InvalidEnum)?;
        // Mesa keeps the plane in f32: e_j = p · column j of the inverse,
        // summed in order (`_mesa_transform_vector`).
        let inv = crate::inverse::inverse(mv).to_cols_array();
        let p = plane.map(|c| c as f32);
        *slot = [0, 1, 2, 3].map(|j| {
            let c = &inv[4 * j..4 * j + 4];
            f64::from(p[0] * c[0] + p[1] * c[1] + p[2] * c[2] + p[3] * c[3])
        });
        Ok(())
    }

    /// Whether any enabled user clip plane exists.
    pub fn clipping(&self) -> bool {
        self.clip_enabled.iter().any(|&e| e)
    }
}

/// Mesa's `TRANSFORM_POINT`: `m · p` in f32, terms summed in column order.
pub fn transform_point(m: &Mat4, p: [f32; 4]) -> [f32; 4] {
    let c = m.to_cols_array();
    [0, 1, 2, 3].map(|r| c[r] * p[0] + c[4 + r] * p[1] + c[8 + r] * p[2] + c[12 + r] * p[3])
}

/// Mesa's `TRANSFORM_DIRECTION`: the upper 3x3 of `m` times `d`, in f32.
pub fn transform_direction(m: &Mat4, d: [f32; 3]) -> [f32; 3] {
    let c = m.to_cols_array();
    [0, 1, 2].map(|r| d[0] * c[r] + d[1] * c[4 + r] + d[2] * c[8 + r])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn glmaterial_of_a_tracked_value_is_ignored_while_colour_material_is_on() {
        let mut st = LightingState {
            color_material: true,
            color_material_face: Face::Front,
            color_material_mode: ColorMaterialMode::Diffuse,
            ..LightingState::default()
        };
        st.track_color(Vec4::new(0.0, 1.0, 0.0, 1.0));
        let red = [1.0, 0.0, 0.0, 1.0];
        st.set_material(Face::FrontAndBack, MaterialParam::AmbientAndDiffuse(red))
            .unwrap();
        // The front diffuse keeps following the colour; the front ambient and
        // both back values take the call's.
        assert_eq!(st.materials[0].diffuse, [0.0, 1.0, 0.0, 1.0]);
        assert_eq!(st.materials[0].ambient, red);
        assert_eq!((st.materials[1].ambient, st.materials[1].diffuse), (red, red));
        // Off again, the call applies.
        st.color_material = false;
        st.set_material(Face::Front, MaterialParam::Diffuse(red)).unwrap();
        assert_eq!(st.materials[0].diffuse, red);
    }
}
