//! `glClipControl` (GL 4.5, ARB_clip_control): where window y = 0 is and
//! which clip-space z range maps onto the depth range.
//!
//! What it changes, as Mesa 22 does (`main/viewport.c`
//! `_mesa_get_viewport_xform`, `state_tracker/st_atom_rasterizer.c`):
//! - the viewport transform: `GL_UPPER_LEFT` negates the y scale;
//!   `GL_ZERO_TO_ONE` maps z with scale `f − n` and translate `n` (instead of
//!   `(f − n)/2` and `(n + f)/2`);
//! - clipping: `GL_ZERO_TO_ONE` moves the near plane from `z ≥ −w` to `z ≥ 0`
//!   (gallium's `clip_halfz`);
//! - facing: `GL_UPPER_LEFT` reverses the winding seen in window space, and
//!   facing reverses with it (`front_ccw ^= 1`), so a polygon keeps its face;
//! - the raster position (mapped and clipped as a vertex); `glWindowPos` not.

use crate::context::Context;
use crate::error::{GlError, GlResult};

/// `GL_CLIP_ORIGIN`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum ClipOrigin {
    /// `GL_LOWER_LEFT`, GL's usual.
    #[default]
    LowerLeft,
    /// `GL_UPPER_LEFT`: clip-space y points down the window.
    UpperLeft,
}

/// `GL_CLIP_DEPTH_MODE`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum ClipDepthMode {
    /// `GL_NEGATIVE_ONE_TO_ONE`, GL's usual: z/w in `[-1, 1]`.
    #[default]
    NegativeOneToOne,
    /// `GL_ZERO_TO_ONE`: z/w in `[0, 1]` (reverse Z with a float depth buffer).
    ZeroToOne,
}

/// The two together, part of the transform state (`GL_TRANSFORM_BIT`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct ClipControl {
    pub origin: ClipOrigin,
    pub depth: ClipDepthMode,
}

impl ClipControl {
    pub const GL_LOWER_LEFT: u32 = 0x8CA1;
    pub const GL_UPPER_LEFT: u32 = 0x8CA2;
    pub const GL_NEGATIVE_ONE_TO_ONE: u32 = 0x935E;
    pub const GL_ZERO_TO_ONE: u32 = 0x935F;

    /// From `glClipControl`'s enums; `InvalidEnum` for others (origin checked first).
    pub fn from_gl(origin: u32, depth: u32) -> GlResult<ClipControl> {
        let origin = match origin {
            ClipControl::GL_LOWER_LEFT => ClipOrigin::LowerLeft,
            ClipControl::GL_UPPER_LEFT => ClipOrigin::UpperLeft,
            _ => return Err(GlError::InvalidEnum),
        };
        let depth = match depth {
            ClipControl::GL_NEGATIVE_ONE_TO_ONE => ClipDepthMode::NegativeOneToOne,
            ClipControl::GL_ZERO_TO_ONE => ClipDepthMode::ZeroToOne,
            _ => return Err(GlError::InvalidEnum),
        };
        Ok(ClipControl { origin, depth })
    }

    /// `GL_CLIP_ORIGIN`'s and `GL_CLIP_DEPTH_MODE`'s values.
    pub fn to_gl(self) -> (u32, u32) {
        let origin = match self.origin {
            ClipOrigin::LowerLeft => ClipControl::GL_LOWER_LEFT,
            ClipOrigin::UpperLeft => ClipControl::GL_UPPER_LEFT,
        };
        let depth = match self.depth {
            ClipDepthMode::NegativeOneToOne => ClipControl::GL_NEGATIVE_ONE_TO_ONE,
            ClipDepthMode::ZeroToOne => ClipControl::GL_ZERO_TO_ONE,
        };
        (origin, depth)
    }

    /// Whether clip-space y is flipped in the window.
    pub fn upper_left(self) -> bool {
        self.origin == ClipOrigin::UpperLeft
    }

    /// Whether the near plane is `z ≥ 0` (gallium's `clip_halfz`).
    pub fn half_z(self) -> bool {
        self.depth == ClipDepthMode::ZeroToOne
    }

    /// The viewport's z scale and translate for depth range `(n, f)`, in
    /// f32 from f64 as `_mesa_get_viewport_xform`.
    pub fn depth_xform(self, (n, f): (f64, f64)) -> (f32, f32) {
        match self.depth {
            ClipDepthMode::NegativeOneToOne => ((0.5 * (f - n)) as f32, (0.5 * (n + f)) as f32),
            ClipDepthMode::ZeroToOne => ((f - n) as f32, n as f32),
        }
    }

    /// The viewport's y scale for a viewport `height` pixels tall.
    pub fn y_scale(self, height: f32) -> f32 {
        match self.origin {
            ClipOrigin::LowerLeft => 0.5 * height,
            ClipOrigin::UpperLeft => -0.5 * height,
        }
    }
}

impl Context {
    /// `glClipControl(origin, depth)`: `InvalidEnum` for an unknown origin or
    /// depth mode, `InvalidOperation` inside `begin`/`end`.
    pub fn clip_control(&mut self, origin: u32, depth: u32) -> GlResult {
        self.outside()?;
        let c = self.record(ClipControl::from_gl(origin, depth))?;
        if self.state.clip_control != c {
            self.state.get_mut().clip_control = c;
        }
        Ok(())
    }

    /// The clip control state (`GL_CLIP_ORIGIN`, `GL_CLIP_DEPTH_MODE`).
    pub fn clip_control_state(&self) -> ClipControl {
        self.state.clip_control
    }

    /// Puts back a clip control state (`glPopAttrib(GL_TRANSFORM_BIT)`).
    pub fn set_clip_control(&mut self, c: ClipControl) -> GlResult {
        self.outside()?;
        if self.state.clip_control != c {
            self.state.get_mut().clip_control = c;
        }
        Ok(())
    }
}
