//! Mipmap generation (`glGenerateMipmap`, `GL_GENERATE_MIPMAP`).

use super::object::{next_size, TexImage, TextureObject};
use super::unpack::{store_texel, texel_channels, Raw, Route};

/// Rebuilds the levels below the base level, down to the last level the
/// chain reaches, from the base image of each face.
pub fn generate(obj: &mut TextureObject) {
    let Ok(base) = usize::try_from(obj.params.base_level) else {
        return;
    };
    let Some(last) = obj.last_level() else { return };
    for face in 0..obj.faces() {
        for level in base + 1..=last {
            let Some(src) = obj.image(level - 1, face) else { return };
            let dst = downsample(src, next_size(obj.target, src.size()));
            if let Some(slot) = obj.image_mut(level, face) {
                *slot = Some(dst);
            }
        }
    }
}

/// `src` reduced to `size`: each texel the average of the 2×2×2 block it covers.
fn downsample(src: &TexImage, size: [u32; 3]) -> TexImage {
    let mut dst = TexImage::new(src.internal, size);
    let step = |d: usize| if src.size()[d] > size[d] { 2 } else { 1 };
    for z in 0..size[2] as usize {
        for y in 0..size[1] as usize {
            for x in 0..size[0] as usize {
                let mut sum = [0f32; 4];
                let mut n = 0.0;
                for dz in 0..step(2) {
                    for dy in 0..step(1) {
                        for dx in 0..step(0) {
                            let ch = texel_channels(src, x * step(0) + dx, y * step(1) + dy, z * step(2) + dz);
                            for c in 0..4 {
                                sum[c] += ch[c].map_or(0.0, Raw::to_f32);
                            }
                            n += 1.0;
                        }
                    }
                }
                let rgba = sum.map(|s| Raw::F(s / n));
                store_texel(&mut dst, (x, y, z), rgba, Route::Direct);
            }
        }
    }
    dst
}
