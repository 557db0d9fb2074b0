//! The varying layout: which attributes a draw's vertices carry past the
//! vertex stage, and where each sits in a vertex's [`Varyings`].
//!
//! The layout is decided once per draw from the same state that builds the
//! [`FragmentKey`](softgl_jit::FragmentKey) (`RasterState::varying_layout`):
//! an attribute no fragment stage reads is neither computed, clipped, set up
//! nor interpolated. Slots are packed in a fixed order — primary colour,
//! back primary colour, secondary colour, back secondary colour, fog
//! coordinate, then the texture coordinates `(s, t, r, q)` of each unit the
//! draw samples, in unit order — each present only when its flag is on.

/// Which varyings a draw carries, decided once per state change from the same
/// state that builds the `FragmentKey`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub struct VaryingLayout {
    /// Primary colour RGBA (front).
    pub color: bool,
    /// Primary colour RGBA for back faces (two-sided lighting only).
    pub back_color: bool,
    /// Secondary colour RGBA (colour sum / separate specular; alpha unused).
    pub secondary: bool,
    /// Back-face secondary colour (two-sided lighting with separate specular).
    pub back_secondary: bool,
    /// Fog coordinate: eye distance `|z_eye|` or `|glFogCoord|`.
    pub fog: bool,
    /// Bit `u` set: the texture coordinates of unit `u` (4 slots), carried
    /// only for a unit with an enabled, complete texture.
    pub tex: u8,
    /// The colours (primary and secondary) are the same at every vertex and
    /// llvmpipe reads them as constants, not interpolated
    /// (`docs/llvmpipe-facts.md` §20): set up as constant planes.
    pub uniform_colors: bool,
}

/// Most f32 slots a vertex carries: 17 for colours and fog, 4 per texture unit.
pub const MAX_VARYINGS: usize = 17 + 4 * softgl_jit::texture::MAX_UNITS;

/// The attribute values of one vertex; the first `layout.len()` slots are meaningful.
pub type Varyings = [f32; MAX_VARYINGS];

impl VaryingLayout {
    /// Slots of each attribute, in packing order, with whether it is on.
    fn parts(&self) -> [(bool, usize); 5] {
        [
            (self.color, 4),
            (self.back_color, 4),
            (self.secondary, 4),
            (self.back_secondary, 4),
            (self.fog, 1),
        ]
    }

    /// The offset of part `k` of [`Self::parts`], if it is on.
    fn offset(&self, k: usize) -> Option<usize> {
        let parts = self.parts();
        parts[k].0.then(|| parts[..k].iter().filter(|p| p.0).map(|p| p.1).sum())
    }

    /// Slots of the colours and the fog coordinate (those before the texture coordinates).
    fn base_len(&self) -> usize {
        self.parts().iter().filter(|p| p.0).map(|p| p.1).sum()
    }

    /// The slots a vertex's primitive is dropped for when not finite: the
    /// colours and the fog coordinate. Texture coordinates may be anything
    /// (infinite, NaN): llvmpipe draws such primitives (measured: a quad
    /// with `glTexCoord4f(inf, …)` or `q = 0` covers its pixels).
    pub fn finite_len(&self) -> usize {
        self.base_len()
    }

    /// f32 slots in use.
    pub fn len(&self) -> usize {
        self.base_len() + 4 * self.tex.count_ones() as usize
    }

    /// Whether the vertices carry nothing but their position.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Offset of texture unit `unit`'s 4 slots `(s, t, r, q)`, if carried.
    pub fn tex(&self, unit: usize) -> Option<usize> {
        if unit >= 8 || self.tex & (1 << unit) == 0 {
            return None;
        }
        let below = self.tex & ((1u16 << unit) - 1) as u8;
        Some(self.base_len() + 4 * below.count_ones() as usize)
    }

    /// The units carried, with the offset of each one's slots, in unit order.
    pub fn tex_units(&self) -> impl Iterator<Item = (usize, usize)> + '_ {
        let base = self.base_len();
        (0..8)
            .filter(|&u| self.tex & (1 << u) != 0)
            .enumerate()
            .map(move |(k, u)| (u, base + 4 * k))
    }

    /// Offset of the primary colour's 4 slots, if active.
    pub fn color(&self) -> Option<usize> {
        self.offset(0)
    }

    /// Offset of the back primary colour's 4 slots, if active.
    pub fn back_color(&self) -> Option<usize> {
        self.offset(1)
    }

    /// Offset of the secondary colour's 4 slots, if active.
    pub fn secondary(&self) -> Option<usize> {
        self.offset(2)
    }

    /// Offset of the back secondary colour's 4 slots, if active.
    pub fn back_secondary(&self) -> Option<usize> {
        self.offset(3)
    }

    /// Offset of the fog coordinate's slot, if active.
    pub fn fog(&self) -> Option<usize> {
        self.offset(4)
    }
}

/// Copies `n` slots of the attribute at `from` in `src` to `to` in `dst`.
#[inline]
pub fn copy_slots(dst: &mut Varyings, to: usize, src: &Varyings, from: usize, n: usize) {
    dst[to..to + n].copy_from_slice(&src[from..from + n]);
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every varying, every unit.
    const ALL: VaryingLayout = VaryingLayout {
        color: true,
        back_color: true,
        secondary: true,
        back_secondary: true,
        fog: true,
        tex: 0xff,
        uniform_colors: false,
    };

    #[test]
    fn offsets_pack_in_order() {
        let all = VaryingLayout { tex: 0, ..ALL };
        assert_eq!(all.len(), 17);
        assert_eq!(
            (
                all.color(),
                all.back_color(),
                all.secondary(),
                all.back_secondary(),
                all.fog()
            ),
            (Some(0), Some(4), Some(8), Some(12), Some(16))
        );
        let some = VaryingLayout {
            color: true,
            fog: true,
            ..VaryingLayout::default()
        };
        assert_eq!((some.len(), some.secondary(), some.fog()), (5, None, Some(4)));
        let fog_only = VaryingLayout {
            fog: true,
            ..VaryingLayout::default()
        };
        assert_eq!((fog_only.len(), fog_only.color(), fog_only.fog()), (1, None, Some(0)));
        assert!(VaryingLayout::default().is_empty());
    }

    #[test]
    fn texture_units_follow_the_fog_coordinate_in_unit_order() {
        let l = VaryingLayout {
            color: true,
            fog: true,
            tex: 0b1000_0101,
            ..VaryingLayout::default()
        };
        assert_eq!(l.len(), 5 + 12);
        assert_eq!(
            (l.tex(0), l.tex(1), l.tex(2), l.tex(7)),
            (Some(5), None, Some(9), Some(13))
        );
        assert_eq!(l.tex_units().collect::<Vec<_>>(), [(0, 5), (2, 9), (7, 13)]);
        assert_eq!((ALL.len(), ALL.tex(7)), (MAX_VARYINGS, Some(MAX_VARYINGS - 4)));
        assert_eq!(VaryingLayout::default().tex(3), None);
    }
}
