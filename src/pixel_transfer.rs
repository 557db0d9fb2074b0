//! Pixel transfer state (GL 1.5 §3.6.3): `glPixelZoom`, `glPixelTransfer`
//! (colour and depth scale and bias, `GL_MAP_COLOR`, `GL_MAP_STENCIL`,
//! `GL_INDEX_SHIFT`, `GL_INDEX_OFFSET`) and the pixel maps (`glPixelMap`),
//! and the operations they make on the pixels `glDrawPixels` and
//! `glCopyPixels` draw (`pixel_rect.rs`).

use crate::error::{GlError, GlResult};

/// `GL_MAX_PIXEL_MAP_TABLE` (Mesa's `MAX_PIXEL_MAP_TABLE`).
pub const MAX_PIXEL_MAP_TABLE: usize = 256;

/// The ten pixel maps, in GL's enum order (`GL_PIXEL_MAP_I_TO_I` = 0x0C70 on).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PixelMapName {
    IToI,
    SToS,
    IToR,
    IToG,
    IToB,
    IToA,
    RToR,
    GToG,
    BToB,
    AToA,
}

impl PixelMapName {
    pub const ALL: [PixelMapName; 10] = [
        PixelMapName::IToI,
        PixelMapName::SToS,
        PixelMapName::IToR,
        PixelMapName::IToG,
        PixelMapName::IToB,
        PixelMapName::IToA,
        PixelMapName::RToR,
        PixelMapName::GToG,
        PixelMapName::BToB,
        PixelMapName::AToA,
    ];

    /// The map of GL enum `e` (`GL_PIXEL_MAP_I_TO_I` … `GL_PIXEL_MAP_A_TO_A`).
    pub fn from_gl(e: u32) -> Option<PixelMapName> {
        e.checked_sub(0x0C70).and_then(|i| Self::ALL.get(i as usize).copied())
    }

    pub fn index(self) -> usize {
        self as usize
    }

    /// Whether the map is indexed by a colour or stencil index (its size must
    /// be a power of two, its values are indices, not clamped).
    pub fn indexed(self) -> bool {
        matches!(self, PixelMapName::IToI | PixelMapName::SToS)
    }

    /// Whether its values are colours (clamped to `[0, 1]` when set).
    pub fn colour(self) -> bool {
        !self.indexed()
    }

    /// Whether its index is a colour or stencil index (the `I_TO_*` and
    /// `S_TO_S` maps: sizes a power of two).
    pub fn from_index(self) -> bool {
        matches!(
            self,
            PixelMapName::IToI
                | PixelMapName::SToS
                | PixelMapName::IToR
                | PixelMapName::IToG
                | PixelMapName::IToB
                | PixelMapName::IToA
        )
    }
}

/// `glPixelTransfer` parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PixelTransferParam {
    MapColor(bool),
    MapStencil(bool),
    IndexShift(i32),
    IndexOffset(i32),
    /// Component (0 red … 3 alpha) scale.
    Scale(usize, f32),
    Bias(usize, f32),
    DepthScale(f32),
    DepthBias(f32),
}

/// The pixel zoom, transfer parameters and maps.
#[derive(Clone, Debug, PartialEq)]
pub struct PixelState {
    /// `GL_ZOOM_X`, `GL_ZOOM_Y`.
    pub zoom: [f32; 2],
    pub scale: [f32; 4],
    pub bias: [f32; 4],
    pub depth_scale: f32,
    pub depth_bias: f32,
    pub map_color: bool,
    pub map_stencil: bool,
    pub index_shift: i32,
    pub index_offset: i32,
    /// The maps, in [`PixelMapName`] order: each one entry, 0, at first.
    pub maps: [Vec<f32>; 10],
}

impl Default for PixelState {
    fn default() -> PixelState {
        PixelState {
            zoom: [1.0, 1.0],
            scale: [1.0; 4],
            bias: [0.0; 4],
            depth_scale: 1.0,
            depth_bias: 0.0,
            map_color: false,
            map_stencil: false,
            index_shift: 0,
            index_offset: 0,
            maps: std::array::from_fn(|_| vec![0.0]),
        }
    }
}

impl PixelState {
    /// Sets one transfer parameter.
    pub fn set(&mut self, p: PixelTransferParam) {
        match p {
            PixelTransferParam::MapColor(b) => self.map_color = b,
            PixelTransferParam::MapStencil(b) => self.map_stencil = b,
            PixelTransferParam::IndexShift(s) => self.index_shift = s,
            PixelTransferParam::IndexOffset(o) => self.index_offset = o,
            PixelTransferParam::Scale(c, v) => self.scale[c.min(3)] = v,
            PixelTransferParam::Bias(c, v) => self.bias[c.min(3)] = v,
            PixelTransferParam::DepthScale(v) => self.depth_scale = v,
            PixelTransferParam::DepthBias(v) => self.depth_bias = v,
        }
    }

