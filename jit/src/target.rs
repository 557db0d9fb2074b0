//! `Target`: a checked view of the buffers a fragment stage writes into.

use crate::key::{ColorFormat, DepthFormat};

/// The depth buffer of a target, one value per pixel, rows of `width` values.
#[derive(Debug)]
pub enum DepthTarget<'a> {
    D16(&'a mut [u16]),
    D24(&'a mut [u32]),
    D32(&'a mut [u32]),
    /// `f32` bits (see [`DepthFormat::D32F`]).
    D32F(&'a mut [u32]),
}

impl DepthTarget<'_> {
    /// The format of the stored values.
    pub fn format(&self) -> DepthFormat {
        match self {
            DepthTarget::D16(_) => DepthFormat::D16,
            DepthTarget::D24(_) => DepthFormat::D24,
            DepthTarget::D32(_) => DepthFormat::D32,
            DepthTarget::D32F(_) => DepthFormat::D32F,
        }
    }

    fn len(&self) -> usize {
        match self {
            DepthTarget::D16(d) => d.len(),
            DepthTarget::D24(d) | DepthTarget::D32(d) | DepthTarget::D32F(d) => d.len(),
        }
    }

    /// The first `n` values and the rest, as two targets of the same format.
    fn split_at(self, n: usize) -> (Self, Self) {
        let n = n.min(self.len());
        match self {
            DepthTarget::D16(d) => {
                let (a, b) = d.split_at_mut(n);
                (DepthTarget::D16(a), DepthTarget::D16(b))
            }
            DepthTarget::D24(d) => {
                let (a, b) = d.split_at_mut(n);
                (DepthTarget::D24(a), DepthTarget::D24(b))
            }
            DepthTarget::D32(d) => {
                let (a, b) = d.split_at_mut(n);
                (DepthTarget::D32(a), DepthTarget::D32(b))
            }
            DepthTarget::D32F(d) => {
                let (a, b) = d.split_at_mut(n);
                (DepthTarget::D32F(a), DepthTarget::D32F(b))
            }
        }
    }

    /// The stored value at `index`.
    #[inline]
    pub fn get(&self, index: usize) -> u32 {
        match self {
            DepthTarget::D16(d) => u32::from(d[index]),
            DepthTarget::D24(d) | DepthTarget::D32(d) | DepthTarget::D32F(d) => d[index],
        }
    }

    /// Stores `value` (already within the format's range) at `index`.
    #[inline]
    pub fn set(&mut self, index: usize, value: u32) {
        match self {
            DepthTarget::D16(d) => d[index] = value as u16,
            DepthTarget::D24(d) | DepthTarget::D32(d) | DepthTarget::D32F(d) => d[index] = value,
        }
    }
}

/// A framebuffer view: color rows of `stride` bytes (row 0 at the bottom unless
/// `top_down`), depth and stencil rows of `width` values with row 0 at the bottom.
///
/// A view may hold only a band of rows, `y0..y0 + rows` of a framebuffer
/// `height` rows tall ([`Target::into_bands`]): its slices then start at the
/// band's first row, and fragments outside the band are not its to write.
/// Bands of one framebuffer are disjoint, so threads can own one each.
#[derive(Debug)]
pub struct Target<'a> {
    width: u32,
    height: u32,
    /// The band of rows this view owns.
    y0: u32,
    rows: u32,
    color_format: ColorFormat,
    /// `color_format.bytes_per_pixel()`, found once: per row in a clear's
    /// loop, the match over six formats cost 6% of `fill clear`'s
    /// instructions (callgrind) once the deep formats were added.
    bpp: usize,
    color: &'a mut [u8],
    stride: usize,
    top_down: bool,
    depth: Option<DepthTarget<'a>>,
    stencil: Option<&'a mut [u8]>,
    /// Fragments that passed every test under keys that count them
    /// (`FragmentKey::count`), since the view was made or last taken.
    samples_passed: u64,
}

/// Buffers too small for the size a target claims.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
pub enum TargetError {
    #[error("color row stride {stride} is smaller than a row of {width} pixels")]
    StrideTooSmall { stride: usize, width: u32 },
    #[error("{buffer} buffer holds {len} elements, {needed} needed")]
    BufferTooSmall {
        buffer: &'static str,
        len: usize,
        needed: usize,
    },
}

impl<'a> Target<'a> {
    /// A view of `color` (rows of `stride` bytes) with optional depth and stencil
    /// buffers, checked once here so the stages need not check again.
    pub fn new(
        width: u32,
        height: u32,
        color_format: ColorFormat,
        color: &'a mut [u8],
        stride: usize,
        depth: Option<DepthTarget<'a>>,
        stencil: Option<&'a mut [u8]>,
    ) -> Result<Target<'a>, TargetError> {
        let (w, h) = (width as usize, height as usize);
        let row = w * color_format.bytes_per_pixel();
        if stride < row {
            return Err(TargetError::StrideTooSmall { stride, width });
        }
        let color_needed = if h == 0 { 0 } else { stride * (h - 1) + row };
        if color.len() < color_needed {
            return Err(TargetError::BufferTooSmall {
                buffer: "color",
                len: color.len(),
                needed: color_needed,
            });
        }
        if let Some(d) = &depth {
            if d.len() < w * h {
                return Err(TargetError::BufferTooSmall {
                    buffer: "depth",
                    len: d.len(),
                    needed: w * h,
                });
            }
        }
        if let Some(s) = &stencil {
            if s.len() < w * h {
                return Err(TargetError::BufferTooSmall {
                    buffer: "stencil",
                    len: s.len(),
                    needed: w * h,
                });
            }
        }
        Ok(Target {
            width,
            height,
            y0: 0,
            rows: height,
            color_format,
            bpp: color_format.bytes_per_pixel(),
            color,
            stride,
            top_down: false,
            depth,
            stencil,
            samples_passed: 0,
        })
    }

    /// Fragments counted by keys with [`FragmentKey::count`](crate::FragmentKey::count)
    /// since the view was made or the count last taken.
    pub fn samples_passed(&self) -> u64 {
        self.samples_passed
    }

    /// The count of [`Self::samples_passed`], reset to 0.
    pub fn take_samples_passed(&mut self) -> u64 {
        std::mem::take(&mut self.samples_passed)
    }

    /// Adds `n` fragments to [`Self::samples_passed`] (the back ends' count).
    pub fn add_samples_passed(&mut self, n: u64) {
        self.samples_passed = self.samples_passed.wrapping_add(n);
    }

    /// Rows `y0..y0 + rows` of a `width`×`height` framebuffer on their own,
    /// as [`Target::into_bands`] makes them (bottom-up, `color` and
    /// `stencil` holding those rows only): the colour a multisampled
    /// draw's fragments are shaded into once, for all of its samples
    /// (softgl's `raster::scene`, shared shading), in the frame of the
    /// framebuffer's band (the same `height`, so the same rows for the
    /// shading stage).
    pub fn band(
        (width, height): (u32, u32),
        (y0, rows): (u32, u32),
        color_format: ColorFormat,
        color: &'a mut [u8],
        stencil: Option<&'a mut [u8]>,
    ) -> Result<Target<'a>, TargetError> {
        let mut t = Target::new(
            width,
            rows,
            color_format,
            color,
            width as usize * color_format.bytes_per_pixel(),
            None,
            stencil,
        )?;
        t.height = height.max(y0 + rows);
        t.y0 = y0;
        Ok(t)
    }

    /// The same view with color row 0 at the top of the image (`OSMESA_Y_UP` false).
    pub fn with_top_down(mut self, top_down: bool) -> Self {
        self.top_down = top_down;
        self
    }

    pub fn width(&self) -> u32 {
        self.width
    }

    /// The framebuffer's height (a band's too: rows are numbered in the framebuffer).
    pub fn height(&self) -> u32 {
        self.height
    }

    /// The rows this view owns, `y0..y1` (all of them unless it is a band).
    pub fn rows(&self) -> std::ops::Range<u32> {
        self.y0..self.y0 + self.rows
    }

    /// Splits the view into bands of `band` rows (the last may be shorter),
    /// bottom band first. Each band owns its rows of every buffer.
    pub fn into_bands(self, band: u32) -> Vec<Target<'a>> {
        let band = band.max(1);
        let end = self.y0 + self.rows;
        let (w, stride) = (self.width as usize, self.stride);
        let starts: Vec<u32> = (self.y0..end).step_by(band as usize).collect();
        // Color rows are stored top band first when top-down: split them in
        // storage order, then hand them out bottom band first.
        let mut colors: Vec<Option<&'a mut [u8]>> = Vec::with_capacity(starts.len());
        let mut color = self.color;
        let stored: Vec<usize> = if self.top_down {
            (0..starts.len()).rev().collect()
        } else {
            (0..starts.len()).collect()
        };
        colors.resize_with(starts.len(), || None);
        for (k, &i) in stored.iter().enumerate() {
            let rows = band.min(end - starts[i]) as usize;
            let take = if k + 1 == stored.len() {
                color.len()
            } else {
                (rows * stride).min(color.len())
            };
            let (a, b) = std::mem::take(&mut color).split_at_mut(take);
            colors[i] = Some(a);
            color = b;
        }
        let (mut depth, mut stencil) = (self.depth, self.stencil);
        let mut bands = Vec::with_capacity(starts.len());
        for (i, &y0) in starts.iter().enumerate() {
            let rows = band.min(end - y0);
            let n = rows as usize * w;
            let (d, rest) = match depth {
                Some(d) => {
                    let (a, b) = d.split_at(n);
                    (Some(a), Some(b))
                }
                None => (None, None),
            };
            depth = rest;
            let (s, rest) = match stencil {
                Some(s) => {
                    let (a, b) = s.split_at_mut(n.min(s.len()));
                    (Some(a), Some(b))
                }
                None => (None, None),
            };
            stencil = rest;
            bands.push(Target {
                width: self.width,
                height: self.height,
                y0,
                rows,
                color_format: self.color_format,
                bpp: self.bpp,
                color: colors[i].take().unwrap_or_default(),
                stride,
                top_down: self.top_down,
                depth: d,
                stencil: s,
                samples_passed: 0,
            });
        }
        bands
    }

    /// The fragments of `span` this view writes: the covered ones inside the
    /// framebuffer's width and in the view's rows.
    #[inline]
    pub fn owned_mask(&self, span: &crate::FragmentSpan) -> u64 {
        if span.y < self.y0 || span.y - self.y0 >= self.rows || span.x >= self.width {
            return 0;
        }
        let inside = (self.width - span.x).min(crate::SPAN_MAX as u32);
        let live = span.live_mask();
        if inside < 64 {
            live & ((1u64 << inside) - 1)
        } else {
            live
        }
    }

    pub fn color_format(&self) -> ColorFormat {
        self.color_format
    }

    pub fn depth_format(&self) -> Option<DepthFormat> {
        self.depth.as_ref().map(DepthTarget::format)
    }

    pub fn has_stencil(&self) -> bool {
        self.stencil.is_some()
    }

    /// Byte offset of pixel `(x, y)` (a row of the view's) in the color buffer.
    #[inline]
    pub fn color_offset(&self, x: u32, y: u32) -> usize {
        let row = if self.top_down {
            self.y0 + self.rows - 1 - y
        } else {
            y - self.y0
        };
        row as usize * self.stride + x as usize * self.bpp
    }

    /// Index of pixel `(x, y)` (a row of the view's) in the depth and stencil buffers.
    #[inline]
    pub fn index(&self, x: u32, y: u32) -> usize {
        (y - self.y0) as usize * self.width as usize + x as usize
    }

    pub fn color_mut(&mut self) -> &mut [u8] {
        self.color
    }

    pub fn color(&self) -> &[u8] {
        self.color
    }

    pub fn depth_mut(&mut self) -> Option<&mut DepthTarget<'a>> {
        self.depth.as_mut()
    }

    pub fn stencil_mut(&mut self) -> Option<&mut [u8]> {
        self.stencil.as_deref_mut()
    }

    /// The geometry [`crate::Specialist`]'s per-span path reads, once a batch.
    pub(crate) fn layout(&self) -> Layout {
        Layout {
            width: self.width,
            height: self.height,
            y0: self.y0,
            rows: self.rows,
            stride: self.stride,
            bpp: self.color_format.bytes_per_pixel(),
            top_down: self.top_down,
        }
    }

    /// Each buffer's first element and length in elements (null and 0 for
    /// a buffer the view lacks), for the batched path: no slicing or enum
    /// match a span.
    pub(crate) fn raw_parts(&mut self) -> RawParts {
        let (depth, depth_len) = match &mut self.depth {
            Some(DepthTarget::D16(d)) => (d.as_mut_ptr().cast(), d.len()),
            Some(DepthTarget::D24(d) | DepthTarget::D32(d) | DepthTarget::D32F(d)) => (d.as_mut_ptr().cast(), d.len()),
            None => (std::ptr::null_mut(), 0),
        };
        let (stencil, stencil_len) = match &mut self.stencil {
            Some(s) => (s.as_mut_ptr(), s.len()),
            None => (std::ptr::null_mut(), 0),
        };
        RawParts {
            color: self.color.as_mut_ptr(),
            color_len: self.color.len(),
            depth,
            depth_len,
            stencil,
            stencil_len,
        }
    }

    /// Splits the view into its color bytes, depth and stencil buffers at once.
    pub fn parts_mut(&mut self) -> (&mut [u8], Option<&mut DepthTarget<'a>>, Option<&mut [u8]>) {
        (self.color, self.depth.as_mut(), self.stencil.as_deref_mut())
    }
}

