//! `FragmentUniforms`: per-fragment values that change often and never change code.

/// Values a specialist reads through a pointer, so that changing them never
/// compiles anything. `#[repr(C)]` so compiled code can address its fields.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct FragmentUniforms {
    /// Scissor box as `[x0, y0, x1, y1]`, `x1`/`y1` exclusive, in window pixels.
    pub scissor: [i32; 4],
    /// `glBlendColor`, as unsigned normalized bytes R, G, B, A.
    pub blend_color: [u8; 4],
    /// `glAlphaFunc` reference, as an unsigned normalized byte.
    pub alpha_ref: u8,
    /// `glStencilFunc` reference, clamped to the stencil range.
    pub stencil_ref: u8,
    /// `glStencilFunc` mask, applied to reference and stored value before comparing.
    pub stencil_value_mask: u8,
    /// `glStencilMask`: which stencil bits may be written.
    pub stencil_write_mask: u8,
    /// Fog parameters and colour (f32 bits), read by the shading stage.
    pub fog: crate::shade::FogUniforms,
    /// What the deep colour formats read (`crate::deep`); specialists never do.
    pub deep: DeepUniforms,
}

/// The values of [`FragmentUniforms`] at f32 precision, for the deep colour
/// formats, as f32 bit patterns so that uniforms stay `Eq + Hash`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct DeepUniforms {
    /// `glAlphaFunc`'s reference, in `[0, 1]`.
    pub alpha_ref: u32,
    /// `glBlendColor`.
    pub blend_color: [u32; 4],
    /// Non-zero when fragment colours are clamped to `[0, 1]` in float
    /// buffers too (`GL_CLAMP_FRAGMENT_COLOR` `GL_TRUE`, `OSMesaColorClamp`);
    /// 0 is GL's `GL_FIXED_ONLY`. Unorm buffers always clamp.
    pub clamp: u32,
}

impl FragmentUniforms {
    /// The uniforms of a key's shading half
    /// ([`FragmentKey::split_shading`](crate::FragmentKey::split_shading)):
    /// these, with the stencil reference 1 written through all-ones masks.
    pub fn shading_half(&self) -> FragmentUniforms {
        FragmentUniforms {
            stencil_ref: 1,
            stencil_value_mask: 0xff,
            stencil_write_mask: 0xff,
            ..*self
        }
    }
}

impl Default for FragmentUniforms {
    /// GL's initial state: empty scissor box (set with the framebuffer size),
    /// zero references, all-ones masks.
    fn default() -> Self {
        FragmentUniforms {
            scissor: [0, 0, 0, 0],
            blend_color: [0, 0, 0, 0],
            alpha_ref: 0,
            stencil_ref: 0,
            stencil_value_mask: 0xff,
            stencil_write_mask: 0xff,
            fog: crate::shade::FogUniforms::default(),
            deep: DeepUniforms::default(),
        }
    }
}