    /// `glPixelMap`: `values` become map `name`: 1 to 256 entries (a power
    /// of two for the maps indexed by an index), else `InvalidValue`.
    /// Colour values are clamped to `[0, 1]` (Mesa's `store_pixelmap`).
    pub fn set_map(&mut self, name: PixelMapName, values: &[f32]) -> GlResult {
        let n = values.len();
        if !(1..=MAX_PIXEL_MAP_TABLE).contains(&n) || (name.from_index() && !n.is_power_of_two()) {
            return Err(GlError::InvalidValue);
        }
        self.maps[name.index()] = values
            .iter()
            .map(|&v| if name.colour() { v.clamp(0.0, 1.0) } else { v })
            .collect();
        Ok(())
    }

    /// Map `name`.
    pub fn map(&self, name: PixelMapName) -> &[f32] {
        &self.maps[name.index()]
    }

    /// Whether any transfer operation does something (checked once per
    /// `glTexImage`/`glReadPixels` call: the identity costs nothing else).
    pub fn is_identity(&self) -> bool {
        !(self.scales_or_biases()
            || self.map_color
            || self.map_stencil
            || self.depth_scale != 1.0
            || self.depth_bias != 0.0
            || self.index_shift != 0
            || self.index_offset != 0)
    }

    /// The colour transfer of Mesa's CPU paths (texture uploads, `glReadPixels`,
    /// `glCopyTexImage`: `_mesa_apply_rgba_transfer_ops`, `main/pixeltransfer.c`):
    /// scale and bias as a product then a sum, each map looked up at
    /// `rint(c·(size − 1))` as GL says, then clamped to `[0, 1]` (NaN as 0).
    pub fn cpu_colour(&self, c: [f32; 4]) -> [f32; 4] {
        let mut out = c;
        if self.scales_or_biases() {
            for k in 0..4 {
                out[k] = c[k] * self.scale[k] + self.bias[k];
            }
        }
        let clamp = |v: f32| if v.is_nan() { 0.0 } else { v.clamp(0.0, 1.0) };
        if self.map_color {
            let names = [
                PixelMapName::RToR,
                PixelMapName::GToG,
                PixelMapName::BToB,
                PixelMapName::AToA,
            ];
            for (k, name) in names.into_iter().enumerate() {
                let m = self.map(name);
                let i = (clamp(out[k]) * (m.len() - 1) as f32).round_ties_even() as usize;
                out[k] = m[i.min(m.len() - 1)];
            }
        }
        out.map(clamp)
    }

    /// Bytes read by `glReadPixels` in `format` ([`crate::ReadFormat`])
    /// through [`Self::cpu_colour`], each component then rounded as Mesa
    /// packs a float (`_mesa_float_to_unorm`: f32 product, ties to even).
    pub fn transfer_read(&self, bytes: &mut [u8], format: crate::ReadFormat) {
        use crate::ReadFormat as F;
        let (bpp, order): (usize, [usize; 4]) = match format {
            F::Rgba8 => (4, [0, 1, 2, 3]),
            F::Bgra8 => (4, [2, 1, 0, 3]),
            F::Rgb8 => (3, [0, 1, 2, 3]),
        };
        for px in bytes.chunks_exact_mut(bpp) {
            let mut c = [0.0, 0.0, 0.0, 1.0];
            for k in 0..bpp {
                c[order[k]] = f32::from(px[k]) * (1.0 / 255.0);
            }
            let c = self.cpu_colour(c);
            for k in 0..bpp {
                px[k] = (c[order[k]] * 255.0).round_ties_even() as u8;
            }
        }
    }

    /// Whether colour scale or bias does anything.
    pub fn scales_or_biases(&self) -> bool {
        self.scale != [1.0; 4] || self.bias != [0.0; 4]
    }

    /// A colour after scale and bias and, with `GL_MAP_COLOR`, the maps:
    /// `c·scale + bias`, then the maps ([`lookup`]).
    pub fn colour(&self, c: [f32; 4]) -> [f32; 4] {
        let mut out = c;
        if self.scales_or_biases() {
            for k in 0..4 {
                // One fused multiply-add (`nir_lower_drawpixels.c`: `ffma`).
                out[k] = c[k].mul_add(self.scale[k], self.bias[k]);
            }
        }
        if self.map_color {
            for (k, name) in [
                PixelMapName::RToR,
                PixelMapName::GToG,
                PixelMapName::BToB,
                PixelMapName::AToA,
            ]
            .into_iter()
            .enumerate()
            {
                out[k] = lookup(self.map(name), out[k]);
            }
        }
        out
    }

    /// A colour index after shift and offset, as RGBA through the
    /// `I_TO_R` … `I_TO_A` maps (an RGBA context always maps indices).
    pub fn index_colour(&self, i: i64) -> [f32; 4] {
        let i = self.shifted(i);
        [
            PixelMapName::IToR,
            PixelMapName::IToG,
            PixelMapName::IToB,
            PixelMapName::IToA,
        ]
        .map(|name| {
            let m = self.map(name);
            m[(i & (m.len() as i64 - 1)) as usize]
        })
    }