/// A target's geometry ([`Target::layout`]).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Layout {
    pub width: u32,
    pub height: u32,
    pub y0: u32,
    pub rows: u32,
    pub stride: usize,
    pub bpp: usize,
    pub top_down: bool,
}

impl Layout {
    /// Whether every pixel of the view (rows `0..rows`, columns
    /// `0..width`) is inside each of `parts`' buffers, at the offsets
    /// `Target::color_offset` and `Target::index` give.
    pub fn fits(&self, parts: &RawParts) -> bool {
        let (rows, width) = (self.rows as usize, self.width as usize);
        if rows == 0 || width == 0 {
            return true;
        }
        let color = (rows - 1)
            .checked_mul(self.stride)
            .and_then(|r| r.checked_add(width.checked_mul(self.bpp)?));
        let pixels = rows.checked_mul(width);
        color.is_some_and(|c| c <= parts.color_len)
            && pixels.is_some_and(|p| {
                (parts.depth.is_null() || p <= parts.depth_len) && (parts.stencil.is_null() || p <= parts.stencil_len)
            })
    }
}

/// A target's buffers as pointers and lengths ([`Target::raw_parts`]).
#[derive(Clone, Copy, Debug)]
pub(crate) struct RawParts {
    pub color: *mut u8,
    pub color_len: usize,
    pub depth: *mut u8,
    pub depth_len: usize,
    pub stencil: *mut u8,
    pub stencil_len: usize,
}
