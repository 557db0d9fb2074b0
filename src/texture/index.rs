//! Colour-index images uploaded to a texture (`GL_COLOR_INDEX` with any
//! integer or float type, or `GL_BITMAP`): an RGBA context turns each index,
//! shifted and offset (`GL_INDEX_SHIFT`, `GL_INDEX_OFFSET`), into RGBA
//! through the `I_TO_R` … `I_TO_A` maps, whatever `GL_MAP_COLOR` says (GL
//! 1.5 §3.6.5, "Color Index to RGBA"); colour scale, bias and the RGBA maps
//! do not apply to it. Mesa: `_mesa_unpack_color_index_to_rgba_ubyte`
//! (`main/pack.c`), whose RGBA8 image is then stored as any RGBA upload.

use super::format::{PixelFormat, PixelType};
use super::unpack::{fetch, ClientLayout, Raw};
use super::PixelStore;
use crate::pixel_rect::BitmapImage;
use crate::pixel_transfer::PixelState;

/// The type of a colour-index image: a GL pixel type, or `GL_BITMAP` (one
/// bit an index, rows as `glBitmap` reads them).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum IndexType {
    Bitmap,
    Type(PixelType),
}

/// Bytes a `size` colour-index image occupies from its pointer under
/// `store` (`dims` 1 to 3); `None` for a type indices cannot have.
pub fn index_image_bytes(ty: IndexType, store: &PixelStore, dims: u32, size: [usize; 3]) -> Option<usize> {
    match ty {
        IndexType::Type(t) => ClientLayout::new(PixelFormat::Red, t, store, dims, size).map(|l| l.len),
        IndexType::Bitmap => {
            let (w, h) = (i32::try_from(size[0]).ok()?, i32::try_from(size[1]).ok()?);
            let slice = BitmapImage::client_bytes(w, h, &bitmap_store(store))?;
            let images = size[2].max(1) + skip_images(store, dims);
            Some(
                slice_stride(w, h, store, dims)
                    .checked_mul(images - 1)?
                    .checked_add(slice)?,
            )
        }
    }
}

/// The RGBA8 image (tight, rows and images in order) the colour indices in
/// `bytes` become under the pixel transfer state `p`; `None` when `bytes`
/// is shorter than [`index_image_bytes`] says.
pub fn index_image_rgba8(
    p: &PixelState,
    bytes: &[u8],
    ty: IndexType,
    store: &PixelStore,
    dims: u32,
    size: [usize; 3],
) -> Option<Vec<u8>> {
    if bytes.len() < index_image_bytes(ty, store, dims, size)? {
        return None;
    }
    let [w, h, d] = size;
    let mut out = Vec::with_capacity(w * h * d * 4);
    let mut push = |i: i64| out.extend(p.index_colour(i).map(clamped_float_to_ubyte));
    match ty {
        IndexType::Type(t) => {
            let layout = ClientLayout::new(PixelFormat::Red, t, store, dims, size)?;
            for k in 0..d {
                for j in 0..h {
                    for i in 0..w {
                        let raw = fetch(bytes, layout.at(i, j, k), PixelFormat::Red, t, store.swap_bytes);
                        push(integer(raw[0]));
                    }
                }
            }
        }
        IndexType::Bitmap => {
            let (wi, hi) = (i32::try_from(w).ok()?, i32::try_from(h).ok()?);
            let stride = slice_stride(wi, hi, store, dims);
            for k in 0..d {
                let from = (skip_images(store, dims) + k) * stride;
                let image = BitmapImage::unpack(wi, hi, bytes.get(from..)?, &bitmap_store(store)).ok()?;
                for j in 0..h as u32 {
                    for i in 0..w as u32 {
                        push(i64::from(image.get(i, j)));
                    }
                }
            }
        }
    }
    Some(out)
}

/// Mesa's `CLAMPED_FLOAT_TO_UBYTE` (`main/macros.h`, release builds): the
/// low byte of `f · (255/256) + 32768` in f32, i.e. `f · 255` rounded to
/// the nearest (ties to even) through the float's mantissa.
fn clamped_float_to_ubyte(f: f32) -> u8 {
    (f * (255.0f32 / 256.0) + 32768.0).to_bits() as u8
}

/// An index of a fetched component: integers as they are, floats truncated.
fn integer(raw: Raw) -> i64 {
    match raw {
        Raw::U(v, _) => i64::from(v),
        Raw::S(v, _) => i64::from(v),
        Raw::F(f) if f.is_finite() => f.clamp(-1e15, 1e15) as i64,
        Raw::F(_) => 0,
    }
}

/// The unpack state a single bitmap image of a 1D/2D/3D upload reads
/// with (the images are then found by [`slice_stride`]).
fn bitmap_store(store: &PixelStore) -> PixelStore {
    PixelStore {
        image_height: 0,
        skip_images: 0,
        ..*store
    }
}

fn skip_images(store: &PixelStore, dims: u32) -> usize {
    if dims == 3 {
        store.skip_images.max(0) as usize
    } else {
        0
    }
}

/// Bytes from one bitmap image to the next (`GL_UNPACK_IMAGE_HEIGHT` rows,
/// or the height, of the padded row stride).
fn slice_stride(w: i32, h: i32, store: &PixelStore, dims: u32) -> usize {
    let rows = if dims == 3 && store.image_height > 0 {
        store.image_height
    } else {
        h
    } as usize;
    let row_length = if store.row_length > 0 { store.row_length } else { w } as usize;
    let align = store.alignment.max(1) as usize;
    rows * (row_length.div_ceil(8).div_ceil(align) * align)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pixel_transfer::PixelMapName;

    #[test]
    fn indices_become_rgba_through_the_i_to_maps() {
        let mut p = PixelState::default();
        p.set_map(PixelMapName::IToR, &[0.0, 1.0]).unwrap();
        p.set_map(PixelMapName::IToG, &[0.0, 0.0]).unwrap();
        p.set_map(PixelMapName::IToB, &[1.0, 0.0]).unwrap();
        p.set_map(PixelMapName::IToA, &[1.0, 1.0]).unwrap();
        let store = PixelStore {
            alignment: 1,
            ..PixelStore::DEFAULT
        };
        // piglit's read-pixels-after-display-list: 0x8f's first bit is set, 0x7f's not.
        let one = |byte: u8| index_image_rgba8(&p, &[byte], IndexType::Bitmap, &store, 2, [1, 1, 1]);
        assert_eq!(one(0x8f), Some(vec![255, 0, 0, 255]));
        assert_eq!(one(0x7f), Some(vec![0, 0, 255, 255]));
        // Bytes: indices 0..3 masked by the 2-entry maps' size.
        let img = index_image_rgba8(
            &p,
            &[0, 1, 2, 3],
            IndexType::Type(PixelType::UnsignedByte),
            &store,
            1,
            [4, 1, 1],
        );
        assert_eq!(
            img,
            Some(vec![0, 0, 255, 255, 255, 0, 0, 255, 0, 0, 255, 255, 255, 0, 0, 255])
        );
        // Too few bytes for a 9-wide bitmap row.
        assert_eq!(
            index_image_rgba8(&p, &[0], IndexType::Bitmap, &store, 1, [9, 1, 1]),
            None
        );
    }

    #[test]
    fn mesas_float_to_ubyte_rounds_to_nearest() {
        assert_eq!(clamped_float_to_ubyte(0.0), 0);
        assert_eq!(clamped_float_to_ubyte(1.0), 255);
        assert_eq!(clamped_float_to_ubyte(0.5), 128); // 127.5 → even
        assert_eq!(clamped_float_to_ubyte(0.2), 51);
    }
}