    /// A stencil index after shift and offset and, with `GL_MAP_STENCIL`, the `S_TO_S` map.
    pub fn stencil(&self, s: i64) -> i64 {
        let s = self.shifted(s);
        if self.map_stencil {
            let m = self.map(PixelMapName::SToS);
            m[(s & (m.len() as i64 - 1)) as usize] as i64
        } else {
            s
        }
    }

    /// A depth after scale and bias, clamped to `[0, 1]`.
    pub fn depth(&self, d: f32) -> f32 {
        let d = d * self.depth_scale + self.depth_bias;
        if d.is_nan() {
            0.0
        } else {
            d.clamp(0.0, 1.0)
        }
    }

    fn shifted(&self, i: i64) -> i64 {
        let s = self.index_shift;
        let shifted = if s >= 0 {
            i.checked_shl(s as u32).unwrap_or(0)
        } else {
            i >> (-s).min(63)
        };
        shifted.wrapping_add(i64::from(self.index_offset))
    }
}

/// The entry of `map` colour `c` reads, as llvmpipe reads it: Mesa packs
/// the maps into a 256-wide texture (entry `k·size/256` at texel `k`,
/// `load_color_map_texture` in `st_atom_pixeltransfer.c`) sampled nearest
/// at `c` (`floor(c·256)`, clamped to the edge). GL's rule,
/// `rint(c·(size − 1))`, picks another entry for some `c` (0.9 of 8 entries:
/// 6 by GL, 7 here).
fn lookup(map: &[f32], c: f32) -> f32 {
    const TEX: usize = 256;
    let c = if c.is_nan() { 0.0 } else { c.clamp(0.0, 1.0) };
    let texel = ((c * TEX as f32).floor() as usize).min(TEX - 1);
    map[(texel * map.len() / TEX).min(map.len() - 1)]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn maps_are_checked_clamped_and_looked_up() {
        let mut p = PixelState::default();
        assert_eq!(p.set_map(PixelMapName::IToR, &[0.0; 3]), Err(GlError::InvalidValue));
        assert_eq!(p.set_map(PixelMapName::RToR, &[]), Err(GlError::InvalidValue));
        p.set_map(PixelMapName::RToR, &[1.0, 2.0, -1.0]).unwrap();
        assert_eq!(p.map(PixelMapName::RToR), [1.0, 1.0, 0.0]);
        p.set(PixelTransferParam::MapColor(true));
        p.set(PixelTransferParam::Scale(0, 2.0));
        // 0.3·2 = 0.6 → texel 153 → entry 153·3/256 = 1.
        assert_eq!(p.colour([0.3, 0.5, 0.5, 0.5])[0], 1.0);
        assert_eq!(lookup(&[0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7], 0.9), 0.7);
        p.set(PixelTransferParam::IndexShift(2));
        p.set(PixelTransferParam::IndexOffset(1));
        p.set_map(PixelMapName::SToS, &[0.0, 10.0, 20.0, 30.0]).unwrap();
        assert_eq!(p.stencil(3), 13);
        p.set(PixelTransferParam::MapStencil(true));
        assert_eq!(p.stencil(3), 10.0 as i64);
        assert_eq!(p.depth(0.75), 0.75);
        p.set(PixelTransferParam::DepthBias(0.5));
        assert_eq!(p.depth(0.75), 1.0);
    }
}

#[cfg(test)]
mod cpu_tests {
    use super::*;
    use crate::{Context, FramebufferDesc, ReadFormat};

    /// The CPU paths' maps take GL's entry, `rint(c·(size − 1))`: 0.9 of 8
    /// entries is entry 6 (the drawing path's texture gives 7); the
    /// identity leaves bytes as they are.
    #[test]
    fn reads_go_through_scale_bias_and_gl_map_lookups() {
        let mut p = PixelState::default();
        assert!(p.is_identity());
        let m = [0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7];
        p.set_map(PixelMapName::RToR, &m).unwrap();
        p.set_map(PixelMapName::GToG, &[0.25, 0.75]).unwrap();
        p.set(PixelTransferParam::MapColor(true));
        assert!(!p.is_identity());
        assert_eq!(p.cpu_colour([0.9, 0.49, 0.5, 1.0]), [0.6, 0.25, 0.0, 0.0]);
        let mut gl = Context::new(FramebufferDesc::rgba8_d24s8(4, 4)).unwrap();
        gl.clear_color(0.2, 0.4, 0.6, 1.0).unwrap();
        gl.clear(crate::ClearMask::COLOR).unwrap();
        gl.pixel_transfer(PixelTransferParam::Scale(0, 2.0)).unwrap();
        gl.pixel_transfer(PixelTransferParam::Bias(2, 0.5)).unwrap();
        // 51·2/255 = 0.4 → 102; 153/255 + 0.5 clamps to 1.
        assert_eq!(
            gl.read_pixels(0, 0, 1, 1, ReadFormat::Bgra8).unwrap(),
            [255, 102, 102, 255]
        );
        assert_eq!(gl.read_pixels_f32(0, 0, 1, 1).unwrap()[0][2], 1.0);
    }
}
