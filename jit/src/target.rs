//! `Target`: a checked view of the buffers a fragment stage writes into.

use crate::key::{ColorFormat, DepthFormat};

/// The depth buffer of a target, one value per pixel, rows of `width` values.
#[derive(Debug)]
pub enum DepthTarget<'a> {
    D16(&'a mut [u16]),
    D24(&'a mut [u32]),
    D32(&'a mut [u32]),
}

impl DepthTarget<'_> {
    /// The format of the stored values.
    pub fn format(&self) -> DepthFormat {
        match self {
            DepthTarget::D16(_) => DepthFormat::D16,
            DepthTarget::D24(_) => DepthFormat::D24,
            DepthTarget::D32(_) => DepthFormat::D32,
        }
    }

    fn len(&self) -> usize {
        match self {
            DepthTarget::D16(d) => d.len(),
            DepthTarget::D24(d) | DepthTarget::D32(d) => d.len(),
        }
    }

    /// The stored value at `index`.
    #[inline]
    pub fn get(&self, index: usize) -> u32 {
        match self {
            DepthTarget::D16(d) => u32::from(d[index]),
            DepthTarget::D24(d) | DepthTarget::D32(d) => d[index],
        }
    }

    /// Stores `value` (already within the format's range) at `index`.
    #[inline]
    pub fn set(&mut self, index: usize, value: u32) {
        match self {
            DepthTarget::D16(d) => d[index] = value as u16,
            DepthTarget::D24(d) | DepthTarget::D32(d) => d[index] = value,
        }
    }
}

/// A framebuffer view: color rows of `stride` bytes (row 0 at the bottom unless
/// `top_down`), depth and stencil rows of `width` values with row 0 at the bottom.
#[derive(Debug)]
pub struct Target<'a> {
    width: u32,
    height: u32,
    color_format: ColorFormat,
    color: &'a mut [u8],
    stride: usize,
    top_down: bool,
    depth: Option<DepthTarget<'a>>,
    stencil: Option<&'a mut [u8]>,
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
            color_format,
            color,
            stride,
            top_down: false,
            depth,
            stencil,
        })
    }

    /// The same view with color row 0 at the top of the image (`OSMESA_Y_UP` false).
    pub fn with_top_down(mut self, top_down: bool) -> Self {
        self.top_down = top_down;
        self
    }

    pub fn width(&self) -> u32 {
        self.width
    }

    pub fn height(&self) -> u32 {
        self.height
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

    /// Byte offset of pixel `(x, y)` in the color buffer.
    #[inline]
    pub fn color_offset(&self, x: u32, y: u32) -> usize {
        let row = if self.top_down { self.height - 1 - y } else { y };
        row as usize * self.stride + x as usize * self.color_format.bytes_per_pixel()
    }

    /// Index of pixel `(x, y)` in the depth and stencil buffers.
    #[inline]
    pub fn index(&self, x: u32, y: u32) -> usize {
        y as usize * self.width as usize + x as usize
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

    /// Splits the view into its color bytes, depth and stencil buffers at once.
    pub fn parts_mut(&mut self) -> (&mut [u8], Option<&mut DepthTarget<'a>>, Option<&mut [u8]>) {
        (self.color, self.depth.as_mut(), self.stencil.as_deref_mut())
    }
}
