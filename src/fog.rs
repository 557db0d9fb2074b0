//! Fog state (GL 1.5 §3.10) and its `glFog` parameters. The per-fragment
//! arithmetic is `softgl_jit::shade`'s; here is what the API sets.

pub use softgl_jit::FogMode;
use softgl_jit::FogUniforms;

/// `GL_FOG_COORD_SRC`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum FogCoordSrc {
    /// `GL_FRAGMENT_DEPTH`: the eye-space distance `|z_eye|`.
    FragmentDepth,
    /// `GL_FOG_COORD`: the vertex's `glFogCoord`.
    FogCoord,
}

/// One `glFog` parameter.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FogParam {
    Mode(FogMode),
    /// Must not be negative (`GL_INVALID_VALUE`).
    Density(f32),
    Start(f32),
    End(f32),
    /// Kept as given; the fragment stages use it clamped to `[0, 1]`.
    Color([f32; 4]),
    /// `GL_FOG_INDEX`: kept for queries only (no colour-index mode).
    Index(f32),
    CoordSrc(FogCoordSrc),
}

/// The fog state of a context (`GL_FOG_BIT`, with the enable).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FogState {
    pub enabled: bool,
    pub mode: FogMode,
    pub density: f32,
    pub start: f32,
    pub end: f32,
    pub color: [f32; 4],
    pub index: f32,
    pub coord_src: FogCoordSrc,
}

impl Default for FogState {
    /// GL's initial fog state.
    fn default() -> Self {
        FogState {
            enabled: false,
            mode: FogMode::Exp,
            density: 1.0,
            start: 0.0,
            end: 1.0,
            color: [0.0; 4],
            index: 0.0,
            coord_src: FogCoordSrc::FragmentDepth,
        }
    }
}

impl FogState {
    /// Applies `p`; a negative (or NaN) density is `Err` and changes nothing.
    pub fn set(&mut self, p: FogParam) -> Result<(), crate::GlError> {
        match p {
            FogParam::Mode(m) => self.mode = m,
            FogParam::Density(d) => {
                if d.is_nan() || d < 0.0 {
                    return Err(crate::GlError::InvalidValue);
                }
                self.density = d;
            }
            FogParam::Start(s) => self.start = s,
            FogParam::End(e) => self.end = e,
            FogParam::Color(c) => self.color = c,
            FogParam::Index(i) => self.index = i,
            FogParam::CoordSrc(s) => self.coord_src = s,
        }
        Ok(())
    }

    /// The values the fragment stages read.
    pub fn uniforms(&self) -> FogUniforms {
        let [r, g, b, _] = self.color;
        FogUniforms::new(self.start, self.end, self.density, [r, g, b])
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use softgl_jit::shade::fog_factor;

    /// GL 1.5 §3.10's fog factors, computed in f64 from the spec's formulas,
    /// against the f32 arithmetic llvmpipe runs (a few ulp apart at most).
    #[test]
    fn fog_factors_follow_the_spec_formulas() {
        let state = |mode, density, start, end| FogState {
            mode,
            density,
            start,
            end,
            ..FogState::default()
        };
        type Spec = fn(&FogState, f64) -> f64;
        let cases: [(FogState, Spec); 3] = [
            (state(FogMode::Linear, 1.0, 2.0, 10.0), |s, c| {
                (f64::from(s.end) - c) / (f64::from(s.end) - f64::from(s.start))
            }),
            (state(FogMode::Exp, 0.35, 0.0, 1.0), |s, c| {
                (-f64::from(s.density) * c).exp()
            }),
            (state(FogMode::Exp2, 0.2, 0.0, 1.0), |s, c| {
                (-(f64::from(s.density) * c).powi(2)).exp()
            }),
        ];
        for (s, spec) in cases {
            for k in 0..=48 {
                let c = k as f32 * 0.25;
                let want = spec(&s, f64::from(c)).clamp(0.0, 1.0);
                let got = f64::from(fog_factor(s.mode, c, &s.uniforms()));
                assert!((got - want).abs() <= 1e-6, "{:?} at {c}: {got} vs {want}", s.mode);
            }
        }
        // Hand-computed values: linear 2..10 at 4 is 6/8; exp with density
        // ln(2) at 1 is 1/2; exp2 with density 1 at 0 is 1.
        let lin = state(FogMode::Linear, 1.0, 2.0, 10.0);
        assert_eq!(fog_factor(FogMode::Linear, 4.0, &lin.uniforms()), 0.75);
        let exp = state(FogMode::Exp, std::f32::consts::LN_2, 0.0, 1.0);
        assert!((fog_factor(FogMode::Exp, 1.0, &exp.uniforms()) - 0.5).abs() < 1e-6);
        assert_eq!(fog_factor(FogMode::Exp2, 0.0, &FogState::default().uniforms()), 1.0);
        // end == start: Mesa's scale is 1 and its bias -end, so f = c - end, clamped.
        let tie = state(FogMode::Linear, 1.0, 5.0, 5.0);
        assert_eq!(fog_factor(FogMode::Linear, 5.5, &tie.uniforms()), 0.5);
        assert_eq!(fog_factor(FogMode::Linear, 4.0, &tie.uniforms()), 0.0);
    }

    #[test]
    fn negative_density_is_refused() {
        let mut s = FogState::default();
        assert_eq!(s.set(FogParam::Density(-0.5)), Err(crate::GlError::InvalidValue));
        assert_eq!(s.set(FogParam::Density(f32::NAN)), Err(crate::GlError::InvalidValue));
        assert_eq!(s.density, 1.0);
        s.set(FogParam::Density(0.0)).unwrap();
        assert_eq!(s.density, 0.0);
    }
}
