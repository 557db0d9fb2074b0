//! The caller's colour formats: which ones softgl draws into directly, and
//! the conversion into the others.

use crate::consts::*;
use softgl::{ColorFormat, Framebuffer};

/// Channel order of an OSMesa format.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Order {
    Rgba,
    Bgra,
    Argb,
    Rgb,
    Bgr,
}

impl Order {
    /// Which of R, G, B, A (0..4) each stored channel holds.
    fn channels(self) -> &'static [usize] {
        match self {
            Order::Rgba => &[0, 1, 2, 3],
            Order::Bgra => &[2, 1, 0, 3],
            Order::Argb => &[3, 0, 1, 2],
            Order::Rgb => &[0, 1, 2],
            Order::Bgr => &[2, 1, 0],
        }
    }
}

/// Channel type of an OSMesa buffer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Channel {
    U8,
    U16,
    F32,
}

impl Channel {
    fn size(self) -> usize {
        match self {
            Channel::U8 => 1,
            Channel::U16 => 2,
            Channel::F32 => 4,
        }
    }
}

/// A format and type pair `OSMesaMakeCurrent` accepts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UserFormat {
    /// RGB 5-6-5 in a native-endian `u16` (`GL_UNSIGNED_SHORT_5_6_5`).
    Rgb565,
    Channels(Order, Channel),
}

impl UserFormat {
    /// The pair for `format` and `type`, or `None` where Mesa 22's OSMesa
    /// refuses it too, except that `OSMESA_BGR` is accepted with the types
    /// of `OSMESA_RGB` (Mesa refuses every type for it).
    pub fn new(format: GLenum, ty: GLenum) -> Option<UserFormat> {
        let order = match format {
            OSMESA_RGB_565 => return (ty == GL_UNSIGNED_SHORT_5_6_5).then_some(UserFormat::Rgb565),
            OSMESA_RGBA => Order::Rgba,
            OSMESA_BGRA => Order::Bgra,
            OSMESA_ARGB => Order::Argb,
            OSMESA_RGB => Order::Rgb,
            OSMESA_BGR => Order::Bgr,
            _ => return None,
        };
        let channel = match ty {
            GL_UNSIGNED_BYTE => Channel::U8,
            GL_UNSIGNED_SHORT => Channel::U16,
            GL_FLOAT => Channel::F32,
            _ => return None,
        };
        Some(UserFormat::Channels(order, channel))
    }

    pub fn bytes_per_pixel(self) -> usize {
        match self {
            UserFormat::Rgb565 => 2,
            UserFormat::Channels(o, c) => o.channels().len() * c.size(),
        }
    }

    /// softgl's format when it draws straight into the caller's buffer.
    fn direct(self) -> Option<ColorFormat> {
        match self {
            UserFormat::Rgb565 => Some(ColorFormat::Rgb565),
            UserFormat::Channels(Order::Rgba, Channel::U8) => Some(ColorFormat::Rgba8),
            UserFormat::Channels(Order::Bgra, Channel::U8) => Some(ColorFormat::Bgra8),
            UserFormat::Channels(Order::Rgb, Channel::U8) => Some(ColorFormat::Rgb8),
            UserFormat::Channels(Order::Rgba, Channel::U16) => Some(ColorFormat::Rgba16),
            UserFormat::Channels(Order::Rgba, Channel::F32) => Some(ColorFormat::Rgba32F),
            UserFormat::Channels(..) => None,
        }
    }

    pub fn is_direct(self) -> bool {
        self.direct().is_some()
    }

    /// The format softgl renders in: the caller's own, else RGBA at the
    /// caller's precision (16-bit or float channels, as Mesa renders them),
    /// or RGBA8 (RGB8 when the caller's bytes have no alpha, so that
    /// destination alpha reads 1 as there).
    pub fn render_format(self) -> ColorFormat {
        self.direct().unwrap_or(match self {
            UserFormat::Channels(_, Channel::U16) => ColorFormat::Rgba16,
            UserFormat::Channels(_, Channel::F32) => ColorFormat::Rgba32F,
            UserFormat::Channels(Order::Rgb | Order::Bgr, _) => ColorFormat::Rgb8,
            _ => ColorFormat::Rgba8,
        })
    }
}

/// Writes `fb`'s colours into `dst` in `format`: rows `stride` bytes apart,
/// the top row first when `top_down`. 16-bit and float channels come from
/// a buffer of their precision, exactly; bytes from a byte buffer.
pub fn store(fb: &Framebuffer, format: UserFormat, dst: &mut [u8], stride: usize, top_down: bool) {
    let UserFormat::Channels(order, channel) = format else {
        return;
    };
    let (w, h) = (fb.width(), fb.height());
    let bpp = format.bytes_per_pixel();
    let size = channel.size();
    for y in 0..h {
        let row = if top_down { h - 1 - y } else { y } as usize;
        let line = &mut dst[row * stride..][..w as usize * bpp];
        for (x, px) in line.chunks_exact_mut(bpp).enumerate() {
            let rgba = fb.pixel(x as u32, y).unwrap_or([0; 4]);
            let deep = fb.pixel_f32(x as u32, y).unwrap_or([0.0; 4]);
            for (out, &c) in px.chunks_exact_mut(size).zip(order.channels()) {
                match channel {
                    Channel::U8 => out[0] = rgba[c],
                    // v / 65535 back to v: exact.
                    Channel::U16 => out.copy_from_slice(&((deep[c] * 65535.0).round() as u16).to_ne_bytes()),
                    Channel::F32 => out.copy_from_slice(&deep[c].to_ne_bytes()),
                }
            }
        }
    }
}
