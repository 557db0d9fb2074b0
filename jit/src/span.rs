//! `FragmentSpan`: the unit of work handed from the rasterizer to the fragment stage.

/// Most fragments one span holds.
pub const SPAN_MAX: usize = 64;

/// Up to [`SPAN_MAX`] horizontally adjacent fragments of one row, starting at
/// `(x, y)` in window coordinates (y up). Bit `i` of `mask` says whether fragment
/// `i` (at `x + i`) is covered; data of uncovered fragments is ignored.
/// Structure-of-arrays so compiled code can load several lanes at once.
#[repr(C)]
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FragmentSpan {
    pub x: u32,
    pub y: u32,
    /// Number of fragment slots in use, at most [`SPAN_MAX`].
    pub len: u32,
    pub mask: u64,
    /// Which of the batch's [`Planes`](crate::Planes) this span's primitive
    /// has (keys with a shading stage only).
    pub planes: u32,
    pub r: [u8; SPAN_MAX],
    pub g: [u8; SPAN_MAX],
    pub b: [u8; SPAN_MAX],
    pub a: [u8; SPAN_MAX],
    /// Window depth in depth-buffer units (`0..=DepthFormat::max_value`);
    /// larger values are clamped to the buffer's range by the depth stage.
    pub z: [u32; SPAN_MAX],
}

impl FragmentSpan {
    /// An empty span at `(x, y)`.
    pub fn new(x: u32, y: u32) -> FragmentSpan {
        FragmentSpan {
            x,
            y,
            len: 0,
            mask: 0,
            planes: 0,
            r: [0; SPAN_MAX],
            g: [0; SPAN_MAX],
            b: [0; SPAN_MAX],
            a: [0; SPAN_MAX],
            z: [0; SPAN_MAX],
        }
    }

    /// Sets slot `i` (covered) to `rgba` and `z`, growing `len` to include it.
    pub fn set(&mut self, i: usize, rgba: [u8; 4], z: u32) {
        self.r[i] = rgba[0];
        self.g[i] = rgba[1];
        self.b[i] = rgba[2];
        self.a[i] = rgba[3];
        self.z[i] = z;
        self.mask |= 1 << i;
        self.len = self.len.max(i as u32 + 1);
    }

    /// The coverage mask limited to the slots in use.
    pub fn live_mask(&self) -> u64 {
        let len = self.len.min(SPAN_MAX as u32);
        if len == 64 {
            self.mask
        } else {
            self.mask & ((1u64 << len) - 1)
        }
    }
}
